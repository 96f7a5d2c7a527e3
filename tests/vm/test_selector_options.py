"""The selector arguments ``name``, ``team``, ``gamemode``, ``level``, ``x_rotation`` and
``y_rotation`` run inside the VM (emulator.vm.entity_arrays, TEST_INT / TEST_RANGE / TEST_ROT),
pinned to the game's behaviour and checked against the reference backend.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): commands/arguments/selector/options/
EntitySelectorOptions.java (``name``: ``entity.getName().getString().equals(s) != inverted``;
``team``: false for anything not a LivingEntity, else the team's name or "" compared;
``gamemode`` and ``level``: players only, setIncludesEntities(false)), commands/arguments/selector/
EntitySelectorParser.java (createRotationPredicate: both bounds ``Mth.wrapDegrees`` of the float,
a missing low 0 and a missing high 359, the angle ``Mth.wrapDegrees`` of the double; a low above the
high matches the wrapped-around arc), world/entity/Entity.java (getName: the custom name, else the
type's name; Player.getName: the profile's name).
"""
from __future__ import annotations

import pytest

from emulator import Emulator
from tests.backends.programs import write_pack

SETUP = ("scoreboard objectives add o dummy\n"
         'summon marker 0 0 0 {Tags:["m"],Rotation:[-170f,0f]}\n'
         'summon marker 1 0 0 {Tags:["m"],Rotation:[170f,45f],CustomName:\'"Bob"\'}\n'
         'summon marker 2 0 0 {Tags:["m"],Rotation:[20f,-45f]}\n'
         'summon marker 3 0 0 {Tags:["m"],Rotation:[200f,90f]}\n'
         'summon armor_stand 4 0 0 {Tags:["m"],Rotation:[-45f,0f],CustomName:\'"Bob"\'}\n')


def _run_both(tmp_path, body: str):
    """Run t:main (SETUP first, after two players joined) on both backends; the VM's emulator,
    once both agree."""
    emus = []
    for backend in ("numba", "python"):
        emu = Emulator(backend=backend)
        emu.load(write_pack(tmp_path / backend, {"t:main": SETUP + body}))
        emu.add_player("Steve", (0, 0, 0), (10.0, -20.0), gamemode="creative", level=7)
        emu.add_player("Bob", (0, 0, 0), (-100.0, 80.0), level=2)
        emu.call("t:main")
        emus.append(emu)
    numba, python = emus
    assert numba.scores() == python.scores()
    assert numba.entities() == python.entities()
    return numba


def _selected(emu) -> list[int]:
    """Who the selector found: the places in ``@e`` of the entities t:main gave an ``o`` score
    (0 Steve, 1 Bob, the markers 2 (yaw -170), 3 ("Bob", 170, pitch 45), 4 (20, -45), 5 (200, 90),
    6 the armor stand "Bob" (-45, 0))."""
    return [i for i, e in enumerate(emu.entities()) if e["scores"].get("o") is not None]


def _host_kinds(emu) -> set[str]:
    return {type(run.node).__name__ for run in emu.backend.host_ops_run()}


@pytest.mark.parametrize("selector, found", [
    # name: players by their name, others by their custom name, else the type's name; negation keeps the rest
    ("@e[name=Bob]", [1, 3, 6]),
    ("@e[type=marker,name=!Bob]", [2, 4, 5]),
    ("@e[name=Marker]", [2, 4, 5]),
    # team: no team is ""; only living entities (players, the armor stand) pass, even negated
    ("@e[team=]", [0, 1, 6]),
    ("@e[team=!red]", [0, 1, 6]),
    ("@e[team=red]", []),
    # gamemode and level select players only
    ("@e[gamemode=creative]", [0]),
    ("@e[gamemode=!creative]", [1]),
    ("@e[level=3..]", [0]),
    ("@e[level=..2]", [1]),
    # rotations: wrapped bounds; 135..-135 is the arc through 180 (200 wraps to -160)
    ("@e[type=marker,y_rotation=135..-135]", [2, 3, 5]),
    ("@e[y_rotation=-45..45]", [0, 4, 6]),
    ("@e[x_rotation=30..]", [0, 1, 3, 4, 5]),  # 30..359: 359 wraps to -1, so the arc through 180 (and -20)
    ("@e[x_rotation=..0]", [2, 6]),  # a missing low is 0
    ("@e[x_rotation=-90..-40,y_rotation=0..100]", [4]),
    ("@e[y_rotation=540..560]", [2, 5]),  # -180..-160 once wrapped, inclusive
])
def test_selector_options_run_in_the_vm(tmp_path, selector, found):
    emu = _run_both(tmp_path, f"execute as {selector} run scoreboard players set @s o 1")
    assert _selected(emu) == found
    assert _host_kinds(emu) == {"ObjectivesAdd", "Summon"}


def test_a_custom_name_given_later_is_seen_by_name(tmp_path):
    # the name the VM compares follows the entity's custom name when NBT changes it
    emu = _run_both(tmp_path, "data merge entity @e[type=marker,limit=1] {CustomName:'\"Bob\"'}\n"
                              "execute store result score #n o if entity @e[name=Bob]")
    assert emu.score("#n", "o") == 4


def test_gamemode_and_level_follow_the_commands_that_change_them(tmp_path):
    emu = _run_both(tmp_path, "gamemode spectator Steve\nxp add Bob 5 levels\n"
                              "execute store result score #spectators o if entity @a[gamemode=spectator]\n"
                              "execute store result score #high o if entity @a[level=7..]")
    assert (emu.score("#spectators", "o"), emu.score("#high", "o")) == (1, 2)


# ORDER_RANDOM (EntitySelectorParser) is Collections.shuffle; both backends draw from the world's
# java.util.Random (emulator.world.java_random), so a random pick is the same on both
def test_random_sorts_run_in_the_vm_and_pick_what_the_reference_picks(tmp_path):
    body = "".join(f'summon marker {i} 0 0 {{Tags:["r"]}}\n' for i in range(8)) + (
        "execute as @e[tag=r,sort=random,limit=3] run scoreboard players add @s o 1\n"
        "execute as @r run scoreboard players add @s o 10\n" * 5
        + "tag @e[type=marker,sort=random,limit=1] add picked\n"
        "execute store result score #n o if entity @e[tag=r,sort=random,limit=5]\n")
    emu = _run_both(tmp_path, body)
    assert _host_kinds(emu) == {"ObjectivesAdd", "Summon"}
    assert emu.score("#n", "o") == 5
    players = [e["scores"].get("o", 0) for e in emu.entities("@a")]
    assert sum(players) == 50 and all(players)  # five picks, each player picked at least once (this seed)
    assert sum(e["scores"].get("o", 0) for e in emu.entities("@e[tag=r]")) == 5 * 3
    assert len(emu.entities("@e[tag=picked]")) == 1


@pytest.mark.parametrize("line", [
    # ScoreboardCommand.performOperation reads the targets, their objective, then the sources: a
    # command failing on its targets never reads (never shuffles) its sources
    "scoreboard players operation @s o = @e[sort=random,limit=2] o",
    "scoreboard players operation @e[tag=none] o += @e[sort=random,limit=1] o",
    "scoreboard players operation #x nope += @e[sort=random,limit=1] o",
    # the host runs a tp whose target goes to another level, and writes tellraw's line: one draw
    "execute in minecraft:the_nether run tp @e[type=marker,sort=random,limit=1] ~ ~ ~",
    'tellraw @r "hi"',
    # a stage making more contexts than the VM has room for runs again once Python made room
    "summon marker 0 0 0\n" * 40 + "execute as @e[type=marker,sort=random] at @s run scoreboard players add @s o 0",
])
def test_a_random_selector_draws_as_often_as_in_the_game(tmp_path, line):
    # every later random pick agrees only if both backends drew the same number of times before
    emu = _run_both(tmp_path, line + "\n" + "execute as @e[sort=random,limit=1] run scoreboard players add @s o 1\n" * 6)
    assert sum(e["scores"].get("o", 0) for e in emu.entities()) >= 6
