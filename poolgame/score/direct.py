"""Models alone: the pack's collision, cushion and cue functions called directly on a ball, against
the float formulas on the same integer inputs (the pack's units: um, um/tick, x 10000 normals)."""
from __future__ import annotations

import math

import numpy as np

from poolgame.physics import ball_ball, cushion
from poolgame.physics import cue as float_cue
from poolgame.physics.constants import Constants
from poolgame.score.floats import RAIL_OF, UM_PER_TICK, angle_between, resolvable
from poolgame.score.metrics import METRICS
from poolgame.shot import ball_holders, reset_table, strike

BALL = "pool.ball_a"                 # a simulated player standing in for the ball (@s)
TWO_R = 57150


def _on_ball(emu, **scores) -> str:
    if emu.score(BALL, "pool.x") is None and not emu.entities(BALL):
        emu.add_player(BALL)
    for name, value in scores.items():
        emu.set_score(BALL, f"pool.{name}", int(value))
    return BALL


def collide(emu, inputs: dict, samples: dict) -> None:
    """pool:physics/resolve/ball_ball/collide at an exact contact (rounded to um): momentum in
    integers, the energy change, and the object ball's direction against the float collision."""
    line, cut = math.radians(inputs["line"]), math.radians(inputs["cut"])
    r_a = np.array([1_000_000, 600_000])
    r_b = r_a + np.round(TWO_R * np.array([math.cos(line), math.sin(line)])).astype(int)
    v_a = np.round(inputs["speed"] * np.array([math.cos(line + cut), math.sin(line + cut)])).astype(int)
    b_angle = math.radians(inputs["b_angle"])
    v_b = np.round(inputs["b_speed"] * np.array([math.cos(b_angle), math.sin(b_angle)])).astype(int)
    holder = _on_ball(emu, x=r_a[0], z=r_a[1], vx=v_a[0], vz=v_a[1])
    for name, value in zip(("x", "z", "vx", "vz"), (*r_b, *v_b)):
        emu.set_score(f"#ball_ball.b.{name}", "pool.tmp", int(value))
    emu.call("pool:physics/resolve/ball_ball/collide", as_=holder)
    a1 = np.array([emu.score(holder, "pool.vx"), emu.score(holder, "pool.vz")], float)
    b1 = np.array([emu.score("#ball_ball.b.vx", "pool.tmp"), emu.score("#ball_ball.b.vz", "pool.tmp")], float)
    samples["momentum"].append(float(np.abs(a1 + b1 - v_a - v_b).max()))
    ke0 = float(v_a @ v_a + v_b @ v_b)
    samples["energy_change"].append(abs(float(a1 @ a1 + b1 @ b1) - ke0) / ke0)
    _, ref_b = ball_ball.collide(r_a.astype(float), v_a.astype(float), r_b.astype(float), v_b.astype(float))
    moved_float, moved_int = ref_b - v_b, b1 - v_b
    if resolvable(np.linalg.norm(moved_float), math.radians(METRICS["collide_direction"].high)):
        samples["collide_direction"].append(angle_between(moved_int, moved_float))


def rebound(emu, inputs: dict, k: Constants, samples: dict) -> None:
    """pool:physics/resolve/cushion/rebound on a ball approaching rail ``rail``."""
    normal = RAIL_OF[inputs["rail"]].normal
    along = np.array([normal[1], -normal[0]])
    v = np.round(inputs["v_along"] * along - inputs["v_in"] * normal).astype(int)
    holder = _on_ball(emu, vx=v[0], vz=v[1], wy=inputs["wy"], wx=0, wz=0)
    emu.set_score("#cushion.nx", "pool.tmp", int(normal[0]))
    emu.set_score("#cushion.nz", "pool.tmp", int(normal[1]))
    emu.call("pool:physics/resolve/cushion/rebound", as_=holder)
    v_int = np.array([emu.score(holder, "pool.vx"), emu.score(holder, "pool.vz")], float)
    v_float, _ = cushion.rebound(v.astype(float), float(inputs["wy"]), normal, k.cushion_restitution,
                                 k.cushion_friction)
    if resolvable(np.linalg.norm(v_float), math.radians(METRICS["rebound_angle"].high)):
        samples["rebound_angle"].append(angle_between(v_int, v_float))
    v_in = -float(v @ normal)
    if resolvable(v_in, METRICS["normal_ratio"].high):
        samples["normal_ratio"].append(abs(float(v_int @ normal) / v_in / k.cushion_restitution - 1))


def cue_strike(emu, shot, k: Constants, samples: dict) -> list[str]:
    """pool:api/shot on a lone cue ball, read before any tick, against the float strike (5.5-5.7)."""
    reset_table(emu, {0: (635_000, 635_000)})
    refused = strike(emu, shot)
    if refused:
        return refused
    (holder,) = ball_holders(emu).values()
    got = np.array([emu.score(holder, f"pool.{n}") for n in ("vx", "vz", "wx", "wz", "wy")], float)
    v, w, wy = float_cue.strike(float_cue.Shot(math.radians(shot.angle), shot.speed, shot.tip_x, shot.tip_y,
                                               math.radians(shot.elevation)), k=k)
    want = np.array([*v, *w, wy]) / UM_PER_TICK
    samples["cue_speed"].append(float(np.linalg.norm(got[:2] - want[:2]) / np.linalg.norm(want[:2])))
    spin = np.linalg.norm(want[2:])
    if resolvable(spin, METRICS["cue_spin"].high):
        samples["cue_spin"].append(float(np.linalg.norm(got[2:] - want[2:]) / spin))
    return []
