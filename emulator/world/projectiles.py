"""Projectiles: arrows, tridents, snowballs and thrown items (eggs, ender pearls, experience
bottles, potions) move each tick as the game moves them (:mod:`emulator.world.projectile_flight`);
the others (fireballs, wind charges, llama spit, rockets, eyes of ender) are not moved here.

- ``launched(state, entity)``: an entity just made (``summon``, a crossbow's shot). One of those
  moved here is followed while it exists; another projectile that flies is watched until
  the next tick.
- ``tick_flying(state)``: each followed projectile takes its tick; one whose tick meets what is not
  modelled (:mod:`emulator.world.projectile_flight`) is reported, once for the run, and left where
  it is from then on; a watched one still there and still in flight (it would have moved) is
  reported as not modelled; ``tick_is_idle``: none followed or watched.
- ``flies(entity)``: a projectile not stuck in a block (``inGround``), unless it has no gravity,
  no motion and no power of its own (a fireball's).
"""
from __future__ import annotations

from emulator.world import projectile_flight
from emulator.world.entity_types import PROJECTILES
from emulator.world.errors import Unmodelled

_POWERED = frozenset("minecraft:" + name for name in (
    "fireball small_fireball dragon_fireball wither_skull wind_charge breeze_wind_charge").split())
MESSAGE = "{} in flight: projectiles do not move here (motion, gravity, drag, hits)"


def flies(entity) -> bool:
    data = entity.data
    if entity.type not in PROJECTILES or int(data.get("inGround", 0)) or int(data.get("in_ground", 0)):
        return False
    still = all(float(m) == 0.0 for m in entity.motion) and int(data.get("NoGravity", 0))
    return not still or entity.type in _POWERED


def launched(state, entity) -> None:
    if entity.type in projectile_flight.MODELLED or flies(entity):
        state.flying.append(entity)


def tick_flying(state) -> None:
    if not state.flying:  # every tick: none made in flight is the common case
        return
    followed = []
    for entity in state.flying:
        if not entity.alive:
            continue
        if entity.type in projectile_flight.MODELLED:
            try:
                projectile_flight.step(state, entity)
            except Unmodelled as reason:
                _report(state, reason.message)
                continue
            if entity.alive:
                followed.append(entity)
        elif flies(entity):
            _report(state, MESSAGE.format(entity.type))
    state.flying[:] = followed


def _report(state, message: str) -> None:
    if not any(d.message == message for d in state.diagnostics):
        state.error(message, severity="warning", unmodelled=True)


def tick_is_idle(state) -> bool:
    return not state.flying
