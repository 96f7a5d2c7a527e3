"""Target selectors (``@e[type=zombie,limit=1]``) and entity arguments (selector, name or UUID).

Option rules follow the game's EntitySelectorOptions: which options accept ``!``, which may
repeat, and which are not applicable to a selector (``limit``/``sort`` on ``@s``, ``type`` on
players-only selectors).
"""
from __future__ import annotations

import re

from .ast import FloatRange, NameTarget, Selector, SelectorArg
from .features import FEATURES
from .game_objects import registry_id
from .primitives import float_range, int_range, is_uuid, json_span, resource_location, rotation_range
from .reader import Reader, show
from .snbt import compound

VARIABLES = frozenset("spaern")
_ALWAYS_VALID = frozenset("spaer")  # @n depends on the version
AT_N = FEATURES["selector @n"][0]
_SORTS = frozenset(("nearest", "furthest", "random", "arbitrary"))
_GAMEMODES = frozenset(("survival", "creative", "adventure", "spectator"))
_NEGATABLE = frozenset(("name", "gamemode", "team", "type", "tag", "nbt", "predicate"))
_REPEATABLE = frozenset(("tag", "nbt", "predicate"))
# Options that may repeat only when negated: a non-negated one must be the only one.
_EXCLUSIVE_EQUALS = frozenset(("name", "gamemode", "team"))
_DOUBLES = frozenset(("x", "y", "z", "dx", "dy", "dz"))
_PLAYER_TYPES = frozenset(("minecraft:player",))
NAME_MAX = 16


# A selector without nested brackets or quotes: its parse depends only on its text and the release
# (ids are checked against the release's registries), so it is cached per release (without
# locations) and rebuilt on a hit; real packs repeat the same few selectors. One that warned is not
# cached: a hit would lose the warning.
_PLAIN_SELECTOR = re.compile(r"@[a-z]\[[^\[\]\"']*\]")
_CACHE: dict[tuple[str, tuple], tuple] = {}
_CACHE_MAX = 4096
_OPTION_KEY = re.compile(r"([a-z_]+)[ \t\r\n]*=[ \t\r\n]*")
_AFTER_VALUE = re.compile(r"[ \t\r\n]*(,[ \t\r\n]*)?")


def selector(r: Reader) -> Selector:
    start = r.pos
    text = r.text
    variable = text[start + 1:start + 2]
    if not text.startswith("[", start + 2):
        r.pos = start + 2
        return bare_selector(r, variable, start)
    if variable not in _ALWAYS_VALID:
        _check_variable(r, variable, start)
    loc = r.loc_at(start)
    plain = _PLAIN_SELECTOR.match(text, start)
    if plain is not None:
        cached = _CACHE.get((plain.group(), r.version))
        if cached is not None:
            r.pos = plain.end()
            loc_at = r.loc_at
            args = []
            for key, value, negated, offset in cached:  # a loop: a comprehension costs a call in 3.11
                args.append(SelectorArg.new(key, value, negated, loc_at(start + offset)))
            return Selector.new(variable, tuple(args), loc)
    r.pos = start + 2
    warned = len(r.warnings)
    args, offsets = _options(r, variable)
    if (plain is not None and r.pos == plain.end() and len(r.warnings) == warned
            and not any(a.key == "nbt" for a in args)):
        if len(_CACHE) >= _CACHE_MAX:
            _CACHE.clear()
        _CACHE[plain.group(), r.version] = tuple((a.key, a.value, a.negated, o - start) for a, o in zip(args, offsets))
    return Selector.new(variable, args, loc)


def bare_selector(r: Reader, variable: str, start: int) -> Selector:
    """``@s``, ``@e`` ... without options, written at offset ``start``."""
    if variable not in _ALWAYS_VALID:
        _check_variable(r, variable, start)
    return Selector.new(variable, (), r.loc_at(start))


def _check_variable(r: Reader, variable: str, start: int) -> None:
    if variable not in VARIABLES or not variable:
        r.fail(f"unknown selector type {show(r.text[start:start + 2])} (expected @s @e @a @p @r @n)", start)
    if variable == "n" and r.version < AT_N:
        r.require("selector @n", start)


def _options(r: Reader, variable: str) -> tuple[tuple[SelectorArg, ...], list[int]]:
    """The ``[...]`` options, and the offset of each option's key."""
    r.pos += 1  # '['
    args: list[SelectorArg] = []
    offsets: list[int] = []
    text = r.text
    r.skip_ws()
    while r.pos < r.end and text[r.pos] != "]":
        key_pos = r.pos
        m = _OPTION_KEY.match(text, key_pos)
        if m is not None:
            key = m.group(1)
            r.pos = m.end()
        else:
            key = r.string()
        if not key:
            r.fail(f"expected a selector option, got {show(r.rest_word()[:1])}", key_pos)
        if key not in _PARSERS:
            r.fail(f"unknown selector option {show(key)}", key_pos)
        if m is None:
            r.skip_ws()
            r.expect("=")
            r.skip_ws()
        negated = False
        if key in _NEGATABLE and text.startswith("!", r.pos):
            negated = True
            r.pos += 1
            r.skip_ws()
        _check_applicable(r, variable, key, negated, args, key_pos)
        args.append(SelectorArg.new(key, _PARSERS[key](r), negated, r.loc_at(key_pos)))
        offsets.append(key_pos)
        after = _AFTER_VALUE.match(text, r.pos)
        r.pos = after.end()
        if after.group(1) is None and r.pos < r.end and text[r.pos] != "]":
            r.fail(f"expected ',' or ']' after selector option, got {r.found()}")
    if r.pos >= r.end:
        r.fail("unclosed selector: expected ']'")
    r.pos += 1
    return tuple(args), offsets


def _check_applicable(r: Reader, variable: str, key: str, negated: bool, args: list[SelectorArg], pos: int):
    """EntitySelectorOptions' ``canUse`` predicates and the checks inside name/gamemode/type."""
    not_here = f"option '{key}' isn't applicable here"
    if key in _REPEATABLE:
        return
    if key in ("limit", "sort") and variable == "s":
        r.fail(f"{not_here}: @s selects only the executor", pos)
    before = [a for a in args if a.key == key]
    if key == "type":
        if variable in "apr":
            r.fail(f"{not_here}: @{variable} selects only players", pos)
        if any(not a.negated and not a.value.startswith("#") for a in before):
            r.fail(f"{not_here}: the entity type is already given", pos)
        if not negated and any(a.negated for a in before):
            r.fail(f"{not_here}: 'type=' can't follow 'type=!'", pos)
        return
    if not before:
        return
    if key in _EXCLUSIVE_EQUALS:
        if any(not a.negated for a in before):
            r.fail(f"{not_here}: '{key}=' is already given", pos)
        if not negated and key != "team":
            r.fail(f"{not_here}: '{key}=' can't follow '{key}=!'", pos)
        return
    r.fail(f"{not_here}: '{key}' may be given only once", pos)


def _distance(r: Reader) -> FloatRange:
    start = r.pos
    rng = float_range(r)
    if rng.lo is not None and rng.lo < 0 or rng.hi is not None and rng.hi < 0:
        r.fail("distance cannot be negative", start)
    return rng


def _level(r: Reader):
    start = r.pos
    rng = int_range(r)
    if rng.lo is not None and rng.lo < 0 or rng.hi is not None and rng.hi < 0:
        r.fail("level cannot be negative", start)
    return rng


def _limit(r: Reader) -> int:
    return r.integer(lo=1, what="limit")


def _sort(r: Reader) -> str:
    start = r.pos
    word = r.unquoted()
    if word not in _SORTS:
        r.fail(f"invalid or unknown sort type {show(word)} (expected nearest|furthest|random|arbitrary)", start)
    return word


def _gamemode(r: Reader) -> str:
    start = r.pos
    word = r.unquoted()
    if word not in _GAMEMODES:
        r.fail(f"invalid or unknown game mode {show(word)} (expected survival|creative|adventure|spectator)", start)
    return word


def _type(r: Reader) -> str:
    if r.peek() == "#":
        r.pos += 1
        return "#" + resource_location(r, "entity type tag")
    return registry_id(r, "entity_type")  # EntitySelectorOptions: ERROR_ENTITY_TYPE_INVALID


def _scores(r: Reader):
    r.expect("{")
    r.skip_ws()
    scores = []
    while r.more() and r.peek() != "}":
        start = r.pos
        name = r.unquoted()
        if not name:
            r.fail(f"expected an objective name, got {r.found()}", start)
        r.skip_ws()
        r.expect("=")
        r.skip_ws()
        scores.append((name, int_range(r)))
        r.skip_ws()
        if r.peek() == ",":
            r.pos += 1
            r.skip_ws()
    r.expect("}")
    return tuple(scores)


def _advancements(r: Reader) -> str:
    if r.peek() != "{":
        r.fail(f"expected '{{' for advancements, got {r.found()}")
    return json_span(r, "advancements")


def _double(r: Reader) -> float:
    return r.double()


_PARSERS = {
    "name": Reader.string,
    "distance": _distance,
    "level": _level,
    "x_rotation": rotation_range,
    "y_rotation": rotation_range,
    "limit": _limit,
    "sort": _sort,
    "gamemode": _gamemode,
    "team": Reader.unquoted,
    "type": _type,
    "tag": Reader.unquoted,
    "nbt": compound,
    "scores": _scores,
    "advancements": _advancements,
    "predicate": lambda r: resource_location(r, "predicate"),
}
for _key in _DOUBLES:
    _PARSERS[_key] = _double


# ----------------------------------------------------------------------------- entity arguments


def is_single(target) -> bool:
    if isinstance(target, NameTarget):
        return True
    if target.variable in "sprn":
        return True
    return any(a.key == "limit" and a.value == 1 for a in target.args)


def is_players_only(target) -> bool:
    if isinstance(target, NameTarget):
        return not target.is_uuid
    if target.variable in "aprs":
        return True
    return any(not a.negated and (a.key == "type" and a.value in _PLAYER_TYPES or a.key in ("level", "gamemode"))
               for a in target.args)


def target(r: Reader, single: bool = False, players: bool = False):
    """An entity argument: a selector, a player name (max 16 characters) or a UUID."""
    start = r.pos
    if r.peek() == "@":
        result = selector(r)
    else:
        loc = r.loc()
        name = r.string()
        uuid = is_uuid(name)
        if not uuid and (not name or len(name) > NAME_MAX):
            if name:
                r.fail(f"player name '{name}' is longer than {NAME_MAX} characters", start)
            r.pos = start
            r.fail(f"expected a selector, player name or UUID, got {r.found()}", start)
        result = NameTarget.new(name, loc, is_uuid=uuid)
    if single and not is_single(result):
        r.fail("only one entity is allowed, but the selector allows more than one (add limit=1)", start)
    if players and not is_players_only(result):
        r.fail("only players may be targeted here, but the selector includes entities (add type=player)", start)
    return result
