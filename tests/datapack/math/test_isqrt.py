"""pool:math/isqrt: the exact floor of the square root over the whole int32 range."""
import math
import random


INT_MAX = 2**31 - 1


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
