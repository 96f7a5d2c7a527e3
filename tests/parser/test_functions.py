import pytest

from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte, String
from mcfunction_parser.parse import parse_command
from tests.parser.parser_helpers import LOC, parse_err, parse_ok


def test_function_forms():
    cmd = parse_ok("function foo")
    assert (cmd.function, cmd.is_tag, cmd.arguments) == ("minecraft:foo", False, None)
    tag = parse_ok("function #ns:load")
    assert (tag.function, tag.is_tag) == ("ns:load", True)
    args = parse_ok('function ns:m {a:1b,b:"x"}').arguments
    assert args == {"a": 1, "b": "x"} and type(args["a"]) is Byte and type(args["b"]) is String
    w = parse_ok("function ns:m with storage ns:s args.list[0]")
    assert isinstance(w.with_source, ast.StorageData) and w.with_path.text == "args.list[0]"
    w2 = parse_ok("function ns:m with entity @s")
    assert isinstance(w2.with_source, ast.EntityData) and w2.with_path is None


def test_function_arguments_need_1_20_2():
    assert "1.20.2" in parse_err("function ns:m {a:1}", (1, 20, 1)).message
    assert parse_ok("function ns:m", (1, 16, 5)).function == "ns:m"


def test_function_id_charset():
    d = parse_err("function ns:Bad")
    assert "invalid character 'B'" in d.message and d.col == len("function ns:") + 1
    assert "':'" in parse_err("function a:b:c").message


def test_return_forms():
    assert parse_ok("return -7").value == -7
    run = parse_ok("return run scoreboard players get @s x")
    assert run.kind == "run" and isinstance(run.command, ast.ScoreGet)
    assert parse_ok("return fail").kind == "fail"


@pytest.mark.parametrize("text,version,needed", [
    ("return 1", (1, 19, 4), "1.20"),
    ("return run say", (1, 20, 2), "1.20.3"),
    ("return fail", (1, 20, 2), "1.20.3"),
])
def test_return_versions(text, version, needed):
    d = parse_err(text, version)
    assert f"requires Minecraft {needed} or later (pack targets {version[0]}.{version[1]}" in d.message


@pytest.mark.parametrize("time,ticks", [("10", 10), ("10t", 10), ("2s", 40), ("1d", 24000), ("0.5s", 10)])
def test_schedule_time_units(time, ticks):
    cmd = parse_ok(f"schedule function ns:f {time}")
    assert cmd.ticks == ticks and cmd.mode == "replace"


@pytest.mark.parametrize("time", ["1x", "1tx", "1e5"])
def test_a_time_unit_is_the_rest_of_the_word(time):
    # TimeArgument.parse: readFloat, then readUnquotedString for the unit, which must be t, s, d or
    # nothing (ERROR_INVALID_UNIT "Invalid unit"): 1e5 is 1 with the unit e5
    d = parse_err(f"schedule function ns:f {time}")
    assert d.message.startswith("invalid unit") and d.col == len("schedule function ns:f 1") + 1


def test_schedule_modes_and_clear():
    assert parse_ok("schedule function #ns:t 1t append").mode == "append"
    clear = parse_ok("schedule clear #ns:t")
    assert isinstance(clear, ast.ScheduleClear) and clear.is_tag and clear.function == "ns:t"


def test_schedule_zero_parses_with_a_warning():
    # ScheduleCommand accepts the argument and throws ERROR_SAME_TICK when run (decompiled 1.21.x),
    # so the function still loads; the command is kept and flagged
    text = "schedule function ns:f 0t"
    cmd, diags = parse_command(text, LOC)
    assert cmd.ticks == 0
    assert [d.severity for d in diags] == ["warning"] and diags[0].col == text.index("0t") + 1
    assert "at least 0" in parse_err("schedule function ns:f -1t").message
    assert "schedule mode" in parse_err("schedule function ns:f 1 later").message
