"""A totem of undying saving its holder from death (LivingEntity.checkTotemDeathProtection).

When a hurt leaves a living entity at 0 health, a totem in its main hand, else its off hand, is
used up (one item, in creative too) unless the damage is in ``#bypasses_invulnerability`` (``kill``,
the void): a player counts ``minecraft.used:minecraft:totem_of_undying`` and fires ``used_totem``
with the stack; the health is set to 1, and the totem's effects follow. From 1.21.2 any item with
the ``death_protection`` component saves, its ``death_effects`` (consume effects) in order, the
totem's by default: every effect cleared, then regeneration II for 900 ticks, absorption II for 100
and fire resistance for 800 (DeathProtection.TOTEM_OF_UNDYING); before, only the totem, with those
effects in code.

Sources: decompiled 26.1.2 and 1.20.6 LivingEntity.checkTotemDeathProtection, 26.1.2
DeathProtection.
"""
from __future__ import annotations

from emulator.world import advancements, consume_effects, inventories, living, predicates, statistics
from emulator.world.errors import Unmodelled
from emulator.world.items import TOTEM_PROTECTION
from mcfunction_parser.nbt import Compound, List

TOTEM = "minecraft:totem_of_undying"
COMPONENT = "minecraft:death_protection"
COMPONENT_VERSION = (1, 21, 2)


def saves(state, entity, source_type: str, harm) -> bool:
    """Whether a totem the entity holds keeps it alive after a hurt by ``source_type`` left it at
    0 health (carrying out the save; ``harm(state, entity, amount)``: an instant damage effect's
    hurt). A ``teleport_randomly`` death effect is not modelled."""
    if state.resources.in_tag("damage_type", "minecraft:bypasses_invulnerability", source_type):
        return False
    for hand in (inventories.MAINHAND, inventories.OFFHAND):
        access = inventories.entity_slot(entity, hand, state.version)
        if access is None:
            continue
        stack = access.get()
        effects = _death_effects(stack, state.version)
        if effects is not None:
            _protect(state, entity, access, stack, effects, harm)
            return True
    return False


def _death_effects(stack, version):
    """The consume effects of a stack that protects from death, None for one that does not."""
    if stack.is_empty:
        return None
    if tuple(version) < COMPONENT_VERSION:
        return TOTEM_PROTECTION["death_effects"] if stack.id == TOTEM else None
    protection = stack.component(COMPONENT)
    if not isinstance(protection, Compound):
        return None
    return protection.get("death_effects", List())


def _protect(state, entity, access, stack, effects, harm) -> None:
    unknown = consume_effects.unmodelled(effects, teleports=False)
    if unknown:
        raise Unmodelled(f"the {unknown} death effect of {stack.id}")
    used = stack.copy()
    stack.count -= 1
    access.set(stack)
    if entity.is_player:
        statistics.award(state, entity, statistics.stat_name("used", used.id))
        advancements.trigger(state, entity, "used_totem", lambda c, ctx: (
            c.get("item") is None or predicates.item_matches(c["item"], ctx, used)))
    living.set_health(entity, 1.0)
    consume_effects.apply(state, entity, effects, harm)
