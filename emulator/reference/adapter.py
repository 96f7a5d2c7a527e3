"""The reference backend's entry into :mod:`emulator.commands` (the commands both backends run):
:class:`ReferenceEnv` is the interpreter as the commands' :class:`~emulator.commands.env.Env`, and
:func:`run_command` / :func:`apply` run a final command or an execute stage for one
:class:`~.source.Source`.

A stage's contexts become sources with the same callback and activation; a ``store`` stage
resolves its target now and chains a callback that stores each result (ExecuteCommand.storeValue,
storeData: the source's ``withCallback``).
"""
from __future__ import annotations

from emulator.commands import dispatch, stages, stores
from emulator.commands.env import Env
from emulator.world.semantics import wrap32
from emulator.world.records import Overflow
from mcfunction_parser import ast

from .queue import chain
from .source import Source


class ReferenceEnv(Env):
    """The interpreter's world, functions and sanitizer, at the source running now (:meth:`at`):
    overflows and warnings are reported at its function and line."""

    def __init__(self, state, packs, sanitize: bool) -> None:
        super().__init__(state, packs.functions, packs.tags)
        self.sanitize = sanitize
        self.source: Source | None = None
        self.where = None

    def at(self, source: Source | None, where) -> "ReferenceEnv":
        self.source, self.where = source, where
        return self

    def overflow(self, op: str, a: int, b: int, exact: int) -> None:
        if self.sanitize:
            activation = self.source.activation if self.source else None
            function = activation.function if activation else "<root>"
            self.state.overflows.append(Overflow(self.state.tick, function, self.where, op, a, b, exact, wrap32(exact)))

    def frames(self, node) -> tuple:
        activation = self.source.activation if self.source else None
        return activation.frames(node.loc) if activation else ()

    def warning(self, node, message: str, unmodelled: bool = False) -> None:
        self.state.error(message, self.frames(node), "warning", unmodelled)


def run_command(env: ReferenceEnv, cmd: ast.Command | ast.Condition, source: Source, where) -> int:
    return dispatch.run_command(env.at(source, where), cmd, source.context)


def apply(env: ReferenceEnv, sub: ast.Subcommand, source: Source, where) -> list[Source]:
    """The sources one stage makes from ``source``."""
    env.at(source, where)
    if stores.is_store(sub):
        target = stores.store_target(env, sub, source.context)

        def store(success: bool, value: int) -> None:
            stores.store(env, sub, target, success, value)

        return [source.with_callback(chain(source.callback, store))]
    return [source if ctx is source.context else source.in_context(ctx)
            for ctx in stages.stage(env, sub, source.context)]
