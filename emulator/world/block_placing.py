"""A player placing the block its held item stands for (BlockItem.useOn), with what a datapack observes:
the block, the item spent, ``minecraft.used:<item>`` and the ``placed_block`` criterion.

- ``place(state, player, hand, clicked, face) -> str``: ``"consume"`` when placed, ``"fail"`` when
  there is no room, ``"pass"`` for an adventure player; None when the held item places no block
  the emulator knows (the caller decides what that means). A block with state properties takes the
  state its placement gives it (emulator.world.placed_states: facing, axis, half ...; a block whose
  rule is not modelled raises Unmodelled), and the stairs beside it take their new shape; a head
  keeps the item's profile, note block sound, name and other components in its block entity; items
  carrying block data (``block_state``, ``block_entity_data``) raise Unmodelled. Other neighbours'
  shapes (fences, walls, panes, redstone) do not follow, as after ``setblock`` here.

Where it goes (BlockPlaceContext): on the clicked block when that one can be replaced (air, water,
lava, grass ...), else on its neighbour in the clicked face's direction, which then must be
replaceable; a living entity (or vehicle) in the way refuses it (Level.isUnobstructed).

Sources (decompiled 1.21.x): world/item/BlockItem.java (useOn, place: PLACED_BLOCK, consume), world/level/block/entity/BlockEntity.java
(applyComponents) and SkullBlockEntity.java (applyImplicitComponents, saveAdditional),
world/item/context/BlockPlaceContext.java, world/item/ItemStack.java (useOn: ITEM_USED; adventure:
canPlaceOnBlockInAdventureMode), world/level/block/state/BlockBehaviour.java (canBeReplaced: the
``replaceable`` tag), world/entity/Entity.java (blocksBuilding).
"""
from __future__ import annotations

from dataclasses import replace

from emulator.world import advancements, inventories, placed_parts, placed_states, statistics
from emulator.world.block_shapes import REPLACEABLE
from emulator.world.blocks import BlockSpec
from emulator.world.errors import Unmodelled
from emulator.world.inventories import NOT_LIVING
from emulator.world.nbt_ops import copy_tag
from mcfunction_parser.nbt import Compound
from mcfunction_parser import gamedata

_OFFSETS = {"up": (0, 1, 0), "down": (0, -1, 0), "north": (0, 0, -1), "south": (0, 0, 1), "west": (-1, 0, 0),
            "east": (1, 0, 0)}
_VEHICLES = ("boat", "raft", "minecart")
SKULLS = ("_skull", "_head")
# the components a head's block entity reads, and the names it saves them under (SkullBlockEntity)
_SKULL_READS = {"minecraft:profile": "profile", "minecraft:note_block_sound": "note_block_sound",
                "minecraft:custom_name": "custom_name"}


def place(state, player, hand_slot: int, clicked, face: str, hit=None) -> str | None:
    """BlockItem.useOn with the stack in ``hand_slot`` on the block ``clicked``, face ``face``, the
    click at ``hit`` (the block's corner when not given)."""
    access = inventories.entity_slot(player, hand_slot, state.version)
    stack = access.get()
    item_id = block_id = stack.id
    properties = _block_properties(block_id, state.version)
    if properties is None:
        return None
    if player.gamemode == "adventure":
        return "pass"  # no can_place_on here (its block predicates are not modelled): refused
    entity = _placed_entity(stack, block_id)
    low, high = state.entities.table.levels.build_height(player.dimension, state.version)
    ctx = _context(state, placed_parts.PlaceContext(state, player, block_id, tuple(clicked), face,
                                                    tuple(hit) if hit is not None else tuple(clicked), True, high))
    if ctx is None or not low <= ctx.target[1] < high or _obstructed(state, ctx.target, player.dimension):
        return "fail"
    placed = _placed_state(ctx, properties)
    if placed is None:
        return "fail"
    block_id, block_properties = placed
    state.blocks.setblock(ctx.target, BlockSpec(block_id, False, tuple(sorted(block_properties.items())), entity))
    placed_parts.after_placed(state, ctx.target, block_id, block_properties)
    placed_states.update_neighbour_stairs(state, ctx.target)
    advancements.trigger(state, player, "placed_block", advancements.location_test(state, player, ctx.target, stack))
    if player.gamemode != "creative":
        stack.count -= 1
        access.set(stack)
    statistics.award(state, player, statistics.stat_name("used", item_id))
    return "consume"


def _placed_entity(stack, block_id: str) -> Compound | None:
    """What the placed block's entity takes from the item (BlockItem.place ->
    BlockEntity.applyComponentsFromItemStack, 1.20.5+): a head or skull reads its ``profile``,
    ``note_block_sound`` and ``custom_name`` (SkullBlockEntity.applyImplicitComponents, saved under
    those names) and keeps the rest of the item's added components under ``components`` (a
    machine library reads its ``custom_data`` there). Another block's use of them, block data
    (``block_state``, ``block_entity_data``) and a head profile the game would still have to look
    up (one without properties and without both a name and an id: ResolvableProfile.isResolved
    in 1.21; the later releases' lookup is not modelled either) are not modelled."""
    for component in ("minecraft:block_state", "minecraft:block_entity_data"):
        if stack.component(component) is not None:
            raise Unmodelled(f"placing {block_id} with its {component} component")
    if not (block_id.endswith(SKULLS) and block_id != "minecraft:piston_head"):
        for component in ("minecraft:custom_name", "minecraft:banner_patterns", "minecraft:profile",
                          "minecraft:note_block_sound"):
            if stack.component(component) is not None:
                raise Unmodelled(f"placing {block_id} with its {component} component")
        return None
    profile = stack.component("minecraft:profile")
    if profile is not None and not _resolved(profile):
        raise Unmodelled(f"placing {block_id} with a profile the game looks up ({profile})")
    entity, rest = Compound(), Compound()
    for name, value in stack.patch.items():
        if name.startswith("!"):
            continue
        if name in _SKULL_READS:
            entity[_SKULL_READS[name]] = copy_tag(value)
        else:
            rest[name] = copy_tag(value)
    if rest:
        entity["components"] = rest
    return entity


def _resolved(profile) -> bool:
    """ResolvableProfile.isResolved (1.21): with properties, or both a name and an id."""
    if not isinstance(profile, Compound):
        return False  # a name alone
    return bool(profile.get("properties")) or ("name" in profile and "id" in profile)


def _placed_state(ctx, properties: dict):
    """The block and its whole state (Block.getStateForPlacement); None when it cannot go there."""
    placed = placed_parts.state_for_placement(ctx)
    if placed is NotImplemented:
        return ctx.block_id, (placed_states.state_for_placement(ctx.state, ctx.player, ctx.block_id, properties,
                                                               ctx.target, ctx.face, ctx.hit) if properties else {})
    if placed is not None:
        missing = set(gamedata.block_states(placed[0], ctx.state.version) or ()) - set(placed[1])
        if missing:
            raise Unmodelled(f"placing {placed[0]} (its {', '.join(sorted(missing))} when placed)")
    return placed


def _block_properties(block_id: str, version):
    """The block the item places (the same id: a BlockItem of its block) and its state properties,
    None when the item is no block the registries know."""
    name = block_id.removeprefix("minecraft:")
    if not block_id.startswith("minecraft:") or name not in gamedata.registry("item", version):
        return None
    return gamedata.block_states(block_id, version)


def _context(state, ctx):
    """BlockPlaceContext: the clicked block if the item can replace it, else its neighbour in the
    clicked face's direction if that one can be replaced."""
    if _replaceable(state.blocks.get(ctx.target), ctx):
        return ctx
    dx, dy, dz = _OFFSETS[ctx.face]
    beside = replace(ctx, target=(ctx.target[0] + dx, ctx.target[1] + dy, ctx.target[2] + dz), replace_clicked=False)
    return beside if _replaceable(state.blocks.get(beside.target), beside) else None


def _replaceable(block, ctx) -> bool:
    """BlockBehaviour.canBeReplaced: the replaceable tag, or a slab the item completes."""
    return block.id in REPLACEABLE or placed_parts.replaceable_by(ctx, block)


def _obstructed(state, pos, dimension: str) -> bool:
    """Level.isUnobstructed: a living entity (not a spectator) or vehicle of the level overlapping the block."""
    for entity in state.entities.entities:
        if not entity.alive or (entity.type in NOT_LIVING and not entity.type.endswith(_VEHICLES)):
            continue
        if entity.dimension != dimension:
            continue
        if entity.is_player and entity.gamemode == "spectator":
            continue
        x0, y0, z0, x1, y1, z1 = entity.bounding_box
        if x0 < pos[0] + 1 and x1 > pos[0] and y0 < pos[1] + 1 and y1 > pos[1] and z0 < pos[2] + 1 and z1 > pos[2]:
            return True
    return False

