"""Score holders and entity targets, as the game resolves them (ScoreHolderArgument, EntityArgument).

Selectors and entity names resolve through the world's entity store (:mod:`.entities`); score
holders named by text (players, ``#fake``, ``$fake``, UUIDs) need no entity.
"""
from __future__ import annotations

from emulator.world.state import Scoreboard
from mcfunction_parser.ast import NameTarget, Selector, Wildcard

from . import entities
from .failure import CommandFailure
from .source import Source


def select_entities(target, source: Source) -> list:
    """EntityArgument.getOptionalEntities: the entities a selector or name finds."""
    return entities.select(target, source)


def holder_names(holder, source: Source, scoreboard: Scoreboard) -> list[str]:
    """ScoreHolderArgument.getNamesWithDefaultWildcard: the holders named, in the game's order.

    ``*`` is every tracked holder (a score in any objective: Scoreboard.getTrackedPlayers), taken
    in first-seen order here; an empty result fails the command.
    """
    if isinstance(holder, NameTarget):
        return [holder.name]
    if isinstance(holder, Wildcard):
        names = scoreboard.tracked_holders()
        if not names:
            raise CommandFailure("No relevant score holders could be found")
        return names
    if isinstance(holder, Selector):
        return entities.holder_names(holder, source)
    raise TypeError(f"not a score holder: {holder!r}")


def single_holder(holder, source: Source, scoreboard: Scoreboard) -> str:
    """ScoreHolderArgument.getName: the first of the names; ``*`` has no default here (an empty
    list), so it always fails."""
    if isinstance(holder, Wildcard):
        raise CommandFailure("No relevant score holders could be found")
    return holder_names(holder, source, scoreboard)[0]

