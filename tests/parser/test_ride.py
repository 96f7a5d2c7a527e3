"""``ride`` (RideCommand, 1.19.4+): single-entity target and vehicle."""
from mcfunction_parser import ast
from tests.parser.parser_helpers import parse_err, parse_ok


def test_ride_forms():
    cmd = parse_ok("ride @s mount @e[tag=v,limit=1]")
    assert (cmd.action, isinstance(cmd.vehicle, ast.Selector)) == ("mount", True)
    cmd = parse_ok("ride @e[tag=a,limit=1] dismount")
    assert (cmd.action, cmd.vehicle) == ("dismount", None)


def test_ride_errors():
    assert "ride action" in parse_err("ride @s jump").message
    assert "only one entity is allowed" in parse_err("ride @e mount @s").message  # EntityArgument.entity()
    assert "1.19.4" in parse_err("ride @s dismount", (1, 19, 3)).message
