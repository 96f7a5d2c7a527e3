"""Argument types shared by commands: coordinates, ranges, resource locations, score holders,
objectives, durations and JSON text spans."""
from __future__ import annotations

import json
import re

from . import snbt
from .ast import Coord, FloatRange, IntRange, NameTarget, Selector, Vec2, Vec3, Wildcard
from .diagnostics import Loc
from .reader import FLOAT_TEXT, INT_MAX, INT_MIN, INT_TEXT, UNQUOTED, WORD, ParseError, Reader, brief, integer_value

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
    if not path:
        r.fail(f"invalid {what} '{token}': empty path", start + colon + 1)
    return token if namespace else "minecraft:" + path


def resource_or_tag(r: Reader, what: str) -> tuple[str, bool]:
    """``#ns:tag`` or ``ns:id``: (normalised id, is_tag)."""
    if r.peek() == "#":
        r.pos += 1
        return resource_location(r, what + " tag"), True
    return resource_location(r, what), False


# ----------------------------------------------------------------------------- coordinates

_COORD = re.compile(r"([~^]?)([0-9.\-]*)")
_VEC3 = re.compile(r"([~^]?)([0-9.\-]*) ([~^]?)([0-9.\-]*) ([~^]?)([0-9.\-]*)")
_KINDS = {"": "abs", "~": "rel", "^": "local"}


def _make_coord(prefix: str, number: str, block: bool) -> Coord | None:
    """The coordinate ``prefix`` + ``number`` (``~``, ``^-1``, ``3``...), None if malformed."""
    if number:
        if not (INT_TEXT if block and not prefix else FLOAT_TEXT).match(number):
            return None
        return Coord(_KINDS[prefix], float(number), not prefix and "." not in number)
    return Coord(_KINDS[prefix], 0.0) if prefix else None


def _coord(r: Reader, block: bool, allow_local: bool) -> Coord:
    start = r.pos
    m = _COORD.match(r.text, start)
    prefix, number = m.group(1), m.group(2)
    if not prefix and not number:
        r.fail(f"expected a coordinate, got {r.found()}")
    if prefix == "^" and not allow_local:
        r.fail("local coordinates (^) are not allowed here", start)
    coord = _make_coord(prefix, number, block)
    if coord is None:
        r.fail(f"invalid {'integer ' if block and not prefix else ''}coordinate '{number}'", start + len(prefix))
    r.pos = m.end()
    return coord


# Well-formed positions by (text, block): their coordinates carry no location, so they are shared.
_VEC3_CACHE: dict[tuple[str, bool], tuple[Coord, Coord, Coord]] = {}
_CACHE_MAX = 4096


def vec3(r: Reader, block: bool = False) -> Vec3:
    """A position; ``block`` for block positions (absolute coordinates must be integers).

    One regex reads the usual well-formed position; anything else goes coordinate by coordinate,
    which finds and reports the error.
    """
    loc = r.loc()
    m = _VEC3.match(r.text, r.pos)
    if m is not None:
        key = (m.group(), block)
        coords = _VEC3_CACHE.get(key)
        if coords is None:
            coords = _fast_coords(m.groups(), block)
            if coords is not None:
                if len(_VEC3_CACHE) >= _CACHE_MAX:
                    _VEC3_CACHE.clear()
                _VEC3_CACHE[key] = coords
        if coords is not None:
            r.pos = m.end()
            return Vec3(*coords, loc)
    start = r.pos
    x = _coord(r, block, True)
    r.space("y coordinate")
    y = _coord(r, block, True)
    r.space("z coordinate")
    z = _coord(r, block, True)
    local = (x.kind == "local") + (y.kind == "local") + (z.kind == "local")
    if local not in (0, 3):
        r.fail("cannot mix world and local coordinates (use ^ for all three or for none)", start)
    return Vec3(x, y, z, loc)


def _fast_coords(g: tuple, block: bool) -> tuple[Coord, Coord, Coord] | None:
    """The coordinates of a _VEC3 match, None when the slow path must find the error."""
    if (g[0] == "^") + (g[2] == "^") + (g[4] == "^") not in (0, 3):
        return None
    x, y, z = _make_coord(g[0], g[1], block), _make_coord(g[2], g[3], block), _make_coord(g[4], g[5], block)
    if x is None or y is None or z is None:
        return None
    return x, y, z


def vec2(r: Reader, integers: bool = False) -> Vec2:
    """A rotation (yaw pitch) or, with ``integers``, a column position (x z)."""
    loc = r.loc()
    x = _coord(r, integers, False)
    r.space("second coordinate")
    y = _coord(r, integers, False)
    return Vec2(x, y, loc)


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


def int_range(r: Reader) -> IntRange:
    start = r.pos
    token = _RANGE_TOKEN.match(r.text, start).group()
    cached = _INT_RANGES.get(token)
    if cached is not None:
        r.pos = start + len(token)
        return cached
    lo, hi = _range(r, True)
    result = IntRange(lo, hi)
    if r.pos == start + len(token):
        if len(_INT_RANGES) >= _CACHE_MAX:
            _INT_RANGES.clear()
        _INT_RANGES[token] = result
    return result


def float_range(r: Reader) -> FloatRange:
    lo, hi = _range(r, False)
    return FloatRange(lo, hi)


def rotation_range(r: Reader) -> FloatRange:
    """``x_rotation``/``y_rotation`` (WrappedMinMaxBounds.fromReader): ``135..-135`` is the half
    turn through 180."""
    lo, hi = _range(r, False, wraps=True)
    return FloatRange(lo, hi)


# ----------------------------------------------------------------------------- names

_OBJECTIVE_OLD_MAX = 16  # objective names were capped at 16 characters before 1.18 (21w37a)
_LONG_OBJECTIVES = (1, 18, 0)


def objective_too_long(name: str, version: tuple[int, int, int]) -> bool:
    return len(name) > _OBJECTIVE_OLD_MAX and version < _LONG_OBJECTIVES


def objective(r: Reader) -> str:
    """An objective name: Brigadier's unquoted string characters."""
    start = r.pos
    m = UNQUOTED.match(r.text, start)
    name = m.group()
    if not name:
        r.fail(f"expected an objective name, got {r.found()}", start)
    if objective_too_long(name, r.version):
        r.fail(f"objective name '{name}' is longer than {_OBJECTIVE_OLD_MAX} characters "
               f"(allowed from Minecraft {_LONG_OBJECTIVES[0]}.{_LONG_OBJECTIVES[1]})", start)
    r.pos = m.end()
    return name


def score_holder(r: Reader):
    """A selector, ``*``, or any non-space word (player names, ``#fake``, ``$y``, UUIDs).

    ScoreHolderArgument accepts ``*`` even where one holder is expected; that fails at run time.
    """
    if r.text.startswith("@", r.pos):
        return selectors.selector(r)
    start = r.pos
    word = WORD.match(r.text, start).group()
    if not word:
        r.fail(f"expected a score holder, got {r.found()}")
    r.pos = start + len(word)
    return holder_from_word(word, r.loc_at(start))


def single_score_holder(r: Reader):
    """ScoreHolderArgument.scoreHolder(): a selector must select at most one entity ('*' still parses)."""
    start = r.pos
    holder = score_holder(r)
    if type(holder) is Selector and not selectors.is_single(holder):
        r.fail("only one score holder is allowed, but the selector allows more than one", start)
    return holder


# A score holder that is one plain word or an option-less selector, for one-regex fast paths.
PLAIN_HOLDER = r"(@[a-z]|[^ @]+)"
PLAIN_OBJECTIVE = r"([0-9A-Za-z_\-.+]+)"


def plain_holder(r: Reader, word: str, start: int):
    """The holder matched by PLAIN_HOLDER at offset ``start``."""
    if word[0] == "@":
        return selectors.bare_selector(r, word[1], start)
    return holder_from_word(word, r.loc_at(start))


def holder_from_word(word: str, loc: Loc):
    """A score holder written as a word: ``*`` or a name (UUIDs recognised)."""
    if word == "*":
        return Wildcard(loc)
    return NameTarget(word, loc, "-" in word and _UUID.match(word) is not None)


# java.util.UUID.fromString: five hyphen-separated hex groups
_UUID = re.compile(r"[0-9a-fA-F]{1,8}-[0-9a-fA-F]{1,4}-[0-9a-fA-F]{1,4}-[0-9a-fA-F]{1,4}-[0-9a-fA-F]{1,12}\Z")


def is_uuid(text: str) -> bool:
    return _UUID.match(text) is not None


# ----------------------------------------------------------------------------- durations

_TIME = re.compile(r"([0-9.\-]*)([tsd]?)")
_TIME_UNITS = {"": 1, "t": 1, "s": 20, "d": 24000}


def duration(r: Reader) -> int:
    """A time argument (``10``, ``10t``, ``2.5s``, ``1d``) converted to ticks (rounded as the game
    does); TimeArgument rejects a negative tick count."""
    start = r.pos
    m = _TIME.match(r.text, start)
    number, unit = m.group(1), m.group(2)
    if not number:
        r.fail(f"expected a time, got {r.found()}")
    if not FLOAT_TEXT.match(number):
        r.fail(f"invalid time '{number}'", start)
    ticks = round(float(number) * _TIME_UNITS[unit])  # TimeArgument uses Math.round
    if ticks < 0:
        r.fail(f"time must be at least 0 ticks, got {m.group()}", start)
    r.pos = m.end()
    return ticks


# ----------------------------------------------------------------------------- JSON text

_JSON_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|\'(?:[^\'\\]|\\.)*\'|[\[\]{}]|["\']')
_JSON_PRIMITIVE = re.compile(r"[^ \[\]{},]+")
_CLOSERS = {"[": "]", "{": "}"}


SNBT_TEXT_COMPONENTS = (1, 21, 5)  # 25w02a: text components in commands are SNBT, not JSON


def text_component(r: Reader) -> str:
    """A text component, as written: strict JSON before 1.21.5 (the game's JsonReader is not
    lenient), SNBT from 1.21.5."""
    start = r.pos
    span = json_span(r, "text component")
    if r.version >= SNBT_TEXT_COMPONENTS:
        inner = Reader(span, r.loc_at(start), r.version)
        try:
            snbt.value(inner)
        except ParseError as error:
            r.fail(f"invalid SNBT text component: {error.message}", start + error.pos)
        if inner.pos != len(span):
            r.fail("invalid SNBT text component: unexpected text after the value", start + inner.pos)
        return span
    try:
        json.loads(span)
    except ValueError as error:
        pos = getattr(error, "pos", 0)
        r.fail(f"invalid JSON text: {getattr(error, 'msg', str(error))}", start + pos)
    return span


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


from . import selectors  # noqa: E402  (selectors imports this module's helpers)
