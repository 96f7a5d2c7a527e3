"""A player using a held item that places no block on a block (ItemStack.useOn -> Item.useOn),
with what a datapack observes: the entity or block it makes, the item spent, ``minecraft.used:<item>``.

- ``use_on(state, player, hand, pos, face, hit) -> str``: ``"consume"``, ``"pass"`` or ``"fail"``;
  an item whose useOn is its own but not modelled here raises Unmodelled. Block items are
  emulator.world.block_placing's; the caller fires ``item_used_on_block`` when the use consumes.

Modelled:
- item frames and glow item frames (HangingEntityItem.useOn; ItemFrameItem.mayPlace: any face
  within the build height): the frame hangs in the block in front of the clicked face, facing out
  of it (``Facing``: the face's 3D data value; ``Rotation``: the face's yaw, or a pitch of -90/90 on
  the top/bottom), centred 0.46875 back from the block's centre toward the clicked block. It stays
  only when that block has no collision, the clicked block is solid (BlockStateBase.isSolid; a
  repeater or comparator under a wall frame is not modelled) and no other frame's box meets its
  own (HangingEntity.survives); else the use consumes and nothing is placed. An item with
  ``entity_data`` is not modelled;
- armor stands (ArmorStandItem.useOn; not on a bottom face: FAIL): one stands at the bottom centre
  of the clicked block when that is replaceable, else of the block in front of the clicked face,
  turned to the player's yaw less 180 rounded to 45 degrees, named by the item's ``custom_name``;
  its two blocks must have no collision and no entity's box meet its own (else FAIL). Over a block
  whose collision is not a full cube (it would stand lower and fall) and with ``entity_data`` it is
  not modelled;
- flint and steel: emulator.world.fire (a campfire or candle lit, a fire, a nether portal);
- hoes (HoeItem.useOn: grass, paths and dirt till to ``farmland[moisture=0]``, coarse dirt to
  dirt, with air above and not from below), shovels (ShovelItem.useOn: grass, dirt, podzol,
  coarse or rooted dirt and mycelium with air above flatten to ``dirt_path``, else a lit campfire
  is put out; not from below) and axes (AxeItem.useOn: logs, wood, stems, hyphae and bamboo blocks
  stripped keeping their axis, else copper scraped back a stage, else waxed copper unwaxed, its
  properties kept; ``item_used_on_block`` fires first with the block as it was; with a shield in
  the offhand a main-hand axe passes unless the player sneaks): each worn by one. Rooted dirt
  tilled (its dropped roots) and copper doors (their other half) are not modelled;
- a water bottle on dirt, coarse or rooted dirt (PotionItem.useOn, not from below) makes mud and
  leaves a glass bottle, counting ``minecraft.used:potion`` twice (PotionItem and ItemStack.useOn
  each award it);
- the items whose useOn acts on some blocks only (an ender eye on an end
  portal frame, a compass on a lodestone, a lead on a fence, a map on a banner, honeycomb on unwaxed
  copper, shears on a growing plant's tip; an end crystal on obsidian or bedrock, a minecart on a
  rail, which fail elsewhere): elsewhere they pass (or fail), and where they act they are not
  modelled;
- items whose useOn is Item's own (emeralds, buckets, food ...: a bucket acts through ``use item``'s
  ray, not here): the use passes.
A creative player keeps the item (ServerPlayerGameMode.useItemOn restores the count); an adventure
player's use passes (ItemStack.useOn: without ``can_place_on``, which is not modelled).

Not modelled (Unmodelled): paintings (their variant), the useOn of the other items that have one
(bone meal, spawn eggs, brushes, fire charges, firework rockets, debug sticks; minecarts on rails,
ender eyes in end portal frames, leads on fences, compasses on lodestones, honeycomb on copper,
shears on growing plants, end crystals on obsidian or bedrock, maps on banners) and the block items
that place a block of another name (seeds, carrots, redstone dust, string ...).

Sources (decompiled 1.21): world/item/ItemStack.java (useOn: mayBuild, ITEM_USED when the result
indicates an item use), Item.java (useOn: PASS), HangingEntityItem.java, ItemFrameItem.java,
ArmorStandItem.java, PotionItem.java, EntityType.java (create, getYOffset, appendCustomNameConfig),
world/entity/decoration/HangingEntity.java (setDirection, recalculateBoundingBox), ItemFrame.java
(calculateBoundingBox, survives), HoeItem.java (TILLABLES, onlyIfAirAbove), ShovelItem.java
(FLATTENABLES), AxeItem.java (STRIPPABLES, evaluateNewBlockState, playerHasShieldUseIntent),
WeatheringCopper.getPrevious, HoneycombItem.WAX_OFF_BY_BLOCK, server/level/ServerPlayerGameMode.java
(useItemOn: a creative player's count restored), core/Direction.java (get3DDataValue, toYRot).
"""
from __future__ import annotations

import numpy as np

from emulator.world import (advancements, block_shapes, cauldrons, fire, frames, inventories, mth, player_actions,
                            statistics, tools)
from emulator.world.blocks import BlockState
from emulator.world.entities import TextTag
from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack
from emulator.world.placed_states import OFFSETS
from emulator.world.player_actions import MAIN, hand_slot
from mcfunction_parser import gamedata
from mcfunction_parser.nbt import Byte, Compound, String

F32 = np.float32

# items whose useOn is their own (Item.useOn overrides) and is not modelled here
_OWN_USE_ON = frozenset("minecraft:" + n for n in (
    "painting bone_meal brush compass debug_stick end_crystal ender_eye fire_charge "
    "firework_rocket honeycomb lead filled_map minecart chest_minecart furnace_minecart tnt_minecart "
    "hopper_minecart command_block_minecart shears").split())
_OWN_USE_ON_SUFFIXES = ("_axe", "_hoe", "_shovel", "_spawn_egg")
# the blocks some of those items act on, and their result on any other (their useOn's first test)
_ACTS_ONLY_ON = {
    "minecraft:ender_eye": (lambda b: b == "minecraft:end_portal_frame", "pass"),  # EnderEyeItem
    "minecraft:compass": (lambda b: b == "minecraft:lodestone", "pass"),  # CompassItem
    "minecraft:lead": (lambda b: b.endswith("_fence"), "pass"),  # LeadItem: #fences
    "minecraft:filled_map": (lambda b: b.endswith("banner"), "pass"),  # MapItem: #banners
    "minecraft:end_crystal": (lambda b: b in ("minecraft:obsidian", "minecraft:bedrock"), "fail"),  # EndCrystalItem
    "minecraft:honeycomb": (lambda b: "copper" in b and "waxed" not in b, "pass"),  # HoneycombItem.getWaxed
    "minecraft:shears": (lambda b: b.removeprefix("minecraft:") in _GROWING_PLANT_HEADS, "pass"),  # ShearsItem
    **{f"minecraft:{cart}": (lambda b: b.endswith("rail"), "fail") for cart in (  # MinecartItem: #rails
        "minecart chest_minecart furnace_minecart tnt_minecart hopper_minecart command_block_minecart").split()},
}
_GROWING_PLANT_HEADS = ("kelp", "weeping_vines", "twisting_vines", "cave_vines")  # GrowingPlantHeadBlock
# block items named otherwise than their block (ItemNameBlockItem, Items: redstone -> redstone_wire ...)
_PLACES_ANOTHER_BLOCK = frozenset("minecraft:" + n for n in (
    "redstone string wheat_seeds beetroot_seeds carrot potato melon_seeds pumpkin_seeds torchflower_seeds "
    "pitcher_pod sweet_berries glow_berries cocoa_beans bamboo powder_snow_bucket lily_pad frogspawn").split())


def use_on(state, player, hand: str, pos, face: str, hit) -> str:
    """ItemStack.useOn for an item that is no block the emulator places (see the module's doc)."""
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    stack = access.get()
    if player.gamemode == "adventure":  # ItemStack.useOn: without mayBuild only where can_place_on allows
        if stack.component("minecraft:can_place_on") is not None:
            raise Unmodelled(f"using {stack.id} in adventure mode with can_place_on")
        return "pass"
    use = USE_ON.get(stack.id)
    if use is None:
        clicked = state.blocks.get(pos).id
        acts_on = _ACTS_ONLY_ON.get(stack.id)
        if acts_on is not None and not acts_on[0](clicked):
            return acts_on[1]  # the item's useOn does nothing to this block
        if stack.id in _OWN_USE_ON or stack.id.endswith(_OWN_USE_ON_SUFFIXES) or stack.id in _PLACES_ANOTHER_BLOCK:
            raise Unmodelled(f"using {stack.id} on {clicked} (its useOn is not modelled)")
        return "pass"
    count = stack.count
    result = use(state, player, hand, access, stack, tuple(pos), face)
    if player.gamemode == "creative":  # ServerPlayerGameMode.useItemOn: the count is put back
        stack.count = count
        access.set(stack)
    if result == "consume":
        statistics.award(state, player, statistics.stat_name("used", stack.id))
    return result


def _item_frame(state, player, hand: str, access, stack, pos, face: str) -> str:
    """HangingEntityItem.useOn for an item frame (see the module's doc)."""
    if stack.component("minecraft:entity_data") is not None:
        raise Unmodelled(f"placing {stack.id} with its entity_data component")
    dx, dy, dz = OFFSETS[face]
    front = (pos[0] + dx, pos[1] + dy, pos[2] + dz)
    low, high = state.entities.table.levels.build_height(player.dimension, state.version)
    if not low <= front[1] < high:
        return "fail"
    if not frames.survives(state, front, face, player.dimension):
        return "consume"  # it would not survive: nothing placed, the use still consumed
    centre = frames.centre(front, face)
    yaw, pitch = frames.rotation(face)
    state.entities.summon(stack.id, centre, Compound(Facing=Byte(frames.FACE_DATA[face])), yaw=yaw, pitch=pitch,
                          dimension=player.dimension)
    stack.count -= 1
    access.set(stack)
    return "consume"


# ---------------------------------------------------------------------- armor stands
ARMOR_STAND_SIZE = (0.5, 1.975)  # EntityType.ARMOR_STAND: sized(0.5F, 1.975F)


def _armor_stand(state, player, hand: str, access, stack, pos, face: str) -> str:
    """ArmorStandItem.useOn (see the module's doc)."""
    if face == "down":
        return "fail"
    if stack.component("minecraft:entity_data") is not None:
        raise Unmodelled(f"placing {stack.id} with its entity_data component")
    blocks = state.blocks
    if blocks.get(pos).id not in block_shapes.REPLACEABLE:  # BlockPlaceContext.getClickedPos
        dx, dy, dz = OFFSETS[face]
        pos = (pos[0] + dx, pos[1] + dy, pos[2] + dz)
    width, height = (float(F32(v)) for v in ARMOR_STAND_SIZE)
    box = (pos[0] + 0.5 - width / 2, pos[1], pos[2] + 0.5 - width / 2,
           pos[0] + 0.5 + width / 2, pos[1] + height, pos[2] + 0.5 + width / 2)
    if any(block_shapes.collides(blocks.get((pos[0], pos[1] + up, pos[2]))) for up in (0, 1)) or \
            _any_entity_in(state, player.dimension, box):
        return "fail"
    below = blocks.get((pos[0], pos[1] - 1, pos[2]))
    if not block_shapes.is_collision_full(below):  # EntityType.getYOffset: it would stand lower, then fall
        raise Unmodelled(f"placing an armor stand over {below.id} (where it lands)")
    turned = mth.wrap_degrees_f(F32(player.yaw) - F32(180.0))
    yaw = float(F32(mth.floor_f((turned + F32(22.5)) / F32(45.0))) * F32(45.0))
    stand = state.entities.summon("minecraft:armor_stand", (pos[0] + 0.5, float(pos[1]), pos[2] + 0.5), None,
                                  yaw=yaw, pitch=0.0, dimension=player.dimension)
    name = stack.component("minecraft:custom_name")  # EntityType.appendCustomNameConfig
    if name is not None:
        stand.custom_name = str(name) if isinstance(name, String) else TextTag(name)
    stack.count -= 1
    access.set(stack)
    return "consume"


def _any_entity_in(state, dimension: str, box) -> bool:
    """Level.getEntities(null, box): any entity but a spectator whose box meets it."""
    for entity in state.entities.entities:
        if not entity.alive or entity.dimension != dimension or (entity.is_player and entity.gamemode == "spectator"):
            continue
        other = entity.bounding_box
        if all(box[i] < other[i + 3] and box[i + 3] > other[i] for i in range(3)):
            return True
    return False


# ---------------------------------------------------------------------- water bottles
TO_MUD = frozenset(("minecraft:dirt", "minecraft:coarse_dirt", "minecraft:rooted_dirt"))  # #convertable_to_mud


def _potion(state, player, hand: str, access, stack, pos, face: str) -> str:
    """PotionItem.useOn: a water bottle on dirt, coarse or rooted dirt (not from below) makes it
    mud and leaves a glass bottle (ItemUtils.createFilledResult), counting used:potion itself
    (and ItemStack.useOn once more); any other use passes."""
    if face == "down" or state.blocks.get(pos).id not in TO_MUD or not cauldrons.is_water_bottle(stack):
        return "pass"
    access.set(player_actions.filled_result(state, player, stack, ItemStack("minecraft:glass_bottle", 1)))
    statistics.award(state, player, statistics.stat_name("used", stack.id))
    _set_block(state, pos, "minecraft:mud", {})
    return "consume"


# ---------------------------------------------------------------------- tools
TILLED = {"minecraft:grass_block": "minecraft:farmland", "minecraft:dirt_path": "minecraft:farmland",
          "minecraft:dirt": "minecraft:farmland", "minecraft:coarse_dirt": "minecraft:dirt"}  # HoeItem.TILLABLES
FLATTENED = frozenset("minecraft:" + n for n in "grass_block dirt podzol coarse_dirt mycelium rooted_dirt".split())
_STRIPPABLE = ("_log", "_wood", "_stem", "_hyphae", "bamboo_block")
_OXIDISED = ("exposed_", "weathered_", "oxidized_")  # WeatheringCopper's stages after the first


def _set_block(state, pos, block_id: str, properties: dict) -> None:
    state.blocks.set_state(pos, BlockState.of(block_id, properties))


def _air_above(state, pos) -> bool:
    return state.blocks.get((pos[0], pos[1] + 1, pos[2])).is_air


def _hoe(state, player, hand: str, access, stack, pos, face: str) -> str:
    """HoeItem.useOn: grass, a path or dirt tills to farmland, coarse dirt to dirt, clicked on any
    face but the bottom with air above (onlyIfAirAbove); the hoe is worn by one. Rooted dirt (its
    hanging roots dropped from the face) is not modelled."""
    block = state.blocks.get(pos)
    if block.id == "minecraft:rooted_dirt":
        raise Unmodelled("tilling rooted dirt (the hanging roots it drops)")
    tilled = TILLED.get(block.id)
    if tilled is None or face == "down" or not _air_above(state, pos):
        return "pass"
    _set_block(state, pos, tilled, {"moisture": "0"} if tilled == "minecraft:farmland" else {})
    tools.hurt_and_break(state, player, access, 1)
    return "consume"


def _shovel(state, player, hand: str, access, stack, pos, face: str) -> str:
    """ShovelItem.useOn (not on the bottom face): grass, dirt, podzol, coarse or rooted dirt and
    mycelium with air above flatten to a path; else a lit campfire is put out (lit=false); the
    shovel is worn by one."""
    block = state.blocks.get(pos)
    if face == "down":
        return "pass"
    if block.id in FLATTENED and _air_above(state, pos):
        _set_block(state, pos, "minecraft:dirt_path", {})
    elif block.id in inventories.CAMPFIRES and dict(block.properties).get("lit") == "true":
        _set_block(state, pos, block.id, {**dict(block.properties), "lit": "false"})
    else:
        return "pass"
    tools.hurt_and_break(state, player, access, 1)
    return "consume"


def _axed(state, block):
    """AxeItem.evaluateNewBlockState: a log, wood, stem, hyphae or bamboo block stripped (its
    axis kept), else copper scraped back one stage (WeatheringCopper.getPrevious), else its wax
    taken off (HoneycombItem.WAX_OFF_BY_BLOCK), the other properties kept; None for any other."""
    name = block.id.removeprefix("minecraft:")
    properties = dict(block.properties)
    if name.endswith(_STRIPPABLE) and not name.startswith("stripped_") and \
            gamedata.block_states(f"minecraft:stripped_{name}", state.version) is not None:
        return f"minecraft:stripped_{name}", {"axis": properties.get("axis", "y")}
    if "copper" in name:
        if name.startswith("waxed_"):
            previous = name.removeprefix("waxed_")
        elif name.startswith(_OXIDISED):
            stage = next(p for p in _OXIDISED if name.startswith(p))
            rest = name.removeprefix(stage)
            earlier = _OXIDISED.index(stage)
            previous = _OXIDISED[earlier - 1] + rest if earlier else ("copper_block" if rest == "copper" else rest)
        else:
            return None
        if name.endswith("_door"):
            raise Unmodelled(f"scraping {block.id} (the door's other half)")
        return f"minecraft:{previous}", properties
    return None


def _axe(state, player, hand: str, access, stack, pos, face: str) -> str:
    """AxeItem.useOn: with a shield in the offhand a main-hand axe passes unless the player sneaks
    (playerHasShieldUseIntent); else the block changes (see _axed), ``item_used_on_block`` fires
    with the block as it was (the axe's own trigger, before the one of every use), and the axe is
    worn by one."""
    offhand = inventories.entity_slot(player, inventories.OFFHAND, state.version).get()
    if hand == MAIN and offhand.id == "minecraft:shield" and not player.sneaking:
        return "pass"
    block = state.blocks.get(pos)
    changed = _axed(state, block)
    if changed is None:
        return "pass"
    advancements.trigger(state, player, "item_used_on_block", advancements.location_test(state, player, pos, stack))
    _set_block(state, pos, *changed)
    tools.hurt_and_break(state, player, access, 1)
    return "consume"


def _tool(use, suffix: str):
    return {f"minecraft:{tier}{suffix}": use for tier in TOOL_TIERS}


TOOL_TIERS = ("wooden", "stone", "iron", "golden", "diamond", "netherite")
USE_ON = {"minecraft:item_frame": _item_frame, "minecraft:glow_item_frame": _item_frame,
          "minecraft:armor_stand": _armor_stand, "minecraft:potion": _potion,
          "minecraft:flint_and_steel": fire.flint_and_steel,
          **_tool(_hoe, "_hoe"), **_tool(_shovel, "_shovel"), **_tool(_axe, "_axe")}
