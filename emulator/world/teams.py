"""Teams, the scoreboard's PlayerTeams: each has a display name, a colour, a prefix and suffix, its
options and its members (score holder names: a player's name, another entity's UUID string, or a
name no entity has). A holder is in one team at most. An entity's team is its holder's, which
``team=``, the ``team`` predicate, display names and friendly fire read.

- ``Teams(on_change)``: ``add``, ``team(name)`` (fails ``Unknown team``), ``remove``, ``empty``,
  ``join(team, holders)``, ``leave(holders)``, ``team_of(holder)``; ``on_change(holder, team name
  or None)`` is told of each membership change.
- ``formatted_name(team, name)``: PlayerTeam.formatNameForTeam (prefix, name, suffix, the colour).
- ``can_harm(teams, target, attacker)``: Player.canHarmPlayer between two players.

Sources (decompiled 1.21): world/scores/Scoreboard.java (addPlayerTeam, removePlayerTeam,
addPlayerToTeam, removePlayerFromTeam), world/scores/PlayerTeam.java (its defaults,
getFormattedName, formatNameForTeam, isAlliedTo), server/commands/TeamCommand.java,
world/entity/player/Player.java (canHarmPlayer), server/level/ServerPlayer.java (hurt).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from emulator.world.errors import CommandFailure

VISIBILITIES = ("always", "never", "hideForOtherTeams", "hideForOwnTeam")  # Team.Visibility
COLLISION_RULES = ("always", "never", "pushOtherTeams", "pushOwnTeam")  # Team.CollisionRule


@dataclass
class Team:
    name: str
    display_name: object  # a text component (plain values)
    color: str = "reset"
    friendly_fire: bool = True
    see_friendly_invisibles: bool = True
    nametag_visibility: str = "always"
    death_message_visibility: str = "always"
    collision_rule: str = "always"
    prefix: object = ""
    suffix: object = ""
    members: list[str] = field(default_factory=list)


class Teams:
    def __init__(self, on_change: Callable[[str, str | None], None] = lambda holder, team: None) -> None:
        self.teams: dict[str, Team] = {}
        self.by_holder: dict[str, str] = {}
        self.on_change = on_change

    def add(self, name: str, display_name=None) -> int:
        """Scoreboard.addPlayerTeam: the number of teams after it."""
        if name in self.teams:
            raise CommandFailure("commands.team.add.duplicate")
        self.teams[name] = Team(name, name if display_name is None else display_name)
        return len(self.teams)

    def team(self, name: str) -> Team:
        """TeamArgument.getTeam."""
        found = self.teams.get(name)
        if found is None:
            raise CommandFailure("team.notFound", name)
        return found

    def remove(self, team: Team) -> int:
        """Scoreboard.removePlayerTeam: its members leave; the number of teams left."""
        for holder in list(team.members):
            self._leave(holder)
        del self.teams[team.name]
        return len(self.teams)

    def empty(self, team: Team) -> int:
        if not team.members:
            raise CommandFailure("commands.team.empty.unchanged")
        members = list(team.members)
        for holder in members:
            self._leave(holder)
        return len(members)

    def join(self, team: Team, holders: list[str]) -> int:
        """Scoreboard.addPlayerToTeam for each (leaving its team first); the number named."""
        for holder in holders:
            if self.by_holder.get(holder) == team.name:
                continue
            self._leave(holder)
            self.by_holder[holder] = team.name
            team.members.append(holder)
            self.on_change(holder, team.name)
        return len(holders)

    def leave(self, holders: list[str]) -> int:
        """Scoreboard.removePlayerFromTeam for each; the number named, in a team or not."""
        for holder in holders:
            self._leave(holder)
        return len(holders)

    def _leave(self, holder: str) -> None:
        name = self.by_holder.pop(holder, None)
        if name is not None:
            self.teams[name].members.remove(holder)
            self.on_change(holder, None)

    def team_of(self, holder: str) -> str | None:
        return self.by_holder.get(holder)


def formatted_name(team: Team | None, name: dict) -> dict:
    """PlayerTeam.formatNameForTeam: the name itself without a team, else an empty component of the
    prefix, the name and the suffix, in the team's colour unless ``reset``."""
    if team is None:
        return name
    formatted = {"text": "", "extra": [team.prefix, name, team.suffix]}
    if team.color != "reset":
        formatted["color"] = team.color
    return formatted


def can_harm(teams: Teams, target, attacker) -> bool:
    """Player.canHarmPlayer (a pvp server): not when both are in one team without friendly fire."""
    name = teams.team_of(target.score_holder)
    if name is None or teams.team_of(attacker.score_holder) != name:
        return True
    return teams.teams[name].friendly_fire
