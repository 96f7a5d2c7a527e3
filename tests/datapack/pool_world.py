"""The pool datapack on `emulator.Emulator` for the tests, with the overflow sanitizer on: every
int32 wrap and every runtime diagnostic fails the test that caused it.

Ball functions run on @s: the unit tests bind @s to a simulated player (its name is its score
holder, `board_with`); the table tests place real ball entities with the pack's own
pool:table/rack/ball (`table`) or rack them with pool:table/setup (`racked_table`), strike
through pool:api/shot (`shoot`) and tick (`play`).
"""
from __future__ import annotations

import numpy as np

from emulator import Emulator
from poolgame.shot import TABLE_CORNER

from tests.datapack.pack_paths import PACK

BACKENDS = ("numba", "python")
BALL_ITEM = "minecraft:white_concrete"
UM_PER_TICK = 1e6 / 20   # um/tick per m/s
TWO_R = 57150            # um
A = "ball_a"             # a simulated player standing in for a ball entity (@s)


class PoolWorld:
    def __init__(self, backend: str = "numba") -> None:
        self.name = backend
        self.emu = Emulator(backend=backend, sanitize=True)
        self.emu.load(PACK)
        self.tick()                                  # the load tick: pool:load creates the objectives
        self._balls: dict[int, str] = {}

    # ------------------------------------------------------------------ running
    def call(self, function: str, as_: str | None = None, arguments: dict | None = None):
        result = self.emu.call(function, as_=as_, at=None if as_ else TABLE_CORNER, arguments=arguments)
        self.check()
        return result

    def tick(self) -> int:
        """One server tick (pool:tick); returns the commands it ran, as the emulator counts them."""
        cost = self.emu.tick()
        self.check()
        return cost

    def check(self) -> None:
        assert not self.emu.overflows, self.emu.overflows[:3]
        assert not self.emu.diagnostics, [d.format() for d in self.emu.diagnostics[:3]]

    # ------------------------------------------------------------------ scores and entities
    def set_score(self, holder: str, objective: str, value: int) -> None:
        self.emu.set_score(holder, objective, value)

    def score(self, holder: str, objective: str) -> int | None:
        return self.emu.score(holder, objective)

    def add_player(self, name: str, rotation=(0.0, 0.0)) -> str:
        return self.emu.add_player(name, TABLE_CORNER, rotation)

    def listen(self) -> None:
        """A player at the table: tellraw @a fails and shows nothing when no player is online
        (as in the game), so tests that read the pack's chat messages need one."""
        self.add_player("Listener")

    @property
    def messages(self) -> list[str]:
        return [entry.text for entry in self.emu.log if entry.kind == "tellraw"]

    def place_balls(self, positions) -> None:
        """Ball i at rest at positions[i] (um, table frame), the table corner at TABLE_CORNER."""
        self.place_balls_with_ids([(i, x, z) for i, (x, z) in enumerate(positions)])

    def place_balls_with_ids(self, placed) -> None:
        """Balls at rest, summoned in the order given: (id, x, z) each (um, table frame)."""
        for axis, value in zip("xyz", TABLE_CORNER):
            self.set_score(f"$origin.{axis}", "pool.game", round(value * 1000))
        for i, x, z in placed:
            self.call("pool:table/rack/ball", arguments={"id": i, "x": x, "z": z, "item": BALL_ITEM})
        self.set_score("$resting", "pool.game", 1)
        self.set_score("$pocketed", "pool.game", 0)

    def ball(self, i: int) -> str:
        """The score holder (UUID) of ball i."""
        if i not in self._balls:
            (entity,) = self.emu.entities(f"@e[tag=pool.ball,scores={{pool.id={i}}}]")
            self._balls[i] = entity["uuid"]
        return self._balls[i]

    def ball_score(self, i: int, objective: str) -> int | None:
        return self.score(self.ball(i), objective)


# ---------------------------------------------------------------------- one ball on a simulated player
def board_with(holder=A, **scores):
    """A world with the simulated player ``holder`` holding ``pool.<name>`` = value for each score."""
    board = PoolWorld()
    board.add_player(holder)
    for name, value in scores.items():
        board.set_score(holder, f"pool.{name}", value)
    return board


def vector(board, x, z, holder=A):
    return np.array([board.score(holder, f"pool.{x}"), board.score(holder, f"pool.{z}")], float)


# ---------------------------------------------------------------------- tables of real balls
def table(positions, backend="numba"):
    board = PoolWorld(backend)
    board.place_balls(positions)
    return board


def racked_table():
    """The pack's own pool:table/setup at the table corner: 16 balls, cue ball (id 0) first."""
    board = PoolWorld()
    board.call("pool:table/setup")
    return board


def shoot(board, angle=0, speed=2000, tip_x=0, tip_y=0, elevation=0):
    board.call("pool:api/shot", arguments=dict(angle=angle, speed=speed, tip_x=tip_x,
                                                 tip_y=tip_y, elevation=elevation))


def play(board, max_ticks=2000):
    """Tick until the table rests; returns the commands run per tick."""
    costs = []
    while board.score("$resting", "pool.game") == 0 and len(costs) < max_ticks:
        costs.append(board.tick())
    return costs


def positions(board, n):
    return np.array([[board.ball_score(i, "pool.x"), board.ball_score(i, "pool.z")] for i in range(n)], float)


def complete(board):
    """The balls' scores hold one moment: no physics tick is carried over to the next game tick
    ($carry pool.game, pool:physics/step: mid-computation, balls are at different times)."""
    return board.score("$carry", "pool.game") != 1


def assert_on_table_and_apart(board, n):
    assert complete(board)
    in_play = [i for i in range(n) if board.ball_score(i, "pool.state") != 3]
    p = positions(board, n)
    for k, i in enumerate(in_play):
        assert 28575 <= p[i][0] <= 2540000 - 28575 and 28575 <= p[i][1] <= 1270000 - 28575, i
        for j in in_play[k + 1:]:
            assert np.linalg.norm(p[i] - p[j]) >= TWO_R - 2, (i, j)
