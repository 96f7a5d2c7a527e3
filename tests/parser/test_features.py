"""The version table checked against the game's command trees that mecha ships (one per minor
version, dumped from its last patch release)."""
from __future__ import annotations

import json
from importlib import resources

import pytest

from mcfunction_parser import features
from tests.parser.parser_helpers import parse_err, parse_ok

pytest.importorskip("mecha")

# mecha resource -> the release its command tree was dumped from
TREES = {"1_16": (1, 16, 5), "1_17": (1, 17, 1), "1_18": (1, 18, 2), "1_19": (1, 19, 4), "1_20": (1, 20, 6),
         "1_21": (1, 21, 11)}
# commands a dedicated server registers that the trees (dumped from an integrated server) may lack, and
# the other way round: none expected
TREE_ONLY: set[str] = set()


def tree(name: str) -> dict:
    return json.loads(resources.files("mecha.resources").joinpath(f"{name}.json").read_text())


@pytest.mark.parametrize("name,version", TREES.items())
def test_command_set_matches_the_game(name, version):
    expected = set(tree(name)["children"]) - TREE_ONLY
    ours = {cmd for cmd in features.COMMANDS if features.command_problem(cmd, version) is None}
    assert ours == expected


@pytest.mark.parametrize("name,version", TREES.items())
def test_execute_conditions_match_the_game(name, version):
    from mcfunction_parser.commands.execute import _CONDITIONS

    expected = set(tree(name)["children"]["execute"]["children"]["if"]["children"])
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
