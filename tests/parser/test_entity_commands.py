import pytest

from mcfunction_parser import ast
from tests.parser.parser_helpers import parse_err, parse_ok


def test_tag():
    cmd = parse_ok("tag @e[type=minecraft:pig] add piggy")
    assert (cmd.action, cmd.name) == ("add", "piggy")
    assert parse_ok("tag @s list").name is None
    assert "tag action" in parse_err("tag @s toggle x").message


def test_player_names_as_targets():
    assert parse_ok("tag Steve add x").targets.name == "Steve"
    assert parse_ok('tag "Steve" add x').targets.name == "Steve"
    uuid = parse_ok("tag 00000000-0000-0000-0000-000000000001 add x").targets
    assert uuid.is_uuid
    # a fake player is a score holder, not an entity (EntitySelectorParser.parseNameOrUUID)
    assert "player name" in parse_err("tag #fake add x").message
    assert "player name" in parse_err("tag abcdefghijklmnopq add x").message


def test_summon():
    cmd = parse_ok("summon armor_stand ~ ~1 ~ {Invisible:1b}")
    assert cmd.entity_type == "minecraft:armor_stand" and cmd.pos.y.value == 1.0 and cmd.nbt["Invisible"] == 1
    bare = parse_ok("summon minecraft:pig")
    assert bare.pos is None and bare.nbt is None


def test_kill():
    assert parse_ok("kill").targets is None
    assert parse_ok("kill @e[type=item]").targets.variable == "e"


@pytest.mark.parametrize("text,targets,dest,extra", [
    ("tp @p", None, ast.Selector, {}),
    ("tp 1 2 3", None, ast.Vec3, {}),
    ("tp Steve", None, ast.NameTarget, {}),
    ("tp @e[tag=a] @s", ast.Selector, ast.Selector, {}),
    ("tp Steve Alex", ast.NameTarget, ast.NameTarget, {}),
    ("teleport @s ~ ~ ~ 90 0", ast.Selector, ast.Vec3, {"rotation": ast.Vec2}),
    ("tp @s ~ ~ ~ facing 0 64 0", ast.Selector, ast.Vec3, {"facing": ast.Vec3}),
    ("tp @s ~ ~ ~ facing entity @p eyes", ast.Selector, ast.Vec3, {"facing_entity": ast.Selector}),
    ("tp @s ^ ^ ^1", ast.Selector, ast.Vec3, {}),
])
def test_teleport_forms(text, targets, dest, extra):
    cmd = parse_ok(text)
    assert isinstance(cmd, ast.Teleport)
    assert (cmd.targets is None) if targets is None else isinstance(cmd.targets, targets)
    assert isinstance(cmd.destination, dest)
    for field, kind in extra.items():
        assert isinstance(getattr(cmd, field), kind)


def test_teleport_errors():
    assert "only one" in parse_err("tp @e").message
    assert "only one" in parse_err("tp @a @e").message
    assert "anchor" in parse_err("tp @s ~ ~ ~ facing entity @p head").message
    assert "mix" in parse_err("tp @s ^ ~ ^").message
