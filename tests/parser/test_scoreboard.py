import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mcfunction_parser import ast
from mcfunction_parser.commands import scoreboard
from mcfunction_parser.parse import parse_command
from tests.parser.parser_helpers import LOC, parse_err, parse_ok


def test_players_set_holds_any_int():
    cmd = parse_ok("scoreboard players set #x obj -2147483648")
    assert isinstance(cmd, ast.ScoreSet)
    assert (cmd.action, cmd.objective, cmd.value) == ("set", "obj", -2147483648)
    assert isinstance(cmd.targets, ast.NameTarget) and cmd.targets.name == "#x"
    assert cmd.targets.loc.col == len("scoreboard players set ") + 1


@pytest.mark.parametrize("action", ["add", "remove"])
def test_add_remove_reject_negative_at_the_number(action):
    text = f"scoreboard players {action} @s obj -1"
    d = parse_err(text)
    assert d.col == text.index("-1") + 1
    assert "at least 0" in d.message


def test_out_of_range_literal_is_an_error_at_its_column():
    text = "scoreboard players set @s obj 2147483648"
    d = parse_err(text)
    assert d.col == text.index("2147483648") + 1
    assert "32-bit" in d.message


def test_add_accepts_int_max():
    assert parse_ok("scoreboard players add $a obj 2147483647").value == 2147483647


@pytest.mark.parametrize("op", ["=", "+=", "-=", "*=", "/=", "%=", "<", ">", "><"])
def test_every_operation(op):
    cmd = parse_ok(f"scoreboard players operation @e[tag=a] x {op} * y")
    assert isinstance(cmd, ast.ScoreOperation)
    assert cmd.op == op and isinstance(cmd.sources, ast.Wildcard)
    assert isinstance(cmd.targets, ast.Selector) and cmd.targets.variable == "e"


def test_unknown_operation_lists_choices():
    d = parse_err("scoreboard players operation @s x ** @s y")
    assert "operation" in d.message and "'**'" in d.message and d.col == 35


def test_score_holders():
    assert parse_ok("scoreboard players get $pub obj").target.name == "$pub"
    assert parse_ok("scoreboard players get .x obj").target.name == ".x"
    uuid = parse_ok("scoreboard players get 0-0-0-0-1 obj").target
    assert uuid.is_uuid


def test_get_needs_a_single_holder():
    assert "only one" in parse_err("scoreboard players get @e obj").message
    parse_ok("scoreboard players get @e[limit=1] obj")
    # ScoreHolderArgument.parse accepts '*' even for a single holder; it fails only at run time
    assert isinstance(parse_ok("scoreboard players get * obj").target, ast.Wildcard)


def test_reset_enable_list():
    assert parse_ok("scoreboard players reset * obj").objective == "obj"
    assert parse_ok("scoreboard players reset @a").objective is None
    assert isinstance(parse_ok("scoreboard players enable @a trig"), ast.ScoreEnable)
    assert parse_ok("scoreboard players list").target is None
    assert parse_ok("scoreboard players list @s").target.variable == "s"


def test_objectives():
    cmd = parse_ok('scoreboard objectives add speed dummy {"text":"Speed"}')
    assert isinstance(cmd, ast.ObjectivesAdd)
    assert (cmd.objective, cmd.criterion, cmd.display_name) == ("speed", "dummy", '{"text":"Speed"}')
    assert parse_ok("scoreboard objectives add jumps minecraft.custom:minecraft.jump").criterion.endswith("jump")
    assert parse_ok("scoreboard objectives add k teamkill.red").criterion == "teamkill.red"
    assert isinstance(parse_ok("scoreboard objectives remove speed"), ast.ObjectivesRemove)
    assert parse_ok("scoreboard objectives setdisplay sidebar.team.red speed").slot == "sidebar.team.red"
    assert parse_ok("scoreboard objectives setdisplay sidebar").objective is None
    assert parse_ok("scoreboard objectives modify speed rendertype hearts").value == "hearts"
    assert isinstance(parse_ok("scoreboard objectives list"), ast.ObjectivesList)


def test_below_name_slot_renamed_in_1_20_2():
    assert parse_ok("scoreboard objectives setdisplay below_name x").slot == "below_name"
    assert "spelled 'below_name'" in parse_err("scoreboard objectives setdisplay belowName x").message
    assert parse_ok("scoreboard objectives setdisplay belowName x", (1, 20, 1)).slot == "belowName"


def test_objective_errors():
    assert "criterion" in parse_err("scoreboard objectives add x nonsense").message
    assert "display slot" in parse_err("scoreboard objectives setdisplay top x").message
    d = parse_err('scoreboard objectives add x dummy {"text":"a"')
    assert "unclosed" in d.message


def test_objective_name_length_depends_on_version():
    long_name = "a" * 17
    assert parse_ok(f"scoreboard objectives add {long_name} dummy").objective == long_name
    assert "16" in parse_err(f"scoreboard objectives add {long_name} dummy", (1, 17, 1)).message


def test_display_and_numberformat_are_1_20_3():
    assert isinstance(parse_ok("scoreboard players display name @s obj {\"text\":\"x\"}"), ast.ScoreDisplay)
    assert "1.20.3" in parse_err("scoreboard players display name @s obj x", (1, 20, 2)).message
    assert parse_ok("scoreboard objectives modify o numberformat styled {\"color\":\"red\"}").field == "numberformat"


@pytest.mark.parametrize("line,col", [
    # ScoreboardCommand.register: players display name <targets> <objective> [<component>], ...
    # numberformat <targets> <objective> [blank | fixed <component> | styled <style>]; objectives
    # modify <objective> numberformat [the same]
    ("scoreboard players display name @x obj", 33),
    ("scoreboard players display name * o!", 36),
    ('scoreboard players display name * obj {"text":', 39),
    ("scoreboard players display numberformat * obj bold", 47),
    ('scoreboard players display numberformat * obj fixed {"text":', 53),
    ("scoreboard players display colour * obj", 28),
    ('scoreboard objectives modify obj numberformat styled {"bold":', 54),
    ("scoreboard objectives modify obj numberformat blank x", 53),
])
def test_display_and_numberformat_arguments_are_checked(line, col):
    assert parse_err(line).col == col  # the caret under the wrong argument


def test_incomplete_and_trailing():
    assert "incomplete" in parse_err("scoreboard players set @s obj").message
    d = parse_err("scoreboard players set @s obj 1 2")
    assert "end of command" in d.message and d.col == 33
    d = parse_err("scoreboard players set @s obj 1x")
    assert d.col == 32


_WORDS = st.sampled_from(["@s", "@e", "@n", "@x", "*", "#tmp", "$x", ".y", "Steve", "0-0-0-0-1", "a@b", '"q"',
                          "@e[tag=a]", "@a[limit=1]", "", "obj", "o.b+j", "abcdefghijklmnopq", "x y"])
_NUMBERS = st.sampled_from(["0", "-1", "5", "2147483647", "2147483648", "-2147483648", "-2147483649", "1.5", "x",
                            "99999999999", "-0"])


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(["set", "add", "remove"]), _WORDS, _WORDS, _NUMBERS, st.sampled_from([(1, 17, 1), (1, 21, 0)]))
def test_fast_set_path_matches_the_general_path(action, holder, obj, number, version):
    text = f"scoreboard players {action} {holder} {obj} {number}"
    _same_as_general(text, version, "_fast_set")


@settings(max_examples=300, deadline=None)
@given(_WORDS, _WORDS, st.sampled_from(["=", "+=", "><", "**", "<", ""]), _WORDS, _WORDS,
       st.sampled_from([(1, 16, 5), (1, 21, 0)]))
def test_fast_operation_path_matches_the_general_path(target, obj, op, source, obj2, version):
    text = f"scoreboard players operation {target} {obj} {op} {source} {obj2}"
    _same_as_general(text, version, "_fast_operation")


def _same_as_general(text, version, fast_name):
    fast = parse_command(text, LOC, version)
    original = getattr(scoreboard, fast_name)
    setattr(scoreboard, fast_name, lambda *args: None)
    try:
        general = parse_command(text, LOC, version)
    finally:
        setattr(scoreboard, fast_name, original)
    assert fast[0] == general[0]
    assert [(d.col, d.message) for d in fast[1]] == [(d.col, d.message) for d in general[1]]


def test_double_space_is_reported_as_such():
    d = parse_err("scoreboard players set @s x 1  ")
    assert "exactly one space" in d.message
