"""The shot API (pool:api/shot): a shot out of range, or while the balls move, is refused with a
message and changes nothing."""
import pytest

from tests.datapack.pool_world import shoot, table


def world_snapshot(board):
    """Every score except the pack's temporaries (#... pool.tmp/pool.math), and every entity."""
    scores = {(objective, holder): value for objective, table_ in board.emu.scores().items()
              for holder, value in table_.items() if not holder.startswith("#")}
    return scores, board.emu.entities("@e")


@pytest.mark.parametrize("arguments,reason", [
    (dict(speed=0), "speed"), (dict(speed=-500), "speed"), (dict(speed=7000), "speed"),
    (dict(tip_x=400, tip_y=400), "miscue"), (dict(elevation=9000), "elevation"),
    (dict(tip_y=-600), "tip_y")])
def test_out_of_range_shots_are_refused_without_change(arguments, reason):
    board = table([(635000, 635000)])
    board.listen()
    shot = dict(angle=0, speed=2000, tip_x=0, tip_y=0, elevation=0) | arguments
    before = world_snapshot(board)
    assert board.call("pool:api/shot", arguments=shot) == 0          # return fail
    assert any("refused" in m and reason in m for m in board.messages)
    assert world_snapshot(board) == before


def test_shot_while_moving_is_refused():
    board = table([(635000, 635000)])
    board.listen()
    shoot(board)
    board.tick()
    vx = board.ball_score(0, "pool.vx")
    shoot(board, angle=9000)
    assert any("still moving" in m for m in board.messages)
    assert board.ball_score(0, "pool.vx") == vx
