"""The issue's command budget (5000 per tick with 16 balls moving) on the emulator's counters,
and the carry-over that keeps it (pool:physics/events/*): a game tick does only the physics work
that fits in $budget pool.const, the rest of the physics tick goes on in the next game tick.
Command counts are deterministic, so they are asserted exactly against the budget."""
from poolgame.shot import BREAK, new_table, play
from tests.datapack.pool_world import play as play_to_rest
from tests.datapack.pool_world import shoot, table

BUDGET = 5000


def outcome(result):
    return [(b.id, b.x_mm, b.z_mm, b.pocketed) for b in result.balls]


def break_with_budget(budget=None):
    emu = new_table(sanitize=True)
    if budget is not None:
        emu.set_score("$budget", "pool.const", budget)
    return emu, play(emu, BREAK)


def test_full_power_break_stays_within_the_budget_every_tick():
    emu, result = break_with_budget()
    assert result.at_rest and not result.overflows and not result.diagnostics
    assert result.commands_max <= BUDGET, result.commands_max
    # the break's burst of events is carried over some ticks, never the whole shot
    assert result.ticks < 2 * 142


def test_carry_over_splits_the_work_without_changing_the_physics():
    _, default = break_with_budget()
    _, ample = break_with_budget(30000)             # (without any budget a break tick passes
    _, tight = break_with_budget(2500)              # the game's 65536-command quota)
    assert outcome(tight) == outcome(default) == outcome(ample)
    assert BUDGET < ample.commands_max < 65536      # the break needs the carry-over
    assert tight.ticks > default.ticks > ample.ticks
    assert tight.commands_max <= 2500 + 1200        # the last step admitted may pass $budget a little


def test_idle_tick_costs_at_most_50_commands():
    board = table([(635000, 635000), (1905000, 640000)])
    board.add_player("Steve")                      # the controls run for every player
    assert board.tick() <= 50


def test_command_cost_per_tick_of_one_rolling_ball():
    board = table([(635000, 635000)])
    shoot(board, angle=1000, speed=1500)
    costs = play_to_rest(board)
    assert max(costs) <= 5000 and sum(costs) / len(costs) <= 500
