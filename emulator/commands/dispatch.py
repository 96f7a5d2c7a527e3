"""The final command of a chain, run once for one context: :func:`run_command` returns its int
result or raises :class:`~emulator.world.errors.CommandFailure`.

``function`` and ``return`` are control flow (each backend queues their work itself). A command
the emulator does not model (``particle``, ``playsound`` ...) succeeds with result 1 and no
effect, with a warning once per command in the source.
"""
from __future__ import annotations

from mcfunction_parser import ast

from . import blocks, bossbar, conditions, data, entities, items, living, scoreboard, server

HANDLERS = {**scoreboard.HANDLERS, **data.HANDLERS, **entities.HANDLERS, **server.HANDLERS, **bossbar.HANDLERS,
            **items.HANDLERS}
# the commands the parser keeps as text, by name
GENERIC_HANDLERS = {**blocks.HANDLERS, **living.HANDLERS}


def run_command(env, cmd: ast.Command | ast.Condition, ctx) -> int:
    if isinstance(cmd, ast.Condition):  # a test ending an execute chain
        return conditions.as_command(env, cmd, ctx)
    handler = HANDLERS.get(type(cmd))
    if handler is None and isinstance(cmd, ast.GenericCommand):
        handler = GENERIC_HANDLERS.get(cmd.name)
    if handler is None:
        return _not_modelled(env, cmd)
    return handler(env, cmd, ctx)


def _not_modelled(env, cmd: ast.Command) -> int:
    env.warn(cmd, f"'{getattr(cmd, 'name', type(cmd).__name__)}' is not emulated: it succeeds without effect")
    return 1
