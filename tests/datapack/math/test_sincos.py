"""pool:math/sincos: sine and cosine x 10000 of an angle in centidegrees."""
import math

import pytest


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
