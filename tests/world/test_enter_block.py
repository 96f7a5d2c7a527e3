"""The ``enter_block`` trigger (emulator.world.inside_blocks, advancements.tick_players): the blocks a
player is inside each tick. Sources (decompiled): 1.21.3 and 26.1.2 LivingEntity.aiStep ->
Entity.applyEffectsFromBlocks -> checkInsideBlocks (non-air blocks in the box deflated by 1.0E-5,
BlockPos.betweenClosed order); 1.21.1 and 1.20.6 Entity.move -> checkInsideBlocks (every block in
the box shrunk by 1.0E-7, air included); ServerPlayer.onInsideBlock; EnterBlockTrigger.TriggerInstance.
matches (``block`` and ``state``)."""
import json

import pytest

from emulator.testing import discover, run_suite
from emulator.world import advancements, falling
from emulator.world.blocks import BlockState
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from tests.conftest import write_pack

NEW, OLD = (1, 21, 4), (1, 21, 1)


def _world(version, **conditions) -> tuple[WorldState, object]:
    bodies = {f"t:{name}": {"criteria": {"c": {"trigger": "minecraft:enter_block", "conditions": c}}}
              for name, c in conditions.items()}
    state = WorldState(resources=Resources(advancements=bodies), version=version)
    return state, state.entities.add_player("Alex", (0.5, 64.0, 0.5))


def _got(state, player, name) -> bool:
    return "c" in state.advancement_progress.of(player, f"t:{name}")


def _unmodelled(state) -> list[str]:
    return [d.message for d in state.diagnostics if "enter_block" in d.message]


def test_from_1_21_2_the_blocks_at_the_feet_and_head_fire_not_air_nor_the_ground():
    # aiStep -> applyEffectsFromBlocks for every server player: the box (y 64..65.8) deflated by
    # 1.0E-5 meets the cells at y 64 and 65, not the ground at 63; air never fires
    state, player = _world(NEW, feet={"block": "minecraft:poppy"}, head={"block": "minecraft:cobweb"},
                           ground={"block": "minecraft:stone"}, anything={})
    blocks = state.blocks_in(player.dimension)
    blocks.set_state((0, 63, 0), BlockState("minecraft:stone"))
    advancements.tick_players(state)
    assert not _got(state, player, "anything")  # only air around the player
    blocks.set_state((0, 64, 0), BlockState("minecraft:poppy"))
    blocks.set_state((0, 65, 0), BlockState("minecraft:cobweb"))
    advancements.tick_players(state)
    assert _got(state, player, "feet") and _got(state, player, "head") and _got(state, player, "anything")
    assert not _got(state, player, "ground")
    assert not _unmodelled(state)


def test_the_state_properties_must_match():
    # EnterBlockTrigger.TriggerInstance.matches: state.is(block), then the StatePropertiesPredicate
    state, player = _world(NEW, north={"block": "minecraft:ladder", "state": {"facing": "north"}},
                           south={"block": "minecraft:ladder", "state": {"facing": "south"}})
    state.blocks_in(player.dimension).set_state((0, 64, 0), BlockState.of("minecraft:ladder",
                                                                    {"facing": "south", "waterlogged": "false"}))
    advancements.tick_players(state)
    assert _got(state, player, "south") and not _got(state, player, "north")


def test_a_spectator_is_not_inside_blocks():
    # Player.tick: noPhysics for a spectator; Entity.isAffectedByBlocks is false then
    state, player = _world(NEW, any={})
    player.gamemode = "spectator"
    state.blocks_in(player.dimension).set_state((0, 64, 0), BlockState("minecraft:poppy"))
    advancements.tick_players(state)
    assert not _got(state, player, "any")


def test_a_block_with_an_inside_shape_of_its_own_is_not_modelled():
    # TripWireBlock.getEntityInsideCollisionShape: the player must meet the wire's shape
    state, player = _world(NEW, wire={"block": "minecraft:tripwire"})
    state.blocks_in(player.dimension).set_state((0, 64, 0), BlockState("minecraft:tripwire"))
    advancements.tick_players(state)
    assert not _got(state, player, "wire")
    assert any("tripwire" in m for m in _unmodelled(state))


def test_before_1_21_2_a_moving_dummy_is_inside_air_too():
    # 1.21.1 Entity.move -> tryCheckInsideBlocks each tick of a dummy's travel: every block of its
    # box, air included (no air test then)
    state, player = _world(OLD, air={"block": "minecraft:air"})
    state.blocks_in(player.dimension).set_state((0, 63, 0), BlockState("minecraft:stone"))
    falling.fall(state, player)
    falling.tick_falling(state)
    advancements.tick_players(state)
    assert _got(state, player, "air") and not _unmodelled(state)


def test_before_1_21_2_a_player_a_client_drives_is_not_modelled():
    # 1.21.1: a client's player is checked when its movement packets move it (client timing)
    state, player = _world(OLD, any={})
    advancements.tick_players(state)
    assert not _got(state, player, "any")
    assert _unmodelled(state)


def _suite(tmp_path, pack_format: int, test: str, files: dict, backend: str):
    root = write_pack(tmp_path / "pack", {"demo/test/t.mcfunction": test, **files})
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": "t"}}))
    [result] = run_suite(discover([root]), backend).results
    return result


# a pack's idiom: the reward revokes its advancement, so the trigger counts every tick in the block
IN_FLOWER = {
    "demo/advancement/in_flower.json": json.dumps(
        {"criteria": {"c": {"trigger": "minecraft:enter_block", "conditions": {"block": "minecraft:poppy"}}},
         "rewards": {"function": "demo:in_flower"}}),
    "demo/function/in_flower.mcfunction": ("advancement revoke @s only demo:in_flower\n"
                                           "scoreboard players add @s flower 1\n"),
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_dummy_standing_in_a_flower_fires_each_tick(tmp_path, backend):
    result = _suite(tmp_path, 61, (  # 1.21.4
        "# @skyaccess\n"
        "scoreboard objectives add flower dummy\n"
        "setblock ~ ~ ~ grass_block\n"
        "setblock ~ ~1 ~ poppy\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        "await delay 5\n"
        "assert score Alex flower matches 5..6\n"
        "setblock ~ ~1 ~ air\n"
        "execute store result score #before flower run scoreboard players get Alex flower\n"
        "await delay 3\n"
        "execute if score Alex flower > #before flower run fail \"fired outside the flower\"\n"
        "succeed\n"), IN_FLOWER, backend)
    assert result.status == "passed", result.report()
