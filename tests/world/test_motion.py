"""Entities other than players move each tick as the game's server moves them (emulator.world.motion,
through Entity.move in emulator.world.falling). Each test names the decompiled 1.21 source it pins."""
import pytest

from emulator.testing import discover, run_suite

SKY = "# @skyaccess\n"
AT_TOP = "execute positioned ~0.5 ~1 ~0.5 unless entity @e[type={},distance=..0.0000001] run fail \"not on top\"\n"


def run(pack, text, backend="numba"):
    [result] = run_suite(discover([pack({"demo/test/t.mcfunction": text})]), backend).results
    return result


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_item_summoned_in_the_air_falls_and_lands_on_the_block(pack, backend):
    # ItemEntity.tick: gravity 0.04 (getDefaultGravity), the move, motion x 0.98: from 3 blocks up
    # the item lands on the stone's top (Entity.move: OnGround) and rests there
    result = run(pack, SKY + (
        "setblock ~ ~ ~ stone\n"
        "summon item ~0.5 ~3 ~0.5 {Item:{id:\"minecraft:stone\",count:1}}\n"
        "await entity @e[type=item,nbt={OnGround:1b}]\n"
        + AT_TOP.format("item") +
        "await delay 5\n"
        + AT_TOP.format("item")), backend)
    assert result.status == "passed", result.report()
