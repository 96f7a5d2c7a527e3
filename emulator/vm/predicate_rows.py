"""The predicates the numba VM evaluates itself (``@e[predicate=P]``, ``execute if predicate P``),
compiled into a postfix program of selector test rows (:mod:`emulator.vm.entity_arrays`).

A predicate compiles when every condition in it reads only what the entity table and the
scoreboard keep (:func:`compile_predicate`; anything else returns None and the host evaluates it
with :mod:`emulator.world.predicates`, the one evaluator these rows follow):

- ``all_of`` / ``any_of`` (``alternative`` before 1.20) / ``inverted`` / ``reference`` (a loaded
  predicate by id; an unknown id or a loop is left to the host): AllOfCondition, AnyOfCondition
  (Util.allOf: empty true; Util.anyOf: empty false), InvertedLootItemCondition, ConditionReference;
- ``entity_properties`` of ``this`` (LootItemEntityPropertyCondition: no predicate is true, a
  missing entity fails EntityPredicate.matches) whose entity predicate has only ``type`` (an id,
  ``#tag`` or a list), ``team`` (Entity.getTeam's name: any entity, no team fails),
  ``type_specific`` player ``gamemode`` / ``level`` (PlayerPredicate) and 26.2's ``entity_tags``
  (EntityTagPredicate: all_of, any_of, none_of);
- ``entity_scores`` of ``this`` with integer bounds (EntityHasScoreCondition: an unset score fails).

Rows (width 4): every leaf of :func:`emulator.vm.loop._passes` (``TEST_TAG``, ``TEST_TYPE``,
``TEST_TYPES`` + members, ``TEST_INT``, ``TEST_RANGE``, ``TEST_SCORE``) pushes whether it passes;
``[TEST_THIS]`` pushes whether there is an entity (``execute if predicate`` run by the server has
none); ``[TEST_CONST, v]`` pushes v; ``[TEST_ALL, n]`` / ``[TEST_ANY, n]`` pop n and push their
and / or; ``[TEST_NOT]`` negates the top. The VM keeps the stack in the bits of one int64, so a
program deeper than :data:`MAX_DEPTH` stays with the host. No row draws from a random, so
evaluating every operand (no short circuit) finds what the game finds.
"""
from __future__ import annotations

from emulator.vm.loop import (
    TEST_ALL, TEST_ANY, TEST_CONST, TEST_INT, TEST_MEMBER, TEST_NOT, TEST_RANGE, TEST_SCORE, TEST_TAG, TEST_THIS,
    TEST_TYPE, TEST_TYPES,
)
from emulator.world import entity_predicate_format
from emulator.world.entity_table import EI_GAMEMODE, EI_TEAM, EI_XP, GAMEMODES
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import min_max
from emulator.world.semantics import INT_MAX, INT_MIN

MAX_DEPTH = 60  # booleans on the VM's stack (bits of an int64)


class _Host(Exception):
    """A part of the predicate the VM does not evaluate."""


def compile_predicate(value, tables, version) -> list[tuple[int, int, int, int]] | None:
    """The postfix rows of predicate ``value`` (a condition or a list of them, all must hold), or
    None for the host. ``tables``: the :class:`~emulator.vm.entity_arrays.SelectorTables` that
    interns names (tags, types, teams, objectives) and knows the resources."""
    rows: list[tuple[int, int, int, int]] = []
    try:
        _Program(tables, version, rows).condition(value, ())
    except (_Host, Unmodelled, KeyError, TypeError, ValueError, AttributeError):
        return None
    return rows if _depth(rows) <= MAX_DEPTH else None


def _depth(rows) -> int:
    """The most booleans the program holds at once."""
    depth = most = 0
    for kind, n, _, _ in rows:
        if kind in (TEST_ALL, TEST_ANY):
            depth -= n - 1
        elif kind not in (TEST_NOT, TEST_MEMBER):
            depth += 1
        most = max(most, depth)
    return most


def _kind(value: dict) -> str:
    return str(value.get("condition") or "").removeprefix("minecraft:")


def _id(text: str) -> str:
    return text if ":" in text else "minecraft:" + text


class _Program:
    def __init__(self, tables, version, rows: list) -> None:
        self.tables = tables
        self.version = version
        self.rows = rows

    def condition(self, value, visiting: tuple[str, ...]) -> None:
        if isinstance(value, list):
            self.all_of(value, visiting)
            return
        if not isinstance(value, dict):
            raise _Host
        kind = _kind(value)
        if kind == "all_of":
            self.all_of(value["terms"], visiting)
        elif kind in ("any_of", "alternative"):
            terms = value["terms"]
            for term in terms:
                self.condition(term, visiting)
            self.rows.append((TEST_ANY, len(terms), 0, 0) if terms else (TEST_CONST, 0, 0, 0))
        elif kind == "inverted":
            self.condition(value["term"], visiting)
            self.rows.append((TEST_NOT, 0, 0, 0))
        elif kind == "reference":
            self.reference(_id(value["name"]), visiting)
        elif kind == "entity_properties" and value.get("entity") == "this":
            if value.get("predicate") is None:
                self.rows.append((TEST_CONST, 1, 0, 0))
            else:
                self.entity(value["predicate"])
        elif kind == "entity_scores" and value.get("entity") == "this":
            scores = value.get("scores", {})
            self.rows.append((TEST_THIS, 0, 0, 0))
            for objective, bounds in scores.items():
                lo, hi = _int_bounds(bounds)
                self.rows.append((TEST_SCORE, self.tables.scoreboard.objective_id(objective), lo, hi))
            self.rows.append((TEST_ALL, 1 + len(scores), 0, 0))
        else:
            raise _Host

    def reference(self, predicate_id: str, visiting: tuple[str, ...]) -> None:
        """ConditionReference: an unknown id or a loop is the host's (it reports them)."""
        found = self.tables.resources.predicates.get(predicate_id)
        if found is None or predicate_id in visiting:
            raise _Host
        self.condition(found, visiting + (predicate_id,))

    def all_of(self, terms: list, visiting: tuple[str, ...]) -> None:
        for term in terms:
            self.condition(term, visiting)
        self.rows.append((TEST_ALL, len(terms), 0, 0) if terms else (TEST_CONST, 1, 0, 0))

    def entity(self, predicate) -> None:
        """EntityPredicate.matches: an entity, then each field (in the classic form of its release)."""
        fields = entity_predicate_format.classic(predicate, self.version)
        if not isinstance(fields, dict):
            raise _Host
        self.rows.append((TEST_THIS, 0, 0, 0))
        pushed = 1
        for key, wanted in fields.items():
            pushed += getattr(self, "field_" + key, self.unknown_field)(wanted)
        if pushed > 1:
            self.rows.append((TEST_ALL, pushed, 0, 0))

    def unknown_field(self, wanted) -> int:
        raise _Host

    def field_type(self, wanted) -> int:
        """A HolderSet of entity types: an id, a ``#tag`` the resources know fully, a list of ids."""
        table = self.tables.table
        if isinstance(wanted, list):
            members = sorted({_id(str(v)) for v in wanted})
        elif isinstance(wanted, str) and wanted.startswith("#"):
            tag = self.tables.resources.tag("entity_type", _id(wanted[1:]))
            if tag is None or tag.unknown:
                raise _Host
            members = sorted(tag.members)
        else:
            self.rows.append((TEST_TYPE, table.type_id(_id(str(wanted))), 0, 0))
            return 1
        self.rows.append((TEST_TYPES, len(members), 0, 0))
        self.rows.extend((TEST_MEMBER, table.type_id(m), 0, 0) for m in members)
        return 1

    def field_team(self, wanted) -> int:
        if not isinstance(wanted, str) or not wanted:
            raise _Host  # an empty name: the table keeps no team and an empty one alike (-1)
        self.rows.append((TEST_INT, EI_TEAM, self.tables.table.name_id(wanted), 0))
        return 1

    def field_entity_tags(self, wanted) -> int:
        """EntityTagPredicate: every ``all_of`` tag, some ``any_of`` tag (when given), no ``none_of`` tag."""
        if not isinstance(wanted, dict) or set(wanted) - {"all_of", "any_of", "none_of"}:
            raise _Host
        pushed = 0
        for tag in wanted.get("all_of", ()):
            self.rows.append((TEST_TAG, self.tables.tag_id(str(tag)), 0, 0))
            pushed += 1
        if "any_of" in wanted:
            tags = wanted["any_of"]
            self.rows.extend((TEST_TAG, self.tables.tag_id(str(tag)), 0, 0) for tag in tags)
            self.rows.append((TEST_ANY, len(tags), 0, 0) if tags else (TEST_CONST, 0, 0, 0))
            pushed += 1
        for tag in wanted.get("none_of", ()):
            self.rows.append((TEST_TAG, self.tables.tag_id(str(tag)), 1, 0))
            pushed += 1
        return pushed

    def field_type_specific(self, wanted) -> int:
        """PlayerPredicate's ``gamemode`` (a mode or a list) and ``level``: the entity is a player."""
        if not isinstance(wanted, dict) or _kind({"condition": wanted.get("type")}) != "player":
            raise _Host
        self.rows.append((TEST_TYPE, self.tables.table.type_id("minecraft:player"), 0, 0))
        pushed = 1
        for key, value in wanted.items():
            if key == "type":
                continue
            if key == "gamemode":
                modes = value if isinstance(value, list) else [value]
                self.rows.extend((TEST_INT, EI_GAMEMODE, GAMEMODES.index(m), 0) for m in modes)
                self.rows.append((TEST_ANY, len(modes), 0, 0) if modes else (TEST_CONST, 0, 0, 0))
            elif key == "level":
                lo, hi = _level_bounds(value)
                self.rows.append((TEST_RANGE, EI_XP, lo, hi))
            else:
                raise _Host
            pushed += 1
        return pushed


def _level_bounds(bounds) -> tuple[int, int]:
    """A player's ``level``: MinMaxBounds.Ints, its bounds read as the game's codec reads them."""
    try:
        lo, hi = min_max(bounds, ints=True)
    except Unmodelled:
        raise _Host from None
    return (INT_MIN if lo is None else lo), (INT_MAX if hi is None else hi)


def _int_bounds(bounds) -> tuple[int, int]:
    """IntRange with integer constants (an int, or ``{min, max}`` of ints); a bound past an int
    is kept past it (int64 rows), so it still passes no score or every one."""
    if isinstance(bounds, int) and not isinstance(bounds, bool):
        lo = hi = bounds
    elif isinstance(bounds, dict) and not set(bounds) - {"min", "max"}:
        lo, hi = bounds.get("min"), bounds.get("max")
        if any(b is not None and (not isinstance(b, int) or isinstance(b, bool)) for b in (lo, hi)):
            raise _Host
    else:
        raise _Host
    lo = INT_MIN if lo is None else max(INT_MIN - 1, min(INT_MAX + 1, lo))
    hi = INT_MAX if hi is None else max(INT_MIN - 1, min(INT_MAX + 1, hi))
    return lo, hi
