"""Cue strike (pool-models 5.5-5.7, errata 5.x)."""
import math

import numpy as np
import pytest

from poolgame.physics.constants import BALL_MASS, BALL_RADIUS, CUE_MASS
from poolgame.physics.cue import Shot, strike


def textbook_speed(v_cue, sin_theta):
    return 2 * v_cue / (1 + BALL_MASS / CUE_MASS + 2.5 * sin_theta**2)


@pytest.mark.parametrize("tip_x,tip_y", [(0, 0), (0.3, 0), (0, -0.4), (0.3, 0.3), (-0.5, 0)])
def test_no_slip_tip_reduces_to_the_textbook_speed(tip_x, tip_y):
    # errata 5.x: with mu = tan(theta) the impulse lies along the cue
    v, w, wy = strike(Shot(angle=0.0, speed=2.0, tip_x=tip_x, tip_y=tip_y))
    expected = textbook_speed(2.0, math.hypot(tip_x, tip_y))
    assert v == pytest.approx([expected, 0.0], abs=1e-12)


def test_top_spin_gives_follow_and_draw_gives_back_spin():
    v, w, _ = strike(Shot(angle=0.0, speed=2.0, tip_y=0.4))
    assert w[0] > 0 and w[1] == pytest.approx(0.0, abs=1e-12)
    v, w, _ = strike(Shot(angle=0.0, speed=2.0, tip_y=-0.4))
    assert w[0] < 0


def test_spin_from_the_angular_impulse():
    # omega = R mu J / I, with J = m_b |v| cos(theta) for mu = tan(theta): |w| = (5/2) |v| sin^2/...
    b = 0.4
    v, w, wy = strike(Shot(angle=0.0, speed=2.0, tip_y=b))
    # the impulse J d/cos(theta) acts at height b R above the centre: L = m |v| b R
    assert np.linalg.norm(w) == pytest.approx(2.5 * b * np.linalg.norm(v), rel=1e-12)
    assert wy == pytest.approx(0.0, abs=1e-12)


def test_side_spin_sign_and_mirror():
    _, _, wy_right = strike(Shot(angle=0.0, speed=2.0, tip_x=0.3))
    _, _, wy_left = strike(Shot(angle=0.0, speed=2.0, tip_x=-0.3))
    assert wy_right == pytest.approx(-wy_left) and wy_right != 0.0
    # aiming +x (east), the right is +z (south); the impulse on the right of centre has torque
    # (R z) x (J x) = +R J y: omega_y > 0, counter-clockwise about +y
    assert wy_right > 0


def test_shot_rotates_with_the_angle():
    v0, w0, _ = strike(Shot(angle=0.0, speed=2.0, tip_y=0.2))
    v1, w1, _ = strike(Shot(angle=math.pi / 2, speed=2.0, tip_y=0.2))
    assert v1 == pytest.approx([0.0, v0[0]], abs=1e-12)
    assert w1 == pytest.approx([0.0, w0[0]], abs=1e-12)


def test_sine_friction_model_undershoots_tan_by_13_percent_at_30_degrees():
    sin_t = 0.5  # theta = 30 degrees
    assert (math.tan(math.asin(sin_t)) - sin_t) / math.tan(math.asin(sin_t)) == pytest.approx(0.134, abs=1e-3)
    v_tan = strike(Shot(angle=0.0, speed=2.0, tip_x=sin_t))
    v_sin = strike(Shot(angle=0.0, speed=2.0, tip_x=sin_t), mu0=1.0)
    assert np.linalg.norm(v_sin[0]) != pytest.approx(np.linalg.norm(v_tan[0]))


def test_energy_is_conserved_at_the_tip():
    # 5.1: cue energy before = cue + ball energy after; the cue keeps v_s1 = v_s0 - J_axis/m_s
    shot = Shot(angle=0.3, speed=2.0)
    v, _, _ = strike(shot)
    speed = np.linalg.norm(v)
    cue_after = 2.0 - BALL_MASS * speed / CUE_MASS
    assert 0.5 * CUE_MASS * 2.0**2 == pytest.approx(
        0.5 * CUE_MASS * cue_after**2 + 0.5 * BALL_MASS * speed**2)


def test_elevation_reduces_the_horizontal_speed_and_adds_masse_spin():
    flat = strike(Shot(angle=0.0, speed=2.0, tip_x=0.3))
    raised = strike(Shot(angle=0.0, speed=2.0, tip_x=0.3, elevation=math.radians(30)))
    assert np.linalg.norm(raised[0]) < np.linalg.norm(flat[0])
    assert abs(raised[1][1]) > 1e-6  # sideways surface velocity: the masse curve


def test_miscue_offset_outside_the_ball_is_refused():
    with pytest.raises(ValueError):
        strike(Shot(angle=0.0, speed=1.0, tip_x=0.8, tip_y=0.8))
