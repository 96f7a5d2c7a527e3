"""Pockets through the tick, with real ball entities: pool:physics/detect/sweep/pocket finds the
opening, pool:physics/resolve/pocket takes the ball out of play and reports it."""
import pytest

from poolgame.shot import TABLE_CORNER
from tests.datapack.pool_world import play, shoot, table


def test_ball_sent_into_a_corner_is_pocketed_and_reported():
    board = table([(300000, 300000)])
    board.listen()
    shoot(board, angle=-13500, speed=2000)
    play(board)
    assert board.ball_score(0, "pool.state") == 3
    assert board.score("$pocketed", "pool.game") == 1
    assert board.score("$last_pocketed", "pool.game") == 0
    assert any("pocketed" in m for m in board.messages)
    # its display sits in the ball return (pool:physics/display/tray): 60 mm x the pocketing order
    # along x, 120 mm outside the z = 0 cushion line, both from the table corner
    (entity,) = board.emu.entities("@e[tag=pool.ball,scores={pool.id=0}]")
    assert entity["pos"][0] == pytest.approx(TABLE_CORNER[0] + 0.060)
    assert entity["pos"][2] == pytest.approx(TABLE_CORNER[2] - 0.120)
