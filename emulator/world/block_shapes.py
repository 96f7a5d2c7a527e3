"""What a placement asks of a neighbouring block's shape, for the blocks whose shape is known here:
full cubes (stone, planks, wool, glass, barriers ...: solid, every face sturdy, a full collision
box) and blocks with no collision at all (air, water, grass, torches, signs, buttons ...). Any other
block (slabs, stairs, fences, carpets ...) raises Unmodelled: its shape is not in the emulator.

- ``is_solid(block)``: BlockStateBase.isSolid (a wall sign or a standing sign needs it);
- ``is_face_sturdy(block)``: isFaceSturdy for any face (a torch, a door's floor);
- ``is_collision_full(block)``: isCollisionShapeFullBlock (a door's hinge side);
- ``collides(block)``: a collision shape at all (Level.noCollision: a random teleport's landing).
For a full cube the three hold, for an empty shape none does, so one classification answers all.

Sources (decompiled 1.21.x): world/level/block/state/BlockBehaviour.java (BlockStateBase.
calculateSolid: a collision box at least 0.73 wide or a block high; isFaceSturdy,
isCollisionShapeFullBlock), world/level/block/Blocks.java (noCollission blocks).
"""
from __future__ import annotations

from emulator.world.errors import Unmodelled

# BlockTags.REPLACEABLE's common members (what a placed block replaces instead of going beside it)
REPLACEABLE = frozenset("minecraft:" + n for n in (
    "air cave_air void_air water lava short_grass grass fern dead_bush tall_grass large_fern vine fire "
    "soul_fire seagrass tall_seagrass light structure_void crimson_roots warped_roots nether_sprouts "
    "hanging_roots glow_lichen").split())

_FULL_NAMES = frozenset((
    "stone cobblestone mossy_cobblestone dirt coarse_dirt rooted_dirt grass_block podzol mycelium sand red_sand "
    "gravel clay bedrock obsidian crying_obsidian netherrack end_stone sandstone red_sandstone smooth_sandstone "
    "cut_sandstone chiseled_sandstone smooth_red_sandstone cut_red_sandstone chiseled_red_sandstone deepslate "
    "cobbled_deepslate polished_deepslate tuff calcite andesite diorite granite polished_andesite "
    "polished_diorite polished_granite smooth_stone bricks glass tinted_glass bookshelf crafting_table "
    "furnace smoker blast_furnace barrel note_block jukebox ice packed_ice blue_ice snow_block moss_block "
    "sponge wet_sponge glowstone sea_lantern target barrier command_block chain_command_block "
    "repeating_command_block structure_block jigsaw dispenser dropper observer piston_head_free "
    "redstone_lamp tnt pumpkin carved_pumpkin jack_o_lantern melon hay_block dried_kelp_block "
    "prismarine prismarine_bricks dark_prismarine purpur_block purpur_pillar quartz_block "
    "smooth_quartz quartz_pillar chiseled_quartz_block quartz_bricks netherite_block ancient_debris "
    "magma_block soul_sand soul_soil basalt polished_basalt smooth_basalt blackstone polished_blackstone "
    "gilded_blackstone mud packed_mud loom cartography_table fletching_table smithing_table "
    "beehive bee_nest lodestone respawn_anchor shroomlight slime_block amethyst_block budding_amethyst "
    "dripstone_block sculk sculk_catalyst reinforced_deepslate ochre_froglight verdant_froglight "
    "pearlescent_froglight crafter").split())
# families of full cubes by the end of their id (wool, concrete, ores, logs, metal blocks ...)
_FULL_SUFFIXES = ("_planks", "_wool", "_concrete", "_concrete_powder", "_terracotta", "terracotta", "_log",
                  "_wood", "_stem", "_hyphae", "_ore", "_bricks", "_stained_glass", "_glazed_terracotta",
                  "_leaves", "copper", "_copper_block", "_copper")
_FULL_EXCEPT = frozenset(("honey_block",))  # its collision box is smaller
_METAL_BLOCKS = frozenset(("iron_block", "gold_block", "diamond_block", "emerald_block", "lapis_block",
                           "redstone_block", "coal_block", "copper_block", "raw_iron_block", "raw_gold_block",
                           "raw_copper_block", "quartz_block"))
# no collision at all (BlockBehaviour.Properties.noCollission)
_EMPTY_SUFFIXES = ("_torch", "_sign", "_button", "_pressure_plate", "_sapling", "_tulip")
_EMPTY_NAMES = frozenset((
    "air cave_air void_air water lava short_grass grass fern dead_bush tall_grass large_fern vine fire "
    "soul_fire seagrass tall_seagrass light structure_void torch lever redstone_wire tripwire dandelion poppy "
    "blue_orchid allium azure_bluet oxeye_daisy cornflower lily_of_the_valley wither_rose sunflower lilac "
    "rose_bush peony brown_mushroom red_mushroom crimson_roots warped_roots nether_sprouts hanging_roots "
    "glow_lichen cobweb sugar_cane wheat carrots potatoes beetroots pumpkin_stem melon_stem "
    "attached_pumpkin_stem attached_melon_stem big_dripleaf_stem").split())  # plant stems: not "_stem" logs


def _kind(block) -> bool:
    """True for a full cube, False for an empty collision shape."""
    name = block.id.removeprefix("minecraft:")
    if name in _EMPTY_NAMES or name.endswith(_EMPTY_SUFFIXES):
        return False
    if name in _FULL_EXCEPT:
        raise Unmodelled(f"the shape of {block.id} (the emulator keeps only full cubes and blocks without collision)")
    if name in _FULL_NAMES or name in _METAL_BLOCKS or name.endswith(_FULL_SUFFIXES):
        return True
    if name.endswith("_slab") and dict(block.properties).get("type") == "double":
        return True
    raise Unmodelled(f"the shape of {block.id} (the emulator keeps only full cubes and blocks without collision)")


def collides(block) -> bool:
    """Whether the block's collision shape is not empty (for the blocks known here: a full cube)."""
    return _kind(block)


def is_solid(block) -> bool:
    return _kind(block)


def is_face_sturdy(block) -> bool:
    return _kind(block)


# blocks 15/16 high (FarmBlock.SHAPE, DirtPathBlock.SHAPE): their collision shape is no full block
_LOWER_THAN_FULL = frozenset(("minecraft:farmland", "minecraft:dirt_path"))


def is_collision_full(block) -> bool:
    if block.id.endswith("_door") or block.id in _LOWER_THAN_FULL:  # a door's box is 3/16 thick
        return False
    return _kind(block)
