"""Pushing apart at the end of a physics tick (pool:physics/resolve/separate/*, run by
pool:physics/events/finish): balls left overlapping are moved to 2R + 10 um, and the balls a push
moved are looked at again."""
import numpy as np

from tests.datapack.pool_world import TWO_R, positions, table


def test_a_push_that_carries_a_ball_into_a_third_is_undone_too():
    # A and B overlap by 100 um and touched this tick; C sits 12 um clear of B: pushing B half the
    # shortfall (55 um) away from A carries it 43 um into C, so the pushed balls are looked at again
    start = [(1000000, 635000), (1000000 + TWO_R - 100, 635000), (1000000 + 2 * TWO_R - 100 + 12, 635000)]
    board = table(start)
    board.call("pool:physics/detect/pair/self", as_=board.ball(0))
    board.call("pool:physics/detect/pair/touching", as_=board.ball(1))
    for name, value in (("#cost.work", 0), ("#events.finishing", 0)):
        board.set_score(name, "pool.tmp", value)
    board.call("pool:physics/events/finish")
    p = positions(board, 3)
    gaps = [np.linalg.norm(p[i + 1] - p[i]) - TWO_R for i in range(2)]
    assert all(0 <= g <= 12 for g in gaps), gaps
    assert p[2][0] > start[2][0]                                   # C was pushed on
