"""The version table checked against the game's command trees shipped in gamedata (one per minor
release from 1.16 and the 1.21 patches)."""
from __future__ import annotations

import pytest

from mcfunction_parser import features, gamedata
from tests.parser.parser_helpers import parse_err, parse_ok


@pytest.mark.parametrize("version", gamedata.shipped_trees())
def test_command_set_matches_the_game(version):
    # the table dates commands for the releases between and before the trees; on each tree it
    # must say what the tree says
    expected = set(gamedata.command_tree(version)["children"])
    ours = {cmd for cmd in features.COMMANDS if features.command_problem(cmd, version) is None}
    assert ours == expected


@pytest.mark.parametrize("version", gamedata.shipped_trees())
def test_execute_conditions_match_the_game(version):
    from mcfunction_parser.commands.execute import _CONDITIONS

    expected = set(gamedata.command_tree(version)["children"]["execute"]["children"]["if"]["children"])
    ours = {kind for kind, (_, feature) in _CONDITIONS.items()
            if feature is None or features.feature_problem(feature, version) is None}
    assert ours == expected


def test_messages_name_both_versions():
    assert features.command_problem("return", (1, 16, 5)) == \
        "`return` requires Minecraft 1.20 or later (pack targets 1.16.5)"
    assert features.command_problem("replaceitem", (1, 17, 0)).startswith(
        "`replaceitem` was removed in Minecraft 1.17 (pack targets 1.17)")


def test_a_valid_1_16_pack_gets_no_false_errors():
    for line in ["replaceitem entity @s weapon.mainhand minecraft:stone", "locatebiome minecraft:plains",
                 "execute as @e[type=minecraft:pig] at @s if block ~ ~-1 ~ minecraft:grass_block run tp @s ~ ~1 ~",
                 "scoreboard objectives setdisplay belowName health",
                 "attribute @s minecraft:generic.max_health base set 40",
                 "data modify storage ns:s list append value [1,2,3]", "spectate @e[type=minecraft:bat,limit=1] @s"]:
        parse_ok(line, (1, 16, 5))


def test_stopwatch_condition():
    cond = parse_ok("execute if stopwatch ns:lap 1.5..", (1, 21, 11)).subcommands[0]
    assert cond.stopwatch == "ns:lap" and cond.range.lo == 1.5
    assert "1.21.11" in parse_err("execute if stopwatch ns:lap 1..", (1, 21, 10)).message


# the syntax features a command tree shows, and where: each must agree with every shipped tree
TREE_PATHS = {
    "execute on": ("execute", "on"),
    "execute summon": ("execute", "summon"),
    "execute positioned over": ("execute", "positioned", "over"),
    "return run": ("return", "run"),
    "return fail": ("return", "fail"),
    "function arguments": ("function", "name", "arguments"),
    "data modify string": ("data", "modify", "block", "targetPos", "targetPath", "set", "string"),
    "scoreboard players display": ("scoreboard", "players", "display"),
    "objectives modify numberformat": ("scoreboard", "objectives", "modify", "objective", "numberformat"),
    "objectives modify displayautoupdate": ("scoreboard", "objectives", "modify", "objective", "displayautoupdate"),
    "random reset": ("random", "reset"),
}


def _in_tree(root: dict, path: tuple[str, ...]) -> bool:
    node = root
    for name in path:
        node = node.get("children", {}).get(name)
        if node is None:
            return False
    return True


@pytest.mark.parametrize("version", gamedata.shipped_trees())
def test_syntax_features_match_the_game(version):
    root = gamedata.command_tree(version)
    ours = {feature for feature in TREE_PATHS if features.feature_problem(feature, version) is None}
    assert ours == {feature for feature, path in TREE_PATHS.items() if _in_tree(root, path)}
