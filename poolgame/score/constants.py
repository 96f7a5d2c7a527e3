"""The pool pack's constants read back from a loaded pack (pool:load's scores on pool.const, the
mass ratio from pool:cue/strike) and turned into SI: the float reference then runs with exactly
the numbers the integers use (the cost of quantising them is reported apart)."""
from __future__ import annotations

from mcfunction_parser.ast import ScoreSet

from poolgame.physics.constants import Constants

UM_PER_TICK2 = 400e-6      # m/s^2 per um/tick^2 (20 ticks per second)
STRIKE = "pool:cue/strike"


class NotPoolPack(ValueError):
    """The pack lacks a constant the pool pack defines."""


def pack_constants(emu) -> Constants:
    def const(name: str) -> int:
        value = emu.score(name, "pool.const")
        if value is None:
            raise NotPoolPack(f"no {name} pool.const after pool:load")
        return value

    return Constants(slide_deceleration=const("$mu_s_g") * UM_PER_TICK2,
                     roll_deceleration=const("$mu_r_g") * UM_PER_TICK2 / 100,   # 0.01 um/tick^2
                     spin_deceleration=const("$spin_decay") * UM_PER_TICK2,
                     cushion_restitution=const("$e_cushion") / 10_000,
                     cushion_friction=const("$mu_cushion") / 10_000,
                     mass_ratio=_mass_ratio(emu))


def _mass_ratio(emu) -> float:
    """pool:cue/strike adds 10^6 (1 + m_b/m_s) to its denominator (the one literal above 10^6 it adds)."""
    function = emu.packs.functions.get(STRIKE)
    literals = [c.value for c in (function.commands if function else ())
                if isinstance(c, ScoreSet) and c.action == "add" and c.value > 1_000_000]
    if len(literals) != 1:
        raise NotPoolPack(f"{STRIKE} does not add 10^6 (1 + m_b/m_s) as the pool pack's does")
    return (literals[0] - 1_000_000) / 1_000_000
