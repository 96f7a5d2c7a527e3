import pytest

from mcfunction_parser import ast
from tests.parser.parser_helpers import parse_err, parse_ok


def test_gamerule():
    assert parse_ok("gamerule doDaylightCycle false").value == "false"
    assert parse_ok("gamerule maxCommandChainLength").value is None
    assert parse_ok("gamerule maxCommandChainLength 100").value == "100"
    assert "true or false" in parse_err("gamerule doDaylightCycle 1").message
    assert "game rule value" in parse_err("gamerule maxCommandChainLength true").message


def test_gamerule_names_by_version():
    # 1.21.11 renamed every rule to snake_case (the game's 1.21.11 command tree)
    assert parse_ok("gamerule max_command_sequence_length 5", (1, 21, 11)).value == "5"
    assert parse_ok("gamerule minecraft:advance_time false", (1, 21, 11)).value == "false"
    assert "snake_case" in parse_err("gamerule doDaylightCycle false", (1, 21, 11)).message
    assert "unknown game rule 'doDaylightCylce'" in parse_err("gamerule doDaylightCylce true", (1, 20, 4)).message
    assert "1.19" in parse_err("gamerule doWardenSpawning false", (1, 18, 2)).message
    parse_ok("gamerule freezeDamage false", (1, 17, 1))


@pytest.mark.parametrize("text,version,message", [
    # GameRuleCommand registers one literal per rule: the release's own command tree decides
    ("gamerule tntExplodes false", (1, 21, 5), None),
    ("gamerule tntExplodes false", (1, 21, 4), "the command tree of 1.21.5 has it"),
    ("gamerule maxCommandForkCount 3", (1, 20, 1), "is not in Minecraft 1.20.1"),
    ("gamerule maxCommandForkCount 3", (1, 20, 3), None),
    ("gamerule locatorBar false", (1, 21, 6), None),
    ("gamerule spawnChunkRadius 2", (1, 21, 8), None),
    ("gamerule spawnChunkRadius 2", (1, 21, 9), "gone from Minecraft 1.21.9: last in the command tree of 1.21.8"),
    ("gamerule bogusRule 1", (1, 21, 6), "unknown game rule 'bogusRule'"),
])
def test_gamerules_come_from_the_releases_command_tree(text, version, message):
    if message is None:
        parse_ok(text, version)
    else:
        assert message in parse_err(text, version).message


def test_gamerules_of_a_stand_in_tree_only_warn():
    # 1.13 - 1.15 are checked against 1.16.5's tree (no maintained package has theirs): a rule of
    # all of them is accepted and one that tree lacks is a warning, not an error
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command

    assert parse_command("gamerule keepInventory true", Loc("t", 1, 1), (1, 14, 4))[1] == []
    cmd, diags = parse_command("gamerule maxCommandForkCount 3", Loc("t", 1, 1), (1, 15, 2))
    assert cmd.value == "3" and [d.severity for d in diags] == ["warning"]
    assert "stands in for 1.15.2" in diags[0].message


def test_random():
    cmd = parse_ok("random value 1..6")
    assert (cmd.action, cmd.range.lo, cmd.range.hi, cmd.sequence) == ("value", 1, 6, None)
    assert parse_ok("random roll 0..10 ns:dice").sequence == "ns:dice"
    reset = parse_ok("random reset * 42 false true")
    assert (reset.sequence, reset.seed, reset.include_world_seed, reset.include_sequence_id) == ("*", 42, False, True)
    # RandomCommand.register: includeWorldSeed is executable, includeSequenceId then true
    reset = parse_ok("random reset ns:seq 7 false")
    assert (reset.sequence, reset.seed, reset.include_world_seed, reset.include_sequence_id) == ("ns:seq", 7, False, True)
    assert "1.20.2" in parse_err("random value 1..2", (1, 20, 1)).message


@pytest.mark.parametrize("text,value", [("time set noon", 6000), ("time set midnight", 18000),
                                        ("time set 1d", 24000), ("time add 20s", 400)])
def test_time(text, value):
    assert parse_ok(text).value == value


def test_time_query():
    assert parse_ok("time query gametime").query == "gametime"
    assert "time query" in parse_err("time query hour").message


def test_trigger():
    cmd = parse_ok("trigger t set -3")
    assert (cmd.objective, cmd.action, cmd.value) == ("t", "set", -3)
    assert parse_ok("trigger t").action is None


def test_say_and_tellraw():
    assert parse_ok("say hello @a world").message == "hello @a world"
    assert "unknown selector option" in parse_err("say hi @e[bogus=1]").message
    cmd = parse_ok('tellraw @a {"text":"hi","extra":[{"text":"]"}]}')
    assert isinstance(cmd, ast.Tellraw) and cmd.text.endswith("]}")
    assert "only players" in parse_err('tellraw @e "x"').message
    parse_ok('tellraw @e[type=player] "x"')
    parse_ok('tellraw @s "x"')


def test_generic_commands_are_kept_as_text():
    cmd = parse_ok("particle minecraft:flame ~ ~ ~ 0 0 0 0 1")
    assert isinstance(cmd, ast.GenericCommand) and cmd.name == "particle" and cmd.text.startswith("particle ")
    assert parse_ok("reload").text == "reload"


@pytest.mark.parametrize("text,version,message", [
    ("replaceitem entity @s weapon.mainhand stone", (1, 17, 0), "removed in Minecraft 1.17"),
    ("item replace entity @s weapon.mainhand with stone", (1, 16, 5), "requires Minecraft 1.17"),
    ("damage @s 1", (1, 19, 3), "1.19.4"),
    ("ride @s mount @e[limit=1]", (1, 19, 3), "1.19.4"),
    ("place feature minecraft:tree", (1, 18, 2), "1.19"),
    ("transfer host", (1, 20, 4), "1.20.5"),
    ("rotate @s 0 0", (1, 21, 1), "1.21.2"),
    ("test run x", (1, 21, 4), "1.21.5"),
    ("frobnicate", (1, 21, 0), "unknown command 'frobnicate'"),
])
def test_command_versions(text, version, message):
    assert message in parse_err(text, version).message


def test_removed_command_suggests_replacement():
    assert "use `item replace`" in parse_err("replaceitem block ~ ~ ~ container.0 stone", (1, 21, 0)).message
    parse_ok("replaceitem entity @s weapon.mainhand stone", (1, 16, 5))


def test_high_permission_commands_warn_and_parse():
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command

    cmd, diags = parse_command("tick rate 40", Loc("t", 1, 1))
    assert isinstance(cmd, ast.GenericCommand)
    assert [d.severity for d in diags] == ["warning"] and "permission level 3" in diags[0].message


def test_text_components_are_strict_json_before_1_21_5():
    # ComponentArgument reads with a non-lenient JsonReader (decompiled Component.Serializer.fromJson)
    text = 'tellraw @a {"text":"a" "color":"red"}'
    d = parse_err(text)
    assert "invalid JSON text" in d.message and d.col == text.index('"color"') + 1
    assert "invalid JSON text" in parse_err("tellraw @a {text:'a'}").message
    assert "invalid JSON text" in parse_err('scoreboard objectives add o dummy {"text":"a",}').message
    parse_ok('tellraw @a ["",{"text":"a","bold":true},"b"]')


def test_text_components_are_snbt_from_1_21_5():
    assert parse_ok("tellraw @a {text:'a',color:red}", (1, 21, 5)).text == "{text:'a',color:red}"
    parse_ok('tellraw @a ["",{"text":"a"}]', (1, 21, 5))
    assert "SNBT text component" in parse_err("tellraw @a {text:}", (1, 21, 5)).message
