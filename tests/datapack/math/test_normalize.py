"""pool:math/normalize: unit vector x 10000 and length, mirror-symmetric."""
import math
import random


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
