"""The server's other commands: ``say``, ``tellraw``, ``gamerule``, ``schedule``, ``time``,
``random``, ``trigger`` and ``help``.

Sources (decompiled 1.21): server/commands/SayCommand.java, TellRawCommand.java,
GameRuleCommand.java, ScheduleCommand.java, TimeCommand.java, RandomCommand.java (randomSample),
TriggerCommand.java (getScore), HelpCommand.java; the texts are the world library's
(:mod:`emulator.world.text_components`).
"""
from __future__ import annotations

from emulator.world import text_components
from emulator.world.clocks import F32
from emulator.world.errors import MESSAGES
from emulator.world.semantics import INT_MAX, INT_MIN, wrap32
from mcfunction_parser import ast, gamedata
from mcfunction_parser.commands import usage
from mcfunction_parser.pack.tags import normalise_id  # ResourceLocation.toString (the MD5 seed hashes it)

from . import entities
from emulator.world.errors import CommandFailure
from .holders import objective

DAY_TICKS = 24000


def sender_name(env, ctx) -> str:
    """CommandSourceStack.getDisplayName: the executor's name (custom name, player name or type
    name), or "Server"."""
    entity = entities.executor(env.state, ctx)
    return "Server" if entity is None else entity.display_name


def say(env, cmd: ast.Say, ctx) -> int:
    message = text_components.say_text(cmd.message, lambda sel: entities.select(env.state, sel, ctx))
    env.state.broadcast("say", f"[{sender_name(env, ctx)}] {message}", cmd.loc)
    return 1


def tellraw(env, cmd: ast.Tellraw, ctx) -> int:
    def select(target) -> list:
        return entities.select(env.state, target, ctx)

    finder = text_components.finder(entities.parse_target, select)
    return text_components.tellraw_command(env.state, cmd, select(cmd.targets), finder)


def gamerule(env, cmd: ast.Gamerule, ctx) -> int:
    """GameRuleCommand: set or query; the result is the value (booleans as 1/0)."""
    rules = env.state.gamerules
    if cmd.value is not None:
        rules.set(cmd.rule, cmd.value)
    value = rules.get(cmd.rule)
    if value is None:
        raise CommandFailure("dpemu.gamerule.unknown", cmd.rule, report=True)
    if value in ("true", "false"):
        return int(value == "true")
    return int(value)


def require_function(env, name: str, is_tag: bool) -> None:
    """FunctionArgument: the function or the function tag must exist (reported: a pack bug)."""
    if name not in (env.tags if is_tag else env.functions):
        raise CommandFailure("arguments.function.unknown", ("#" if is_tag else "") + name, report=True)


def schedule(env, cmd: ast.Schedule, ctx) -> int:
    """ScheduleCommand.schedule: ``0t`` fails (ERROR_SAME_TICK, reported: the function would never
    run); the result is floorMod(due time, Integer.MAX_VALUE)."""
    require_function(env, cmd.function, cmd.is_tag)
    if cmd.ticks == 0:
        raise CommandFailure("commands.schedule.same_tick", report=True)
    state = env.state
    due = state.schedule.schedule(cmd.function, cmd.is_tag, cmd.ticks, cmd.mode, state.gametime)
    return due % INT_MAX


def schedule_clear(env, cmd: ast.ScheduleClear, ctx) -> int:
    removed = env.state.schedule.clear(cmd.function, cmd.is_tag)
    if removed == 0:
        raise CommandFailure("commands.schedule.cleared.failure", ("#" if cmd.is_tag else "") + cmd.function)
    return removed


def _java_rem(a: int, b: int) -> int:
    """Java ``%`` on longs (the sign of the dividend)."""
    r = abs(a) % b
    return -r if a < 0 else r


def time(env, cmd: ast.Time, ctx) -> int:
    """``time set|add`` change the day time of every level (the result is the new day time
    modulo 24000); ``time query daytime|gametime|day`` return (int)(dayTime % 24000),
    (int)(gameTime % Integer.MAX_VALUE) and (int)(dayTime / 24000 % Integer.MAX_VALUE)."""
    state = env.state
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


def clock(env, cmd: ast.ClockCommand, ctx) -> int:
    """TimeCommand on a world clock (26.1.2): the one ``time of <clock>`` names, else the executing
    dimension's default clock (none in the nether: commands.time.no_default_clock). ``set`` returns
    the ticks set; ``add``, ``set <marker>`` and the queries the clock's ticks wrapped as
    wrapTime (ticks % Integer.MAX_VALUE); ``pause``, ``resume`` and ``rate`` 1. ``query <timeline>``
    reads a timeline of that clock (commands.time.wrong_timeline_for_clock otherwise): the ticks
    within its period (Timeline.getCurrentTicks), or with ``repetition`` the periods passed
    (getPeriodCount, 0 without a period)."""
    clocks = env.state.clocks
    name = cmd.clock
    if name is None:
        name, dimension_type = env.state.entities.table.levels.default_clock(ctx.dimension)
        if name is None:
            raise CommandFailure("commands.time.no_default_clock", dimension_type)
    _known(clocks is not None and name in clocks, name, "world_clock")  # a macro line's clock; else the load refused it
    action = cmd.action
    if action == "set":
        clocks.set_ticks(name, cmd.value)
        return cmd.value
    if action == "add":
        return _wrap_time(clocks.add_ticks(name, cmd.value))
    if action == "marker":
        if not clocks.move_to_marker(name, cmd.value):
            # 26.1.2 formats the marker's ResourceKey (ERROR_NO_TIME_MARKER_FOUND.create(clock, timeMarkerId))
            raise CommandFailure("commands.time.no_time_marker_found",
                                 f"ResourceKey[minecraft:clock_time_marker / {cmd.value}]", name)
        return _wrap_time(clocks.ticks(name))
    if action in ("pause", "resume"):
        clocks.instances[name].paused = action == "pause"
        return 1
    if action == "rate":
        clocks.instances[name].rate = F32(cmd.value)
        return 1
    ticks = clocks.ticks(name)
    if cmd.timeline is None:
        return _wrap_time(ticks)
    timeline = clocks.registry.timelines.get(cmd.timeline)
    _known(timeline is not None, cmd.timeline, "timeline")
    if timeline.clock != name:
        raise CommandFailure("commands.time.wrong_timeline_for_clock", cmd.timeline, name)
    if cmd.repetition:
        return 0 if timeline.period is None else _java_rem(wrap32(ticks // timeline.period), INT_MAX)
    return _wrap_time(ticks if timeline.period is None else ticks % timeline.period)


def _known(found: bool, rid: str, registry: str) -> None:
    if not found:
        raise CommandFailure("argument.resource.not_found", rid, "minecraft:" + registry, report=True)


def _wrap_time(ticks: int) -> int:
    """TimeCommand.wrapTime: Math.toIntExact(ticks % Integer.MAX_VALUE) (a clock's ticks are never negative)."""
    return ticks % INT_MAX


def random(env, cmd: ast.RandomCommand, ctx) -> int:
    """``random value|roll RANGE [SEQUENCE]``: a bound left open is Integer.MIN/MAX_VALUE; the span
    max - min must be 1 .. 2147483646. ``roll`` broadcasts "<name> rolled N (from A to B)" (logged
    as chat). ``random reset ID|* ...``: 1 for a sequence, the number forgotten for ``*``."""
    sequences = env.state.random_sequences
    if cmd.action == "reset":
        return _random_reset(sequences, cmd)
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
        text = MESSAGES["commands.random.roll"].format(sender_name(env, ctx), value, low, high)
        env.state.broadcast("chat", text, cmd.loc)
    return value


def _random_reset(sequences, cmd: ast.RandomCommand) -> int:
    if cmd.sequence != "*":
        sequences.reset(normalise_id(cmd.sequence), cmd.seed, cmd.include_world_seed, cmd.include_sequence_id)
        return 1
    if cmd.seed is not None:
        sequences.salt = cmd.seed
        sequences.include_world_seed = cmd.include_world_seed
        sequences.include_sequence_id = cmd.include_sequence_id
    return sequences.clear()


def trigger(env, cmd: ast.Trigger, ctx) -> int:
    """TriggerCommand: run by a player, on a ``trigger`` objective whose score for that player
    exists and is unlocked; the score is locked again, then ``add N`` (default 1) or ``set N``.
    The result is the new value. The player is required before the objective is read
    (simpleTrigger's arguments: getPlayerOrException, then getObjective)."""
    player = entities.executor(env.state, ctx)
    if player is None or not player.is_player:
        raise CommandFailure("permissions.requires.player")
    objective(env, cmd.objective)
    board = env.state.scoreboard
    if board.criteria[board.objective_ids[cmd.objective]] != "trigger":
        raise CommandFailure("commands.trigger.failed.invalid")
    name = player.score_holder
    if not board.is_unlocked(name, cmd.objective):
        raise CommandFailure("commands.trigger.failed.unprimed")
    board.lock(name, cmd.objective)
    if cmd.action == "set":
        value = cmd.value
    else:
        value = wrap32(board.get(name, cmd.objective) + (1 if cmd.action is None else cmd.value))
    board.set(name, cmd.objective, value)
    return value


def help_(env, cmd: ast.GenericCommand, ctx) -> int:
    """HelpCommand: the number of usage messages it sends (a player sees them; a command block
    keeps the last, :func:`emulator.world.command_blocks.feedback`); a command the source may not
    use fails."""
    text = cmd.text.partition(" ")[2] or None
    try:
        count = usage.help_count(gamedata.command_tree(env.state.version), text)
    except (gamedata.GameDataMissing, ValueError) as reason:
        env.unmodelled(cmd, f"'help' is not emulated here ({reason}): it succeeds without effect")
        return 1
    if count is None:
        raise CommandFailure("commands.help.failed", report=True)
    return count


HANDLERS = {
    ast.Say: say,
    ast.Tellraw: tellraw,
    ast.Gamerule: gamerule,
    ast.Schedule: schedule,
    ast.ScheduleClear: schedule_clear,
    ast.Time: time,
    ast.ClockCommand: clock,
    ast.RandomCommand: random,
    ast.Trigger: trigger,
}
# the forms the parser keeps as text, by command name
GENERIC_HANDLERS = {"help": help_}
