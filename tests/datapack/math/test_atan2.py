"""pool:math/atan2: the angle of a vector in centidegrees, within one centidegree."""
import math
import random

import pytest


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
