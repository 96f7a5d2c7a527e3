"""The final command of a chain, run once for one context: :func:`run_command` returns its int
result or raises :class:`~emulator.world.errors.CommandFailure`.

``function`` and ``return`` are control flow (each backend queues their work itself). A command
the emulator does not model succeeds with result 1 and no effect, with a warning once per command
in the source. Commands whose effect no pack can read back (:data:`NO_OBSERVABLE_EFFECT`: the operator's
``debug``, ``perf``, ``jfr`` and ``save-*``) stop there; any other is *unmodelled*: a test that runs one is
inconclusive, since its pass or failure may hang on the missing effect.
"""
from __future__ import annotations

from mcfunction_parser import ast

from . import (advancements, blocks, bossbar, conditions, data, entities, items, level, living, packs, packtest,
               recipes, scoreboard, server, shown, teams)

# The server operator's commands (permission level 3 and 4: no function loads them, a server may
# raise its function level): no world state a pack can test changes.
NO_OBSERVABLE_EFFECT = frozenset({
    "debug", "perf", "jfr", "save-all", "save-off", "save-on",
})


def _unread(env, cmd: ast.UnreadCommand, ctx) -> int:
    env.unmodelled(cmd, f"'{cmd.name}' is not emulated here: the line was not read ({cmd.reason})")
    return 1


HANDLERS = {**scoreboard.HANDLERS, **data.HANDLERS, **entities.HANDLERS, **server.HANDLERS, **bossbar.HANDLERS,
            **items.HANDLERS, **packtest.HANDLERS, ast.UnreadCommand: _unread}
# the commands the parser keeps as text, by name
GENERIC_HANDLERS = {**blocks.HANDLERS, **living.HANDLERS, **advancements.HANDLERS, **recipes.HANDLERS,
                    **server.GENERIC_HANDLERS, **items.GENERIC_HANDLERS, **teams.HANDLERS,
                    **entities.GENERIC_HANDLERS, **level.GENERIC_HANDLERS, **packs.GENERIC_HANDLERS,
                    **shown.GENERIC_HANDLERS}


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
    name = getattr(cmd, "name", type(cmd).__name__)
    if name in NO_OBSERVABLE_EFFECT:
        env.warn(cmd, f"'{name}' is not emulated: it succeeds without effect (none a pack can read back)")
    else:
        env.unmodelled(cmd, f"'{name}' is not emulated: it succeeds without effect")
    return 1
