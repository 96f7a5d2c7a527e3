"""The pair search's immediate contacts (pool:physics/detect/pair/touching, resolved_apart,
separating, recontact): a pair that touches at once but does not approach is no event at once,
found again and again at the same time otherwise (regressions from racked tables that froze); it
becomes one where the two run into each other later in the tick."""
import numpy as np

from tests.datapack.pool_world import (TWO_R, assert_on_table_and_apart, complete, play, positions, racked_table, shoot,
                                       table)


def test_near_tangent_contact_in_the_rack_does_not_freeze_the_table():
    # this shot left ball 4 grazing ball 10: an immediate contact that the sweep reported and the
    # collision found not approaching, again and again at the same time (8 events a tick, for ever)
    board = racked_table()
    shoot(board, angle=-2847, speed=1263, tip_x=-58, tip_y=50)
    costs = play(board, max_ticks=400)
    assert board.score("$resting", "pool.game") == 1
    assert_on_table_and_apart(board, 16)
    assert len(costs) < 400


def test_immediate_contact_rounded_to_now_does_not_freeze_the_table():
    # the sweep put this pair's contact one fraction unit after #now, which rounds to #now: the
    # collision found no approach, the search found it again at the same time, for ever (the
    # physics tick never ended once the rest of a tick was carried over instead of dropped)
    board = racked_table()
    shoot(board, angle=-6088, speed=3081, tip_x=264, tip_y=-241)
    costs = play(board, max_ticks=600)
    assert board.score("$resting", "pool.game") == 1
    assert_on_table_and_apart(board, 16)
    assert len(costs) < 600


def test_a_ball_sliding_into_its_touching_neighbour_passes_the_push_on_by_collisions():
    # a collision stopped ball 0 against ball 1 with its forward spin left (w = 20000 um/tick): it
    # slides into ball 1 from a standstill. Touching without approaching at the tick's start, the
    # pair is no event at once; pool:physics/detect/pair/recontact finds where the two run into each
    # other within the tick, and collisions hand ball 1 momentum. Before, ball 0 overlapped ball 1
    # by 2.45 mm at the tick's end and the push apart left ball 1 without speed.
    board = table([(1000000, 635000), (1000000 + TWO_R + 1, 635000)])
    for name, value in dict(state=1, vx=0, vz=0, wx=20000, wz=0, wy=0).items():
        board.set_score(board.ball(0), f"pool.{name}", value)
    board.call("pool:physics/motion/start", as_=board.ball(0))
    board.set_score("$resting", "pool.game", 0)
    events = 0
    while True:                                         # the first complete physics tick
        board.tick()
        events += board.score("#events.count", "pool.tmp")
        if complete(board):
            break
    p = positions(board, 2)
    assert events >= 2
    assert board.ball_score(1, "pool.vx") > 1000 and board.ball_score(1, "pool.vz") == 0
    assert TWO_R <= np.linalg.norm(p[1] - p[0]) <= TWO_R + 60
