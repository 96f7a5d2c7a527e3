"""A player breaking a block (ServerPlayerGameMode.destroyBlock: PackTest's ``dummy mine`` breaks it
at once, without the mining time), with what a datapack observes: the block gone, in survival the
block's loot dropped as item entities, ``minecraft.mined:<block>`` and the food exhaustion.

- ``destroy_block(state, player, pos) -> bool``: False when the game refuses (adventure and
  spectator players, operator blocks such as command blocks, a creative player holding a sword).
  Survival drops come from the block's loot table (``blocks/<id>``), which only a loaded pack can
  supply here: without it, or for a block whose need of the right tool is not known here
  (:data:`HAND_HARVESTABLE` / :data:`NEEDS_TOOL`), the break raises Unmodelled. A tool decides
  whether a block that needs one drops (its rules read the game's block tags: pass ``--game-jar``
  or define them) and takes its durability damage (emulator.world.tools).

Sources (decompiled 1.21.x): server/level/ServerPlayerGameMode.java (destroyBlock), world/level/
block/Block.java (playerDestroy: BLOCK_MINED, causeFoodExhaustion(0.005), dropResources; popResource:
the item at the block's centre +-0.25, minus half the item's height, pickup delay 10),
world/entity/player/Player.java (hasCorrectToolForDrops, blockActionRestricted), world/level/block/
GameMasterBlock implementers, world/food/FoodData.java (addExhaustion: capped at 40).
"""
from __future__ import annotations

import numpy as np

from emulator.world import inventories, living, loot, statistics, tools
from emulator.world.combat import award_orbs
from emulator.world.blocks import BlockState, parse_block, with_defaults
from emulator.world.id_families import COLOURS, WOODS
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.items import EMPTY, enchantment_levels
from emulator.world.loot_context import LootContext
from mcfunction_parser.nbt import Compound, Double, List, Short

F32 = np.float32
MINING_EXHAUSTION = F32(0.005)  # Block.playerDestroy
ITEM_HALF_HEIGHT = 0.125  # EntityType.ITEM's height (0.25) / 2
OPERATOR_BLOCKS = frozenset("minecraft:" + n for n in (
    "command_block chain_command_block repeating_command_block structure_block jigsaw test_block "
    "test_instance_block").split())
# blocks whose drops need no tool (Block.Properties without requiresCorrectToolForDrops)
HAND_HARVESTABLE = frozenset("minecraft:" + n for n in (
    "dirt coarse_dirt rooted_dirt grass_block podzol mycelium sand red_sand gravel clay soul_sand soul_soil "
    "crafting_table chest trapped_chest barrel note_block jukebox bookshelf pumpkin carved_pumpkin jack_o_lantern "
    "melon hay_block glass tinted_glass glowstone sponge wet_sponge torch lever ladder scaffolding "
    "dried_kelp_block target honey_block slime_block sculk sculk_vein sculk_catalyst sculk_sensor "
    "calibrated_sculk_sensor sculk_shrieker").split()) | frozenset(
    f"minecraft:{w}_{k}" for w in WOODS for k in (
        "planks", "log", "wood", "stripped_log", "stripped_wood", "slab", "stairs", "fence", "fence_gate", "door",
        "trapdoor", "button", "pressure_plate", "sign", "leaves", "sapling")) | frozenset(
    f"minecraft:{c}_{k}" for c in COLOURS for k in ("wool", "carpet", "stained_glass", "bed", "concrete_powder"))
# blocks that drop nothing unless mined with the right tool (requiresCorrectToolForDrops)
NEEDS_TOOL = frozenset("minecraft:" + n for n in (
    "stone cobblestone mossy_cobblestone stone_bricks smooth_stone granite diorite andesite deepslate "
    "cobbled_deepslate tuff calcite blackstone basalt netherrack end_stone obsidian crying_obsidian bricks "
    "sandstone red_sandstone terracotta iron_block gold_block diamond_block emerald_block lapis_block "
    "redstone_block coal_block netherite_block copper_block furnace smoker blast_furnace dispenser dropper "
    "observer hopper anvil cauldron iron_bars iron_door iron_trapdoor chain lantern bell brewing_stand "
    "enchanting_table ender_chest spawner stonecutter grindstone lodestone respawn_anchor nether_gold_ore "
    "nether_quartz_ore ancient_debris").split()) | frozenset(
    f"minecraft:{d}{o}_ore" for d in ("", "deepslate_")
    for o in ("coal", "iron", "copper", "gold", "redstone", "lapis", "diamond", "emerald")) | frozenset(
    f"minecraft:{c}_{k}" for c in COLOURS for k in ("concrete", "terracotta", "glazed_terracotta"))


# the experience blocks drop (Blocks: DropExperienceBlock's IntProvider; RedStoneOreBlock.spawnAfterBreak
# UniformInt.of(1, 5); SculkBlock 1; SculkCatalystBlock, SculkSensorBlock, SculkShriekerBlock 5): inclusive
BLOCK_EXPERIENCE = {
    **{f"minecraft:{d}{ore}": bounds for d in ("", "deepslate_") for ore, bounds in (
        ("coal_ore", (0, 2)), ("lapis_ore", (2, 5)), ("diamond_ore", (3, 7)), ("emerald_ore", (3, 7)),
        ("redstone_ore", (1, 5)), ("iron_ore", (0, 0)), ("gold_ore", (0, 0)), ("copper_ore", (0, 0)))},
    "minecraft:nether_gold_ore": (0, 1), "minecraft:nether_quartz_ore": (2, 5), "minecraft:sculk": (1, 1),
    "minecraft:sculk_catalyst": (5, 5), "minecraft:sculk_sensor": (5, 5), "minecraft:calibrated_sculk_sensor": (5, 5),
    "minecraft:sculk_shrieker": (5, 5),
}


def destroy_block(state, player, pos) -> bool:
    """ServerPlayerGameMode.destroyBlock for the player at ``pos``."""
    pos = tuple(pos)
    blocks = state.blocks_in(player.dimension)
    block = blocks.get(pos)
    held = inventories.entity_slot(player, inventories.MAINHAND, state.version).get()
    if player.gamemode == "creative" and held.id.endswith(("_sword", "trident", "mace")):
        return False  # Item.canDestroyBlock: weapons do not break blocks in creative
    if block.id in OPERATOR_BLOCKS and player.gamemode != "creative":
        return False  # Player.canUseGameMasterBlocks: an operator in creative
    if player.gamemode in ("adventure", "spectator"):
        return False  # Player.blockActionRestricted (adventure's can_break is not modelled: refused)
    if block.is_air:
        return True  # Level.removeBlock changes nothing: nothing to drop
    _one_block(block)
    if player.gamemode == "creative":
        _remove(state, pos, block, player.dimension)
        return True
    harvest = _can_harvest(state, block, held)
    drops = _drops(state, pos, block, player.dimension, player, held) if harvest else []
    _remove(state, pos, block, player.dimension)
    tools.mine_block(state, player, inventories.entity_slot(player, inventories.MAINHAND, state.version), block.id)
    if harvest:
        statistics.award(state, player, statistics.stat_name("mined", block.id))
        living.exhaust(player, MINING_EXHAUSTION)
        _pop_all(state, pos, drops, player.dimension)
        _pop_experience(state, pos, block, held, player.dimension)
    return True


def destroy(state, pos, dimension: str) -> bool:
    """Level.destroyBlock(pos, true), which setblock's and fill's ``destroy`` mode run: False on air;
    else the block's drops pop (Block.dropResources with no tool and no entity: the loot table's own
    conditions decide, no tool is required) and the block goes (water where it was waterlogged)."""
    pos = tuple(pos)
    block = state.blocks_in(dimension).get(pos)
    if block.is_air:
        return False
    _one_block(block)
    drops = _drops(state, pos, block, dimension, None, EMPTY.copy())
    _pop_all(state, pos, drops, dimension)
    _pop_experience(state, pos, block, EMPTY, dimension)
    _remove(state, pos, block, dimension)
    return True


def _one_block(block: BlockState) -> None:
    if any(key in ("half", "part") for key, _ in block.properties):
        raise Unmodelled(f"breaking {block.id}: its other half (Block.playerWillDestroy, updateShape)")


def _can_harvest(state, block: BlockState, held) -> bool:
    """Player.hasCorrectToolForDrops: a block that needs no tool, or the held tool is right for it
    (emulator.world.tools: Tool.isCorrectForDrops)."""
    if block.id in HAND_HARVESTABLE:
        return True
    if block.id not in NEEDS_TOOL:
        raise Unmodelled(f"mining {block.id} in survival (whether it needs the right tool for drops)")
    found = tools.tool(held, state.version)
    return found is not None and found.correct_for_drops(block.id, state.resources)


def _drops(state, pos, block: BlockState, dimension: str, entity, tool) -> list:
    """Block.dropResources: the block's loot table with the tool, the block, its entity and the
    entity breaking it (none for a command's destroy)."""
    blocks = state.blocks_in(dimension)
    held_items = inventories.container(blocks, pos, state.version)
    if held_items is not None and any(not held_items.slot(i).get().is_empty for i in range(held_items.size)):
        raise Unmodelled(f"the contents {block.id} spills when mined")
    table_id = "minecraft:blocks/" + block.id.split(":", 1)[-1]
    table = state.resources.loot_table(table_id) or {}  # none: LootTable.EMPTY, nothing drops
    ctx = LootContext(state, (pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5), this=entity, tool=tool, block_state=block,
                      block_entity=blocks.entity(pos), dimension=dimension, random=state.resources.random)
    try:
        return loot.roll_table(table, ctx)
    except CommandFailure as error:
        raise Unmodelled(error.message) from None


def _remove(state, pos, block: BlockState, dimension: str) -> None:
    """Level.removeBlock: air, or water where the block was waterlogged."""
    water = dict(block.properties).get("waterlogged") == "true"
    state.blocks_in(dimension).setblock(pos, with_defaults(parse_block("minecraft:water" if water else "minecraft:air"),
                                                           state.version))


def _pop_all(state, pos, drops, dimension: str) -> None:
    """Block.popResource for each stack, unless the doTileDrops rule is off."""
    if state.gamerules.get("doTileDrops") != "false":
        for stack in drops:
            _pop(state, pos, stack, dimension)


def _pop_experience(state, pos, block: BlockState, tool, dimension: str) -> None:
    """BlockState.spawnAfterBreak with dropExperience (Block.dropResources): a block's experience
    (Block.tryDropExperience: its IntProvider sampled, here from the emulator's seeded random; a spawner's 15 +
    nextInt(15) + nextInt(15), not through the enchantments) as orbs at its centre, unless the
    doTileDrops rule is off (Block.popExperience)."""
    if block.id == "minecraft:spawner":
        rng = state.resources.random
        amount = 15 + rng.randrange(15) + rng.randrange(15)
    else:
        bounds = BLOCK_EXPERIENCE.get(block.id)
        if bounds is None or bounds == (0, 0):
            return
        if enchantment_levels(tool):  # EnchantmentHelper.processBlockExperience: silk touch's block_experience
            raise Unmodelled(f"the experience {block.id} drops when mined with an enchanted tool "
                             "(its enchantments' block_experience effects)")
        amount = state.resources.random.randint(*bounds)  # Mth.randomBetweenInclusive
    if amount > 0 and state.gamerules.get("doTileDrops") != "false":
        award_orbs(state, (pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5), amount, dimension)


def _pop(state, pos, stack, dimension: str) -> None:
    """Block.popResource: an item entity about the block's centre (pickup delay 10)."""
    rng = state.resources.random
    x, y, z = (pos[0] + 0.5 + rng.uniform(-0.25, 0.25), pos[1] + 0.5 + rng.uniform(-0.25, 0.25) - ITEM_HALF_HEIGHT,
               pos[2] + 0.5 + rng.uniform(-0.25, 0.25))
    inventories.drop_item(state.entities, (x, y, z), stack, state.version, rng,
                          Compound(PickupDelay=Short(10), Motion=List([Double(rng.random() * 0.2 - 0.1), Double(0.2),
                                                                        Double(rng.random() * 0.2 - 0.1)])), dimension)
