"""The server's stopwatches (1.21.11+, ``stopwatch create|query|restart|remove`` and ``execute if
stopwatch``): each one's start, as Stopwatches and Stopwatch keep it (decompiled 1.21.11,
world/Stopwatches.java, world/Stopwatch.java, server/commands/StopwatchCommand.java,
ExecuteCommand.checkStopwatch).

A stopwatch measures real time (Util.getMillis), which the game's ticks do not govern. The
emulator's clock stands for it as a server keeping its 20 ticks a second would: 50 ms for each
server tick run (``state.tick``), so a stopwatch reads 0 within one tick and 1.0 s twenty ticks
after it started; on a real server the same reading varies with its load.

- ``create(state, id)``, ``restart(state, id)``, ``remove(state, id)``: the failures are the game's
  (already exists, does not exist);
- ``elapsed_seconds(state, id)``: Stopwatch.elapsedSeconds (milliseconds / 1000.0);
- ``query(state, id, scale)``: StopwatchCommand.queryStopwatch's result, ``(int)(seconds * scale)``
  (Java's cast: saturated, NaN 0).
"""
from __future__ import annotations

from emulator.world.errors import CommandFailure
from emulator.world.semantics import double_to_int

MS_PER_TICK = 50  # a server at its tick rate of 20


def _now(state) -> int:
    return state.tick * MS_PER_TICK


def _full(stopwatch_id: str) -> str:
    return stopwatch_id if ":" in stopwatch_id else "minecraft:" + stopwatch_id


def create(state, stopwatch_id: str) -> int:
    stopwatch_id = _full(stopwatch_id)
    if stopwatch_id in state.stopwatches:
        raise CommandFailure("commands.stopwatch.already_exists", stopwatch_id)
    state.stopwatches[stopwatch_id] = _now(state)
    return 1


def _existing(state, stopwatch_id: str) -> str:
    stopwatch_id = _full(stopwatch_id)
    if stopwatch_id not in state.stopwatches:
        raise CommandFailure("commands.stopwatch.does_not_exist", stopwatch_id)
    return stopwatch_id


def restart(state, stopwatch_id: str) -> int:
    state.stopwatches[_existing(state, stopwatch_id)] = _now(state)
    return 1


def remove(state, stopwatch_id: str) -> int:
    del state.stopwatches[_existing(state, stopwatch_id)]
    return 1


def elapsed_seconds(state, stopwatch_id: str) -> float:
    return (_now(state) - state.stopwatches[_existing(state, stopwatch_id)]) / 1000.0


def query(state, stopwatch_id: str, scale: float = 1.0) -> int:
    return double_to_int(elapsed_seconds(state, stopwatch_id) * scale)
