"""``give``, ``clear``, ``item replace|modify``, ``loot`` and ``execute if items``, on the
inventories of :mod:`emulator.world.inventories` with the loot of :mod:`emulator.world.loot`.

Sources (decompiled 1.21): server/commands/GiveCommand.java, ClearInventoryCommands.java,
ItemCommands.java, LootCommand.java, ExecuteCommand.java (countItems), world/entity/item/ItemEntity.java.
"""
from __future__ import annotations

import json

from emulator.world import enchanting, inventories, loot, text_components
from emulator.world.entities import Entity
from emulator.world.errors import CommandFailure
from emulator.world.item_predicates import matches
from emulator.world.items import ItemStack, create, hover_name
from emulator.world.living import is_living
from emulator.world.loot_context import DamageSource, LootContext
from mcfunction_parser import ast
from mcfunction_parser.nbt import Compound, Int, IntArray, Short

from . import entities
from .advancements import broadcast_changes
from .blocks import loaded_block_pos
from .entities import executor, world_source


def _version(env):
    return env.state.version


def _test(env, predicate: ast.ItemPredicate | None):
    if predicate is None:
        return lambda stack: True
    resources, version = env.state.resources, env.state.version
    return lambda stack: matches(predicate, stack, resources, version)


def _name(env, stack: ItemStack) -> str:
    """ItemStack.getDisplayName as text: the hover name in square brackets."""
    return f"[{hover_name(stack, env.state.version)}]"


def _players(env, target, ctx) -> list[Entity]:
    found = entities.select(env.state, target, ctx)
    if not found or any(not e.is_player for e in found):
        raise CommandFailure("argument.entity.notfound.player")
    return found


def _drop(env, pos, stack: ItemStack, dimension: str, nbt: Compound | None = None) -> Entity:
    return inventories.drop_item(env.state.entities, pos, stack, _version(env), env.state.resources.random, nbt,
                                 dimension)


# ---------------------------------------------------------------------- give / clear
def give(env, cmd: ast.Give, ctx) -> int:
    """GiveCommand: stacks of at most the maximum size into each player's inventory; what does not
    fit is dropped at the player (no pickup delay, owned by the player). The result is the number
    of players."""
    players = _players(env, cmd.targets, ctx)
    sample = create(cmd.item, 1)
    limit = sample.max_stack_size * 100
    if cmd.count > limit:
        raise CommandFailure("commands.give.failed.toomanyitems", limit, _name(env, sample))
    for player in players:
        inventory = inventories.player_inventory(player, _version(env))
        remaining = cmd.count
        while remaining > 0:
            size = min(sample.max_stack_size, remaining)
            remaining -= size
            left = create(cmd.item, size)
            inventory.add(left)  # GiveCommand drops whatever is left of the stack
            if left.is_empty:  # the whole stack went in: its menu broadcasts the change
                broadcast_changes(env, [player])
            else:
                x, y, z = player.pos
                _drop(env, (x, y + float(player.eye_height) - 0.3, z), left, player.dimension,
                      Compound(PickupDelay=Short(0), Owner=IntArray(Int(v) for v in player.uuid)))
    return len(players)


def clear(env, cmd: ast.Clear, ctx) -> int:
    """ClearInventoryCommands: the count removed (or with a maximum of 0, counted); nothing found fails."""
    if cmd.targets is None:
        player = executor(env.state, ctx)
        if player is None or not player.is_player:
            raise CommandFailure("permissions.requires.player")
        players = [player]
    else:
        players = _players(env, cmd.targets, ctx)
    test = _test(env, cmd.item)
    max_count = -1 if cmd.max_count is None else cmd.max_count
    total = 0
    for player in players:  # ClearInventoryCommands: each player's menu broadcasts its changes
        total += inventories.player_inventory(player, _version(env)).clear_or_count(test, max_count)
        broadcast_changes(env, [player])
    if total == 0:
        if len(players) == 1:
            raise CommandFailure("clear.failed.single", players[0].display_name)
        raise CommandFailure("clear.failed.multiple", len(players))
    return total


# ---------------------------------------------------------------------- item
def _container(env, pos_arg, ctx, source: bool) -> inventories.Container:
    pos = loaded_block_pos(env.state, ctx, pos_arg)
    found = inventories.container(env.state.blocks_in(ctx.dimension), pos, _version(env))
    if found is None:
        raise CommandFailure("commands.item.source.not_a_container" if source else
                             "commands.item.target.not_a_container", *pos)
    return found


def _read_slot(env, where: ast.ItemTarget, slot: int, ctx) -> ItemStack:
    """ItemCommands.getEntityItem / getBlockItem: a copy of the source slot."""
    if where.kind == "block":
        access = _container(env, where.target, ctx, source=True).slot(slot)
    else:
        access = inventories.entity_slot(entities.single(env.state, where.target, ctx), slot, _version(env))
    if access is None:
        raise CommandFailure("commands.item.source.no_such_slot", slot)
    return access.get()


def _modify_with(env, modifier: ast.ResourceOrInline, ctx):
    """ItemCommands.applyModifier: the modifier run in a command context, then limitSize."""
    value = modifier.inline
    if value is None:
        value = env.state.resources.item_modifiers.get(modifier.id)
        if value is None:
            raise CommandFailure("dpemu.loot.unknown_modifier", modifier.id, report=True)

    def apply(stack: ItemStack) -> ItemStack:
        result = loot.apply_modifier(value, stack.copy(), loot_context(env, ctx))
        result.count = min(result.count, result.max_stack_size)
        return result
    return apply


def item_replace(env, cmd: ast.ItemReplace, ctx) -> int:
    slot = cmd.slot.ids[0]
    if cmd.item is not None:
        stack = create(cmd.item, 1 if cmd.count is None else cmd.count)
        if cmd.count is not None and cmd.count > stack.max_stack_size:
            raise CommandFailure("arguments.item.overstacked", stack.id, stack.max_stack_size)
    else:
        stack = _read_slot(env, cmd.source, cmd.source_slot.ids[0], ctx)
        if cmd.modifier is not None:
            stack = _modify_with(env, cmd.modifier, ctx)(stack)
    if cmd.target.kind == "block":
        access = _container(env, cmd.target.target, ctx, source=False).slot(slot)
        if access is None:
            raise CommandFailure("commands.item.target.no_such_slot", slot)
        access.set(stack)
        return 1
    accepted = 0
    for entity in entities.found(env.state, cmd.target.target, ctx):
        access = inventories.entity_slot(entity, slot, _version(env))
        accepted += access is not None and access.set(stack.copy())
        broadcast_changes(env, [entity])  # ItemCommands: a player's menu broadcasts
    if accepted == 0:
        raise CommandFailure("commands.item.target.no_changed.known_item", _name(env, stack), slot)
    return accepted


def item_modify(env, cmd: ast.ItemModify, ctx) -> int:
    slot = cmd.slot.ids[0]
    apply = _modify_with(env, cmd.modifier, ctx)
    if cmd.target.kind == "block":
        access = _container(env, cmd.target.target, ctx, source=False).slot(slot)
        if access is None:
            raise CommandFailure("commands.item.target.no_such_slot", slot)
        access.set(apply(access.get()))
        return 1
    accepted = 0
    for entity in entities.found(env.state, cmd.target.target, ctx):
        access = inventories.entity_slot(entity, slot, _version(env))
        if access is not None:
            accepted += access.set(apply(access.get()))
        broadcast_changes(env, [entity])
    if accepted == 0:
        raise CommandFailure("commands.item.target.no_changes", slot)
    return accepted


# ---------------------------------------------------------------------- execute if items
def count_items(env, cond: ast.IfItems, ctx) -> int:
    """ExecuteCommand.countItems: the summed counts of the matching stacks in the slots."""
    test = _test(env, cond.predicate)
    if cond.source.kind == "block":
        holder = _container(env, cond.source.target, ctx, source=True)
        accesses = [holder.slot(s) for s in cond.slots.ids]
    else:
        accesses = [inventories.entity_slot(e, s, _version(env))
                    for e in entities.found(env.state, cond.source.target, ctx) for s in cond.slots.ids]
    stacks = [a.get() for a in accesses if a is not None]
    return sum(s.count for s in stacks if not s.is_empty and test(s))


# ---------------------------------------------------------------------- loot
def loot_context(env, ctx, **parts) -> LootContext:
    """The LootParams of the ``loot`` and ``item modify`` commands: the context's position and
    entity, the seeded loot random source."""
    state = env.state
    parts.setdefault("this", executor(state, ctx))
    parts.setdefault("origin", ctx.pos)
    return LootContext(state, dimension=ctx.dimension, random=state.resources.random,
                       resolve_text=lambda component, entity: _resolved(env, component, entity), **parts)


def _resolved(env, component, entity: Entity):
    """ComponentUtils.updateForEntity as ``entity`` (selectors from its position, ``@s`` itself)."""
    entity_ctx = entities.entity_context(env.state, entity)
    select = text_components.finder(entities.parse_target, lambda t: entities.select(env.state, t, entity_ctx))
    return json.loads(text_components.resolved_text(json.dumps(component), env.state, select, entity))


def _table(env, ref: ast.ResourceOrInline) -> dict:
    if ref.inline is not None:
        return ref.inline
    table = env.state.resources.loot_table(ref.id)
    if table is None:
        raise CommandFailure("dpemu.loot.unknown_table", ref.id, report=True)
    return table


def _own_table(env, table_id: str) -> dict:
    """An entity's or block's own loot table (LootCommand.dropKillLoot / dropBlockLoot): one that
    does not exist drops nothing (LootTable.EMPTY)."""
    return env.state.resources.loot_table(table_id) or {}


def _tool(env, tool, ctx) -> ItemStack | None:
    if tool is None:
        return ItemStack("minecraft:air", 0)
    if isinstance(tool, ast.ItemArgument):
        return create(tool, 1)
    holder = executor(env.state, ctx)
    if holder is None:
        raise CommandFailure("permissions.requires.entity")
    access = inventories.entity_slot(holder, inventories.MAINHAND if tool == "mainhand" else inventories.OFFHAND,
                                     _version(env))
    if access is None:
        raise CommandFailure("commands.drop.no_held_items")
    return access.get()


def _loot_items(env, cmd: ast.Loot, ctx) -> list[ItemStack]:
    source = world_source(env.state, ctx)
    if cmd.source == "loot":
        return loot.roll_table(_table(env, cmd.table), loot_context(env, ctx))
    if cmd.source == "fish":  # LootCommand.dropFishingLoot: the origin is the block's centre
        origin = _centre(loaded_block_pos(env.state, ctx, cmd.pos, source))
        lctx = loot_context(env, ctx, tool=_tool(env, cmd.tool, ctx), origin=origin)
        return loot.roll_table(_table(env, cmd.table), lctx)
    if cmd.source == "kill":
        victim = entities.single(env.state, cmd.entity, ctx)
        if not is_living(victim.type):  # only living entities have a loot table
            raise CommandFailure("commands.drop.no_loot_table", victim.display_name)
        table_id = victim.data.get("DeathLootTable") or "minecraft:entities/" + victim.type.split(":", 1)[-1]
        lctx = loot_context(env, ctx, this=victim, damage_source=DamageSource("minecraft:magic")).killed_by(executor(env.state, ctx))
        return loot.roll_table(_own_table(env, str(table_id)), lctx)
    pos = loaded_block_pos(env.state, ctx, cmd.pos, source)
    blocks = env.state.blocks_in(ctx.dimension)
    block = blocks.get(pos)
    table_id = "minecraft:blocks/" + block.id.split(":", 1)[-1]
    if block.is_air:
        return []
    return loot.roll_table(_own_table(env, table_id),  # LootCommand.dropBlockLoot
                           loot_context(env, ctx, tool=_tool(env, cmd.tool, ctx), block_entity=blocks.entity(pos),
                                        block_state=block, origin=_centre(pos)))


def _centre(pos) -> tuple[float, float, float]:
    return pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5


def loot_command(env, cmd: ast.Loot, ctx) -> int:
    """LootCommand: the items of the source handed to the target; the result counts what went in."""
    items = _loot_items(env, cmd, ctx)
    source = world_source(env.state, ctx)
    if cmd.action == "spawn":
        pos = source.position_of(cmd.destination)
        for stack in items:
            _drop(env, pos, stack, ctx.dimension)
        return len(items)
    if cmd.action == "give":
        players = _players(env, cmd.destination, ctx)
        given = 0
        for stack in items:
            for player in players:
                given += inventories.player_inventory(player, _version(env)).add(stack.copy())
        return given
    if cmd.action == "insert":
        holder = _container(env, cmd.destination, ctx, source=False)
        return sum(_distribute(holder, stack.copy()) for stack in items)
    return _replace(env, cmd, items, ctx)


def _distribute(holder: inventories.Container, stack: ItemStack) -> bool:
    """LootCommand.distributeToContainer: into the first empty slot, or onto matching stacks."""
    changed = False
    for index in range(holder.size):
        if stack.is_empty:
            break
        access = holder.slot(index)
        there = access.get()
        if there.is_empty:
            access.set(stack)
            return True
        if there.same_item_same_components(stack) and there.count < there.max_stack_size:
            moved = min(stack.count, stack.max_stack_size - there.count)
            stack.count -= moved
            there.count += moved
            access.set(there)
            changed = True
    return changed


def _replace(env, cmd: ast.Loot, items: list[ItemStack], ctx) -> int:
    """LootCommand.blockReplace / entityReplace: slot, slot+1 ... each gets the next item (or empty)."""
    first = cmd.slot.ids[0]
    span = len(items) if cmd.count is None else cmd.count
    fill = [items[j] if j < len(items) else ItemStack("minecraft:air", 0) for j in range(span)]
    if cmd.destination.kind == "block":
        holder = _container(env, cmd.destination.target, ctx, source=False)
        if holder.slot(first) is None:
            raise CommandFailure("commands.item.target.no_such_slot", first)
        placed = 0
        for j, stack in enumerate(fill):
            access = holder.slot(first + j)
            placed += access is not None and access.set(stack.copy())
        return placed
    placed = 0
    for entity in entities.found(env.state, cmd.destination.target, ctx):
        for j, stack in enumerate(fill):
            access = inventories.entity_slot(entity, first + j, _version(env))
            placed += access is not None and access.set(stack.copy())
        broadcast_changes(env, [entity])  # LootCommand.entityReplace (loot give waits for the tick)
    return placed


# ---------------------------------------------------------------------- enchant
def enchant_command(env, cmd: ast.GenericCommand, ctx) -> int:
    """``enchant TARGETS ENCHANTMENT [LEVEL]`` (EnchantCommand.enchant): the held item of each
    living target that can take the enchantment beside the ones it has; alone, a target that
    cannot is an error; the count enchanted, none an error."""
    words, target = entities.arguments(cmd)
    who = entities.target_word(cmd, words, 0, target)
    if len(words) < 2:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected an enchantment", report=True)
    enchantment_id = words[1] if ":" in words[1] else "minecraft:" + words[1]
    try:
        level = int(words[2]) if len(words) > 2 else 1
    except ValueError:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, f"expected a level, got '{words[2]}'",
                             report=True) from None
    resources, version = env.state.resources, _version(env)
    found = enchanting.definition(resources, enchantment_id)
    if level > found["max_level"]:
        raise CommandFailure("commands.enchant.failed.level", level, found["max_level"])
    targets = entities.found(env.state, who, ctx)
    alone = len(targets) == 1
    changed = 0
    for entity in targets:
        if not is_living(entity.type):
            if alone:
                raise CommandFailure("commands.enchant.failed.entity", entity.display_name)
            continue
        access = inventories.entity_slot(entity, inventories.MAINHAND, version)
        stack = access.get() if access is not None else None
        if stack is None or stack.is_empty:
            if alone:
                raise CommandFailure("commands.enchant.failed.itemless", entity.display_name)
            continue
        if enchanting.can_enchant(resources, found, stack) and \
                enchanting.compatible(resources, enchanting.current(stack), enchantment_id, found):
            enchanting.enchant(stack, enchantment_id, level, version)
            access.set(stack)
            changed += 1
        elif alone:
            raise CommandFailure("commands.enchant.failed.incompatible", hover_name(stack, env.state.version))
    if not changed:
        raise CommandFailure("commands.enchant.failed")
    if found.get("effects"):
        env.unmodelled(cmd, f"the effects of enchantment {enchantment_id} are not modelled")
    return changed


HANDLERS = {ast.Give: give, ast.Clear: clear, ast.ItemReplace: item_replace, ast.ItemModify: item_modify,
            ast.Loot: loot_command}
GENERIC_HANDLERS = {"enchant": enchant_command}
