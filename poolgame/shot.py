"""One pool shot on the pool datapack in the emulator: set up a table, rack, strike through the
pack's public API (``pool:api/shot``), tick until the table is at rest, and report where every
ball went. ``dpemu shot`` (poolgame/cli.py) prints it; the datapack tests and the bench
drive the same functions.
"""
from __future__ import annotations

import math
import random
import re
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from emulator.api import Emulator
from emulator.world.text import plain_text
from poolgame.trajectory import Trajectory


def _default_pack() -> Path:
    """The pool datapack: package data beside this module once installed (setup.py maps it), else
    the source tree's top-level ``datapack/``."""
    here = Path(__file__).resolve().parent
    installed = here / "datapack"
    return installed if installed.is_dir() else here.parent / "datapack"


DEFAULT_PACK = _default_pack()
TABLE_CORNER = (0.0, 64.0, 0.0)   # where pool:table/setup runs (the playing area's corner)
AT_REST, POCKETED = 0, 3          # pool.state of a ball at rest and of one that left play (pool:load's header)
REQUIRED_FUNCTIONS = ("pool:table/setup", "pool:api/shot")
LISTENER = "dpemu"                # the simulated player who watches (and reads the chat)


# pool:api/shot's macro arguments in player units: the option that gives each, the factor from the
# player's unit to the pack's, and the player's unit.
PLAYER_UNITS = {
    "angle": ("--angle", 100, "degrees"),
    "speed": ("--speed", 1000, "m/s"),
    "tip_x": ("--tip X", 1000, "ball radii"),
    "tip_y": ("--tip Y", 1000, "ball radii"),
    "elevation": ("--elevation", 100, "degrees"),
}
_RANGE_MESSAGE = re.compile(r"\b(angle|speed|tip_x|tip_y|elevation) must be (-?\d+)\.\.(-?\d+)(?: \([^)]*\))?")


def in_player_units(message: str) -> str:
    """A refusal of pool:api/shot ("speed must be 1..6500 (mm/s)") in the units the options take
    ("--speed must be 0.001..6.5 m/s"); other text as it is."""
    def player(m: re.Match) -> str:
        option, factor, unit = PLAYER_UNITS[m.group(1)]
        return f"{option} must be {int(m.group(2)) / factor:g}..{int(m.group(3)) / factor:g} {unit}"
    return _RANGE_MESSAGE.sub(player, message)


@dataclass(frozen=True)
class Shot:
    """A cue shot in player units; ``macro_arguments`` turns it into pool:api/shot's integers."""

    angle: float = 0.0            # degrees, counter-clockwise from the table's +x towards +z
    speed: float = 6.5            # cue speed, m/s
    tip_x: float = 0.0            # tip offset right of centre, fraction of the ball radius
    tip_y: float = 0.0            # tip offset above centre, fraction of the ball radius
    elevation: float = 0.0        # cue butt raised, degrees

    def macro_arguments(self) -> dict[str, int]:
        return {name: round(getattr(self, name) * factor) for name, (_, factor, _) in PLAYER_UNITS.items()}


# The break: full power (the trigger's 100 %) from the head spot straight at the apex ball.
BREAK = Shot(angle=0.0, speed=6.5)


def random_shot(rng: random.Random, k: int) -> Shot:
    """The k-th shot of the overflow sweep: every tenth the break, else any aim, speed up to full
    power, a tip offset inside the miscue limit, a level or raised cue."""
    if k % 10 == 0:
        return BREAK
    # radius 0.499: the tip's components are rounded to 1/1000, which must not pass the limit 0.5
    r, phi = 0.499 * math.sqrt(rng.random()), rng.uniform(0, 2 * math.pi)
    return Shot(angle=rng.uniform(-180, 180), speed=rng.uniform(0.05, 6.5), tip_x=round(r * math.cos(phi), 3),
                tip_y=round(r * math.sin(phi), 3), elevation=rng.choice([0.0, rng.uniform(0, 30)]))


@dataclass
class BallOutcome:
    id: int
    x_mm: float                   # final centre, table frame (from the corner), millimetres
    z_mm: float
    pocketed: bool
    tick: int | None              # pocketed or stopped at this tick (1 = the first after the strike); None: never moved
    moving: bool = False          # still sliding or rolling when the ticks ran out


@dataclass
class ShotResult:
    refused: list[str]            # the pack's chat messages when it refused the shot
    at_rest: bool
    ticks: int
    commands_per_tick: list[int]
    seconds: float                # wall time of the ticks after the strike
    balls: list[BallOutcome] = field(default_factory=list)
    overflows: list = field(default_factory=list)
    diagnostics: list = field(default_factory=list)
    carried: int = 0              # ticks that ended mid physics tick ($carry pool.game: slow motion)
    interrupted: bool = False     # Ctrl-C stopped the ticks; the rest is what was played until then
    trajectory: Trajectory | None = None   # with play(record=True)

    @property
    def commands_mean(self) -> float:
        return sum(self.commands_per_tick) / len(self.commands_per_tick) if self.commands_per_tick else 0.0

    @property
    def commands_max(self) -> int:
        return max(self.commands_per_tick, default=0)

    def to_json(self, trajectory: bool = False) -> dict:
        extra = {"trajectory": self.trajectory.to_json()} if trajectory and self.trajectory is not None else {}
        return {**extra, "refused": self.refused, "at_rest": self.at_rest, "ticks": self.ticks, "carried": self.carried,
                "commands_per_tick": {"mean": self.commands_mean, "max": self.commands_max,
                                      "each": self.commands_per_tick},
                "seconds": self.seconds, "balls": [asdict(b) for b in self.balls],
                "overflows": [o.to_json() for o in self.overflows],
                "diagnostics": [d.to_json() for d in self.diagnostics], "interrupted": self.interrupted}


def missing_functions(emu: Emulator) -> list[str]:
    """The pool API functions the loaded packs lack (empty for a pool datapack)."""
    return [f for f in REQUIRED_FUNCTIONS if f not in emu.packs.functions]


def new_table(pack: str | Path = DEFAULT_PACK, backend: str = "numba", sanitize: bool = False,
              balls: dict[int, tuple[int, int]] | None = None) -> Emulator:
    """An emulator with ``pack`` loaded, its load tick run, a racked table at TABLE_CORNER (or only
    ``balls``: id -> (x, z) um at rest) and a player (LISTENER) watching."""
    emu = Emulator(backend=backend, sanitize=sanitize)
    emu.load(pack)
    if missing_functions(emu):
        return emu
    return _set_up(emu, balls)


def reset_table(emu: Emulator, balls: dict[int, tuple[int, int]] | None = None) -> Emulator:
    """A fresh world on ``emu``'s already loaded and compiled pack (no reparse, no recompile): its
    load tick run and a table at TABLE_CORNER, as :func:`new_table` leaves it. Many shots on one
    emulator start each from here, so that no score or entity of an earlier shot slows the next."""
    emu.new_world()
    return _set_up(emu, balls)


def _set_up(emu: Emulator, balls: dict[int, tuple[int, int]] | None = None) -> Emulator:
    emu.tick()                                         # the load tick
    if balls is None:
        emu.call("pool:table/setup", at=TABLE_CORNER)
    else:
        _place(emu, balls)
    # a player at the table, added after the balls: tellraw @a fails with nobody online (as in
    # the game), and the pack's refusals are read from the chat
    emu.add_player(LISTENER, TABLE_CORNER, gamemode="spectator")
    return emu


def _place(emu: Emulator, balls: dict[int, tuple[int, int]]) -> None:
    """Balls at rest where given (as pool:table/rack places them) on an empty table at TABLE_CORNER."""
    for axis, value in zip("xyz", TABLE_CORNER):
        emu.set_score(f"$origin.{axis}", "pool.game", round(value * 1000))
    for i, (x, z) in balls.items():
        item = "minecraft:white_concrete" if i == 0 else "minecraft:yellow_concrete"
        emu.call("pool:table/rack/ball", at=TABLE_CORNER, arguments={"id": i, "x": x, "z": z, "item": item})
    emu.set_score("$resting", "pool.game", 1)
    emu.set_score("$pocketed", "pool.game", 0)


def ball_holders(emu: Emulator) -> dict[int, str]:
    """Ball id -> its entity's score holder (UUID), found once by selector."""
    return {e["scores"]["pool.id"]: e["uuid"] for e in emu.entities("@e[tag=pool.ball]")}


BALL_FIELDS = ["pool.x", "pool.z", "pool.state"]


def ball_states(emu: Emulator, holders: dict[int, str] | None = None) -> dict[int, tuple[int, int, int]]:
    """Ball id -> (x um, z um, pool.state) from the balls' scores (``holders`` from
    :func:`ball_holders` saves running a selector each time)."""
    holders = holders if holders is not None else ball_holders(emu)
    return _states(holders, emu.score_block(list(holders.values()), BALL_FIELDS))


def _states(holders: dict[int, str], block) -> dict[int, tuple[int, int, int]]:
    """Ball id -> its row of ``block`` (:data:`BALL_FIELDS` of each holder, in ``holders``' order)."""
    return {i: tuple(row) for i, row in zip(holders, block.tolist())}


def strike(emu: Emulator, shot: Shot) -> list[str]:
    """Play ``shot`` through pool:api/shot; returns the refusal messages (empty when struck)."""
    first = len(emu.log)
    result = emu.call("pool:api/shot", arguments=shot.macro_arguments())
    if result == 1:
        return []
    return [plain_text(entry.text) for entry in emu.log[first:] if entry.kind == "tellraw"] or ["the pack refused the shot"]


def play(emu: Emulator, shot: Shot, max_ticks: int = 2000, on_tick=None, record: bool = False) -> ShotResult:
    """Strike and tick until ``$resting pool.game`` is 1 or ``max_ticks`` ran (``on_tick`` hears
    each tick: a progress bar). ``record`` keeps every ball's state after each complete physics
    tick and the events the pack resolved (``ShotResult.trajectory``)."""
    refused = strike(emu, shot)
    holders = ball_holders(emu)
    ids = list(holders)
    read_balls = emu.score_reader(holders.values(), BALL_FIELDS)
    start = read_balls()
    trajectory = Trajectory(emu, holders) if record and not refused else None
    if refused:
        return ShotResult(refused, emu.score("$resting", "pool.game") == 1, 0, [], 0.0,
                          _outcomes(_states(holders, start), {}), list(emu.overflows),
                          list(emu.diagnostics))
    states = [start]  # the balls' fields after the strike and after each tick
    first_tick = len(emu.commands_per_tick)
    started = time.perf_counter()
    at_rest, carried, interrupted, count = False, 0, False, 0
    try:
        for _ in range(max_ticks):
            emu.tick()
            if on_tick is not None:
                on_tick()
            carry = emu.score("$carry", "pool.game") == 1
            carried += carry
            if trajectory is not None:
                count += emu.score("#events.count", "pool.tmp") or 0
                if not carry:
                    trajectory.observe(emu, count)
                    count = 0
            states.append(read_balls())
            if emu.score("$resting", "pool.game") == 1:
                at_rest = True
                break
    except KeyboardInterrupt:  # the summary of the ticks played so far is still worth printing
        interrupted = True
    seconds = time.perf_counter() - started
    costs = emu.commands_per_tick[first_tick:]
    return ShotResult([], at_rest, len(costs), costs, seconds, _outcomes(_states(holders, states[-1]),
                                                                         _last_changes(ids, states)),
                      list(emu.overflows), list(emu.diagnostics), carried, interrupted, trajectory)


def _last_changes(ids: list[int], states: list[np.ndarray]) -> dict[int, int]:
    """Ball id -> the last tick (1 = the first after the strike) that changed one of its fields,
    for the balls that changed: compared once after the shot, not each tick."""
    if len(states) < 2:
        return {}
    changed = (np.diff(np.stack(states), axis=0) != 0).any(axis=2)  # [tick - 1, ball]
    ticks = changed.shape[0] - np.argmax(changed[::-1], axis=0)
    return {ids[row]: int(ticks[row]) for row in np.flatnonzero(changed.any(axis=0)).tolist()}


def _outcomes(states: dict[int, tuple[int, int, int]], last_change: dict[int, int]) -> list[BallOutcome]:
    return [BallOutcome(i, x / 1000, z / 1000, state == POCKETED, last_change.get(i), state not in (AT_REST, POCKETED))
            for i, (x, z, state) in sorted(states.items())]
