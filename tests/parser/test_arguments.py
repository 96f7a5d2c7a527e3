import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mcfunction_parser import arguments, primitives
from mcfunction_parser.ast import Coord
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.reader import ParseError, Reader
from tests.parser.parser_helpers import parse_err, parse_ok


def reader(text: str, version=(1, 21, 0)) -> Reader:
    return Reader(text, Loc("t", 1, 1), version)


def slow_vec3(text: str, block: bool):
    """The coordinate-by-coordinate path that the one-regex fast path must agree with."""
    r = reader(text)
    coords = [arguments._coord(r, block, True)]
    for _ in range(2):
        r.space()
        coords.append(arguments._coord(r, block, True))
    if sum(c.kind == "local" for c in coords) not in (0, 3):
        raise ParseError("mixed", 0)
    return coords, r.pos


COORD = st.one_of(st.sampled_from(["~", "^", "0", "-1", "1.5", ".5", "1.", "-", "1..2", "~-3", "^.5", "~1.5", "12"]),
                  st.from_regex(r"[~^]?-?[0-9]{0,3}(\.[0-9]{0,2})?", fullmatch=True))


@settings(max_examples=300, deadline=None)
@given(st.tuples(COORD, COORD, COORD), st.booleans())
def test_vec3_fast_path_agrees_with_slow_path(parts, block):
    text = " ".join(parts)
    try:
        expected = slow_vec3(text, block)
    except ParseError:
        expected = None
    for _ in range(2):  # the second time the well-formed positions come from the cache
        r = reader(text)
        try:
            got = arguments.vec3(r, block)
            got = ([got.x, got.y, got.z], r.pos)
        except ParseError:
            got = None
        assert got == expected


RANGE = st.one_of(st.sampled_from(["1", "..-1", "1..", "5..1", "..", "1.5", "", "2147483648", "-0..0", "1...2", ".."]),
                  st.from_regex(r"-?[0-9]{0,3}(\.\.?)?-?[0-9]{0,3}", fullmatch=True))


@settings(max_examples=300, deadline=None)
@given(RANGE, st.sampled_from(["", " x", "]", ",a"]))
def test_int_range_cache_agrees_with_the_general_path(text, tail):
    def general():
        r = reader(text + tail)
        try:
            lo, hi = primitives._range(r, True)
            return (lo, hi), r.pos
        except ParseError as error:
            return error.message, error.pos

    def cached():
        r = reader(text + tail)
        try:
            rng = primitives.int_range(r)
            return (rng.lo, rng.hi), r.pos
        except ParseError as error:
            return error.message, error.pos

    expected = general()
    assert cached() == expected and cached() == expected  # a miss, then a hit when it parsed


def test_coordinates():
    v = arguments.vec3(reader("~ ~1.5 -3"))
    assert (v.x, v.y, v.z) == (Coord("rel", 0.0), Coord("rel", 1.5), Coord("abs", -3.0, True))
    assert arguments.vec3(reader("1.0 2 3")).x.is_int is False
    with pytest.raises(ParseError, match="integer coordinate"):
        arguments.vec3(reader("1.5 2 3"), block=True)
    assert arguments.vec3(reader("~0.5 2 3"), block=True).x.value == 0.5


@pytest.mark.parametrize("text,lo,hi", [("1..5", 1, 5), ("..0", None, 0), ("3", 3, 3), ("-5..", -5, None)])
def test_int_ranges(text, lo, hi):
    rng = primitives.int_range(reader(text))
    assert (rng.lo, rng.hi) == (lo, hi)


@pytest.mark.parametrize("text,lo,hi", [("1.5..", 1.5, None), ("..-.5", None, -0.5), ("0.1..2", 0.1, 2.0)])
def test_float_ranges(text, lo, hi):
    rng = primitives.float_range(reader(text))
    assert (rng.lo, rng.hi) == (lo, hi)


@pytest.mark.parametrize("text,message", [("..", "value or range"), ("5..1", "bigger than"),
                                          ("1.5", "invalid integer")])
def test_range_errors(text, message):
    with pytest.raises(ParseError, match=message):
        primitives.int_range(reader(text))


@pytest.mark.parametrize("text,expected", [("foo", "minecraft:foo"), ("a:b/c", "a:b/c"), (":x", "minecraft:x"),
                                           ("a.b-c_d:e/f.g", "a.b-c_d:e/f.g"), ("a:", "a:"), (":", "minecraft:")])
def test_resource_locations(text, expected):
    """ResourceLocation.bySeparator; isValidPath accepts an empty path (no character to refuse)."""
    assert primitives.resource_location(reader(text)) == expected


@pytest.mark.parametrize("text,message", [("Foo", "invalid character 'F'"), ("a:b:c", "more than one"),
                                          ("a/b:c", "namespace")])
def test_resource_location_errors(text, message):
    with pytest.raises(ParseError, match=message):
        primitives.resource_location(reader(text))


def test_json_spans():
    r = reader('{"a":"]}","b":[1,{"c":2}]} rest')
    assert primitives.json_span(r) == '{"a":"]}","b":[1,{"c":2}]}' and r.pos == r.text.index(" rest")
    assert primitives.json_span(reader('"a \\" b"')) == '"a \\" b"'
    with pytest.raises(ParseError, match="unbalanced"):
        primitives.json_span(reader('{"a":[1}'))
    with pytest.raises(ParseError, match="unclosed quoted"):
        primitives.json_span(reader('{"a:1}'))


def test_durations():
    assert arguments.duration(reader("1.5s")) == 30
    with pytest.raises(ParseError, match="at least 0"):
        arguments.duration(reader("-1"))
    with pytest.raises(ParseError, match="invalid time"):
        arguments.duration(reader("1..2"))


def test_durations_round_as_math_round_of_a_float():
    """TimeArgument.parse: Math.round(readFloat() * unit), the product in float: halves round up
    (0.5 -> 1, 2.5 -> 3, -0.5 -> 0, where Python's round gives 0, 2 and -0) and a huge count
    saturates at Integer.MAX_VALUE."""
    assert [arguments.duration(reader(text)) for text in ("0.5", "2.5", "-0.5", "0.49", "0.05s", "0.1d")] == \
        [1, 3, 0, 0, 1, 2400]
    assert arguments.duration(reader("9" * 50)) == 2**31 - 1
    assert parse_ok("weather rain 0.5")  # the node's minimum is 1: 0.5 rounds to 1 tick


def test_integer_errors_name_the_token():
    d = parse_err("scoreboard players set @s x 1.5")
    assert "invalid integer '1.5'" in d.message
    assert "expected score" in parse_err("scoreboard players set @s x abc").message
    assert parse_ok("scoreboard players set @s x -0").value == 0


HUGE = "9" * 1_000_000


@pytest.mark.parametrize("text, col", [
    (f"scoreboard players set #a o {HUGE}", 29),
    (f"scoreboard players add #a o -{HUGE}", 29),
    (f"execute if score #a o matches ..{HUGE} run say x", 33),
    (f"data get storage t:a a[{HUGE}]", 24),
])
def test_a_huge_integer_literal_is_out_of_range_at_its_column(text, col):
    # Brigadier's readInt fails on any literal past Integer.MAX_VALUE; a million digits is no
    # different, and the message quotes the literal's start, not all of it.
    error = parse_err(text)
    assert "out of range" in error.message and error.col == col
    assert len(error.message) < 200


def test_a_huge_literal_in_snbt_is_not_a_number():
    # TagParser.type: an integer out of range for its type reads as a string
    cmd = parse_ok(f"data merge storage t:a {{a:{HUGE}}}")
    assert type(cmd.nbt["a"]).__name__ == "String"
