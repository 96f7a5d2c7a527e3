"""Entities other than players that the server moves each tick: item entities, experience orbs,
primed TNT, falling blocks, mobs and armor stands, as their ``tick`` moves them (decompiled 1.21),
through the one Entity.move there is (:func:`emulator.world.falling.move`: full cubes, ``OnGround``, the fall
distance and fall damage). Players are :mod:`emulator.world.falling`'s (a PackTest dummy falls
there; a client's player moves by its client); projectiles are :mod:`emulator.world.projectiles`'.

- ``tick_moving(state)``: each such entity's tick, in the store's order; ``tick_is_idle(state)``:
  none would change (none exists, or each is a mob without AI or an armor stand without physics
  with no motion, or a mob resting on a block; an item or orb always ages).

Each tick (the game's order within an entity's tick):
- the void (Entity.baseTick -> checkBelowWorld): below the level's bottom - 64 an item or orb is
  gone (onBelowWorld: discard), a living entity takes 4 ``minecraft:out_of_world`` damage each tick
  (LivingEntity.onBelowWorld; an armor stand is killed by it: ArmorStand.hurt);
- an item (ItemEntity.tick): ``PickupDelay`` counts down (not 32767), the gravity 0.04 (none with
  ``NoGravity``); it moves when in the air, with horizontal motion (> 1.0E-5F squared), or every
  fourth tick of its life at rest; its motion is then scaled by 0.98F (x, z: by the friction of
  the block under it x 0.98F on the ground: 0.6 default, 0.98 ice, 0.989 blue ice, 0.8 slime)
  and 0.98 (y), and a downward y on the ground is halved and turned up (x -0.5). Whether it is in
  a fluid or inside a block (not modelled) is looked at on the ticks it moves (at rest: one in four). ``Age`` counts up
  (not -32768) and at 6000 the item is gone. Every 40th tick of its life (2nd while it moves
  from block to block) a mergeable item (ItemEntity.isMergable: alive, a pickup delay other than
  32767, an age other than -32768 and under 6000, a count under its max stack size) merges with
  the mergeable items its box inflated by 0.5 sideways meets, in the entities' order
  (mergeWithNeighbours, tryToMerge): same ``Owner``, same item and components, the two counts
  within a stack; the fewer go into the more (into the neighbour on a tie), at most 64 in a
  stack; the one left keeps the longer ``PickupDelay`` and the younger ``Age``; an emptied item is
  gone. With no pickup delay left, each living player that is not a spectator (no other
  ``Owner``) whose box inflated by (1, 0.5, 1) meets it (riding: the box spanning it and its
  vehicle, by (1, 0, 1)) picks it up (Player.aiStep -> ItemEntity.playerTouch:
  :mod:`emulator.world.pickup`), at the item's tick;
- an experience orb (ExperienceOrb.tick): gravity 0.03, moves, the same friction, on the ground
  the y is scaled by -0.9; ``Age`` counts up to 6000;
- a falling block (FallingBlockEntity.tick; ``BlockState``, sand when missing): ``Time`` counts,
  gravity 0.04, the move; on the ground the motion is scaled by (0.7, -0.5, 0.7) and the block is
  set where the entity is (the entity is gone) when what is there is replaceable and the block
  under it is not free (air, fire, a fluid, replaceable: FallingBlock.isFree); otherwise it
  breaks: gone, and (``DropItem``, ``doEntityDrops``) its block's item drops where it was
  (Entity.spawnAtLocation: pickup delay 10, the item's random motion drawn from the emulator's
  random). In the air it breaks so after 600 ticks, or 100 below the bottom or above the top;
  the motion is then x 0.98. Like TNT it does not run baseTick (no void);
- primed TNT (PrimedTnt.tick): gravity 0.04, moves, motion x 0.98, on the ground x (0.7, -0.5,
  0.7); ``fuse`` counts down (no baseTick: the void does not remove it);
- a living entity other than a player (LivingEntity.aiStep, travel): a mob with ``NoAI`` or an
  armor stand with ``NoGravity`` or ``Marker`` (isEffectiveAi false) does not travel: its motion is
  only scaled by 0.98 each tick (it hangs where it is). Otherwise a motion component under 0.003
  becomes 0, the mob moves by its motion with no input of its own (its AI is not modelled), then
  its horizontal motion is scaled by the friction of the block under it x 0.91F (0.91F in the air;
  the ground as it was before the move), its vertical motion loses the gravity (the ``gravity``
  attribute; at most 0.01 falling with slow falling) and is scaled by 0.98F; fall damage as for
  players (none for an armor stand).

An entity riding another does not move by itself (Entity.rideTick: its vehicle places it).

Not modelled (reported once as not modelled, and that entity no longer moves here): water, lava
and bubble columns, blocks that are not full cubes or empty (slabs, stairs, fences ...), an item
or orb inside a block (pushed out of it), stepping up, slime blocks' bounce, honey and soul sand,
climbing, an orb following a player, TNT
exploding, a falling block breaking whose block has no item of its id, falling anvils and dripstone (they hurt what
they land on), a falling block with block entity data, concrete powder meeting water, a vehicle
carrying its passengers, and a flying mob with AI given motion.

Not modelled and not reported: what a mob's AI does (wandering, pathfinding, targeting, jumping:
a mob with AI moves only by its motion and gravity here, which is the game's result while its AI
stays idle; a flying mob with AI, whose flight is all AI, stays where it is), a mob's suffocation
with its eyes in a block (LivingEntity.baseTick: isInWall; it is no movement), boats and
minecarts (:mod:`emulator.world.block_contact` reports a cart that would ride), and the void
under entities not moved here (interactions, area effect clouds, hanging entities; markers and
displays do not look), and orbs merging (ExperienceOrb.scanForEntities: it goes by the orbs'
network ids, which no pack sees). The fourth-tick rule of a resting item counts the item's own ticks (the
game adds its network id, which no pack sees).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import block_shapes, combat, falling, inventories, items, living, pickup
from emulator.world.blocks import BlockSpec, BlockState
from emulator.world.errors import Unmodelled
from mcfunction_parser.nbt import Compound, Int, Short, String

F32 = np.float32
ITEM, ORB, TNT = "minecraft:item", "minecraft:experience_orb", "minecraft:tnt"
ARMOR_STAND = "minecraft:armor_stand"
FALLING_BLOCK = "minecraft:falling_block"
GRAVITY = {ITEM: 0.04, ORB: 0.03, TNT: 0.04, FALLING_BLOCK: 0.04}  # getDefaultGravity
DEFAULT_FALLING = "minecraft:sand"  # FallingBlockEntity.blockState's default
# blocks whose item is not their id (Block.asItem): a falling one's drop is not modelled
NO_ITEM = frozenset("minecraft:" + n for n in (
    "water lava fire soul_fire bubble_column powder_snow redstone_wire tripwire moving_piston "
    "piston_head end_portal nether_portal end_gateway frosted_ice").split())
# FallingBlockEntity.hurtEntities: set for these (FallingBlockEntity.fall, AnvilBlock, PointedDripstoneBlock)
HURTS_ENTITIES = frozenset("minecraft:" + n for n in (
    "anvil chipped_anvil damaged_anvil pointed_dripstone").split())
DESPAWN_AGE = 6000  # ItemEntity.tick, ExperienceOrb.tick
NO_PICKUP = 32767  # ItemEntity: a pickup delay that never counts down
NO_AGE = -32768  # ItemEntity: an age that never counts up
MIN_MOVEMENT = 0.003  # LivingEntity.aiStep
DRAG_F = float(F32(0.98))  # 0.98F widened
AIR_FRICTION = F32(0.91)  # LivingEntity.travel
RESTING_MOVE = float(F32(1.0E-5))  # ItemEntity.tick: horizontalDistanceSqr() > 1.0E-5F
MERGE_REACH = (0.5, 0.0, 0.5)  # ItemEntity.mergeWithNeighbours: getBoundingBox().inflate(0.5, 0.0, 0.5)
MERGE_MAX = 64  # ItemEntity.merge(ItemEntity, ItemStack, ItemStack): merge(dest, src, 64)
TOUCH_REACH = (1.0, 0.5, 1.0)  # Player.aiStep: getBoundingBox().inflate(1.0, 0.5, 1.0)
RIDING_REACH = (1.0, 0.0, 1.0)  # Player.aiStep riding: the box with the vehicle's, inflate(1.0, 0.0, 1.0)
FOLLOW_RANGE = 8.0  # ExperienceOrb.scanForEntities
VOID_DEPTH = 64  # Entity.checkBelowWorld: below the level's bottom - 64
VOID_DAMAGE = 4.0  # LivingEntity.onBelowWorld
# BlockBehaviour.Properties.friction (Blocks): 0.6 for any other block
FRICTION = {"minecraft:ice": 0.98, "minecraft:packed_ice": 0.98, "minecraft:frosted_ice": 0.98,
            "minecraft:blue_ice": 0.989, "minecraft:slime_block": 0.8}
DEFAULT_FRICTION = 0.6
BELOW_AFFECTING = 0.500001  # Entity.getBlockPosBelowThatAffectsMyMovement: getOnPos(0.500001F)
# FlyingAnimal or a travel of their own: with AI they do not move as LivingEntity.travel moves them
FLYING = frozenset("minecraft:" + n for n in (
    "bat bee parrot allay phantom ghast vex blaze ender_dragon wither breeze").split())
_NOT_MOVED_HERE = frozenset(("minecraft:player",))
_BOTTOMS: dict = {}  # (level, release) -> (the Levels it was read from, its bottom)


def _moves(type_id: str) -> bool:
    """Whether the server moves an entity of this type here."""
    if type_id in _NOT_MOVED_HERE:
        return False
    return type_id in GRAVITY or living.is_living(type_id)


def movers(state) -> list:
    """The entities moved here, in the store's order (found again only when entities came or left)."""
    store = state.entities
    cached = state.movers
    if cached[0] != store.changes or cached[1] is not store.entities:
        state.movers = cached = (store.changes, store.entities, [e for e in store.entities if _moves(e.type)])
    return cached[2]


def _held(entity) -> bool:
    """A living entity that does not travel (isEffectiveAi false): a mob with NoAI, an armor stand
    with NoGravity or Marker (ArmorStand.hasPhysics)."""
    data = entity.data
    if entity.type == ARMOR_STAND:
        return bool(int(data.get("NoGravity", 0)) or int(data.get("Marker", 0)))
    return bool(int(data.get("NoAI", 0)))


def _idle(state, entity) -> bool:
    """Whether the entity's tick would change nothing: a living entity that does not travel and has
    no motion, one without gravity or motion off the ground, or one resting on a full cube (on the
    ground, no fall distance, the motion its last landing left: (0, -gravity x 0.98F, 0), nothing
    its tick would report); one that is not moved here. An item, orb, TNT or falling block always
    changes (its age, its fuse). The VM ends a batch of ticks after a root that moved a living
    entity (``tp``, ``execute store`` into its Pos or Motion), so a rest seen before a batch holds
    through it; a block changes only by a host command, which ends the batch too."""
    if entity.type in GRAVITY:
        return not entity.alive or entity in state.not_moving
    if not entity.alive or entity in state.not_moving or entity.vehicle is not None:
        return True
    if _held(entity) or entity.type in FLYING:
        return not any(entity.motion)
    gravity = _gravity(entity, 0.0)
    if not gravity and not any(entity.motion):  # floating: its zero move leaves it off the ground
        return not _on_ground(entity)
    if not _on_ground(entity) or float(entity.data.get("FallDistance", 0.0)):
        return False
    rest = (0.0 - gravity) * DRAG_F
    if entity.motion != (0.0, rest, 0.0):
        return False
    if living.effect_amplifier(entity, "minecraft:levitation") is not None:
        return False
    try:
        _inside_fluid(state, entity)
        moved, below = falling.collide(state.blocks_in(entity.dimension), entity.bounding_box, (0.0, rest, 0.0))
    except Unmodelled:
        return False
    return moved[1] == 0.0 and below is not None and below.id not in falling.BOUNCY


def tick_is_idle(state) -> bool:
    return all(_idle(state, e) for e in movers(state))


def tick_moving(state) -> None:
    entities = movers(state)
    if not entities:
        return
    stopped = state.not_moving
    for entity in list(entities):
        if not entity.alive or entity in stopped or entity.vehicle is not None:
            continue
        try:
            _tick(state, entity)
        except Unmodelled as reason:
            stopped.add(entity)
            state.unmodelled_once(f"{entity.type} moving", reason)


def _tick(state, entity) -> None:
    kind = entity.type
    if entity.passengers and not _idle(state, entity):
        raise Unmodelled("a vehicle carrying its passengers")
    if kind == TNT:
        _tick_tnt(state, entity)
        return
    if kind == FALLING_BLOCK:
        _tick_falling_block(state, entity)
        return
    if _below_world(state, entity):
        return
    if kind == ITEM:
        _tick_item(state, entity)
    elif kind == ORB:
        _tick_orb(state, entity)
    else:
        _tick_living(state, entity)


def _bottom(state, dimension: str) -> int:
    """The level's bottom (its dimension type's min_y), kept per world and level."""
    levels = state.entities.table.levels
    key = (dimension, tuple(state.version))
    cached = _BOTTOMS.get(key)
    if cached is None or cached[0] is not levels:
        cached = _BOTTOMS[key] = (levels, levels.build_height(dimension, state.version)[0])
    return cached[1]


def _below_world(state, entity) -> bool:
    """Entity.checkBelowWorld / onBelowWorld; True when the entity is gone."""
    if entity.pos[1] >= _bottom(state, entity.dimension) - VOID_DEPTH:
        return False
    if not living.is_living(entity.type) or entity.type == ARMOR_STAND:  # discard; ArmorStand.hurt: kill
        state.discard(entity)
        return True
    combat.hurt(state, entity, VOID_DAMAGE, combat.DamageSource("minecraft:out_of_world"))
    return not entity.alive


def _no_gravity(entity) -> bool:
    return bool(int(entity.data.get("NoGravity", 0)))


def _on_ground(entity) -> bool:
    return bool(int(entity.data.get("OnGround", 0)))


def _friction(state, entity) -> F32:
    """Block.getFriction of the block under the entity that affects its movement (the block
    0.500001 below its feet; the game's supporting block where the entity straddles two is not
    looked for)."""
    x, y, z = entity.pos
    block = state.blocks_in(entity.dimension).get((math.floor(x), math.floor(y - BELOW_AFFECTING), math.floor(z)))
    return F32(FRICTION.get(block.id, DEFAULT_FRICTION))


def _ticks_lived(state, entity) -> int:
    """Entity.tickCount after this tick's increment (ServerLevel.tickNonPassenger)."""
    count = state.ticks_lived.get(entity, 0) + 1
    state.ticks_lived[entity] = count
    return count


def _age(entity, key: str) -> bool:
    """Count ``key`` (Age) up; True when it reached the despawn age (the entity is then gone)."""
    age = int(entity.data.get(key, 0))
    if age != NO_AGE:
        age += 1
    entity.data[key] = Short(age)
    return age >= DESPAWN_AGE


def _ground_scaled(state, entity, motion):
    """The items' and orbs' friction after their move: x, z by the friction under them (on the
    ground) x 0.98F, else 0.98F; y by 0.98. Also whether the entity is on the ground."""
    f = F32(0.98)
    on_ground = _on_ground(entity)
    if on_ground:
        f = _friction(state, entity) * F32(0.98)
    x, y, z = motion[0] * float(f), motion[1] * 0.98, motion[2] * float(f)
    return x, y, z, on_ground


def _tick_item(state, entity) -> None:
    """ItemEntity.tick (its water and lava: :func:`_check_cells`)."""
    data = entity.data
    delay = int(data.get("PickupDelay", 0))
    if 0 < delay != NO_PICKUP:
        data["PickupDelay"] = Short(delay - 1)
    x, y, z = entity.motion
    if not _no_gravity(entity):
        y -= GRAVITY[ITEM]
    lived = _ticks_lived(state, entity)
    moved_block = False
    if not _on_ground(entity) or x * x + z * z > RESTING_MOVE or lived % 4 == 0:
        _check_cells(state, entity)  # a resting item is looked at on its moving ticks only
        start = entity.pos
        moved = falling.move(state, entity, (x, y, z))
        x, y, z, on_ground = _ground_scaled(state, entity, moved)
        if on_ground and y < 0.0:
            y *= -0.5
        moved_block = any(math.floor(a) != math.floor(b) for a, b in zip(start, entity.pos))
    entity.motion = (x, y, z)
    if int(data.get("PickupDelay", 0)) == 0:
        _check_pickup(state, entity)
    if lived % (2 if moved_block else 40) == 0 and _mergeable(entity):
        _check_merging(state, entity)
    if _age(entity, "Age"):
        state.discard(entity)


def _check_pickup(state, item) -> None:
    """Player.aiStep: a living player that is not a spectator touches what its box inflated by (1,
    0.5, 1) meets; ItemEntity.playerTouch takes an item with no pickup delay whose ``Owner`` is
    none or that player into its inventory (:func:`emulator.world.pickup.player_touch`), the
    players in their order until the item is gone."""
    if int(item.data.get("PickupDelay", 0)) != 0:
        return
    owner = item.data.get("Owner")
    for player in state.entities.players():
        if player.gamemode == "spectator" or living.health(player) <= 0 or player.dimension != item.dimension:
            continue
        if owner is not None and tuple(owner) != tuple(player.uuid):
            continue
        if _meets(*_touching_box(player), item.bounding_box):
            pickup.player_touch(state, player, item)
            if not item.alive:
                return


def _touching_box(player) -> tuple:
    """Player.aiStep's box and reach: riding a vehicle that is there, the box spanning both
    (AABB.minmax) inflated by (1, 0, 1); else its own by (1, 0.5, 1)."""
    vehicle = player.vehicle
    if vehicle is None or not vehicle.alive:
        return player.bounding_box, TOUCH_REACH
    mine, its = player.bounding_box, vehicle.bounding_box
    spanning = tuple(min(mine[a], its[a]) for a in range(3)) + tuple(max(mine[a], its[a]) for a in range(3, 6))
    return spanning, RIDING_REACH


def _meets(box, reach, other) -> bool:
    """AABB.intersects of ``box`` inflated by ``reach`` (x, y, z) and ``other``."""
    return all(box[a] - reach[a] < other[a + 3] and box[a + 3] + reach[a] > other[a] for a in range(3))


def _mergeable(item) -> bool:
    """ItemEntity.isMergable."""
    stack = items.from_nbt(item.data.get("Item"))
    age = int(item.data.get("Age", 0))
    return (item.alive and int(item.data.get("PickupDelay", 0)) != NO_PICKUP and age != NO_AGE
            and age < DESPAWN_AGE and stack.count < stack.max_stack_size)


def _check_merging(state, item) -> None:
    """ItemEntity.mergeWithNeighbours: each mergeable item (in the entities' order) that the item's
    box inflated by 0.5 sideways meets is tried (tryToMerge) until the item itself is gone."""
    for other in movers(state):
        if other is item or other.type != ITEM or other.dimension != item.dimension or not _mergeable(other):
            continue
        if _meets(item.bounding_box, MERGE_REACH, other.bounding_box):
            _try_to_merge(state, item, other)
            if not item.alive:
                return


def _try_to_merge(state, item, other) -> None:
    """ItemEntity.tryToMerge: the same ``Owner`` (the target) and areMergable (the two counts within
    the other's max stack size, ItemStack.isSameItemSameComponents); the fewer merge into the more,
    into ``other`` on a tie."""
    mine, theirs = items.from_nbt(item.data.get("Item")), items.from_nbt(other.data.get("Item"))
    if other.data.get("Owner") != item.data.get("Owner") or not (
            theirs.count + mine.count <= theirs.max_stack_size and theirs.same_item_same_components(mine)):
        return
    if theirs.count < mine.count:
        _merge(state, item, mine, other, theirs)
    else:
        _merge(state, other, theirs, item, mine)


def _merge(state, dest, dest_stack, src, src_stack) -> None:
    """ItemEntity.merge: as many as fit (ItemEntity.merge(ItemStack, ItemStack, 64)) move to ``dest``,
    which keeps the longer pickup delay and the younger age; an emptied ``src`` is discarded."""
    moved = min(min(dest_stack.max_stack_size, MERGE_MAX) - dest_stack.count, src_stack.count)
    dest_stack.count += moved
    src_stack.count -= moved
    dest.data["Item"] = items.to_nbt(dest_stack, state.version)
    dest.data["PickupDelay"] = Short(max(int(dest.data.get("PickupDelay", 0)), int(src.data.get("PickupDelay", 0))))
    dest.data["Age"] = Short(min(int(dest.data.get("Age", 0)), int(src.data.get("Age", 0))))
    if src_stack.is_empty:
        state.discard(src)
    else:
        src.data["Item"] = items.to_nbt(src_stack, state.version)


def _tick_orb(state, entity) -> None:
    """ExperienceOrb.tick (its water and lava: :func:`_check_cells`)."""
    _check_cells(state, entity)
    if any(p.gamemode != "spectator" and living.health(p) > 0 and _within(p, entity, FOLLOW_RANGE)
           for p in state.entities.players()):  # scanForEntities: getNearestPlayer(this, 8.0), not dying
        raise Unmodelled("an experience orb following a player")
    x, y, z = entity.motion
    if not _no_gravity(entity):
        y -= GRAVITY[ORB]
    moved = falling.move(state, entity, (x, y, z))
    x, y, z, on_ground = _ground_scaled(state, entity, moved)
    if on_ground:
        y *= -0.9
    entity.motion = (x, y, z)
    if _age(entity, "Age"):
        state.discard(entity)


def _within(player, entity, distance: float) -> bool:
    if player.dimension != entity.dimension:
        return False
    return sum((a - b) ** 2 for a, b in zip(player.pos, entity.pos)) < distance * distance


def _tick_tnt(state, entity) -> None:
    """PrimedTnt.tick: gravity 0.04, the move, x 0.98, on the ground x (0.7, -0.5, 0.7), the fuse."""
    x, y, z = entity.motion
    if not _no_gravity(entity):
        y -= GRAVITY[TNT]
    x, y, z = falling.move(state, entity, (x, y, z))
    x, y, z = x * 0.98, y * 0.98, z * 0.98
    if _on_ground(entity):
        x, y, z = x * 0.7, y * -0.5, z * 0.7
    entity.motion = (x, y, z)
    fuse = int(entity.data.get("fuse", 80)) - 1
    entity.data["fuse"] = Short(fuse)
    if fuse <= 0:
        state.discard(entity)
        raise Unmodelled("TNT exploding")


def _carried(entity) -> BlockState:
    """FallingBlockEntity.readAdditionalSaveData: ``BlockState`` (NbtUtils.readBlockState; sand
    when missing)."""
    tag = entity.data.get("BlockState")
    if not isinstance(tag, Compound) or not isinstance(tag.get("Name"), String):
        return BlockState(DEFAULT_FALLING)
    properties = tag.get("Properties")
    props = tuple((str(k), str(v)) for k, v in properties.items()) if isinstance(properties, Compound) else ()
    name = str(tag["Name"])
    return BlockState(name if ":" in name else "minecraft:" + name, props)


def _tick_falling_block(state, entity) -> None:
    """FallingBlockEntity.tick: ``Time`` counts, gravity 0.04, the move; on the ground the motion is
    scaled by (0.7, -0.5, 0.7) and the block lands where the entity is when that block can be
    replaced and the one under it is not free (FallingBlock.isFree: air, fire, a fluid, a
    replaceable block), else it breaks (an item when ``DropItem``); in the air 600 ticks (100 out of
    the build height) end it; then the motion x 0.98."""
    carried = _carried(entity)
    if carried.is_air:
        state.discard(entity)
        return
    if carried.id in HURTS_ENTITIES or "TileEntityData" in entity.data:
        raise Unmodelled(f"a falling {carried.id} (what it hurts, its block entity)")
    data = entity.data
    time = int(data.get("Time", 0)) + 1
    data["Time"] = Int(time)
    x, y, z = entity.motion
    if not _no_gravity(entity):
        y -= GRAVITY[FALLING_BLOCK]
    x, y, z = falling.move(state, entity, (x, y, z))
    blocks = state.blocks_in(entity.dimension)
    pos = tuple(math.floor(c) for c in entity.pos)
    drops = int(data.get("DropItem", 1)) and state.gamerules.get("doEntityDrops") != "false"  # the default: true
    if _on_ground(entity):
        x, y, z = x * 0.7, y * -0.5, z * 0.7
        there = blocks.get(pos)
        if there.id != "minecraft:moving_piston":
            below = blocks.get((pos[0], pos[1] - 1, pos[2]))
            if there.id in block_shapes.REPLACEABLE and not _free(below):
                blocks.place(pos, BlockSpec(carried.id, False, carried.properties, None))
                state.discard(entity)
                return
            _break(state, entity, carried, drops)
            return
    else:
        bottom, height = state.entities.table.levels.build_height(entity.dimension, state.version)
        if (time > 100 and not bottom < pos[1] <= bottom + height) or time > 600:
            _break(state, entity, carried, drops)
            return
    entity.motion = (x * 0.98, y * 0.98, z * 0.98)


def _break(state, entity, carried: BlockState, drops: bool) -> None:
    """The falling block is gone; with ``drops`` its block's item drops where it was
    (Entity.spawnAtLocation: an item entity with the default pickup delay, 10, and ItemEntity's
    random motion)."""
    if drops and carried.id in NO_ITEM:
        raise Unmodelled(f"a falling {carried.id} breaking (its block has no item of the same id)")
    state.discard(entity)
    if drops:
        inventories.drop_item(state.entities, entity.pos, items.ItemStack(carried.id), state.version,
                              state.resources.random, dimension=entity.dimension)


def _free(block) -> bool:
    """FallingBlock.isFree: air, fire, a fluid or a replaceable block."""
    return block.is_air or block.id in block_shapes.REPLACEABLE or block.id in falling.FLUIDS


def _tick_living(state, entity) -> None:
    """LivingEntity.aiStep then travel, with no input (no AI)."""
    x, y, z = entity.motion
    held = _held(entity)
    if held:  # aiStep: not isEffectiveAi
        x, y, z = x * 0.98, y * 0.98, z * 0.98
    x, y, z = (0.0 if abs(m) < MIN_MOVEMENT else m for m in (x, y, z))
    if held:
        entity.motion = (x, y, z)
        return
    if entity.type in FLYING:  # its flight is its AI: it stays, unless a motion would move it
        if x or y or z:
            raise Unmodelled(f"{entity.type}'s flight (a flying mob with AI given motion)")
        entity.motion = (x, y, z)
        return
    _inside_fluid(state, entity)
    falling.keep_falls_short(entity)
    scale = _friction(state, entity) * AIR_FRICTION if _on_ground(entity) else AIR_FRICTION
    x, y, z = falling.move(state, entity, (x, y, z))
    gravity = 0.0 if _no_gravity(entity) else living.attribute_value(entity, "gravity")
    entity.motion = (x * float(scale), falling.vertical_after(entity, y, gravity) * DRAG_F, z * float(scale))


def _gravity(entity, y: float) -> float:
    """LivingEntity.travel's gravity: the ``gravity`` attribute (none with NoGravity), at most 0.01
    falling (``y`` <= 0) with slow falling."""
    gravity = 0.0 if _no_gravity(entity) else living.attribute_value(entity, "gravity")
    if y <= 0.0 and living.effect_amplifier(entity, "minecraft:slow_falling") is not None:
        gravity = min(gravity, falling.SLOW_FALLING_GRAVITY)
    return gravity


def _check_cells(state, entity) -> None:
    """An item's or orb's box in a fluid (ItemEntity/ExperienceOrb.tick's water and lava) or, less
    1.0E-7 all round, meeting a full cube (Level.noCollision of the deflated box: noPhysics, pushed
    out by moveTowardsClosestSpace): not modelled."""
    x0, y0, z0, x1, y1, z1 = entity.bounding_box
    e = falling.EPSILON
    blocks = state.blocks_in(entity.dimension)
    for cx in range(math.floor(x0 + e), math.ceil(x1 - e)):
        for cy in range(math.floor(y0 + e), math.ceil(y1 - e)):
            for cz in range(math.floor(z0 + e), math.ceil(z1 - e)):
                block = blocks.get((cx, cy, cz))
                if block.is_air:
                    continue
                _not_fluid(block)
                if block_shapes.collides(block):
                    raise Unmodelled(f"{entity.type} inside a block (pushed out of it)")


def _inside_fluid(state, entity) -> None:
    x, y, z = entity.pos
    _not_fluid(state.blocks_in(entity.dimension).get((math.floor(x), math.floor(y), math.floor(z))))


def _not_fluid(block) -> None:
    if block.id in falling.FLUIDS or ("waterlogged", "true") in block.properties:
        raise Unmodelled(f"an entity in {block.id}")
