"""The player controls (pool:controls/*): "/trigger pool.power set P" strikes the cue ball along
the player's view."""
import numpy as np
import pytest

from tests.datapack.pool_world import table


@pytest.mark.parametrize("yaw,direction", [(-90.0, (1, 0)), (0.0, (0, 1)), (90.0, (-1, 0)),
                                           (180.0, (0, -1)), (-45.0, (1, 1))])
def test_trigger_strikes_along_the_players_view(yaw, direction):
    # Minecraft's yaw: 0 faces south (+z), 90 west (-x), -90 east (+x)
    board = table([(1270000, 635000)])
    board.add_player("Steve", rotation=(yaw, 0.0))
    board.set_score("Steve", "pool.power", 40)
    board.tick()
    assert board.score("Steve", "pool.power") == 0
    v = np.array([board.ball_score(0, "pool.vx"), board.ball_score(0, "pool.vz")], float)
    assert np.linalg.norm(v) > 0
    expected = np.array(direction, float) / np.linalg.norm(direction)
    assert np.allclose(v / np.linalg.norm(v), expected, atol=1e-3)
