"""Block entities: which blocks have one, the id of its type, and what a new one saves.

- ``type_id(block_id)``: the key of the block's BlockEntityType (``minecraft:sign`` for every
  standing or wall sign, ``minecraft:mob_spawner`` for a spawner, ``minecraft:beehive`` for a bee
  nest ...), the ``id`` BlockEntity.saveWithFullMetadata adds for ``data get block``; None for a
  block without a block entity (its NBT in ``setblock`` is ignored: BlockInput.place).
- ``new_entity(block_id, version, triggered)``: saveAdditional of a new block entity of the block
  in release ``version``, as ``setblock``/``fill`` leave it before any NBT is merged in; None for
  a block without one, or one whose saved form the emulator does not know (``known``).
- ``known(block_id, version)``: whether :func:`new_entity` knows what that block entity saves. A
  block entity it does not know (sculk sensors' vibration listeners, structure blocks, jigsaws,
  trial spawners, vaults, a spawner before 1.18, a jukebox of 1.19.3 - 1.20.6 whose ``TickCount``
  counts every tick ...) is not modelled when a command reads it.

What ticking block entities do each tick is :mod:`emulator.world.block_entity_ticks`'.

Sources (decompiled 1.21, and the mapped releases 1.14.4 - 1.21.3 for the renames):
world/level/block/entity/BlockEntityType.java (the types and their blocks), BlockEntity.java
(saveWithFullMetadata), each type's saveAdditional: AbstractFurnaceBlockEntity (BurnTime,
CookTime, CookTimeTotal, RecipesUsed; from 1.21.4 lit_time_remaining, cooking_time_spent,
cooking_total_time, lit_total_time), BrewingStandBlockEntity (BrewTime, Fuel),
world/level/BaseSpawner.save (the delays and counts as shorts, SpawnPotentials; SpawnData only once
drawn from 1.19.3, a pig before), BeehiveBlockEntity (bees from 1.20.5, Bees before),
BeaconBlockEntity (Levels; Primary and Secondary -1 before 1.20.2: MobEffect.getIdFromNullable of
none, the registry's default id), ComparatorBlockEntity (OutputSignal), TheEndGatewayBlockEntity
(Age), HopperBlockEntity (TransferCooldown -1), ShulkerBoxBlockEntity (saveAllItems without the
empty list), ChiseledBookShelfBlockEntity (last_interacted_slot -1), JukeboxBlockEntity.
"""
from __future__ import annotations

from mcfunction_parser.nbt import Byte, Compound, Int, List, Long, Short, String
from emulator.world import command_blocks, signs
from emulator.world.id_families import COLOURS, WOODS
from emulator.world.nbt_ops import copy_tag
from emulator.world.inventories import CONTAINER_SIZES, SHULKER_BOXES, default_block_entity


# BlockEntityType: the blocks of each type whose id is not the block's own
_TYPES = {
    **{box: "minecraft:shulker_box" for box in SHULKER_BOXES},
    **{f"minecraft:{c}_bed": "minecraft:bed" for c in COLOURS},
    **{f"minecraft:{c}{wall}_banner": "minecraft:banner" for c in COLOURS for wall in ("", "_wall")},
    **{f"minecraft:{w}{wall}_sign": "minecraft:sign" for w in WOODS for wall in ("", "_wall")},
    **{f"minecraft:{w}{wall}_hanging_sign": "minecraft:hanging_sign" for w in WOODS for wall in ("", "_wall")},
    **{f"minecraft:{h}{wall}_{kind}": "minecraft:skull"
       for h, kind in (("skeleton", "skull"), ("wither_skeleton", "skull"), ("zombie", "head"), ("player", "head"),
                       ("creeper", "head"), ("dragon", "head"), ("piglin", "head"))
       for wall in ("", "_wall")},
    "minecraft:spawner": "minecraft:mob_spawner",
    "minecraft:moving_piston": "minecraft:piston",
    "minecraft:chain_command_block": "minecraft:command_block",
    "minecraft:repeating_command_block": "minecraft:command_block",
    "minecraft:soul_campfire": "minecraft:campfire",
    "minecraft:bee_nest": "minecraft:beehive",
    "minecraft:suspicious_sand": "minecraft:brushable_block",
    "minecraft:suspicious_gravel": "minecraft:brushable_block",
}
# the blocks whose type has the block's own id
_OWN_TYPES = frozenset("minecraft:" + n for n in (
    "furnace chest trapped_chest ender_chest jukebox dispenser dropper brewing_stand enchanting_table end_portal "
    "beacon daylight_detector hopper comparator structure_block end_gateway command_block conduit "
    "barrel smoker blast_furnace lectern bell jigsaw campfire beehive sculk_sensor calibrated_sculk_sensor "
    "sculk_catalyst sculk_shrieker chiseled_bookshelf decorated_pot crafter trial_spawner vault creaking_heart "
    "test_block test_instance_block").split())

# new block entities that save nothing (or only what a new one does not have: a custom name, a book ...)
_SAVE_NOTHING = frozenset("minecraft:" + n for n in (
    "ender_chest enchanting_table end_portal daylight_detector bed bell conduit banner skull lectern "
    "brushable_block decorated_pot").split())
_FURNACES = frozenset({"minecraft:furnace", "minecraft:smoker", "minecraft:blast_furnace"})
FURNACE_KEYS_VERSION = (1, 21, 4)  # AbstractFurnaceBlockEntity's keys renamed (BlockEntityFurnaceBurnTimeFix)


def type_id(block_id: str) -> str | None:
    if block_id in _OWN_TYPES:
        return block_id
    return _TYPES.get(block_id)


def known(block_id: str, version) -> bool:
    return type_id(block_id) is None or _new(block_id, tuple(version), False) is not None


def new_entity(block_id: str, version, triggered: bool = False) -> Compound | None:
    return _new(block_id, tuple(version), triggered)


def placed_with(block_id: str, version, given: Compound, triggered: bool = False) -> Compound:
    """The block entity a block placed with NBT saves: BlockInput.place has the new block entity
    load only the NBT written (loadWithComponents), so a field that NBT lacks keeps the new one's
    value unless load reads it anyway: a hopper's TransferCooldown and a chiseled bookshelf's
    last_interacted_slot become 0 (getInt), a spawner's Delay 0 (getShort) and, without
    SpawnPotentials, its one potential spawn is its SpawnData (or an empty one: BaseSpawner.load)."""
    version = tuple(version)
    nbt = _new(block_id, version, triggered) or Compound()
    kind = type_id(block_id)
    for key, value in _READ_WHEN_MISSING.get(kind, {}).items():
        if key not in given:
            nbt[key] = value
    if kind == "minecraft:mob_spawner" and "SpawnPotentials" not in given and nbt:
        default = Compound(entity=Compound(id=String("minecraft:pig")) if version < (1, 19, 3) else Compound())
        spawn = given.get("SpawnData") if isinstance(given.get("SpawnData"), Compound) else default
        nbt["SpawnPotentials"] = List([Compound(data=copy_tag(spawn), weight=Int(1))])
    nbt.update(copy_tag(given))
    return nbt


# what load reads for a field the NBT lacks, where it differs from a new block entity's value
_READ_WHEN_MISSING = {
    "minecraft:hopper": {"TransferCooldown": Int(0)},
    "minecraft:chiseled_bookshelf": {"last_interacted_slot": Int(0)},
    "minecraft:mob_spawner": {"Delay": Short(0)},
}


def _new(block_id: str, version: tuple, triggered: bool) -> Compound | None:
    kind = type_id(block_id)
    if kind is None:
        return None
    if kind in _SAVE_NOTHING:
        return Compound()
    if kind == "minecraft:sign" or kind == "minecraft:hanging_sign":
        return signs.new_entity(version)
    if kind == "minecraft:command_block":
        return command_blocks.default_entity(block_id)
    saved = _SAVES.get(kind)
    if saved is not None:
        return saved(version)
    if block_id in CONTAINER_SIZES or kind in ("minecraft:campfire", "minecraft:jukebox"):
        return _container(block_id, kind, version, triggered)
    return None


def _container(block_id: str, kind: str, version: tuple, triggered: bool) -> Compound | None:
    if kind == "minecraft:jukebox":  # 1.19.3 - 1.20.6 save IsPlaying, RecordStartTick and a TickCount that counts every tick
        return Compound() if not (1, 19, 3) <= version < (1, 21) else None
    if kind in _FURNACES:
        return _furnace(version)
    if kind == "minecraft:brewing_stand":
        return Compound(BrewTime=Short(0), Items=List(), Fuel=Byte(0))
    nbt = default_block_entity(block_id, triggered)
    if kind == "minecraft:shulker_box":  # ContainerHelper.saveAllItems(tag, items, false): no empty list
        del nbt["Items"]
    elif kind == "minecraft:hopper":
        nbt["TransferCooldown"] = Int(-1)
    elif kind == "minecraft:chiseled_bookshelf":
        nbt["last_interacted_slot"] = Int(-1)
    return nbt


def _furnace(version: tuple) -> Compound:
    if version >= FURNACE_KEYS_VERSION:
        times = dict(cooking_time_spent=Short(0), cooking_total_time=Short(0), lit_time_remaining=Short(0),
                     lit_total_time=Short(0))
    else:
        times = dict(BurnTime=Short(0), CookTime=Short(0), CookTimeTotal=Short(0))
    return Compound(**times, Items=List(), RecipesUsed=Compound())


def _spawner(version: tuple) -> Compound | None:
    if version < (1, 18):  # the older SpawnData and SpawnPotentials forms are not modelled
        return None
    nbt = Compound(Delay=Short(20), MinSpawnDelay=Short(200), MaxSpawnDelay=Short(800), SpawnCount=Short(4),
                   MaxNearbyEntities=Short(6), RequiredPlayerRange=Short(16), SpawnRange=Short(4))
    if version < (1, 19, 3):  # a new spawner's next spawn was a pig (new SpawnData())
        nbt["SpawnData"] = Compound(entity=Compound(id=String("minecraft:pig")))
    nbt["SpawnPotentials"] = List()
    return nbt


def _beacon(version: tuple) -> Compound:
    if version < (1, 20, 2):
        return Compound(Primary=Int(-1), Secondary=Int(-1), Levels=Int(0))
    return Compound(Levels=Int(0))


_SAVES = {
    "minecraft:mob_spawner": _spawner,
    "minecraft:beehive": lambda version: Compound(**{"bees" if version >= (1, 20, 5) else "Bees": List()}),
    "minecraft:beacon": _beacon,
    "minecraft:comparator": lambda version: Compound(OutputSignal=Int(0)),
    "minecraft:end_gateway": lambda version: Compound(Age=Long(0)),
}
