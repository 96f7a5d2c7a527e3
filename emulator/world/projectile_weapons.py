"""Bows and crossbows in a player's hands: whether they can be drawn, and a charged crossbow's shot.

- ``ammunition(state, player, weapon) -> ItemStack``: Player.getProjectile: an arrow (or, for a
  crossbow, a firework rocket) in either hand, else the first arrow of the inventory, else for a
  creative player a plain arrow; empty when there is none.
- ``shoot_charged(state, player, hand, access)``: CrossbowItem.performShooting: the charged
  projectiles are cleared from the crossbow and each becomes an arrow at the eyes less 0.1, owned by
  the player (``Owner``), ``pickup`` allowed (creative-only for an ``intangible_projectile``),
  ``crit``, ``damage`` 2, ``item`` and ``weapon``, shot along the player's view at 3.15 blocks per
  tick with the game's inaccuracy 1 (Projectile.getMovementToShoot: a triangle spread of
  0.0172275 per axis, drawn from the emulator's random, not the arrow's own: the motion's last
  digits differ from the game's), its rotation from its motion; the crossbow wears by one per arrow
  (emulator.world.tools), ``minecraft.used:crossbow`` and ``shot_crossbow``.

A bow is drawn by ``use item`` and only shoots when released, which PackTest has no action for: a
dummy never shoots one, as in the game. Not modelled (Unmodelled): firework rockets and more than
one charged projectile (multishot's spread), a crossbow with enchantments that change the shot.

Sources (decompiled 1.21.x and 26.1): world/item/BowItem.java and CrossbowItem.java (use,
performShooting, getShootingPower, shootProjectile), ProjectileWeaponItem.java (shoot,
createProjectile, ARROW_ONLY / ARROW_OR_FIREWORK), world/entity/player/Player.java (getProjectile),
world/entity/projectile/Projectile.java (shoot, getMovementToShoot), arrow/AbstractArrow.java
(constructor: eyes - 0.1; setOwner; addAdditionalSaveData), Entity.calculateViewVector.
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import advancements, inventories, mth, statistics, tools
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack, enchantment_levels, from_nbt, set_component, to_nbt
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, IntArray, List

F32 = np.float32
ARROWS = frozenset({"minecraft:arrow", "minecraft:tipped_arrow", "minecraft:spectral_arrow"})  # #arrows
CROSSBOW_ARROW_POWER = 3.15  # CrossbowItem.getShootingPower (1.6 for a firework rocket)
INACCURACY = 1.0  # CrossbowItem.use: performShooting(..., 1.0F)
SPREAD = 0.0172275  # Projectile.getMovementToShoot
ARROW_ENTITIES = {"minecraft:arrow": "minecraft:arrow", "minecraft:tipped_arrow": "minecraft:arrow",
                  "minecraft:spectral_arrow": "minecraft:spectral_arrow"}


def ammunition(state, player, weapon: ItemStack) -> ItemStack:
    """Player.getProjectile for a bow or crossbow."""
    held = ARROWS | ({"minecraft:firework_rocket"} if weapon.id == "minecraft:crossbow" else set())
    for slot in (inventories.OFFHAND, inventories.MAINHAND):  # ProjectileWeaponItem.getHeldProjectile
        stack = inventories.entity_slot(player, slot, state.version).get()
        if stack.id in held and not stack.is_empty:
            return stack
    for index in range(inventories.PLAYER_INVENTORY_SIZE):
        stack = inventories.entity_slot(player, index, state.version).get()
        if stack.id in ARROWS and not stack.is_empty:
            return stack
    return ItemStack("minecraft:arrow") if player.gamemode == "creative" else EMPTY


def charged(stack: ItemStack) -> list[ItemStack]:
    """The crossbow's ``charged_projectiles`` (1.20.5+; before, the NBT ``ChargedProjectiles``)."""
    found = stack.component("minecraft:charged_projectiles")
    if found is None and stack.tag is not None:
        found = stack.tag.get("ChargedProjectiles") if stack.tag.get("Charged") else None
    items = [from_nbt(tag) for tag in (found or ())]
    return [s for s in items if s is not None and not s.is_empty]


def shoot_charged(state, player, hand_slot: int) -> None:
    """CrossbowItem.performShooting with the charged projectiles of the crossbow in ``hand_slot``."""
    access = inventories.entity_slot(player, hand_slot, state.version)
    weapon = access.get()
    projectiles = charged(weapon)
    if len(projectiles) > 1 or any(p.id not in ARROW_ENTITIES for p in projectiles):
        raise Unmodelled(f"shooting {', '.join(p.id for p in projectiles)} from a crossbow "
                         "(only one charged arrow is modelled)")
    if set(enchantment_levels(weapon)) - {"minecraft:unbreaking", "minecraft:mending", "minecraft:quick_charge"}:
        raise Unmodelled("a crossbow enchantment that changes its shot")
    _clear_charge(weapon, state.version)
    access.set(weapon)
    for projectile in projectiles:
        _spawn_arrow(state, player, projectile, weapon)
        tools.hurt_and_break(state, player, access, 1)  # CrossbowItem.getDurabilityUse: 1 for an arrow
        if access.get().is_empty:
            break
    advancements.trigger(state, player, "shot_crossbow")
    statistics.award(state, player, statistics.stat_name("used", weapon.id))


def _clear_charge(weapon: ItemStack, version) -> None:
    if tuple(version) >= tools.COMPONENTS_VERSION:
        set_component(weapon, "minecraft:charged_projectiles", List())
    else:
        weapon.tag["Charged"] = Byte(0)
        weapon.tag["ChargedProjectiles"] = List()


def _spawn_arrow(state, player, projectile: ItemStack, weapon: ItemStack) -> None:
    """ArrowItem.createArrow and Projectile.shoot along the player's view."""
    item = projectile.copy()
    item.count = 1
    intangible = "minecraft:intangible_projectile" in item.patch
    item.patch.pop("minecraft:intangible_projectile", None)
    motion = _movement(_view_vector(player), state.resources.random)
    horizontal = math.sqrt(motion[0] ** 2 + motion[2] ** 2)
    yaw = float(F32(mth.atan2(motion[0], motion[2]) * 57.2957763671875))
    pitch = float(F32(mth.atan2(motion[1], horizontal) * 57.2957763671875))
    x, y, z = player.pos
    data = Compound(Owner=IntArray(Int(v) for v in player.uuid), pickup=Byte(2 if intangible else 1),
                    crit=Byte(1), damage=Double(2.0), item=to_nbt(item, state.version),
                    weapon=to_nbt(weapon, state.version), Motion=List(Double(v) for v in motion))
    data["Rotation"] = List([Float(yaw), Float(pitch)])
    state.entities.summon(ARROW_ENTITIES[projectile.id], (x, y + float(player.eye_height) - float(F32(0.1)), z),
                          data, yaw=yaw, pitch=pitch, dimension=player.dimension)


def _view_vector(player) -> tuple[float, float, float]:
    """Entity.calculateViewVector(xRot, yRot) in float math."""
    pitch = F32(player.pitch) * F32(math.pi / 180)
    yaw = -F32(player.yaw) * F32(math.pi / 180)
    h, i, j, k = mth.cos(yaw), mth.sin(yaw), mth.cos(pitch), mth.sin(pitch)
    return float(i * j), float(-k), float(h * j)


def _movement(view, rng) -> tuple[float, float, float]:
    """Projectile.getMovementToShoot: normalize, add a triangle spread per axis, scale by the power."""
    length = math.sqrt(sum(v * v for v in view))
    unit = [v / length for v in view] if length >= 1.0E-5 else [0.0, 0.0, 0.0]
    spread = SPREAD * INACCURACY
    power = float(F32(CROSSBOW_ARROW_POWER))
    return tuple((u + spread * (rng.random() - rng.random())) * power for u in unit)
