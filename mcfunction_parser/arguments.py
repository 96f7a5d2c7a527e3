"""Argument types shared by commands: coordinates, score holders, objectives, durations and text
components (the values they build on, such as ranges and resource locations, are in
:mod:`.primitives`)."""
from __future__ import annotations

import json
import math
import re

from . import selectors, snbt
from .ast import Coord, NameTarget, Selector, Vec2, Vec3, Wildcard
from .diagnostics import Loc
from .primitives import is_uuid, json_span
from .reader import FLOAT_TEXT, INT_TEXT, UNQUOTED, WORD, ParseError, Reader

# ----------------------------------------------------------------------------- coordinates

_COORD = re.compile(r"([~^]?)([0-9.\-]*)")
_VEC3 = re.compile(r"([~^]?)([0-9.\-]*) ([~^]?)([0-9.\-]*) ([~^]?)([0-9.\-]*)")
_KINDS = {"": "abs", "~": "rel", "^": "local"}


def _make_coord(prefix: str, number: str, block: bool) -> Coord | None:
    """The coordinate ``prefix`` + ``number`` (``~``, ``^-1``, ``3``...), None if malformed."""
    if number:
        if not (INT_TEXT if block and not prefix else FLOAT_TEXT).match(number):
            return None
        return Coord.new(_KINDS[prefix], float(number), not prefix and "." not in number)
    return Coord.new(_KINDS[prefix], 0.0) if prefix else None


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
            return Vec3.new(*coords, loc)
    start = r.pos
    x = _coord(r, block, True)
    r.space("y coordinate")
    y = _coord(r, block, True)
    r.space("z coordinate")
    z = _coord(r, block, True)
    local = (x.kind == "local") + (y.kind == "local") + (z.kind == "local")
    if local not in (0, 3):
        r.fail("cannot mix world and local coordinates (use ^ for all three or for none)", start)
    return Vec3.new(x, y, z, loc)


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
    return Vec2.new(x, y, loc)


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


def plain_holder(r: Reader, m, group: int):
    """The holder a PLAIN_HOLDER group of the match ``m`` matched."""
    word = m.group(group)
    start = m.start(group)
    if word[0] == "@":
        return selectors.bare_selector(r, word[1], start)
    return holder_from_word(word, r.loc_at(start))


def holder_from_word(word: str, loc: Loc):
    """A score holder written as a word: ``*`` or a name (UUIDs recognised)."""
    if word == "*":
        return Wildcard.new(loc)
    return NameTarget.new(word, loc, "-" in word and is_uuid(word))


# ----------------------------------------------------------------------------- durations

# TimeArgument.parse: StringReader.readFloat, then readUnquotedString for the unit
_TIME = re.compile(r"([0-9.\-]*)([0-9A-Za-z_.+\-]*)")
_TIME_UNITS = {"": 1, "t": 1, "s": 20, "d": 24000}


def _java_round(value: float) -> int:
    """Math.round(float): half up (0.5 -> 1, -0.5 -> 0), saturating at the int bounds."""
    if value != value:
        return 0
    if abs(value) == float("inf"):
        return 2**31 - 1 if value > 0 else -2**31
    return max(-2**31, min(2**31 - 1, math.floor(value + 0.5)))


def duration(r: Reader, minimum: int = 0) -> int:
    """A time argument (``10``, ``10t``, ``2.5s``, ``1d``) converted to ticks (rounded as the game
    does: TimeArgument.parse multiplies the float by the unit in float and takes Math.round);
    TimeArgument rejects a tick count below its minimum (0 unless the command says otherwise)."""
    start = r.pos
    m = _TIME.match(r.text, start)
    number, unit = m.group(1), m.group(2)
    if not number:
        r.fail(f"expected a time, got {r.found()}")
    if not FLOAT_TEXT.match(number):
        r.fail(f"invalid time '{number}'", start)
    if unit not in _TIME_UNITS:  # ERROR_INVALID_UNIT
        r.fail(f"invalid unit '{unit}' (expected t, s or d)", start + len(number))
    ticks = _java_round(snbt.to_float32(snbt.to_float32(float(number)) * _TIME_UNITS[unit]))
    if ticks < minimum:
        r.fail(f"time must be at least {minimum} ticks, got {m.group()}", start)
    r.pos = m.end()
    return ticks


# ----------------------------------------------------------------------------- JSON text

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
