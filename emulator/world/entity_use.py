"""A player using (right-clicking) an entity, as Player.interactOn carries it out, with what a datapack
observes: an ``interaction`` entity's ``interaction`` record, an item frame taking the held item or
turning its own, an armor stand trading items, a mob's own interaction, the held item's use on a
living entity, and the entities that have no use of their own.

- ``interact_at(state, player, hand, entity, at) -> str``: Entity.interactAt, which PackTest's
  ``use entity`` calls first: an armor stand's (emulator.world.armor_stands), any other passes.
- ``interact_on(state, player, hand, entity) -> str``: ``"consume"`` or ``"pass"``: the entity's
  interact (a mob's: emulator.world.mob_use), then, when that passes, the held item's use on a
  living entity (name tags, saddles); a boat or a minecart takes the player as its rider
  (Boat.interact, Minecart.interact: emulator.world.relations.mount); an entity whose
  interaction is not modelled (chest boats, the other minecarts, the mobs mob_use does not know
  ...) raises Unmodelled.
- ``record(state, player, entity, key)``: an interaction entity's ``attack`` / ``interaction``
  ``{player: UUID, timestamp: game time}`` (Interaction.skipAttackInteraction / interact).
- ``attack(state, player, target) -> bool``: Player.attack: an interaction entity records the
  attack and fires ``player_hurt_entity`` (generic damage, 1 dealt and taken, not blocked:
  Interaction.skipAttackInteraction); any other target is :func:`emulator.world.combat.attack`.

The ``player_interacted_with_entity`` criterion fires in the game's network handler
(ServerGamePacketListenerImpl.handleInteract), which PackTest's dummy bypasses: it does not fire
for a dummy, here as in the game.

Sources (decompiled 1.21.x): world/entity/player/Player.java (interactOn), world/entity/
Interaction.java (interact, skipAttackInteraction), world/entity/decoration/ItemFrame.java
(interact: a fixed frame passes; an empty one takes one of the held items; a full one turns its
item by one of 8 steps, ``ItemRotation``; an empty frame used with an empty hand consumes the use
before 1.21.2 and passes from it), world/entity/Entity.java (interact: passes),
world/entity/vehicle/Boat.java (interact, canAddPassenger, getPassengerAttachmentPoint),
Minecart.java (interact).
"""
from __future__ import annotations

import math

from emulator.world import armor_stands, combat, frames, inventories, living, mob_use, relations
from emulator.world.entity_types import BOATS
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import DamageSource
from emulator.world.player_actions import hand_slot
from mcfunction_parser.nbt import Byte, Compound, Int, IntArray, Long

ARMOR_STAND = "minecraft:armor_stand"
MINECART = "minecraft:minecart"
RESULTS_VERSION = (1, 21, 2)  # InteractionResult's rework: an empty frame used with an empty hand passes
# entities whose interact is Entity's own (no leash, no ride, no menu): using them passes
PASSIVE = frozenset("minecraft:" + n for n in (
    "marker item experience_orb area_effect_cloud falling_block tnt block_display item_display text_display "
    "arrow spectral_arrow trident snowball egg ender_pearl potion experience_bottle fireball small_fireball "
    "dragon_fireball wither_skull wind_charge breeze_wind_charge firework_rocket eye_of_ender evoker_fangs "
    "lightning_bolt painting shulker_bullet llama_spit end_crystal").split())


def record(state, player, entity, key: str) -> None:
    entity.data[key] = Compound(player=IntArray(Int(v) for v in player.uuid), timestamp=Long(state.gametime))


def attack(state, player, target) -> bool:
    """Player.attack: True when the target was hurt (an interaction entity never is)."""
    if target.type == "minecraft:interaction":
        record(state, player, target, "attack")
        combat.player_hurt_entity(state, player, target, DamageSource("minecraft:generic"), 1.0)
        return False
    return combat.attack(state, player, target)


def interact_at(state, player, hand: str, entity, at) -> str:
    """Entity.interactAt, which PackTest's useEntity calls before Player.interactOn with ``at`` the
    position given (the entity's own position when none is): only an armor stand has one."""
    if entity.type != ARMOR_STAND:
        return "pass"
    return armor_stands.interact_at(state, player, hand, entity, at)


def interact_on(state, player, hand: str, entity) -> str:
    """Player.interactOn: a spectator only opens menus; else the entity's own interact, and when
    that passes, the held item's use on a living entity (ItemStack.interactLivingEntity); a creative
    player keeps what the use took from its hand."""
    if player.gamemode == "spectator":
        return "pass"
    if entity.type == "minecraft:interaction":
        record(state, player, entity, "interaction")
        return "consume"
    if entity.type in frames.FRAMES:
        return _item_frame(state, player, hand, entity)
    if entity.type in PASSIVE:
        return "pass"
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    held = access.get()
    if entity.type == ARMOR_STAND or entity.is_player:  # no interact of their own (Entity.interact: not Leashable)
        result = "pass"
    elif entity.type in BOATS or entity.type == MINECART:
        return _ride_vehicle(state, player, hand, entity)
    elif living.is_living(entity.type) and not entity.is_player:
        result = mob_use.interact(state, player, hand, entity)
    else:
        raise Unmodelled(f"using {entity.type} (its interaction is not modelled: only interaction entities, item "
                         "frames, armor stands, some mobs and entities without an interaction of their own)")
    if result != "consume" and not held.is_empty and living.is_living(entity.type):
        result = mob_use.item_on_living(state, player, hand, entity)
    return result


def _ride_vehicle(state, player, hand: str, vehicle) -> str:
    """Boat.interact / Minecart.interact: a sneaking player passes; else the player gets in
    (Player.startRiding: one rider here; a boat whose eyes are under water refuses) and the use is
    consumed, or passes when refused. A boat's leash (Entity.interact: Leashable), chest boats and
    the other minecarts (their containers and blocks) are not modelled."""
    held = inventories.entity_slot(player, hand_slot(hand), state.version).get()
    if vehicle.type in BOATS:
        if "chest" in vehicle.type:
            raise Unmodelled(f"using {vehicle.type} (its chest)")
        if held.id == "minecraft:lead" or vehicle.data.get("leash") is not None:
            raise Unmodelled(f"leashing {vehicle.type} (Leashable)")
    if player.sneaking:
        return "pass"
    if vehicle.type in BOATS:
        eyes = tuple(math.floor(c) for c in vehicle.anchor("eyes"))
        if state.blocks_in(vehicle.dimension).get(eyes).id == "minecraft:water":  # isEyeInFluid(WATER)
            return "pass"
        riders = relations.passengers_of(vehicle)
        if len(riders) == 1 and player not in riders:  # a boat seats two
            raise Unmodelled(f"a second passenger in {vehicle.type} (where each sits)")
    return "consume" if relations.mount(state, player, vehicle) else "pass"


def _item_frame(state, player, hand: str, frame) -> str:
    """ItemFrame.interact on the server: a fixed frame passes; an empty frame takes one of the held
    items (consumed unless creative; a map is not modelled); a full one turns its item."""
    if frame.data.get("Fixed"):
        return "pass"
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    held = access.get()
    framed = inventories.entity_slot(frame, 0, state.version)
    if framed.get().is_empty:
        if held.is_empty:  # before 1.21.2 the server consumed every use of a frame that is not fixed
            return "pass" if tuple(state.version) >= RESULTS_VERSION else "consume"
        if held.id == "minecraft:filled_map":
            raise Unmodelled("putting a map in an item frame (map data)")
        one = held.copy()
        one.count = 1
        framed.set(one)
        if player.gamemode != "creative":
            held.count -= 1
            access.set(held)
        return "consume"
    frame.data["ItemRotation"] = Byte((int(frame.data.get("ItemRotation", Byte(0))) + 1) % 8)
    return "consume"

