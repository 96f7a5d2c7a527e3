"""What a command needs from the backend that runs it: :class:`Env`.

Every command of :mod:`emulator.commands` takes an ``env`` first and reaches nothing else of its
backend:

- ``env.state``: the :class:`~emulator.world.state.WorldState` it reads and changes;
- ``env.functions`` / ``env.tags``: the pack's function ids and function tag ids (``schedule``
  and ``function`` name them);
- ``env.arith(op, a, b, exact)``: the int32 a score arithmetic stores (Java's wrapping), with a
  result that wrapped reported to the overflow sanitizer (:meth:`Env.overflow`);
- ``env.warn(node, message)``: a warning, once per command or stage in the source
  (:meth:`Env.warning`); ``env.unmodelled(node, message)``: the same for something the emulator
  does not model whose effect a pack could observe (a test meeting one is inconclusive).

A backend subclasses :class:`Env` to say where overflows and warnings go (the numba VM's host
side at its current instruction, the reference interpreter at its current source). The base
class drops both, for callers outside a run (``dpemu test`` evaluating an execute prefix).
"""
from __future__ import annotations

from collections.abc import Container, Mapping

from emulator.world.semantics import wrap32, wraps32
from emulator.world.state import WorldState


class Env:
    def __init__(self, state: WorldState, functions: Mapping, tags: Container[str]) -> None:
        self.state = state
        self.functions = functions
        self.tags = tags
        self._warned: set[tuple[str, int, int]] = set()

    def arith(self, op: str, a: int, b: int, exact: int) -> int:
        """The stored (wrapped) result of ``a op b`` whose exact value is ``exact``."""
        if wraps32(exact):
            self.overflow(op, a, b, exact)
        return wrap32(exact)

    def warn(self, node, message: str, unmodelled: bool = False) -> None:
        key = (node.loc.path, node.loc.line, node.loc.col)
        if key not in self._warned:
            self._warned.add(key)
            self.warning(node, message, unmodelled)

    def unmodelled(self, node, message: str) -> None:
        """Something the emulator does not model met at ``node`` (its result may be wrong)."""
        self.warn(node, message, unmodelled=True)

    def overflow(self, op: str, a: int, b: int, exact: int) -> None:
        """An arithmetic result that wrapped (the sanitizer's report; nothing by default)."""

    def frames(self, node) -> tuple:
        """The call stack running ``node`` now, the root first (:class:`~emulator.world.records.Frame`
        each; none by default)."""
        return ()

    def warning(self, node, message: str, unmodelled: bool = False) -> None:
        """A warning's first occurrence (nothing by default)."""
