"""The scores: one metric per row of ``dpemu score``, with its pass range (DESIGN.md section 6 for
the seeded mode; the end-to-end allowances are derived in :mod:`poolgame.score.endtoend`).

A case adds samples to metrics by key; a row passes when every sample lies in its range.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

MODES = ("seeded", "end-to-end")        # the modes rows belong to (their models: poolgame.score.MODELS)


@dataclass(frozen=True)
class Metric:
    key: str
    model: str
    mode: str
    text: str                     # what the row measures
    unit: str
    low: float                    # the pass range, inclusive
    high: float
    scored: bool = True           # False: reported for information (the cost of the constants alone)

    def passes(self, value: float) -> bool:
        return self.low <= value <= self.high

    @property
    def threshold(self) -> str:
        if not self.scored:
            return "info"
        if self.low == self.high:
            return f"= {self.high:g}"
        if self.low > -math.inf:
            return f"{self.low:g} .. {self.high:g}"
        return f"<= {self.high:g}"


_S, _E = MODES
METRICS = {m.key: m for m in (
    Metric("roll_velocity", "motion", _S, "slide->roll rolling velocity, per component", "um/tick", -math.inf, 2),
    Metric("transition_tick", "motion", _S, "slide->roll transition tick", "ticks", -math.inf, 1),
    Metric("stop", "motion", _S, "stop position / (1 mm + 0.05 % of path)", "ratio", -math.inf, 1),
    Metric("trajectory_rms", "motion", _S, "single-ball trajectory, per-tick RMS", "mm", -math.inf, 0.5),
    Metric("trajectory_max", "motion", _S, "single-ball trajectory, per-tick max", "mm", -math.inf, 2),
    Metric("momentum", "ball-ball", _S, "momentum change in integers", "um/tick", 0, 0),
    Metric("energy_change", "ball-ball", _S, "|dKE| / KE of a collision", "ratio", -math.inf, 1e-3),
    Metric("collide_direction", "ball-ball", _S, "object-ball direction, same contact", "deg", -math.inf, 0.1),
    Metric("contact", "ball-ball", _S, "centre distance - 2R at resolution", "mm", 0, 0.2),
    Metric("object_direction", "ball-ball", _S, "object-ball direction (its impulse) vs exact 2R contact", "deg", -math.inf, 0.1),
    Metric("rebound_angle", "cushion", _S, "rebound angle", "deg", -math.inf, 0.25),
    Metric("normal_ratio", "cushion", _S, "normal-speed ratio vs e, relative", "ratio", -math.inf, 1e-3),
    Metric("cue_speed", "cue", _S, "ball speed after the strike, relative", "ratio", -math.inf, 1e-3),
    Metric("cue_spin", "cue", _S, "spin after the strike, relative", "ratio", -math.inf, 5e-3),
    Metric("energy_rise", "shots", _S, "KE rise between ticks without a collision / KE", "ratio", -math.inf, 0),
    Metric("energy_rise_collision", "shots", _S, "KE rise over a tick with a collision / KE", "ratio",
           -math.inf, 1e-3),
    Metric("symmetry", "shots", _S, "mirrored shot, largest integer difference", "units", -math.inf, 1),
    Metric("overflow", "shots", _S, "wrapped intermediates per shot", "count", 0, 0),
    Metric("e2e_trajectory", "motion", _E, "per-tick distance / allowance", "ratio", -math.inf, 1),
    Metric("e2e_stop", "motion", _E, "stop position / allowance", "ratio", -math.inf, 1),
    Metric("e2e_object_direction", "ball-ball", _E, "first object-ball direction / allowance", "ratio",
           -math.inf, 1),
    Metric("constants_stop", "shots", _E, "constants alone: stop position, pack vs seed constants", "mm",
           -math.inf, math.inf, scored=False),
    Metric("constants_trajectory", "shots", _E, "constants alone: per-tick max, pack vs seed constants",
           "mm", -math.inf, math.inf, scored=False),
)}


@dataclass
class Row:
    metric: Metric
    values: list

    @property
    def passed(self) -> bool:
        return not self.metric.scored or all(self.metric.passes(v) for v in self.values)

    def to_json(self) -> dict:
        m = self.metric
        stats = percentiles(self.values)
        return {"metric": m.key, "model": m.model, "mode": m.mode, "what": m.text, "unit": m.unit,
                "cases": len(self.values), **stats, "threshold": m.threshold,
                "pass": self.passed if self.values else None}


def percentiles(values) -> dict:
    if not values:
        return {"min": None, "p50": None, "p95": None, "max": None}
    a = np.asarray(values, float)
    return {"min": float(a.min()), "p50": float(np.percentile(a, 50)), "p95": float(np.percentile(a, 95)),
            "max": float(a.max())}


def rows(samples: dict[str, list], models, modes) -> list[Row]:
    """The rows of the chosen models and modes, and any other row that has samples (a cushion a
    lone ball met, the energy of every shot)."""
    return [Row(m, samples.get(m.key, [])) for m in METRICS.values()
            if m.mode in modes and (m.model in models or samples.get(m.key))]
