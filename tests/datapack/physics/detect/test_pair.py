"""The pair search's immediate contacts (pool:physics/detect/pair/touching, resolved_apart,
separating): a pair that touches at once but does not approach is no event, found again and
again at the same time otherwise. Regressions from racked tables that froze."""
from tests.datapack.pool_world import assert_on_table_and_apart, play, racked_table, shoot


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
