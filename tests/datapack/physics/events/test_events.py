"""The event loop (pool:physics/events/*): the events of a physics tick are resolved in time
order."""
from tests.datapack.pool_world import table


def moving_table(balls):
    """Balls sliding without spin: [((x, z), (vx, vz))], ball i created i-th (the order @e visits)."""
    board = table([r for r, _ in balls])
    for i, (_, (vx, vz)) in enumerate(balls):
        for name, value in dict(state=1, vx=vx, vz=vz, wx=0, wz=0, wy=0).items():
            board.set_score(board.ball(i), f"pool.{name}", value)
        board.call("pool:physics/motion/start", as_=f"@e[tag=pool.ball,scores={{pool.id={i}}}]")
    board.set_score("$resting", "pool.game", 0)
    return board


def test_events_of_one_tick_are_resolved_earliest_first():
    # issue 5: the running minimum `execute as @e ... if score @s pool.nt < #te ... run take` let
    # the last ball visited win (every execute stage runs over all contexts before `run`,
    # 1.20.3+), so the later cushion of ball 1 was resolved before the earlier one of ball 0
    board = moving_table([((2540000 - 28575 - 30000, 635000), (200000, 0)),
                          ((900000, 28575 + 70000), (0, -200000))])
    board.tick()
    times = [board.ball_score(i, "pool.bt") for i in range(2)]     # each ball's event time
    assert board.score("#events.count", "pool.tmp") == 2 and 0 < times[0] < times[1]
    assert board.score("#events.now", "pool.tmp") == times[1]             # the last event resolved is the latest
