"""Selectors, tags, scores and positions of entities run inside the VM (emulator.vm.entity_arrays),
pinned to the game's behaviour and checked against the reference backend.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): commands/arguments/selector/EntitySelector.java
(unsorted order, limit), server/commands/TagCommand.java (the count of changed entities; none
fails), server/commands/ScoreboardCommand.java (set: value x targets; enableTrigger), server/
commands/ExecuteCommand.java (if entity counts; store entity ... double), server/commands/data/
DataCommands.java (data get ... scale: Mth.floor).
"""
from __future__ import annotations

import pytest

from emulator.vm import loop as vm
from tests.vm.helpers import emulator_for

SETUP = ("scoreboard objectives add o dummy\nscoreboard objectives add s dummy\n"
         "scoreboard objectives add t trigger\n"
         'summon marker 0 0 0 {Tags:["x","a"]}\nsummon marker 1 0 0 {Tags:["x"]}\n'
         'summon armor_stand 2 0 0 {Tags:["x"]}\nsummon marker 3 0 0 {Tags:["y"]}\n')


def _run_both(tmp_path, body: str, shuffle: int | None = None):
    """Run t:main (SETUP first) on both backends; returns the two emulators after checking they agree."""
    emus = []
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, {"t:main": SETUP + body}, backend=backend)
        if shuffle is not None:
            emu.shuffle = shuffle
            emu.load_parsed(emu.packs)
        emu.call("t:main")
        emus.append(emu)
    numba, python = emus
    assert numba.scores() == python.scores()
    assert numba.entities() == python.entities()
    assert [e.text for e in numba.log] == [e.text for e in python.log]
    return numba


def _score(emu, selector: str, objective: str = "o") -> list:
    return [e["scores"].get(objective) for e in emu.entities(selector)]


def test_execute_as_filters_by_tag_type_and_scores(tmp_path):
    emu = _run_both(tmp_path, "scoreboard players set @e[tag=x] s 1\nscoreboard players set @e[type=marker,tag=a] s 5\n"
                              "execute as @e[tag=x,scores={s=0..2}] run scoreboard players add @s o 1\n"
                              "execute as @e[type=!marker] run scoreboard players add @s o 10\n"
                              "execute as @e[tag=x,tag=!a] run scoreboard players add @s o 100")
    assert _score(emu, "@e") == [None, 101, 111, None]


def test_limit_takes_the_first_in_creation_order_and_shuffle_permutes_it(tmp_path):
    emu = _run_both(tmp_path, "tag @e[tag=x,limit=2] add l")
    assert [("l" in e["tags"]) for e in emu.entities()] == [True, True, False, False]
    for seed in range(4):  # the first two tagged x in the permuted order, whatever it is
        shuffled = _run_both(tmp_path / f"shuffled{seed}", "tag @e[tag=x,limit=2] add l", shuffle=seed)
        assert [("l" in e["tags"]) for e in shuffled.entities("@e[tag=x]")] == [True, True, False]


def test_a_selector_that_finds_nothing_fails_the_command(tmp_path):
    emu = _run_both(tmp_path, "execute store success score #tag o run tag @e[tag=none] add q\n"
                              "execute store success score #set o run scoreboard players set @e[tag=none] o 1\n"
                              "execute store result score #as o run execute as @e[tag=none] run say never")
    # `as` finding nothing leaves no context: nothing runs, so its store never fires
    assert [emu.score(h, "o") for h in ("#tag", "#set", "#as")] == [0, 0, None]


def test_results_count_entities(tmp_path):
    # if entity: the count; tag: the entities changed (none changed fails); set: value x targets
    emu = _run_both(tmp_path, "execute store result score #if o if entity @e[tag=x]\n"
                              "execute store result score #unless o unless entity @e[tag=none]\n"
                              "execute store result score #tag o run tag @e[tag=x] add a\n"
                              "execute store success score #again o run tag @e[tag=a,tag=!x] add a\n"
                              "execute store result score #set o run scoreboard players set @e[tag=x] s 7\n"
                              "execute store result score #reset o run scoreboard players reset @e[tag=x] s")
    assert [emu.score(h, "o") for h in ("#if", "#unless", "#tag", "#again", "#set", "#reset")] == [3, 1, 2, 0, 21, 3]


def test_operation_with_a_selector_on_either_side(tmp_path):
    emu = _run_both(tmp_path, "scoreboard players set #m o 100\n"
                              "execute as @e run scoreboard players operation @s s = @s o\n"
                              "scoreboard players set @e[tag=x,limit=1] o 4\nscoreboard players set @e[tag=y] o -3\n"
                              "scoreboard players operation #m o < @e[scores={o=..10}] o\n"
                              "execute store result score #sum o run scoreboard players operation @e[tag=x] s += @e[tag=y] o")
    assert emu.score("#m", "o") == -3
    assert _score(emu, "@e[tag=x]", "s") == [-3, -3, -3]  # created as 0 (get-or-create), then += -3
    assert emu.score("#sum", "o") == -9


def test_enable_creates_and_unlocks_trigger_scores(tmp_path):
    # enableTrigger: get-or-create, unlock; the count of scores unlocked; none unlocked or a
    # non-trigger objective fails
    emu = _run_both(tmp_path, "execute store result score #first o run scoreboard players enable @e[tag=x] t\n"
                              "execute store success score #again o run scoreboard players enable @e[tag=x] t\n"
                              "execute store success score #dummy o run scoreboard players enable @e[tag=x] s")
    assert [emu.score(h, "o") for h in ("#first", "#again", "#dummy")] == [3, 0, 0]
    assert _score(emu, "@e[tag=x]", "t") == [0, 0, 0]


def test_store_and_read_positions(tmp_path):
    # store ... double: (double)(result * scale), clamped as Entity.load clamps it; data get: Mth.floor
    emu = _run_both(tmp_path, "scoreboard players set #p o -1234567\n"
                              "execute as @e[tag=a] run execute store result entity @s Pos[0] double 0.001 run "
                              "scoreboard players get #p o\n"
                              "execute as @e[tag=a] store result score #x o run data get entity @s Pos[0] 10\n"
                              "execute as @e[tag=a] store result score #floor o run data get entity @s Pos[0]\n"
                              "execute as @e[tag=a] run execute store result entity @s Pos[1] double 100000 run "
                              "scoreboard players set #big o 2000000000")
    pos = emu.entities("@e[tag=a]")[0]["pos"]
    assert pos == [-1234567 * 0.001, 2.0e7, 0.5]  # summoned at 0 0 0: integer x/z are centred (+0.5)
    assert (emu.score("#x", "o"), emu.score("#floor", "o")) == (-12346, -1235)


def test_host_commands_see_vm_changes_and_the_vm_sees_host_changes(tmp_path):
    # tag (VM) -> kill with sort (host); summon (host) -> execute as (VM)
    emu = _run_both(tmp_path, "tag @e[tag=x,tag=!a] add doomed\nkill @e[tag=doomed,sort=nearest,limit=1]\n"
                              'summon marker 9 0 0 {Tags:["x"]}\nexecute as @e[tag=x] run scoreboard players add #n o 1')
    assert emu.score("#n", "o") == 3
    assert len(emu.entities()) == 4


def test_the_forms_compile_to_vm_instructions(tmp_path):
    emu = emulator_for(tmp_path, {"t:main": SETUP + "execute as @e[tag=x,scores={s=0..2}] run tag @s add b\n"
                                              "execute if entity @e[type=marker] run scoreboard players enable @a t\n"
                                              "execute store result entity @s Pos[0] double 0.5 run data get entity @s Pos[1]"})
    emu.call("t:main")
    ops = {row[0] for row in emu.backend.program.rows}
    assert {vm.OP_ASSTAGE, vm.OP_TAG, vm.OP_IFENT, vm.OP_ENABLE, vm.OP_FIELDSTAGE, vm.OP_STOREFIELD, vm.OP_GETFIELD} <= ops
    assert [type(run.node).__name__ for run in emu.backend.host_ops_run()] == ["ObjectivesAdd"] * 3 + ["Summon"] * 4


@pytest.mark.parametrize("selector", ["@e[nbt={}]", "@e[predicate=t:p]",
                                      "@a[advancements={t:a=true}]"])
def test_other_selectors_stay_with_the_host(tmp_path, selector):
    emu = emulator_for(tmp_path, {"t:main": SETUP + f"tag {selector} add z"})
    emu.call("t:main")
    assert [type(run.node).__name__ for run in emu.backend.host_ops_run()][-1] == "TagCommand"


def test_tellraw_needs_a_player(tmp_path):
    # TellRawCommand: the targets are EntityArgument.getPlayers (none found fails the command and
    # nothing is sent); the result is the number of players
    body = ('execute store result score #none o run tellraw @a {"text":"nobody"}\n'
            'execute store result score #one o run tellraw @a[tag=!none] {"text":"hi"}')
    emu = _run_both(tmp_path, body)
    assert (emu.score("#none", "o"), emu.score("#one", "o"), emu.log) == (0, 0, [])
    emu.add_player("Steve")
    emu.call("t:main")
    assert (emu.score("#none", "o"), emu.score("#one", "o")) == (1, 1)
    assert [e.text for e in emu.log] == ['{"text":"nobody"}', '{"text":"hi"}']


def test_a_killed_entity_loses_its_scores(tmp_path):
    # Scoreboard.entityRemoved -> resetAllPlayerScores: it leaves `*` and every objective
    emu = _run_both(tmp_path, "scoreboard players set @e s 4\nkill @e[tag=a]\n"
                              "execute store result score #n o run scoreboard players add * s 0")
    assert emu.score("#n", "o") == 12
    assert sum(len(holders) for holders in emu.scores().values()) == 4  # three entities' s, and #n


def test_teleport_and_execute_at(tmp_path):
    # TeleportCommand.teleportToPos: every target to the same point, integer x/z centred, `~`
    # from the execution position; out of the spawnable bounds fails; `at` takes the entity's position
    emu = _run_both(tmp_path, "tp @e[tag=x] 5 64 -3\n"
                              "execute as @e[tag=a] at @s run tp @e[tag=y] ~1 ~0.5 ~\n"
                              "execute store success score #far o run tp @e[tag=y] 30000000 0 0")
    assert [e["pos"] for e in emu.entities()] == [[5.5, 64.0, -2.5]] * 3 + [[6.5, 64.5, -2.5]]
    assert emu.score("#far", "o") == 0
    ops = {row[0] for row in emu.backend.program.rows}
    assert {vm.OP_TP, vm.OP_ASSTAGE} <= ops
    assert {type(run.node).__name__ for run in emu.backend.host_ops_run()} == {"ObjectivesAdd", "Summon"}


def test_any_number_of_tags_run_in_the_vm(tmp_path):
    # 300 tags interned by the pack (several bitset words): tag commands and tests on the late
    # ones run in the VM, and the host sees them (kill with a sort is a host op)
    adds = "".join(f"tag @e[tag=x] add t{i}\n" for i in range(300))
    emu = _run_both(tmp_path, adds + "tag @e[tag=t299,tag=a] remove t250\n"
                                     "execute as @e[tag=t250,tag=!y] run scoreboard players add @s o 1\n"
                                     "execute as @e[tag=] run scoreboard players add @s o 10\n"
                                     "execute as @e[tag=!] run scoreboard players add @s o 100\n"
                                     "kill @e[tag=t299,tag=!t250,sort=nearest]")
    assert _score(emu, "@e") == [101, 101, 100]  # the first (tag a) was killed
    assert len(emu.entities("@e[tag=x]")[0]["tags"]) == 301
    ops = {type(run.node).__name__ for run in emu.backend.host_ops_run()}
    assert ops == {"ObjectivesAdd", "Summon", "Kill"}


def test_an_entity_holds_at_most_1024_tags_in_the_vm(tmp_path):
    # Entity.addTag: refused once the entity has 1024 tags (TagCommand counts only the added ones)
    adds = "".join(f"tag @e[tag=a] add t{i}\n" for i in range(1030))
    emu = _run_both(tmp_path, adds + "execute store result score #last o run tag @e[tag=x] add last")
    assert len(emu.entities("@e[tag=a]")[0]["tags"]) == 1024
    assert emu.score("#last", "o") == 2  # the two other x entities


# Positions: 0.5 0 0.5 (marker, x a), 1.5 0 0.5 (marker, x), 2.5 0 0.5 (armor stand 0.5 x 1.975, x),
# 3.5 0 0.5 (marker, y). EntitySelector / EntitySelectorParser / EntitySelectorOptions (1.21)
@pytest.mark.parametrize("selector, found", [
    ("@e[distance=..1.5]", 1),  # squared distance to the feet, inclusive, from the context (0 0 0)
    ("@e[distance=1..2]", 1),
    ("@e[x=3,y=0,z=0,distance=..1]", 2),  # the armor stand at 0.5 and the marker at 0.5 horizontally
    ("@e[x=2,y=0,z=0,dx=0,dy=0,dz=0]", 1),  # the box [2, 3] x [0, 1] x [0, 1]: only the armor stand's hitbox
    ("@e[x=1.6,y=0,z=0,dx=0.5,dy=0,dz=0]", 1),  # [1.6, 2.6]: the armor stand's hitbox, not the marker at 1.5
    ("@e[x=2.8,y=-1,z=0,dx=-1,dy=0.5,dz=1]", 2),  # a negative extent: [1.8, 3.8] x [-1, 0.5] x [0, 2]
    ("@e[type=#minecraft:skeletons]", 0),
    ("@e[type=!#minecraft:skeletons,tag=x]", 3),
    ("@e[sort=nearest,limit=2,x=3,y=0,z=0]", 2),
    ("@n[tag=x]", 1),
    ("@p", 0),
])
def test_position_selectors_run_in_the_vm(tmp_path, selector, found):
    emu = _run_both(tmp_path, f"execute store result score #n o if entity {selector}\n"
                              f"execute as {selector} run scoreboard players add @s s 1\n"
                              f"tag {selector} add found")
    assert emu.score("#n", "o") == found
    assert {type(run.node).__name__ for run in emu.backend.host_ops_run()} == {"ObjectivesAdd", "Summon"}


def test_sorted_selectors_keep_the_game_order(tmp_path):
    # sort=nearest|furthest: List.sort (stable) by squared distance, then the limit; @n is nearest, limit 1
    emu = _run_both(tmp_path, "summon marker 2 0 0 {Tags:[\"x\"]}\n"
                              "execute positioned 2 0 0 as @e[sort=nearest,limit=3] run scoreboard players add #near o 1\n"
                              "execute positioned 2 0 0 run tag @e[sort=furthest,limit=2] add far\n"
                              "execute positioned 2 0 0 run tag @n[tag=x,tag=!far] add near\n"
                              "scoreboard players set @e[sort=furthest,x=0,y=0,z=0,tag=x] s 5")
    # from (2.5, 0, 0.5) (positioned centres integers): squared distances 4, 1, 0, 1, 0; ties keep the store's order
    assert [("far" in e["tags"], "near" in e["tags"]) for e in emu.entities()] == [
        (True, False), (True, False), (False, True), (False, False), (False, False)]
    assert emu.score("#near", "o") == 3


def test_contexts_the_vm_made_hold_only_in_their_root(tmp_path):
    """as_cache keeps the contexts a root made (R_ROOT tells roots apart): in the next root, context 1
    is the `positioned` one, which a row left by the last root's `as` must not be taken for."""
    emus = []
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, {
            "t:setup": SETUP, "t:as": "execute as @e[tag=x] run scoreboard players add @s s 1",
            "t:both": "execute positioned 5 0 0 run scoreboard players add #p o 1\n"
                      "execute as @e[tag=x] run scoreboard players add @s s 1"}, backend=backend)
        for function in ("t:setup", "t:as", "t:both", "t:both"):
            emu.call(function)
        emu.tick(3)
        emus.append(emu)
    numba, python = emus
    assert numba.scores() == python.scores()
    assert _score(numba, "@e", "s") == [3, 3, 3, None]
