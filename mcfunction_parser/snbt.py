r"""SNBT (stringified NBT) literals, with the game's TagParser rules (1.13 – 1.21.4).

Unquoted values are typed by the game's patterns: ``1b 2s 3 4L 1.5f 2.0d 1.5`` (a bare decimal is
a double), ``true``/``false`` are bytes, a number out of its type's range stays a string.
From 1.21.5 (25w02a) the game's new SNBT grammar (SnbtGrammar) also accepts lists of mixed types,
more escapes in quoted strings (``\n \t \s \x41 \u00e9 \N{name}``...), the ``bool(..)``/``uuid(..)``
operations and new number literals: hex ``0x1F``, binary ``0b101``, ``_`` between digits, signed and
unsigned suffixes (``0xFFub``, ``-1sb``), an exponent without a point (``1e3``); typed arrays hold
integer literals typed by the array (``[B;1,2]``). A token that starts like a number (a digit, sign or
point) must then be a valid number: out of range, ``01`` or ``1a`` are errors instead of strings.
Compounds and lists nest up to 512 levels, the game's NBT depth limit.
"""
from __future__ import annotations

import re
import struct
import sys
import unicodedata

from .nbt import (Byte, ByteArray, Compound, Double, Float, Int, IntArray, List, Long, LongArray, Short,
                  String)
from .primitives import UUID_TEXT, uuid_ints
from .reader import UNQUOTED, Reader, integer_value, show

_INTEGER = re.compile(r"[-+]?(?:0|[1-9][0-9]*)([bBsSlL]?)\Z")
_DECIMAL = re.compile(r"[-+]?(?:[0-9]+\.|[0-9]*\.[0-9]+)(?:[eE][-+]?[0-9]+)?\Z")
_SUFFIXED = re.compile(r"[-+]?(?:[0-9]+\.?|[0-9]*\.[0-9]+)(?:[eE][-+]?[0-9]+)?([dDfF])\Z")
_INT_TYPES = {"": (Int, 32), "b": (Byte, 8), "s": (Short, 16), "l": (Long, 64)}
_WS = " \t\r\n"
_ARRAY_TYPES = {"B": (ByteArray, Byte), "I": (IntArray, Int), "L": (LongArray, Long)}
_TYPE_NAMES = {Byte: "TAG_Byte", Short: "TAG_Short", Int: "TAG_Int", Long: "TAG_Long", Float: "TAG_Float",
               Double: "TAG_Double", String: "TAG_String", List: "TAG_List", Compound: "TAG_Compound",
               ByteArray: "TAG_Byte_Array", IntArray: "TAG_Int_Array", LongArray: "TAG_Long_Array"}
NEW_GRAMMAR = (1, 21, 5)
_NEW_QUOTED = {
    '"': re.compile(r'"((?:[^"\\]|\\.)*)"'),
    "'": re.compile(r"'((?:[^'\\]|\\.)*)'"),
}
_NEW_ESCAPE = re.compile(r"\\(?:x([0-9a-fA-F]{2})|u([0-9a-fA-F]{4})|U([0-9a-fA-F]{8})|N\{([^}]*)\}|(.))")
_SIMPLE_ESCAPES = {"b": "\b", "s": " ", "t": "\t", "n": "\n", "f": "\f", "r": "\r", "\\": "\\", '"': '"', "'": "'"}

MAX_DEPTH = 512  # NbtAccounter: NBT deeper than this can't be stored or read back
# Each level is two Python frames (value -> _compound or _list_or_array); pure-Python calls don't use
# the C stack from Python 3.11, so a limit that fits 512 levels and the command around them is safe.
if sys.getrecursionlimit() < 4 * MAX_DEPTH:
    sys.setrecursionlimit(4 * MAX_DEPTH)

# SnbtGrammar's number literals. A run of digits may contain '_' but not start or end with it.
_DEC = r"[0-9](?:[0-9_]*[0-9])?"
_HEX = r"[0-9a-fA-F](?:[0-9a-fA-F_]*[0-9a-fA-F])?"
_BIN = r"[01](?:[01_]*[01])?"
# float_literal: DEC '.' DEC? | '.' DEC | DEC followed by an exponent or a suffix; then EXP? SUFFIX?
_NEW_FLOAT = re.compile(rf"([-+]?)(?:({_DEC})?\.({_DEC})?|({_DEC})(?=[eEfFdD]))(?:[eE]([-+]?{_DEC}))?([fFdD]?)\Z")
_NEW_INTEGER = re.compile(rf"([-+]?)(?:0[xX]({_HEX})|0[bB]({_BIN})|(0|[1-9](?:[0-9_]*[0-9])?))([uUsS]?[bBsSiIlL])?\Z")
_NUMBER_START = frozenset("+-.0123456789")
_SUFFIX_TYPES = {"b": Byte, "s": Short, "i": Int, "l": Long}
_BITS = {Byte: 8, Short: 16, Int: 32, Long: 64}


def to_float32(value: float) -> float:
    try:
        return struct.unpack("f", struct.pack("f", value))[0]
    except OverflowError:
        return float("inf") if value > 0 else float("-inf")


def typed_primitive(token: str):
    """The NBT value of an unquoted SNBT token (TagParser.type)."""
    m = _INTEGER.match(token)
    if m:
        kind, bits = _INT_TYPES[m.group(1).lower()]
        value = integer_value(token[:-1] if m.group(1) else token)
        if -(1 << (bits - 1)) <= value < (1 << (bits - 1)):
            return kind(value)
        return String(token)
    m = _SUFFIXED.match(token)
    if m:
        value = float(token[:-1])
        return Float(to_float32(value)) if m.group(1) in "fF" else Double(value)
    if _DECIMAL.match(token):
        return Double(float(token))
    lowered = token.lower()  # TagParser compares with equalsIgnoreCase
    if lowered == "true" or lowered == "false":
        return Byte(lowered == "true")
    return String(token)


def _new_number(r: Reader, token: str, start: int, array_type=None):
    """The value of ``token`` (at offset ``start``), which starts like a number, in SnbtGrammar (1.21.5+).

    ``array_type`` is the element type of a typed array (Byte, Int or Long), whose elements are
    integer literals defaulting to that type; None for a plain value (floats allowed, integers Int).
    """
    m = None if array_type else _NEW_FLOAT.match(token)
    if m is not None and (m.group(2) or m.group(3) or m.group(4)):
        return _new_float(r, token, start, m)
    m = _NEW_INTEGER.match(token)
    if m is None:
        r.fail(f"invalid number '{token}'", start)
    sign, hex_digits, bin_digits, dec_digits, suffix = m.groups()
    suffix = (suffix or "").lower()
    kind = _SUFFIX_TYPES[suffix[-1]] if suffix else (array_type or Int)
    if array_type and kind is not array_type and _BITS[kind] >= _BITS[array_type]:
        r.fail(f"can't insert {_TYPE_NAMES[kind]} into an array of {_TYPE_NAMES[array_type]}", start)
    digits, base = (hex_digits, 16) if hex_digits else (bin_digits, 2) if bin_digits else (dec_digits, 10)
    # decimal numbers are signed by default, hex and binary unsigned; 's' or 'u' before the type says so
    signed = suffix[:1] == "s" and len(suffix) == 2 or not suffix[:1] == "u" and base == 10
    value = integer_value(digits.replace("_", ""), base)
    bits = _BITS[kind]
    if signed:
        value = -value if sign == "-" else value
        if not -(1 << (bits - 1)) <= value < (1 << (bits - 1)):
            r.fail(f"number '{token}' is out of range for {_TYPE_NAMES[kind]}", start)
    else:
        if sign == "-":
            r.fail(f"expected a non-negative number: '{token}' is unsigned", start)
        if value >= 1 << bits:
            r.fail(f"number '{token}' is out of range for an unsigned {_TYPE_NAMES[kind]}", start)
        if value >= 1 << (bits - 1):
            value -= 1 << bits  # stored as the signed type, as the game's createByte/Int/... do
    return kind(value) if array_type is None else array_type(value)


def _new_float(r: Reader, token: str, start: int, m):
    sign, whole, fraction, whole_only, exponent, suffix = m.groups()
    text = sign + (whole or whole_only or "0") + "." + (fraction or "0") + ("e" + exponent if exponent else "")
    value = float(text.replace("_", ""))
    if suffix in ("f", "F"):
        value = to_float32(value)
    if value in (float("inf"), float("-inf")):
        r.fail(f"number '{token}' is too large (infinity is not allowed)", start)
    return Float(value) if suffix in ("f", "F") else Double(value)


def _quoted(r: Reader) -> str:
    """A quoted string: Brigadier's escapes (quote and backslash) before 1.21.5, the SNBT grammar's after."""
    if r.version < NEW_GRAMMAR:
        return r.quoted()
    start = r.pos
    m = _NEW_QUOTED[r.text[start]].match(r.text, start)
    if m is None:
        r.fail("unclosed quoted string", start)
    body = m.group(1)
    if "\\" in body:
        body = _NEW_ESCAPE.sub(lambda e: _unescape(r, e, start + 1), body)
    r.pos = m.end()
    return body


def _unescape(r: Reader, e, offset: int) -> str:
    hex_2, hex_4, hex_8, name, char = e.groups()
    code = hex_2 or hex_4 or hex_8
    if code:
        value = int(code, 16)
        if value > 0x10FFFF:
            r.fail(f"invalid code point in escape '{e.group()}'", offset + e.start())
        return chr(value)
    if name is not None:
        try:
            return unicodedata.lookup(name)
        except KeyError:
            r.fail(f"unknown character name in escape '{e.group()}'", offset + e.start())
    if char in _SIMPLE_ESCAPES:
        return _SIMPLE_ESCAPES[char]
    r.fail(f"invalid escape sequence '{e.group()}' in quoted string", offset + e.start())


def _skip_ws(r: Reader) -> None:
    text, pos, end = r.text, r.pos, r.end
    while pos < end and text[pos] in _WS:
        pos += 1
    r.pos = pos


def compound(r: Reader) -> Compound:
    """A ``{...}`` compound starting at the cursor."""
    if r.peek() != "{":
        r.fail(f"expected an NBT compound '{{...}}', got {r.found()}")
    return _compound(r, 1)


def value(r: Reader, depth: int = 0):
    """Any SNBT value starting at the cursor; ``depth`` counts the compounds and lists around it."""
    _skip_ws(r)
    c = r.peek()
    if c == "{":
        return _compound(r, depth + 1)
    if c == "[":
        return _list_or_array(r, depth + 1)
    if c == '"' or c == "'":
        return String(_quoted(r))
    start = r.pos
    m = UNQUOTED.match(r.text, start)
    token = m.group()
    if not token:
        r.fail(f"expected an NBT value, got {show(r.text[start:start + 1])}")
    r.pos = m.end()
    if r.version < NEW_GRAMMAR:
        return typed_primitive(token)
    if token[0] in _NUMBER_START:
        return _new_number(r, token, start)
    if token in _OPERATIONS and r.peek() == "(":
        return _OPERATIONS[token](r, start, depth)
    lowered = token.lower()
    if lowered == "true" or lowered == "false":
        return Byte(lowered == "true")
    return String(token)


def _operation_argument(r: Reader, depth: int):
    r.pos += 1  # '('
    argument = value(r, depth)
    _skip_ws(r)
    r.expect(")")
    return argument


def _bool(r: Reader, start: int, depth: int) -> Byte:
    """``bool(x)``: 1b when the number x is not zero (or x is true)."""
    argument = _operation_argument(r, depth)
    if type(argument) is String:
        r.fail("bool(..) expects a number or a boolean", start)
    return Byte(1 if argument else 0)


def _uuid(r: Reader, start: int, depth: int) -> IntArray:
    """``uuid(x)``: the UUID text as the game's four-int array."""
    r.pos += 1  # '('
    _skip_ws(r)
    m = UUID_TEXT.match(r.text, r.pos)
    if m is None:
        r.fail("uuid(..) expects a UUID like 0-0-0-0-1", r.pos)
    r.pos = m.end()
    _skip_ws(r)
    r.expect(")")
    return IntArray(uuid_ints(m.group()))


_OPERATIONS = {"bool": _bool, "uuid": _uuid}


def _check_depth(r: Reader, depth: int) -> None:
    if depth > MAX_DEPTH:
        r.fail(f"NBT nested deeper than {MAX_DEPTH} levels (the game can't store it)")


def _compound(r: Reader, depth: int) -> Compound:
    _check_depth(r, depth)
    r.pos += 1  # '{'
    result = Compound()
    _skip_ws(r)
    text = r.text
    while r.pos < r.end and text[r.pos] != "}":
        key_start = r.pos
        key = _quoted(r) if text[key_start] in "\"'" else r.unquoted()
        if not key:
            r.fail(f"expected a key, got {show(text[key_start:key_start + 1])}", key_start)
        _skip_ws(r)
        r.expect(":")
        result[key] = value(r, depth)
        if not _separator(r):
            break
        if r.pos >= r.end:
            r.fail("expected a key, got end of command")
    _skip_ws(r)
    if r.pos >= r.end or text[r.pos] != "}":
        r.fail(f"expected ',' or '}}' in NBT compound, got {show(text[r.pos:r.pos + 1])}")
    r.pos += 1
    return result


def _separator(r: Reader) -> bool:
    _skip_ws(r)
    if r.pos < r.end and r.text[r.pos] == ",":
        r.pos += 1
        _skip_ws(r)
        return True
    return False


def _list_or_array(r: Reader, depth: int):
    _check_depth(r, depth)
    text, pos = r.text, r.pos
    if pos + 2 < r.end and text[pos + 1] not in "\"'" and text[pos + 2] == ";":
        return _array(r, depth)
    r.pos += 1  # '['
    _skip_ws(r)
    items = List()
    first_type = None
    mixed_ok = r.version >= NEW_GRAMMAR
    while r.pos < r.end and text[r.pos] != "]":
        item_start = r.pos
        item = value(r, depth)
        if first_type is None:
            first_type = type(item)
        elif type(item) is not first_type and not mixed_ok:
            r.fail(f"can't insert {_TYPE_NAMES[type(item)]} into a list of {_TYPE_NAMES[first_type]}", item_start)
        items.append(item)
        if not _separator(r):
            break
        if r.pos >= r.end:
            r.fail("expected a value, got end of command")
    _skip_ws(r)
    if r.pos >= r.end or text[r.pos] != "]":
        r.fail(f"expected ',' or ']' in NBT list, got {show(text[r.pos:r.pos + 1])}")
    r.pos += 1
    return items


def _array(r: Reader, depth: int):
    text = r.text
    letter = text[r.pos + 1]
    if letter not in _ARRAY_TYPES:
        r.fail(f"invalid array type '{letter}' (expected B, I or L)", r.pos + 1)
    array_type, item_type = _ARRAY_TYPES[letter]
    r.pos += 3
    _skip_ws(r)
    items = array_type()
    new_grammar = r.version >= NEW_GRAMMAR
    while r.pos < r.end and text[r.pos] != "]":
        item_start = r.pos
        if new_grammar:  # int_array_entries: integer literals only, typed by the array
            token = r.unquoted()
            if not token or token[0] not in _NUMBER_START:
                r.fail(f"expected an integer in {_TYPE_NAMES[array_type]}, got {r.found() if not token else show(token)}",
                       item_start)
            item = _new_number(r, token, item_start, item_type)
        else:
            item = value(r, depth)
            if type(item) is not item_type:
                r.fail(f"can't insert {_TYPE_NAMES[type(item)]} into {_TYPE_NAMES[array_type]}", item_start)
        items.append(int(item))
        if not _separator(r):
            break
        if r.pos >= r.end:
            r.fail("expected a value, got end of command")
    _skip_ws(r)
    if r.pos >= r.end or text[r.pos] != "]":
        r.fail(f"expected ',' or ']' in NBT array, got {show(text[r.pos:r.pos + 1])}")
    r.pos += 1
    return items
