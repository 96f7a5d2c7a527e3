"""The balls' displays (pool:physics/display/*): item_display entities placed from the table
corner and the balls' scores at the end of each complete physics tick, held still while a tick is
carried over."""
import pytest

from poolgame.shot import BREAK, new_table, reset_table
from tests.datapack.pool_world import shoot, table


def test_displays_follow_the_scores_from_the_table_corner():
    board = table([(635000, 635000)])
    for axis, value in zip("xyz", (100000, 64000, -20000)):      # corner at (100, 64, -20) blocks
        board.set_score(f"$origin.{axis}", "pool.game", value)
    shoot(board, angle=0, speed=1000)
    board.tick()
    (ball,) = board.emu.entities("@e[tag=pool.ball]")
    x, z = board.ball_score(0, "pool.x"), board.ball_score(0, "pool.z")
    assert ball["pos"] == pytest.approx([100 + x // 1000 / 1000, 64 + 28 / 1000, -20 + z // 1000 / 1000])


def test_displays_hold_still_while_a_tick_is_carried_over():
    emu = reset_table(new_table())
    emu.set_score("$budget", "pool.const", 2500)
    emu.call("pool:api/shot", arguments=BREAK.macro_arguments())
    carried = 0
    for _ in range(60):
        before = [e["pos"] for e in emu.entities("@e[tag=pool.ball]")]
        emu.tick()
        if emu.score("$carry", "pool.game") == 1:
            carried += 1
            assert [e["pos"] for e in emu.entities("@e[tag=pool.ball]")] == before
    assert carried >= 5
