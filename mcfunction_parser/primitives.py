"""The argument values the other argument types are read with: resource locations, int and float
ranges (MinMaxBounds), UUIDs and JSON/SNBT spans. Selector options (:mod:`.selectors`) and the
command arguments (:mod:`.arguments`, whose score holders read selectors) both build on them."""
from __future__ import annotations

import re

from .ast import FloatRange, IntRange
from .reader import FLOAT_TEXT, INT_MAX, INT_MIN, INT_TEXT, Reader, brief, integer_value

# ----------------------------------------------------------------------------- resource locations

# Characters Minecraft's ResourceLocation.read consumes; validity of each part is checked after.
_RESLOC = re.compile(r"[0-9a-z_:/.\-]*")
_RESLOC_STOP = frozenset(" ,]}=[{")


def resource_location(r: Reader, what: str = "resource location") -> str:
    """``ns:path`` or ``path`` (namespace ``minecraft``), normalised with its namespace."""
    start = r.pos
    text = r.text
    m = _RESLOC.match(text, start)
    end = m.end()
    if end < r.end and text[end] not in _RESLOC_STOP:
        r.fail(f"invalid character '{text[end]}' in {what} (allowed: a-z 0-9 _ - . / and one ':')", end)
    token = m.group()
    if not token:
        r.fail(f"expected {what}, got {r.found()}")
    r.pos = end
    colon = token.find(":")
    if colon < 0:
        return "minecraft:" + token
    namespace, path = token[:colon], token[colon + 1:]
    if ":" in path:
        r.fail(f"invalid {what} '{token}': more than one ':'", start + colon + 1 + path.index(":"))
    if "/" in namespace:
        r.fail(f"invalid {what} '{token}': '/' is not allowed in the namespace", start)
    # an empty path is valid (ResourceLocation.isValidPath of ""): ``storage call_stack:`` is a storage
    return token if namespace else "minecraft:" + path


def resource_or_tag(r: Reader, what: str) -> tuple[str, bool]:
    """``#ns:tag`` or ``ns:id``: (normalised id, is_tag)."""
    if r.peek() == "#":
        r.pos += 1
        return resource_location(r, what + " tag"), True
    return resource_location(r, what), False


# ----------------------------------------------------------------------------- ranges

# MinMaxBounds reads digits, '-' and '.' unless the '.' starts '..'.
_BOUND = re.compile(r"(?:[0-9\-]|\.(?!\.))*")


def _bound(r: Reader, is_int: bool):
    start = r.pos
    token = _BOUND.match(r.text, start).group()
    if not token:
        return None
    if not (INT_TEXT if is_int else FLOAT_TEXT).match(token):
        r.fail(f"invalid {'integer' if is_int else 'number'} '{token}' in range", start)
    r.pos = start + len(token)
    if is_int:
        value = integer_value(token)
        if not INT_MIN <= value <= INT_MAX:
            r.fail(f"integer {brief(token)} is out of range for a 32-bit int", start)
        return value
    return float(token)


def _range(r: Reader, is_int: bool, wraps: bool = False):
    """MinMaxBounds.fromReader: ``lo``, ``lo..``, ``..hi`` or ``lo..hi``; ``wraps`` (rotations,
    WrappedMinMaxBounds) lets the minimum be bigger than the maximum: the range goes round."""
    start = r.pos
    lo = _bound(r, is_int)
    if r.text.startswith("..", r.pos):
        r.pos += 2
        hi = _bound(r, is_int)
        if lo is None and hi is None:
            r.fail("expected a value or range of values, got '..'", start)
    else:
        if lo is None:
            r.fail(f"expected a value or range of values, got {r.found()}", start)
        hi = lo
    if not wraps and lo is not None and hi is not None and lo > hi:
        r.fail(f"range minimum {lo} is bigger than its maximum {hi}", start)
    return lo, hi


# A range token is read from these characters only, and ranges carry no location, so a
# successfully parsed token's IntRange is shared by every later occurrence of the same text.
_RANGE_TOKEN = re.compile(r"[0-9.\-]*")
_INT_RANGES: dict[str, IntRange] = {}
_CACHE_MAX = 4096


def int_range(r: Reader) -> IntRange:
    start = r.pos
    token = _RANGE_TOKEN.match(r.text, start).group()
    cached = _INT_RANGES.get(token)
    if cached is not None:
        r.pos = start + len(token)
        return cached
    lo, hi = _range(r, True)
    result = IntRange.new(lo, hi)
    if r.pos == start + len(token):
        if len(_INT_RANGES) >= _CACHE_MAX:
            _INT_RANGES.clear()
        _INT_RANGES[token] = result
    return result


def float_range(r: Reader) -> FloatRange:
    lo, hi = _range(r, False)
    return FloatRange.new(lo, hi)


def rotation_range(r: Reader) -> FloatRange:
    """``x_rotation``/``y_rotation`` (WrappedMinMaxBounds.fromReader): ``135..-135`` is the half
    turn through 180."""
    lo, hi = _range(r, False, wraps=True)
    return FloatRange.new(lo, hi)


# ----------------------------------------------------------------------------- UUIDs

# java.util.UUID.fromString: five hyphen-separated hex groups
UUID_TEXT = re.compile(r"[0-9a-fA-F]{1,8}-[0-9a-fA-F]{1,4}-[0-9a-fA-F]{1,4}-[0-9a-fA-F]{1,4}-[0-9a-fA-F]{1,12}")


def is_uuid(text: str) -> bool:
    return UUID_TEXT.fullmatch(text) is not None


def uuid_ints(text: str) -> tuple[int, int, int, int]:
    """The UUID ``text`` (:func:`is_uuid`) as the game saves it: UUIDUtil.uuidToIntArray, four
    signed ints, the most significant first (UUID.fromString reads each group as hex)."""
    parts = [int(part, 16) for part in text.split("-")]
    bits = (parts[0] << 96) | (parts[1] << 80) | (parts[2] << 64) | (parts[3] << 48) | parts[4]
    words = [(bits >> shift) & 0xFFFFFFFF for shift in (96, 64, 32, 0)]
    return tuple(w - (1 << 32) if w >= 1 << 31 else w for w in words)


# ----------------------------------------------------------------------------- JSON spans

_JSON_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|\'(?:[^\'\\]|\\.)*\'|[\[\]{}]|["\']')
_JSON_PRIMITIVE = re.compile(r"[^ \[\]{},]+")
_CLOSERS = {"[": "]", "{": "}"}



def json_span(r: Reader, what: str = "JSON text") -> str:
    """One JSON (or SNBT) value, checked for balanced brackets and quotes, returned as written."""
    start = r.pos
    text = r.text
    c = r.peek()
    if not c:
        r.fail(f"expected {what}, got end of command")
    if c in "[{":
        stack = []
        pos = start
        while True:
            m = _JSON_TOKEN.search(text, pos)
            if m is None:
                r.fail(f"unclosed '{stack[-1]}' in {what}", start)
            tok = m.group()
            if tok in ("[", "{"):
                stack.append(tok)
            elif tok in ("]", "}"):
                if not stack or _CLOSERS[stack.pop()] != tok:
                    r.fail(f"unbalanced '{tok}' in {what}", m.start())
                if not stack:
                    r.pos = m.end()
                    return text[start:r.pos]
            elif len(tok) == 1:
                r.fail(f"unclosed quoted string in {what}", m.start())
            pos = m.end()
    if c == '"' or c == "'":
        m = _JSON_TOKEN.match(text, start)
        if m is None or len(m.group()) == 1:
            r.fail(f"unclosed quoted string in {what}", start)
        r.pos = m.end()
        return m.group()
    m = _JSON_PRIMITIVE.match(text, start)
    if m is None:
        r.fail(f"expected {what}, got {r.found()}")
    r.pos = m.end()
    return m.group()
