"""The selectors the numba VM evaluates itself, as rows of tables over the world's entity arrays.

The entities are the world's own arrays (:mod:`emulator.world.entity_table`), which the VM reads
and writes in place: nothing is copied, rebuilt or written back. This module compiles selectors
into the VM's tables, interning their tag and type names in that table and their objectives in
the scoreboard.

Selectors the VM evaluates (:meth:`SelectorTables.selector`): ``@e @a @s @p @n`` with ``type``
(``!``, and ``#`` tags the world's resources resolve fully), ``tag``
(any number, ``!``, the empty ``tag=``), ``scores``, ``name``, ``team``, ``gamemode``, ``level``,
``x_rotation``, ``y_rotation``, ``x y z``, ``dx dy dz`` volumes,
``distance``, ``limit`` and ``sort`` (``@r`` and ``sort=random`` shuffle with the world's
``java.util.Random``, :mod:`emulator.world.java_random`), ``predicate`` of the predicates
:mod:`emulator.vm.predicate_rows` compiles, each limited to the context's level
or searching every level as ``selectors.SelectorQuery`` does; and ``execute if predicate``'s
test on the executor (a loaded predicate or an inline one) (:meth:`SelectorTables.this_predicate`). A selector row and its floats are
laid out as :mod:`emulator.vm.loop` describes (``S_*``, ``SF_*``); its tests are rows of ``tests``
(``TEST_*``). Every other selector (``nbt``, ``advancements``, a predicate the VM does not
evaluate) stays with the host (returns None).
"""
from __future__ import annotations

import math

import numpy as np

from mcfunction_parser import ast
from mcfunction_parser.pack import conditions as pack_conditions
from emulator.world import mth
from emulator.vm.predicate_rows import compile_predicate
from emulator.world.resources import Resources
from emulator.world.entity_table import EF_PITCH, EF_YAW, EI_GAMEMODE, EI_NAME, EI_TEAM, EI_XP, GAMEMODES, EntityTable
from emulator.world.selectors import WORLD_LIMITING as _WORLD_LIMITING
from emulator.world.semantics import INT_MAX, INT_MIN
from emulator.vm.loop import (
    KIND_E, KIND_S, KIND_THIS, S_ALIVE, S_BOX, S_DIST, S_KIND, S_LIMIT, S_NTESTS, S_PLAYERS, S_SORT, S_TESTS, S_WORLD, SEL_WIDTH,
    SF_BOX, SF_DHI, SF_DLO, SF_ORIGIN, SF_ROT, SF_WIDTH, SORT_ARBITRARY, SORT_FURTHEST, SORT_NEAREST, SORT_RANDOM,
    TEST_INT, TEST_MEMBER, TEST_NOTAGS, TEST_PRED, TEST_RANGE, TEST_ROT, TEST_SCORE, TEST_TAG, TEST_TYPE, TEST_TYPES,
)

# (limit, players only, sort) per selector variable (selectors._VARIABLES)
_VARIABLES = {"a": (INT_MAX, True, SORT_ARBITRARY), "e": (INT_MAX, False, SORT_ARBITRARY),
              "n": (1, False, SORT_NEAREST), "p": (1, True, SORT_NEAREST), "r": (1, True, SORT_RANDOM),
              "s": (1, False, SORT_ARBITRARY)}
_SORTS = {"arbitrary": SORT_ARBITRARY, "nearest": SORT_NEAREST, "furthest": SORT_FURTHEST, "random": SORT_RANDOM}
_AXES = {"x": 0, "y": 1, "z": 2}
_DELTAS = {"dx": 0, "dy": 1, "dz": 2}
# the rotation arguments: (the entity's column, the first of their two bounds in the selector's floats)
# the arguments SelectorQuery applies after the others (a position, a box, a distance) or that
# order and cut what the tests found
_UNORDERED = frozenset({"x", "y", "z", "dx", "dy", "dz", "distance", "sort", "limit"})
_ROTATIONS = {"x_rotation": (EF_PITCH, SF_ROT), "y_rotation": (EF_YAW, SF_ROT + 2)}


class SelectorTables:
    def __init__(self, scoreboard, table: EntityTable, resources: Resources | None = None, version=None) -> None:
        self.scoreboard = scoreboard  # objectives of `scores=` are interned here
        self.table = table  # tag and type names are interned here
        self.resources = resources or Resources()  # entity type tags (the packs' and the game's), predicates
        self.version = version  # the packs' release (how their predicates read); None: predicates stay with the host
        self._programs: dict[tuple, tuple[int, int]] = {}  # predicate rows -> (first, count) in test_rows
        self.sel_rows: list[list[int]] = []
        self.float_rows: list[list[float]] = []
        self.test_rows: list[list[int]] = []
        self._selector_ids: dict[tuple, int] = {}
        self._arrays: tuple | None = None

    def tag_id(self, tag: str) -> int:
        return self.table.tag_id(tag)

    def selector(self, target) -> int | None:
        """The selector table row of ``target`` when the VM can evaluate it, else None."""
        if not isinstance(target, ast.Selector) or target.variable not in _VARIABLES:
            return None
        row = [0] * SEL_WIDTH
        row[S_LIMIT], row[S_PLAYERS], row[S_SORT] = _VARIABLES[target.variable]
        row[S_ALIVE] = int(target.variable in "en")  # EntitySelectorParser: @e and @n test isAlive
        row[S_KIND] = KIND_S if target.variable == "s" else KIND_E
        floats = [math.nan] * 3 + [0.0] * (SF_WIDTH - 3)
        deltas, distance, tests = {}, None, []
        for arg in target.args:
            if (arg.key == "type" and arg.value == "minecraft:player" and not arg.negated) or arg.key in (
                    "gamemode", "level"):
                row[S_PLAYERS] = 1  # a selector of players only searches the player list (setIncludesEntities)
            if arg.key in _ROTATIONS:
                column, first = _ROTATIONS[arg.key]
                floats[first:first + 2] = _rotation_bounds(arg.value)
                tests.append((TEST_ROT, column, first, 0))
                continue
            tested = self._test(arg, tests)
            if tested is None:
                return None
            if tested:
                continue
            key, value = arg.key, arg.value
            if key in _WORLD_LIMITING:
                row[S_WORLD] = 1
            if key in _AXES:
                floats[SF_ORIGIN + _AXES[key]] = float(value)
            elif key in _DELTAS:
                deltas[_DELTAS[key]] = float(value)
            elif key == "distance":
                distance = value
            elif key == "limit":
                row[S_LIMIT] = int(value)
            elif key == "sort" and value in _SORTS:
                row[S_SORT] = _SORTS[value]
            else:
                return None
        if row[S_KIND] == KIND_S:
            row[S_LIMIT], row[S_SORT], row[S_WORLD] = 1, SORT_ARBITRARY, 0
        self._box(row, floats, deltas, distance)
        return self._intern(row, floats, tests)

    def guard(self, target) -> int | None:
        """For a selector the host evaluates: a selector the VM evaluates that finds every entity
        the host would test an argument of its own on (None when there is none). The host's
        ``SelectorQuery`` tests each entity with the arguments in their order, then the box and the
        distance: the guard keeps the arguments before the first one the VM cannot evaluate and
        drops the positions, the sort and the limit (finding more is allowed; a shuffle is not:
        ``@r`` and ``@p`` search as ``@a``, ``@n`` as ``@e``). When it finds nobody, the host's
        selector finds nobody without testing anyone, so skipping it changes nothing."""
        if not isinstance(target, ast.Selector) or target.variable not in _VARIABLES:
            return None
        kept = []
        for arg in target.args:
            if arg.key in _UNORDERED:
                continue
            if self.selector(ast.Selector("e", (arg,), target.loc)) is None:
                variable = {"r": "a", "p": "a", "n": "e"}.get(target.variable, target.variable)
                return self.selector(ast.Selector(variable, tuple(kept), target.loc))
            kept.append(arg)
        return None  # the VM evaluates the whole selector

    def this_predicate(self, predicate: str) -> int | None:
        """The selector row (KIND_THIS) of ``execute if predicate ID|{...}`` when the VM evaluates
        the predicate (ExecuteCommand.checkCustomPredicate: the executor as ``this``), else None."""
        program = self._inline(predicate) if predicate[:1] in "{[" else self._program(predicate)
        if program is None:
            return None
        row = [0] * SEL_WIDTH
        row[S_KIND], row[S_LIMIT] = KIND_THIS, 1
        row[S_TESTS], row[S_NTESTS] = program
        return self._intern(row, [0.0] * SF_WIDTH, [])

    def _program(self, predicate_id: str) -> tuple[int, int] | None:
        """(first row, rows) of a loaded predicate's program in the test rows, or None."""
        if predicate_id not in self.resources.predicates:
            return None
        return self._rows({"condition": "reference", "name": predicate_id})

    def _inline(self, text: str) -> tuple[int, int] | None:
        """An inline predicate's program: one that reads and that the game loads (else the host fails it)."""
        try:
            value = pack_conditions.parse_inline(text)
        except ValueError:
            return None
        return None if self.version is None or pack_conditions.problem(value, self.version) else self._rows(value)

    def _rows(self, value) -> tuple[int, int] | None:
        rows = None if self.version is None else compile_predicate(value, self, self.version)
        if rows is None:
            return None
        key = tuple(rows)
        if key not in self._programs:
            self._programs[key] = (len(self.test_rows), len(rows))
            self.test_rows.extend(list(r) for r in rows)
            self._arrays = None
        return self._programs[key]

    def _intern(self, row: list[int], floats: list[float], tests: list) -> int:
        key = (tuple(row), tuple(floats), tuple(tests))
        index = self._selector_ids.get(key)
        if index is None:
            index = self._selector_ids[key] = len(self.sel_rows)
            if row[S_KIND] != KIND_THIS:
                row[S_TESTS], row[S_NTESTS] = len(self.test_rows), len(tests)
            self.sel_rows.append(row)
            self.float_rows.append(floats)
            self.test_rows.extend(list(t) for t in tests)
            self._arrays = None
        return index

    def _test(self, arg: ast.SelectorArg, tests: list) -> bool | None:
        """Append the test rows of a tag, type or scores argument: True; False for another
        argument; None for one the VM does not evaluate (``type=#tag`` of a tag it does not know)."""
        if arg.key == "tag":
            if arg.value:
                tests.append((TEST_TAG, self.tag_id(arg.value), int(arg.negated), 0))
            else:
                tests.append((TEST_NOTAGS, int(arg.negated), 0, 0))
        elif arg.key == "type" and arg.value.startswith("#"):
            tag = self.resources.tag("entity_type", arg.value[1:])
            if tag is None or tag.unknown:
                return None  # the host evaluates it (an unknown tag, or one holding unknown vanilla tags)
            members = sorted(tag.members)
            tests.append((TEST_TYPES, len(members), int(arg.negated), 0))
            tests.extend((TEST_MEMBER, self.table.type_id(m), 0, 0) for m in members)
        elif arg.key == "type":
            tests.append((TEST_TYPE, self.table.type_id(arg.value), int(arg.negated), 0))
        elif arg.key == "name":  # Entity.getName().getString()
            tests.append((TEST_INT, EI_NAME, self.table.name_id(arg.value), int(arg.negated)))
        elif arg.key == "team":  # LivingEntity only; "" is no team
            tests.append((TEST_INT, EI_TEAM, self.table.name_id(arg.value or None), int(arg.negated) | 2))
        elif arg.key == "gamemode":
            tests.append((TEST_INT, EI_GAMEMODE, GAMEMODES.index(arg.value), int(arg.negated)))
        elif arg.key == "level":
            lo = INT_MIN if arg.value.lo is None else max(INT_MIN, arg.value.lo)
            hi = INT_MAX if arg.value.hi is None else min(INT_MAX, arg.value.hi)
            tests.append((TEST_RANGE, EI_XP, lo, hi))
        elif arg.key == "predicate":  # EntitySelectorOptions: the entity as `this` at its position
            program = self._program(arg.value)
            if program is None:
                return None
            tests.append((TEST_PRED, *program, int(arg.negated)))
        elif arg.key == "scores":
            for objective, bounds in arg.value:
                lo = INT_MIN if bounds.lo is None else max(INT_MIN, bounds.lo)
                hi = INT_MAX if bounds.hi is None else min(INT_MAX, bounds.hi)
                tests.append((TEST_SCORE, self.scoreboard.objective_id(objective), lo, hi))
        else:
            return False
        return True

    @staticmethod
    def _box(row: list[int], floats: list[float], deltas: dict[int, float], distance) -> None:
        """The box and distance tests as ``SelectorQuery.run`` builds them: a ``dx/dy/dz`` box from
        the origin corner, else ``distance=..R``'s box ``[-R, R + 1]``; squared distance bounds."""
        if deltas:
            d = [deltas.get(i, 0.0) for i in range(3)]
            lows = [v if v < 0 else 0.0 for v in d]
            highs = [(0.0 if v < 0 else v) + 1.0 for v in d]
            row[S_BOX] = 1
            floats[SF_BOX:SF_BOX + 6] = lows + highs
        elif distance is not None and distance.hi is not None:
            r = distance.hi
            row[S_BOX] = 1
            floats[SF_BOX:SF_BOX + 6] = [-r, -r, -r, r + 1.0, r + 1.0, r + 1.0]
        if distance is not None:
            row[S_DIST] = 1
            floats[SF_DLO] = -math.inf if distance.lo is None else distance.lo * distance.lo
            floats[SF_DHI] = math.inf if distance.hi is None else distance.hi * distance.hi

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(selectors int64[n, SEL_WIDTH], their floats float64[n, SF_WIDTH], tests int64[m, 4])`` for the VM."""
        if self._arrays is None:
            sels = np.array(self.sel_rows or [[0] * SEL_WIDTH], dtype=np.int64).reshape(-1, SEL_WIDTH)
            floats = np.array(self.float_rows or [[0.0] * SF_WIDTH], dtype=np.float64).reshape(-1, SF_WIDTH)
            tests = np.array(self.test_rows or [[0] * 4], dtype=np.int64).reshape(-1, 4)
            self._arrays = (sels, floats, tests)
        return self._arrays


def _rotation_bounds(bounds: ast.FloatRange) -> list[float]:
    """EntitySelectorParser.createRotationPredicate's bounds: wrapped floats, a missing low 0 and
    a missing high 359 (the test wraps the entity's angle as a double and compares)."""
    return [float(mth.wrap_degrees_f(0.0 if bounds.lo is None else bounds.lo)),
            float(mth.wrap_degrees_f(359.0 if bounds.hi is None else bounds.hi))]


def shuffles(target) -> bool:
    """``@r`` or ``sort=random``: evaluating the selector draws from the world's random."""
    return isinstance(target, ast.Selector) and (target.variable == "r" or any(
        arg.key == "sort" and arg.value == "random" for arg in target.args))
