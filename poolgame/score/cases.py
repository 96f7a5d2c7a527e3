"""The scenarios ``dpemu score`` plays: each model alone swept over its inputs, and whole shots.

A case is either a shot on a table (``balls`` at rest where given, ``None``: the rack) played
through the pack's tick, or one model's function called directly on a simulated ball
(``kind`` "collide", "rebound", "strike"). Every number a case holds is already what the pack
receives (integers in its units, shots as pool:api/shot's rounded arguments), so the float
reference starts from exactly the same input. A random sweep is a function of (model, N, seed).
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

from poolgame.physics.constants import BALL_MASS, BALL_RADIUS, CUE_MASS, TABLE_LENGTH, TABLE_WIDTH
from poolgame.shot import BREAK, Shot, random_shot

R, L, W = round(BALL_RADIUS * 1e6), round(TABLE_LENGTH * 1e6), round(TABLE_WIDTH * 1e6)   # um
HEAD_SPOT = (L // 4, W // 2)
MAX_CUE_SPEED = 6.5             # m/s, pool:api/shot's limit
MAX_TIP = 0.499                 # the miscue limit 0.5, less the rounding of each component to 1/1000


@dataclass(frozen=True)
class Case:
    name: str
    model: str                    # poolgame.score.metrics.MODELS
    kind: str = "table"           # "table", "collide", "rebound", "strike"
    shot: Shot | None = None
    balls: dict | None = None     # id -> (x, z) um; None: the rack
    mirrored: bool = False        # also play the mirror image (z -> W - z) and compare
    inputs: dict = field(default_factory=dict)   # a direct call's scores


def rounded(shot: Shot) -> Shot:
    """The shot as the pack receives it (pool:api/shot's integer arguments)."""
    args = shot.macro_arguments()
    return Shot(args["angle"] / 100, args["speed"] / 1000, args["tip_x"] / 1000, args["tip_y"] / 1000,
                args["elevation"] / 100)


def mirror(shot: Shot) -> Shot:
    return Shot(-shot.angle, shot.speed, -shot.tip_x, shot.tip_y, shot.elevation)


def cue_speed_for(ball_speed: float, tip: float) -> float:
    """The cue speed that gives the ball ``ball_speed`` (errata 5.x: V = 2 v / (1 + m_b/m_s + (5/2) tip^2))."""
    return ball_speed * (1 + BALL_MASS / CUE_MASS + 2.5 * tip * tip) / 2


def _shot(angle, ball_speed, tip_x=0.0, tip_y=0.0, elevation=0.0) -> Shot:
    speed = min(MAX_CUE_SPEED, max(0.001, cue_speed_for(ball_speed, math.hypot(tip_x, tip_y))))
    return rounded(Shot(angle, speed, tip_x, tip_y, elevation))


def _tip(rng: random.Random) -> tuple[float, float]:
    if rng.random() < 0.2:      # tiny offsets: 1..5 per mille of R
        return rng.choice([-1, 1]) * rng.randint(1, 5) / 1000, rng.choice([-1, 1]) * rng.randint(0, 5) / 1000
    r, phi = MAX_TIP * math.sqrt(rng.random()), rng.uniform(0, 2 * math.pi)
    return round(r * math.cos(phi), 3), round(r * math.sin(phi), 3)


def _speed(rng: random.Random) -> float:
    return math.exp(rng.uniform(math.log(0.05), math.log(10.0)))   # ball speed, m/s


# ---------------------------------------------------------------------------- motion: one ball
def motion_cases(n: int, rng: random.Random) -> list[Case]:
    centre = {0: (L // 2, W // 2)}
    named = [Case("motion: slow roll 0.05 m/s", "motion", shot=_shot(0, 0.05, tip_y=0.4), balls=centre),
             Case("motion: stun 10 m/s", "motion", shot=_shot(17, 10.0), balls=centre),
             Case("motion: draw", "motion", shot=_shot(0, 3.0, tip_y=-0.45), balls=centre),
             Case("motion: follow with side", "motion", shot=_shot(30, 2.0, 0.3, 0.3), balls=centre),
             Case("motion: tiny tip", "motion", shot=_shot(-45, 2.0, 0.001, 0.002), balls=centre),
             Case("motion: masse 89 deg", "motion", shot=_shot(100, 1.0, 0.3, 0.0, 89), balls=centre)]
    random_ = [Case(f"motion: random {k}", "motion", balls=centre,
                    shot=_shot(rng.uniform(-180, 180), _speed(rng), *_tip(rng),
                               rng.choice([0.0, rng.uniform(0, 89)])))
               for k in range(n)]
    return named + random_


# ---------------------------------------------------------------------------- cushions
def _toward_rail(approach: float, rail: int, along: float) -> tuple[dict, float]:
    """A ball 0.3 m from rail ``rail`` (1 x=R, 2 x=L-R, 3 z=R, 4 z=W-R), aimed at the point ``along``
    (fraction of the rail) at ``approach`` degrees to it; returns (balls, aim in degrees)."""
    a = math.radians(approach)
    if rail in (3, 4):
        target = (along * L, R if rail == 3 else W - R)
        inward = 1 if rail == 3 else -1           # the normal into the table, along z
        d = (math.cos(a), -inward * math.sin(a))
    else:
        target = (R if rail == 1 else L - R, along * W)
        inward = 1 if rail == 1 else -1
        d = (-inward * math.sin(a), math.cos(a) if along > 0.5 else -math.cos(a))   # from the middle outwards
    back = min(0.3e6, 0.9 * (W / 2 - R) / max(math.sin(a), 1e-9))
    start = (round(target[0] - d[0] * back), round(target[1] - d[1] * back))
    return {0: start}, math.degrees(math.atan2(d[1], d[0]))


def cushion_cases(n: int, rng: random.Random) -> list[Case]:
    cases = []
    for k, approach in enumerate([5, 30, 45, 60, 85]):
        balls, aim = _toward_rail(approach, 1 + k % 4, 0.3)
        cases.append(Case(f"cushion: {approach} deg", "cushion", shot=_shot(aim, 2.0), balls=balls))
    for k in range(n):
        balls, aim = _toward_rail(rng.uniform(5, 85), rng.randint(1, 4), rng.uniform(0.2, 0.35))
        cases.append(Case(f"cushion: random {k}", "cushion", balls=balls,
                          shot=_shot(aim, rng.uniform(0.5, 8.0), rng.uniform(-0.45, 0.45), 0.0)))
    for k in range(n):          # the rebound alone, on a simulated ball
        approach, speed = math.radians(rng.uniform(5, 85)), rng.uniform(1e3, 4e5)
        rail = rng.randint(1, 4)
        cases.append(Case(f"cushion rebound {k}", "cushion", "rebound", inputs={
            "rail": rail, "v_along": round(speed * math.cos(approach) * rng.choice([-1, 1])),
            "v_in": round(speed * math.sin(approach)), "wy": round(rng.uniform(-1, 1) * speed)}))
    return cases


# ---------------------------------------------------------------------------- ball-ball
def _cut(cut: float, ball_speed: float, aim: float, distance: float, tip_y: float = 0.0) -> Case:
    d = (math.cos(math.radians(aim)), math.sin(math.radians(aim)))
    side = 2 * R * math.sin(math.radians(cut))
    cue = (L // 2 - round(d[0] * distance / 2), W // 2 - round(d[1] * distance / 2))
    obj = (round(cue[0] + d[0] * distance - d[1] * side), round(cue[1] + d[1] * distance + d[0] * side))
    return Case(f"ball-ball: cut {cut:.1f} deg at {ball_speed:.2f} m/s, aim {aim:.0f}", "ball-ball",
                shot=_shot(aim, ball_speed, 0.0, tip_y), balls={0: cue, 1: obj})


def ball_ball_cases(n: int, rng: random.Random) -> list[Case]:
    cases = [_cut(cut, 2.0, aim, 0.4e6) for cut in (0, 30, -45, 60, 80, -85, 89) for aim in (0, 37)]
    for _ in range(n):
        speed = _speed(rng)
        reach = speed ** 2 / (2 * 0.0981) * 1e6 * 0.8          # well short of where it stops rolling
        distance = min(0.6e6, max(2 * R + 3000, reach))
        cases.append(_cut(rng.uniform(-89, 89), speed, rng.uniform(-180, 180), rng.uniform(2 * R + 2000, distance),
                          rng.choice([0.0, rng.uniform(-0.4, 0.4)])))
    for k in range(n):          # the collision alone, at an exact contact rounded to um
        phi, speed = rng.uniform(-89, 89), _speed(rng) * 5e4
        cases.append(Case(f"ball-ball collide {k}", "ball-ball", "collide", inputs={
            "line": rng.uniform(-180, 180), "cut": phi, "speed": round(speed),
            "b_speed": rng.choice([0, round(rng.uniform(0, speed / 4))]), "b_angle": rng.uniform(-180, 180)}))
    return cases


# ---------------------------------------------------------------------------- cue strike
def cue_cases(n: int, rng: random.Random) -> list[Case]:
    named = [(6.5, 0.0, 0.0, 0), (0.05, 0.0, 0.0, 0), (3.0, 0.001, 0.0, 0), (3.0, 0.0, -0.005, 0),
             (3.0, 0.3, 0.3, 45), (3.0, -0.2, 0.1, 89), (5.0, 0.0, 0.45, 10)]
    cases = [Case(f"cue: {s} m/s tip {x},{y} elevation {e}", "cue", "strike",
                  shot=rounded(Shot(rng.uniform(-180, 180), s, x, y, e))) for s, x, y, e in named]
    for k in range(n):
        cases.append(Case(f"cue: random {k}", "cue", "strike", shot=rounded(Shot(
            rng.uniform(-180, 180), rng.uniform(0.05, MAX_CUE_SPEED), *_tip(rng), rng.uniform(0, 89)))))
    return cases


# ---------------------------------------------------------------------------- whole shots
def shot_cases(n: int, rng: random.Random) -> list[Case]:
    cue, obj = HEAD_SPOT, (L // 2 + 300000, W // 2 + 40000)
    named = [
        Case("shot: straight", "shots", shot=_shot(math.degrees(math.atan2(obj[1] - cue[1], obj[0] - cue[0])), 3.0),
             balls={0: cue, 1: obj}),
        Case("shot: cut", "shots", shot=_shot(0, 3.0, 0.0, 0.2), balls={0: cue, 1: obj}, mirrored=True),
        Case("shot: bank", "shots", shot=_shot(60, 4.0), balls={0: cue, 1: (L - 300000, W // 2)}, mirrored=True),
        Case("shot: masse", "shots", shot=_shot(20, 1.5, 0.35, 0.0, 70), balls={0: cue, 1: obj}, mirrored=True),
        Case("shot: break", "shots", shot=BREAK, mirrored=True),
    ]
    return named + [Case(f"shot: random {k}", "shots", shot=rounded(random_shot(rng, k + 1))) for k in range(n)]


GENERATORS = {"motion": motion_cases, "cushion": cushion_cases, "ball-ball": ball_ball_cases, "cue": cue_cases,
              "shots": shot_cases}


def cases(models, n: int, seed: int) -> list[Case]:
    """The named cases of each model and ``n`` random ones (from ``seed``, per model)."""
    found = []
    for model in models:
        found += GENERATORS[model](n, random.Random(f"{seed}:{model}"))
    return found
