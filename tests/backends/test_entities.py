"""Entities in the emulator: packs that keep their state on entities run identically on both
backends, and give the numbers the game's own formulas give (computed here with the world
library's float math, :mod:`emulator.world.rotation` / :mod:`emulator.world.stores`)."""
from __future__ import annotations

import dataclasses
import random
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from emulator.api import Emulator
from emulator.commands import data
from emulator.world import nbt_ops, rotation, stores
from emulator.world.entities import EntityStore, entity_nbt
from emulator.world.stores import stored_tag
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command
from mcfunction_parser.reader import Reader
from mcfunction_parser.snbt import compound
from tests.backends.programs import write_pack

F32 = np.float32
SETUP = "scoreboard objectives add v dummy\n"


def run_both(tmp_path: Path, functions: dict[str, str], entry: str = "t:main", players=(), shuffle=None,
             ticks: int = 0):
    """Run ``entry`` on both backends; assert they agree on scores, entities, log, diagnostics and
    cost; return the reference emulator."""
    pack = write_pack(tmp_path / "pack", functions)
    runs = []
    for backend in ("python", "numba"):
        emu = Emulator(backend=backend, shuffle=shuffle)
        emu.load(pack)
        for name, pos, rot in players:
            emu.add_player(name, pos, rot)
        root = emu.runtime.call(entry)
        emu.tick(ticks)
        runs.append((emu, root.cost))
    (ref, ref_cost), (vm, vm_cost) = runs
    assert vm.scores() == ref.scores()
    assert vm.entities() == ref.entities()
    assert [e.text for e in vm.log] == [e.text for e in ref.log]
    assert [d.format() for d in vm.diagnostics] == [d.format() for d in ref.diagnostics]
    assert (vm_cost, vm.commands_per_tick) == (ref_cost, ref.commands_per_tick)
    return ref


def tagged(emu: Emulator, tag: str) -> list[dict]:
    return emu.entities(f"@e[tag={tag}]")


# ---------------------------------------------------------------------- tp ^ at game rotations
ROTATIONS = [(0.0, 0.0), (45.0, 0.0), (90.0, 0.0), (137.5, 0.0), (0.0, 45.0), (137.5, -30.0), (-90.0, 90.0)]
_rng = random.Random(4)
ROTATIONS += [(_rng.uniform(-180, 180), _rng.uniform(-90, 90)) for _ in range(4)]


@pytest.mark.parametrize("yaw,pitch", ROTATIONS)
def test_tp_local_forward_matches_the_game_formula(tmp_path, yaw, pitch):
    # LocalCoordinates.getPosition with Mth.sin/cos (the 65536-entry float table), as the world
    # library computes it; the ball loop moves each ball twice.
    summon = f"summon marker 1.25 64 -3.5 {{Tags:[\"ball\"],Rotation:[{yaw}f,{pitch}f]}}\n"
    loop = "execute as @e[tag=ball] at @s run tp @s ^ ^ ^1\n"
    emu = run_both(tmp_path, {"t:main": SETUP + summon + loop + loop})
    [ball] = tagged(emu, "ball")
    yaw32, pitch32 = F32(yaw), F32(pitch)
    expected = (1.25, 64.0, -3.5)
    for _ in range(2):
        expected = rotation.local_to_world(expected, yaw32, pitch32, 0.0, 0.0, 1.0)
    assert ball["pos"] == list(expected)
    assert ball["rotation"] == [float(F32(yaw)), float(F32(pitch))]


def test_tp_forward_at_yaw_zero_moves_south(tmp_path):
    # yaw 0 looks to +z (Entity.calculateViewVector): ^ ^ ^1 adds 1 to z exactly
    emu = run_both(tmp_path, {"t:main": SETUP + "summon marker 0.5 0 0.5 {Tags:[\"b\"]}\n"
                                                "execute as @e[tag=b] at @s run tp @s ^ ^ ^1"})
    assert tagged(emu, "b")[0]["pos"][2] == 1.5


def test_facing_entity_then_reading_rotation(tmp_path):
    # execute facing entity: CommandSourceStack.facing (Mth.atan2, float rotation); tp ~ ~ ~ ~ ~
    # stores it wrapped (Entity.setYRot/ setXRot via teleportTo), data get Rotation[i] 1000 floors
    body = (SETUP + "summon marker 1 2 3 {Tags:[\"a\"]}\nsummon marker -4.25 7 9.5 {Tags:[\"b\"]}\n"
            "execute as @e[tag=a] at @s facing entity @e[tag=b,limit=1] feet run tp @s ~ ~ ~ ~ ~\n"
            "execute as @e[tag=a] store result score #yaw v run data get entity @s Rotation[0] 1000\n"
            "execute as @e[tag=a] store result score #pitch v run data get entity @s Rotation[1] 1000\n")
    emu = run_both(tmp_path, {"t:main": body})
    yaw, pitch = rotation.teleport_rotation(*rotation.facing_rotation((1.5, 2.0, 3.5), (-4.25, 7.0, 9.5)))
    assert tagged(emu, "a")[0]["rotation"] == [float(yaw), float(pitch)]
    assert emu.score("#yaw", "v") == int(np.floor(float(yaw) * 1000.0))
    assert emu.score("#pitch", "v") == int(np.floor(float(pitch) * 1000.0))


# ---------------------------------------------------------------------- selectors
def test_distance_is_inclusive_at_the_boundary(tmp_path):
    # EntitySelector: distance compares squared distances to the feet, inclusive (MinMaxBounds)
    body = (SETUP + "summon marker 2.0 0 0.5 {Tags:[\"on\"]}\nsummon marker 2.0001 0 0.5 {Tags:[\"past\"]}\n"
            "execute positioned 0.5 0 0.5 store result score #n v if entity @e[distance=..1.5]\n"
            "execute positioned 0.5 0 0.5 store result score #far v if entity @e[distance=1.5..]\n"
            "execute positioned 0.5 0 0.5 store result score #open v if entity @e[distance=1.50001..]\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert (emu.score("#n", "v"), emu.score("#far", "v"), emu.score("#open", "v")) == (1, 2, 1)


def test_box_volumes_use_strict_hitbox_intersection(tmp_path):
    # x/y/z + dx/dy/dz: the box [x, x + dx + 1) per axis; AABB.intersects is strict, so a
    # zero-size marker on the box's faces is outside (EntitySelectorParser.createAabb)
    body = SETUP + "".join(f"summon marker {x} 0.5 0.5 {{Tags:[\"m{i}\"]}}\n" for i, x in enumerate(("0.0", "0.5", "1.0", "1.999", "2.0")))
    body += "execute store result score #dx0 v if entity @e[x=0,y=0,z=0,dx=0,dy=0,dz=0]\n"
    body += "execute store result score #dx1 v if entity @e[x=0,y=0,z=0,dx=1,dy=0,dz=0]\n"
    body += "execute as @e[x=0,y=0,z=0,dx=1,dy=0,dz=0] run tag @s add inside\n"
    emu = run_both(tmp_path, {"t:main": body})
    assert (emu.score("#dx0", "v"), emu.score("#dx1", "v")) == (1, 3)
    assert [e["pos"][0] for e in tagged(emu, "inside")] == [0.5, 1.0, 1.999]


def test_selector_order_with_and_without_sort(tmp_path):
    # unsorted @e: creation order; nearest/furthest: stable sort by distance; @n: the nearest
    body = SETUP + "".join(f"summon marker {x} 0 0 {{Tags:[\"m\"]}}\n" for x in (3, 1, 2, 1))
    body += "execute as @e[tag=m,x=0,y=0,z=0,sort=furthest,limit=2] run tag @s add far\n"
    body += "execute positioned 0 0 0 as @n[tag=m] run tag @s add nearest\n"
    emu = run_both(tmp_path, {"t:main": body})
    by_x = [e["pos"][0] for e in tagged(emu, "m")]
    assert by_x == [3.5, 1.5, 2.5, 1.5]  # creation order
    assert emu.entities("@e[tag=m,sort=nearest]") == [tagged(emu, "m")[i] for i in (1, 3, 2, 0)]
    assert emu.entities("@e[tag=m,sort=furthest]") == [tagged(emu, "m")[i] for i in (0, 2, 1, 3)]
    assert tagged(emu, "nearest") == [tagged(emu, "m")[1]]
    assert [e["pos"][0] for e in tagged(emu, "far")] == [3.5, 2.5]


def test_sorted_selectors_keep_equal_distances_in_their_order_in_the_vm(tmp_path):
    # EntitySelectorParser.ORDER_NEAREST / ORDER_FURTHEST: List.sort by the squared distance, which is
    # stable (TimSort): entities at equal distances stay in the store's order, and a limit keeps the
    # first of them (EntitySelector.sortAndLimit). 21 markers, many ties, numbered in the order
    # `execute as` visits them
    xs = (3, -1, 2, 1, -3, 0, 2, -2, 1, 3, -1, 0, 2, -4, 4, 1, -2, 0, 3, -3, 2)
    body = SETUP + "".join(f"summon marker {x} 0 0 {{Tags:[\"m\"]}}\n" for x in xs)
    functions = {}
    cases = {"a": "sort=nearest", "b": "sort=furthest", "c": "sort=nearest,limit=1", "d": "sort=furthest,limit=1",
             "e": "sort=nearest,limit=5", "f": "sort=furthest,limit=9"}
    for objective, options in cases.items():
        body += (f"scoreboard objectives add {objective} dummy\nscoreboard players set #i v 0\n"
                 f"execute as @e[tag=m,x=0.5,y=0,z=0,{options}] run function t:{objective}\n")
        functions[f"t:{objective}"] = f"scoreboard players add #i v 1\nscoreboard players operation @s {objective} = #i v"
    emu = run_both(tmp_path, {"t:main": body, **functions})
    markers = tagged(emu, "m")
    for objective, options in cases.items():
        order = sorted(range(len(xs)), key=lambda i: abs(xs[i]) * (1 if "nearest" in options else -1))  # stable
        limit = int(options.partition("limit=")[2] or len(xs))
        numbered = [markers[i]["scores"].get(objective) for i in order]
        assert numbered == list(range(1, limit + 1)) + [None] * (len(xs) - limit), options


def test_shuffle_permutes_unsorted_order_and_both_backends_agree(tmp_path):
    body = SETUP + "".join(f"summon marker {x} 0 0 {{Tags:[\"m\"]}}\n" for x in range(8))
    body += "execute as @e[tag=m] run scoreboard players add #i v 1\n"
    body += "execute as @e[tag=m] run scoreboard players operation @s v = #i v\n"
    plain = run_both(tmp_path / "plain", {"t:main": body})
    shuffled = run_both(tmp_path / "shuffled", {"t:main": body}, shuffle=7)
    xs = lambda emu: [e["pos"][0] for e in tagged(emu, "m")]  # noqa: E731
    assert xs(plain) == [x + 0.5 for x in range(8)]
    assert sorted(xs(shuffled)) == xs(plain) and xs(shuffled) != xs(plain)
    # sorting ignores the shuffle
    assert [e["pos"][0] for e in shuffled.entities("@e[tag=m,sort=nearest,x=0,y=0,z=0]")] == xs(plain)


# ---------------------------------------------------------------------- scores and data on entities
def test_scores_on_entities_are_held_by_uuid(tmp_path):
    body = (SETUP + "summon marker 0 0 0 {Tags:[\"ball\"]}\nsummon marker 1 0 0 {Tags:[\"ball\"]}\n"
            "execute as @e[tag=ball] store result score @s v run data get entity @s Pos[0] 100\n"
            "execute as @e[tag=ball,scores={v=100..}] run tag @s add moved\n"
            "scoreboard players add @e[tag=ball] v 1\n")
    emu = run_both(tmp_path, {"t:main": body})
    balls = tagged(emu, "ball")
    assert [b["scores"] for b in balls] == [{"v": 51}, {"v": 151}]
    assert emu.score(balls[1]["uuid"], "v") == 151
    assert [b["uuid"] for b in tagged(emu, "moved")] == [balls[1]["uuid"]]


STORE_VALUES = [(300, "byte", 1.0), (-129, "byte", 1.0), (40000, "short", 1.0), (7, "int", 0.5),
                (-7, "int", 0.5), (2147483647, "int", 2.0), (2147483647, "long", 2.0), (3, "float", 0.1),
                (3, "double", 0.1), (-2147483648, "short", 1.0)]


@pytest.mark.parametrize("value,type_name,scale", STORE_VALUES)
def test_every_store_cast_into_entity_nbt(tmp_path, value, type_name, scale):
    # ExecuteCommand.storeData: (TYPE)(value * scale) with Java's narrowing; read back unscaled
    body = (SETUP + f"scoreboard players set #x v {value}\nsummon marker 0 0 0 {{Tags:[\"m\"]}}\n"
            f"execute as @e[tag=m] store result entity @s data.n {type_name} {scale} run scoreboard players get #x v\n"
            "execute as @e[tag=m] store result score #back v run data get entity @s data.n 1000\n")
    emu = run_both(tmp_path, {"t:main": body})
    stored = float(stored_tag(type_name, value, scale))
    assert emu.score("#back", "v") == max(-2**31, min(2**31 - 1, int(np.floor(stored * 1000.0))))


def test_store_cast_pins(tmp_path):
    # (byte) 300 = 44, (short) 40000 = -25536, (int) 3.5 = 3, (int) -3.5 = -3 (truncation)
    assert [int(stored_tag(*args)) for args in (("byte", 300, 1.0), ("short", 40000, 1.0),
                                                ("int", 7, 0.5), ("int", -7, 0.5))] == [44, -25536, 3, -3]


def test_entity_data_modify_and_storage_round_trip(tmp_path):
    body = (SETUP + "summon marker 1 2 3 {Tags:[\"m\"],data:{speed:5}}\n"
            "data modify storage t:s pos set from entity @e[tag=m,limit=1] Pos\n"
            "execute store result score #len v run data get storage t:s pos\n"
            "data modify entity @e[tag=m,limit=1] data.speed set value 9\n"
            "execute store result score #speed v run data get entity @e[tag=m,limit=1] data.speed\n"
            "data merge entity @e[tag=m,limit=1] {Tags:[\"m\",\"merged\"]}\n"
            "execute store result score #has v if data entity @e[tag=merged,limit=1] data.speed\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert (emu.score("#len", "v"), emu.score("#speed", "v"), emu.score("#has", "v")) == (3, 9, 1)


# ---------------------------------------------------------------------- failures
def test_a_selector_matching_nothing_fails_and_store_stores_zero(tmp_path):
    body = (SETUP + "scoreboard players set #r v 5\nscoreboard players set #s v 5\n"
            "execute store result score #r v run kill @e[tag=none]\n"
            "execute store success score #s v run tp @e[tag=none] 0 0 0\n"
            "execute store result score #t v run tag @e[tag=none] add x\n"
            "summon marker 0 0 0 {Tags:[\"m\"]}\n"
            "execute store success score #bad v run data get entity @e[tag=m,limit=1] no.such.path\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert [emu.score(h, "v") for h in ("#r", "#s", "#t", "#bad")] == [0, 0, 0, 0]
    assert emu.diagnostics == []  # routine failures are silent, as in the game


def test_every_type_has_its_size_and_unknown_predicate_matches_nothing(tmp_path):
    # allay has its size from the game's EntityType table (0.35 x 0.6, eyes at 0.36), so no
    # warning; an id the game doesn't know (foo:bar) is refused when the function loads
    # (ResourceArgument: ERROR_UNKNOWN_RESOURCE). EntitySelectorOptions "predicate": an id with no
    # loaded predicate matches no entity, silently
    assert parse_command("summon foo:bar", Loc("t", 1, 1), (1, 21, 0))[0] is None
    body = SETUP + "summon allay 0 0 0\nexecute store result score #p v if entity @e[predicate=t:p]\n"
    emu = run_both(tmp_path, {"t:main": body})
    assert [e["type"] for e in emu.entities()] == ["minecraft:allay"]
    assert emu.diagnostics == []
    assert emu.score("#p", "v") == 0


def test_stale_fork_context_does_not_leak_into_the_next_command(tmp_path):
    # after `execute ... at @s run ...` the next line runs at the function's own position again
    body = (SETUP + "summon marker 0 0 5 {Tags:[\"b\"]}\nsummon marker 0 0 9 {Tags:[\"b\"]}\n"
            "execute as @e[tag=b] at @s run say x\nsummon pig\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert [e["pos"] for e in emu.entities("@e[type=pig]")] == [[0.0, 0.0, 0.0]]


# ---------------------------------------------------------------------- players and blocks
def test_players_and_call_as(tmp_path):
    functions = {"t:main": SETUP + "execute as @a at @s run summon marker ^ ^ ^2 {Tags:[\"m\"]}",
                 "t:me": "scoreboard players set @s v 3\ntp @s ~ ~1 ~"}
    emu = run_both(tmp_path, functions, players=[("Alex", (0.5, 64, 0.5), (90.0, 0.0))])
    [marker] = tagged(emu, "m")
    assert marker["pos"] == list(rotation.local_to_world((0.5, 64.0, 0.5), F32(90), F32(0), 0.0, 0.0, 2.0))
    emu.call("t:me", as_="Alex")
    [alex] = emu.entities("Alex")
    assert alex["scores"] == {"v": 3} and alex["pos"] == [0.5, 65.0, 0.5] and alex["name"] == "Alex"


def test_blocks_setblock_fill_and_if_block(tmp_path):
    body = (SETUP + "fill 0 0 0 2 0 2 stone\nsetblock 1 0 1 minecraft:gold_block\n"
            "execute store result score #stone v if blocks 0 0 0 2 0 2 0 0 0 all\n"
            "execute store success score #gold v if block 1 0 1 gold_block\n"
            "execute store success score #air v if block 1 1 1 air\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert (emu.score("#stone", "v"), emu.score("#gold", "v"), emu.score("#air", "v")) == (9, 1, 1)


def test_each_stage_sees_every_context_before_any_command_runs(tmp_path):
    # BuildContexts applies a stage to all contexts, then queues the command per context: the
    # `if` below is tested for the three markers before any increments #x (so all three run)
    body = (SETUP + "".join(f"summon marker {x} 0 0 {{Tags:[\"m\"]}}\n" for x in range(3))
            + "scoreboard players set #x v 0\n"
            "execute as @e[tag=m] if score #x v matches 0 run scoreboard players add #x v 1\n"
            "scoreboard players set #y v 0\n"
            "execute as @e[tag=m] as @e[tag=m] if score #y v matches 0 run function t:inc\n")
    emu = run_both(tmp_path, {"t:main": body, "t:inc": "scoreboard players add #y v 1"})
    assert (emu.score("#x", "v"), emu.score("#y", "v")) == (3, 9)


def test_self_scores_run_in_the_vm_and_fail_for_the_server(tmp_path):
    # `@s` as a holder is the executor's UUID; run by the server it finds no entity: the command
    # fails silently (ScoreHolderArgument), a condition stage drops the context
    body = (SETUP + "summon marker 0 0 0 {Tags:[\"m\"]}\nsummon marker 1 0 0 {Tags:[\"m\"]}\n"
            "scoreboard players set #two v 2\n"
            "execute as @e[tag=m] run scoreboard players set @s v 5\n"
            "execute as @e[tag=m] run scoreboard players operation @s v += #two v\n"
            "execute as @e[tag=m] if score @s v matches 7 run scoreboard players add #seven v 1\n"
            "execute as @e[tag=m] if score @s v = @s v store result score #got v run scoreboard players get @s v\n"
            "execute store success score #server v run scoreboard players set @s v 1\n"
            "execute store success score #op v run scoreboard players operation #two v += @s v\n"
            "execute store success score #if v if score @s v matches 7\n"
            "execute if score @s v matches 7 run scoreboard players set #ran v 1\n"
            "execute as @e[tag=m] run scoreboard players reset @s v\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert [emu.score(h, "v") for h in ("#seven", "#got", "#server", "#op", "#if", "#ran", "#two")] == [
        2, 7, 0, 0, 0, None, 2]
    assert [e["scores"] for e in tagged(emu, "m")] == [{}, {}]
    assert emu.diagnostics == []


def test_context_stages_from_entities(tmp_path):
    # positioned as / rotated as / execute summon / on (no relations here) / kill then @s
    body = (SETUP + "summon marker 3.25 4 5.75 {Tags:[\"a\"],Rotation:[30f,-20f]}\n"
            "execute positioned as @e[tag=a] run summon marker ~ ~1 ~ {Tags:[\"above\"]}\n"
            "execute rotated as @e[tag=a] positioned 0 0 0 run summon marker ^ ^ ^2 {Tags:[\"ahead\"]}\n"
            "execute summon marker run tag @s add made\n"
            "execute store result score #on v as @e[tag=a] on vehicle run say never\n"
            "execute as @e[tag=made] run kill @s\n"
            "execute store result score #made v if entity @e[tag=made]\n"
            "execute as @e[tag=a] at @s run tp @s ~ ~ ~ facing 0 4 0\n"
            "execute as @e[tag=a] at @s run tp @s ^1 ^ ^\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert tagged(emu, "above")[0]["pos"] == [3.25, 5.0, 5.75]
    ahead = rotation.local_to_world((0.5, 0.0, 0.5), F32(30), F32(-20), 0.0, 0.0, 2.0)  # 0 0 0 is centred
    assert tagged(emu, "ahead")[0]["pos"] == list(ahead)
    assert (emu.score("#on", "v"), emu.score("#made", "v")) == (None, 0)  # no context: nothing stored
    yaw, pitch = rotation.teleport_rotation(*rotation.facing_rotation((3.25, 4.0, 5.75), (0.5, 4.0, 0.5)))
    [a] = tagged(emu, "a")
    assert a["rotation"] == [float(yaw), float(pitch)]
    assert a["pos"] == list(rotation.local_to_world((3.25, 4.0, 5.75), yaw, pitch, 1.0, 0.0, 0.0))


def test_self_tags_run_in_the_vm_and_agree(tmp_path):
    # `tag @s add|remove` fails when nothing changes (TagCommand); `if entity @s[tag=..]` tests the
    # executor only, alive or not; the server has no @s
    body = (SETUP + "summon marker 0 0 0 {Tags:[\"m\",\"x\"]}\nsummon marker 1 0 0 {Tags:[\"m\"]}\n"
            "execute as @e[tag=m] store success score @s v run tag @s add x\n"
            "execute as @e[tag=m] if entity @s[tag=x,tag=!y] run tag @s add y\n"
            "execute as @e[tag=m] unless entity @s[tag=y] run scoreboard players add #bad v 1\n"
            "execute as @e[tag=m,limit=1] run tag @s remove x\n"
            "execute store result score #xs v if entity @e[tag=x]\n"
            "execute store success score #server v run tag @s add z\n"
            "execute store success score #sif v if entity @s[tag=x]\n"
            "execute as @e[tag=m] store result score @s v if entity @s[tag=!x]\n"
            "data merge entity @e[tag=m,limit=1] {Tags:[\"m\",\"w\"]}\n"
            "execute as @e[tag=m] if entity @s[tag=w] run tag @s add seen\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert [(e["tags"], e["scores"]) for e in tagged(emu, "m")] == [
        (["m", "seen", "w"], {"v": 1}), (["m", "x", "y"], {"v": 0})]
    assert [emu.score(h, "v") for h in ("#bad", "#xs", "#server", "#sif")] == [None, 1, 0, 0]


def test_execute_summon_is_a_redirect_not_a_fork(tmp_path):
    # ExecuteCommand registers `summon` with redirect (not fork): a later stage's error fails the
    # whole command and the stages after it are not charged, as without summon
    body = (SETUP + "execute summon marker store result score @s nope positioned ~ ~ ~ rotated 0 0 run say x\n"
            "execute summon marker store result score @s v positioned ~ ~ ~ run say y\n")
    emu = run_both(tmp_path, {"t:main": body})
    assert [e.text for e in emu.log] == ["[Marker] y"] and len(emu.entities()) == 2


# ---------------------------------------------------------------------- the Pos store shortcut
SUMMONS = [("minecraft:marker", '{data:{k:1b},Tags:["a"]}'), ("minecraft:item_display",
           '{teleport_duration:1,item:{id:"minecraft:stone",count:1},transformation:{left_rotation:[0f,0f,0f,1f],'
           'right_rotation:[0f,0f,0f,1f],translation:[0f,0.5f,0f],scale:[0.057f,0.057f,0.057f]},Rotation:[370f,-20f]}'),
           ("minecraft:armor_stand", '{Motion:[0.5d,12.0d,0.0d],NoGravity:1b,CustomName:\'"x"\'}'),
           ("minecraft:pig", "{}"), ("minecraft:text_display", '{text:\'"hi"\',brightness:{sky:3,block:4}}')]


@settings(max_examples=150, deadline=None)
@given(kind=st.sampled_from(SUMMONS), axis=st.integers(0, 2), value=st.integers(-2**31, 2**31 - 1),
       scale=st.sampled_from([0.001, 1.0, -0.5, 1e3, 1e300, float("inf")]))
def test_position_store_shortcut_equals_the_full_round_trip(kind, axis, value, scale):
    # ExecuteCommand.storeData through EntityDataAccessor: save, set Pos[i], load
    type_id, snbt = kind
    stores_ = [EntityStore(seed=1), EntityStore(seed=1)]
    nbt = compound(Reader(snbt, Loc("t", 1, 1), (1, 21, 0)))
    slow, fast = (s.summon(type_id, (1.5, 64.0, -2.25), nbt) for s in stores_)
    cmd, _ = parse_command(f"execute store result entity @s Pos[{axis}] double 1 run say x", Loc("t", 1, 1))
    sub = dataclasses.replace(cmd.subcommands[0], scale=scale)
    data.EntityAccessor(slow, stores_[0]).change(lambda root: stores.store(root, sub.path, "double", value, sub.scale))
    data.store(data.EntityAccessor(fast, stores_[1]), sub, value)
    assert fast.pos == slow.pos
    assert nbt_ops.tags_equal(entity_nbt(fast), entity_nbt(slow))
    assert (fast.yaw, fast.pitch, fast.motion, fast.tags) == (slow.yaw, slow.pitch, slow.motion, slow.tags)



# ---------------------------------------------------------------------- wrapped rotation ranges
def test_a_rotation_range_whose_minimum_is_bigger_goes_round_through_180(tmp_path):
    # WrappedMinMaxBounds.fromReader accepts 135..-135, and EntitySelector's rotation predicate
    # matches f >= min || f <= max when min > max: the half turn through 180 degrees
    functions = {"t:main": SETUP + "\n".join(
        f"summon marker 0 0 0 {{Tags:[\"m\"],Rotation:[{yaw}f,0f]}}" for yaw in (180, -170, 140, 0, 90, -100)
    ) + "\nexecute store result score #n v if entity @e[tag=m,y_rotation=135..-135]"
        "\nexecute store result score #p v if entity @e[tag=m,x_rotation=80..-80]"}
    emu = run_both(tmp_path, functions)
    assert emu.score("#n", "v") == 3  # 180, -170, 140
    assert emu.score("#p", "v") == 0  # every pitch is 0, outside 80..180 and -180..-80


def test_block_nbt_with_a_quoted_space_is_read_whole(tmp_path):
    # BlockStateParser reads a block's {nbt} with the SNBT parser: a quoted string may hold spaces
    functions = {"t:main": SETUP + 'setblock 0 64 0 chest{CustomName:"a b"}\n'
                 'execute store success score #found v if block 0 64 0 chest{CustomName:"a b"}\n'
                 'execute store success score #other v if block 0 64 0 chest{CustomName:"a c"}\n'
                 'fill 1 64 0 2 64 0 barrel{CustomName:"x y"} replace air\n'
                 'execute store success score #filled v if block 2 64 0 barrel{CustomName:"x y"}'}
    emu = run_both(tmp_path, functions)
    assert (emu.score("#found", "v"), emu.score("#other", "v"), emu.score("#filled", "v")) == (1, 0, 1)
    assert emu.diagnostics == []
