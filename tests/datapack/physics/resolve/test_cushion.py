"""Cushion rebound (pool:physics/resolve/cushion/rebound) against the float reference, with the
design notes' thresholds, on a simulated player standing in for the ball."""
import math

import numpy as np
import pytest

from poolgame.physics import cushion
from poolgame.physics.ball import Ball, advance
from poolgame.physics.simulator import _next_event
from tests.datapack.pool_world import A, BACKENDS, UM_PER_TICK, board_with, complete, shoot, table, vector


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


def ball_state(board):
    score = lambda name: board.ball_score(0, f"pool.{name}")
    return Ball(np.array([score("x"), score("z")]) / 1e6, np.array([score("vx"), score("vz")]) / UM_PER_TICK,
                np.array([score("wx"), score("wz")]) / UM_PER_TICK, score("wy") / UM_PER_TICK)


def float_crossing(ball):
    """Where the float takes ``ball`` to its first rail line, and its velocity after the rebound."""
    while True:
        dt, what = _next_event([ball], 10.0)
        advance(ball, dt)
        assert what[0] in ("transition", "rail"), what
        if what[0] == "rail":
            return ball.r * 1e6, cushion.rebound(ball.v, ball.wy, what[2].normal)[0] * UM_PER_TICK


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("approach,speed,tip", [(5, 4000, (300, 200)), (20, 3000, (-350, -200)),
                                                (45, 1500, (0, 0)), (70, 6500, (0, -400))])
def test_a_ball_meets_the_cushion_where_its_path_crosses_the_rail_line(backend, approach, speed, tip):
    # judged at resolution (the state saved at the event, pool.b*) against the float from the ball's
    # integers at the start of the event's tick: the contact point within 20 um along the rail (the
    # chord's crossing, linear in time, left it 0.1..0.56 mm away on sliding paths), the rebound
    # angle within 0.25 degrees and the normal-speed ratio within 1e-3 (DESIGN.md section 6)
    start = [(1270000, 28575 + round(400000 * math.sin(math.radians(approach))))]
    board = table(start, backend)
    shoot(board, angle=-approach * 100, speed=speed, tip_x=tip[0], tip_y=tip[1])
    while True:
        if complete(board):
            before = ball_state(board)
        board.tick()
        if complete(board) and board.ball_score(0, "pool.bvz") > 0:
            break
    crossing, v_ref = float_crossing(before)
    contact = np.array([board.ball_score(0, "pool.bx"), board.ball_score(0, "pool.bz")], float)
    assert contact[1] == 28575
    assert abs(contact[0] - crossing[0]) <= 20, contact - crossing
    v = np.array([board.ball_score(0, "pool.bvx"), board.ball_score(0, "pool.bvz")], float)
    assert abs(math.degrees(math.atan2(v[0], v[1]) - math.atan2(v_ref[0], v_ref[1]))) <= 0.25
    assert abs(v[1] / v_ref[1] - 1) <= 1e-3
