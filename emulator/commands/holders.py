"""Score holders and objectives as the scoreboard commands read them (ScoreHolderArgument,
ObjectiveArgument, 1.21).

Holders named by text (players, ``#fake``, ``$fake``, UUIDs) need no entity; a selector's holders
are its entities' (:func:`emulator.commands.entities.holder_names`). A command reads its
arguments in the order the game passes them to its method (Java evaluates them left to right),
which decides which failure a command with two bad arguments reports.
"""
from __future__ import annotations

from mcfunction_parser import ast

from . import entities
from emulator.world.errors import CommandFailure


def holder_names(env, holder, ctx) -> list[str]:
    """ScoreHolderArgument.getNamesWithDefaultWildcard: the holders named, in the game's order.

    ``*`` is every tracked holder (a score in any objective: Scoreboard.getTrackedPlayers); an
    empty result fails the command.
    """
    if isinstance(holder, ast.NameTarget):
        return [holder.name]
    if isinstance(holder, ast.Wildcard):
        names = env.state.scoreboard.tracked_holders()
        if not names:
            raise CommandFailure("argument.scoreHolder.empty")
        return names
    return entities.holder_names(env.state, holder, ctx)


def single_holder(env, holder, ctx) -> str:
    """ScoreHolderArgument.getName (``get``, ``list``, ``if score``): the first of the names;
    ``*`` has no default here (an empty list), so it always fails."""
    if isinstance(holder, ast.Wildcard):
        raise CommandFailure("argument.scoreHolder.empty")
    return holder_names(env, holder, ctx)[0]


def objective(env, name: str) -> str:
    """ObjectiveArgument.getObjective: the objective must exist (reported: a pack bug)."""
    if not env.state.scoreboard.exists(name):
        raise CommandFailure("arguments.objective.notFound", name, report=True)
    return name


def writable_objective(env, name: str) -> str:
    """ObjectiveArgument.getWritableObjective: exists and its criterion is not read-only
    (``health`` ...). Reported like an unknown objective: such a write can never succeed."""
    objective(env, name)
    if not env.state.scoreboard.is_writable(name):
        raise CommandFailure("arguments.objective.readonly", name, report=True)
    return name
