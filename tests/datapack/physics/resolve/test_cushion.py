"""Cushion rebound (pool:physics/resolve/cushion/rebound) against the float reference, with the
design notes' thresholds, on a simulated player standing in for the ball."""
import math

import numpy as np
import pytest

from poolgame.physics import cushion
from tests.datapack.pool_world import A, UM_PER_TICK, board_with, vector


RAIL_NORMALS = [(1, 0), (-1, 0), (0, 1), (0, -1)]


@pytest.mark.parametrize("normal", RAIL_NORMALS)
@pytest.mark.parametrize("v,wy", [((-200000, 30000), 0), ((-50000, -150000), 20000),
                                  ((-300000, 5000), -8000), ((-1000, 400000), 0)])
def test_cushion_matches_reference(normal, v, wy):
    n = np.array(normal, float)
    # express v in the rail's frame so that it approaches this cushion
    t_hat = cushion.tangent(n)
    v_xz = -abs(v[0]) * n + v[1] * t_hat
    board = board_with(x=100000, z=100000, vx=int(v_xz[0]), vz=int(v_xz[1]), wx=0, wz=0, wy=wy)
    board.set_score("#cushion.nx", "pool.tmp", normal[0])
    board.set_score("#cushion.nz", "pool.tmp", normal[1])
    board.call("pool:physics/resolve/cushion/rebound", as_=A)
    v_ref, wy_ref = cushion.rebound(v_xz / UM_PER_TICK, wy / UM_PER_TICK, n)
    mine = vector(board, "vx", "vz")
    assert np.abs(mine - v_ref * UM_PER_TICK).max() <= 2
    assert abs(board.score(A, "pool.wy") - wy_ref * UM_PER_TICK) <= 2
    v_n0 = abs(v[0])
    assert abs(abs(mine @ n) / v_n0 - 0.85) <= 1e-3 + 1 / v_n0   # normal-speed ratio
    angle_ref = math.degrees(math.atan2(v_ref @ t_hat, v_ref @ n))
    angle = math.degrees(math.atan2(mine @ t_hat, mine @ n))
    assert abs(angle - angle_ref) <= 0.25
