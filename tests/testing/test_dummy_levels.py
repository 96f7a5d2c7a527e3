"""Dummies acting on blocks in the level they are in (DummyCommand uses dummy.serverLevel(); the
block code gets that ServerLevel): pressing, mining and placing in the nether leaves the overworld's
blocks alone; a button's scheduled tick springs back in its own level; the nether's build height.
Every check names its level (``execute in ... run assert``)."""
import json

import pytest

from tests.testing.test_dummy_hands import run

NETHER, OVERWORLD = "execute in minecraft:the_nether ", "execute in minecraft:overworld "
DIRT_TABLE = {"minecraft/loot_table/blocks/dirt.json": json.dumps({"pools": [{"rolls": 1, "entries": [
    {"type": "minecraft:item", "name": "minecraft:diamond"}]}]})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_dummy_in_the_nether_uses_and_mines_the_nethers_blocks(tmp_path, backend):
    result = run(tmp_path, "# @dummy\n" + (
        f"{OVERWORLD}run setblock ~2 ~ ~ stone_button[face=floor,facing=north,powered=false]\n"
        f"{NETHER}run setblock ~2 ~ ~ stone_button[face=floor,facing=north,powered=false]\n"
        f"{NETHER}run tp @s ~ ~ ~\n"
        "dummy @s use block ~2 ~ ~\n"
        f"{NETHER}run assert block ~2 ~ ~ stone_button[powered=true]\n"
        f"{OVERWORLD}run assert block ~2 ~ ~ stone_button[powered=false]\n"
        "await delay 20\n"
        f"{NETHER}run assert block ~2 ~ ~ stone_button[powered=false]\n"
        f"{OVERWORLD}run setblock ~3 ~ ~ dirt\n"
        f"{NETHER}run setblock ~3 ~ ~ dirt\n"
        "dummy @s mine ~3 ~ ~\n"
        f"{OVERWORLD}run assert block ~3 ~ ~ dirt\n"
        f"{NETHER}run assert block ~3 ~ ~ air\n"
        f"{NETHER}run assert entity @e[type=item,x=0,dx=10]\n"
        f"{OVERWORLD}run assert not entity @e[type=item,x=0,dx=10]\n"), files=DIRT_TABLE, backend=backend)
    assert result.status == "passed", result.report()


def test_placing_in_the_nether_keeps_to_its_build_height(tmp_path):
    """DimensionType the_nether: min_y 0, so nothing goes below y 0 there."""
    result = run(tmp_path, "# @dummy\n" + (
        f"{NETHER}run setblock ~2 ~ ~ dirt\n"
        f"{NETHER}run tp @s ~ ~ ~\n"
        "give @s stone 2\n"
        "dummy @s use block ~2 ~ ~ up\n"
        f"{NETHER}run assert block ~2 ~1 ~ stone\n"
        f"{OVERWORLD}run assert block ~2 ~1 ~ air\n"
        f"{NETHER}run setblock ~2 0 ~ dirt\n"
        "dummy @s use block ~2 0 ~ down\n"
        "assert items entity @s weapon.mainhand stone[count=1]\n"))
    assert result.status == "passed", result.report()
    assert "cannot interact with that block" in "\n".join(result.details)
