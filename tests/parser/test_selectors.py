import pytest

from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command
from tests.parser.parser_helpers import parse_err, parse_ok


def _sel(text: str) -> ast.Selector:
    return parse_ok(f"kill {text}").targets


def test_every_option():
    sel = _sel('@e[type=!minecraft:pig,tag=a,tag=!b,tag=,scores={x=1..,y=..-2,z=3},limit=2,sort=furthest,'
               'distance=0.5..10,x=1,y=-2.5,z=3,dx=1,dy=2,dz=3,name="A B",nbt={OnGround:1b},'
               'team=!red,predicate=ns:p,x_rotation=-90..0,y_rotation=10,'
               'advancements={story/root=true,a:b={crit=false}}]')
    args = {a.key: a for a in sel.args if a.key not in ("tag",)}
    assert args["type"].value == "minecraft:pig" and args["type"].negated
    assert [(a.value, a.negated) for a in sel.get("tag")] == [("a", False), ("b", True), ("", False)]
    scores = dict(args["scores"].value)
    assert (scores["x"].lo, scores["x"].hi, scores["y"].hi, scores["z"].lo) == (1, None, -2, 3)
    assert args["limit"].value == 2 and args["sort"].value == "furthest"
    assert (args["distance"].value.lo, args["distance"].value.hi) == (0.5, 10.0)
    assert args["y"].value == -2.5 and args["name"].value == "A B"
    assert type(args["nbt"].value["OnGround"]) is Byte
    assert args["team"].negated and args["predicate"].value == "ns:p"
    assert args["advancements"].value.startswith("{story/root")


def test_level_and_gamemode_on_players():
    sel = _sel("@a[level=5..,gamemode=!creative]")
    assert sel.get("level")[0].value.lo == 5 and sel.get("gamemode")[0].negated


def test_whitespace_inside_brackets():
    sel = _sel("@e[ tag = a , limit = 1 ]")
    assert [a.key for a in sel.args] == ["tag", "limit"]


def test_type_tag_keeps_hash():
    assert _sel("@e[type=#minecraft:skeletons]").args[0].value == "#minecraft:skeletons"


@pytest.mark.parametrize("text,message", [
    ("@e[foo=1]", "unknown selector option 'foo'"),
    ("@x", "unknown selector type"),
    ("@e[limit=0]", "at least 1"),
    ("@s[limit=1]", "isn't applicable"),
    ("@s[sort=nearest]", "isn't applicable"),
    ("@a[type=player]", "isn't applicable"),
    ("@e[type=pig,type=cow]", "isn't applicable"),
    ("@e[type=!pig,type=cow]", "isn't applicable"),
    ("@e[name=a,name=b]", "isn't applicable"),
    ("@e[name=!a,name=b]", "isn't applicable"),
    ("@e[limit=1,limit=2]", "only once"),
    ("@e[distance=-1..]", "negative"),
    ("@e[level=-1]", "negative"),
    ("@e[sort=closest]", "sort type"),
    ("@e[gamemode=god]", "game mode"),
    ("@e[scores={x=5..1}]", "bigger than its maximum"),
    ("@e[tag=a", "unclosed selector"),
    ("@e[tag=a tag=b]", "expected ',' or ']'"),
    ("@e[tag=a,,tag=b]", "expected a selector option"),
    ("@e[limit=!1]", "expected limit"),
    ("@e[x=1..2]", "invalid number"),
])
def test_selector_errors(text, message):
    assert message in parse_err(f"kill {text}").message


def test_repeatable_and_negated_options():
    sel = _sel("@e[type=!pig,type=!cow,name=!a,name=!b,team=!x,team=y,nbt={a:1},nbt=!{b:2},"
               "predicate=a:b,predicate=!c:d]")
    assert len(sel.args) == 10


def test_error_column_points_at_option():
    text = "kill @e[tag=a,limit=1,limit=2]"
    assert parse_err(text).col == text.rindex("limit") + 1


def test_at_n_needs_1_21():
    assert "1.21" in parse_err("kill @n", (1, 20, 6)).message
    parse_ok("kill @n")


def test_repeated_selector_gets_its_own_locations():
    first = _sel("@e[tag=a, limit=2]")
    again = parse_ok("execute as @e[tag=a, limit=2] run kill").subcommands[0].targets
    assert [(a.key, a.value) for a in first.args] == [(a.key, a.value) for a in again.args]
    assert [a.loc.col for a in first.args] == [len("kill @e[") + 1, len("kill @e[tag=a, ") + 1]
    assert [a.loc.col for a in again.args] == [len("execute as @e[") + 1, len("execute as @e[tag=a, ") + 1]
    assert again.loc.col == len("execute as ") + 1


def test_repeated_selector_still_checks_the_version():
    parse_ok("kill @n[tag=a]")
    assert "1.21" in parse_err("kill @n[tag=a]", (1, 20, 4)).message


def test_a_selector_parsed_for_one_release_is_checked_again_for_another():
    # the parse of a plain selector is cached per release: armadillos exist from 1.20.5 on, so the
    # same text parsed first for 1.21 still fails for 1.20.4 (EntitySelectorOptions 'type' reads the
    # release's entity type registry); a warning (an id checked against an older release's
    # registry) is given on every parse, not only the first
    parse_ok("kill @e[type=armadillo,tag=cached]", (1, 21, 0))
    assert "unknown entity type" in parse_err("kill @e[type=armadillo,tag=cached]", (1, 20, 4)).message
    for _ in range(2):
        _, diags = parse_command("kill @e[type=nosuch,tag=cached]", Loc("t", 1, 1), (26, 2, 0))
        assert [d.severity for d in diags] == ["warning"]
