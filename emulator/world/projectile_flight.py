"""Arrows, tridents, snowballs and thrown items (eggs, ender pearls, experience bottles, potions)
moved tick by tick as the game moves them (from 1.20.5, when gravity became the entity's own
double): motion, gravity, drag and rotation, hitting blocks and entities (arrows stick:
``inGround``; a thrown one's hit ends it: :mod:`emulator.world.thrown_hits`), lying in the ground
(``life``, despawning after 1200 ticks, falling when the block under them goes).

- ``MODELLED``: the types moved here; ``step(state, entity)``: one tick of one of them.

A snowball that meets a living entity hurts it by 0 (3 a blaze) as ``thrown`` damage its owner is
responsible for (HurtTime, ``player_hurt_entity`` with the snowball as direct entity) and breaks;
the hit's knockback is not modelled.

In water at the start of its tick (:func:`emulator.world.fluids.in_water`) its motion is scaled
by 0.6F (an arrow), 0.99F (a trident) or 0.8F (a thrown one) instead of 0.99F.

Gravity (getDefaultGravity): 0.05 an arrow or a potion, 0.07 an experience bottle, 0.03 a
snowball, egg or ender pearl. Until it has left its owner (Projectile.checkLeftOwner: neither the
owner nor what rides with it in its box stretched along its motion and inflated by 1, then
``LeftOwner``) a projectile does not hit them (Projectile.canHitEntity); the check comes first in
an arrow's tick and a 1.21 thrown one's, after the move in a 1.21.2+ thrown one's.

Each tick (AbstractArrow.tick; ThrowableProjectile.tick) the projectile clips the segment from its
position along its motion against the blocks' collision shapes (:mod:`emulator.world.ray`). An
arrow in flight moves along its motion (to the hit when it hits: AbstractArrow.onHitBlock), its
motion scaled by 0.99F and gravity 0.05 taken from it (not when it stuck, from 1.21.2); a thrown
one's gravity and drag come before its move from 1.21.2, after it before. A thrown one's hit
(ThrowableProjectile.tick: hitTargetOrDeflectSelf) acts in 1.21 from where it stood at the start of
the tick, from 1.21.2 from the hit (an entity's: its position, EntityHitResult(entity)). The rotation turns a fifth of the way to the motion's (lerpRotation);
before 1.21.2 an arrow whose previous rotation is 0, 0 takes the motion's at once.

A block hit (1.21 / 1.21.2+): the arrow's motion becomes the way to the hit, it steps back 0.05
along it and keeps moving by it (``inGround``, ``shake`` 7, ``crit`` and ``PierceLevel`` 0,
``inBlockState``); from 1.21.2 it stands at the hit less 0.05 along each axis it moved on, with no
motion. An arrow in the ground counts ``life`` to 1200 (then it is gone) unless the block it
sits in changed and nothing is within 0.06 of it (AbstractArrow.shouldFall: it falls again).

An arrow that meets a living entity first hurts it by ceil(speed x ``damage``) as ``arrow``
damage its owner is responsible for and is gone (AbstractArrow.onHitEntity); a spectral arrow's
target glows for the arrow's ``Duration`` (SpectralArrow.doPostHurtEffects). A burning arrow
(:func:`emulator.world.burning.is_on_fire`) first sets what it hits on fire for 100 ticks
(igniteForSeconds(5.0F)); its own ``Fire`` counts down as any entity's (:mod:`emulator.world.burning`).

Not modelled (raises Unmodelled, the test is inconclusive): a critical, piercing or tipped arrow's
hit, a trident's, a spectral arrow hitting a player, an arrow bouncing off (a hurt that fails), a player's arrow
hitting a player, ``killed_by_arrow``, what :mod:`emulator.world.thrown_hits` does not model of a
thrown one's hit, a projectile in flowing water (its current) or passing blocks that act on what is inside them
(pressure plates, buttons, tripwires, cobwebs, fire, portals ...), hitting a target block or TNT,
an arrow falling with motion (random), a player picking an arrow up, catching fire on the way, a
trident with Loyalty, other projectiles (fireballs, wind charges, llama spit ...) and releases
before 1.20.5 (gravity was a float then).

Sources (decompiled 1.21, and 1.21.2+ from the decompiled classes the wiki's search reaches):
world/entity/projectile/AbstractArrow.java (tick, stepMoveAndHit, onHitBlock, shouldFall,
startFalling, tickDespawn, getWaterInertia), ThrowableProjectile.java (tick, applyInertia,
getDefaultGravity), Projectile.java (updateRotation, lerpRotation, canHitEntity, checkLeftOwner),
ProjectileUtil.java (getEntityHitResult: the nearest box, inflated by 0.3, the segment enters),
ThrownPotion.java, ThrownExperienceBottle.java (getDefaultGravity), ThrownTrident.java, damagesource/DamageSources.java (thrown), world/entity/Entity.java (applyGravity, getGravity).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import block_shapes, burning, combat, fluids, living, mth, ray, thrown_hits
from emulator.world.errors import Unmodelled
from emulator.world.items import enchantment_level, enchantment_levels, from_nbt
from emulator.world.loot_context import DamageSource
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Byte, Compound, Short, String

F32 = np.float32
ARROWS = frozenset(("minecraft:arrow", "minecraft:spectral_arrow", "minecraft:trident"))
# ThrowableProjectile.getDefaultGravity 0.03; ThrownPotion 0.05 (1.21.5+ AbstractThrownPotion); ThrownExperienceBottle 0.07
THROWN_GRAVITY = {**dict.fromkeys(("minecraft:snowball", "minecraft:egg", "minecraft:ender_pearl"), 0.03),
                  **dict.fromkeys(thrown_hits.POTIONS, 0.05), "minecraft:experience_bottle": 0.07}
THROWN = frozenset(THROWN_GRAVITY)
MODELLED = ARROWS | THROWN
FIRST_RELEASE = (1, 20, 5)  # Entity.getDefaultGravity (a double) from here
STEP_AND_HIT = (1, 21, 2)  # AbstractArrow.stepMoveAndHit; throwables' gravity and drag before the move
ARROW_GRAVITY = 0.05
DRAG = float(F32(0.99))  # 0.99F widened
THROWN_WATER_INERTIA = float(F32(0.8))
_WATER_INERTIA = {"minecraft:arrow": float(F32(0.6)), "minecraft:spectral_arrow": float(F32(0.6)),
                  "minecraft:trident": DRAG}  # AbstractArrow.getWaterInertia; ThrownTrident 0.99F
HIT_STEP = float(F32(0.05))  # 0.05F widened
DESPAWN = 1200
SHAKE = 7
BASE_DAMAGE = 2.0  # AbstractArrow.baseDamage
SPECTRAL_GLOWING = 200  # SpectralArrow.duration
ARROW_IGNITES = 100  # AbstractArrow.onHitEntity: igniteForSeconds(5.0F)
_PLAIN_ARROWS = frozenset(("minecraft:arrow", "minecraft:spectral_arrow"))
ENTITY_MARGIN = 0.3  # ProjectileUtil: the target's box inflated by 0.3
_RAD_TO_DEG = float(mth.RAD_TO_DEG)
_LERP = F32(0.2)
# not pickable (Entity.isPickable false): what a projectile flies through
_NOT_PICKABLE = frozenset("minecraft:" + n for n in (
    "marker item experience_orb area_effect_cloud block_display item_display text_display lightning_bolt "
    "evoker_fangs arrow spectral_arrow trident snowball egg ender_pearl experience_bottle potion splash_potion "
    "lingering_potion llama_spit firework_rocket eye_of_ender fishing_bobber").split())
# blocks whose entityInside or collision a projectile feels beyond a plain shape
_ACTS_INSIDE = ("_pressure_plate", "_button", "tripwire", "cobweb", "fire", "lava", "water", "sweet_berry_bush",
                "powder_snow", "portal", "bubble_column", "kelp", "seagrass", "honey_block", "cactus")
# living entities whose hurt by an arrow is their own: an enderman teleports, an armor stand breaks
_OWN_HURT = frozenset(("minecraft:enderman", "minecraft:armor_stand"))
_HIT_REACTIONS = frozenset(("minecraft:target", "minecraft:tnt"))  # BlockBehaviour.onProjectileHit
SOUND_HIT = "minecraft:entity.arrow.hit"


def step(state, entity) -> None:
    """One tick of an arrow, trident, snowball or thrown item (:data:`MODELLED`)."""
    if tuple(state.version) < FIRST_RELEASE:
        raise Unmodelled(f"{entity.type} in flight before 1.20.5")
    if entity.type in ARROWS:
        _arrow(state, entity)
    else:
        _thrown(state, entity)


# ---------------------------------------------------------------------- arrows
def _arrow(state, entity) -> None:
    data, new = entity.data, tuple(state.version) >= STEP_AND_HIT
    if entity.type == "minecraft:trident" and _loyal(entity):
        raise Unmodelled("a trident with Loyalty (it returns to its owner)")
    _check_left_owner(state, entity)  # Projectile.tick, first in AbstractArrow.tick
    yaw0, pitch0 = entity.yaw, entity.pitch
    motion = tuple(entity.motion)
    if not new and yaw0 == 0.0 and pitch0 == 0.0:  # 1.21: the first rotation is the motion's
        yaw0, pitch0 = _angles(motion)
        entity.yaw, entity.pitch = yaw0, pitch0
    blocks = state.blocks_in(entity.dimension)
    cell = tuple(math.floor(c) for c in entity.pos)
    here = blocks.get(cell)
    if not here.is_air and block_shapes.collides(here):  # a full cube holds the arrow
        data["inGround"] = Byte(1)
    if _int(data, "shake", 0) > 0:
        data["shake"] = Byte(_int(data, "shake", 0) - 1)
    if _int(data, "inGround", 0):
        _in_ground(state, entity, here)
        return
    inertia = _inertia(blocks, entity, motion)
    if new:
        _arrow_moves(state, entity, motion, yaw0, pitch0, inertia)
    else:
        _arrow_moves_1_21(state, entity, motion, yaw0, pitch0, inertia)


def _arrow_moves(state, entity, motion, yaw0, pitch0, inertia: float) -> None:
    """1.21.2+: turn toward the motion, move to the first hit (or along the motion), then drag and
    gravity unless it stuck."""
    start = entity.pos
    end = _add(start, motion)
    hit, gone = _hits(state, entity, start, end, motion)
    if gone:
        return
    yaw, pitch = _angles(motion)
    entity.pitch, entity.yaw = _lerp_rotation(pitch0, pitch), _lerp_rotation(yaw0, yaw)
    entity.pos = hit[0] if hit else end
    if hit:
        _stick(state, entity, hit, tuple(-HIT_STEP * _sign(m) for m in motion))
        entity.motion = (0.0, 0.0, 0.0)
    entity.motion = _scaled(entity.motion, inertia)
    if not _int(entity.data, "inGround", 0):
        _fall(entity, ARROW_GRAVITY)


def _arrow_moves_1_21(state, entity, motion, yaw0, pitch0, inertia: float) -> None:
    """1.21: a hit turns the motion toward it (onHitBlock) and the arrow moves by it from 0.05 back;
    then it turns, drags and falls."""
    start = entity.pos
    hit, gone = _hits(state, entity, start, _add(start, motion), motion)
    if gone:
        return
    if hit:
        motion = tuple(h - s for h, s in zip(hit[0], start))
        length = math.sqrt(sum(m * m for m in motion))
        back = (0.0, 0.0, 0.0) if length < 1.0E-4 else tuple(m / length * HIT_STEP for m in motion)
        entity.pos = tuple(s - b for s, b in zip(start, back))
        _stick(state, entity, hit, (0.0, 0.0, 0.0))
    yaw, pitch = _angles(motion)
    entity.pitch, entity.yaw = _lerp_rotation(pitch0, pitch), _lerp_rotation(yaw0, yaw)
    entity.pos = _add(entity.pos, motion)
    entity.motion = _scaled(motion, inertia)
    _fall(entity, ARROW_GRAVITY)


def _stick(state, entity, hit, back) -> None:
    """AbstractArrow.onHitBlock: the block it hit is its ``inBlockState``; it steps back."""
    location, cell = hit
    block = state.blocks_in(entity.dimension).get(cell)
    if block.id in _HIT_REACTIONS:
        raise Unmodelled(f"{entity.type} hitting {block.id} (its reaction to projectiles)")
    entity.pos = _add(entity.pos, back)
    data = entity.data
    data["inBlockState"] = _state_tag(block)
    data["inGround"], data["shake"] = Byte(1), Byte(SHAKE)
    data["crit"], data["PierceLevel"] = Byte(0), Byte(0)
    data["SoundEvent"] = String(SOUND_HIT)


def _in_ground(state, entity, here) -> None:
    """A stuck arrow: it falls again when the block it sits in is not the one it hit and nothing
    is within 0.06 of it (shouldFall; startFalling scales its motion by random factors, so only a
    still one is followed), else ``life`` counts to its despawn."""
    data = entity.data
    _no_player_picks_up(state, entity)
    if data.get("inBlockState") != _state_tag(here) and _nothing_near(state, entity):
        if any(m != 0.0 for m in entity.motion):
            raise Unmodelled(f"{entity.type} falling out of the ground (its motion scaled by random factors)")
        data["inGround"] = Byte(0)
        data["life"] = Short(0)
        return
    life = _int(data, "life", 0) + 1
    data["life"] = Short(life)
    if life >= DESPAWN:
        state.discard(entity)


def _nothing_near(state, entity) -> bool:
    """Level.noCollision of the point's box inflated by 0.06 (blocks only here)."""
    x, y, z = entity.pos
    box = (x - 0.06, y - 0.06, z - 0.06, x + 0.06, y + 0.06, z + 0.06)
    blocks = state.blocks_in(entity.dimension)
    return not any(not blocks.get(c).is_air and block_shapes.collides(blocks.get(c)) for c in ray.box_cells(box))


def _no_player_picks_up(state, entity) -> None:
    """Player.touch -> AbstractArrow.playerTouch: a player within 1 (0.5 up and down) of a stuck
    arrow that stopped shaking takes it (or tries to)."""
    if _int(entity.data, "shake", 0) > 0:
        return
    box = entity.bounding_box
    for player in state.entities.players():
        if player.alive and player.gamemode != "spectator" and player.dimension == entity.dimension:
            near = _inflate(player.bounding_box, 1.0, 0.5, 1.0)
            if ray.boxes_meet(near, box):
                raise Unmodelled(f"{player.display_name} touching a stuck {entity.type} (picking it up)")


# ---------------------------------------------------------------------- thrown
def _thrown(state, entity) -> None:
    """ThrowableProjectile.tick: 1.21 checks whether it left its owner (Projectile.tick), finds
    the hit along its motion from where it stands, then moves, drags and falls; 1.21.2+ falls and
    drags first, moves to the hit (an entity's: to the entity's position, EntityHitResult(entity)),
    then checks its owner. A hit ends it (:func:`emulator.world.thrown_hits.hit`)."""
    blocks = state.blocks_in(entity.dimension)
    motion = tuple(entity.motion)
    inertia = _inertia(blocks, entity, motion)
    new = tuple(state.version) >= STEP_AND_HIT
    if new:  # gravity, then drag, then the move by the new motion
        motion = _scaled(_fallen(entity, motion, THROWN_GRAVITY[entity.type]), inertia)
        entity.motion = motion
    else:
        _check_left_owner(state, entity)
    start = entity.pos
    hit = ray.clip_blocks(blocks, start, _add(start, motion))
    target = _entity_hit(state, entity, start, hit[0] if hit else _add(start, motion))
    yaw, pitch = _angles(motion)
    if new:
        entity.pos = target.pos if target is not None else hit[0] if hit else _add(start, motion)
        entity.pitch, entity.yaw = _lerp_rotation(entity.pitch, pitch), _lerp_rotation(entity.yaw, yaw)
        _check_left_owner(state, entity)
    if target is None and hit:
        block = blocks.get(hit[1])
        if block.id in _HIT_REACTIONS:
            raise Unmodelled(f"{entity.type} hitting {block.id} (its reaction to projectiles)")
    if target is not None or hit:
        thrown_hits.hit(state, entity, target, None if target is not None else hit[1])  # 1.21: from where it stood
        return
    if not new:
        entity.pitch, entity.yaw = _lerp_rotation(entity.pitch, pitch), _lerp_rotation(entity.yaw, yaw)
        entity.pos = _add(start, motion)
        entity.motion = _scaled(motion, inertia)
        _fall(entity, THROWN_GRAVITY[entity.type])


def _check_left_owner(state, entity) -> None:
    """Projectile.checkLeftOwner, until it did (``LeftOwner``): no pickable entity riding with its
    owner (the owner itself too) in its box stretched along its motion and inflated by 1."""
    data = entity.data
    if _int(data, "LeftOwner", 0):
        return
    owner = thrown_hits.owner(state, entity)
    if owner is not None:
        near = _inflate(_swept(entity.bounding_box, entity.motion), 1.0, 1.0, 1.0)
        riding = thrown_hits.root(owner)
        if any(ray.boxes_meet(near, other.bounding_box) and thrown_hits.root(other) is riding
               for other in _pickable(state, entity)):
            return
    data["LeftOwner"] = Byte(1)


# ---------------------------------------------------------------------- shared
def _hits(state, entity, start, end, motion):
    """The block the segment hits first, ``(location, cell)`` or None, and whether an entity in the
    way (nearer than that block) took the arrow (:func:`_arrow_hits`)."""
    hit = ray.clip_blocks(state.blocks_in(entity.dimension), start, end)
    target = _entity_hit(state, entity, start, hit[0] if hit else end)
    if target is None:
        return hit, False
    _arrow_hits(state, entity, target, motion)
    return None, True


def _arrow_hits(state, arrow, target, motion) -> None:
    """AbstractArrow.onHitEntity for a plain or spectral arrow: ceil(speed x ``damage``) as ``arrow``
    damage of its owner (else of the arrow), a spectral arrow's glowing for its ``Duration``, then
    it is gone. A critical arrow's random bonus, piercing, tipped arrows' effects, a weapon's
    enchantments, a hurt that fails (the arrow bounces back), an enderman, a player shooting a
    player (teams), a spectral arrow hitting a player, the ``killed_by_arrow`` criterion and a
    trident's hit raise Unmodelled."""
    data = arrow.data
    reason = None
    spectral = arrow.type == "minecraft:spectral_arrow"
    if arrow.type not in _PLAIN_ARROWS or not living.is_living(target.type) or target.type in _OWN_HURT \
            or (spectral and target.is_player):
        reason = f"{arrow.type} hitting {target.type}"
    elif _int(data, "crit", 0):
        reason = "a critical arrow's bonus damage (random)"
    elif _int(data, "PierceLevel", 0) > 0:
        reason = "an arrow piercing what it hits"
    elif _tipped(data) or _enchanted(data.get("weapon")):
        reason = "a tipped arrow's effects or its weapon's enchantments on a hit"
    owner = thrown_hits.owner(state, arrow)
    if reason is None and target.is_player and owner is not None and owner.is_player:
        reason = "an arrow of a player hitting a player (Player.canHarmPlayer: teams)"
    if reason is not None:
        raise Unmodelled(reason)
    speed = float(F32(math.sqrt(sum(m * m for m in motion))))
    base = float(numeric_value(data["damage"])) if is_numeric(data.get("damage")) else BASE_DAMAGE
    damage = _ceil(min(max(speed * base, 0.0), 2.147483647E9))
    fire_before = target.data.get("Fire")
    if burning.is_on_fire(arrow):  # a burning arrow sets what it hits on fire for 5 seconds
        burning.ignite_for_ticks(target, ARROW_IGNITES)
    if not combat.hurt(state, target, float(damage), DamageSource("minecraft:arrow", owner or arrow, arrow)):
        if fire_before is not None:
            target.data["Fire"] = fire_before  # its fire as it was (setRemainingFireTicks)
        raise Unmodelled(f"an arrow bouncing off {target.type} (its hurt failed: ProjectileDeflection.REVERSE)")
    if spectral:  # SpectralArrow.doPostHurtEffects: glowing for its Duration
        living.give_effect(state, target, "minecraft:glowing", _int(data, "Duration", SPECTRAL_GLOWING), 0, True)
    if arrow.alive:
        state.discard(arrow)
    if owner is not None and owner.is_player and not target.alive:
        raise Unmodelled("the killed_by_arrow criterion")


def _tipped(data: Compound) -> bool:
    item = data.get("item")
    components = item.get("components") if isinstance(item, Compound) else None
    return any(key in data for key in ("Potion", "custom_potion_effects", "CustomPotionEffects", "Color")) or (
        isinstance(components, Compound) and "minecraft:potion_contents" in components)


def _enchanted(weapon) -> bool:
    return isinstance(weapon, Compound) and len(enchantment_levels(from_nbt(weapon))) > 0


def _ceil(x: float) -> int:
    """Mth.ceil(double)."""
    whole = int(x)
    return whole + 1 if x > whole else whole


def _entity_hit(state, entity, start, end):
    """ProjectileUtil.getEntityHitResult: of the entities it can hit, the one whose box (inflated by
    0.3) the segment enters nearest its start."""
    best, nearest = None, math.inf
    for other in _targets(state, entity):
        location = ray.clip(_inflate(other.bounding_box, ENTITY_MARGIN, ENTITY_MARGIN, ENTITY_MARGIN), start, end)
        if location is not None:
            distance = sum((a - b) ** 2 for a, b in zip(location, start))
            if distance < nearest:
                best, nearest = other, distance
    return best


def _targets(state, entity):
    """What the projectile could hit (Projectile.canHitEntity): what is pickable, but what rides
    with its owner (the owner too) until it left it (``LeftOwner``)."""
    owner = None if _int(entity.data, "LeftOwner", 0) else thrown_hits.owner(state, entity)
    riding = None if owner is None else thrown_hits.root(owner)
    for other in _pickable(state, entity):
        if riding is None or thrown_hits.root(other) is not riding:
            yield other


def _pickable(state, entity):
    """Entity.canBeHitByProjectile: alive, pickable, not a spectator."""
    for other in state.entities.entities:
        if (other is entity or not other.alive or other.type in _NOT_PICKABLE or other.dimension != entity.dimension
                or (other.is_player and other.gamemode == "spectator")
                or (other.type == "minecraft:armor_stand" and _int(other.data, "Marker", 0))):
            continue
        yield other


def _inertia(blocks, entity, motion) -> float:
    """The factor its motion is scaled by this tick: 0.99F, in water (Entity.isInWater, from where
    it stands at the start of the tick) 0.6F an arrow's, 0.99F a trident's, 0.8F a thrown one's
    (AbstractArrow.getWaterInertia, ThrowableProjectile). Water that pushes (a flow: its current)
    and blocks that act on what passes through them (pressure plates, cobwebs, fire ...) on its way
    are not modelled: they raise Unmodelled."""
    for cell in ray.box_cells(_swept(entity.bounding_box, motion)):
        block = blocks.get(cell)
        if block.is_air or block.id == "minecraft:water":
            continue
        name = block.id.removeprefix("minecraft:")
        if any(part in name for part in _ACTS_INSIDE):
            raise Unmodelled(f"{entity.type} in or through {block.id}")
    box = entity.bounding_box
    flowing = fluids.pushing(blocks, box)
    if flowing is not None:
        raise Unmodelled(f"{entity.type} in flowing water at {flowing} (its current)")
    if not fluids.in_water(blocks, box):
        return DRAG
    return _WATER_INERTIA.get(entity.type, THROWN_WATER_INERTIA)


def _loyal(entity) -> bool:
    item = entity.data.get("item") or entity.data.get("Trident")
    return isinstance(item, Compound) and enchantment_level(from_nbt(item), "minecraft:loyalty") > 0


def _angles(motion) -> tuple[np.float32, np.float32]:
    """The motion's yaw and pitch: ``(float)(Mth.atan2(x, z) * RAD_TO_DEG)`` and of y over the
    horizontal distance."""
    x, y, z = motion
    return F32(mth.atan2(x, z) * _RAD_TO_DEG), F32(mth.atan2(y, math.sqrt(x * x + z * z)) * _RAD_TO_DEG)


def _lerp_rotation(current, target) -> np.float32:
    """Projectile.lerpRotation: the current angle brought within 180 of the target, then a fifth
    of the way (Mth.lerp in float)."""
    current, target = F32(current), F32(target)
    while target - current < F32(-180.0):
        current = F32(current - F32(360.0))
    while target - current >= F32(180.0):
        current = F32(current + F32(360.0))
    return F32(current + _LERP * F32(target - current))


def _fall(entity, gravity: float) -> None:
    entity.motion = _fallen(entity, entity.motion, gravity)


def _fallen(entity, motion, gravity: float):
    """Entity.applyGravity: getGravity is 0 with ``NoGravity``."""
    if _int(entity.data, "NoGravity", 0):
        return tuple(motion)
    x, y, z = motion
    return (x, y - gravity, z)


def _scaled(v, factor: float):
    return tuple(c * factor for c in v)


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _sign(x: float) -> float:
    return 0.0 if x == 0.0 else math.copysign(1.0, x)


def _swept(box, motion):
    """AABB.expandTowards: the box stretched along the motion."""
    return tuple(min(b, b + m) for b, m in zip(box[:3], motion)) + tuple(max(b, b + m) for b, m in zip(box[3:], motion))


def _inflate(box, dx, dy, dz):
    return (box[0] - dx, box[1] - dy, box[2] - dz, box[3] + dx, box[4] + dy, box[5] + dz)


def _int(data: Compound, key: str, default: int) -> int:
    value = data.get(key)
    return int(numeric_value(value)) if is_numeric(value) else default


def _state_tag(block) -> Compound:
    """NbtUtils.writeBlockState: ``Name`` and, when it has any, ``Properties``."""
    tag = Compound(Name=String(block.id))
    if block.properties:
        tag["Properties"] = Compound({k: String(v) for k, v in block.properties})
    return tag
