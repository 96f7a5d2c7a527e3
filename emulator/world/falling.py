"""Players whose physics the server ticks fall: gravity and drag, landing on blocks (``OnGround``),
the fall distance and fall damage, as LivingEntity.travel and Entity.move do it.

Which players: PackTest's dummies (``Dummy.tick`` calls ``doTick``, so Player.tick -> aiStep ->
travel runs on the server each tick, as for Carpet's fake players). A player that a client
drives (``Emulator.add_player``, ``--player``) moves only by its client's packets: its position
and ``OnGround`` are what the API sets (ServerPlayer.tick does not call travel), so it does not
fall here.

- ``fall(state, player)``: register a player whose physics the server ticks.
- ``tick_falling(state)``: each such player's tick (its move kept in ``state.moves`` for the tick's
  later steps: :mod:`emulator.world.inside_blocks`); ``tick_is_idle(state)``.
- ``jump(state, player)``: LivingEntity.jumpFromGround (Player's: the ``jump`` statistic, exhaustion).
- ``move(state, entity, motion)``: Entity.move for any entity (the one there is: the other entities'
  ticks in :mod:`emulator.world.motion` move through it); ``collide(blocks, box, motion)``:
  Entity.collideBoundingBox against the full cubes, y first, then x and z (Direction.axisStepOrder).
  A stopped horizontal axis zeroes its motion; a living entity that walks into a wall on the ground
  would step up (maxUpStep 0.6): not modelled. Fall damage is a living entity's (not an armor
  stand's: ArmorStand.hurt refuses a fall).

One tick (LivingEntity.aiStep, travel; Entity.move, checkFallDamage):
1. a motion component under 0.003 in size becomes 0;
2. the player moves by its motion, stopped by the full cubes below or above it (Shapes.collide
   along y: the 1.0E-7 tolerance); ``OnGround`` is whether the move was stopped going down;
3. on the ground a fall distance > 0 lands: Player.causeFallDamage (none for creative players:
   ``mayfly``; ``minecraft.custom:minecraft.fall_one_cm`` x 100 from 2 blocks) and
   LivingEntity.calculateFallDamage: ceil((distance - safe_fall_distance) x multiplier x
   fall_damage_multiplier) as ``minecraft:fall`` damage (a hay block's multiplier is 0.2:
   HayBlock.fallOn); the distance is reset. In the air the distance grows by the drop;
4. a stopped vertical move zeroes the vertical motion (Block.updateEntityAfterFallOn);
5. the vertical motion loses the gravity (the ``gravity`` attribute, 0.08; at most 0.01 falling
   with slow falling) or, levitating, moves a fifth of the way to 0.05 x (amplifier + 1), then is
   scaled by 0.98F (travel: ``d2 * 0.98F``, the float widened); slow falling and levitation
   reset the fall distance first (aiStep). A spectator with no motion stays where it is.

So a player standing on a block keeps ``Motion[1]`` = -0.0784000015258789, as in the game, and a
player just placed on a block with no motion is not on the ground for its first tick (its move
is zero, so not stopped going down). The fall distance is the float of 1.21-1.21.4 (1.21.5 made
it a double: a fall distance there can differ in its last bits).

Not modelled (Unmodelled, reported once): a dummy's horizontal motion (friction, stepping up), a
block whose shape is not a full cube or empty, water and lava (they reset and slow the fall),
slime blocks and beds (they bounce), a spectator's motion (no collision).

Sources (decompiled 1.21): world/entity/LivingEntity.java (aiStep, travel, jumpFromGround,
causeFallDamage, calculateFallDamage), world/entity/Entity.java (move, checkFallDamage,
collideBoundingBox), world/entity/player/Player.java (causeFallDamage, jumpFromGround),
world/phys/shapes/VoxelShape.java (collide), world/level/block/{Block,HayBlock,SlimeBlock,
BedBlock}.java (fallOn, updateEntityAfterFallOn); misode/packtest Dummy.java (tick).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import block_shapes, combat, living, relations, statistics
from emulator.world.errors import Unmodelled
from mcfunction_parser.nbt import Byte, Float

F32 = np.float32
EPSILON = 1.0E-7  # Shapes/VoxelShape.collide's tolerance
MIN_MOVEMENT = 0.003  # LivingEntity.aiStep
DRAG = float(F32(0.98))  # travel: d2 * 0.98F
SLOW_FALLING_GRAVITY = 0.01
FALL_MULTIPLIERS = {"minecraft:hay_block": 0.2}  # Block.fallOn's damage multiplier (else 1.0)
BOUNCY = frozenset({"minecraft:slime_block"})  # SlimeBlock.updateEntityAfterFallOn
FLUIDS = frozenset({"minecraft:water", "minecraft:lava", "minecraft:bubble_column"})
JUMP_EXHAUSTION = (0.05, 0.2)  # Player.jumpFromGround: walking, sprinting
HORIZONTAL_EQUAL = float(F32(1.0E-5))  # Mth.equal(double, double): |a - b| < 1.0E-5F
# maxUpStep 0 (Entity.maxUpStep): what walks into a wall without stepping up it
NO_FALL_DAMAGE = frozenset(("minecraft:armor_stand",))
NO_STEP = frozenset("minecraft:" + n for n in ("item", "experience_orb", "falling_block", "tnt"))


def fall(state, player) -> None:
    """From now on the server ticks ``player``'s physics."""
    state.falling.append(player)


def tick_is_idle(state) -> bool:
    return not state.falling


def tick_falling(state) -> None:
    if state.moves:
        state.moves.clear()
    if not state.falling:
        return
    state.falling[:] = [p for p in state.falling if p.alive]
    for player in state.falling:
        try:
            _tick(state, player)
        except Unmodelled as reason:
            state.unmodelled_once("a player's fall", reason)


def jump(state, player) -> None:
    """LivingEntity.jumpFromGround: the motion's y becomes the jump power (jump_strength, plus 0.1
    per jump boost level; a block's jump factor is 1 for the full cubes known here; sprinting
    adds a push forward, not modelled); Player's: ``minecraft.custom:minecraft.jump`` and the food
    exhaustion."""
    if player.sprinting:
        raise Unmodelled("a sprinting jump (its push forward)")
    power = F32(living.attribute_value(player, "jump_strength"))  # getJumpPower (a float)
    boost = living.effect_amplifier(player, "minecraft:jump_boost")
    if boost is not None:  # getJumpBoostPower: 0.1F x (amplifier + 1)
        power = power + F32(0.1) * F32(boost + 1)
    x, _, z = player.motion
    if power > F32(1.0E-5):
        player.motion = (x, float(power), z)
    statistics.award(state, player, statistics.stat_name("custom", "jump"))
    living.exhaust(player, F32(JUMP_EXHAUSTION[0]))


def _tick(state, player) -> None:
    if living.health(player) <= 0:
        return
    if relations.vehicle_of(player) is not None:  # Entity.rideTick instead of travel
        relations.ride_tick(player)
        return
    x, y, z = (0.0 if abs(m) < MIN_MOVEMENT else m for m in player.motion)
    if player.gamemode == "spectator":  # no physics, flying: with no motion it stays (Player.travel)
        if x or y or z:
            raise Unmodelled("a spectator's movement (no collision)")
        return
    if x or z:
        raise Unmodelled("horizontal motion (friction, walls, stepping up)")
    keep_falls_short(player)
    before = player.pos
    _, y, _ = move(state, player, (x, y, z))
    state.moves[player] = (before, player.pos)
    player.motion = (x, vertical_after(player, y, living.attribute_value(player, "gravity")) * DRAG, z)


def keep_falls_short(entity) -> None:
    """LivingEntity.aiStep: slow falling and levitation reset the fall distance before travel."""
    if (living.effect_amplifier(entity, "minecraft:slow_falling") is not None
            or living.effect_amplifier(entity, "minecraft:levitation") is not None):
        entity.data["FallDistance"] = Float(0.0)


def vertical_after(entity, y: float, gravity: float) -> float:
    """LivingEntity.travelInAir's vertical motion after the move ``y``, before the drag: levitation
    pulls it towards 0.05 x (amplifier + 1) by a fifth; else the gravity is taken (at most 0.01
    falling with slow falling: getEffectiveGravity)."""
    levitation = living.effect_amplifier(entity, "minecraft:levitation")
    if levitation is not None:
        return y + (0.05 * (levitation + 1) - y) * 0.2
    if y <= 0.0 and living.effect_amplifier(entity, "minecraft:slow_falling") is not None:
        gravity = min(gravity, SLOW_FALLING_GRAVITY)
    return y - gravity


def move(state, entity, motion) -> tuple[float, float, float]:
    """Entity.move for the full cubes known here: ``entity`` moves by ``motion`` as far as the blocks
    let it (Entity.collide), ``OnGround`` is whether a move down was stopped, the fall distance
    lands or grows (checkFallDamage), a stopped axis's motion becomes 0 (a horizontal one:
    Entity.move; the vertical one: Block.updateEntityAfterFallOn). Returns the motion after it
    (the entity's ``motion`` is left to the caller)."""
    dx, dy, dz = motion
    blocks = state.blocks_in(entity.dimension)
    (mx, my, mz), below = collide(blocks, entity.bounding_box, motion)
    if mx * mx + my * my + mz * mz > EPSILON:  # Entity.move: lengthSqr > 1.0E-7
        px, py, pz = entity.pos
        entity.pos = (px + mx, py + my, pz + mz)
    stopped_x, stopped_z = abs(mx - dx) >= HORIZONTAL_EQUAL, abs(mz - dz) >= HORIZONTAL_EQUAL  # !Mth.equal
    stopped_y = my != dy
    on_ground = stopped_y and dy < 0.0
    if (stopped_x or stopped_z) and entity.type not in NO_STEP and (on_ground or int(entity.data.get("OnGround", 0))):
        raise Unmodelled("a mob walking into a wall (stepping up)")
    entity.data["OnGround"] = Byte(int(on_ground))
    _check_fall_damage(state, entity, my, on_ground, below)
    if on_ground and below is not None and below.id in BOUNCY:
        raise Unmodelled(f"landing on {below.id} (it bounces)")
    return (0.0 if stopped_x else dx), (0.0 if stopped_y else dy), (0.0 if stopped_z else dz)


def collide(blocks, box, motion):
    """Entity.collideBoundingBox for the full cubes around ``box`` (Shapes.collide, axis by axis:
    y, then the larger of x and z last, Direction.axisStepOrder): the move allowed, and the block
    a move down stopped on (else None)."""
    dx, dy, dz = motion
    box = list(box)
    stop = None
    order = (1, 2, 0) if abs(dx) < abs(dz) else (1, 0, 2)
    moved = [dx, dy, dz]
    for axis in order:
        d, block = _collide_axis(blocks, box, axis, moved[axis])
        moved[axis] = d
        box[axis] += d
        box[axis + 3] += d
        if axis == 1:
            stop = block
    return tuple(moved), stop


def _collide_axis(blocks, box, axis: int, d: float):
    """VoxelShape.collide along one axis: the distance ``box`` may go before a full cube (the 1.0E-7
    tolerance), and the block that stopped it."""
    if abs(d) < EPSILON:
        return 0.0, None
    lo, hi = box[axis], box[axis + 3]
    span = [(math.floor(box[a]), math.ceil(box[a + 3])) for a in range(3)]
    span[axis] = (math.floor(lo + d), math.ceil(hi)) if d < 0 else (math.floor(lo), math.ceil(hi + d))
    low, high = (lo + d, hi) if d < 0 else (lo, hi + d)
    stop = None
    for cx in range(*span[0]):
        for cy in range(*span[1]):
            for cz in range(*span[2]):
                c = (cx, cy, cz)[axis]
                if not (c < high and c + 1 > low):  # AABB.intersects: strict
                    continue
                block = blocks.get((cx, cy, cz))
                if block.id in FLUIDS:
                    raise Unmodelled(f"moving through {block.id}")
                if block.is_air or not block_shapes.collides(block):
                    continue
                if d < 0 and c + 1 - lo <= EPSILON and c + 1 - lo > d:
                    d, stop = c + 1 - lo, block
                elif d > 0 and c - hi >= -EPSILON and c - hi < d:
                    d, stop = c - hi, block
    return (0.0 if abs(d) < EPSILON else d), stop


def _check_fall_damage(state, entity, moved: float, on_ground: bool, below) -> None:
    """Entity.checkFallDamage: landing takes the fall (Block.fallOn), else a drop adds to it."""
    distance = F32(float(entity.data.get("FallDistance", Float(0.0))))
    if on_ground:
        if distance > 0:
            multiplier = FALL_MULTIPLIERS.get(below.id if below is not None else "", 1.0)
            _cause_fall_damage(state, entity, distance, F32(multiplier))
        distance = F32(0.0)
    elif moved < 0.0:
        distance = distance - F32(moved)
    entity.data["FallDistance"] = Float(float(distance))


def _cause_fall_damage(state, entity, distance, multiplier) -> None:
    """Player.causeFallDamage then LivingEntity.causeFallDamage / calculateFallDamage. What is not
    living takes none (Entity.causeFallDamage), nor an armor stand (ArmorStand.hurt refuses a fall:
    it is not in ``#can_break_armor_stand``)."""
    if entity.type in NO_FALL_DAMAGE or not living.is_living(entity.type):
        return
    if entity.is_player:
        if entity.gamemode == "creative":  # abilities.mayfly
            return
        if distance >= F32(2.0):
            statistics.award(state, entity, statistics.stat_name("custom", "fall_one_cm"),
                             math.floor(float(distance) * 100.0 + 0.5))  # Math.round
    safe = F32(living.attribute_value(entity, "safe_fall_distance"))
    damage = math.ceil(float((distance - safe) * multiplier) * living.attribute_value(entity, "fall_damage_multiplier"))
    if damage > 0:
        combat.hurt(state, entity, float(damage), combat.DamageSource("minecraft:fall"))
