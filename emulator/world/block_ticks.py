"""Scheduled block ticks (the level's LevelTicks for blocks): a block asks to be ticked after a delay
(a pressed button springs back). ``schedule(pos, block_id, delay, gametime, action)``; each server
tick ``run_due(state)`` runs, after the scheduled functions, every tick due by the game time, in
due then scheduling order, and only while the block at ``pos`` is still ``block_id`` (a block tick
of a block that was replaced does nothing: ServerLevel.tickBlock checks the block).

Sources (decompiled 1.21): world/ticks/LevelTicks.java (tick: trigger time <= game time, then
priority and insertion order), server/level/ServerLevel.java (tick: tickTime, then blockTicks.tick;
tickBlock).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field


@dataclass
class BlockTicks:
    pending: list = field(default_factory=list)  # (due game time, order, pos, block id, action(state, pos))
    order: int = 0

    def schedule(self, pos, block_id: str, delay: int, gametime: int, action: Callable) -> None:
        """LevelAccessor.scheduleTick: a tick already pending for that block at ``pos`` stays (no second)."""
        if any(p[2] == tuple(pos) and p[3] == block_id for p in self.pending):
            return
        self.order += 1
        self.pending.append((gametime + delay, self.order, tuple(pos), block_id, action))

    def next_due(self) -> int | None:
        """The game time of the next pending block tick, None when none is pending."""
        return min((p[0] for p in self.pending), default=None)

    def run_due(self, state) -> None:
        if not self.pending:  # every tick: nothing pending is the common case
            return
        due = sorted(p for p in self.pending if p[0] <= state.gametime)
        self.pending = [p for p in self.pending if p[0] > state.gametime]
        for _, _, pos, block_id, action in due:
            if state.blocks.get(pos).id == block_id:
                action(state, pos)
