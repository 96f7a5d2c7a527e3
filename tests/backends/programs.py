"""Datapack writing helpers and hypothesis strategies for random scoreboard programs.

``write_pack`` turns ``{function id: text}`` into a 1.21 pack folder. ``programs()`` draws a
:class:`Program`: several functions in namespace ``t`` that set, add, operate on, compare, store,
return, say and call each other (``function``, ``execute if|unless function``, ``return run``),
plus leaf functions reached through the tag ``#t:leaves``, a macro function ``t:mac`` (also in the
tag ``#t:macs``) and one counted self-recursive loop. Lines also schedule functions, set and query
gamerules, read and write command storage, write and read a read-only (``health``) objective and
log with ``say``/``tellraw``. Calls only go to later functions, leaves, the macro or the loop, so
every program ends.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from hypothesis import strategies as st

from mcfunction_parser.nbt import to_snbt

INT_MIN, INT_MAX = -(2**31), 2**31 - 1

HOLDERS = ("#a", "#b", "#c", "$d", "e")
OBJECTIVES = ("o", "p")
OPERATIONS = ("=", "+=", "-=", "*=", "/=", "%=", "<", ">", "><")
COMPARISONS = ("<", "<=", "=", ">=", ">")
INTERESTING = (INT_MIN, INT_MIN + 1, -65536, -7, -2, -1, 0, 1, 2, 3, 7, 46341, 65536, INT_MAX - 1, INT_MAX)


def write_pack(root: Path, functions: dict[str, str], tags: dict[str, list[str]] | None = None,
               pack_format: int = 48, files: dict[str, str] | None = None) -> Path:
    """Write a pack: ``functions`` maps ``ns:path`` to the file text; ``tags`` maps a function
    tag id to its values; ``files`` maps other paths under ``data/`` to their text."""
    root.mkdir(parents=True, exist_ok=True)
    for path, text in (files or {}).items():
        file = root / "data" / path
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(text)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": "test"}}))
    for fid, text in functions.items():
        ns, path = fid.split(":", 1)
        file = root / "data" / ns / "function" / f"{path}.mcfunction"
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(text if text.endswith("\n") else text + "\n")
    for tid, values in (tags or {}).items():
        ns, path = tid.split(":", 1)
        file = root / "data" / ns / "tags" / "function" / f"{path}.json"
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(json.dumps({"values": values}))
    return root


@dataclass(frozen=True)
class Program:
    functions: dict[str, str]
    tags: dict[str, list[str]]
    entry: str = "t:f0"
    files: dict[str, str] = field(default_factory=dict)  # other files under data/ (predicates)

    def text(self) -> str:
        tags = "".join(f"# tag {tid}: {values}\n" for tid, values in self.tags.items())
        return tags + "\n".join(f"# {fid}\n{body}" for fid, body in self.functions.items())


objectives = st.sampled_from(OBJECTIVES)
ints = st.one_of(st.sampled_from(INTERESTING), st.integers(INT_MIN, INT_MAX), st.integers(-20, 20))
non_negative = st.one_of(st.sampled_from((0, 1, 2, 7, 65536, INT_MAX)), st.integers(0, INT_MAX))

# Stages that change the context but not the scores (``as @e`` with no entities: 0 contexts)
MODIFIERS = ("positioned ~1 ~ ~-2", "align xz", "anchored eyes", "rotated 90 0", "in minecraft:the_nether", "as @e")
# With entities: three markers summoned by t:f0, tagged m+a, m, n, an armor stand tagged m, a
# marker tagged m in the nether (selectors with a position, volume or distance search the context's
# level only), an item display tagged d, an armor stand tagged v carrying two markers tagged r (one
# also m), and a trigger objective t
ENTITY_SETUP = ('summon marker ~ ~ ~ {Tags:["m","a"]}', 'summon marker ~2 ~ ~ {Tags:["m"],CustomName:\'"Bob"\',Rotation:[170f,45f]}',
                'summon marker ~ ~1 ~5 {Tags:["n"]}', 'summon armor_stand ~1 ~ ~1 {Tags:["m"]}',
                'execute in minecraft:the_nether run summon marker ~ ~ ~1 {Tags:["m","nether"]}',
                'summon item_display ~-1 ~ ~ {Tags:["d"],Rotation:[30f,10f]}',
                'summon armor_stand ~-2 ~ ~ {Tags:["v"],Passengers:[{id:"marker",Tags:["m","r"]},{id:"marker",Tags:["r"]}]}',
                "scoreboard objectives add t trigger")
# (the VM evaluates @e/@a/@s/@p/@n with type, #type, tag, scores, name, team, gamemode, level, rotations,
# x/y/z, volumes, distance, limit and sort nearest/furthest itself; random sorts, nbt ... go to the host)
ENTITY_MODIFIERS = ("as @e[tag=m]", "at @e[tag=m]", "as @e[tag=a]", "as @e[type=marker,sort=nearest,limit=2]",
                    "positioned as @e[tag=n]", "as @e[tag=m] at @s", "as @e[sort=furthest]",
                    "as @e[tag=m,tag=!a]", "as @e[type=marker,scores={o=0..}]", "as @e[type=!marker]",
                    "as @e[tag=m,limit=2]", "as @s[tag=m]", "as @e[scores={o=..3,p=-5..}]",
                    "rotated as @e[type=armor_stand]", "positioned as @s", "as @e[distance=..2.5]",
                    "at @e[distance=1..,sort=nearest,limit=2]", "as @e[x=0,y=0,z=0,dx=2,dy=1,dz=5]",
                    "as @e[dx=-1,dy=0,dz=1,tag=m]", "as @n[tag=m]", "as @e[type=!#minecraft:skeletons,tag=]",
                    "as @e[tag=w69]", "positioned ^1 ^ ^2", "rotated 30 10", "as @e[tag=!] at @s",
                    "in minecraft:the_nether", "at @e[tag=nether]", "as @e[tag=m,distance=0..]",
                    "in minecraft:the_end as @e[x=0,sort=furthest]", "as @e[tag=m] positioned as @e[tag=nether]",
                    "rotated ~10 ~-95", "align xyz", "anchored eyes positioned ^ ^ ^1", "anchored feet",
                    "at @e[tag=d] rotated ~ ~20 align y", "as @e[name=Bob]", "as @e[name=!Marker,tag=m]",
                    "as @e[y_rotation=135..-135]", "as @e[x_rotation=..10,y_rotation=-30..]", "as @e[team=]",
                    "as @e[team=!t,type=!marker]", "as @e[gamemode=!creative]", "as @a[level=1..]",
                    "as @e[tag=m,sort=random,limit=2]", "at @e[sort=random]", "as @r",
                    "facing 1 -2 3", "as @e[tag=m] at @s facing ^1 ^ ^-2", "anchored eyes facing ~1 ~2 ~-3",
                    "facing entity @e[tag=m] eyes", "as @e[tag=n] at @s facing entity @e[type=armor_stand] feet",
                    "at @e[tag=d] anchored eyes facing entity @e[tag=!d,sort=nearest,limit=2] eyes",
                    "facing entity @s feet", "on vehicle", "as @e on passengers", "as @e[tag=r] on vehicle at @s",
                    "as @e[type=armor_stand] on passengers on vehicle")
# Predicates (data/t/predicate/*.json) read by `predicate=` and `if predicate`: the VM evaluates
# those whose conditions read the entity table and the scores (emulator.vm.predicate_rows), the
# host the rest (nbt, a reference to itself, a random chance)
PREDICATES = {
    "marker": {"condition": "entity_properties", "entity": "this", "predicate": {"type": "minecraft:marker"}},
    "not_marker": {"condition": "inverted", "term": {"condition": "reference", "name": "t:marker"}},
    "types": {"condition": "entity_properties", "entity": "this",
              "predicate": {"type": ["armor_stand", "minecraft:item_display"]}},
    "skeletons": {"condition": "entity_properties", "entity": "this", "predicate": {"type": "#minecraft:skeletons"}},
    "scores": {"condition": "entity_scores", "entity": "this", "scores": {"o": {"min": -5, "max": 5}, "p": 3}},
    "o_set": {"condition": "entity_scores", "entity": "this", "scores": {"o": {}}},
    "stand_or_o": {"condition": "any_of", "terms": [
        {"condition": "entity_properties", "entity": "this", "predicate": {"type": "armor_stand"}},
        {"condition": "entity_scores", "entity": "this", "scores": {"o": {"min": 1}}}]},
    "all": [{"condition": "reference", "name": "t:marker"}, {"condition": "all_of", "terms": []},
            {"condition": "inverted", "term": {"condition": "any_of", "terms": []}}],
    "entity": {"condition": "entity_properties", "entity": "this", "predicate": {}},
    "any_entity": {"condition": "entity_properties", "entity": "this"},
    "team": {"condition": "entity_properties", "entity": "this", "predicate": {"team": "t"}},
    "creative": {"condition": "entity_properties", "entity": "this",
                 "predicate": {"type_specific": {"type": "player", "gamemode": ["creative", "spectator"]}}},
    "nbt": {"condition": "entity_properties", "entity": "this", "predicate": {"nbt": "{Tags:[\"a\"]}"}},
    "loop": {"condition": "all_of", "terms": [{"condition": "reference", "name": "t:loop"}]},
}
PREDICATE_FILES = {f"t/predicate/{name}.json": json.dumps(value) for name, value in PREDICATES.items()}
ENTITY_MODIFIERS += ("as @e[predicate=t:marker]", "as @e[predicate=!t:not_marker,tag=m]", "as @e[predicate=t:types]",
                     "as @e[predicate=t:stand_or_o] at @s", "as @e[predicate=t:all,predicate=!t:scores]",
                     "as @e[predicate=t:nbt]", "as @e[predicate=!t:o_set,sort=nearest]", "if predicate t:scores",
                     "unless predicate t:stand_or_o", "if predicate t:entity", "if predicate t:any_entity",
                     "as @e[predicate=t:skeletons]", "unless predicate t:team", "if predicate t:creative",
                     "if predicate t:loop", "as @e[tag=q,nbt={}]", "as @e[tag=n,predicate=t:loop]",
                     "as @e[tag=zz,predicate=t:loop]", "at @e[predicate=t:loop,tag=zz]", "unless entity @a[nbt={}]",
                     "as @r[predicate=t:nbt]", "if entity @e[tag=zz,tag=!a,nbt={Tags:[]}]",
                     "positioned as @n[tag=m,predicate=t:nbt,sort=random]", "as @s[tag=a,advancements={t:x=true}]",
                     'if predicate {condition:"entity_scores",entity:"this",scores:{o:{min:1}}}',
                     'unless predicate [{condition:"reference",name:"t:marker"},{condition:"inverted",term:{condition:"any_of",terms:[]}}]',
                     'if predicate {condition:"entity_properties",entity:"this",predicate:{nbt:"{}"}}')
SINGLE_ENTITY_HOLDERS = ("@s", "@e[tag=n,limit=1]", "@e[tag=m,sort=nearest,limit=1]", "@e[tag=m,sort=random,limit=1]")
MULTI_ENTITY_HOLDERS = ("@e[tag=m]", "@e[tag=m,scores={o=..5}]", "@e[type=marker,limit=2]", "@e[tag=!n]",
                        "@e[sort=random,limit=2]")
ENTITY_COMMANDS = ("tag @s add a", "scoreboard players enable * t", "tag @s remove a", "tag @e[tag=n] add m", "kill @e[tag=a,limit=1]",
                   'summon marker ~ ~ ~ {Tags:["n"]}', "scoreboard players add @e[tag=m] o 3",
                   "tag @e[tag=m,tag=!a] add a", "tag @e[scores={o=1..}] remove m", "tag @e[type=armor_stand] add n",
                   "scoreboard players operation #a o < @e[tag=m] o", "scoreboard players reset @e[tag=a] o",
                   "scoreboard players operation @e[tag=m] o += @e[tag=n] p", "scoreboard players enable @e[tag=m] t",
                   "execute store result entity @s Pos[0] double 0.5 run scoreboard players get #a o",
                   "execute store success entity @s Pos[1] double 2 if entity @e[tag=a]",
                   "execute store result score #b o run data get entity @s Pos[0] 100",
                   "execute store result score #c p run data get entity @s Pos[1]",
                   "tp @s ~1 ~ ~-0.5", "tp @e[tag=n] 3 4.5 -2", "execute at @s run tp @e[tag=a] ~ ~1 ~",
                   "tp @s 40000000 0 0", "execute at @e[tag=m] run tp @s ~ ~ ~0.25",
                   "execute store result score @s o run scoreboard players add #a o 1",
                   "execute store success score @s p if score @s o matches 1.. run scoreboard players get #a o",
                   'tellraw @a {"text":"hi"}', 'execute store result score #t o run tellraw @a[tag=!x] "x"',
                   "data modify entity @s data.v set value 3", "execute store result score #d o run data get entity @s data.v",
                   "execute store result entity @e[tag=n,limit=1] data.v int 2 run scoreboard players get #a o",
                   'data merge entity @e[tag=a,limit=1] {Tags:["m","a","q"]}', "scoreboard players set @e[tag=m,sort=nearest] hp 3",
                   "ride @e[tag=n,limit=1] mount @e[type=armor_stand,limit=1]", "ride @s dismount",
                   "tag @e[distance=..3] add q", "tag @e[dx=1,dy=1,dz=1,tag=!a] remove m",
                   "scoreboard players add @n[tag=m] o 1", "tag @e[sort=furthest,limit=1] add far",
                   "execute as @e[tag=m] run function t:wide", "tag @e[tag=w5,tag=!w68] remove w69",
                   "tp @s ^ ^ ^1", "tp @s ^0.5 ^-1 ^", "execute as @e[tag=n] at @s run tp @s ^ ^ ^-0.25",
                   "tp @e[x=0,y=0,z=0,distance=..4] ~ ~0.5 ~", "execute in minecraft:the_nether run tp @s ~ ~ ~1",
                   "execute in minecraft:the_end run tp @e[tag=n] ~ ~ ~", "tp @s @e[tag=nether,limit=1]",
                   'execute in minecraft:the_end run summon marker ~ ~ ~ {Tags:["m","n"]}',
                   "execute if dimension minecraft:the_nether run tag @s add q",
                   # numeric fields the entity table keeps: a display's transformation, Rotation, Motion
                   "execute as @e[tag=d] store result entity @s transformation.scale[1] float 0.125 run "
                   "scoreboard players get #a o",
                   "execute store result entity @s transformation.translation[0] float -0.5 run scoreboard players get #a o",
                   "execute store success entity @s transformation.left_rotation[-1] double 3 if entity @e[tag=a]",
                   "execute store result entity @s Rotation[0] float 1 run scoreboard players get #a o",
                   "execute store success entity @s Rotation[1] float 1000000000000000000000000000000000000000 if entity @e[tag=a]",
                   "execute store result entity @s Motion[2] double 0.01 run scoreboard players get #a o",
                   "execute store result entity @s Motion[0] int 1 run scoreboard players get #a o",
                   "execute store result score #e o run data get entity @s transformation.scale[1] 1000",
                   "execute as @e[tag=d] store result score @s p run data get entity @s transformation.scale[1] 1000",
                   "execute store result score #f o run data get entity @s Rotation[0] 10",
                   "execute store result score #g p run data get entity @s Motion[-1] 100",
                   "execute as @e[tag=d] run data get entity @s transformation.right_rotation[3]",
                   "tp @s ~ ~ ~ ~180 ~", "tp @e[tag=n] 1 2 3 45 -100", "tp @e[tag=m] ~ ~ ~ ~-370.5 ~95",
                   "execute rotated as @e[tag=m] run tp @s ^ ^ ^1 ~ ~10", "tag @e[name=Bob,y_rotation=..90] add q",
                   "data merge entity @s {CustomName:'\"Bob\"'}", "scoreboard players add @e[x_rotation=-45..45] o 1",
                   "tp @s ~ ~ ~ 1000000000000000000000000000000000000000 0",
                   "execute facing 0 1 0 run tp @s ~ ~ ~ ~ ~", "execute at @s facing entity @e[tag=n] eyes run tp @s ~ ~ ~ ~ ~1",
                   "tp @e[tag=m] ~ ~1 ~ facing 0 0 0", "execute anchored eyes run tp @s ^ ^ ^1 facing ~1 ~ ~",
                   "tp @e[tag=n] ~ ~ ~ facing entity @n[tag=m] eyes", "tp @s @n[type=armor_stand]",
                   "tp @e[tag=m] @e[tag=n,limit=1]", "execute as @e[tag=nether] run tp @s @e[tag=m,limit=1,sort=nearest]",
                   "tp @e[tag=a] ~ ~ ~ facing entity @e[tag=zz,limit=1] feet", "tp @s ~ ~ ~ facing entity @s feet",
                   "tp @n[tag=d]", "execute store success score #t o run tp @e[tag=n] 0 -30000000 0",
                   "execute store result score #u o run tp @e[tag=m] ~ ~ ~ facing entity @n[tag=d] feet")
# t:wide: 70 tags, so that some live past the first word of the VM's tag bitsets
WIDE_TAGS = "\n".join(f"tag @s add w{i}" for i in range(70))


# Server commands whose results and effects (schedules, gamerules, objectives, the log) are compared; `0t`
# fails (ScheduleCommand)
SERVER_COMMANDS = ("say hi", 'tellraw @a "x"', "schedule function t:leaf0 1t", "schedule function t:leaf0 0t",
                   "schedule function t:leaf1 3t append", "schedule function t:leaf1 3t append",
                   "schedule function #t:leaves 2t replace", "schedule function t:leaf0 5t replace",
                   "schedule clear t:leaf0", "schedule clear #t:leaves", "schedule clear t:nothing",
                   "gamerule randomTickSpeed 7", "gamerule randomTickSpeed", "gamerule doDaylightCycle false",
                   "gamerule doDaylightCycle", "scoreboard objectives add q dummy",
                   "scoreboard players add #q q 4", "scoreboard objectives remove q", "scoreboard objectives add o dummy",
                   "execute store result score #q o run scoreboard objectives add q dummy",
                   "execute store result score #q p run scoreboard objectives remove q", "scoreboard players add * q 1")
# Command storage t:s: data commands, `if data`, `data get` into scores
STORAGE_COMMANDS = ("data merge storage t:s {a:1,l:[1,2]}", "data modify storage t:s l append value 3",
                    "data remove storage t:s a", "data modify storage t:s v set from storage t:s l[0]",
                    "data modify storage t:s l prepend from storage t:s n", "data get storage t:s l",
                    "data get storage t:s missing", "data remove storage t:s l[0]", "data get storage t:s",
                    "data modify storage t:s w set string storage t:s v", "data get storage t:s n 3",
                    "data get storage t:s d -0.5", "data modify storage t:s f set value 1b",
                    "data modify storage t:s d set value 0.5d",
                    # list elements (their numbers mirrored by the VM; l[0] and l[-1] may be one number)
                    "data get storage t:s l[0]", "data get storage t:s l[-1] 2", "data modify storage t:s l[1] set value 7",
                    "data modify storage t:s l[0] set value 2.5d", "data modify storage t:s l[-1] set value 4",
                    "data merge storage t:s {m:[{x:1},{x:2b}],ia:[I;5,6]}", "data get storage t:s m[-1].x 3",
                    "data modify storage t:s m[0].x set value 9", "data get storage t:s ia[1]",
                    "data remove storage t:s l[-1]", "data modify storage t:s l prepend value 1b",
                    # copies between numbers (the VM's when both are mirrored numbers: the type goes along)
                    "data modify storage t:s n set from storage t:s d", "data modify storage t:s d set from storage t:s f",
                    "data modify storage t:s l[0] set from storage t:s n", "data modify storage t:s m[0].x set from storage t:s l[-1]",
                    "data modify storage t:s f set from storage t:s missing", "data modify storage t:s n set from storage t:s n",
                    "data modify storage t:s ia[0] set from storage t:s n", "data modify storage t:s d set from storage t:s m[1].x")
# `if|unless data storage t:s PATH`
DATA_CONDITIONS = ('a', 'l[]', 'l[{}]', 'n', 'missing', '{n:3}', '{f:1b}', '{d:0.5d}', '{a:1}', 'l[0]', 'l[-1]', 'l[2]',
                   'm[-1].x', 'ia[1]')
# The read-only objective hp (criterion health, created by t:f0): writes fail (reported; `*` and
# selectors keep them on the VM's host side), reads and `execute store` work
READ_ONLY_COMMANDS = ("scoreboard players set * hp 1", "scoreboard players add * hp 2",
                      "scoreboard players operation * hp += #a o", "scoreboard players operation #a o += #b hp",
                      "scoreboard players reset #b hp")


@dataclass(frozen=True)
class Vocabulary:
    """What random programs are made of: which score holders (single: usable where the game
    wants one), execute modifiers and extra commands."""

    holders: st.SearchStrategy
    single_holders: st.SearchStrategy
    modifiers: tuple[str, ...]
    extra_commands: tuple[str, ...]
    setup: tuple[str, ...]


def vocabulary(modifiers: bool, entities: bool) -> Vocabulary:
    names = st.sampled_from(HOLDERS)
    if not entities:
        return Vocabulary(names, names, MODIFIERS if modifiers else (), (), ())
    single = st.one_of(names, st.sampled_from(SINGLE_ENTITY_HOLDERS))
    return Vocabulary(st.one_of(single, st.sampled_from(MULTI_ENTITY_HOLDERS)), single,
                      (MODIFIERS if modifiers else ()) + ENTITY_MODIFIERS, ENTITY_COMMANDS, ENTITY_SETUP)


@st.composite
def ranges(draw) -> str:
    lo = draw(st.one_of(st.none(), st.integers(-10, 10), st.sampled_from((INT_MIN, INT_MAX))))
    hi = draw(st.one_of(st.none(), st.integers(-10, 10), st.sampled_from((INT_MIN, INT_MAX))))
    if lo is None and hi is None:
        return str(draw(st.integers(-5, 5)))
    if lo is not None and hi is not None and lo > hi:
        lo, hi = hi, lo
    return f"{'' if lo is None else lo}..{'' if hi is None else hi}"


@st.composite
def score_commands(draw, vocab: Vocabulary) -> str:
    """A scoreboard command that can run anywhere (no calls)."""
    kind = draw(st.sampled_from(("set", "add", "remove", "operation", "operation", "operation", "reset", "get")))
    h, o = draw(vocab.holders), draw(objectives)
    if kind in ("set", "add", "remove", "reset", "operation") and draw(st.integers(0, 9)) == 0:
        h = "*"  # every tracked holder (the VM runs the forms whose order changes nothing, the host the others)
    if kind == "set":
        return f"scoreboard players set {h} {o} {draw(ints)}"
    if kind in ("add", "remove"):
        return f"scoreboard players {kind} {h} {o} {draw(non_negative)}"
    if kind == "reset":
        return f"scoreboard players reset {h} {o}"
    if kind == "get":
        return f"scoreboard players get {draw(vocab.single_holders)} {o}"
    source = "*" if h != "*" and draw(st.integers(0, 9)) == 0 else draw(vocab.holders)
    return f"scoreboard players operation {h} {o} {draw(st.sampled_from(OPERATIONS))} {source} {draw(objectives)}"


@st.composite
def server_commands(draw, vocab: Vocabulary) -> str:
    """A schedule, gamerule, storage, read-only objective or log line (no calls)."""
    kind = draw(st.sampled_from(("server", "server", "server", "storage", "storage", "store", "read_only", "read_only")))
    if kind == "server":
        return draw(st.sampled_from(SERVER_COMMANDS))
    if kind == "storage":
        fixed = st.sampled_from(STORAGE_COMMANDS)
        return draw(st.one_of(fixed, ints.map(lambda v: f"data modify storage t:s n set value {v}")))
    if kind == "store":
        what, into = draw(st.sampled_from((("result", "n int 1"), ("result", "d double 0.5"), ("success", "f byte 1"),
                                           ("result", "l[0] int 1"), ("result", "l[-1] double 2"),
                                           ("result", "m[1].x byte 1"), ("result", "ia[0] int 1"))))
        inner = draw(score_commands(vocab))
        return f"execute store {what} storage t:s {into} run {inner}"
    if draw(st.booleans()):
        return draw(st.sampled_from(READ_ONLY_COMMANDS))
    h = draw(vocab.single_holders)
    return draw(st.sampled_from((f"execute store result score {h} hp run scoreboard players get #a o",
                                 f"scoreboard players get {h} hp", f"execute if score {h} hp matches 0..")))


@st.composite
def conditions(draw, callees: list[str], vocab: Vocabulary) -> str:
    word = draw(st.sampled_from(("if", "unless")))
    kinds = ["matches", "compare", "data"] + (["function"] if callees else []) + (["entity"] if vocab.setup else [])
    kind = draw(st.sampled_from(kinds))
    if kind == "data":
        return (f"{word} data storage t:s "
                f"{draw(st.sampled_from(DATA_CONDITIONS))}")
    single = vocab.single_holders
    if kind == "matches":
        return f"{word} score {draw(single)} {draw(objectives)} matches {draw(ranges())}"
    if kind == "compare":
        return (f"{word} score {draw(single)} {draw(objectives)} {draw(st.sampled_from(COMPARISONS))} "
                f"{draw(single)} {draw(objectives)}")
    if kind == "entity":
        targets = ('@s', '@e[tag=a]', '@e[tag=n]', '@e[tag=m,scores={o=1..}]', '@e[type=marker,limit=1]',
                   '@s[tag=a]', '@e[tag=m,tag=!a]', '@e[type=!marker]', '@e[distance=..1.5]',
                   '@e[dx=2,dy=0,dz=2,tag=m]', '@n[tag=w69]', '@e[type=#minecraft:skeletons]', '@e[name=Bob]',
                   '@s[x_rotation=40..50]', '@e[team=t]', '@s[y_rotation=-10..10,name=!Bob]')
        if draw(st.integers(0, 3)) == 0:
            return f"{word} predicate t:{draw(st.sampled_from(sorted(PREDICATES)))}"
        return f"{word} entity {draw(st.sampled_from(targets))}"
    return f"{word} function {draw(st.sampled_from(callees))}"


@st.composite
def stage_chains(draw, callees: list[str], vocab: Vocabulary) -> str:
    """1 to 3 execute stages: conditions, plus the vocabulary's modifiers and stores if it has any."""
    stage = conditions(callees, vocab)
    if vocab.modifiers:
        stores = st.builds(lambda kind, h, o: f"store {kind} score {h} {o}",
                           st.sampled_from(("result", "success")), vocab.holders, objectives)
        stage = st.one_of(stage, st.sampled_from(vocab.modifiers), stores)
    return " ".join(draw(st.lists(stage, min_size=1, max_size=3)))


@st.composite
def macro_calls(draw, vocab: Vocabulary) -> str:
    """``t:mac`` or the tag ``#t:macs`` (a plain member, then t:mac) with arguments; sometimes the
    tag without them (its macro member cannot be instantiated: the call fails after the first)."""
    holder = draw(vocab.single_holders)
    target = draw(st.sampled_from(("t:mac", "t:mac", "#t:macs")))
    if target == "#t:macs" and draw(st.integers(0, 3)) == 0:
        return "function #t:macs"
    return f'function {target} {{h:"{holder}", v:{draw(ints)}}}'


@st.composite
def commands(draw, callees: list[str], vocab: Vocabulary) -> str:
    """One line of a function that may call ``callees`` (ids or ``#tags``) and the macro."""
    simple = st.one_of(score_commands(vocab), score_commands(vocab), score_commands(vocab), server_commands(vocab))
    if vocab.extra_commands:
        simple = st.one_of(simple, simple, st.sampled_from(vocab.extra_commands))
    call = st.one_of(st.sampled_from(callees).map(lambda f: f"function {f}"), macro_calls(vocab)) if callees else simple
    inner = st.one_of(simple, simple, call)
    kind = draw(st.sampled_from(("score", "score", "score", "say", "call", "if", "store", "condition", "return")))
    if kind == "score":
        return draw(simple)
    if kind == "say":
        return f"say {draw(st.sampled_from(('a', 'b', 'c')))}"
    if kind == "call":
        return draw(call)
    if kind == "if":
        return f"execute {draw(stage_chains(callees, vocab))} run {draw(inner)}"
    if kind == "store":
        what = draw(st.sampled_from(("result", "success")))
        holder = "*" if draw(st.integers(0, 7)) == 0 else draw(vocab.holders)
        return f"execute store {what} score {holder} {draw(objectives)} run {draw(inner)}"
    if kind == "condition":
        # `if function` must be followed by more (ExecuteCommand registers it with fork only)
        return f"execute {draw(conditions([], vocab))}"
    ret = draw(st.sampled_from(("value", "fail", "run")))
    guard = f"execute {draw(stage_chains(callees, vocab))} run " if draw(st.booleans()) else ""
    if ret == "value":
        return f"{guard}return {draw(ints)}"
    if ret == "fail":
        return f"{guard}return fail"
    return f"{guard}return run {draw(inner)}"


@st.composite
def programs(draw, max_functions: int = 4, max_lines: int = 8, modifiers: bool = False,
             entities: bool = False) -> Program:
    """``modifiers``: execute chains may hold context modifiers (positioned, align, in, as @e ...)
    and stores; ``entities``: three markers exist, selected, tagged, killed and used as holders."""
    vocab = vocabulary(modifiers, entities)
    count = draw(st.integers(1, max_functions))
    names = [f"t:f{i}" for i in range(count)]
    functions: dict[str, str] = {}
    for leaf in ("t:leaf0", "t:leaf1"):
        body = draw(st.lists(score_commands(vocab), min_size=1, max_size=3))
        ending = draw(st.sampled_from(("", "return 1", "return -4", "return fail", "return 0")))
        functions[leaf] = "\n".join(body + ([ending] if ending else []))
    tags = {"t:leaves": draw(st.lists(st.sampled_from(("t:leaf0", "t:leaf1")), min_size=1, max_size=3)),
            "t:macs": ["t:leaf1", "t:mac"]}
    functions["t:mac"] = "$scoreboard players set $(h) o $(v)\n" + draw(
        st.sampled_from(("$return $(v)", "$scoreboard players operation #a o += $(h) o", "return run say mac")))
    for i, name in enumerate(names):
        callees = names[i + 1:] + ["t:loop", "t:leaf0", "#t:leaves"]
        lines = draw(st.lists(commands(callees, vocab), min_size=1, max_size=max_lines))
        if i == 0:
            lines = ["scoreboard objectives add o dummy", "scoreboard objectives add p dummy",
                     "scoreboard objectives add hp health",
                     f"scoreboard players set #n p {draw(st.integers(0, 6))}", *vocab.setup] + lines
        functions[name] = "\n".join(lines)
    if entities:
        functions["t:wide"] = WIDE_TAGS
    loop_body = draw(st.lists(score_commands(vocab), min_size=0, max_size=3))
    functions["t:loop"] = "\n".join(
        ["scoreboard players remove #n p 1"] + loop_body + ["execute if score #n p matches 1.. run function t:loop"]
    )
    return Program(functions, tags, files=PREDICATE_FILES if entities else {})


# ----------------------------------------------------------------------------- running


@dataclass(frozen=True)
class Outcome:
    """What one root run left behind, in a form two backends can be compared on."""

    scores: dict
    result: int | None
    cost: int
    cut: bool
    overflows: tuple
    log: tuple
    diagnostics: tuple
    line_costs: dict  # {(file name, line): cost charged there}
    entities: tuple = ()  # (uuid, type, pos, sorted tags, dimension, its NBT) of every entity, in the store's order
    storage: dict = None  # {storage id: SNBT}
    schedules: tuple = ()  # (name, due) of every pending schedule, in run order
    gamerules: dict = None
    roots: tuple = ()  # (result, cost, cut) of each root run
    ran: str = ""  # the backend's name, or which ran (Emulator.backend_ran)


def run_root(backend_name: str, pack: Path, entry: str, sanitize: bool = False, scores: dict | None = None,
             limit: int | None = None, roots: int = 1, switch_after: int | None = None) -> Outcome:
    """Load ``pack`` and run ``entry`` as ``roots`` roots on a fresh world (the outcome's result,
    cost and cut are the last one's); ``scores`` seeds ``{(holder, objective): value}`` first;
    ``limit`` sets maxCommandChainLength; ``switch_after``: run on the auto backend
    (:mod:`emulator.runtime.auto`) switching after that much work, ``backend_name`` ignored."""
    from emulator.runtime.auto import AutoBackend
    from emulator.runtime.factory import make_backend
    from emulator.world.entities import entity_nbt
    from emulator.world.resources import Resources
    from emulator.world.state import WorldState
    from mcfunction_parser.pack.loader import load_packs

    packs = load_packs([pack])
    errors = [d.format() for d in packs.diagnostics if d.severity == "error"]
    assert not errors, errors
    state = WorldState()
    state.resources = Resources.from_packs(packs)  # as the runtime: predicates, tags
    if limit is not None:
        state.gamerules.set("maxCommandChainLength", str(limit))
    for (holder, objective), value in (scores or {}).items():
        state.scoreboard.set(holder, objective, value)
    if switch_after is None:
        backend = make_backend(backend_name)
    else:
        backend = AutoBackend(make_backend("python"), lambda: make_backend("numba"), switch_after)
    backend.load(packs, state, sanitize=sanitize)
    results = [backend.run_root(entry) for _ in range(roots)]
    root = results[-1]
    return Outcome(
        scores=state.scoreboard.scores(),
        result=root.result,
        cost=root.cost,
        cut=root.cut,
        overflows=tuple((o.function, o.loc.line, o.op, o.a, o.b, o.exact, o.stored) for o in state.overflows),
        log=tuple((e.kind, e.text) for e in state.log),
        diagnostics=tuple((d.message, tuple((f.function, f.loc.line) for f in d.frames)) for d in state.diagnostics),
        line_costs={(Path(path).name, line): n for (path, line), n in backend.line_counts().items() if n},
        entities=tuple((e.uuid_string, e.type, e.pos, tuple(sorted(e.tags)), e.dimension, to_snbt(entity_nbt(e)))
                       for e in state.entities.entities),
        storage={sid: to_snbt(root) for sid, root in state.storage.items()},
        schedules=tuple((e.name, e.due) for e in state.schedule.pending()),
        gamerules=dict(state.gamerules.values),
        roots=tuple((r.result, r.cost, r.cut) for r in results),
        ran=getattr(backend, "ran", backend.name),
    )
