"""Cushion rebound, ball-ball collision and cue strike in mcfunction (pool:physics/resolve/..., pool:cue/strike) against the
float reference, with DESIGN.md section 6's thresholds. Run on the emulator (numba, sanitizer on)
with @s a simulated player."""
import math

import numpy as np
import pytest

from poolgame.physics import ball_ball, cushion
from poolgame.physics.cue import Shot, strike
from tests.datapack.pool_world import PoolWorld

UM_PER_TICK = 1e6 / 20
A = "ball_a"     # a simulated player stands in for the ball entity (@s)


def board_with(holder=A, **scores):
    board = PoolWorld()
    board.add_player(holder)
    for name, value in scores.items():
        board.set_score(holder, f"pool.{name}", value)
    return board


def vector(board, x, z, holder=A):
    return np.array([board.score(holder, f"pool.{x}"), board.score(holder, f"pool.{z}")], float)


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


def collide_on_board(r_a, v_a, r_b, v_b):
    board = board_with(x=r_a[0], z=r_a[1], vx=v_a[0], vz=v_a[1])
    for name, value in zip(("x", "z", "vx", "vz"), (*r_b, *v_b)):
        board.set_score(f"#ball_ball.b.{name}", "pool.tmp", value)
    board.call("pool:physics/resolve/ball_ball/collide", as_=A)
    v_b1 = np.array([board.score("#ball_ball.b.vx", "pool.tmp"), board.score("#ball_ball.b.vz", "pool.tmp")])
    return board, vector(board, "vx", "vz"), v_b1


CONTACTS = [  # (angle of the line of centres in degrees, v_a, v_b) in um/tick
    (0.0, (200000, 0), (0, 0)),
    (45.0, (200000, 0), (0, 0)),
    (-30.0, (150000, 20000), (-10000, 5000)),
    (123.4, (-90000, 170000), (3000, -4000)),
    (80.0, (1000, 240000), (0, 0)),
]


@pytest.mark.parametrize("phi,v_a,v_b", CONTACTS)
def test_ball_ball_conserves_momentum_exactly_and_energy_closely(phi, v_a, v_b):
    r_b = (500000 + round(57150 * math.cos(math.radians(phi))),
           500000 + round(57150 * math.sin(math.radians(phi))))
    board, v_a1, v_b1 = collide_on_board((500000, 500000), v_a, r_b, v_b)
    assert board.score("#ball_ball.hit", "pool.tmp") == 1
    assert list(v_a1 + v_b1) == [v_a[0] + v_b[0], v_a[1] + v_b[1]]
    ke0 = np.dot(v_a, v_a) + np.dot(v_b, v_b)
    assert abs(v_a1 @ v_a1 + v_b1 @ v_b1 - ke0) / ke0 <= 1e-3
    ref_a, ref_b = ball_ball.collide(np.array([0.5, 0.5]), np.array(v_a, float),
                                     np.array(r_b) / 1e6, np.array(v_b, float))
    moved = ref_b - np.array(v_b)
    if np.linalg.norm(moved) > 1000:
        mine = v_b1 - np.array(v_b)
        error = math.degrees(abs(math.atan2(mine[1], mine[0]) - math.atan2(moved[1], moved[0])))
        assert error <= 0.1


def test_cut_at_45_degrees_splits_the_energy():
    _, v_a1, v_b1 = collide_on_board((500000, 500000), (200000, 0), (540411, 540411), (0, 0))
    assert abs(v_a1 @ v_a1 - v_b1 @ v_b1) / 4e10 <= 1e-3


def test_separating_balls_are_left_alone():
    board, v_a1, v_b1 = collide_on_board((500000, 500000), (-1000, 0), (557150, 500000), (0, 0))
    assert board.score("#ball_ball.hit", "pool.tmp") == 0
    assert list(v_a1) == [-1000, 0] and list(v_b1) == [0, 0]


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


def touch_shift(v_a, gap):
    """pool:physics/resolve/ball_ball/touch for a at (600000, 600000) with velocity v_a and b at rest 2R + gap
    along +x: a's displacement (um)."""
    board = board_with(x=600000, z=600000, vx=v_a[0], vz=v_a[1])
    for name, value in zip(("x", "z", "vx", "vz"), (600000 + 57150 + gap, 600000, 0, 0)):
        board.set_score(f"#ball_ball.b.{name}", "pool.tmp", value)
    board.call("pool:physics/resolve/ball_ball/touch", as_=A)
    return vector(board, "x", "z") - 600000


def test_contact_shift_closes_the_gap_of_a_head_on_pair():
    # gap 40 um, 10 um kept: a moves 30 um towards b
    assert touch_shift((100000, 0), 40) == pytest.approx([30, 0], abs=1)


def test_contact_shift_is_skipped_for_a_nearly_tangent_pair():
    # closing speed 1000 um/tick against 100000 along the tangent: closing 30 um would carry a
    # 3 mm along its path (into any ball there), so nothing moves
    assert list(touch_shift((1000, 100000), 40)) == [0, 0]
    # |vx| + |vz| = 115000 <= 8 x 15000: it still moves, 100000 x 30 / 15000 = 200 um along z
    shift = touch_shift((15000, 100000), 40)
    assert shift[0] == pytest.approx(30, abs=1) and 0 < shift[1] <= 8 * 30
