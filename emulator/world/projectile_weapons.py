"""Bows and crossbows in a player's hands: whether they can be drawn, and a charged crossbow's shot.

- ``ammunition(state, player, weapon) -> ItemStack``: Player.getProjectile: an arrow (or, for a
  crossbow, a firework rocket) in either hand, else the first arrow of the inventory, else for a
  creative player a plain arrow; empty when there is none.
- ``shoot_charged(state, player, hand, access)``: CrossbowItem.performShooting: the charged
  projectiles are cleared from the crossbow and each is shot, turned by its share of the multishot
  spread (10 degrees a level, split evenly: 0, +10, -10 for three) about the player's up vector:
  an arrow at the eyes less 0.1, owned by the player (``Owner``), ``pickup`` allowed
  (creative-only for an ``intangible_projectile``), ``crit``, ``damage`` 2, ``item``, ``weapon``
  and Piercing's ``PierceLevel``; a firework rocket at the eyes less 0.15 (``FireworksItem``,
  ``ShotAtAngle``, ``LifeTime`` from its flight). They fly at 3.15 blocks per tick (1.6 when a
  rocket is among them) with the game's inaccuracy 1 (Projectile.getMovementToShoot: a triangle
  spread of 0.0172275 per axis, drawn from the emulator's random, not the projectile's own: the
  motion's last digits differ from the game's, and the turn is worked out in double, not float),
  their rotation from their motion; the crossbow wears by one per arrow and three per rocket
  (emulator.world.tools), ``minecraft.used:crossbow`` and ``shot_crossbow``.

- ``throw(state, player, stack)``: SnowballItem/EggItem/EnderpearlItem.use (1.5 blocks per tick along
  the view), ThrowablePotionItem.use (0.5, 20 degrees up) and ExperienceBottleItem.use (0.7, 20 up):
  the item's projectile at the eyes less 0.1, owned by the player, with inaccuracy 1 (the spread
  drawn from the emulator's random, as above).

A bow is drawn by ``use item`` and only shoots when released, which PackTest has no action for: a
dummy never shoots one, as in the game. Arrows and snowballs fly (emulator.world.projectile_flight);
a rocket does not move here (it never explodes). Not modelled (Unmodelled): another charged item, a
crossbow enchantment other than Multishot, Piercing, Quick Charge, Unbreaking, Mending and Curse of
Vanishing.

Sources (decompiled 1.21.x and 26.1): world/item/BowItem.java and CrossbowItem.java (use,
performShooting, getShootingPower, shootProjectile), ProjectileWeaponItem.java (shoot,
createProjectile, ARROW_ONLY / ARROW_OR_FIREWORK), world/entity/player/Player.java (getProjectile),
world/entity/projectile/Projectile.java (shoot, shootFromRotation, getMovementToShoot),
world/item/SnowballItem.java, EggItem.java, EnderpearlItem.java, ThrowablePotionItem.java,
ExperienceBottleItem.java, ThrowableItemProjectile.java (eyes - 0.1F), arrow/AbstractArrow.java
(constructor: eyes - 0.1; setOwner; addAdditionalSaveData), FireworkRocketEntity.java (constructor,
addAdditionalSaveData), Entity.calculateViewVector and calculateUpVector, Enchantments.java
(MULTISHOT, PIERCING).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import advancements, inventories, mth, projectiles, statistics, tools
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack, enchantment_levels, from_nbt, set_component, to_nbt
from emulator.world.nbt_ops import numeric_value
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, IntArray, List

F32 = np.float32
ARROWS = frozenset({"minecraft:arrow", "minecraft:tipped_arrow", "minecraft:spectral_arrow"})  # #arrows
CROSSBOW_ARROW_POWER = 3.15  # CrossbowItem.getShootingPower
FIREWORK_POWER = 1.6  # ... when a firework rocket is charged
FIREWORK = "minecraft:firework_rocket"
MULTISHOT_SPREAD = 10.0  # Enchantments.MULTISHOT: projectile_spread + 10 per level
# the crossbow enchantments whose effect on a shot is modelled (or that have none)
_SHOT_ENCHANTMENTS = frozenset(("minecraft:unbreaking", "minecraft:mending", "minecraft:quick_charge",
                                "minecraft:multishot", "minecraft:piercing", "minecraft:vanishing_curse"))
INACCURACY = 1.0  # CrossbowItem.use: performShooting(..., 1.0F); SnowballItem.use: shootFromRotation(..., 1.0F)
# the items thrown on use: (power, pitch offset) of their shootFromRotation
THROWS = {"minecraft:snowball": (1.5, 0.0), "minecraft:egg": (1.5, 0.0), "minecraft:ender_pearl": (1.5, 0.0),
          "minecraft:splash_potion": (0.5, -20.0), "minecraft:lingering_potion": (0.5, -20.0),
          "minecraft:experience_bottle": (0.7, -20.0)}
POTION_TYPES = (1, 21, 5)  # the splash_potion and lingering_potion entity types
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
    """CrossbowItem.performShooting with the charged projectiles of the crossbow in ``hand_slot``
    (ProjectileWeaponItem.shoot: each turned by its share of the multishot spread about the
    shooter's up vector, CrossbowItem.shootProjectile; the power 1.6 when a firework rocket is
    among them, else 3.15; the crossbow wears by 3 per rocket, 1 per arrow)."""
    access = inventories.entity_slot(player, hand_slot, state.version)
    weapon = access.get()
    projectiles = charged(weapon)
    unknown = [p.id for p in projectiles if p.id not in ARROW_ENTITIES and p.id != FIREWORK]
    if unknown:
        raise Unmodelled(f"shooting {unknown[0]} from a crossbow")
    levels = enchantment_levels(weapon)
    if set(levels) - _SHOT_ENCHANTMENTS:
        raise Unmodelled(f"the crossbow enchantment {sorted(set(levels) - _SHOT_ENCHANTMENTS)[0]} (its effect on the shot)")
    _clear_charge(weapon, state.version)
    access.set(weapon)
    power = FIREWORK_POWER if any(p.id == FIREWORK for p in projectiles) else CROSSBOW_ARROW_POWER
    spread = F32(MULTISHOT_SPREAD * int(levels.get("minecraft:multishot", 0)))
    step = F32(0.0) if len(projectiles) == 1 else F32(2.0) * spread / F32(len(projectiles) - 1)
    angle, sign = F32((len(projectiles) - 1) % 2) * step / F32(2.0), F32(1.0)
    for index, projectile in enumerate(projectiles):
        turn = angle + sign * F32((index + 1) // 2) * step
        sign = -sign
        direction = _turned(_view_vector(player), _up_vector(player), float(turn))
        if projectile.id == FIREWORK:
            _spawn_firework(state, player, projectile, direction, power)
        else:
            _spawn_arrow(state, player, projectile, weapon, direction, power, int(levels.get("minecraft:piercing", 0)))
        tools.hurt_and_break(state, player, access, 3 if projectile.id == FIREWORK else 1)  # getDurabilityUse
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


def _spawn_arrow(state, player, projectile: ItemStack, weapon: ItemStack, direction, power: float,
                 piercing: int) -> None:
    """ArrowItem.createArrow (PierceLevel from Piercing) and Projectile.shoot along ``direction``."""
    item = projectile.copy()
    item.count = 1
    intangible = "minecraft:intangible_projectile" in item.patch
    item.patch.pop("minecraft:intangible_projectile", None)
    motion, yaw, pitch = _shot(direction, power, state.resources.random)
    x, y, z = player.pos
    data = Compound(Owner=IntArray(Int(v) for v in player.uuid), pickup=Byte(2 if intangible else 1),
                    crit=Byte(1), damage=Double(2.0), item=to_nbt(item, state.version),
                    weapon=to_nbt(weapon, state.version), Motion=List(Double(v) for v in motion),
                    PierceLevel=Byte(piercing))
    data["Rotation"] = List([Float(yaw), Float(pitch)])
    projectiles.launched(state, state.entities.summon(
        ARROW_ENTITIES[projectile.id], (x, y + float(player.eye_height) - float(F32(0.1)), z), data, yaw=yaw,
        pitch=pitch, dimension=player.dimension))


def _spawn_firework(state, player, projectile: ItemStack, direction, power: float) -> None:
    """ProjectileWeaponItem.createProjectile for a rocket: a FireworkRocketEntity at the eyes less
    0.15, shot at an angle, owned by the player, its LifeTime 10 x (flight + 1) + nextInt(6) +
    nextInt(7) (from the emulator's random)."""
    item = projectile.copy()
    item.count = 1
    rng = state.resources.random
    lifetime = 10 * (1 + _flight(item)) + rng.randrange(6) + rng.randrange(7)
    motion, yaw, pitch = _shot(direction, power, rng)
    x, y, z = player.pos
    data = Compound(Owner=IntArray(Int(v) for v in player.uuid), Life=Int(0), LifeTime=Int(lifetime),
                    FireworksItem=to_nbt(item, state.version), ShotAtAngle=Byte(1),
                    Motion=List(Double(v) for v in motion))
    data["Rotation"] = List([Float(yaw), Float(pitch)])
    projectiles.launched(state, state.entities.summon(
        "minecraft:firework_rocket", (x, y + float(player.eye_height) - float(F32(0.15)), z), data, yaw=yaw,
        pitch=pitch, dimension=player.dimension))


def throw(state, player, stack: ItemStack) -> None:
    """The throw of SnowballItem, EggItem, EnderpearlItem, ThrowablePotionItem or ExperienceBottleItem
    (:data:`THROWS`): a ThrowableItemProjectile at the eyes less 0.1F, the player its ``Owner``, one
    of the stack as its ``Item``, shot from the player's rotation (Projectile.shootFromRotation:
    its pitch offset on the vertical only, the item's power, inaccuracy 1; a standing player adds
    no movement of its own)."""
    power, pitch_offset = THROWS[stack.id]
    item = stack.copy()
    item.count = 1
    motion, yaw, pitch = _shot(_rotation_vector(player, pitch_offset), power, state.resources.random)
    x, y, z = player.pos
    data = Compound(Owner=IntArray(Int(v) for v in player.uuid), Item=to_nbt(item, state.version),
                    Motion=List(Double(v) for v in motion))
    data["Rotation"] = List([Float(yaw), Float(pitch)])
    projectiles.launched(state, state.entities.summon(
        _thrown_type(stack.id, state.version), (x, y + float(player.eye_height) - float(F32(0.1)), z), data, yaw=yaw,
        pitch=pitch, dimension=player.dimension))


def _thrown_type(item_id: str, version) -> str:
    """A potion flies as ``potion`` before 1.21.5, as ``splash_potion``/``lingering_potion`` after."""
    if item_id in ("minecraft:splash_potion", "minecraft:lingering_potion") and tuple(version) < POTION_TYPES:
        return "minecraft:potion"
    return item_id


def _rotation_vector(player, pitch_offset: float) -> tuple[float, float, float]:
    """Projectile.shootFromRotation's direction in float math: the offset turns only its y (not the
    view vector's floats: Mth.cos is not even in its table)."""
    rad = F32(math.pi / 180)
    yaw, pitch = F32(player.yaw) * rad, F32(player.pitch) * rad
    cos_pitch = mth.cos(pitch)
    return (float(-mth.sin(yaw) * cos_pitch), float(-mth.sin((F32(player.pitch) + F32(pitch_offset)) * rad)),
            float(mth.cos(yaw) * cos_pitch))


def _flight(item: ItemStack) -> int:
    """The rocket's flight duration (the ``fireworks`` component; ``Fireworks.Flight`` before 1.20.5)."""
    fireworks = item.component("minecraft:fireworks")
    if fireworks is None and item.tag is not None:
        fireworks = item.tag.get("Fireworks")
    flight = fireworks.get("flight_duration", fireworks.get("Flight")) if isinstance(fireworks, Compound) else None
    return int(numeric_value(flight)) if flight is not None else 0


def _shot(direction, power: float, rng):
    """Projectile.shoot: the motion and the rotation it gives the projectile."""
    motion = _movement(direction, power, rng)
    horizontal = math.sqrt(motion[0] ** 2 + motion[2] ** 2)
    yaw = float(F32(mth.atan2(motion[0], motion[2]) * 57.2957763671875))
    pitch = float(F32(mth.atan2(motion[1], horizontal) * 57.2957763671875))
    return motion, yaw, pitch


def _up_vector(player) -> tuple[float, float, float]:
    """Entity.calculateUpVector: the view vector of the pitch less 90."""
    return _view_vector(player, pitch_offset=-90.0)


def _turned(vector, axis, degrees: float) -> tuple[float, float, float]:
    """Vector3f.rotate(Quaternionf.setAngleAxis(degrees, axis)), in double math (the game's floats
    differ in the last digits, as the spread's draw does)."""
    if degrees == 0.0:
        return vector
    angle = math.radians(degrees)
    c, s = math.cos(angle), math.sin(angle)
    ax, ay, az = axis
    norm = math.sqrt(ax * ax + ay * ay + az * az)
    ax, ay, az = ax / norm, ay / norm, az / norm
    vx, vy, vz = vector
    dot = ax * vx + ay * vy + az * vz
    cross = (ay * vz - az * vy, az * vx - ax * vz, ax * vy - ay * vx)
    return tuple(v * c + k * s + a * dot * (1 - c) for v, k, a in zip(vector, cross, (ax, ay, az)))


def _view_vector(player, pitch_offset: float = 0.0) -> tuple[float, float, float]:
    """Entity.calculateViewVector(xRot, yRot) in float math."""
    pitch = (F32(player.pitch) + F32(pitch_offset)) * F32(math.pi / 180)
    yaw = -F32(player.yaw) * F32(math.pi / 180)
    h, i, j, k = mth.cos(yaw), mth.sin(yaw), mth.cos(pitch), mth.sin(pitch)
    return float(i * j), float(-k), float(h * j)


def _movement(view, power: float, rng) -> tuple[float, float, float]:
    """Projectile.getMovementToShoot: normalize, add a triangle spread per axis, scale by the power."""
    length = math.sqrt(sum(v * v for v in view))
    unit = [v / length for v in view] if length >= 1.0E-5 else [0.0, 0.0, 0.0]
    spread = SPREAD * INACCURACY
    return tuple((u + spread * (rng.random() - rng.random())) * float(F32(power)) for u in unit)
