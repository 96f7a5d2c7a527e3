"""Crafters: a crafter powered by a neighbour crafts from its nine slots, as the game's CrafterBlock
does, with what a pack observes: the result and remainders in the container in front or thrown
into the world, the slots each one item lighter, the ``triggered`` and ``crafting`` states, the
``crafter_recipe_crafted`` criterion.

- ``after_change(state, dimension, positions)``: after ``setblock``/``fill`` changed ``positions``,
  each crafter beside a changed block hears it (CrafterBlock.neighborChanged): powered
  (:func:`emulator.world.command_blocks.has_neighbour_signal`) and not ``triggered``, it becomes
  triggered and crafts in 4 ticks; unpowered and triggered, it is neither triggered nor crafting.
  A crafter placed beside a power source is not triggered by its own placement (``setblock`` only
  updates the neighbours), as in the game.
- The craft (CrafterBlock.dispenseFrom): the recipe of the slots (:func:`emulator.world.crafting.craft`);
  none, or an empty result: nothing. Else ``crafting`` for 6 ticks (CrafterBlockEntity.serverTick
  counts ``crafting_ticks_remaining`` down: :func:`tick_crafting`, after the entities' steps), the
  result then each remainder dispensed (dispenseItem), then every stack of the slots shrinks by one.
- dispenseItem: into the container in front (:func:`emulator.world.hoppers.add_item`, through the
  face the crafter meets: a free slot takes the stack, a matching one fills up to the item's
  maximum; one at a time when the stack is bigger than the container takes, 99), what does not fit thrown from 0.7 past the crafter's
  centre, 0.15625 lower (0.125 facing up or down), with DefaultDispenseItemBehavior.spawnItem's
  motion (speed 6) and no pickup delay; then every player whose box meets the 17-block cube around
  the crafter fires ``crafter_recipe_crafted`` with the recipe and the nine slots' stacks. The
  containers in front are those a hopper sees (:func:`emulator.world.hoppers.container_at`: chests
  single or double, barrels, hoppers, dispensers, droppers, shulker boxes, furnaces by face);
  another one (a crafter, a brewing stand ...) or a container entity there is not modelled (Unmodelled).

Sources (decompiled 1.21): world/level/block/CrafterBlock.java (neighborChanged, tick,
dispenseFrom, dispenseItem), block/entity/CrafterBlockEntity.java (serverTick, saveAdditional:
``crafting_ticks_remaining``, ``triggered``), block/entity/HopperBlockEntity.java (getContainerAt,
addItem, tryMoveInItem, canMergeItems), core/dispenser/DefaultDispenseItemBehavior.spawnItem,
world/Container.getMaxStackSize (99), advancements/critereon/RecipeCraftedTrigger.java.
"""
from __future__ import annotations

from emulator.world import advancements, command_blocks, crafting, hoppers, inventories, predicates
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.loot_context import namespaced
from mcfunction_parser.nbt import Double, Int, List, Short

CRAFTER = "minecraft:crafter"
CRAFT_DELAY, CRAFTING_TICKS = 4, 6
CONTAINER_MAX = 99  # Container.getMaxStackSize


def _properties(block) -> dict[str, str]:
    return dict(block.properties)


def _with(block, **changes: str) -> BlockState:
    props = _properties(block)
    props.update(changes)
    return BlockState(block.id, tuple(props.items()))


def after_change(state, dimension: str, positions) -> None:
    level = state.level(dimension)
    for pos in command_blocks.neighbours_of(level.blocks, positions, (CRAFTER,)):
        _neighbour_changed(level, pos)


def _neighbour_changed(level, pos) -> None:
    block, nbt = level.blocks.get(pos), level.blocks.entity(pos)
    powered = command_blocks.has_neighbour_signal(level, pos)
    triggered = _properties(block).get("triggered") == "true"
    if powered and not triggered:
        level.block_ticks.schedule(pos, CRAFTER, CRAFT_DELAY, level.gametime, craft)
        level.blocks.set_state(pos, _with(block, triggered="true"))
    elif not powered and triggered:
        level.blocks.set_state(pos, _with(block, triggered="false", crafting="false"))
    else:
        return
    if nbt is not None:
        nbt["triggered"] = Int(int(powered))


def craft(level, pos) -> None:
    """CrafterBlock.dispenseFrom (a scheduled block tick: what is not modelled is reported, and the
    craft stops there)."""
    try:
        _craft(level, pos)
    except Unmodelled as reason:
        _world(level).error(f"the crafter at {' '.join(map(str, pos))}: {reason}", severity="warning",
                            unmodelled=True)


def _craft(level, pos) -> None:
    nbt = level.blocks.entity(pos)
    if nbt is None:
        return
    box = inventories.Container(nbt, 9, level.version)
    grid = [box.slot(i).get() for i in range(9)]
    crafted = crafting.craft(level.resources, grid, level.version)
    if crafted is None or crafted.result.is_empty:
        return
    nbt["crafting_ticks_remaining"] = Int(CRAFTING_TICKS)
    _world(level).crafting[(_dimension(level), tuple(pos))] = CRAFTING_TICKS
    level.blocks.set_state(pos, _with(level.blocks.get(pos), crafting="true"))
    for stack in [crafted.result] + [r for r in crafted.remainders if not r.is_empty]:
        _dispense(level, pos, stack, crafted.recipe_id, grid)
    for i, stack in enumerate(grid):
        if not stack.is_empty:
            stack.count -= 1
            box.slot(i).set(stack if stack.count > 0 else EMPTY.copy())


def _front(block) -> str:
    return _properties(block).get("orientation", "north_up").split("_")[0]


def _dispense(level, pos, stack: ItemStack, recipe_id: str, grid: list[ItemStack]) -> None:
    """CrafterBlock.dispenseItem."""
    direction = _front(level.blocks.get(pos))
    step = hoppers.OFFSETS[direction]
    target = (pos[0] + step[0], pos[1] + step[1], pos[2] + step[2])
    rest = stack.copy()
    container = hoppers.container_at(_world(level), _dimension(level), level.blocks, target,
                                     "a crafter putting its result into")
    if container is not None:
        one_at_a_time = stack.count > min(CONTAINER_MAX, stack.max_stack_size)
        face = hoppers.OPPOSITE[direction]
        while not rest.is_empty:
            before = rest.count
            moving = rest.copy()
            if one_at_a_time:
                moving.count = 1
            left = hoppers.add_item(None, container, moving, face, set())
            if one_at_a_time:
                if not left.is_empty:
                    break
                rest.count -= 1
            else:
                rest = left
                if rest.count == before:
                    break
    if rest.is_empty:
        return
    _spawn(level, pos, rest, direction, step)
    centre = (pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5)
    for player in level.entities.players():
        if player.alive and player.dimension == _dimension(level) and _meets_cube(player, centre):
            advancements.trigger(_world(level), player, "crafter_recipe_crafted", lambda c, ctx: (
                _recipe_crafted_matches(c, ctx, recipe_id, grid)))


def _spawn(level, pos, stack: ItemStack, direction: str, step) -> None:
    """DefaultDispenseItemBehavior.spawnItem(level, stack, 6, direction, centre + 0.7 x direction)."""
    x, y, z = (pos[i] + 0.5 + 0.7 * step[i] for i in range(3))
    y -= 0.125 if step[1] else 0.15625
    rng = level.resources.random
    speed = rng.random() * 0.1 + 0.2

    def triangle(mean: float, spread: float) -> float:  # RandomSource.triangle
        return mean + spread * (rng.random() - rng.random())
    motion = [triangle(step[0] * speed, 0.0172275 * 6), triangle(0.2, 0.0172275 * 6),
              triangle(step[2] * speed, 0.0172275 * 6)]
    inventories.drop_item(level.entities, (x, y, z), stack, level.version, rng,
                          {"Motion": List([Double(v) for v in motion]), "PickupDelay": Short(0)},
                          dimension=_dimension(level))


def _dimension(level) -> str:
    """The level's dimension (the overworld's view is the world itself)."""
    return getattr(level, "dimension", "minecraft:overworld")


def _world(level):
    """The world a level view (WorldState.level) belongs to."""
    return getattr(level, "_state", level)


def _meets_cube(player, centre) -> bool:
    """The player's box meets AABB.ofSize(centre, 17, 17, 17) (Level.getEntitiesOfClass)."""
    low, high = player.bounding_box[:3], player.bounding_box[3:]
    return all(lo < c + 8.5 and hi > c - 8.5 for lo, hi, c in zip(low, high, centre))


def _recipe_crafted_matches(conditions: dict, ctx, recipe_id: str, grid: list[ItemStack]) -> bool:
    """RecipeCraftedTrigger.TriggerInstance.matches: the recipe, and each ingredient predicate
    taking a different one of the nine stacks."""
    if namespaced(str(conditions.get("recipe_id", ""))) != recipe_id:
        return False
    left = list(grid)
    for wanted in conditions.get("ingredients", []):
        found = next((i for i, stack in enumerate(left) if predicates.item_matches(wanted, ctx, stack)), None)
        if found is None:
            return False
        left.pop(found)
    return True


def tick_is_idle(state) -> bool:
    return not state.crafting


def tick_crafting(state) -> None:
    """CrafterBlockEntity.serverTick: ``crafting_ticks_remaining`` counts down; at 0 the crafter
    stops ``crafting``."""
    if not state.crafting:  # every tick: no crafter crafting is the common case
        return
    for (dimension, pos), left in list(state.crafting.items()):
        blocks = state.blocks_in(dimension)
        nbt = blocks.entity(pos)
        if blocks.get(pos).id != CRAFTER or nbt is None:
            del state.crafting[(dimension, pos)]
            continue
        left -= 1
        nbt["crafting_ticks_remaining"] = Int(left)
        if left > 0:
            state.crafting[(dimension, pos)] = left
            continue
        del state.crafting[(dimension, pos)]
        blocks.set_state(pos, _with(blocks.get(pos), crafting="false"))
