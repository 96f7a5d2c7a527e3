"""Commands without a parser of their own, checked against the game's command tree and registries
of the target release (mcfunction_parser/commands/tree.py, game_objects.py)."""
from __future__ import annotations

import pytest

from mcfunction_parser import ast, gamedata
from mcfunction_parser.check import check_packs
from mcfunction_parser.commands import tree
from tests.parser.parser_helpers import parse_err, parse_ok
from tests.parser.test_check import fn, write

V21 = (1, 21, 4)


@pytest.mark.parametrize("text,col,words", [
    # the examples of issue 14: each an error with the caret under the wrong argument
    ("give @s diamond 1 2 3", 19, "expected end of command, got '2'"),
    ("gamemode flying", 10, "expected game mode"),
    ("setblock ~ ~ ~ stone[facing=north", 22, "has no state 'facing'"),
    ("setblock ~ ~ ~ oak_stairs[facing=up]", 34, "does not accept 'up'"),
    ("setblock ~ ~ ~ oak_stairs[facing=north", 39, "expected ',' or ']'"),
    ("give @s diamond -1", 17, "at least 1"),
    ("effect give @s speedy", 16, "unknown effect 'minecraft:speedy'"),
    ("give @s mymod:thing", 9, "unknown item"),  # items are a static registry
    ("weather rain -5", 14, "time"),
    ("team modify red color pink", 23, "expected color"),
    ("gamemode", 9, "incomplete command: expected <gamemode>"),
    ("xp add @s five", 11, "expected integer"),
    ("item replace entity @s weapon.left with stone", 24, "unknown slot 'weapon.left'"),
])
def test_tree_errors_point_at_the_argument(text, col, words):
    error = parse_err(text, V21)
    assert words in error.message and error.col == col, (error.message, error.col)


@pytest.mark.parametrize("text", [
    "give @s diamond 64",
    "gamemode creative @a",
    "setblock ~ ~ ~ oak_stairs[facing=north, half=top]{}",
    "fill ~ ~ ~ ~1 ~1 ~1 air replace #minecraft:logs",
    "effect give @s minecraft:speed infinite 1 true",
    "particle dust{color:[1.0,0.0,0.0],scale:1} ~ ~ ~ 0 0 0 0 1 force @a",
    "tell @a hi @s",  # a redirect: tell -> msg
    "xp add @s 5 levels",
    "item replace entity @s weapon.mainhand with diamond_sword[enchantments={sharpness:1},!food]",
    "clear @s #minecraft:logs[damage=1|count~{min:1}] 3",
    "playsound minecraft:block.note_block.pling master @a ~ ~ ~ 1 2",
    "team modify red color red",
    "attribute @s max_health base set 20",  # renamed from generic.max_health in 1.21.2
    "loot give @s loot minecraft:chests/simple_dungeon",
    "spreadplayers 0 0 1 10 false @a",
    "title @a times 10 20 10",
    "enchant @s mypack:custom",  # enchantments are data-driven from 1.21
])
def test_valid_commands_pass(text):
    assert isinstance(parse_ok(text, V21), ast.Command)  # give, clear, item and loot have parsers of their own


def test_commands_after_run_are_checked_too():
    parse_ok("execute if entity @s run give @s stone", V21)
    assert parse_err("execute if entity @s run gamemode flying", V21).col == 35


def test_arguments_follow_the_release():
    # item stacks took {nbt} before 1.20.5 and [components] after
    parse_ok("give @s diamond_sword{Damage:5}", (1, 20, 4))
    parse_err("give @s diamond_sword{Damage:5}", V21)
    # particles took their options as words before 1.20.5
    parse_ok("particle dust 1 0 0 1 ~ ~ ~ 0 0 0 0 1", (1, 20, 4))
    parse_err("particle dust 1 0 0 1 ~ ~ ~ 0 0 0 0 1", V21)
    # attribute ids: generic.* until 1.21.1
    parse_ok("attribute @s generic.max_health base set 20", (1, 21, 1))
    assert "unknown attribute" in parse_err("attribute @s generic.max_health base set 20", V21).message


def test_ids_unknown_to_older_registry_data_are_warnings():
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command
    # 26.2 is newer than the newest registries shipped (26.1): a new id may exist there
    cmd, diags = parse_command("give @s no_such_item", Loc("t", 1, 1), (26, 2, 0))
    assert cmd is not None and [d.severity for d in diags] == ["warning"]
    assert "not in the 26.1 registry" in diags[0].message
    _, diags = parse_command("give @s no_such_item", Loc("t", 1, 1), (1, 21, 11))
    assert [d.severity for d in diags] == ["error"]


def test_a_release_newer_than_every_tree_is_checked_against_the_newest_as_warnings(tmp_path, monkeypatch):
    # with trees only before 1.21, 1.21.4 stands for a release newer than every shipped tree (26.x today)
    shipped = gamedata._index()
    trimmed = {**shipped, "commands": {v: f for v, f in shipped["commands"].items() if v < (1, 21, 0)}}
    monkeypatch.setattr(gamedata, "_index", lambda: trimmed)
    monkeypatch.setattr(tree, "_TREES", {})
    monkeypatch.setattr(tree, "_VALID", {})
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path / "none"))
    root = write(tmp_path / "p", {fn("f"): "xp add @s five\nxp add @s 5\n"})
    result = check_packs([root], "1.21.4")
    assert [d for d in result.diagnostics if d.severity == "error"] == []
    warnings = [d.message for d in result.diagnostics if d.severity == "warning"]
    said = [m for m in warnings if "no command tree for Minecraft 1.21.4" in m]
    assert len(said) == 1 and "--reports" in said[0] and "against the 1.20.6 command tree" in said[0]
    assert any("checked against the 1.20.6 command tree" in m and "Minecraft" not in m for m in warnings)


def test_teleport_tries_the_targets_branch_too():
    # Brigadier tries `teleport <location>` and `teleport <targets> <location>`: "-1" is a player name
    cmd = parse_ok("tp -1 ~ ~1 ~", V21)
    assert cmd.targets is not None and cmd.targets.name == "-1"
    assert parse_err("tp ~ ~ ~ extra", V21).col == 10


def test_game_profiles_take_players_only():
    # GameProfileArgument.parse: ERROR_ONLY_PLAYERS_ALLOWED
    assert "only players" in parse_err("op @e", V21).message
    parse_ok("op @a", V21)


def test_integer_game_rules_take_the_trees_bounds():
    # 1.21.11's tree gives max_entity_cramming a minimum of 0
    assert "at least 0" in parse_err("gamerule max_entity_cramming -1", (1, 21, 11)).message
    parse_ok("gamerule maxEntityCramming -1", (1, 20, 4))


def test_another_minor_releases_tree_only_warns():
    # 1.13 – 1.15 are checked with the 1.16.5 tree, where locate's structures were renamed
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command
    cmd, diags = parse_command("locate Village", Loc("t", 1, 1), (1, 13, 2))
    assert cmd is not None and [d.severity for d in diags] == ["warning"]
    assert "checked against the 1.16.5 command tree" in diags[0].message
    assert "locate" in parse_err("locate Village", (1, 16, 5)).source_line


def test_a_check_for_1_13_to_1_15_says_once_which_tree_it_uses(tmp_path, monkeypatch):
    # no maintained package has the 1.13 – 1.15 trees: the check names the 1.16.5 stand-in once
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path / "none"))
    root = write(tmp_path / "p", {"pack.mcmeta": '{"pack": {"pack_format": 4, "description": ""}}',
                                  "data/a/functions/f.mcfunction": "locate Village\nsay hi\n"})
    result = check_packs([root], "1.13.2")
    assert [d for d in result.diagnostics if d.severity == "error"] == []
    warnings = [d.message for d in result.diagnostics if d.severity == "warning"]
    said = [m for m in warnings if "no command tree for Minecraft 1.13.2" in m]
    assert len(said) == 1 and "against the 1.16.5 command tree" in said[0]
    assert "java -cp server.jar net.minecraft.data.Main --reports" in said[0]
    assert any("(checked against the 1.16.5 command tree" in m for m in warnings if m not in said)


@pytest.mark.parametrize("line,version,message", [
    # ParticleArgument.readParticle (1.20.5+): the options are decoded with the type's codec, from
    # {} when none are written
    ("particle dust ~ ~ ~", (1, 21, 4), "missing field 'color'"),
    ("particle dust{color:[1,0,0],scale:1} ~ ~ ~", (1, 21, 4), None),
    # DustParticleOptions: ExtraCodecs.VECTOR3F in 1.21, RGB_COLOR_CODEC (an int too) by 1.21.11
    ("particle dust{color:16711680,scale:1} ~ ~ ~", (1, 21, 0), "list of 3 numbers"),
    ("particle dust{color:16711680,scale:1} ~ ~ ~", (1, 21, 11), None),
    ("particle dust{color:[1,0,0],scale:4.01} ~ ~ ~", (1, 21, 4), "from 0.01 to 4.0"),  # ScalableParticleOptionsBase
    ("particle dust_color_transition{from_color:[1,0,0],scale:1} ~ ~ ~", (1, 21, 4), "missing field 'to_color'"),
    ("particle entity_effect{color:[1,1,1]} ~ ~ ~", (1, 21, 4), "ARGB int or a list of 4 numbers"),
    ('particle block{block_state:"minecraft:nope"} ~ ~ ~', (1, 21, 4), "unknown block 'minecraft:nope'"),
    ('particle block{block_state:{Name:"stone",Properties:{}}} ~ ~ ~', (1, 21, 4), None),
    ('particle item{item:"air"} ~ ~ ~', (1, 21, 4), "may not be minecraft:air"),
    ('particle item{item:{id:"stone",count:2}} ~ ~ ~', (1, 21, 4), None),
    ("particle shriek{delay:'x'} ~ ~ ~", (1, 21, 4), "expected an integer"),
    ("particle flame{anything:1} ~ ~ ~", (1, 21, 4), None),  # SimpleParticleType: a unit codec
    # before 1.20.5 the options are words (DustParticleOptions.DESERIALIZER.fromCommand)
    ("particle dust 1 0 0 1 ~ ~ ~", (1, 20, 4), None),
    ("particle dust 1 0 0 ~ ~ ~", (1, 20, 4), "expected number"),
])
def test_particle_options_per_release(line, version, message):
    if message is None:
        parse_ok(line, version)
    else:
        assert message in parse_err(line, version).message


def test_a_line_a_release_after_every_tree_may_accept_is_kept_unread():
    from mcfunction_parser.parse import parse_function
    # 26.2 has no tree here (26.1's stands in) and may have changed any syntax: a line no reader
    # accepts is a warning and an UnreadCommand, so the function loads as it may in the game
    text = "frobnicate 1\nscoreboard players frob x\ntime add 1t\n"
    function, diags = parse_function(text, "f", "a:f", (26, 2, 0))
    assert [d.severity for d in diags] == ["warning", "warning"]
    assert [type(c).__name__ for c in function.commands] == ["UnreadCommand", "UnreadCommand", "ClockCommand"]
    assert function.commands[0].name == "frobnicate"
    assert function.commands[0].reason == ("unknown command 'frobnicate' (checked against the 26.1 command tree: "
                                           "dpemu has none for 26.2)")
    function, diags = parse_function(text, "f", "a:f", (26, 1, 0))
    assert [d.severity for d in diags] == ["error", "error"] and len(function.commands) == 1
    # a short time line the stand-in tree only warns about is unread too, never a traceback
    short = "time add\ntime of\ntime of a:clock\ntime\ntime query\n"
    function, diags = parse_function(short, "f", "a:f", (26, 2, 0))
    assert [type(c).__name__ for c in function.commands] == ["UnreadCommand"] * 5
    assert all(d.severity == "warning" for d in diags)


def test_26_1_time_has_world_clocks():
    from mcfunction_parser.ast import ClockCommand, Time
    from mcfunction_parser.parse import parse_function
    # 26.1's command tree (minecraft-data 3.119's commands.json; TimeCommand.register, 26.1.2): time
    # [of <clock>] add|set|pause|resume|rate|query, query gametime; time add takes a negative time;
    # set tries <time> before a time marker id (Brigadier takes the first argument that parses:
    # "-5" is not a time of set, so it reads as the marker minecraft:-5); query day|daytime are gone
    # ("day" and "daytime" read as timeline ids)
    text = ("time add -5\ntime set 100\ntime query gametime\ntime of a:clock add 1t\ntime pause\n"
            "time set a:dawn\ntime of a:clock rate 0\ntime query daytime extra\ntime set -5\n"
            "time of the_end query a:t repetition\ntime rate 0.1\ntime query time\n")
    function, diags = parse_function(text, "f", "a:f", (26, 1, 0))
    assert function.commands[2] == Time(function.commands[2].loc, "query", None, "gametime")
    clocks = [(c.action, c.clock, c.value, c.timeline, c.repetition) for c in function.commands
              if isinstance(c, ClockCommand)]
    assert clocks == [("add", None, -5, None, False), ("set", None, 100, None, False),
                      ("add", "a:clock", 1, None, False), ("pause", None, None, None, False),
                      ("marker", None, "a:dawn", None, False), ("marker", None, "minecraft:-5", None, False),
                      ("query", "minecraft:the_end", None, "a:t", True),
                      ("rate", None, 0.10000000149011612, None, False), ("query", None, None, None, False)]
    assert function.commands[3].clock_loc.col == 9 and function.commands[7].timeline_loc.col == 23
    assert [(d.line, d.message) for d in diags] == [(7, "number must be at least 1e-05, got 0"),
                                                    (8, "expected repetition, got 'extra'")]
    _, diags = parse_function("time add -5\ntime of a:clock pause\nswing @s\n", "f", "a:f", (1, 21, 11))
    assert [d.line for d in diags] == [1, 2, 3]


def test_a_macro_line_that_does_not_parse_stays_an_error_after_every_tree():
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command
    # a macro line is parsed when the function is called, and one that does not parse fails the
    # call (FunctionBuilder / MacroFunction.instantiate): packs test that invalid input errors
    cmd, diags = parse_command("frobnicate 1", Loc("f", 1, 2), (26, 2, 0))
    assert cmd is None and [d.severity for d in diags] == ["error"]
