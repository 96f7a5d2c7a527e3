"""NBT value types, as SNBT literals in commands produce them and as the emulator's world stores them.

Each numeric tag is a subclass of ``int`` or ``float`` so arithmetic and comparisons work directly,
while the class keeps the tag type that the game distinguishes (``1b`` is not ``1``).
Compounds are ``dict`` subclasses (key order kept), lists are ``list`` subclasses.
"""
from __future__ import annotations

import re


class Byte(int):
    tag_id = 1
    suffix = "b"


class Short(int):
    tag_id = 2
    suffix = "s"


class Int(int):
    tag_id = 3
    suffix = ""


class Long(int):
    tag_id = 4
    suffix = "L"


class Float(float):
    tag_id = 5
    suffix = "f"


class Double(float):
    tag_id = 6
    suffix = "d"


class String(str):
    tag_id = 8


class List(list):
    tag_id = 9


class Compound(dict):
    tag_id = 10


class ByteArray(list):
    tag_id = 7
    prefix = "B"


class IntArray(list):
    tag_id = 11
    prefix = "I"


class LongArray(list):
    tag_id = 12
    prefix = "L"


NUMERIC_TYPES = (Byte, Short, Int, Long, Float, Double)
ARRAY_TYPES = (ByteArray, IntArray, LongArray)
INT_RANGES = {Byte: 8, Short: 16, Int: 32, Long: 64}


def to_snbt(value, from_1_21_5: bool = False, decimal=None) -> str:
    """Serialise a value to SNBT as the game prints it (StringTagVisitor: ``data get`` output, a text
    component's ``nbt``, a macro argument): a compound's keys in order (Collections.sort before
    1.21.5, Entry.comparingByKey from it: String.compareTo, by UTF-16 unit), each written bare when
    simple: SIMPLE_VALUE ``[A-Za-z0-9._+-]+`` before 1.21.5, from it (``from_1_21_5``)
    UNQUOTED_KEY_MATCH ``[A-Za-z._]+[A-Za-z0-9._+-]*`` and not true or false (handleKeyEscape);
    strings as :func:`_quote` writes them.
    ``decimal(x)`` writes a Float's or a Double's digits (the game: Float.toString and
    Double.toString; by default Python's repr, without a trailing ``.0``)."""
    if isinstance(value, bool):
        return "1b" if value else "0b"
    if isinstance(value, (Byte, Short, Int, Long)):
        return f"{int(value)}{value.suffix}"
    if isinstance(value, (Float, Double)):
        return f"{(decimal or _float_text)(value)}{value.suffix}"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{(decimal or _float_text)(Double(value))}d"
    if isinstance(value, str):
        return _quote(value, from_1_21_5)
    if isinstance(value, ARRAY_TYPES):
        suffix = _ARRAY_SUFFIX[type(value)]  # visitByteArray writes 1B, visitLongArray 1L
        return f"[{value.prefix};" + ",".join(f"{int(v)}{suffix}" for v in value) + "]"
    if isinstance(value, dict):
        key = _new_key if from_1_21_5 else _key
        return "{" + ",".join(f"{key(k)}:{to_snbt(value[k], from_1_21_5, decimal)}" for k in sorted(value, key=_java_order)) + "}"
    if isinstance(value, list):
        return "[" + ",".join(to_snbt(v, from_1_21_5, decimal) for v in value) + "]"
    raise TypeError(f"not an NBT value: {value!r}")


_ARRAY_SUFFIX = {ByteArray: "B", IntArray: "", LongArray: "L"}


def _java_order(key: str) -> bytes:
    """String.compareTo's order: by UTF-16 code unit (a code point above U+FFFF sorts as its
    surrogates, below U+E000)."""
    return key.encode("utf-16-be", "surrogatepass")


def type_of_array_item(array) -> type:
    return {ByteArray: Byte, IntArray: Int, LongArray: Long}[type(array)]


def _float_text(x) -> str:
    text = repr(float(x))
    return text[:-2] if text.endswith(".0") and "e" not in text else text


_BARE = set("0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_-.+")


def _key(key: str) -> str:
    return key if key and all(c in _BARE for c in key) else _quote(key)


_UNQUOTED_KEY = re.compile(r"[A-Za-z._]+[A-Za-z0-9._+-]*")


def _new_key(key: str) -> str:
    return key if _UNQUOTED_KEY.fullmatch(key) and key.lower() not in ("true", "false") else _quote(key, True)


def _quote(text: str, new: bool = False) -> str:
    r"""StringTag.quoteAndEscape: in the quote that the first quote character of the text is not
    (double when there is none), that quote and backslashes escaped; from 1.21.5 (``new``) control
    characters too (SnbtGrammar.escapeControlCharacters: \b \t \n \f \r, any other below a space
    as \xHH)."""
    first = next((c for c in text if c in "\"'"), None)
    quote = "'" if first == '"' else '"'
    escaped = text.replace("\\", "\\\\").replace(quote, "\\" + quote)
    if new and any(c < " " for c in escaped):
        escaped = "".join((_CONTROL.get(c) or f"\\x{ord(c):02X}") if c < " " else c for c in escaped)
    return f"{quote}{escaped}{quote}"


_CONTROL = {"\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}
