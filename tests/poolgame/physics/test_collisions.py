"""Ball-ball and ball-cushion collisions (errata 3.x and 4.x)."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from poolgame.physics import ball_ball, cushion
from poolgame.physics.constants import BALL_RADIUS, CUSHION_FRICTION, CUSHION_RESTITUTION

component = st.floats(-10.0, 10.0, allow_nan=False)
angle = st.floats(0.0, 2 * math.pi)


@settings(max_examples=200, deadline=None)
@given(component, component, component, component, angle)
def test_momentum_and_energy_conserved(vax, vaz, vbx, vbz, phi):
    r_a = np.zeros(2)
    r_b = 2 * BALL_RADIUS * np.array([math.cos(phi), math.sin(phi)])
    v_a, v_b = np.array([vax, vaz]), np.array([vbx, vbz])
    va1, vb1 = ball_ball.collide(r_a, v_a, r_b, v_b)
    assert np.allclose(va1 + vb1, v_a + v_b, atol=1e-9)
    assert va1 @ va1 + vb1 @ vb1 == pytest.approx(v_a @ v_a + v_b @ v_b, rel=1e-9, abs=1e-9)


def test_separating_balls_do_not_collide():
    v_a, v_b = np.array([-1.0, 0.0]), np.array([1.0, 0.0])
    va1, vb1 = ball_ball.collide([0, 0], v_a, [2 * BALL_RADIUS, 0], v_b)
    assert np.array_equal(va1, v_a) and np.array_equal(vb1, v_b)


def test_cut_at_45_degrees_splits_energy_equally_at_right_angles():
    d = 2 * BALL_RADIUS / math.sqrt(2)
    va1, vb1 = ball_ball.collide([0, 0], np.array([1.0, 0.0]), [d, d], np.zeros(2))
    assert va1 @ va1 == pytest.approx(0.5) and vb1 @ vb1 == pytest.approx(0.5)
    assert va1 @ vb1 == pytest.approx(0.0, abs=1e-12)
    assert math.degrees(math.atan2(vb1[1], vb1[0])) == pytest.approx(45.0)


def test_head_on_exchanges_velocities():
    va1, vb1 = ball_ball.collide([0, 0], np.array([2.0, 0.0]), [2 * BALL_RADIUS, 0], np.zeros(2))
    assert np.allclose(va1, 0.0) and np.allclose(vb1, [2.0, 0.0])


def test_cushion_reverses_normal_speed_with_restitution():
    v, wy = cushion.rebound(np.array([-2.0, 0.0]), 0.0, np.array([1.0, 0.0]))
    assert v == pytest.approx([2.0 * CUSHION_RESTITUTION, 0.0])
    assert wy == 0.0


def test_cushion_friction_is_capped_by_the_stick_limit():
    # hard into the rail with little slip: (2/7)|s| < mu_c (1+e)|v_n|, so the slip ends
    n = np.array([1.0, 0.0])
    v, wy = cushion.rebound(np.array([-2.0, 0.1]), 0.0, n)
    t_hat = cushion.tangent(n)
    assert v @ t_hat - wy == pytest.approx(0.0, abs=1e-12)


def test_cushion_friction_is_coulomb_below_the_limit():
    n = np.array([0.0, 1.0])
    v0 = np.array([2.0, -1.0])
    v, wy = cushion.rebound(v0, 0.0, n)
    t_hat = cushion.tangent(n)
    dv_t = (v - v0) @ t_hat
    assert abs(dv_t) == pytest.approx(CUSHION_FRICTION * (1 + CUSHION_RESTITUTION) * 1.0)
    assert wy == pytest.approx(-2.5 * dv_t)


@settings(max_examples=200, deadline=None)
@given(component, component, st.floats(-5, 5), st.sampled_from([(1, 0), (-1, 0), (0, 1), (0, -1)]))
def test_cushion_never_adds_energy(vx, vz, wy, normal):
    n = np.array(normal, float)
    v0 = np.array([vx, vz])
    if v0 @ n >= 0:
        v0 = v0 - 2 * (v0 @ n) * n - 0.01 * n  # make it approach the cushion
    v, wy1 = cushion.rebound(v0, wy, n)
    assert v @ v + 0.4 * wy1 * wy1 <= v0 @ v0 + 0.4 * wy * wy + 1e-9


def test_cushion_is_mirror_symmetric():
    n = np.array([1.0, 0.0])
    v, wy = cushion.rebound(np.array([-1.5, 0.7]), 0.3, n)
    vm, wym = cushion.rebound(np.array([-1.5, -0.7]), -0.3, n)
    assert vm == pytest.approx([v[0], -v[1]]) and wym == pytest.approx(-wy)
