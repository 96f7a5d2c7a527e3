"""The cue strike (pool:cue/strike) against the float reference, with the design notes'
thresholds: ball speed 0.1 %, spin 0.5 %, on a simulated player standing in for the cue ball."""
import math

import numpy as np
import pytest

from poolgame.physics.cue import Shot, strike
from tests.datapack.pool_world import A, UM_PER_TICK, board_with, vector


SHOTS = [  # angle (centidegrees), cue speed (mm/s), tip_x, tip_y (per mille of R), elevation
    (0, 3000, 0, 0, 0),
    (3000, 2000, 0, 400, 0),
    (-12000, 4500, 300, -300, 0),
    (27500, 1000, -250, 100, 1500),
    (9000, 6500, 0, -450, 500),
    (4500, 2500, 400, 0, 3000),
]


@pytest.mark.parametrize("angle,speed,tip_x,tip_y,elevation", SHOTS)
def test_cue_strike_matches_reference(angle, speed, tip_x, tip_y, elevation):
    board = board_with(x=600000, z=600000, vx=0, vz=0, wx=0, wz=0, wy=0)
    for name, value in zip(("angle", "speed", "tip_x", "tip_y", "elevation"),
                           (angle, speed, tip_x, tip_y, elevation)):
        board.set_score(f"$shot.{name}", "pool.game", value)
    board.call("pool:cue/strike", as_=A)
    v, w, wy = strike(Shot(math.radians(angle / 100), speed / 1000, tip_x / 1000, tip_y / 1000,
                           math.radians(elevation / 100)))
    v, w, wy = v * UM_PER_TICK, w * UM_PER_TICK, wy * UM_PER_TICK
    mine_v, mine_w = vector(board, "vx", "vz"), vector(board, "wx", "wz")
    assert np.linalg.norm(mine_v - v) <= 1e-3 * np.linalg.norm(v) + 1
    spin = math.sqrt(w @ w + wy * wy)
    spin_error = math.sqrt(((mine_w - w) ** 2).sum() + (board.score(A, "pool.wy") - wy) ** 2)
    assert spin_error <= 5e-3 * spin + 2
    assert board.score(A, "pool.state") in (1, 2)
