"""Cross-check accept/reject decisions with mecha on a corpus of valid and invalid lines.

mecha's ``version="1.21"`` follows the newest 1.21.x command tree, so the corpus avoids syntax that
changed inside 1.21 (game rule names, SNBT details). Lines where we deliberately disagree are listed
in DIFFERENCES with the reason; each side's decision there is asserted too, so a change in either
parser shows up.
"""
from __future__ import annotations

import pytest

from mcfunction_parser.lines import logical_lines
from mcfunction_parser.parse import parse_function

mecha = pytest.importorskip("mecha")

VALID = [
    "say hello world",
    "scoreboard objectives add speed dummy",
    'scoreboard objectives add speed dummy {"text":"Speed","color":"red"}',
    "scoreboard objectives remove speed",
    "scoreboard objectives setdisplay sidebar speed",
    "scoreboard objectives modify speed rendertype hearts",
    "scoreboard players set @s speed -5",
    "scoreboard players add #global speed 2147483647",
    "scoreboard players remove $x speed 0",
    "scoreboard players operation @e[tag=ball] speed *= #ten const",
    "scoreboard players operation @s a >< @s b",
    "scoreboard players reset * speed",
    "scoreboard players get @s speed",
    "scoreboard players enable @a trig",
    "scoreboard players list",
    "execute as @e[type=minecraft:zombie,limit=3,sort=nearest] at @s run tp @s ~ ~1 ~",
    "execute if score @s a = @s b run say equal",
    "execute unless score @s a matches ..0",
    "execute if entity @a[distance=..5,gamemode=!creative]",
    "execute store result score @s x run data get entity @s Pos[0] 100",
    "execute store success storage ns:s flag byte 1 run say x",
    "execute positioned ^ ^ ^1 rotated ~ 0 facing entity @p eyes anchored feet align xyz run say x",
    "execute in minecraft:the_nether positioned over motion_blocking run say x",
    "execute on passengers summon minecraft:marker run tag @s add new",
    "execute if data storage ns:s list[0] if block ~ ~ ~ minecraft:stone if predicate ns:p run say x",
    "execute if function ns:check run say x",
    "execute if loaded 0 0 0 if dimension minecraft:overworld if biome ~ ~ ~ minecraft:plains",
    "execute if blocks ~ ~ ~ ~1 ~1 ~1 0 0 0 all",
    "function ns:path/to/fn",
    "function #ns:tag",
    "function ns:macro {a:1,b:\"x\"}",
    "function ns:macro with storage ns:s args",
    "function ns:macro with entity @s data.args",
    "return 5",
    "return fail",
    "return run scoreboard players get @s x",
    "schedule function ns:f 20t append",
    "schedule function ns:f 1s",
    "schedule clear ns:f",
    "schedule function ns:f 0t",  # parses; fails only when run (we warn)
    "data get storage ns:s path.to.value 0.5",
    "data merge entity @s {NoAI:1b,Tags:[\"a\"]}",
    "data modify storage ns:s list append value {x:1.5d,y:[I;1,2,3]}",
    "data modify storage ns:s a set from entity @s SelectedItem.components",
    "data modify storage ns:s a insert 0 value 'text'",
    "data modify storage ns:s a set string storage ns:s b 0 5",
    "data modify entity @s Inventory[{Slot:0b}].count set value 3",
    "data remove storage ns:s a[-1]",
    "tag @e[tag=!a] add a",
    "tag @s list",
    "summon minecraft:armor_stand ~ ~ ~ {Invisible:1b,CustomName:'\"Name\"'}",
    "kill @e[type=item,nbt={Item:{id:\"minecraft:stone\"}}]",
    "kill",
    "tp @s 0 64 0 90 0",
    "tp @s ~ ~ ~ facing 0 64 0",
    "teleport @e[tag=a] @s",
    "tp 1 2 3",
    "random value 1..6",
    "random roll 1..100 ns:seq",
    "time set midnight",
    "time add 1d",
    "time query daytime",
    "trigger trig set 3",
    "trigger trig",
    'tellraw @a {"text":"hi"}',
    'tellraw @p ["", {"text":"a"}]',
    "particle minecraft:flame ~ ~ ~ 0 0 0 0.1 5",
    "setblock ~ ~ ~ minecraft:stone",
    "kill @e[x=1,y=2,z=3,dx=4,dy=5,dz=6,x_rotation=-90..90,y_rotation=0]",
    "kill @e[scores={a=1..5,b=..0},team=,tag=,predicate=!ns:p]",
    "kill @e[tag=a,]",
    "kill @e[]",
    "kill 0-0-0-0-1",
    "$say $(x)",
]

INVALID = [
    "scoreboard players add @s x -1",
    "scoreboard players set @s x",
    "scoreboard players operation @s x ** @s y",
    "execute as @s",
    "execute store result score @s x",
    "execute align xx run say x",
    "data get entity @e x",
    "tp @e",
    "tellraw @e \"x\"",
    'tellraw @a {"text":"a" "color":"red"}',
    'scoreboard objectives add o dummy {"text":"a",:"b"}',
    "execute if block ~ ~ ~ minecraft:chest{Items:[}] run say x",
    "function ns:Bad",
    "say hi @e[bogus=1]",
    "data modify storage a:b x set value [B;1,2]",
    "execute if block ~ ~ ~ stone[",
    "tellraw @a {\"text\":\"a\"",
    "kill @e[,]",
    "data get storage a:b a..b",
    "return 1.5",
    "kill @e[x=1..2]",
    "kill @e[nbt={a:1}]extra",
    "$say no variables",
    "$say $(bad-key)",
    "frobnicate",
    "kill @x",
    "summon",
    "tag @s add",
    "time query hour",
    "schedule function ns:f 1 later",
]

# (line, we accept?, why we differ from mecha)
DIFFERENCES = [
    ("kill @e[limit=0]", False, "EntitySelectorOptions: limit must be at least 1"),
    ("kill @s[limit=1]", False, "limit isn't applicable to @s (canUse: !isCurrentEntity)"),
    ("kill @a[type=player]", False, "@a is already limited to players (isTypeLimited)"),
    ("kill @e[type=pig,type=cow]", False, "type may be given once unless negated"),
    ("kill @e[name=a,name=b]", False, "name= may be given once"),
    ("kill @e[limit=1,limit=2]", False, "limit may be given once"),
    ("kill @e[distance=-1..]", False, "distance cannot be negative"),
    ("kill @e[scores={x=5..1}]", False, "MinMaxBounds: min cannot be bigger than max"),
    ("scoreboard players set @s x 2147483648", False, "not a 32-bit int"),
    ("tag #fake add x", False, "entity arguments take names, not fake players"),
    ("tag abcdefghijklmnopq add x", False, "player names are at most 16 characters"),
    ("scoreboard objectives add x nonsense", False, "unknown criterion"),
    ("execute positioned ^ ~ ^ run say x", False, "cannot mix world and local coordinates"),
    ("random value 5..1", False, "min cannot be bigger than max"),
    ("data modify storage a:b x set value [1,2b]", False, "mixed lists need the 1.21.5 SNBT grammar"),
    ("scoreboard players  set @s x 1", False, "Brigadier separates arguments by exactly one space"),
]


@pytest.fixture(scope="module")
def mecha_parser():
    return mecha.Mecha(version="1.21")


def mecha_accepts(mc, line: str) -> bool:
    try:
        mc.parse(line, multiline=True)
    except mecha.DiagnosticError:
        return False
    return True


def ours_accepts(line: str) -> bool:
    _, diags = parse_function(line + "\n", "t.mcfunction", "t:t", (1, 21, 0))
    return not [d for d in diags if d.severity == "error"]


@pytest.mark.parametrize("line", VALID)
def test_both_accept(mecha_parser, line):
    assert ours_accepts(line)
    assert mecha_accepts(mecha_parser, line)


@pytest.mark.parametrize("line", INVALID)
def test_both_reject(mecha_parser, line):
    assert not ours_accepts(line)
    assert not mecha_accepts(mecha_parser, line)


@pytest.mark.parametrize("line,we_accept,reason", DIFFERENCES)
def test_deliberate_differences(mecha_parser, line, we_accept, reason):
    assert ours_accepts(line) is we_accept, reason
    assert mecha_accepts(mecha_parser, line) is not we_accept, f"mecha now agrees: {reason}"


def test_generated_corpus_is_accepted_by_both(mecha_parser, tmp_path):
    """Every line of a small benchmark corpus: valid for us at 1.21 and for mecha, except game rules
    (mecha's 1.21 tree is 1.21.11, where every rule was renamed)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
    from corpus import write_corpus

    write_corpus(tmp_path, lines=800, seed=7)
    checked = 0
    for path in sorted(tmp_path.rglob("*.mcfunction")):
        text = path.read_text()
        _, diags = parse_function(text, str(path), "bench:f", (1, 21, 0))
        assert not diags, [d.format() for d in diags]
        for line, *_ in logical_lines(text.split("\n"), (1, 21, 0)):
            if line[0] != "$" and "gamerule" not in line:
                assert mecha_accepts(mecha_parser, line), line
                checked += 1
    assert checked > 500
