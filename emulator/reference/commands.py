"""Final commands other than ``function`` and ``return`` (those queue work: see :mod:`.engine`).

:func:`run_command` runs one command for one source and returns its int result or raises
:class:`CommandFailure`. Commands the emulator does not model (``particle``, ``playsound`` ...)
succeed with result 1 and no effect; each such command is reported once as a warning.
"""
from __future__ import annotations

from emulator.world.semantics import INT_MAX
from mcfunction_parser import ast

from emulator.world import bossbars, relations, server_commands, text_components

from . import conditions, data, entities, scoreboard
from .data import world_failures
from .failure import CommandFailure
from .scoreboard import objective
from .source import Source


def say(env, cmd: ast.Say, source: Source, where) -> int:
    message = text_components.say_text(cmd.message, lambda sel: entities.select(sel, source))
    env.state.broadcast("say", f"[{sender_name(source)}] {message}", where)
    return 1


def tellraw(env, cmd: ast.Tellraw, source: Source, where) -> int:
    def select(target) -> list:
        return entities.select(target, source)

    finder = text_components.finder(entities.world.parse_target, select)
    with world_failures():
        return text_components.tellraw_command(env.state, cmd, select(cmd.targets), finder)


def sender_name(source: Source) -> str:
    """The executor's display name (custom name, player name or type name), or "Server"."""
    entity = entities.world.executor(source.state, source.context)
    return "Server" if entity is None else entity.display_name


def gamerule(env, cmd: ast.Gamerule, source: Source, where) -> int:
    """GameRuleCommand: set or query; the result is the value (booleans as 1/0)."""
    rules = env.state.gamerules
    if cmd.value is not None:
        rules.set(cmd.rule, cmd.value)
        return _rule_result(cmd.value)
    value = rules.get(cmd.rule)
    if value is None:
        raise CommandFailure(f"Unknown game rule '{cmd.rule}'", report=True)
    return _rule_result(value)


def _rule_result(value: str) -> int:
    if value in ("true", "false"):
        return int(value == "true")
    return int(value)


def schedule(env, cmd: ast.Schedule, source: Source, where) -> int:
    """ScheduleCommand.schedule: the result is floorMod(due time, Integer.MAX_VALUE)."""
    env.require_function(cmd.function, cmd.is_tag)
    due = env.state.schedule.schedule(cmd.function, cmd.is_tag, cmd.ticks, cmd.mode, env.state.gametime)
    return due % INT_MAX


def schedule_clear(env, cmd: ast.ScheduleClear, source: Source, where) -> int:
    removed = env.state.schedule.clear(cmd.function, cmd.is_tag)
    if removed == 0:
        name = ("#" if cmd.is_tag else "") + cmd.function
        raise CommandFailure(f"No schedules with id {name}")
    return removed


def time(env, cmd: ast.Time, source: Source, where) -> int:
    return server_commands.time_command(env.state, cmd)


def random(env, cmd: ast.RandomCommand, source: Source, where) -> int:
    with world_failures():
        return server_commands.random_command(env.state, cmd, sender_name(source))


def trigger(env, cmd: ast.Trigger, source: Source, where) -> int:
    objective(env, cmd.objective)
    with world_failures():
        return server_commands.trigger_command(env.state, cmd, entities.world.executor(source.state, source.context))


def bossbar(env, cmd: ast.Bossbar, source: Source, where) -> int:
    players = None
    if cmd.targets is not None:  # EntityArgument.getOptionalPlayers: none found is not an error
        found = entities.select(cmd.targets, source)
        players = [e.player_name for e in found if e.is_player]
    with world_failures():
        return bossbars.bossbar_command(env.state.bossbars, cmd, players)


def ride(env, cmd: ast.Ride, source: Source, where) -> int:
    riders = entities.select(cmd.target, source)
    vehicles = [] if cmd.vehicle is None else entities.select(cmd.vehicle, source)
    with world_failures():
        return relations.ride_command(cmd, riders, vehicles)


def not_modelled(env, cmd: ast.Command, source: Source, where) -> int:
    name = getattr(cmd, "name", type(cmd).__name__)
    env.warn_once(cmd, f"'{name}' is not emulated: it succeeds without effect", source)
    return 1


def condition(env, cond: ast.Condition, source: Source, where) -> int:
    return conditions.run_as_command(env, cond, source, where)


HANDLERS = {
    **scoreboard.HANDLERS,
    **data.HANDLERS,
    ast.Say: say,
    ast.Tellraw: tellraw,
    ast.Gamerule: gamerule,
    ast.Schedule: schedule,
    ast.ScheduleClear: schedule_clear,
    ast.Time: time,
    ast.RandomCommand: random,
    ast.Trigger: trigger,
    ast.Bossbar: bossbar,
    ast.Ride: ride,
}


def run_command(env, cmd, source: Source, where) -> int:
    if isinstance(cmd, ast.Condition):
        return condition(env, cmd, source, where)
    if entities.world.is_world_command(cmd):
        return entities.command(env, cmd, source, where)
    handler = HANDLERS.get(type(cmd), not_modelled)
    return handler(env, cmd, source, where)
