"""The scenarios: reproducible from the seed, inside the pack's limits, covering the sweeps' ranges."""
import math

from poolgame.score.cases import MAX_CUE_SPEED, R, W, L, cases, mirror
from poolgame.shot import Shot


def test_the_same_seed_gives_the_same_cases_and_another_seed_others():
    assert cases(("motion", "ball-ball"), 3, 5) == cases(("motion", "ball-ball"), 3, 5)
    assert cases(("motion",), 3, 5) != cases(("motion",), 3, 6)


def test_every_shot_is_one_the_pack_accepts_and_every_ball_is_on_the_table():
    for case in cases(("motion", "ball-ball", "cushion", "cue", "shots"), 30, 1):
        if case.shot is not None:
            args = case.shot.macro_arguments()
            assert 1 <= args["speed"] <= MAX_CUE_SPEED * 1000 and 0 <= args["elevation"] <= 8900
            assert args["tip_x"] ** 2 + args["tip_y"] ** 2 <= 250000
        for x, z in (case.balls or {}).values():
            assert R < x < L - R and R < z < W - R, case.name


def test_the_sweeps_reach_their_ranges():
    found = cases(("ball-ball", "cue"), 60, 2)
    cuts = [float(c.name.split("cut ")[1].split(" deg")[0]) for c in found if c.kind == "table"]
    assert min(cuts) < -80 and max(cuts) >= 89
    elevations = [c.shot.elevation for c in found if c.kind == "strike"]
    assert min(elevations) == 0 and max(elevations) >= 89
    tips = [math.hypot(c.shot.tip_x, c.shot.tip_y) for c in found if c.kind == "strike"]
    assert min(t for t in tips if t > 0) <= 0.005


def test_a_mirrored_shot_mirrors_aim_and_side_spin():
    assert mirror(Shot(30, 2, 0.2, -0.1, 5)) == Shot(-30, 2, -0.2, -0.1, 5)
