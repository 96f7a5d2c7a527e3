"""The selectors the numba VM evaluates itself, as rows of tables over the world's entity arrays.

The entities are the world's own arrays (:mod:`emulator.world.entity_table`), which the VM reads
and writes in place: nothing is copied, rebuilt or written back. This module compiles selectors
into the VM's tables, interning their tag and type names in that table and their objectives in
the scoreboard.

Selectors the VM evaluates (:meth:`SelectorTables.selector`): ``@e``, ``@a``, ``@s`` with ``type``
(``!`` too, no ``#`` tags), ``tag`` (any number, ``!``, the empty ``tag=``), ``scores``, and for
``@e``/``@a`` ``limit`` with ``sort=arbitrary``. A selector row is ``[kind, limit, first test,
test count]``; its tests are rows of ``tests`` (``TEST_*`` in :mod:`emulator.vm.loop`). Every other
selector stays with the host (returns None).
"""
from __future__ import annotations

import numpy as np

from mcfunction_parser import ast
from emulator.world.entity_table import EntityTable
from emulator.world.semantics import INT_MAX, INT_MIN
from emulator.vm.loop import KIND_A, KIND_E, KIND_S, SEL_WIDTH, TEST_NOTAGS, TEST_SCORE, TEST_TAG, TEST_TYPE

_KINDS = {"e": KIND_E, "a": KIND_A, "s": KIND_S}


class SelectorTables:
    def __init__(self, scoreboard, table: EntityTable) -> None:
        self.scoreboard = scoreboard  # objectives of `scores=` are interned here
        self.table = table  # tag and type names are interned here
        self.sel_rows: list[list[int]] = []
        self.test_rows: list[list[int]] = []
        self._selector_ids: dict[tuple, int] = {}
        self._arrays: tuple | None = None

    def tag_id(self, tag: str) -> int:
        return self.table.tag_id(tag)

    def selector(self, target) -> int | None:
        """The selector table row of ``target`` when the VM can evaluate it, else None."""
        if not isinstance(target, ast.Selector) or target.variable not in _KINDS:
            return None
        kind = _KINDS[target.variable]
        tests, limit = [], INT_MAX
        for arg in target.args:
            if arg.key == "tag":
                if arg.value:
                    tests.append((TEST_TAG, self.tag_id(arg.value), int(arg.negated), 0))
                else:
                    tests.append((TEST_NOTAGS, int(arg.negated), 0, 0))
            elif arg.key == "type" and not arg.value.startswith("#"):
                tests.append((TEST_TYPE, self.table.type_id(arg.value), int(arg.negated), 0))
            elif arg.key == "scores":
                for objective, bounds in arg.value:
                    lo = INT_MIN if bounds.lo is None else max(INT_MIN, bounds.lo)
                    hi = INT_MAX if bounds.hi is None else min(INT_MAX, bounds.hi)
                    tests.append((TEST_SCORE, self.scoreboard.objective_id(objective), lo, hi))
            elif arg.key == "limit" and kind != KIND_S:
                limit = int(arg.value)
            elif not (arg.key == "sort" and arg.value == "arbitrary"):
                return None
        key = (kind, limit, tuple(tests))
        index = self._selector_ids.get(key)
        if index is None:
            index = self._selector_ids[key] = len(self.sel_rows)
            self.sel_rows.append([kind, limit, len(self.test_rows), len(tests)])
            self.test_rows.extend(list(t) for t in tests)
            self._arrays = None
        return index

    def arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """``(selectors int64[n, SEL_WIDTH], tests int64[m, 4])`` for the VM."""
        if self._arrays is None:
            sels = np.array(self.sel_rows or [[0] * SEL_WIDTH], dtype=np.int64).reshape(-1, SEL_WIDTH)
            tests = np.array(self.test_rows or [[0] * 4], dtype=np.int64).reshape(-1, 4)
            self._arrays = (sels, tests)
        return self._arrays
