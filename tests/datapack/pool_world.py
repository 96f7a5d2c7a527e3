"""The pool datapack on `emulator.Emulator` for the tests, with the overflow sanitizer on: every
int32 wrap and every runtime diagnostic fails the test that caused it.

Ball functions run on @s: the unit tests bind @s to a simulated player (its name is its score
holder); the table tests place real ball entities with the pack's own pool:table/rack/ball.
"""
from __future__ import annotations

from emulator import Emulator
from poolgame.shot import TABLE_CORNER

from tests.datapack.pack_paths import PACK

BACKENDS = ("numba", "python")
BALL_ITEM = "minecraft:white_concrete"


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
        for axis, value in zip("xyz", TABLE_CORNER):
            self.set_score(f"$origin.{axis}", "pool.game", round(value * 1000))
        for i, (x, z) in enumerate(positions):
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
