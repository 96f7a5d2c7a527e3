"""The entity types' sizes and eye heights: one table, as the game's EntityType registers them.

``entity_type(id) -> EntityType(id, width, height, eye_height)`` (float32 values, as the game's
``EntityDimensions`` holds them); ``ENTITY_TYPES``: every type of the table. A type's builder sets
``sized(width, height)`` and ``eyeHeight(e)``; without ``eyeHeight`` the eye is at ``height * 0.85F``
(EntityDimensions.scalable), and an id outside the table gets the builder's default size 0.6 x 1.8.

Poses and ages that change a living entity's size (LivingEntity.getDimensions: the type's
dimensions scaled by ``getAgeScale()`` and by the ``scale`` attribute; a type may override its
baby size): ``PLAYER_CROUCHING`` (Player.POSES: 0.6 x 1.5, eyes at 1.27), ``baby_scale(id)``
(LivingEntity.getAgeScale: 0.5; HappyGhast's 0.2375) and ``BABY_EYE_HEIGHT`` (the types whose
babies set their own eye height: Zombie.BABY_DIMENSIONS, eyes at 0.93, for the zombies and the
types extending Zombie; Piglin.BABY_DIMENSIONS, 0.97; ArmorStand.BABY_DIMENSIONS, a small
armor stand's, 0.9875). Other types' own baby sizes (a turtle's,
the horses' attachments) are not in the table: their babies are half size.

Source: decompiled 1.21.11 world/entity/EntityType.java (the registrations), 1.21
world/entity/player/Player.java (POSES), world/entity/monster/Zombie.java and
piglin/Piglin.java, decoration/ArmorStand.java (BABY_DIMENSIONS), 1.21.6 animal/HappyGhast.java (getAgeScale).
The ids of older releases (``boat``, ``chest_boat`` before 1.21.2; ``potion`` before 1.21.5) are
kept with their sizes.
"""
from __future__ import annotations

import math

from dataclasses import dataclass

import numpy as np

from mcfunction_parser.nbt import Int, IntArray

F32 = np.float32


@dataclass(frozen=True)
class EntityType:
    id: str
    width: np.float32
    height: np.float32
    eye_height: np.float32


def _type(name: str, width: float, height: float, eye: float | None = None) -> EntityType:
    w, h = F32(width), F32(height)
    # EntityDimensions.scalable: eye height defaults to height * 0.85F (float math).
    return EntityType("minecraft:" + name, w, h, F32(eye) if eye is not None else h * F32(0.85))


_BOATS = " ".join(f"{wood}_boat {wood}_chest_boat" for wood in (
    "acacia", "birch", "cherry", "dark_oak", "jungle", "mangrove", "oak", "pale_oak", "spruce")) \
    + " bamboo_raft bamboo_chest_raft boat chest_boat"
BOATS = frozenset("minecraft:" + name for name in _BOATS.split())
# BlockAttachedEntity: the block it hangs on is its own position's (setPos: BlockPos.containing), saved
# as TileX/TileY/TileZ before 1.21.5 and as block_pos from it (vanilla-mcdoc's BlockAttachedEntity)
BLOCK_ATTACHED = frozenset({"minecraft:item_frame", "minecraft:glow_item_frame", "minecraft:painting",
                            "minecraft:leash_knot"})
BLOCK_POS_VERSION = (1, 21, 5)


KNOT_LIFT = ((1, 17, 0), 0.375, 0.5)  # LeashFenceKnotEntity.recalculateBoundingBox: y + 0.375 from 1.17, 0.5 before


def settle_knot(entity, version) -> None:
    """A leash knot as ``summon`` leaves it: on its position's block (BlockAttachedEntity.setPos),
    at that block's centre x/z and 0.375 above its bottom (LeashFenceKnotEntity.recalculateBoundingBox)."""
    block = tuple(math.floor(c) for c in entity.pos)
    lift = KNOT_LIFT[1] if tuple(version) >= KNOT_LIFT[0] else KNOT_LIFT[2]
    entity.pos = (block[0] + 0.5, block[1] + lift, block[2] + 0.5)
    set_attached_block(entity.data, block, version)


def saved_attached_block(data, version) -> tuple[int, int, int] | None:
    """The block a block-attached entity's NBT names in the fields of ``version`` (None: none)."""
    if tuple(version) >= BLOCK_POS_VERSION:
        found = data.get("block_pos")
        return tuple(int(c) for c in found) if found is not None and len(found) == 3 else None
    if all(k in data for k in ("TileX", "TileY", "TileZ")):
        return tuple(int(data[k]) for k in ("TileX", "TileY", "TileZ"))
    return None


def set_attached_block(data, block, version) -> None:
    """Save ``block`` in a block-attached entity's NBT ``data`` in the fields of ``version``."""
    for key in ("TileX", "TileY", "TileZ", "block_pos"):
        data.pop(key, None)
    if tuple(version) >= BLOCK_POS_VERSION:
        data["block_pos"] = IntArray([Int(c) for c in block])
    else:
        data.update(TileX=Int(block[0]), TileY=Int(block[1]), TileZ=Int(block[2]))
_MINECARTS = "minecart chest_minecart command_block_minecart furnace_minecart hopper_minecart spawner_minecart " \
             "tnt_minecart"
# the types whose entities are projectiles (the classes extending Projectile, and the eye of ender)
PROJECTILES = frozenset("minecraft:" + name for name in (
    "arrow spectral_arrow trident snowball egg ender_pearl experience_bottle potion splash_potion lingering_potion "
    "fireball small_fireball dragon_fireball wither_skull wind_charge breeze_wind_charge llama_spit "
    "shulker_bullet firework_rocket eye_of_ender").split())
_SMALL_PROJECTILES = "egg ender_pearl experience_bottle eye_of_ender firework_rocket llama_spit ominous_item_spawner " \
                     "snowball splash_potion lingering_potion potion fishing_bobber"
# name width height [eye height]; a line of names shares the numbers of the line's end
_TABLE = f"""
{_BOATS} 1.375 0.5625 0.5625
{_MINECARTS} 0.98 0.7
{_SMALL_PROJECTILES} 0.25 0.25
marker block_display item_display text_display interaction lightning_bolt 0 0
breeze_wind_charge wind_charge 0.3125 0.3125 0
shulker_bullet small_fireball wither_skull 0.3125 0.3125
arrow spectral_arrow trident 0.5 0.5 0.13
dragon_fireball fireball 1 1
allay 0.35 0.6 0.36
area_effect_cloud 6 0.5
armadillo 0.7 0.65 0.26
armor_stand 0.5 1.975 1.7775
axolotl 0.75 0.42 0.2751
bat 0.5 0.9 0.45
bee 0.7 0.6 0.3
blaze 0.6 1.8
bogged parched skeleton stray 0.6 1.99 1.74
breeze 0.6 1.77 1.3452
camel camel_husk 1.7 2.375 2.275
cat 0.6 0.7 0.35
cave_spider 0.7 0.5 0.45
chicken 0.4 0.7 0.644
cod 0.5 0.3 0.195
copper_golem 0.49 0.98 0.8125
cow mooshroom 0.9 1.4 1.3
creaking 0.9 2.7 2.3
creeper 0.6 1.7
dolphin 0.9 0.6 0.3
donkey 1.3964844 1.5 1.425
drowned husk zombie zombie_villager 0.6 1.95 1.74
elder_guardian 1.9975 1.9975 0.99875
enderman 0.6 2.9 2.55
endermite silverfish 0.4 0.3 0.13
ender_dragon 16 8
end_crystal 2 2
evoker illusioner pillager vindicator 0.6 1.95
evoker_fangs 0.5 0.8
experience_orb painting 0.5 0.5
falling_block 0.98 0.98
fox 0.6 0.7 0.4
frog 0.5 0.5
ghast happy_ghast 4 4 2.6
giant 3.6 12 10.44
glow_item_frame item_frame 0.5 0.5 0
glow_squid squid 0.8 0.8 0.4
goat 0.9 1.3
guardian 0.85 0.85 0.425
hoglin zoglin 1.3964844 1.4
horse mule skeleton_horse zombie_horse 1.3964844 1.6 1.52
iron_golem 1.4 2.7
item 0.25 0.25 0.2125
leash_knot 0.375 0.5 0.0625
llama trader_llama 0.9 1.87 1.7765
magma_cube slime 0.52 0.52 0.325
mannequin player 0.6 1.8 1.62
nautilus zombie_nautilus 0.875 0.95 0.2751
ocelot 0.6 0.7
panda 1.3 1.25
parrot 0.5 0.9 0.54
phantom 0.9 0.5 0.175
pig 0.9 0.9
piglin piglin_brute zombified_piglin 0.6 1.95 1.79
polar_bear 1.4 1.4
pufferfish 0.7 0.7 0.455
rabbit 0.4 0.5
ravager 1.95 2.2
salmon 0.7 0.4 0.26
sheep 0.9 1.3 1.235
shulker 1 1 0.5
sniffer 1.9 1.75 1.05
snow_golem 0.7 1.9 1.7
spider 1.4 0.9 0.65
strider 0.9 1.7
tadpole 0.4 0.3 0.19500001
tnt 0.98 0.98 0.15
tropical_fish 0.5 0.4 0.26
turtle 1.2 0.4
vex 0.4 0.8 0.51875
villager wandering_trader witch 0.6 1.95 1.62
warden 0.9 2.9
wither 0.9 3.5
wither_skeleton 0.7 2.4 2.1
wolf 0.6 0.85 0.68
"""


def _read(table: str) -> dict[str, EntityType]:
    types = {}
    for line in table.strip().splitlines():
        words = line.split()
        numbers = [float(w) for w in words if w[0].isdigit()]
        for name in words[:len(words) - len(numbers)]:
            types["minecraft:" + name] = _type(name, *numbers)
    return types


ENTITY_TYPES = _read(_TABLE)

PLAYER_CROUCHING = _type("player", 0.6, 1.5, 1.27)
BABY_SCALE = F32(0.5)
BABY_SCALES = {"minecraft:happy_ghast": F32(0.2375)}  # HappyGhast.getAgeScale
BABY_EYE_HEIGHT = {**{f"minecraft:{name}": F32(0.93) for name in (
    "zombie", "husk", "drowned", "zombie_villager", "zombified_piglin")}, "minecraft:piglin": F32(0.97),
    "minecraft:armor_stand": F32(0.9875)}


def baby_scale(type_id: str) -> np.float32:
    return BABY_SCALES.get(type_id, BABY_SCALE)


def entity_type(type_id: str) -> EntityType:
    """The type's size; an id outside the table gets the game builder's default size."""
    return ENTITY_TYPES.get(type_id) or _type(type_id.split(":", 1)[-1], 0.6, 1.8)
