"""Host-side (Python) execution of the commands the VM does not run itself.

The VM stops at a host op and the numba backend calls one of (the VM has charged the costs):

- :meth:`Host.run_final`: a final command (``say``, ``schedule``, a score command on ``*`` or a
  selector, a condition ending a chain ...) run once for the current context;
- :meth:`Host.run_stage`: an execute stage the VM does not evaluate (``as``, ``positioned``,
  ``if entity`` ...), giving the contexts the rest of the chain runs in;
- :meth:`Host.run_store_stage`: a ``store`` stage whose target the VM cannot name (a selector's
  score holders, an entity, a block): the target, resolved now, as ExecuteCommand.storeValue does;
- :meth:`Host.run_store`: a ``store`` into storage, or into the target its stage resolved.

Entities, blocks and entity/block data go through :mod:`emulator.commands.entities`, the code the
reference backend runs too.

Failures are the game's: the command fails (result 0) and the run goes on. Failures that point at
a bug or at a limit of the emulator become diagnostics; routine ones (``get`` of an unset score,
``objectives add`` of an existing one) are silent, as in the game.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Callable

import numpy as np

from emulator.world.semantics import INT_MAX, floor_mod, wrap32, wraps32
from emulator.commands import entities as world_entities
from emulator.world.state import Context, WorldState
from emulator.world import bossbars, nbt_ops, relations, server_commands, stores, text_components
from emulator.world.errors import CommandFailure as WorldFailure
from emulator.world.source import Source
from mcfunction_parser import ast
from mcfunction_parser.nbt import Compound


class HostFailure(Exception):
    """A failing command; ``report``: also record a diagnostic."""

    def __init__(self, message: str, report: bool = False) -> None:
        super().__init__(message)
        self.message = message
        self.report = report


@dataclass(frozen=True)
class StoreTarget:
    """What a store stage resolved: score holder names, or a world store's entity/block accessor."""
    value: object


def resolves_target(st: ast.Subcommand) -> bool:
    """A store stage the host resolves (a score store on a name is the VM's own)."""
    return (isinstance(st, ast.StoreScore) and not isinstance(st.targets, ast.NameTarget)) or \
        isinstance(st, ast.StoreBossbar) or world_entities.is_world_store(st)


@dataclass
class HostResult:
    has: bool  # the command ran (its callbacks fired)
    ok: bool
    value: int


class Host:
    """Runs host ops against ``state`` (the VM has charged their cost)."""

    def __init__(self, state: WorldState, functions: dict, tags, report: Callable[[str, str], None],
                 overflow: Callable[[str, int, int, int], None] | None = None) -> None:
        self.state = state
        self.functions = functions
        self.tags = tags
        self.report = report  # (message, severity) -> diagnostic at the current command
        self.overflow = overflow  # sanitizer: (op, a, b, exact) for a result that wraps
        self._warned: set = set()

    def arith(self, op: str, a: int, b: int, exact: int) -> int:
        """The stored (wrapped) result; under the sanitizer a wrap is reported."""
        if self.overflow is not None and wraps32(exact):
            self.overflow(op, a, b, exact)
        return wrap32(exact)

    # ------------------------------------------------------------------ entry points
    def run_final(self, cmd: ast.Command | ast.Condition, ctx: Context) -> HostResult:
        """A command (or a condition ending an execute chain) run once for ``ctx``."""
        try:
            if isinstance(cmd, ast.Condition):  # a test ending the chain: its count, or 1 for unless
                count = self.condition_count(cmd, ctx)
                if (count > 0) == cmd.negated:
                    raise HostFailure("Test failed")
                return HostResult(True, True, 1 if cmd.negated else count)
            return HostResult(True, True, wrap32(self.command(cmd, ctx)))
        except HostFailure as failure:
            if failure.report:
                self.report(failure.message, "error")
            return HostResult(True, False, 0)

    def run_stage(self, st: ast.Subcommand, ctx: Context) -> list[Context] | None:
        """The contexts one execute stage makes from ``ctx``; None when the stage fails (the
        whole command, or in a forked chain only this context: the caller decides)."""
        try:
            return self.stage(st, ctx)
        except HostFailure as failure:
            if failure.report:
                self.report(failure.message, "error")
            return None

    def run_store_stage(self, st: ast.Subcommand, ctx: Context) -> StoreTarget | None:
        """A store stage with a target to resolve (:func:`resolves_target`): the target, or None
        when the stage fails (no entity, an unknown objective ...)."""
        try:
            if isinstance(st, ast.StoreScore):
                self.objective(st.objective)
                return StoreTarget(tuple(self.holders(st.targets, ctx)))
            if isinstance(st, ast.StoreBossbar):
                return StoreTarget(_world(bossbars.store_target, self.state.bossbars, st))
            return StoreTarget(_entities(world_entities.store_target, self.state, st, ctx))
        except HostFailure as failure:
            if failure.report:
                self.report(failure.message, "error")
            return None

    def run_store(self, st: ast.Subcommand, target: StoreTarget | None, ok: bool, value: int) -> None:
        """A ``store`` stage's callback: ``result`` stores the value (0 on failure), ``success`` 1/0.
        ``target``: what the stage resolved (None for storage)."""
        stored = (value if ok else 0) if st.kind == "result" else int(ok)
        if isinstance(st, ast.StoreData) and isinstance(st.target, ast.StorageData):
            stores.store(self.storage(st.target, create=True), st.path, st.type, stored, st.scale)
        elif world_entities.is_world_store(st):
            world_entities.store(self.state, target.value, st, ok, value)
        elif isinstance(st, ast.StoreScore):
            for name in target.value:
                self.state.scoreboard.set(name, st.objective, stored)
        else:
            bossbars.store(target.value, st, ok, value)

    # ------------------------------------------------------------------ execute stages
    def stage(self, st: ast.Subcommand, ctx: Context) -> list[Context]:
        """The contexts one stage makes from one context."""
        if isinstance(st, ast.Condition):
            return [ctx] if self.condition(st, ctx) else []
        if world_entities.is_world_stage(st):
            return _entities(world_entities.stage, self.state, st, ctx)
        if isinstance(st, ast.StoreData):
            return [ctx]
        if isinstance(st, ast.ExIn):
            return [replace(ctx, dimension=st.dimension)]
        if isinstance(st, (ast.ExAnchored, ast.ExAlign, ast.ExPositioned, ast.ExRotated, ast.ExFacing)):
            return [_context(_SOURCE_MODIFIERS[type(st)](_source(ctx), st), ctx)]
        self.warn(st, f"'{type(st).__name__}' is not emulated: the context is kept unchanged")
        return [ctx]

    def condition(self, st: ast.Subcommand, ctx: Context) -> bool:
        return (self.condition_count(st, ctx) > 0) != st.negated

    def condition_count(self, st: ast.Subcommand, ctx: Context) -> int:
        """What an ``if`` test counts (0: it fails): 1 for scores, the entities of ``if entity``,
        the matches of ``if data``, the blocks of ``if blocks``."""
        if isinstance(st, ast.IfScoreMatches):
            value = self.score_of(st.target, st.objective, ctx)
            return int(value is not None and st.range.contains(value))
        if isinstance(st, ast.IfScore):
            a = self.score_of(st.target, st.objective, ctx)
            b = self.score_of(st.source, st.source_objective, ctx)
            return int(a is not None and b is not None and _COMPARE[st.op](a, b))
        if isinstance(st, ast.IfData) and isinstance(st.source, ast.StorageData):
            return _world(nbt_ops.count_matching, self.storage(st.source, create=False), st.path)
        if world_entities.is_world_condition(st):
            return _entities(world_entities.condition_count, self.state, st, ctx)
        raise HostFailure(f"'{type(st).__name__}' is not supported yet", report=True)

    def score_of(self, holder, objective: str, ctx: Context) -> int | None:
        self.objective(objective)
        return self.state.scoreboard.get(self.holder(holder, ctx), objective)

    # ------------------------------------------------------------------ final commands
    def command(self, cmd: ast.Command, ctx: Context) -> int:
        if world_entities.is_world_command(cmd):
            return _entities(world_entities.command, self.state, cmd, ctx, self.warn)
        handler = _HANDLERS.get(type(cmd))
        if handler is None:
            self.warn(cmd, f"'{getattr(cmd, 'name', type(cmd).__name__)}' is not emulated: it succeeds without effect")
            return 1
        return handler(self, cmd, ctx)

    def warn(self, node, message: str) -> None:
        key = (node.loc.path, node.loc.line, node.loc.col)
        if key not in self._warned:
            self._warned.add(key)
            self.report(message, "warning")

    def holders(self, holder, ctx: Context) -> list[str]:
        """ScoreHolderArgument.getNamesWithDefaultWildcard: names, ``*``, or a selector's entities."""
        if isinstance(holder, ast.NameTarget):
            return [holder.name]
        if isinstance(holder, ast.Wildcard):
            names = self.state.scoreboard.tracked_holders()
            if not names:
                raise HostFailure("No relevant score holders could be found")
            return names
        return _entities(world_entities.holder_names, self.state, holder, ctx)

    def holder(self, holder, ctx: Context) -> str:
        """ScoreHolderArgument.getName (one holder: ``get``, ``if score``, ``list``): the first name;
        its ``*`` has an empty default, so ``*`` fails there."""
        if isinstance(holder, ast.Wildcard):
            raise HostFailure("No relevant score holders could be found")
        return self.holders(holder, ctx)[0]

    def objective(self, name: str, writable: bool = False) -> int:
        sb = self.state.scoreboard
        if not sb.exists(name):
            raise HostFailure(f"Unknown scoreboard objective '{name}'", report=True)
        if writable and not sb.is_writable(name):
            raise HostFailure(f"Objective '{name}' is read-only", report=True)
        return sb.objective_ids[name]

    def storage(self, target: ast.DataTarget, create: bool) -> Compound:
        """The compound of ``storage ID`` (CommandStorage: a missing id reads as empty)."""
        if not isinstance(target, ast.StorageData):
            raise HostFailure("entity and block data are not emulated yet", report=True)
        root = self.state.storage.get(target.id)
        if root is None:
            root = Compound()
            if create:
                self.state.storage[target.id] = root
        return root

    def function_exists(self, function: str, is_tag: bool) -> None:
        if function not in (self.tags if is_tag else self.functions):
            raise HostFailure(f"Unknown function {'#' if is_tag else ''}{function}", report=True)


# ---------------------------------------------------------------------- handlers
def _say(host: Host, cmd: ast.Say, ctx: Context) -> int:
    message = text_components.say_text(cmd.message, lambda sel: _entities(world_entities.select, host.state, sel, ctx))
    host.state.broadcast("say", f"[{_sender_name(host, ctx)}] {message}", cmd.loc)
    return 1


def _tellraw(host: Host, cmd: ast.Tellraw, ctx: Context) -> int:
    def select(target) -> list:
        return _entities(world_entities.select, host.state, target, ctx)

    finder = text_components.finder(world_entities.parse_target, select)
    return _world(text_components.tellraw_command, host.state, cmd, select(cmd.targets), finder)


def _gamerule(host: Host, cmd: ast.Gamerule, ctx: Context) -> int:
    rules = host.state.gamerules
    if cmd.value is not None:
        rules.set(cmd.rule, cmd.value)
        value = cmd.value
    else:
        value = rules.get(cmd.rule)
        if value is None:
            raise HostFailure(f"Unknown game rule '{cmd.rule}'", report=True)
    return int(value == "true") if value in ("true", "false") else int(value)


def _schedule(host: Host, cmd: ast.Schedule, ctx: Context) -> int:
    """ScheduleCommand: the result is floorMod(due time, Integer.MAX_VALUE)."""
    host.function_exists(cmd.function, cmd.is_tag)
    if cmd.ticks <= 0:
        raise HostFailure("Can't schedule for current tick", report=True)
    due = host.state.schedule.schedule(cmd.function, cmd.is_tag, cmd.ticks, cmd.mode, host.state.gametime)
    return due % INT_MAX


def _schedule_clear(host: Host, cmd: ast.ScheduleClear, ctx: Context) -> int:
    removed = host.state.schedule.clear(cmd.function, cmd.is_tag)
    if removed == 0:
        raise HostFailure(f"No schedules with id {'#' if cmd.is_tag else ''}{cmd.function}")
    return removed


def _time(host: Host, cmd: ast.Time, ctx: Context) -> int:
    return server_commands.time_command(host.state, cmd)


def _random(host: Host, cmd: ast.RandomCommand, ctx: Context) -> int:
    return _world(server_commands.random_command, host.state, cmd, _sender_name(host, ctx))


def _trigger(host: Host, cmd: ast.Trigger, ctx: Context) -> int:
    host.objective(cmd.objective)
    return _world(server_commands.trigger_command, host.state, cmd, world_entities.executor(host.state, ctx))


def _bossbar(host: Host, cmd: ast.Bossbar, ctx: Context) -> int:
    players = None
    if cmd.targets is not None:  # EntityArgument.getOptionalPlayers: none found is not an error
        found = _entities(world_entities.select, host.state, cmd.targets, ctx)
        players = [e.player_name for e in found if e.is_player]
    return _world(bossbars.bossbar_command, host.state.bossbars, cmd, players)


def _ride(host: Host, cmd: ast.Ride, ctx: Context) -> int:
    riders = _entities(world_entities.select, host.state, cmd.target, ctx)
    vehicles = [] if cmd.vehicle is None else _entities(world_entities.select, host.state, cmd.vehicle, ctx)
    return _world(relations.ride_command, cmd, riders, vehicles)


def _sender_name(host: Host, ctx: Context) -> str:
    """CommandSourceStack.getDisplayName: the executor's name, or "Server"."""
    entity = world_entities.executor(host.state, ctx)
    return "Server" if entity is None else entity.display_name


def _objectives_add(host: Host, cmd: ast.ObjectivesAdd, ctx: Context) -> int:
    sb = host.state.scoreboard
    if not sb.add_objective(cmd.objective, cmd.criterion, cmd.display_name):
        raise HostFailure("An objective already exists by that name")
    return int(sb.alive.sum())


def _objectives_remove(host: Host, cmd: ast.ObjectivesRemove, ctx: Context) -> int:
    host.objective(cmd.objective)
    sb = host.state.scoreboard
    sb.remove_objective(cmd.objective)
    return int(sb.alive.sum())


def _objectives_other(host: Host, cmd, ctx: Context) -> int:
    if getattr(cmd, "objective", None) is not None:
        host.objective(cmd.objective)
    return 0


def _players_set(host: Host, cmd: ast.ScoreSet, ctx: Context) -> int:
    host.objective(cmd.objective, writable=True)
    sb = host.state.scoreboard
    total = 0
    names = host.holders(cmd.targets, ctx)
    for name in names:
        if cmd.action == "set":
            value = cmd.value
        else:
            old = sb.get(name, cmd.objective) or 0
            value = host.arith(cmd.action, old, cmd.value, old + cmd.value if cmd.action == "add" else old - cmd.value)
        sb.set(name, cmd.objective, value)
        total += value
    return wrap32(cmd.value * len(names)) if cmd.action == "set" else wrap32(total)


def _players_reset(host: Host, cmd: ast.ScoreReset, ctx: Context) -> int:
    if cmd.objective is not None:
        host.objective(cmd.objective)
    names = host.holders(cmd.targets, ctx)
    for name in names:
        host.state.scoreboard.reset(name, cmd.objective)
    return len(names)


def _players_get(host: Host, cmd: ast.ScoreGet, ctx: Context) -> int:
    host.objective(cmd.objective)
    name = host.holder(cmd.target, ctx)
    value = host.state.scoreboard.get(name, cmd.objective)
    if value is None:
        raise HostFailure(f"Can't get value of {cmd.objective} for {name}; none is set")
    return value


def _players_operation(host: Host, cmd: ast.ScoreOperation, ctx: Context) -> int:
    host.objective(cmd.objective, writable=True)
    host.objective(cmd.source_objective)
    sb = host.state.scoreboard
    targets = host.holders(cmd.targets, ctx)
    sources = host.holders(cmd.sources, ctx)
    total = 0
    for t in targets:
        for s in sources:
            a = _get_or_create(sb, t, cmd.objective)
            b = _get_or_create(sb, s, cmd.source_objective)
            if cmd.op == "><":
                sb.set(s, cmd.source_objective, a)
                sb.set(t, cmd.objective, b)
                continue
            if cmd.op in ("/=", "%=") and b == 0:
                raise HostFailure("Cannot divide by zero", report=True)
            sb.set(t, cmd.objective, host.arith(cmd.op, a, b, _OPERATIONS[cmd.op](a, b)))
        total += sb.get(t, cmd.objective)
    return wrap32(total)


def _objectives_list(host: Host, cmd: ast.ObjectivesList, ctx: Context) -> int:
    return int(host.state.scoreboard.alive.sum())


def _players_list(host: Host, cmd: ast.ScoreList, ctx: Context) -> int:
    """The number of holders tracked, or of one holder's scores."""
    sb = host.state.scoreboard
    if cmd.target is None:
        return len(sb.tracked_holders())
    name = host.holder(cmd.target, ctx)
    return sum(1 for objective in sb.objectives if sb.get(name, objective) is not None)


def _players_enable(host: Host, cmd: ast.ScoreEnable, ctx: Context) -> int:
    names = host.holders(cmd.targets, ctx)
    host.objective(cmd.objective)
    return _world(server_commands.enable_command, host.state, names, cmd.objective)


def _players_display(host: Host, cmd: ast.ScoreDisplay, ctx: Context) -> int:
    return _world(server_commands.display_command, host.state, cmd, lambda holder: host.holders(holder, ctx),
                  host.objective)


def _data_get(host: Host, cmd: ast.DataGet, ctx: Context) -> int:
    root = host.storage(cmd.target, create=False)
    if cmd.path is None:
        return 1
    if cmd.scale is None:
        return _world(stores.data_get, root, cmd.path)
    return _world(stores.data_get_scaled, root, cmd.path, cmd.scale)


def _data_merge(host: Host, cmd: ast.DataMerge, ctx: Context) -> int:
    return _world(nbt_ops.data_merge, host.storage(cmd.target, create=True), cmd.nbt)


def _data_modify(host: Host, cmd: ast.DataModify, ctx: Context) -> int:
    values = _source_values(host, cmd.source)
    return _world(nbt_ops.modify, host.storage(cmd.target, create=True), cmd.path, cmd.mode, values, cmd.index)


def _data_remove(host: Host, cmd: ast.DataRemove, ctx: Context) -> int:
    return _world(nbt_ops.data_remove, host.storage(cmd.target, create=True), cmd.path)


def _source_values(host: Host, source) -> list:
    """The tags a ``data modify`` source gives (copies, so the target never aliases them)."""
    if isinstance(source, ast.SourceValue):
        return [source.value]
    root = host.storage(source.source, create=False)
    values = [root] if source.path is None else _world(nbt_ops.get, root, source.path)
    if isinstance(source, ast.SourceString):
        return _world(nbt_ops.string_source, values, source.start, source.end)
    return [nbt_ops.copy_tag(v) for v in values]


def _entities(operation, *args):
    """Run a :mod:`emulator.commands.entities` operation; its failures are this command's failures."""
    try:
        return operation(*args)
    except world_entities.WorldCommandError as failure:
        raise HostFailure(failure.message, failure.report) from None


def _world(operation, *args):
    """Run a world-library operation; its failures are this command's failures."""
    try:
        return operation(*args)
    except WorldFailure as failure:
        raise HostFailure(failure.message) from None


def _get_or_create(sb, holder: str, objective: str) -> int:
    value = sb.get(holder, objective)
    if value is None:
        sb.set(holder, objective, 0)
        return 0
    return value


def _source(ctx: Context) -> Source:
    """The world library's view of a context (its float32 rotation and local-coordinate math)."""
    return Source(pos=ctx.pos, yaw=np.float32(ctx.rot[0]), pitch=np.float32(ctx.rot[1]), anchor=ctx.anchor)


def _context(source: Source, ctx: Context) -> Context:
    return replace(ctx, pos=tuple(source.pos), rot=(float(source.yaw), float(source.pitch)), anchor=source.anchor)


_SOURCE_MODIFIERS = {
    ast.ExAnchored: lambda src, st: src.with_anchor(st.anchor),
    ast.ExAlign: lambda src, st: src.aligned(st.axes),
    ast.ExPositioned: lambda src, st: src.positioned(st.pos),  # also resets the anchor to the feet
    ast.ExRotated: lambda src, st: src.with_rotation(*src.rotation_of(st.rot)),
    ast.ExFacing: lambda src, st: src.facing_position(src.position_of(st.pos)),
}


_OPERATIONS = {  # exact results; Host.arith wraps them (floorDiv's MIN / -1 included)
    "=": lambda a, b: b,
    "+=": lambda a, b: a + b,
    "-=": lambda a, b: a - b,
    "*=": lambda a, b: a * b,
    "/=": lambda a, b: a // b,
    "%=": floor_mod,
    "<": min,
    ">": max,
}
_COMPARE = {
    "<": lambda a, b: a < b, "<=": lambda a, b: a <= b, "=": lambda a, b: a == b,
    ">=": lambda a, b: a >= b, ">": lambda a, b: a > b,
}
_HANDLERS = {
    ast.Say: _say,
    ast.Tellraw: _tellraw,
    ast.Gamerule: _gamerule,
    ast.Schedule: _schedule,
    ast.ScheduleClear: _schedule_clear,
    ast.Time: _time,
    ast.RandomCommand: _random,
    ast.Trigger: _trigger,
    ast.Bossbar: _bossbar,
    ast.Ride: _ride,
    ast.ObjectivesAdd: _objectives_add,
    ast.ObjectivesRemove: _objectives_remove,
    ast.ObjectivesModify: _objectives_other,
    ast.ObjectivesSetdisplay: _objectives_other,
    ast.ObjectivesList: _objectives_list,
    ast.ScoreList: _players_list,
    ast.ScoreDisplay: _players_display,
    ast.ScoreSet: _players_set,
    ast.ScoreReset: _players_reset,
    ast.ScoreGet: _players_get,
    ast.ScoreOperation: _players_operation,
    ast.ScoreEnable: _players_enable,
    ast.DataGet: _data_get,
    ast.DataMerge: _data_merge,
    ast.DataModify: _data_modify,
    ast.DataRemove: _data_remove,
}
