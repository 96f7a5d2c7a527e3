"""poolgame.trajectory: the pack's events read from its saved state after each complete tick."""
from poolgame.shot import Shot, new_table, play


def test_a_two_ball_shot_records_the_contact_and_the_cushions():
    emu = new_table(balls={0: (635_000, 635_000), 1: (1_500_000, 650_000)})
    result = play(emu, Shot(angle=0, speed=2), record=True)
    t = result.trajectory
    assert len(t.ticks) == result.ticks - result.carried
    contact = [e for e in t.events if e.kind == "ball"]
    assert {t.ids[e.ball] for e in contact[:2]} == {0, 1} and contact[0].partner == contact[1].ball
    assert contact[0].time == contact[1].time and 0 < contact[0].fraction < 10_000
    cushions = [e for e in t.events if e.kind == "cushion"]
    assert cushions and all(1 <= e.rail <= 4 for e in cushions)
    assert not t.unseen
    json = result.to_json(trajectory=True)["trajectory"]
    assert len(json["positions_mm"]) == len(t.ticks) + 1 and json["events"][0]["kind"] == "ball"


def test_the_break_marks_the_ticks_whose_events_were_not_all_seen():
    result = play(new_table(), Shot(angle=0, speed=6.5), record=True)
    assert result.trajectory.unseen          # the apex ball meets two balls in one tick
