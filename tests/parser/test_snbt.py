import math

import pytest

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import (Byte, ByteArray, Compound, Double, Float, Int, IntArray, List, Long, LongArray,
                                   Short, String, to_snbt)
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import value


def snbt(text: str, version=(1, 21, 0)):
    r = Reader(text, Loc("t", 1, 1), version)
    result = value(r)
    assert r.pos == len(text), f"stopped at {r.pos}"
    return result


def snbt_error(text: str, version=(1, 21, 0)) -> ParseError:
    with pytest.raises(ParseError) as info:
        snbt(text, version)
    return info.value


@pytest.mark.parametrize("text,kind,expected", [
    ("1b", Byte, 1), ("-2s", Short, -2), ("3", Int, 3), ("4L", Long, 4), ("4l", Long, 4),
    ("1.5f", Float, 1.5), ("2d", Double, 2.0), ("2.5", Double, 2.5), (".5", Double, 0.5), ("1.", Double, 1.0),
    ("1e3", String, "1e3"),  # an exponent without a point or suffix is not a number in TagParser
    ("1.5e3", Double, 1500.0), ("true", Byte, 1), ("false", Byte, 0),
    ("128b", String, "128b"),  # out of a byte's range: the game keeps the text as a string
    ("2147483648", String, "2147483648"), ("abc", String, "abc"), ("+5", Int, 5), ("01", String, "01"),
])
def test_typed_primitives(text, kind, expected):
    result = snbt(text)
    assert type(result) is kind and result == expected


def test_float_rounds_to_32_bits():
    assert snbt("0.1f") == pytest.approx(0.1, rel=1e-7) and snbt("0.1f") != 0.1


def test_strings_and_escapes():
    assert snbt('"a\\"b"') == 'a"b'
    assert snbt("'it''s'".replace("''", "\\'")) == "it's"
    assert "escape" in snbt_error('"a\\nb"').message


def test_compounds_lists_arrays():
    c = snbt('{a: 1b , "b c":[1,2,],d:{},e:[B;1b,2b],f:[L;1L],g:[]}')
    assert type(c) is Compound and list(c) == ["a", "b c", "d", "e", "f", "g"]
    assert type(c["b c"]) is List and c["b c"] == [1, 2]
    assert type(c["e"]) is ByteArray and type(c["f"]) is LongArray
    assert type(snbt("[I;]")) is IntArray


def test_round_trip_through_to_snbt():
    text = '{a:1b,b:2s,c:3,d:4L,e:1.5f,f:2.5d,g:"x",h:[1,2],i:[I;1,2]}'
    assert snbt(to_snbt(snbt(text))) == snbt(text)


@pytest.mark.parametrize("text,message", [
    ("[1,2b]", "can't insert TAG_Byte into a list of TAG_Int"),
    ("[B;1,2]", "can't insert TAG_Int into TAG_Byte_Array"),
    ("[X;1]", "invalid array type"),
    ("{a:1", "expected ',' or '}'"),
    ("{:1}", "expected a key"),
    ("{a 1}", "expected ':'"),
    ("[1 2]", "expected ',' or ']'"),
    ('"open', "unclosed"),
])
def test_errors(text, message):
    assert message in snbt_error(text).message


def test_mixed_lists_from_1_21_5():
    assert snbt("[1,2b]", (1, 21, 5)) == [1, 2]


def test_float_overflow_is_infinity():
    # Float.parseFloat("1e39") is Infinity; TagParser keeps it as a float tag
    result = snbt("1e39f")
    assert type(result) is Float and math.isinf(result)


def test_new_grammar_escapes_from_1_21_5():
    # 25w02a: quoted SNBT strings gained \b \s \t \n \f \r \x.. \u.... \U........ \N{name}
    assert snbt(r'"a\nb\tc\sd\x41\u00e9\N{SNOWMAN}"', (1, 21, 5)) == "a\nb\tc dA\u00e9\u2603"
    assert snbt(r"{'k\n':1}", (1, 21, 5)) == {"k\n": 1}
    assert "escape" in snbt_error(r'"a\qb"', (1, 21, 5)).message
    assert "character name" in snbt_error(r'"\N{NOT A NAME}"', (1, 21, 5)).message
    assert "escape" in snbt_error(r'"a\nb"', (1, 21, 4)).message


def test_arrays_take_any_integer_from_1_21_5():
    assert type(snbt("[B;1,2]", (1, 21, 5))) is ByteArray


def test_operations_from_1_21_5():
    assert snbt("bool(5)", (1, 21, 5)) == 1 and type(snbt("bool(0)", (1, 21, 5))) is Byte
    assert snbt("{a:bool(false)}", (1, 21, 5)) == {"a": 0}
    # UUID 0-0-0-0-1 is the int array [0,0,0,1]; f81d4fae-7dec-11d0-a765-00a0c91e6bf6 as the game stores it
    assert snbt("uuid(0-0-0-0-1)", (1, 21, 5)) == [0, 0, 0, 1]
    assert snbt("uuid(f81d4fae-7dec-11d0-a765-00a0c91e6bf6)", (1, 21, 5)) == [-132296786, 2112623056, -1486552928,
                                                                               -920753162]
    assert "bool(..)" in snbt_error("bool('x')", (1, 21, 5)).message
    assert type(snbt("bool", (1, 21, 5))) is String


NEW = (1, 21, 5)


# SnbtGrammar (25w02a, read in the decompiled 1.21.7 source): integer_literal is sign? (0x HEX | 0b BIN |
# DEC) suffix?, where hex and binary are unsigned unless 's' precedes the type, decimal signed unless 'u'
# does; '_' may separate digits; float_literal also takes an exponent without a point.
@pytest.mark.parametrize("text,kind,expected", [
    ("0x1F", Int, 31), ("0xFFub", Byte, -1), ("0xFFFFFFFF", Int, -1), ("-1sb", Byte, -1), ("0b101", Int, 5),
    ("0b", Byte, 0), ("0b1b", Byte, 1), ("0xFFb", Int, 0xFFB),  # hex digits run greedily: 'b' is one
    ("1_000", Int, 1000), ("1ub", Byte, 1), ("1sl", Long, 1), ("0xFFFFFFFFFFFFFFFFul", Long, -1),
    ("1e3", Double, 1000.0), ("1.5e3f", Float, 1500.0), ("+.5e-3d", Double, 0.0005), ("1.", Double, 1.0),
    ("1i", Int, 1), ("TRUE", Byte, 1), ("False", Byte, 0), ("_1", String, "_1"),
])
def test_new_grammar_numbers(text, kind, expected):
    result = snbt(text, NEW)
    assert type(result) is kind and result == expected


@pytest.mark.parametrize("text,message", [
    ("01", "invalid number"),  # leading_zero_not_allowed
    ("1_", "invalid number"), ("1a", "invalid number"), ("-", "invalid number"),  # invalid_unquoted_start
    ("-0x1", "non-negative"), ("-1ub", "non-negative"),
    ("128b", "out of range for TAG_Byte"), ("2147483648", "out of range for TAG_Int"),
    ("0x100000000", "out of range for an unsigned TAG_Int"),
    ("1e400", "infinity"), ("1e39f", "infinity"),
])
def test_new_grammar_number_errors(text, message):
    # the old parser kept such tokens as strings; the new grammar only lets an unquoted string start
    # with a character that can't start a number
    assert message in snbt_error(text, NEW).message
    assert snbt_error(text, NEW).pos == 0


def test_new_grammar_typed_arrays_hold_integer_literals_of_their_type():
    # ArrayPrefix: B takes bytes, I ints, bytes and shorts, L every integer type; no suffix means the array's type
    assert snbt("[B;1,2]", NEW) == [1, 2] and snbt("[I;1b,2s,3]", NEW) == [1, 2, 3]
    assert type(snbt("[L;1,2i]", NEW)) is LongArray
    assert "TAG_Long into an array of TAG_Byte" in snbt_error("[B;1L]", NEW).message
    assert "TAG_Long into an array of TAG_Int" in snbt_error("[I;1L]", NEW).message
    assert "out of range for TAG_Byte" in snbt_error("[B;200]", NEW).message
    assert "expected an integer" in snbt_error("[I;abc]", NEW).message
    assert snbt_error("[I;1.5]", NEW).pos == 3


def test_old_grammar_keeps_strings_and_compares_booleans_ignoring_case():
    # TagParser.type (1.13 - 1.21.4): patterns match the whole token or it is a string; "true".equalsIgnoreCase
    assert snbt("0x1F") == "0x1F" and type(snbt("1_000")) is String
    assert type(snbt("TRUE")) is Byte and snbt("TRUE") == 1


@pytest.mark.parametrize("version", [(1, 20, 4), NEW])
def test_nesting_up_to_512_levels(version):
    # the game's NBT depth limit is 512 (NbtAccounter); deeper data can't be stored
    deep = snbt("{a:" * 512 + "1" + "}" * 512, version)
    assert type(deep) is Compound
    assert type(snbt("[" * 512 + "]" * 512, version)) is List
    assert "deeper than 512" in snbt_error("[" * 513 + "]" * 513, version).message
    assert "deeper than 512" in snbt_error("{a:" * 600 + "1" + "}" * 600, version).message


def test_a_command_with_512_levels_parses():
    from mcfunction_parser.parse import parse_command
    cmd, diagnostics = parse_command("execute as @s run data merge storage a:b " + "{a:" * 512 + "1" + "}" * 512,
                                     Loc("f", 1, 1))
    assert cmd is not None and diagnostics == []


@pytest.mark.parametrize("text, old, new", [
    # StringTag.quoteAndEscape: the quote is the one the first quote character of the text is not,
    # only that quote (and backslashes) escaped; 1.21.5 adds SnbtGrammar.escapeControlCharacters
    # (decompiled 1.21.1 and 1.21.11 nbt/StringTag)
    ('a"b\'c', "'a\"b\\'c'", "'a\"b\\'c'"),
    ("a'b\"c", '"a\'b\\"c"', '"a\'b\\"c"'),
    ("x\\y", '"x\\\\y"', '"x\\\\y"'),
    ("l1\nl2\t\x01\x7f", '"l1\nl2\t\x01\x7f"', '"l1\\nl2\\t\\x01\x7f"'),
])
def test_strings_are_quoted_as_the_game_quotes_them(text, old, new):
    assert (to_snbt(String(text)), to_snbt(String(text), from_1_21_5=True)) == (old, new)


def test_arrays_print_with_the_games_suffixes():
    # StringTagVisitor.visitByteArray appends 'B' (upper case), visitLongArray 'L', visitIntArray none
    # (decompiled 1.21.11 nbt/StringTagVisitor)
    assert [to_snbt(ByteArray([1, -2])), to_snbt(IntArray([1])), to_snbt(LongArray([3]))] == [
        "[B;1B,-2B]", "[I;1]", "[L;3L]"]
