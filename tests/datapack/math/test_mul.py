"""pool:math/mul_unit and pool:math/mul_1e5: products rounded half away from zero, exact past the
int32 product range."""
import random

import pytest

from tests.datapack.math.rounding import round_half_away


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
        assert board.score("$out", "pool.math") == round_half_away(a * b, 100_000), (a, b)
