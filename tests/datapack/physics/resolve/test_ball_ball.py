"""Ball-ball collision (pool:physics/resolve/ball_ball/collide) and the contact shift before it
(pool:physics/resolve/ball_ball/touch) against the float reference, on a simulated player
standing in for ball a."""
import math

import numpy as np
import pytest

from poolgame.physics import ball_ball
from tests.datapack.pool_world import A, board_with, vector


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
