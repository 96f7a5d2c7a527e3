"""Scheduled block ticks (the level's LevelTicks for blocks): a block asks to be ticked after a delay
(a pressed button springs back). ``schedule(pos, block_id, delay, gametime, action)``; each server
tick ``run_due(state)`` runs, after the scheduled functions, every tick due by the game time, in
due then scheduling order, and only while the block at ``pos`` is still ``block_id`` (a block tick
of a block that was replaced does nothing: ServerLevel.tickBlock checks the block). Each tick is of a
level: ``action(level, pos)`` gets that level's view (WorldState.level).

Sources (decompiled 1.21): world/ticks/LevelTicks.java (tick: trigger time <= game time, then
priority and insertion order), server/level/ServerLevel.java (tick: tickTime, then blockTicks.tick;
tickBlock).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field


OVERWORLD = "minecraft:overworld"


@dataclass
class BlockTicks:
    # (due game time, order, pos, block id, action(level, pos), level): ``level`` is the dimension
    pending: list = field(default_factory=list)
    order: int = 0

    def schedule(self, pos, block_id: str, delay: int, gametime: int, action: Callable,
                 dimension: str = OVERWORLD) -> None:
        """LevelAccessor.scheduleTick: a tick already pending for that block at ``pos`` stays (no second)."""
        if any(p[2] == tuple(pos) and p[3] == block_id and p[5] == dimension for p in self.pending):
            return
        self.order += 1
        self.pending.append((gametime + delay, self.order, tuple(pos), block_id, action, dimension))

    def copy_area(self, source: str, lo, hi, offset, target: str) -> None:
        """LevelTicks.copyAreaFrom: each tick pending in level ``source`` within the box ``lo``..``hi``
        again at its position moved by ``offset`` in level ``target``, due at the same game time."""
        for due, _, pos, block_id, action, dimension in list(self.pending):
            if dimension == source and all(l <= p <= h for p, l, h in zip(pos, lo, hi)):
                moved = tuple(p + o for p, o in zip(pos, offset))
                if not any(p[2] == moved and p[3] == block_id and p[5] == target for p in self.pending):
                    self.order += 1
                    self.pending.append((due, self.order, moved, block_id, action, target))

    def in_level(self, dimension: str) -> "LevelTicks":
        return LevelTicks(self, dimension)

    def next_due(self) -> int | None:
        """The game time of the next pending block tick, None when none is pending."""
        return min((p[0] for p in self.pending), default=None)

    def run_due(self, state) -> None:
        if not self.pending:  # every tick: nothing pending is the common case
            return
        due = sorted(p for p in self.pending if p[0] <= state.gametime)
        self.pending = [p for p in self.pending if p[0] > state.gametime]
        for _, _, pos, block_id, action, dimension in due:
            if state.blocks_in(dimension).get(pos).id == block_id:
                action(state.level(dimension), pos)


@dataclass
class LevelTicks:
    """One level's block ticks (the ``block_ticks`` of a level view)."""

    ticks: BlockTicks
    dimension: str

    def schedule(self, pos, block_id: str, delay: int, gametime: int, action: Callable) -> None:
        self.ticks.schedule(pos, block_id, delay, gametime, action, self.dimension)

    def next_due(self) -> int | None:
        return self.ticks.next_due()
