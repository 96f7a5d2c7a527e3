"""``spreadplayers``: random columns round a centre, pushed apart until none is closer than the spread
distance to another and each stands on a safe block, then the entities (or teams) put there, as
SpreadPlayersCommand does it.

- ``spread(state, entities, center, distance, max_range, max_height, respect_teams, dimension)``:
  the command's work; returns the number of positions (entities, or teams with ``respect_teams``).
  Raises CommandFailure with the game's messages when 10,000 rounds do not settle (a world with no
  safe column in range: the void, water, fire) or ``max_height`` is under the level's bottom.

The algorithm (decompiled 1.21 server/commands/SpreadPlayersCommand.java): each position starts at
a random point of the square centre +- max range (Mth.nextDouble); each round, a position closer
than the spread distance to others moves one block away from their mean offset (a random point
when that is zero) and is clamped to the square; a round with no move checks each position's
column: the spawn height is the top of the first non-air block, going down from ``max_height``,
with two air blocks over it (``max_height + 1`` when there is none), and the position is safe when
the block under it is below ``max_height``, not a liquid and not fire; an unsafe one is redrawn.
The entities go to the block centres of their columns at the spawn height, in the source's level,
keeping their rotation (Entity.teleportTo), each team of players sharing one position (entities
that are not players count as one team, the null team).

The game draws from a new unseeded random (RandomSource.create()) every time, so where they land is
not reproducible there; the emulator draws from its seeded random: the same rules, other columns.
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import teleport
from emulator.world.blocks import AIR_TYPES
from emulator.world.errors import CommandFailure
from emulator.world.text import java_float_string

MAX_ITERATIONS = 10000
_UNSAFE = frozenset({"minecraft:water", "minecraft:lava", "minecraft:fire", "minecraft:soul_fire"})
_FLOAT_MAX = float(np.finfo(np.float32).max)


class _Position:
    __slots__ = ("x", "z")

    def __init__(self, x: float = 0.0, z: float = 0.0) -> None:
        self.x, self.z = x, z

    def dist(self, other: "_Position") -> float:
        return math.sqrt((self.x - other.x) ** 2 + (self.z - other.z) ** 2)

    def randomize(self, random, lo_x: float, lo_z: float, hi_x: float, hi_z: float) -> None:
        self.x, self.z = _next_double(random, lo_x, hi_x), _next_double(random, lo_z, hi_z)

    def clamp(self, lo_x: float, lo_z: float, hi_x: float, hi_z: float) -> bool:
        moved = False
        if self.x < lo_x or self.x > hi_x:
            self.x, moved = (lo_x if self.x < lo_x else hi_x), True
        if self.z < lo_z or self.z > hi_z:
            self.z, moved = (lo_z if self.z < lo_z else hi_z), True
        return moved


def _next_double(random, lo: float, hi: float) -> float:
    """Mth.nextDouble: ``lo`` when the range is empty."""
    return lo if lo >= hi else random.random() * (hi - lo) + lo


class _Columns:
    """The level's non-air blocks by column (x, z) -> their ys, highest first: the spawn heights
    without walking every y (the command reads hundreds of blocks per column per round)."""

    def __init__(self, blocks) -> None:
        self.blocks = blocks
        self.solid: dict[tuple[int, int], list[int]] = {}
        for (x, y, z), block in blocks.states.items():
            if block.id not in AIR_TYPES:
                self.solid.setdefault((x, z), []).append(y)
        for ys in self.solid.values():
            ys.sort(reverse=True)

    def spawn_y(self, pos: _Position, max_height: int, bottom: int) -> int:
        """Position.getSpawnY: from ``max_height - 1`` down to the bottom, the first non-air block
        with air at the next two (blocks above the build height are air)."""
        column = (math.floor(pos.x), math.floor(pos.z))
        ys = self.solid.get(column, ())
        taken = set(ys)
        for y in ys:
            if bottom <= y < max_height and y + 1 not in taken and y + 2 not in taken:
                return y + 1
        return max_height + 1

    def is_safe(self, pos: _Position, max_height: int, bottom: int) -> bool:
        y = self.spawn_y(pos, max_height, bottom) - 1
        block = self.blocks.get((math.floor(pos.x), y, math.floor(pos.z)))
        return y < max_height and block.id not in _UNSAFE


def _team_count(entities, team_of) -> int:
    return len({team_of(e.score_holder) if e.is_player else None for e in entities})


def spread(state, entities, center, distance: float, max_range: float, max_height: int, respect_teams: bool,
           dimension: str) -> int:
    bottom, _ = state.entities.table.levels.build_height(dimension, state.version)
    if max_height < bottom:
        raise CommandFailure("commands.spreadplayers.failed.invalid.height", max_height, bottom)
    cx, cz = np.float32(center[0]), np.float32(center[1])
    # float arithmetic, then widened (center.x - maxRange: both floats)
    square = (float(cx - np.float32(max_range)), float(cz - np.float32(max_range)),
              float(cx + np.float32(max_range)), float(cz + np.float32(max_range)))
    count = _team_count(entities, state.teams.team_of) if respect_teams else len(entities)
    random = state.resources.random
    positions = [_Position() for _ in range(count)]
    for position in positions:
        position.randomize(random, *square)
    columns = _Columns(state.blocks_in(dimension))
    _settle(positions, float(np.float32(distance)), columns, random, square, max_height, bottom, respect_teams, (cx, cz))
    _place(state, entities, positions, columns, max_height, bottom, respect_teams, dimension)
    return count


def _settle(positions, distance, columns, random, square, max_height, bottom, respect_teams, center) -> None:
    """SpreadPlayersCommand.spreadPositions."""
    unsettled, closest, rounds = True, _FLOAT_MAX, 0
    while rounds < MAX_ITERATIONS and unsettled:
        rounds += 1
        unsettled, closest = False, _FLOAT_MAX
        for j, position in enumerate(positions):
            near, away = 0, _Position()
            for k, other in enumerate(positions):
                if j != k:
                    apart = position.dist(other)
                    closest = min(apart, closest)
                    if apart < distance:
                        near += 1
                        away.x += other.x - position.x
                        away.z += other.z - position.z
            if near > 0:
                away.x /= near
                away.z /= near
                length = math.sqrt(away.x * away.x + away.z * away.z)
                if length > 0.0:
                    position.x -= away.x / length
                    position.z -= away.z / length
                else:
                    position.randomize(random, *square)
                unsettled = True
            if position.clamp(*square):
                unsettled = True
        if not unsettled:
            for position in positions:
                if not columns.is_safe(position, max_height, bottom):
                    position.randomize(random, *square)
                    unsettled = True
    if rounds >= MAX_ITERATIONS:
        closest = 0.0 if closest == _FLOAT_MAX else closest
        key = "commands.spreadplayers.failed." + ("teams" if respect_teams else "entities")
        raise CommandFailure(key, len(positions), java_float_string(center[0]), java_float_string(center[1]), f"{closest:.2f}")


def _place(state, entities, positions, columns, max_height, bottom, respect_teams, dimension) -> None:
    """SpreadPlayersCommand.setPlayerPositions (the average distance it reports is only feedback)."""
    by_team: dict = {}
    taken = iter(positions)
    for entity in entities:
        if respect_teams:
            team = state.teams.team_of(entity.score_holder) if entity.is_player else None
            if team not in by_team:
                by_team[team] = next(taken)
            position = by_team[team]
        else:
            position = next(taken)
        pos = (math.floor(position.x) + 0.5, float(columns.spawn_y(position, max_height, bottom)),
               math.floor(position.z) + 0.5)
        if entity.dimension == dimension:  # Entity.teleportTo in its level: moveTo, its motion kept
            entity.pos = pos
        else:
            teleport.apply(entity, teleport.Destination(pos, entity.yaw, entity.pitch, dimension), state.entities,
                           state.version)
