"""Swept (continuous) collision tests of the event search (pool:physics/detect/sweep/*) on the
emulator's both backends, and a ball at 10 m/s that does not tunnel through another."""
import math
import random

import numpy as np
import pytest

from poolgame.physics.constants import CORNER_OPENING, SIDE_OPENING_HALF
from tests.datapack.pool_world import BACKENDS, TWO_R, PoolWorld, shoot, table

CONTACT = TWO_R + 20   # $contact: the sweep reports contacts 20 um early (pool:physics/detect/sweep/pair)
NO_EVENT = 10001


@pytest.fixture(scope="module", params=BACKENDS)
def board(request):
    return PoolWorld(request.param)


def set_chord(board, who, start, end):
    for name, value in zip(("bx", "bz", "ex", "ez"), (*start, *end)):
        board.set_score(f"#sweep.{who}.{name}", "pool.tmp", int(value))


def exact_contact_fraction(a0, a1, b0, b1):
    d0 = np.subtract(b0, a0, dtype=float)
    d = np.subtract(b1, b0, dtype=float) - np.subtract(a1, a0, dtype=float)
    a, b, c = d @ d, 2 * d0 @ d, d0 @ d0 - CONTACT**2
    disc = b * b - 4 * a * c
    if a == 0 or disc < 0:
        return None
    f = (-b - math.sqrt(disc)) / (2 * a)
    if f > 1 or d0 @ d >= 0:
        return None
    return max(f, 0.0)


def chords():
    rng = random.Random(2)
    fixed = [((0, 0), (500000, 0), (300000, 0), (300000, 0)),          # head-on, 10 m/s
             ((0, 0), (200000, 0), (150000, 40000), (150000, 40000)),  # cut
             ((0, 0), (100000, 0), (60000, 57000), (60000, 57000)),    # nearly grazing
             ((0, 0), (0, 0), (200000, 0), (-100000, 0)),              # the other one moves
             ((0, 0), (100000, 0), (-200000, 0), (-200000, 0))]       # moving away
    drawn = []
    for _ in range(150):
        a0 = (rng.randint(0, 2_000_000), rng.randint(0, 1_000_000))
        b0 = (a0[0] + rng.randint(-400000, 400000), a0[1] + rng.randint(-200000, 200000))
        a1 = (a0[0] + rng.randint(-500000, 500000), a0[1] + rng.randint(-500000, 500000))
        b1 = (b0[0] + rng.randint(-100000, 100000), b0[1] + rng.randint(-100000, 100000))
        if math.dist(a0, b0) > CONTACT:
            drawn.append((a0, a1, b0, b1))
    return fixed + drawn


def test_pair_sweep_finds_the_first_contact(board):
    hits = 0
    for a0, a1, b0, b1 in chords():
        set_chord(board, "a", a0, a1)
        set_chord(board, "b", b0, b1)
        board.call("pool:physics/detect/sweep/pair")
        f = board.score("#sweep.f", "pool.tmp")
        expected = exact_contact_fraction(a0, a1, b0, b1)
        if expected is None:
            assert f == NO_EVENT, (a0, a1, b0, b1)
            continue
        hits += 1
        assert f != NO_EVENT, (a0, a1, b0, b1)
        # centre distance at the reported fraction: 2R .. 2R + 0.2 mm
        t = f / 10000
        pa = np.add(a0, t * np.subtract(a1, a0))
        pb = np.add(b0, t * np.subtract(b1, b0))
        assert 0 <= np.linalg.norm(pb - pa) - TWO_R <= 200, (a0, a1, b0, b1, f, expected)
    assert hits >= 10


@pytest.mark.parametrize("start,end,rail,pocket", [
    ((100000, 600000), (0, 650000), 1, 0),
    ((2400000, 600000), (2600000, 600000), 2, 0),
    ((800000, 60000), (820000, 0), 3, 0),
    ((800000, 1200000), (800000, 1300000), 4, 0),
    ((60000, 60000), (0, 0), 1, 1),                       # corner, crossing the left line first
    ((1270000, 100000), (1270000, 0), 3, 1),              # side pocket
    ((1270000 + 70000, 100000), (1270000 + 70000, 0), 3, 0),
    ((600000, 600000), (700000, 650000), 0, 0),           # stays inside
])
def test_rail_sweep(board, start, end, rail, pocket):
    set_chord(board, "a", start, end)
    board.call("pool:physics/detect/sweep/rails")
    assert board.score("#sweep.rail", "pool.tmp") == rail
    assert board.score("#sweep.pocket", "pool.tmp") == pocket
    if rail:
        axis, line = [(0, 28575), (0, 2540000 - 28575), (1, 28575), (1, 1270000 - 28575)][rail - 1]
        f = board.score("#sweep.rf", "pool.tmp") / 10000
        crossing = start[axis] + f * (end[axis] - start[axis])
        assert abs(crossing - line) <= 1 + abs(end[axis] - start[axis]) / 10000


def test_pocket_openings_match_the_reference_constants():
    assert CORNER_OPENING * 1e6 == 90000 and SIDE_OPENING_HALF * 1e6 == 65000


def test_no_tunnelling_at_ten_metres_per_second():
    # cue speed 6.5 m/s gives the ball ~10 m/s: 0.5 m per tick, the object ball 7 diameters away
    board = table([(635000, 635000), (1035000, 635000)])
    shoot(board, angle=0, speed=6500)
    assert board.ball_score(0, "pool.vx") >= 490000
    board.tick()
    assert board.ball_score(1, "pool.vx") > 400000          # hit within the first tick
    assert board.ball_score(1, "pool.x") - board.ball_score(0, "pool.x") >= TWO_R
