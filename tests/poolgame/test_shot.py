"""poolgame.shot: what a played shot reports of its balls."""
import numpy as np

from poolgame.shot import _last_changes


def test_a_ball_stopped_at_the_last_tick_that_changed_one_of_its_fields():
    states = [np.array(s) for s in ([[0, 0, 1], [5, 5, 0]], [[1, 0, 1], [5, 5, 0]], [[2, 0, 1], [5, 5, 0]],
                                    [[2, 0, 0], [5, 5, 0]], [[2, 0, 0], [5, 5, 0]])]
    assert _last_changes([0, 7], states) == {0: 3}  # ball 7 never moved; ball 0 came to rest at tick 3
    assert _last_changes([0, 7], states[:1]) == {}
