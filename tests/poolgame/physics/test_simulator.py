"""Whole-shot event-driven simulation: ordering, contact distance, energy, symmetry, pockets."""
import math

import numpy as np
import pytest

from poolgame.physics import ball_ball
from poolgame.physics.ball import AT_REST, POCKETED, Ball
from poolgame.physics.constants import BALL_RADIUS, TABLE_LENGTH, TABLE_WIDTH
from poolgame.physics.cue import Shot, strike
from poolgame.physics.simulator import simulate, simulate_ticks


def shot_ball(position, shot):
    v, w, wy = strike(shot)
    return Ball(position, v, w, wy)


def two_ball_table(shot, object_ball=(1.9, 0.635)):
    return [shot_ball([0.635, 0.635], shot), Ball(list(object_ball))]


def test_no_tunnelling_at_ten_metres_per_second():
    # 0.5 m per tick: the object ball is 8 diameters away but must still be hit
    balls = [Ball([0.3, 0.635], [10.0, 0.0], [10.0, 0.0]), Ball([0.7, 0.635])]
    events = simulate(balls, 0.05)
    assert [e.kind for e in events if e.kind != "transition"][:1] == ["ball"]


def test_contact_distance_is_two_radii_at_every_collision(monkeypatch):
    distances = []
    collide = ball_ball.collide

    def measuring_collide(r_a, v_a, r_b, v_b, restitution=1.0):
        distances.append(np.linalg.norm(np.asarray(r_b) - np.asarray(r_a)))
        return collide(r_a, v_a, r_b, v_b, restitution)

    monkeypatch.setattr(ball_ball, "collide", measuring_collide)
    simulate(two_ball_table(Shot(angle=0.02, speed=3.0, tip_y=0.2)), 30.0)
    assert distances
    assert all(abs(d - 2 * BALL_RADIUS) < 1e-9 for d in distances)


def test_energy_never_rises_tick_to_tick():
    balls = two_ball_table(Shot(angle=0.3, speed=4.0, tip_x=0.2, tip_y=-0.3))
    energies = [sum(b.kinetic_energy() for b in s) for s in simulate_ticks(balls, 200)]
    assert all(b <= a * (1 + 1e-9) for a, b in zip(energies, energies[1:]))
    assert energies[-1] < energies[0]


def test_balls_stay_on_the_table_and_stop():
    balls = two_ball_table(Shot(angle=0.7, speed=5.0, tip_x=-0.3))
    events = simulate(balls, 120.0)
    assert any(e.kind == "cushion" for e in events)
    for ball in balls:
        assert ball.state in (AT_REST, POCKETED)
        if not ball.pocketed:
            assert BALL_RADIUS - 1e-9 <= ball.r[0] <= TABLE_LENGTH - BALL_RADIUS + 1e-9
            assert BALL_RADIUS - 1e-9 <= ball.r[1] <= TABLE_WIDTH - BALL_RADIUS + 1e-9


def test_mirrored_shot_gives_mirrored_result():
    shot = Shot(angle=0.4, speed=3.0, tip_x=0.25, tip_y=0.1)
    mirrored = Shot(angle=-0.4, speed=3.0, tip_x=-0.25, tip_y=0.1)
    a = two_ball_table(shot, (1.6, 0.8))
    b = two_ball_table(mirrored, (1.6, TABLE_WIDTH - 0.8))
    b[0].r[1] = TABLE_WIDTH - b[0].r[1]
    events_a, events_b = simulate(a, 60.0), simulate(b, 60.0)
    assert [e.kind for e in events_a] == [e.kind for e in events_b]
    for ball_a, ball_b in zip(a, b):
        assert ball_b.r == pytest.approx([ball_a.r[0], TABLE_WIDTH - ball_a.r[1]], abs=1e-9)


def test_straight_shot_into_a_corner_pocket():
    direction = np.array([-1.0, -1.0]) / math.sqrt(2)
    balls = [Ball([0.5, 0.5], 2.0 * direction, 2.0 * direction)]
    events = simulate(balls, 10.0)
    assert [e.kind for e in events] == ["pocket"]
    assert balls[0].state == POCKETED


def test_side_pocket_takes_a_ball_sent_straight_at_it():
    balls = [Ball([TABLE_LENGTH / 2, 0.6], [0.0, 1.5], [0.0, 1.5])]
    events = simulate(balls, 10.0)
    assert events[-1].kind == "pocket" and events[-1].rail == "far"


def test_momentum_is_conserved_at_a_collision():
    balls = [Ball([0.5, 0.6], [2.0, 0.1], [2.0, 0.1]), Ball([0.9, 0.62])]
    event = next(e for e in simulate(balls, 5.0) if e.kind == "ball")
    # replay to just before the collision and measure the momentum across it
    balls2 = [Ball([0.5, 0.6], [2.0, 0.1], [2.0, 0.1]), Ball([0.9, 0.62])]
    simulate(balls2, event.time - 1e-9)
    before = balls2[0].v + balls2[1].v
    simulate(balls2, 2e-9)
    after = balls2[0].v + balls2[1].v
    assert after == pytest.approx(before, abs=1e-6)
    assert balls2[1].v @ balls2[1].v > 0
