"""``team add|remove|empty|join|leave|list|modify`` on the world's teams (:mod:`emulator.world.teams`).

The parser keeps ``team`` as text; it is read here. Results are the game's: ``add`` and ``remove``
the number of teams after, ``empty``, ``join`` and ``leave`` the holders named, ``list`` the teams
or members counted, ``modify`` 0 (1 for ``prefix`` and ``suffix``), failing when an option is
already that value. Source (decompiled 1.21): server/commands/TeamCommand.java.
"""
from __future__ import annotations

from emulator.world.errors import CommandFailure
from emulator.world.teams import COLLISION_RULES, VISIBILITIES
from emulator.world.text import read_component
from mcfunction_parser import ast

from mcfunction_parser.arguments import holder_from_word

from .entities import _executor_required, arguments
from .holders import holder_names

# the options whose value is a word, with the error when it is already set
_FLAGS = {"friendlyFire": ("friendly_fire", "commands.team.option.friendlyfire.already"),
          "seeFriendlyInvisibles": ("see_friendly_invisibles", "commands.team.option.seeFriendlyInvisibles.already")}
_CHOICES = {"nametagVisibility": ("nametag_visibility", VISIBILITIES, "commands.team.option.nametagVisibility.unchanged"),
            "deathMessageVisibility": ("death_message_visibility", VISIBILITIES,
                                       "commands.team.option.deathMessageVisibility.unchanged"),
            "collisionRule": ("collision_rule", COLLISION_RULES, "commands.team.option.collisionRule.unchanged")}


def team_command(env, cmd: ast.GenericCommand, ctx) -> int:
    words, target = arguments(cmd)
    teams = env.state.teams
    action = words[0] if words else ""
    if action == "list":
        return len(teams.team(words[1]).members) if len(words) > 1 else len(teams.teams)
    if action == "add":
        return teams.add(_word(cmd, words, 1), _component(cmd, _rest(cmd, 2)) if len(words) > 2 else None)
    if action == "leave":
        return teams.leave(_holders(env, cmd, words, 1, target, ctx))
    team = teams.team(_word(cmd, words, 1))
    if action == "remove":
        return teams.remove(team)
    if action == "empty":
        return teams.empty(team)
    if action == "join":
        if len(words) > 2:
            return teams.join(team, _holders(env, cmd, words, 2, target, ctx))
        return teams.join(team, [_executor_required(env.state, ctx).score_holder])
    if action == "modify":
        return _modify(cmd, team, _word(cmd, words, 2), words)
    raise CommandFailure("dpemu.command.unreadable", cmd.name, f"unknown action '{action}'", report=True)


def _modify(cmd, team, option: str, words: list) -> int:
    if option in ("prefix", "suffix"):
        setattr(team, option, _component(cmd, _rest(cmd, 3)))
        return 1
    if option == "displayName":
        name = _component(cmd, _rest(cmd, 3))
        if name == team.display_name:
            raise CommandFailure("commands.team.option.name.unchanged")
        team.display_name = name
        return 0
    value = _word(cmd, words, 3)
    if option == "color":
        if value == team.color:
            raise CommandFailure("commands.team.option.color.unchanged")
        team.color = value
        return 0
    if option in _FLAGS:
        field, error = _FLAGS[option]
        on = value == "true"
        if getattr(team, field) == on:
            raise CommandFailure(error + ("Enabled" if on else "Disabled"))
        setattr(team, field, on)
        return 0
    if option in _CHOICES:
        field, _, error = _CHOICES[option]
        if getattr(team, field) == value:
            raise CommandFailure(error)
        setattr(team, field, value)
        return 0
    raise CommandFailure("dpemu.command.unreadable", cmd.name, f"unknown option '{option}'", report=True)


def _holders(env, cmd, words: list, index: int, target, ctx) -> list[str]:
    """ScoreHolderArgument.getNamesWithDefaultWildcard of the members argument."""
    if index >= len(words):
        raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected members", report=True)
    holder = target if words[index] is None else holder_from_word(words[index], cmd.loc)
    return holder_names(env, holder, ctx)


def _word(cmd, words: list, index: int) -> str:
    if index >= len(words) or words[index] is None:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected a team", report=True)
    return words[index]


def _rest(cmd, skip: int) -> str:
    """The text after the command's name and ``skip`` words (a component may hold spaces)."""
    parts = cmd.text.split(None, skip + 1)
    return parts[skip + 1] if len(parts) > skip + 1 else ""


def _component(cmd, text: str):
    component = read_component(text)
    if component is None:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, f"not a text component: {text}", report=True)
    return component


HANDLERS = {"team": team_command}
