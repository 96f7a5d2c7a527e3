"""A player using a block (right-clicking it with a hand), as ServerPlayerGameMode.useItemOn carries
it out, with what a datapack observes: the block's new state (levers, buttons that spring back, the
command blocks and crafters beside them hearing the change,
note blocks, doors, trapdoors, fence gates, a barrel's ``open``), the statistics of opening
containers and workstations and of ringing bells, and the ``default_block_use`` /
``item_used_on_block`` criteria. Cauldrons: emulator.world.cauldrons; items that place no block:
emulator.world.items_on_blocks.

- ``use_item_on(state, player, hand, pos, face)``: returns ``"consume"``, ``"pass"`` or ``"fail"``;
  a block or held item whose use is not modelled raises Unmodelled.
- ``tick_menus(state)``: a player's open container closes when it is out of reach or gone
  (Player.tick: containerMenu.stillValid), and the barrel it opened closes with it.
- ``close_menu(state, player)``: the player's open container closes (it leaves, dies, respawns).

The flow (ServerPlayerGameMode.useItemOn, 1.20.5+): a spectator only opens menus; unless the
player sneaks holding something, the block reacts to the item (BlockState.useItemOn; every block
modelled here passes on to the empty-hand use), then, for the main hand, to the hand
(useWithoutItem): if that consumes the action, ``default_block_use`` fires. Otherwise the held
item is used on the block (ItemStack.useOn): a block item places its block
(emulator.world.block_placing) and ``item_used_on_block`` fires; other items are not modelled. Before
1.20.5 the block's use (BlockState.use) fires ``item_used_on_block`` with the held stack.

Sources (decompiled 1.21.x): server/level/ServerPlayerGameMode.java (useItemOn),
world/level/block/{ChestBlock,EnderChestBlock,BarrelBlock,ShulkerBoxBlock,HopperBlock,
DispenserBlock,AbstractFurnaceBlock,BrewingStandBlock,CraftingTableBlock,AnvilBlock,...}.java
(useWithoutItem, the statistic each awards), LeverBlock.pull, ButtonBlock (press, the ticks it
stays pressed: BlockSetType / ButtonBlock constructor), NoteBlock.useWithoutItem/useItemOn,
DoorBlock, TrapDoorBlock, FenceGateBlock (useWithoutItem), BarrelBlockEntity.startOpen/stopOpen
(ContainerOpenersCounter), world/Container.stillValidBlockEntity, core/Direction.fromYRot,
advancements/critereon/ItemUsedOnLocationTrigger.java and DefaultBlockInteractionTrigger.java.
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import (advancements, block_placing, block_shapes, cauldrons, command_blocks, crafters, inventories,
                            item_cooldowns, items, items_on_blocks, placed_states, signs, statistics)
from emulator.world.blocks import BlockState
from emulator.world.context import Context
from emulator.world.living import attribute_value
from emulator.world.player_actions import MAIN, hand_slot
from emulator.world.id_families import COLOURS, WOODS
from emulator.world.errors import Unmodelled
from mcfunction_parser.nbt import Compound, Int

DEFAULT_BLOCK_USE_VERSION = (1, 20, 5)  # useWithoutItem and its own trigger (24w13a)
F32 = np.float32
MENU_REACH = 4.0  # Container.stillValidBlockEntity's buffer over the block interaction range

# the statistic a container or workstation awards when its menu opens (None: it has none)
MENUS = {
    "minecraft:chest": "open_chest", "minecraft:trapped_chest": "trigger_trapped_chest",
    "minecraft:ender_chest": "open_enderchest", "minecraft:barrel": "open_barrel",
    "minecraft:shulker_box": "open_shulker_box", **{f"minecraft:{c}_shulker_box": "open_shulker_box" for c in COLOURS},
    "minecraft:hopper": "inspect_hopper", "minecraft:dispenser": "inspect_dispenser",
    "minecraft:dropper": "inspect_dropper", "minecraft:furnace": "interact_with_furnace",
    "minecraft:smoker": "interact_with_smoker", "minecraft:blast_furnace": "interact_with_blast_furnace",
    "minecraft:brewing_stand": "interact_with_brewingstand", "minecraft:crafting_table": "interact_with_crafting_table",
    "minecraft:anvil": "interact_with_anvil", "minecraft:chipped_anvil": "interact_with_anvil",
    "minecraft:damaged_anvil": "interact_with_anvil", "minecraft:grindstone": "interact_with_grindstone",
    "minecraft:stonecutter": "interact_with_stonecutter", "minecraft:loom": "interact_with_loom",
    "minecraft:cartography_table": "interact_with_cartography_table",
    "minecraft:smithing_table": "interact_with_smithing_table", "minecraft:enchanting_table": None,
}
_MENU_BLOCKS = frozenset(MENUS) | {"minecraft:lectern"}  # blocks whose menu stays open while they stand
# containers that do not open with a solid block above (ChestBlock.isChestBlockedAt,
# EnderChestBlock) or in front of their lid (ShulkerBoxBlock.canOpen)
_BLOCKED_ABOVE = {"minecraft:chest", "minecraft:trapped_chest", "minecraft:ender_chest"}
# buttons: the ticks they stay pressed (ButtonBlock: stone 20, wood 30)
BUTTONS = {**{f"minecraft:{w}_button": 30 for w in WOODS}, "minecraft:stone_button": 20,
           "minecraft:polished_blackstone_button": 20}
_HAND_OPENED = {"door", "trapdoor"}  # every type but iron (BlockSetType.canOpenByHand)
_DIRECTIONS = ("south", "west", "north", "east")  # Direction.from2DDataValue
_OFFSETS = {"up": (0, 1, 0), "down": (0, -1, 0), "north": (0, 0, -1), "south": (0, 0, 1), "west": (-1, 0, 0),
            "east": (1, 0, 0)}

def use_item_on(state, player, hand: str, pos, face: str, hit=None) -> str:
    """ServerPlayerGameMode.useItemOn with the stack in ``hand`` on the block at ``pos``, clicked at
    ``hit`` (the block's corner when not given)."""
    pos = tuple(pos)
    hit = tuple(hit) if hit is not None else pos
    block = state.blocks.get(pos)
    stack = inventories.entity_slot(player, hand_slot(hand), state.version).get()
    if player.gamemode == "spectator":
        if block.id == "minecraft:lectern":
            return _lectern(state, player, pos, block, award=False) if _property(block, "has_book", "") == "true" else "pass"
        return _open_menu(state, player, pos, block, award=False) if block.id in MENUS else "pass"
    holding = any(not inventories.entity_slot(player, s, state.version).get().is_empty
                  for s in (inventories.MAINHAND, inventories.OFFHAND))
    if not (player.sneaking and holding):
        before = stack.copy()
        on_block = _use_item_on_block(state, player, hand, pos, block, stack, face)
        if on_block == "consume":  # BlockState.useItemOn consumed the action: the criterion with the stack as it was
            advancements.trigger(state, player, "item_used_on_block", advancements.location_test(state, player, pos, before))
            return on_block
        if on_block == "try_empty_hand" and hand == MAIN:
            result = _use_without_item(state, player, pos, block, face, hit)
            if result == "consume":
                if tuple(state.version) >= DEFAULT_BLOCK_USE_VERSION:
                    trigger, used = "default_block_use", None
                else:
                    trigger, used = "item_used_on_block", stack
                advancements.trigger(state, player, trigger, advancements.location_test(state, player, pos, used))
                return result
    if stack.is_empty or item_cooldowns.on_cooldown(state, player, stack):
        return "pass"
    placed = block_placing.place(state, player, hand_slot(hand), pos, face, hit)
    if placed is None:
        placed = items_on_blocks.use_on(state, player, hand, pos, face, hit)
    if placed == "consume":  # ItemStack.useOn consumed the action: the criterion, with the stack as it was
        advancements.trigger(state, player, "item_used_on_block", advancements.location_test(state, player, pos, stack))
    return placed


def _use_item_on_block(state, player, hand: str, pos, block: BlockState, stack, face: str) -> str:
    """BlockBehaviour.useItemOn: ``"try_empty_hand"`` (PASS_TO_DEFAULT_BLOCK_INTERACTION) for the
    blocks modelled here, except a note block clicked on top with a head (NoteBlock.useItemOn:
    ``"skip"``, the head is placed instead) and a lectern (LecternBlock.useItemOn: a lectern book
    goes onto one without a book, ``"consume"``; an empty main hand skips to the item); a dye, ink
    sac or honeycomb applied to an unwaxed sign (SignBlock.useItemOn) and food put on a campfire
    (CampfireBlock.useItemOn) are not modelled; a cauldron's is emulator.world.cauldrons."""
    if block.id == "minecraft:note_block" and face == "up" and stack.id.endswith(("_head", "_skull")):
        return "skip"
    if block.id == "minecraft:lectern":
        return _lectern_item(state, player, hand, pos, block, stack)
    if block.id in cauldrons.CAULDRONS:
        return cauldrons.use_item_on(state, player, hand, pos, block, stack)
    if block.id in inventories.CAMPFIRES and not stack.is_empty and _cookable(state, stack):
        raise Unmodelled(f"cooking {stack.id} on a campfire (CampfireBlock.useItemOn: placeFood)")
    if signs.is_sign(block.id) and stack.id in signs.APPLICATORS and player.gamemode != "adventure":
        sign = state.blocks.entity(pos)
        if sign is not None and not int(sign.get("is_waxed", 0)):
            raise Unmodelled(f"applying {stack.id} to a sign (SignApplicator.tryApplyToSign)")
    return "try_empty_hand"


# the inputs of the game's campfire_cooking recipes (1.21)
CAMPFIRE_FOODS = frozenset("minecraft:" + n for n in
                           "beef chicken cod salmon mutton porkchop rabbit potato kelp".split())


def _cookable(state, stack) -> bool:
    """CampfireBlockEntity.getCookableRecipe: the game's foods, or any item when a pack adds a
    campfire recipe (its ingredients are not matched here)."""
    return stack.id in CAMPFIRE_FOODS or any(kind == "minecraft:campfire_cooking" and not rid.startswith("minecraft:")
                                             for rid, kind in state.resources.recipes.items())


LECTERN_BOOKS = ("minecraft:writable_book", "minecraft:written_book")  # #minecraft:lectern_books


def _lectern_item(state, player, hand: str, pos, block: BlockState, stack) -> str:
    """LecternBlock.useItemOn: with a book it passes to the empty hand; a lectern book is placed
    (tryPlaceBook -> placeBook: one taken from the stack, not from a creative player, saved as
    ``Book`` with ``Page`` 0, the block ``has_book=true`` and unpowered: resetBookState)."""
    if tuple(state.version) < DEFAULT_BLOCK_USE_VERSION:
        raise Unmodelled("using a lectern before 1.20.5 (LecternBlock.use and the books' useOn)")
    if _property(block, "has_book", "false") == "true":
        return "try_empty_hand"
    if stack.id in LECTERN_BOOKS:
        if stack.id == "minecraft:written_book" and stack.component("minecraft:written_book_content") is not None:
            raise Unmodelled("placing a written book on a lectern (LecternBlockEntity.resolveBook resolves its pages)")
        access = inventories.entity_slot(player, hand_slot(hand), state.version)
        book = stack.copy()
        book.count = 1
        if player.gamemode != "creative":  # ItemStack.consumeAndReturn
            stack.count -= 1
            access.set(stack)
        _set(state, pos, block, has_book="true", powered="false")
        lectern = state.blocks.entity(pos)
        if lectern is None:
            lectern = state.blocks.entities[tuple(pos)] = Compound()
        lectern["Book"] = items.to_nbt(book, state.version)
        lectern["Page"] = Int(0)
        return "consume"
    return "skip" if stack.is_empty and hand == MAIN else "try_empty_hand"


def _lectern(state, player, pos, block: BlockState, award: bool = True) -> str:
    """LecternBlock.useWithoutItem: with a book its menu opens (interact_with_lectern), else the
    use is consumed all the same."""
    if _property(block, "has_book", "false") != "true":
        return "consume"
    close_menu(state, player)
    state.open_menus[player] = (player.dimension, pos)
    if award:
        statistics.award(state, player, statistics.stat_name("custom", "interact_with_lectern"))
    return "consume"


def _use_without_item(state, player, pos, block: BlockState, face: str, hit) -> str:
    """BlockBehaviour.useWithoutItem of the modelled blocks (BlockState.use before 1.20.5)."""
    name = block.id.removeprefix("minecraft:")
    if block.is_air or block.id in PLAIN or block.id.endswith(_PLAIN_KINDS) or block.id in block_shapes.REPLACEABLE:
        return "pass"
    if block.id in MENUS:
        return _open_menu(state, player, pos, block, award=True)
    if signs.is_sign(block.id):
        return signs.use(state, player, pos, block, _run_click_command)
    if block.id == "minecraft:lectern":
        return _lectern(state, player, pos, block)
    if block.id == "minecraft:lever":
        _set(state, pos, block, powered=_flip(block, "powered"))
        _neighbours_hear(state, pos)
        return "consume"
    if block.id in BUTTONS:
        return _press(state, pos, block)
    if block.id == "minecraft:bell":
        return _bell(state, player, pos, block, face, hit)
    if block.id == "minecraft:note_block":
        note = int(_property(block, "note", "0"))
        _set(state, pos, block, note=str((note + 1) % 25))
        statistics.award(state, player, statistics.stat_name("custom", "tune_noteblock"))
        return "consume"
    kind = name.rsplit("_", 1)[-1]
    if kind in _HAND_OPENED and not name.startswith("iron_"):
        return _open_door(state, pos, block) if kind == "door" else _toggle(state, pos, block)
    if name.endswith("fence_gate"):
        return _fence_gate(state, player, pos, block)
    if kind in _HAND_OPENED:
        return "pass"  # iron doors and trapdoors open by redstone only
    raise Unmodelled(f"using the block {block.id} (its interaction is not modelled)")


BELL_PROPER_HIT_HEIGHT = float(F32(0.8124))  # BellBlock.isProperHit: a side clicked no higher in the block
# raiders a ringing bell shows (BellBlockEntity: #raiders; made to glow when it stops shaking)
_RAIDERS = frozenset("minecraft:" + n for n in "pillager vindicator evoker illusioner ravager witch".split())


def _bell(state, player, pos, block: BlockState, face: str, hit) -> str:
    """BellBlock.useWithoutItem -> onHit -> isProperHit: a side (not the top or bottom) clicked at
    most 0.8124 up the block rings it when the side lies on the bell's facing axis for a floor
    bell, off it for a wall bell, any side for a ceiling bell: ``minecraft.custom:minecraft.
    bell_ring``; any other click passes (on to the held item). A ringing bell near raiders (48
    blocks) makes them glow after it shakes: not modelled."""
    facing, attachment = _property(block, "facing", "north"), _property(block, "attachment", "floor")
    if face in ("up", "down") or hit[1] - pos[1] > BELL_PROPER_HIT_HEIGHT:
        return "pass"
    across = placed_states.AXIS[facing] == placed_states.AXIS[face]
    if not {"floor": across, "ceiling": True}.get(attachment, not across):
        return "pass"
    centre = (pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5)
    for entity in state.entities.living_mobs():
        if entity.type in _RAIDERS and entity.dimension == player.dimension and \
                all(abs(c - p) <= 48.5 for c, p in zip(entity.pos, centre)):
            raise Unmodelled("a ringing bell showing raiders nearby (BellBlockEntity.makeRaidersGlow)")
    statistics.award(state, player, statistics.stat_name("custom", "bell_ring"))
    return "consume"


def _run_click_command(state, command: str, player, pos) -> None:
    """SignBlockEntity.executeClickCommandsIfPresent: performPrefixedCommand as the player, at the
    sign's centre, rotation zero, in the player's level (createCommandSourceStack)."""
    at = (pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5)
    state.command_runner(command.removeprefix("/"), Context(player.order, at, (0.0, 0.0), "feet", player.dimension))


def _property(block: BlockState, key: str, default: str) -> str:
    return dict(block.properties).get(key, default)


def _flip(block: BlockState, key: str) -> str:
    return "false" if _property(block, key, "false") == "true" else "true"


def _set(state, pos, block: BlockState, **changes: str) -> BlockState:
    properties = dict(block.properties)
    properties.update(changes)
    new = BlockState(block.id, tuple(sorted(properties.items())))
    state.blocks.set_state(pos, new)
    return new


def _toggle(state, pos, block: BlockState) -> str:
    """TrapDoorBlock.toggle: OPEN cycles."""
    _set(state, pos, block, open=_flip(block, "open"))
    return "consume"


def _open_door(state, pos, block: BlockState) -> str:
    """DoorBlock.useWithoutItem: OPEN cycles; the other half follows (DoorBlock.updateShape copies
    the state to the half above or below)."""
    half = dict(block.properties).get("half")
    if half is None:
        raise Unmodelled(f"using a {block.id} placed without its 'half' property")
    opened = _flip(block, "open")
    _set(state, pos, block, open=opened)
    other = (pos[0], pos[1] + (1 if half == "lower" else -1), pos[2])
    partner = state.blocks.get(other)
    if partner.id == block.id and _property(partner, "half", "") != half:
        _set(state, other, partner, open=opened)
    return "consume"


def _fence_gate(state, player, pos, block: BlockState) -> str:
    """FenceGateBlock.useWithoutItem: an open gate closes; a closed one opens, turning to face the way
    the player looks when it faced the player."""
    if _property(block, "open", "false") == "true":
        _set(state, pos, block, open="false")
        return "consume"
    looking = _DIRECTIONS[math.floor(float(player.yaw) / 90.0 + 0.5) & 3]
    opposite = {"south": "north", "north": "south", "west": "east", "east": "west"}[looking]
    facing = _property(block, "facing", "north")
    _set(state, pos, block, open="true", facing=looking if facing == opposite else facing)
    return "consume"


def _press(state, pos, block: BlockState) -> str:
    """ButtonBlock.useWithoutItem: a pressed button consumes the use; else it is pressed and springs
    back after its ticks (ButtonBlock.tick -> checkPressed, no arrows here)."""
    if _property(block, "powered", "false") == "true":
        return "consume"
    _set(state, pos, block, powered="true")
    _neighbours_hear(state, pos)

    def release(state, pos) -> None:
        current = state.blocks.get(pos)
        _set(state, pos, current, powered="false")
        _neighbours_hear(state, pos)
    state.block_ticks.schedule(pos, block.id, BUTTONS[block.id], state.gametime, release)
    return "consume"


def _neighbours_hear(state, pos) -> None:
    """LeverBlock.pull / ButtonBlock.press and checkPressed: updateNeighbours, so a command block
    or crafter beside it reads its new signal (the neighbours of the block it hangs on are not
    reached: power through a block is not modelled)."""
    dimension = getattr(state, "dimension", "minecraft:overworld")
    command_blocks.after_change(state, dimension, [pos])
    crafters.after_change(state, dimension, [pos])


# ---------------------------------------------------------------------- containers
def _open_menu(state, player, pos, block: BlockState, award: bool) -> str:
    """The block's menu opens (Player.openMenu): the player's open container closes first; a chest
    under a block or a shulker box with its lid blocked does not open (the use still succeeds); a
    locked container or one with a loot table to unpack is not modelled."""
    nbt = state.blocks.entity(pos) or Compound()
    if nbt.get("lock") or nbt.get("Lock"):
        raise Unmodelled(f"opening the locked {block.id}")
    if "LootTable" in nbt:
        raise Unmodelled(f"opening {block.id}: unpacking its loot table when opened")
    if block.id in _BLOCKED_ABOVE and _property(block, "type", "single") != "single":
        raise Unmodelled(f"opening a double {block.id}")
    blocker = _blocker(block, pos)
    if blocker is not None and not state.blocks.get(blocker).is_air:
        raise Unmodelled(f"opening {block.id} under {state.blocks.get(blocker).id} (whether it blocks the lid)")
    close_menu(state, player)
    if block.id == "minecraft:barrel":
        _set(state, pos, block, open="true")  # BarrelBlockEntity.startOpen -> updateBlockState
    state.open_menus[player] = (player.dimension, pos)
    if award and MENUS[block.id] is not None:
        statistics.award(state, player, statistics.stat_name("custom", MENUS[block.id]))
    return "consume"


def _blocker(block: BlockState, pos):
    if block.id in _BLOCKED_ABOVE:
        return (pos[0], pos[1] + 1, pos[2])
    if block.id.endswith("shulker_box"):
        dx, dy, dz = _OFFSETS[_property(block, "facing", "up")]
        return (pos[0] + dx, pos[1] + dy, pos[2] + dz)
    return None


def close_menu(state, player) -> None:
    """AbstractContainerMenu.removed -> Container.stopOpen: a barrel with no viewer left closes."""
    opened = state.open_menus.pop(player, None)
    if opened is None:
        return
    level = state.level(opened[0])
    pos = opened[1]
    block = level.blocks.get(pos)
    if block.id == "minecraft:barrel" and opened not in state.open_menus.values():
        _set(level, pos, block, open="false")


def tick_is_idle(state) -> bool:
    """Whether :func:`tick_menus` would do nothing now: no player has a container open."""
    return not state.open_menus


def tick_menus(state) -> None:
    """Player.tick: a menu no longer valid closes (the block is gone, or the player's eyes are out of
    the block interaction range + 4 of the block's box: Player.canInteractWithBlock)."""
    if not state.open_menus:  # every tick: no open container is the common case
        return
    for player, (dimension, pos) in list(state.open_menus.items()):
        if (not player.alive or player.dimension != dimension or state.blocks_in(dimension).get(pos).id not in _MENU_BLOCKS
                or not _within_reach(player, pos)):
            close_menu(state, player)


def _within_reach(player, pos) -> bool:
    eye = player.anchor("eyes")
    gap = [max(lo - c, 0.0, c - (lo + 1)) for c, lo in zip(eye, pos)]
    reach = attribute_value(player, "block_interaction_range") + MENU_REACH
    return sum(g * g for g in gap) < reach * reach


# blocks without a use of their own (plain Block, RotatedPillarBlock, StairBlock, piston bases,
# observers ...): a click on them goes on to the held item
PLAIN = frozenset("minecraft:" + n for n in (
    "stone granite diorite andesite cobblestone dirt coarse_dirt grass_block sand red_sand gravel bedrock glass "
    "obsidian smooth_stone stone_bricks deepslate netherrack end_stone bricks sandstone barrier iron_block "
    "gold_block diamond_block emerald_block lapis_block coal_block netherite_block piston sticky_piston observer "
    "hay_block bone_block basalt polished_basalt quartz_pillar purpur_pillar carved_pumpkin jack_o_lantern "
    "end_rod campfire soul_campfire").split()) | frozenset(
    f"minecraft:{c}_{k}" for c in COLOURS for k in ("wool", "concrete", "terracotta", "stained_glass")) | frozenset(
    f"minecraft:{w}_planks" for w in WOODS)
_PLAIN_KINDS = ("_stairs", "_slab", "_torch", "_log", "_wood", "_stem", "_hyphae", "_glazed_terracotta",
                "copper", "copper_block", "copper_grate", "copper_bulb", "cauldron")  # copper's blocks (WeatheringCopper*)
