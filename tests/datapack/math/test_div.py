"""pool:math/div_round: quotients rounded half away from zero (mirror-symmetric)."""
from tests.datapack.math.rounding import round_half_away


def test_div_round_halves_away_from_zero(board):
    for a, b in [(7, 2), (-7, 2), (6, 4), (-6, 4), (5, 7), (-5, 7), (2_000_000_000, 3), (0, 9)]:
        board.set_score("$a", "pool.math", a)
        board.set_score("$b", "pool.math", b)
        board.call("pool:math/div_round")
        assert board.score("$out", "pool.math") == round_half_away(a, b), (a, b)
