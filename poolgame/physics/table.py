"""Table geometry: the four rail lines the ball centre can reach (R inside the cushions) and the
pocket openings on them (a simplified pocket model shared with the datapack)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from poolgame.physics.constants import (BALL_RADIUS, CORNER_OPENING, SIDE_OPENING_HALF,
                                        TABLE_LENGTH, TABLE_WIDTH)


@dataclass(frozen=True)
class Rail:
    name: str
    normal: np.ndarray   # unit, pointing into the table
    offset: float        # the rail line is normal . r = offset
    along: int           # index of the coordinate that runs along the rail
    openings: tuple      # (low, high) intervals of that coordinate where a pocket opens

    def distance(self, r: np.ndarray) -> float:
        return float(self.normal @ r) - self.offset

    def pocketed_at(self, r: np.ndarray) -> bool:
        c = r[self.along]
        return any(low <= c <= high for low, high in self.openings)


def _openings(length: float, side_pocket: bool) -> tuple:
    corners = ((-np.inf, CORNER_OPENING), (length - CORNER_OPENING, np.inf))
    if not side_pocket:
        return corners
    middle = length / 2
    return corners + ((middle - SIDE_OPENING_HALF, middle + SIDE_OPENING_HALF),)


RAILS = (
    Rail("left", np.array([1.0, 0.0]), BALL_RADIUS, 1, _openings(TABLE_WIDTH, False)),
    Rail("right", np.array([-1.0, 0.0]), BALL_RADIUS - TABLE_LENGTH, 1, _openings(TABLE_WIDTH, False)),
    Rail("near", np.array([0.0, 1.0]), BALL_RADIUS, 0, _openings(TABLE_LENGTH, True)),
    Rail("far", np.array([0.0, -1.0]), BALL_RADIUS - TABLE_WIDTH, 0, _openings(TABLE_LENGTH, True)),
)
