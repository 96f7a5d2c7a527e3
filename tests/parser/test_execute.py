import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mcfunction_parser import ast
from mcfunction_parser.commands import execute as execute_module
from mcfunction_parser.parse import parse_command
from tests.parser.parser_helpers import LOC, parse_err, parse_ok


def test_chain_with_run():
    text = "execute as @e[type=zombie] at @s positioned ~ ~1 ~ run say hi"
    cmd = parse_ok(text)
    assert isinstance(cmd, ast.Execute)
    kinds = [type(s) for s in cmd.subcommands]
    assert kinds == [ast.ExAs, ast.ExAt, ast.ExPositioned]
    assert [s.loc.col for s in cmd.subcommands] == [text.index(w) + 1 for w in ("as ", "at ", "positioned")]
    assert isinstance(cmd.run, ast.Say) and cmd.run.loc.col == text.index("say") + 1


def test_modifiers():
    cmd = parse_ok("execute positioned as @s positioned over ocean_floor rotated 90 -10 rotated as @p "
                   "facing 1 2 3 facing entity @s feet anchored eyes align xz in minecraft:the_end "
                   "on vehicle summon minecraft:marker run kill")
    subs = cmd.subcommands
    assert isinstance(subs[0], ast.ExPositionedAs)
    assert subs[1].heightmap == "ocean_floor"
    assert (subs[2].rot.x.value, subs[2].rot.y.value) == (90.0, -10.0)
    assert isinstance(subs[3], ast.ExRotatedAs)
    assert isinstance(subs[4], ast.ExFacing) and subs[4].pos.x.is_int
    assert subs[5].anchor == "feet" and subs[6].anchor == "eyes"
    assert subs[7].axes == "xz" and subs[8].dimension == "minecraft:the_end"
    assert subs[9].relation == "vehicle" and subs[10].entity_type == "minecraft:marker"
    assert isinstance(cmd.run, ast.Kill) and cmd.run.targets is None


@pytest.mark.parametrize("op", ["<", "<=", "=", ">=", ">"])
def test_if_score_comparisons(op):
    cmd = parse_ok(f"execute if score @s a {op} #b c run say x")
    cond = cmd.subcommands[0]
    assert isinstance(cond, ast.IfScore) and cond.op == op and not cond.negated
    assert cond.source.name == "#b" and cond.source_objective == "c"


def test_unless_score_matches():
    cond = parse_ok("execute unless score @s a matches ..-1").subcommands[0]
    assert isinstance(cond, ast.IfScoreMatches) and cond.negated
    assert (cond.range.lo, cond.range.hi) == (None, -1)


def test_conditions():
    cmd = parse_ok("execute if entity @e[tag=x] if data storage a:b path.x if data entity @s Pos[0] "
                   "if data block ~ ~ ~ Items if block ~ ~-1 ~ #minecraft:logs[axis=y]{x:1} "
                   "if blocks 0 0 0 1 1 1 5 5 5 masked if predicate a:p if function #a:t "
                   "if biome ~ ~ ~ #minecraft:is_forest if loaded 0 0 0 if dimension minecraft:overworld "
                   "if items entity @s weapon.* minecraft:stick[count=1]")
    subs = cmd.subcommands
    assert cmd.run is None
    assert isinstance(subs[1].source, ast.StorageData) and subs[1].path.text == "path.x"
    assert isinstance(subs[2].source, ast.EntityData)
    assert isinstance(subs[3].source, ast.BlockData)
    assert subs[4].block == "#minecraft:logs[axis=y]{x:1}"
    assert subs[5].mode == "masked"
    assert subs[6].predicate == "a:p"
    assert subs[7].is_tag and subs[7].function == "a:t"
    assert subs[8].biome == "#minecraft:is_forest"
    assert isinstance(subs[9], ast.IfLoaded)
    assert subs[10].dimension == "minecraft:overworld"
    assert (subs[11].source.kind, subs[11].slots) == ("entity", ast.SlotArgument("weapon.*", (98, 99)))
    assert subs[11].predicate.id == "minecraft:stick" and subs[11].predicate.tests[0][0].name == "minecraft:count"


def test_store():
    cmd = parse_ok("execute store result score @s x store success storage a:b p.q byte 0.5 "
                   "store result entity @s Motion[0] double 0.001 store result block ~ ~ ~ Items[0].Count int 1 "
                   "store success bossbar a:bar max run data get storage a:b x")
    a, b, c, d, e = cmd.subcommands
    assert isinstance(a, ast.StoreScore) and a.kind == "result"
    assert isinstance(b, ast.StoreData) and (b.kind, b.type, b.scale) == ("success", "byte", 0.5)
    assert isinstance(c.target, ast.EntityData) and c.path.text == "Motion[0]"
    assert isinstance(d.target, ast.BlockData)
    assert isinstance(e, ast.StoreBossbar) and e.field == "max"
    assert isinstance(cmd.run, ast.DataGet)


def test_chain_may_end_only_on_a_condition():
    assert parse_ok("execute if entity @s").run is None
    d = parse_err("execute as @s")
    assert "'run'" in d.message
    assert "'run'" in parse_err("execute store result score @s x").message
    assert "incomplete" in parse_err("execute").message


def test_store_entity_needs_one_entity():
    assert "only one" in parse_err("execute store result entity @e x int 1 run say x").message


def test_bad_subcommand_column():
    text = "execute as @s jump run say x"
    d = parse_err(text)
    assert d.col == text.index("jump") + 1 and "subcommand" in d.message


def test_nested_run_and_errors_inside_run():
    cmd = parse_ok("execute as @a run execute at @s run function a:b")
    assert isinstance(cmd.run, ast.Execute) and isinstance(cmd.run.run, ast.FunctionCall)
    text = "execute as @a run scoreboard players add @s x -5"
    assert parse_err(text).col == text.index("-5") + 1


@pytest.mark.parametrize("text,version", [
    ("execute on owner run say x", (1, 19, 3)),
    ("execute summon pig run say x", (1, 19, 3)),
    ("execute positioned over world_surface run say x", (1, 19, 3)),
    ("execute if dimension minecraft:overworld", (1, 19, 3)),
    ("execute if loaded ~ ~ ~", (1, 19, 3)),
    ("execute if biome ~ ~ ~ minecraft:plains", (1, 19, 2)),
    ("execute if function a:b run say x", (1, 20, 2)),
    ("execute if items entity @s weapon minecraft:stick", (1, 20, 4)),
])
def test_version_gated_subcommands(text, version):
    d = parse_err(text, version)
    assert "requires Minecraft" in d.message
    parse_ok(text, (1, 21, 0))


@pytest.mark.parametrize("text", ["execute if function a:b", "execute unless function #a:t",
                                  "execute as @e if function a:b"])
def test_if_function_cannot_end_the_chain(text):
    # ExecuteCommand.addConditionals: `if|unless function <name>` only forks to `execute`, with no
    # `executes` (the game's command tree: not executable), so the command is incomplete there
    d = parse_err(text, (1, 21, 0))
    assert "incomplete execute" in d.message and d.col == len(text) + 1


def test_align_rejects_repeats():
    assert "swizzle" in parse_err("execute align xx run say x").message


def test_local_coordinates_all_or_none():
    assert parse_ok("execute positioned ^ ^1 ^-2 run say x").subcommands[0].pos.is_local
    d = parse_err("execute positioned ^ ~ ^ run say x")
    assert "mix" in d.message and d.col == len("execute positioned ") + 1


_HOLDERS = st.sampled_from(["@s", "@x", "@n", "*", "#t", "$v", "a@b", "@e[limit=1]", "0-0-0-0-1", ""])
_OBJECTIVES = st.sampled_from(["obj", "o.b-j+", "abcdefghijklmnopq", "", "Ob"])
_RANGES = st.sampled_from(["1", "..-1", "1..", "5..1", "..", "1.5", "x", "", "2147483648", "-0..0"])
_TAILS = st.sampled_from(["", " run say x", " if entity @s", "x", " ", " run"])


@settings(max_examples=400, deadline=None)
@given(st.sampled_from(["if", "unless"]), _HOLDERS, _OBJECTIVES, _RANGES, _TAILS,
       st.sampled_from([(1, 17, 1), (1, 20, 6), (1, 21, 0)]))
def test_fast_score_matches_path_matches_the_general_path(kind, holder, objective, rng, tail, version):
    text = f"execute {kind} score {holder} {objective} matches {rng}{tail}"
    fast = parse_command(text, LOC, version)
    original = execute_module._fast_score_matches
    execute_module._fast_score_matches = lambda *args: None
    try:
        general = parse_command(text, LOC, version)
    finally:
        execute_module._fast_score_matches = original
    assert fast[0] == general[0]
    assert [(d.col, d.message) for d in fast[1]] == [(d.col, d.message) for d in general[1]]


def test_if_score_holders_must_be_single():
    # ScoreHolderArgument.scoreHolder() rejects a selector that can select more than one entity
    assert "only one score holder" in parse_err("execute if score @e[tag=a] x matches 1").message
    assert "only one score holder" in parse_err("execute if score @s x = @a y").message
    assert "only one score holder" in parse_err("execute unless score @a x matches 1").message
    parse_ok("execute if score @e[tag=a,limit=1] x matches 1")
    parse_ok("execute if score * x matches 1")


def test_block_states_are_checked():
    assert parse_ok("execute if block ~ ~ ~ minecraft:oak_stairs[ facing = east , half=top ]").subcommands[0].block \
        == "minecraft:oak_stairs[ facing = east , half=top ]"
    assert "state" in parse_err("execute if block ~ ~ ~ stone[slab[type=top] run say x").message
    assert "state" in parse_err("execute if block ~ ~ ~ stone[facing] run say x").message
    assert "expected '='" in parse_err("execute if block ~ ~ ~ oak_stairs[facing] run say x").message
