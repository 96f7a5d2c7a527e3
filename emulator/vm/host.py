"""The bridge from the VM's host ops to :mod:`emulator.commands` (the commands the VM does not run
itself, in Python, the same code the reference backend runs).

The VM stops at a host op and the numba backend calls one of (the VM has charged the costs):

- :meth:`Host.run_final`: a final command (``say``, ``schedule``, a score command on ``*`` or a
  selector, a condition ending a chain ...) run once for the current context;
- :meth:`Host.run_stage`: an execute stage the VM does not evaluate (``as``, ``positioned``,
  ``if entity`` ...), giving the contexts the rest of the chain runs in;
- :meth:`Host.run_store_stage`: a ``store`` stage whose target the VM cannot name (a selector's
  score holders, an entity, a block, a bossbar): the target, resolved now, as ExecuteCommand does;
- :meth:`Host.run_store`: a ``store`` into storage, or into the target its stage resolved.

A :class:`~emulator.world.errors.CommandFailure` fails the command (or the stage) and the run
goes on; a reported one is a diagnostic at the current instruction.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from emulator.commands import stages, stores
from emulator.commands.dispatch import run_command
from emulator.commands.env import Env
from emulator.world.errors import CommandFailure
from emulator.world.semantics import wrap32
from emulator.world.context import Context
from emulator.world.state import WorldState
from mcfunction_parser import ast


@dataclass(frozen=True)
class StoreTarget:
    """What a store stage resolved (:func:`emulator.commands.stores.store_target`)."""
    value: object


def resolves_target(st: ast.Subcommand) -> bool:
    """A store stage the host resolves: not a score store on a name (the VM's own), nor one into
    storage (whose target is the same in every context and cannot fail: it is resolved when the
    result is stored)."""
    if isinstance(st, ast.StoreScore):
        return not isinstance(st.targets, ast.NameTarget)
    return isinstance(st, ast.StoreBossbar) or (isinstance(st, ast.StoreData) and not isinstance(st.target, ast.StorageData))


@dataclass
class HostResult:
    has: bool  # the command ran (its callbacks fired)
    ok: bool
    value: int


class Host(Env):
    """Runs host ops against ``state``; ``report(message, severity)`` records a diagnostic at the
    current instruction, ``overflow(op, a, b, exact)`` a wrapped result under the sanitizer."""

    def __init__(self, state: WorldState, functions: dict, tags, report: Callable[[str, str, bool], None],
                 overflow: Callable[[str, int, int, int], None] | None = None,
                 where: Callable[[], tuple] = tuple) -> None:
        super().__init__(state, functions, tags)
        self.report = report
        self._overflow = overflow
        self._where = where  # the call stack at the current instruction

    def frames(self, node) -> tuple:
        return self._where()

    def overflow(self, op: str, a: int, b: int, exact: int) -> None:
        if self._overflow is not None:
            self._overflow(op, a, b, exact)

    def warning(self, node, message: str, unmodelled: bool = False) -> None:
        self.report(message, "warning", unmodelled)

    def run_final(self, cmd: ast.Command | ast.Condition, ctx: Context) -> HostResult:
        """A command (or a condition ending an execute chain) run once for ``ctx``."""
        try:
            return HostResult(True, True, wrap32(run_command(self, cmd, ctx)))
        except CommandFailure as failure:
            self._failed(failure)
            return HostResult(True, False, 0)

    def run_stage(self, st: ast.Subcommand, ctx: Context) -> list[Context] | None:
        """The contexts one execute stage makes from ``ctx``; None when the stage fails (the
        whole command, or in a forked chain only this context: the caller decides)."""
        if stores.is_store(st):
            return [ctx]  # a store into storage: resolved by run_store
        try:
            return stages.stage(self, st, ctx)
        except CommandFailure as failure:
            self._failed(failure)
            return None

    def run_store_stage(self, st: ast.Subcommand, ctx: Context) -> StoreTarget | None:
        """A store stage with a target to resolve (:func:`resolves_target`): the target, or None
        when the stage fails (no entity, an unknown objective ...)."""
        try:
            return StoreTarget(stores.store_target(self, st, ctx))
        except CommandFailure as failure:
            self._failed(failure)
            return None

    def run_store(self, st: ast.Subcommand, target: StoreTarget | None, ok: bool, value: int) -> None:
        """A ``store`` stage's callback; ``target``: what its stage resolved (None for storage)."""
        resolved = stores.store_target(self, st, None) if target is None else target.value
        stores.store(self, st, resolved, ok, value)

    def _failed(self, failure: CommandFailure) -> None:
        if failure.report:
            self.report(failure.message, "error", failure.unmodelled)
