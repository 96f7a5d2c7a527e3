"""Consume effects in the 1.21.2 component form (a consumable's ``on_consume_effects``, a
``death_protection``'s ``death_effects``) carried out on a living entity, in their order
(Consumable.onConsume, DeathProtection.applyEffects): ``apply_effects`` (its chance drawn from the
emulator's random, not the entity's; an instant effect acts at once through ``harm``),
``remove_effects`` (an effect tag is not modelled), ``clear_all_effects``, ``teleport_randomly``
(where the caller can teleport) and ``play_sound`` (nothing a pack observes).

A player whose effects changed fires ``effects_changed``.
"""
from __future__ import annotations

from emulator.world import advancements, consumables, living
from emulator.world.errors import Unmodelled
from emulator.world.nbt_ops import numeric_value
from mcfunction_parser.nbt import Compound, String

KNOWN = frozenset({"apply_effects", "remove_effects", "clear_all_effects", "teleport_randomly", "play_sound"})


def effect_type(effect) -> str:
    return str(effect.get("type", "")).removeprefix("minecraft:") if isinstance(effect, Compound) else ""


def unmodelled(effects, teleports: bool = True) -> str | None:
    """The type of the first effect :func:`apply` cannot carry out (``teleports``: whether the
    caller can teleport)."""
    known = KNOWN if teleports else KNOWN - {"teleport_randomly"}
    unknown = [e for e in effects if effect_type(e) not in known]
    return effect_type(unknown[0]) if unknown else None


def apply(state, entity, effects, harm, teleport=None, per_effect_draw: bool = False) -> None:
    """Each effect in order; ``harm(state, entity, amount) -> bool`` hurts for an instant effect,
    ``teleport(state, entity, diameter)`` carries out ``teleport_randomly``."""
    for effect in effects:
        kind = effect_type(effect)
        if kind == "apply_effects":
            give_effects(state, entity, consumables.drawn(effect, state.resources.random, per_effect_draw), harm)
        elif kind == "remove_effects":
            _remove_effects(state, entity, effect)
        elif kind == "clear_all_effects" and living.clear_effects(entity):  # LivingEntity.removeAllEffects
            advancements.effects_changed(state, entity, None)
        elif kind == "teleport_randomly":
            diameter = effect.get("diameter")
            teleport(state, entity, float(numeric_value(diameter)) if diameter is not None else 16.0)


def give_effects(state, entity, effects, harm) -> None:
    """LivingEntity.addEffect for each (PotionContents.applyToLivingEntity: an instantaneous effect
    acts at once instead)."""
    for effect_id, duration, amplifier in effects:
        if effect_id in living.INSTANT:
            living.apply_instant(state, entity, effect_id, amplifier, harm)
        elif living.give_effect(state, entity, effect_id, duration, amplifier, effect_id != "minecraft:bad_omen"):
            advancements.effects_changed(state, entity, None)


def _remove_effects(state, entity, effect) -> None:
    """RemoveStatusEffectsConsumeEffect: the listed effects (an id, a list or a #tag)."""
    listed = effect.get("effects")
    ids = [str(listed)] if isinstance(listed, String) else [str(e) for e in (listed or ())]
    if any(i.startswith("#") for i in ids):
        raise Unmodelled("a remove_effects consume effect naming an effect tag")
    if any([living.clear_effects(entity, i) for i in ids]):
        advancements.effects_changed(state, entity, None)
