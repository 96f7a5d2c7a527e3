"""``bossbar``: the command tree of BossBarCommands.register (1.21)."""
import pytest

from mcfunction_parser import ast
from tests.parser.parser_helpers import parse_err, parse_ok


def test_add_remove_list():
    cmd = parse_ok('bossbar add t:hp {"text":"HP"}')
    assert (cmd.action, cmd.id, cmd.text) == ("add", "t:hp", '{"text":"HP"}')
    assert parse_ok('bossbar add hp "plain"').text == '"plain"'
    assert parse_ok("bossbar remove t:hp").action == "remove"
    assert parse_ok("bossbar list") == ast.Bossbar(parse_ok("bossbar list").loc, "list", None)


@pytest.mark.parametrize("text, field, attr, value", [
    ("bossbar set t:hp value 5", "value", "number", 5),
    ("bossbar set t:hp max 20", "max", "number", 20),
    ("bossbar set t:hp visible false", "visible", "flag", False),
    ("bossbar set t:hp color red", "color", "text", "red"),
    ("bossbar set t:hp style notched_10", "style", "text", "notched_10"),
    ('bossbar set t:hp name "x"', "name", "text", '"x"'),
    ("bossbar set t:hp players", "players", "targets", None),
])
def test_set(text, field, attr, value):
    cmd = parse_ok(text)
    assert (cmd.action, cmd.field, getattr(cmd, attr)) == ("set", field, value)


def test_set_players_takes_player_targets():
    assert isinstance(parse_ok("bossbar set t:hp players @a").targets, ast.Selector)


@pytest.mark.parametrize("field", ["value", "max", "visible", "players"])
def test_get(field):
    assert parse_ok(f"bossbar get t:hp {field}").field == field


@pytest.mark.parametrize("text, message", [
    ("bossbar set t:hp value -1", "bossbar value"),   # IntegerArgumentType.integer(0)
    ("bossbar set t:hp max 0", "bossbar max"),        # integer(1)
    ("bossbar set t:hp color orange", "color"),
    ("bossbar get t:hp name", "bossbar property"),     # get has no name
    ("bossbar add t:hp", "bossbar name"),
    ("bossbar set t:hp visible maybe", "true"),
])
def test_errors(text, message):
    assert message in parse_err(text).message
