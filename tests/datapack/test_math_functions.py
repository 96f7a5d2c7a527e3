"""The pool math library (datapack/data/pool/function/math) run on the emulator's both backends."""
import math
import random

import pytest

from tests.datapack.pool_world import BACKENDS, PoolWorld

INT_MAX = 2**31 - 1


@pytest.fixture(scope="module", params=BACKENDS)
def board(request):
    return PoolWorld(request.param)


def _isqrt_cases():
    rng = random.Random(5)
    cases = {0, 1, 2, 3, INT_MAX, INT_MAX - 1, 2**30, 2**30 - 1}
    for root in [2, 3, 10, 255, 256, 1000, 32767, 32768, 46339, 46340]:
        cases |= {root * root - 1, root * root, root * root + 1}
    for k in range(16):
        cases |= {n for n in (4**k - 1, 4**k, 4**k + 1) if 0 <= n <= INT_MAX}
    cases |= {rng.randrange(INT_MAX) for _ in range(300)}
    cases |= {rng.randrange(10**6) for _ in range(100)}
    return sorted(cases)


def test_isqrt_is_exact_floor(board):
    for n in _isqrt_cases():
        board.set_score("$in", "pool.math", n)
        board.call("pool:math/isqrt")
        assert board.score("$out", "pool.math") == math.isqrt(n), n


def test_isqrt_of_negative_is_zero(board):
    board.set_score("$in", "pool.math", -7)
    board.call("pool:math/isqrt")
    assert board.score("$out", "pool.math") == 0


@pytest.mark.parametrize("a,b", [(123456789, 7071), (-123456789, 7071), (2**30, -10000),
                                 (-1, 5000), (14999, 1), (2_000_000_000, 10000), (999, -9999),
                                 (214700, -10000), (-214700, 9999), (214701, 10000), (46341, 46341)])
def test_mul_unit_rounds_half_away_from_zero(board, a, b):
    board.set_score("$a", "pool.math", a)
    board.set_score("$b", "pool.math", b)
    board.call("pool:math/mul_unit")
    exact = abs(a * b)
    expected = (exact + 5000) // 10000 * (1 if a * b >= 0 else -1)
    assert board.score("$out", "pool.math") == expected


def _vectors():
    rng = random.Random(7)
    fixed = [(3, 4), (1, 0), (0, -1), (1, 1), (-1, 1), (500000, 0), (2**30 - 1, 2**30 - 1),
             (-28575, 57150), (7, -2**29)]
    drawn = [(rng.randint(-2**29, 2**29) // rng.choice([1, 1000, 10**6]),
              rng.randint(-2**29, 2**29) // rng.choice([1, 1000, 10**6])) for _ in range(300)]
    return [v for v in fixed + drawn if v != (0, 0)]


def test_normalize_unit_vector_and_length(board):
    for x, z in _vectors():
        board.set_score("$x", "pool.math", x)
        board.set_score("$z", "pool.math", z)
        board.call("pool:math/normalize")
        length = math.hypot(x, z)
        assert abs(board.score("$ux", "pool.math") - 1e4 * x / length) <= 1.0, (x, z)
        assert abs(board.score("$uz", "pool.math") - 1e4 * z / length) <= 1.0, (x, z)
        assert abs(board.score("$len", "pool.math") - length) <= 1 + 1e-4 * length, (x, z)


def test_normalize_is_mirror_symmetric(board):
    for x, z in _vectors()[:60]:
        results = []
        for sx, sz in [(1, 1), (-1, 1), (1, -1), (-1, -1)]:
            board.set_score("$x", "pool.math", sx * x)
            board.set_score("$z", "pool.math", sz * z)
            board.call("pool:math/normalize")
            results.append((sx * board.score("$ux", "pool.math"),
                            sz * board.score("$uz", "pool.math"), board.score("$len", "pool.math")))
        assert len(set(results)) == 1, (x, z, results)


def test_normalize_zero_vector(board):
    board.set_score("$x", "pool.math", 0)
    board.set_score("$z", "pool.math", 0)
    board.call("pool:math/normalize")
    assert [board.score(h, "pool.math") for h in ("$ux", "$uz", "$len")] == [0, 0, 0]


def test_sincos_error_within_one_and_a_half_units(board):
    worst = 0.0
    for angle in list(range(-36000, 72001, 37)) + [0, 4500, 9000, 13500, 18000, 27000, -9000]:
        board.set_score("$a", "pool.math", angle)
        board.call("pool:math/sincos")
        rad = math.radians(angle / 100)
        worst = max(worst, abs(board.score("$sin", "pool.math") - 1e4 * math.sin(rad)),
                    abs(board.score("$cos", "pool.math") - 1e4 * math.cos(rad)))
    assert worst <= 1.5


@pytest.mark.parametrize("angle,sin,cos", [(0, 0, 10000), (9000, 10000, 0), (18000, 0, -10000),
                                           (27000, -10000, 0), (-9000, -10000, 0)])
def test_sincos_exact_at_right_angles(board, angle, sin, cos):
    board.set_score("$a", "pool.math", angle)
    board.call("pool:math/sincos")
    assert (board.score("$sin", "pool.math"), board.score("$cos", "pool.math")) == (sin, cos)


def test_atan2_error_within_one_centidegree(board):
    rng = random.Random(3)
    worst = 0.0
    for _ in range(800):
        scale = rng.choice([10, 1000, 10**6, 2**29])
        x, z = rng.randint(-scale, scale), rng.randint(-scale, scale)
        if (x, z) == (0, 0):
            continue
        board.set_score("$x", "pool.math", x)
        board.set_score("$z", "pool.math", z)
        board.call("pool:math/atan2")
        out = board.score("$out", "pool.math")
        assert -18000 < out <= 18000
        error = abs(out - 100 * math.degrees(math.atan2(z, x)))
        worst = max(worst, min(error, 36000 - error))
    assert worst <= 1.0


@pytest.mark.parametrize("x,z,expected", [(1, 0, 0), (0, 1, 9000), (-1, 0, 18000), (0, -1, -9000),
                                          (5, 5, 4500), (-5, -5, -13500), (0, 0, 0)])
def test_atan2_axes_and_diagonals(board, x, z, expected):
    board.set_score("$x", "pool.math", x)
    board.set_score("$z", "pool.math", z)
    board.call("pool:math/atan2")
    assert board.score("$out", "pool.math") == expected


def _round_half_away(numerator, denominator):
    q = (abs(numerator) * 2 + denominator) // (2 * denominator)
    return q if numerator >= 0 else -q


def test_mul_1e5_rounds_exactly(board):
    rng = random.Random(11)
    cases = [(21_000_000, 100_000), (-21_000_000, 99_999), (1, 50_000), (-1, 50_000), (0, 7)]
    # both sides of the direct-product path (|a| <= 21474)
    cases += [(21474, 100_000), (-21474, -100_000), (21475, 100_000), (-21475, 99_999), (3, -50_000)]
    cases += [(rng.randint(-21_000_000, 21_000_000), rng.randint(-100_000, 100_000))
              for _ in range(300)]
    cases += [(rng.randint(-21474, 21474), rng.randint(-100_000, 100_000)) for _ in range(200)]
    for a, b in cases:
        board.set_score("$a", "pool.math", a)
        board.set_score("$b", "pool.math", b)
        board.call("pool:math/mul_1e5")
        assert board.score("$out", "pool.math") == _round_half_away(a * b, 100_000), (a, b)


def test_div_round_halves_away_from_zero(board):
    for a, b in [(7, 2), (-7, 2), (6, 4), (-6, 4), (5, 7), (-5, 7), (2_000_000_000, 3), (0, 9)]:
        board.set_score("$a", "pool.math", a)
        board.set_score("$b", "pool.math", b)
        board.call("pool:math/div_round")
        assert board.score("$out", "pool.math") == _round_half_away(a, b), (a, b)
