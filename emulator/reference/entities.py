"""The reference backend's entry into the world (entities, blocks, entity and block data): each
function runs the shared :mod:`emulator.commands.entities` and turns its failures into this
backend's :class:`CommandFailure`, so both backends share one implementation.

The world state is reached through ``source.state`` (set on the root source by the engine).
"""
from __future__ import annotations

from contextlib import contextmanager

from emulator.commands import entities as world
from mcfunction_parser import ast

from .failure import CommandFailure
from .queue import chain
from .source import Source


@contextmanager
def _failures():
    try:
        yield
    except world.WorldCommandError as error:
        raise CommandFailure(error.message, error.report) from None


def select(target, source: Source) -> list:
    with _failures():
        return world.select(source.state, target, source.context)


def holder_names(selector: ast.Selector, source: Source) -> list[str]:
    with _failures():
        return world.holder_names(source.state, selector, source.context)


def stage(sub: ast.Subcommand, source: Source) -> list[Source]:
    """An entity stage: one source per context it makes (same callback and activation)."""
    with _failures():
        contexts = world.stage(source.state, sub, source.context)
    return [source.with_context(**_fields(c)) for c in contexts]


def _fields(context) -> dict:
    return {"executor": context.executor, "pos": context.pos, "rot": context.rot, "anchor": context.anchor}


def condition_count(cond: ast.Condition, source: Source) -> int:
    with _failures():
        return world.condition_count(source.state, cond, source.context)


def store_data(sub: ast.StoreData, source: Source) -> Source:
    """``store ... entity|block``: the target is resolved now; the callback stores each result."""
    with _failures():
        target = world.store_target(source.state, sub, source.context)

    def store(success: bool, value: int) -> None:
        world.store(source.state, target, sub, success, value)

    return source.with_callback(chain(source.callback, store))


def command(env, cmd: ast.Command, source: Source, where) -> int:
    with _failures():
        return world.command(source.state, cmd, source.context,
                             lambda node, message: env.warn_once(node, message, source))
