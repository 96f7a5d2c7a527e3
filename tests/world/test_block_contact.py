"""A mob in or on a block that acts on it (a big dripleaf tilting under it, a pressure plate, a
magma block) is not modelled here: the test waiting for the block's answer is inconclusive, never
failed. Sources (decompiled 1.21): BigDripleafBlock.entityInside / canEntityTilt,
BasePressurePlateBlock.entityInside, MagmaBlock.stepOn, Entity.getOnPos (0.2 below the feet)."""
import json

import pytest

from emulator.testing import discover, run_suite
from emulator.world.block_contact import CART, MESSAGE
from tests.conftest import write_pack
from tests.world.world_emulator import emulator

# the shape collections use: a leaf under the dummy, then wait for the tilt the game gives it
FILES = {
    "demo/test/leaf.mcfunction": "# @dummy ~1 ~2 ~1\nsetblock ~1 ~ ~1 minecraft:dirt\n"
                                 "setblock ~1 ~1 ~1 minecraft:big_dripleaf\n"
                                 "await block ~1 ~1 ~1 minecraft:big_dripleaf[tilt=partial]\n",
    "demo/test/no_leaf.mcfunction": "# @dummy ~1 ~2 ~1\nsetblock ~1 ~1 ~1 minecraft:stone\nsucceed\n",
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_waiting_for_a_leaf_to_tilt_under_a_dummy_is_inconclusive(tmp_path, backend):
    root = write_pack(tmp_path / "pack", FILES)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "t"}}))
    results = {r.id: r for r in run_suite(discover([root]), backend).results}
    assert results["demo:leaf"].status == "inconclusive"
    assert MESSAGE.format("minecraft:big_dripleaf") in results["demo:leaf"].message
    assert results["demo:no_leaf"].status == "passed"


def _reported(emu):
    return [d.message for d in emu.diagnostics if d.unmodelled]


def test_a_mob_on_a_plate_or_magma_is_reported_once_and_a_marker_is_not(tmp_path):
    emu = emulator(tmp_path, "python", {"t:s": "\n".join([
        "setblock 0 0 0 stone_pressure_plate", "setblock 4 0 0 magma_block",
        "summon marker 0.5 0 0.5", "summon marker 4.5 1 0.5"])})
    emu.call("t:s")
    emu.tick(2)
    assert _reported(emu) == []  # a marker presses and touches nothing (no bounding box)
    emu.add_player("Alex", (4.5, 1.0, 0.5))  # on the magma block: its getOnPos is the block below
    emu.add_player("Steve", (0.5, 0.0, 0.5))  # in the plate's cell
    emu.tick(3)
    assert _reported(emu) == [MESSAGE.format("minecraft:magma_block"),  # in the mobs' order, once each
                              MESSAGE.format("minecraft:stone_pressure_plate")]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_plate_placed_under_a_standing_mob_is_reported_from_the_next_tick(tmp_path, backend):
    # the world held no acting block while the player stood there (nothing to report, nothing to
    # look at); the plate set later is found at the tick's end, as the game's entity would press it
    emu = emulator(tmp_path, backend, {"t:plate": "setblock 0 5 0 stone_pressure_plate",
                                       "t:floor": "setblock 0 4 0 stone"})
    emu.call("t:floor")
    emu.add_player("Alex", (0.5, 5.0, 0.5))
    emu.tick(2)
    assert _reported(emu) == []
    emu.call("t:plate")
    emu.tick()
    assert _reported(emu) == [MESSAGE.format("minecraft:stone_pressure_plate")]


def test_magma_beside_the_feet_acts_only_from_below(tmp_path):
    # stepOn is the block under the feet: magma in the feet's own cell is a block the mob is inside
    emu = emulator(tmp_path, "python", {"t:s": "setblock 0 5 0 magma_block"})
    emu.call("t:s")
    emu.add_player("Alex", (0.5, 5.0, 0.5))
    emu.tick(2)
    assert _reported(emu) == []


def test_a_minecart_that_would_ride_its_rails_is_reported(tmp_path):
    # AbstractMinecart.tick / moveAlongTrack: a cart with motion moves, one on a powered powered_rail
    # is pushed; one at rest on a plain or unpowered rail stays, as here
    emu = emulator(tmp_path, "python", {"t:s": "\n".join([
        "setblock 0 0 0 rail", "setblock 2 0 0 powered_rail[powered=false]", "setblock 4 0 0 powered_rail[powered=true]",
        "summon minecart 0.5 0 0.5", "summon minecart 2.5 0 0.5"]),
        "t:push": "summon minecart 4.5 0 0.5",
        "t:go": "summon chest_minecart 8.5 0 0.5 {Motion:[0.2d,0.0d,0.0d]}"})
    emu.call("t:s")
    emu.tick(2)
    assert _reported(emu) == []
    emu.call("t:push")
    emu.call("t:go")
    emu.tick(2)
    assert _reported(emu) == [CART.format("on a powered rail"), CART.format("with motion")]


@pytest.mark.parametrize("block", ["fire", "lava"])
def test_a_mob_in_fire_or_lava_is_reported(tmp_path, block):
    # BaseFireBlock.entityInside / Entity.lavaHurt set what is inside on fire: not modelled
    emu = emulator(tmp_path, "python", {"t:s": f"setblock 0 5 0 {block}\nsummon pig 0.5 5 0.5 {{NoAI:1b}}"})
    emu.call("t:s")
    emu.tick()
    assert _reported(emu) == [MESSAGE.format("minecraft:" + block)]
