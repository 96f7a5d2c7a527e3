"""The ``flags`` of an entity predicate (EntityFlagsPredicate.matches).

- ``flags_match(value, state, entity)``: each flag the release's codec reads must equal the
  entity's; a flag the release does not have is ignored, as its codec ignores an unknown field.

What each flag reads: ``is_on_fire`` (Entity.isOnFire on the server), ``is_sneaking``,
``is_sprinting``, ``is_on_ground`` (``OnGround``), ``is_baby`` and ``is_fall_flying`` (living
entities only: another entity passes them whatever they say), ``is_in_water`` (Entity.isInWater:
its box in water, as the last tick's fluid update left it), ``is_swimming`` (the flag
Entity.updateSwimming sets each tick: never without sprinting in water, and a sprinting entity in
water is not modelled: whether its eyes are under water, and the flag kept from the tick before,
decide), ``is_flying`` (a gliding living entity, or a player whose abilities fly: a spectator
always does, GameType.updatePlayerAbilities; creative players fly only when their client asks,
which the emulated world has no client to do, or keep flying from spectator mode).

Sources: advancements/critereon/EntityFlagsPredicate.java (decompiled 1.21.1: is_on_ground and
is_flying from 1.21; 26.1.2: is_in_water and is_fall_flying, from 1.21.11 per the vanilla mcdoc),
world/entity/Entity.java (updateSwimming, isInWater, isUnderWater), world/entity/monster/zombie/
Drowned.java (updateSwimming: its AI's wish to swim), world/level/GameType.java.
"""
from __future__ import annotations

from typing import Callable

from emulator.world import burning, fluids, living
from emulator.world.errors import Unmodelled
from emulator.world.nbt_ops import is_numeric, numeric_value

# the release each flag appeared in; the others are as old as the predicate
_SINCE = {"is_on_ground": (1, 21, 0), "is_flying": (1, 21, 0), "is_in_water": (1, 21, 11),
          "is_fall_flying": (1, 21, 11)}
_LIVING_ONLY = frozenset({"is_baby", "is_fall_flying"})


def flags_match(value: dict, state, entity) -> bool:
    version = tuple(state.version)
    for flag, wanted in value.items():
        if version < _SINCE.get(flag, (0, 0, 0)):
            continue
        read = _FLAGS.get(flag)
        if read is None:
            continue  # not a field of the codec: ignored
        if flag in _LIVING_ONLY and not living.is_living(entity.type):
            continue
        if read(state, entity) != bool(wanted):
            return False
    return True


def _in_water(state, entity) -> bool:
    return fluids.in_water(state.blocks_in(entity.dimension), entity.bounding_box)


def _saved_flag(entity, key: str) -> bool:
    tag = entity.data.get(key)
    return is_numeric(tag) and numeric_value(tag) != 0


def _swimming(state, entity) -> bool:
    if entity.vehicle is not None or not _in_water(state, entity):
        return False  # both of updateSwimming's branches need the entity in water and riding nothing
    if entity.type == "minecraft:drowned":
        raise Unmodelled("whether a drowned in water swims (Drowned.updateSwimming: its AI's wish to swim)")
    if not entity.sprinting:
        return False
    raise Unmodelled("whether an entity sprinting in water swims (Entity.updateSwimming: its eyes under water, "
                     "and the flag it had the tick before)")


def _fall_flying(state, entity) -> bool:
    if _saved_flag(entity, "FallFlying"):
        raise Unmodelled("gliding (LivingEntity.updateFallFlying: whether the entity may keep gliding)")
    return False


def _flying(state, entity) -> bool:
    if living.is_living(entity.type) and _fall_flying(state, entity):
        return True
    return entity.is_player and entity.flying


def flying_after(mode: str, flying: bool) -> bool:
    """A player's abilities.flying once its game mode is ``mode`` (GameType.updatePlayerAbilities:
    a spectator flies, survival and adventure do not, creative keeps what it had)."""
    return True if mode == "spectator" else flying if mode == "creative" else False


_FLAGS: dict[str, Callable] = {
    "is_on_fire": lambda state, e: burning.is_on_fire(e),  # Entity.isOnFire on the server: not HasVisualFire
    "is_sneaking": lambda state, e: e.sneaking,
    "is_sprinting": lambda state, e: e.sprinting,
    "is_on_ground": lambda state, e: _saved_flag(e, "OnGround"),
    "is_baby": lambda state, e: living.is_baby(e),
    "is_swimming": _swimming,
    "is_flying": _flying,
    "is_in_water": _in_water,
    "is_fall_flying": _fall_flying,
}
