"""The table (pool:table/*): setup racks sixteen balls at the corner; after a scratch the cue ball
goes back on the head spot, unless a ball lies there."""
import pytest

from poolgame.shot import TABLE_CORNER
from tests.datapack.pool_world import assert_on_table_and_apart, play, racked_table, shoot, table


def test_setup_racks_sixteen_balls_apart_at_the_corner():
    board = racked_table()
    assert [board.score(f"$origin.{a}", "pool.game") for a in "xyz"] == [0, 64000, 0]
    assert sorted(e["scores"]["pool.id"] for e in board.emu.entities("@e[tag=pool.ball]")) == list(range(16))
    assert board.emu.entities("@e[type=marker]") == []           # the origin marker is gone
    assert_on_table_and_apart(board, 16)
    assert board.score("$resting", "pool.game") == 1


def scratched(other_ball):
    """A table on which the cue ball went into the corner pocket at (0, 0), another ball at rest at
    ``other_ball`` (um)."""
    board = table([(300000, 300000), other_ball])
    board.listen()
    shoot(board, angle=-13500, speed=2000)
    play(board)
    assert board.ball_score(0, "pool.state") == 3
    return board


def test_pocketed_cue_ball_is_refused_then_spotted_again():
    board = scratched((1905000, 635000))
    shoot(board, angle=0)
    assert any("not on the table" in m for m in board.messages)
    board.call("pool:table/spot_cue")
    assert [board.ball_score(0, f"pool.{k}") for k in ("x", "z", "state")] == [635000, 635000, 0]
    (entity,) = board.emu.entities("@e[tag=pool.ball,scores={pool.id=0}]")
    assert entity["pos"][0] == pytest.approx(TABLE_CORNER[0] + 0.635)  # the display is back on the table
    assert entity["pos"][2] == pytest.approx(TABLE_CORNER[2] + 0.635)
    shoot(board, angle=0, speed=1000)
    assert board.score("$resting", "pool.game") == 0


def test_cue_ball_is_not_spotted_onto_another_ball():
    board = scratched((650000, 640000))
    board.call("pool:table/spot_cue")
    assert board.ball_score(0, "pool.state") == 3
    assert any("head spot is taken" in m for m in board.messages)
