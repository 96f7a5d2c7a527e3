"""``time``, ``random``, ``trigger`` and ``scoreboard players enable`` over the world state: the
code both backends run (each wraps :class:`~emulator.world.errors.CommandFailure` into its own
failed command).

Sources (decompiled 1.21): server/commands/TimeCommand.java, server/commands/RandomCommand.java
(randomSample), server/commands/TriggerCommand.java (getScore), server/commands/ScoreboardCommand.java
(enableTrigger, setScoreDisplay, setScoreNumberFormat), server/level/ServerLevel.tickTime (see
:func:`advance_time`).
"""
from __future__ import annotations

from typing import Callable

from emulator.world.semantics import INT_MAX, INT_MIN, wrap32
from emulator.world.state import WorldState
from emulator.world.entities import Entity
from emulator.world.errors import MESSAGES, CommandFailure
from mcfunction_parser import ast
from mcfunction_parser.arguments import score_holder
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.pack.tags import normalise_id  # ResourceLocation.toString (the MD5 seed hashes it)

DAY_TICKS = 24000


def _java_rem(a: int, b: int) -> int:
    """Java ``%`` on longs (the sign of the dividend)."""
    r = abs(a) % b
    return -r if a < 0 else r


def time_command(state: WorldState, cmd: ast.Time) -> int:
    """``time set|add`` change the day time of every level (the result is the new day time
    modulo 24000); ``time query daytime|gametime|day`` return (int)(dayTime % 24000),
    (int)(gameTime % Integer.MAX_VALUE) and (int)(dayTime / 24000 % Integer.MAX_VALUE)."""
    if cmd.action == "set":
        state.daytime = cmd.value
    elif cmd.action == "add":
        state.daytime += cmd.value
    elif cmd.query == "gametime":
        return wrap32(_java_rem(state.gametime, INT_MAX))
    elif cmd.query == "day":
        days = abs(state.daytime) // DAY_TICKS * (-1 if state.daytime < 0 else 1)  # Java long division
        return wrap32(_java_rem(days, INT_MAX))
    return wrap32(_java_rem(state.daytime, DAY_TICKS))


def advance_time(state: WorldState) -> None:
    """ServerLevel.tickTime after the scheduled functions: the day time advances by one when
    ``doDaylightCycle`` (1.21.11: ``advance_time``) is true."""
    if state.gamerules.get("doDaylightCycle") == "true":
        state.daytime += 1


def random_command(state: WorldState, cmd: ast.RandomCommand, source_name: str) -> int:
    """``random value|roll RANGE [SEQUENCE]``: a bound left open is Integer.MIN/MAX_VALUE; the span
    max - min must be 1 .. 2147483646. ``roll`` broadcasts "<name> rolled N (from A to B)" (logged
    as chat). ``random reset ID|* ...``: 1 for a sequence, the number forgotten for ``*``."""
    sequences = state.random_sequences
    if cmd.action == "reset":
        if cmd.sequence != "*":
            sequences.reset(normalise_id(cmd.sequence), cmd.seed, cmd.include_world_seed, cmd.include_sequence_id)
            return 1
        if cmd.seed is not None:
            sequences.salt = cmd.seed
            sequences.include_world_seed = cmd.include_world_seed
            sequences.include_sequence_id = cmd.include_sequence_id
        return sequences.clear()
    low = INT_MIN if cmd.range.lo is None else cmd.range.lo
    high = INT_MAX if cmd.range.hi is None else cmd.range.hi
    span = high - low
    if span == 0:
        raise CommandFailure("commands.random.error.range_too_small")
    if span >= INT_MAX:
        raise CommandFailure("commands.random.error.range_too_large")
    source = sequences.level_random if cmd.sequence is None else sequences.get(normalise_id(cmd.sequence))
    value = source.between_inclusive(low, high)
    if cmd.action == "roll":
        state.broadcast("chat", MESSAGES["commands.random.roll"].format(source_name, value, low, high), cmd.loc)
    return value


def trigger_command(state: WorldState, cmd: ast.Trigger, executor: Entity | None) -> int:
    """TriggerCommand: run by a player, on a ``trigger`` objective whose score for that player
    exists and is unlocked; the score is locked again, then ``add N`` (default 1) or ``set N``.
    The result is the new value."""
    if executor is None or not executor.is_player:
        raise CommandFailure("permissions.requires.player")
    board = state.scoreboard
    if board.criteria[board.objective_ids[cmd.objective]] != "trigger":
        raise CommandFailure("commands.trigger.failed.invalid")
    name = executor.score_holder
    if not board.is_unlocked(name, cmd.objective):
        raise CommandFailure("commands.trigger.failed.unprimed")
    board.lock(name, cmd.objective)
    if cmd.action == "set":
        value = cmd.value
    else:
        value = wrap32(board.get(name, cmd.objective) + (1 if cmd.action is None else cmd.value))
    board.set(name, cmd.objective, value)
    return value


def enable_command(state: WorldState, names: list[str], objective: str) -> int:
    """ScoreboardCommand.enableTrigger: unlock each holder's score (created as 0 if missing); the
    count of scores that were locked; none fails."""
    board = state.scoreboard
    if board.criteria[board.objective_ids[objective]] != "trigger":
        raise CommandFailure("commands.scoreboard.players.enable.invalid")
    unlocked = sum(board.enable(name, objective) for name in names)
    if unlocked == 0:
        raise CommandFailure("commands.scoreboard.players.enable.failed")
    return unlocked


def display_command(state: WorldState, cmd: ast.ScoreDisplay, holders: Callable[[object], list[str]],
                    objective: Callable[[str], object]) -> int:
    """``scoreboard players display name|numberformat TARGETS OBJECTIVE ...``: each target's score
    is fetched get-or-create (an unset one becomes 0, as for ``set``) before its display name or
    number format changes, which the emulator does not keep; the result is the number of targets.
    ``holders`` resolves the targets (getNamesWithDefaultWildcard), ``objective`` checks the name
    (ObjectiveArgument.getObjective: any objective, read-only ones too); both fail the command."""
    holder, name = display_arguments(cmd)
    targets = holders(holder)  # the arguments are read in order: the targets, then the objective
    objective(name)
    for target in targets:
        if state.scoreboard.get(target, name) is None:
            state.scoreboard.set(target, name, 0)
    return len(targets)


def display_arguments(cmd: ast.ScoreDisplay) -> tuple[object, str]:
    """The TARGETS (a score holder node) and OBJECTIVE of the text the parser kept after ``display``."""
    kind, _, rest = cmd.text.partition(" ")
    reader = Reader(rest, cmd.loc, (1, 21, 0))
    try:
        holder = score_holder(reader)
    except ParseError:
        raise CommandFailure("command.unknown.argument") from None
    name = rest[reader.pos:].split(maxsplit=1)
    if not name:
        raise CommandFailure("command.unknown.argument")
    return holder, name[0]
