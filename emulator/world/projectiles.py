"""Projectiles in flight, which the emulator does not move: the game moves each one every tick
(Projectile.tick, AbstractArrow.tick: motion, gravity, drag, hitting blocks and entities).

- ``launched(state, entity)``: an entity just made (``summon``, a crossbow's shot); one that flies
  is watched until the next tick.
- ``tick_flying(state)``: at the next tick's entity steps, a watched one still there and still in
  flight (it would have moved) is reported as not modelled, once for the run; ``tick_is_idle``:
  none watched.
- ``flies(entity)``: a projectile not stuck in a block (``inGround``), unless it has no gravity,
  no motion and no power of its own (a fireball's).
"""
from __future__ import annotations

PROJECTILES = frozenset("minecraft:" + name for name in (
    "arrow spectral_arrow trident snowball egg ender_pearl experience_bottle potion splash_potion lingering_potion "
    "fireball small_fireball dragon_fireball wither_skull wind_charge breeze_wind_charge llama_spit "
    "shulker_bullet firework_rocket eye_of_ender").split())
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
    if flies(entity):
        state.flying.append(entity)


def tick_flying(state) -> None:
    for entity in state.flying:
        if entity.alive and flies(entity):
            message = MESSAGE.format(entity.type)
            if not any(d.message == message for d in state.diagnostics):
                state.error(message, severity="warning", unmodelled=True)
    state.flying.clear()


def tick_is_idle(state) -> bool:
    return not state.flying
