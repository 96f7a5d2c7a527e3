"""Loot tables and item modifiers, run as the game runs them, with a seedable random source.

- ``LootContext`` (:mod:`emulator.world.loot_context`): the world and the roll's parameters.
- ``roll_table(table, ctx)``: LootTable.getRandomItems: each pool's items, the table's functions
  applied, stacks over their maximum split (count 0 dropped).
- ``apply_modifier(modifier, stack, ctx)``: an item modifier (one function or a list: a sequence).
Conditions (of pools, entries and functions, and ``filtered``'s item filter) are the predicates
of :mod:`emulator.world.predicates`.

Entries: item, tag (``expand`` both ways), loot_table (id or inline), alternatives, group,
sequence, empty, dynamic (the mined block's ``contents``). Functions modelled: set_count,
set_damage, limit_count, set_components, set_custom_data, set_name, set_lore, copy_name,
copy_custom_data, copy_components (block_entity), set_contents, set_enchantments,
enchant_randomly, enchanted_count_increase/looting_enchant, apply_bonus, explosion_decay,
set_item, set_potion, set_loot_table, set_nbt/copy_nbt (before 1.20.5), filtered, sequence,
reference, fill_player_head, set_ominous_bottle_amplifier, set_custom_model_data (its int form,
before 1.21.4), set_stew_effect, copy_state, modify_contents, and the whole-component writers of
:mod:`emulator.world.loot_components` (set_book_cover, set_written_book_pages,
set_writable_book_pages, set_fireworks, set_firework_explosion, set_banner_pattern,
set_attributes, toggle_tooltips, furnace_smelt, discard). Anything else (an entry, function, condition or
number provider type) raises :class:`~emulator.world.errors.Unmodelled` naming it: the command
fails with a diagnostic, never an empty drop in silence. A table, modifier or predicate reached
again through itself is skipped with a warning (LootContext.pushVisitedElement: the game logs
"Detected infinite loop in loot tables").

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): world/level/storage/loot/LootTable.java,
LootPool.java (addRandomItem: weights), entries/*.java, functions/*.java (SetItemCountFunction,
SetItemDamageFunction, LimitCount, SetCustomDataFunction, SetLoreFunction, SetContainerContents,
EnchantRandomlyFunction, ApplyBonusCount, FilteredFunction, FunctionReference ...),
providers/number/*.java.
"""
from __future__ import annotations

import math
from typing import Any, Callable

from mcfunction_parser.nbt import Compound, Int, IntArray, List, String
from emulator.world import nbt_ops
from emulator.world.entities import entity_nbt
from emulator.world.errors import CommandFailure
from emulator.world.inventories import MAINHAND, entity_slot
from emulator.world.items import (
    ItemStack, enchantment_level, enchantment_levels, from_nbt, remove_component, set_component, to_nbt,
)
from emulator.world.loot_context import (
    LootContext, component_tag, integer, int_range, namespaced as _id, not_modelled, number, path_of as _path,
    snbt_or_tag, stored_text, to_tag,
)
from emulator.world.loot_components import FUNCTIONS as COMPONENT_FUNCTIONS, list_operation
from emulator.world.predicates import item_matches, test as all_hold
from emulator.world.nbt_ops import copy_tag, merge_compounds

# Vanilla enchantments' maximum levels (Enchantments.java, 1.21): enchant_randomly's level range.
MAX_LEVELS = {f"minecraft:{k}": v for k, v in {
    "protection": 4, "fire_protection": 4, "feather_falling": 4, "blast_protection": 4, "projectile_protection": 4,
    "respiration": 3, "aqua_affinity": 1, "thorns": 3, "depth_strider": 3, "frost_walker": 2, "binding_curse": 1,
    "soul_speed": 3, "swift_sneak": 3, "sharpness": 5, "smite": 5, "bane_of_arthropods": 5, "knockback": 2,
    "fire_aspect": 2, "looting": 3, "sweeping_edge": 3, "efficiency": 5, "silk_touch": 1, "unbreaking": 3,
    "fortune": 3, "power": 5, "punch": 2, "flame": 1, "infinity": 1, "luck_of_the_sea": 3, "lure": 3,
    "loyalty": 3, "impaling": 5, "riptide": 3, "channeling": 1, "multishot": 1, "quick_charge": 3, "piercing": 4,
    "density": 5, "breach": 4, "wind_burst": 3, "mending": 1, "vanishing_curse": 1}.items()}



MAX_LORE_LINES = 256  # ItemLore.MAX_LINES


# ---------------------------------------------------------------------- tables
def roll_table(table: dict, ctx: LootContext) -> list[ItemStack]:
    """LootTable.getRandomItems: stacks split to their maximum size; empty ones dropped."""
    out: list[ItemStack] = []
    for stack in roll_raw(table, ctx):
        while stack.count > 0:
            part = stack.copy()
            part.count = min(stack.count, stack.max_stack_size)
            stack.count -= part.count
            out.append(part)
    return out


def roll_raw(table: dict, ctx: LootContext) -> list[ItemStack]:
    raw: list[ItemStack] = []
    for pool in table.get("pools", []):
        raw.extend(_roll_pool(pool, ctx))
    functions = table.get("functions", [])
    return [s for s in (_apply_all(functions, stack, ctx) for stack in raw) if not s.is_empty]


def _roll_pool(pool: dict, ctx: LootContext) -> list[ItemStack]:
    if not all_hold(pool.get("conditions", []), ctx):
        return []
    rolls = integer(pool.get("rolls", 1), ctx) + math.floor(number(pool.get("bonus_rolls", 0.0), ctx) * 0.0)
    out: list[ItemStack] = []
    for _ in range(rolls):
        out.extend(_roll_once(pool.get("entries", []), ctx))
    functions = pool.get("functions", [])
    return [_apply_all(functions, stack, ctx) for stack in out]


def _roll_once(entries: list, ctx: LootContext) -> list[ItemStack]:
    """LootPool.addRandomItem: expand the entries, pick one by weight (luck 0)."""
    choices: list[tuple[dict, Any]] = []
    for entry in entries:
        _expand(entry, ctx, choices)
    weighted = [(e, item) for e, item in choices if _weight(e) > 0]
    if not weighted:
        return []
    if len(weighted) == 1:
        return _create(*weighted[0], ctx)
    pick = ctx.random.randrange(sum(_weight(e) for e, _ in weighted))
    for entry, item in weighted:
        pick -= _weight(entry)
        if pick < 0:
            return _create(entry, item, ctx)
    return []


def _weight(entry: dict) -> int:
    return max(math.floor(entry.get("weight", 1) + entry.get("quality", 0) * 0.0), 0)


def _expand(entry: dict, ctx: LootContext, out: list) -> bool:
    """LootPoolEntryContainer.expand: add the singleton entries this one stands for; False when
    its conditions fail (what alternatives and sequence read)."""
    kind = _id(entry.get("type", ""))
    if not all_hold(entry.get("conditions", []), ctx):
        return False
    if kind == "minecraft:alternatives":
        return any(_expand(child, ctx, out) for child in entry.get("children", []))
    if kind == "minecraft:group":
        for child in entry.get("children", []):
            _expand(child, ctx, out)
        return True
    if kind == "minecraft:sequence":
        return all(_expand(child, ctx, out) for child in entry.get("children", []))
    if kind == "minecraft:tag" and entry.get("expand", False):
        out.extend((entry, item) for item in sorted(ctx.resources.item_tag(_id(entry["name"]))))
        return True
    if kind in ("minecraft:item", "minecraft:tag", "minecraft:loot_table", "minecraft:empty", "minecraft:dynamic"):
        out.append((entry, None))
        return True
    raise not_modelled("loot entry", kind)


def _create(entry: dict, item: str | None, ctx: LootContext) -> list[ItemStack]:
    """LootPoolSingletonContainer.createItemStack with the entry's functions."""
    kind = _id(entry.get("type", ""))
    if item is not None:
        made = [ItemStack(item, 1)]
    elif kind == "minecraft:item":
        made = [ItemStack(_id(entry["name"]), 1)]
    elif kind == "minecraft:tag":
        made = [ItemStack(i, 1) for i in sorted(ctx.resources.item_tag(_id(entry["name"])))]
    elif kind == "minecraft:loot_table":
        made = _nested_table(entry.get("value", entry.get("name")), ctx)
    elif kind == "minecraft:dynamic":
        made = _dynamic(entry, ctx)
    else:
        made = []
    functions = entry.get("functions", [])
    return [_apply_all(functions, stack, ctx) for stack in made]


def _nested_table(value, ctx: LootContext) -> list[ItemStack]:
    if isinstance(value, dict):
        return roll_raw(value, ctx)
    table_id = _id(value)
    table = ctx.resources.loot_table(table_id)
    if table is None or not ctx.visit("loot_table " + table_id):
        return []  # LootTable.EMPTY for a missing id (a warning at load in the game)
    try:
        return roll_raw(table, ctx)
    finally:
        ctx.leave("loot_table " + table_id)


def _dynamic(entry: dict, ctx: LootContext) -> list[ItemStack]:
    """DynamicLoot: a mined container's ``contents`` (ShulkerBoxBlock) or a pot's ``sherds``."""
    name = _id(entry["name"])
    if name != "minecraft:contents":
        raise not_modelled("dynamic loot", name)
    items = ctx.block_entity.get("Items") if ctx.block_entity is not None else None
    return [from_nbt(e) for e in items] if isinstance(items, List) else []


# ---------------------------------------------------------------------- functions
def apply_modifier(modifier, stack: ItemStack, ctx: LootContext) -> ItemStack:
    """An item modifier file's value: one function, or a list run as a sequence."""
    return _apply_all(modifier if isinstance(modifier, list) else [modifier], stack, ctx)


def _apply_all(functions: list, stack: ItemStack, ctx: LootContext) -> ItemStack:
    for function in functions:
        stack = apply_function(function, stack, ctx)
    return stack


def apply_function(function, stack: ItemStack, ctx: LootContext) -> ItemStack:
    """One LootItemFunction (LootItemConditionalFunction: its conditions gate it)."""
    if isinstance(function, list):
        return _apply_all(function, stack, ctx)
    kind = _id(function.get("function", ""))
    handler = FUNCTIONS.get(kind)
    if handler is None:
        raise not_modelled("item function", kind)
    if not all_hold(function.get("conditions", []), ctx):
        return stack
    return handler(function, stack, ctx)


def _set_count(f, stack, ctx):
    value = integer(f.get("count", 1), ctx)
    stack.count = stack.count + value if f.get("add", False) else value
    return stack


def _set_damage(f, stack, ctx):
    max_damage = stack.component("minecraft:max_damage")
    if max_damage is None:
        return stack  # "Couldn't set damage of loot item" (logged)
    max_damage = int(max_damage)
    current = 1.0 - int(stack.component("minecraft:damage") or 0) / max_damage if f.get("add", False) else 0.0
    remaining = 1.0 - min(max(number(f.get("damage", 1.0), ctx) + current, 0.0), 1.0)
    set_component(stack, "minecraft:damage", Int(math.floor(remaining * max_damage)))
    return stack


def _limit_count(f, stack, ctx):
    lo, hi = int_range(f.get("limit", {}), ctx)
    if lo is not None:
        stack.count = max(stack.count, int(lo))
    if hi is not None:
        stack.count = min(stack.count, int(hi))
    return stack


def _set_components(f, stack, ctx):
    for name, value in f.get("components", {}).items():
        if name.startswith("!"):
            remove_component(stack, _id(name[1:]))
        else:
            set_component(stack, _id(name), component_tag(_id(name), value))
    return stack


def _custom_data(stack) -> Compound:
    found = stack.component("minecraft:custom_data")
    return copy_tag(found) if isinstance(found, Compound) else Compound()


def _set_custom_data(f, stack, ctx):
    set_component(stack, "minecraft:custom_data", merge_compounds(_custom_data(stack), snbt_or_tag(f.get("tag", "{}"))))
    return stack


def _set_name(f, stack, ctx):
    """SetNameFunction: with ``entity``, the name is resolved as that entity (its scores, NBT and
    selectors from its position); without it, kept as written."""
    target = _id(f.get("target", "custom_name"))
    if "name" not in f:
        return stack
    name = f["name"]
    entity = ctx.entity(f["entity"]) if "entity" in f else None
    if entity is not None and ctx.resolve_text is not None:
        name = ctx.resolve_text(name, entity)
    set_component(stack, target, stored_text(name, ctx.version))
    return stack


def _set_lore(f, stack, ctx):
    """SetLoreFunction: the lines by the list operation (at most ItemLore.MAX_LINES, 256)."""
    lines = [stored_text(v, ctx.version) for v in f.get("lore", [])]
    old = list(stack.component("minecraft:lore") or [])
    set_component(stack, "minecraft:lore", List(list_operation(f, old, lines, MAX_LORE_LINES)))
    return stack


def _copy_name(f, stack, ctx):
    source = f.get("source", "this")
    entity = None if source == "block_entity" else ctx.entity(source)
    name = entity.custom_name if entity is not None and not entity.is_player else None
    if entity is not None and entity.is_player:
        name = '{"text":"%s"}' % entity.player_name
    if source == "block_entity" and ctx.block_entity is not None:
        name = ctx.block_entity.get("CustomName")
    if name is not None:
        set_component(stack, "minecraft:custom_name", String(name))
    return stack


def _source_nbt(source, ctx) -> Compound | None:
    """CopyCustomDataFunction's source: an entity (this, killer ...), the block entity or storage."""
    if isinstance(source, dict):
        if _id(source.get("type", "")) == "minecraft:storage":
            return ctx.storage(_id(source.get("source", "")))
        source = source.get("target", "this")
    if source == "block_entity":
        return ctx.block_entity
    entity = ctx.entity(source)
    if entity is None:
        return None
    return entity_nbt(entity)


def _copy_custom_data(f, stack, ctx):
    source = _source_nbt(f.get("source", "this"), ctx)
    if source is None:
        return stack
    data = _custom_data(stack)
    changed = False
    for op in f.get("ops", []):
        try:
            found = nbt_ops.get(source, _path(op["source"]))
        except CommandFailure:
            continue
        target = _path(op["target"])
        mode = op.get("op", "replace")
        try:
            if mode == "replace":
                nbt_ops.set_path(data, target, found[-1])
            elif mode == "append":
                nbt_ops.insert(data, target, -1, found)
            elif mode == "merge":
                nbt_ops.merge_into(data, target, found)
            changed = True
        except CommandFailure:
            continue
    if changed:
        set_component(stack, "minecraft:custom_data", data)
    return stack


def _copy_components(f, stack, ctx):
    if f.get("source") != "block_entity":
        raise not_modelled("copy_components source", str(f.get("source")))
    components = (ctx.block_entity or Compound()).get("components")
    for name, value in (components.items() if isinstance(components, Compound) else ()):
        include, exclude = f.get("include"), f.get("exclude", [])
        if (include is None or name in map(_id, include)) and name not in map(_id, exclude):
            set_component(stack, name, value)
    return stack


def _set_contents(f, stack, ctx):
    component = _id(f.get("component", f.get("type", "minecraft:container")))
    made: list[ItemStack] = []
    for entry in f.get("entries", []):
        choices: list = []
        _expand(entry, ctx, choices)
        for chosen, item in choices:
            made.extend(_create(chosen, item, ctx))
    if component == "minecraft:container":
        value = List(Compound(slot=Int(i), item=to_nbt(s, ctx.version)) for i, s in enumerate(made[:27]))
    elif component in ("minecraft:bundle_contents", "minecraft:charged_projectiles"):
        value = List(to_nbt(s, ctx.version) for s in made)
    else:
        raise not_modelled("set_contents component", component)
    set_component(stack, component, value)
    return stack


def _modify_contents(f, stack, ctx):
    """ModifyContainerContents (1.21.2+): the ``modifier`` applied to each item of the container,
    bundle or charged projectiles (ContainerComponentManipulator.modifyItems: empty slots skipped,
    a container's items kept at their slots, an item the modifier empties gone)."""
    component = _id(f.get("component", ""))
    contents = stack.component(component)
    if stack.is_empty or not isinstance(contents, list):
        return stack
    modifier = f.get("modifier", [])
    if component == "minecraft:container":
        slots = [(int(e.get("slot", 0)), apply_modifier(modifier, from_nbt(e.get("item", Compound())), ctx))
                 for e in contents if isinstance(e, dict)]
        value = List(Compound(slot=Int(i), item=to_nbt(s, ctx.version)) for i, s in slots if not s.is_empty)
    elif component in ("minecraft:bundle_contents", "minecraft:charged_projectiles"):
        made = [apply_modifier(modifier, from_nbt(e), ctx) for e in contents if isinstance(e, dict)]
        value = List(to_nbt(s, ctx.version) for s in made if not s.is_empty)
    else:
        raise not_modelled("modify_contents component", component)
    set_component(stack, component, value)
    return stack


def _put_enchantments(stack, levels: Compound, version) -> None:
    key = "minecraft:stored_enchantments" if stack.id == "minecraft:book" or stack.id == "minecraft:enchanted_book" \
        else "minecraft:enchantments"
    if stack.id == "minecraft:book":
        stack.id = "minecraft:enchanted_book"
    set_component(stack, key, levels if tuple(version) >= (1, 21, 5) else Compound(levels=levels))


def _set_enchantments(f, stack, ctx):
    levels = enchantment_levels(stack) if f.get("add", False) else Compound()
    for name, provider in f.get("enchantments", {}).items():
        name = _id(name)
        level = integer(provider, ctx) + (int(levels.get(name, 0)) if f.get("add", False) else 0)
        if level > 0:
            levels[name] = Int(min(level, 255))
        else:
            levels.pop(name, None)
    _put_enchantments(stack, levels, ctx.version)
    return stack


def _enchant_randomly(f, stack, ctx):
    options = f.get("options", f.get("enchantments"))
    if isinstance(options, str):
        options = [options]
    if not isinstance(options, list) or not options or any(o.startswith("#") for o in options):
        raise not_modelled("enchant_randomly over", "all enchantments or an enchantment tag")
    name = _id(ctx.random.choice(options))
    if name not in MAX_LEVELS:
        raise not_modelled("enchantment", name)
    levels = enchantment_levels(stack)
    levels[name] = Int(1 + ctx.random.randrange(MAX_LEVELS[name]))
    _put_enchantments(stack, levels, ctx.version)
    return stack


def _enchanted_count_increase(f, stack, ctx):
    """EnchantedCountIncreaseFunction / LootingEnchantFunction: count + level x number, limited."""
    weapon = None
    if ctx.attacker is not None:
        access = entity_slot(ctx.attacker, MAINHAND, ctx.version)
        weapon = access.get() if access is not None else None
    level = enchantment_level(weapon, f.get("enchantment", "minecraft:looting"))
    if level == 0:
        return stack
    stack.count += round(level * number(f.get("count", 1), ctx))
    limit = f.get("limit", 0)
    if limit > 0:
        stack.count = min(stack.count, limit)
    return stack


def _apply_bonus(f, stack, ctx):
    level = enchantment_level(ctx.tool, f.get("enchantment", ""))
    formula = _id(f.get("formula", ""))
    params = f.get("parameters", {})
    count = stack.count
    if formula == "minecraft:binomial_with_bonus_count":
        count += sum(ctx.random.random() < params.get("probability", 0) for _ in range(level + params.get("extra", 0)))
    elif formula == "minecraft:uniform_bonus_count":
        count += ctx.random.randrange(params.get("bonusMultiplier", 1) * level + 1) if level > 0 else 0
    elif formula == "minecraft:ore_drops":
        if level > 0:
            count *= max(ctx.random.randrange(level + 2) - 1, 0) + 1
    else:
        raise not_modelled("apply_bonus formula", formula)
    stack.count = count
    return stack


def _explosion_decay(f, stack, ctx):
    if ctx.explosion_radius is None:
        return stack
    keep = 1.0 / ctx.explosion_radius
    stack.count = sum(ctx.random.random() <= keep for _ in range(stack.count))
    return stack


def _set_item(f, stack, ctx):
    stack.id = _id(f["item"])
    return stack


def _set_potion(f, stack, ctx):
    set_component(stack, "minecraft:potion_contents", Compound(potion=String(_id(f["id"]))))
    return stack


def _set_loot_table(f, stack, ctx):
    value = Compound(loot_table=String(_id(f["name"])))
    if f.get("seed", 0):
        value["seed"] = to_tag(f["seed"])
    set_component(stack, "minecraft:container_loot", value)
    return stack


def _set_nbt(f, stack, ctx):
    stack.tag = merge_compounds(stack.tag or Compound(), snbt_or_tag(f.get("tag", "{}")))
    return stack


def _fill_player_head(f, stack, ctx):
    """FillPlayerHeadFunction: a player head gets the player's profile."""
    entity = ctx.entity(f.get("entity", "this"))
    if stack.id == "minecraft:player_head" and entity is not None and entity.is_player:
        set_component(stack, "minecraft:profile", Compound(name=String(entity.player_name),
                                                            id=IntArray(Int(v) for v in entity.uuid)))
    return stack


def _set_ominous_bottle_amplifier(f, stack, ctx):
    set_component(stack, "minecraft:ominous_bottle_amplifier", Int(min(max(integer(f["amplifier"], ctx), 0), 4)))
    return stack


def _set_custom_model_data(f, stack, ctx):
    if "value" not in f:  # 1.21.4: floats/flags/strings/colors list operations
        raise not_modelled("set_custom_model_data form", "floats/flags/strings/colors")
    set_component(stack, "minecraft:custom_model_data", Int(integer(f["value"], ctx)))
    return stack


_INSTANT_EFFECTS = {"minecraft:instant_health", "minecraft:instant_damage", "minecraft:saturation"}


def _set_stew_effect(f, stack, ctx):
    """SetStewEffectFunction: one of the effects at random, its duration in seconds (ticks for
    instant effects) added to the stew's effects."""
    effects = f.get("effects", [])
    if stack.id != "minecraft:suspicious_stew" or not effects:
        return stack
    chosen = effects[ctx.random.randrange(len(effects))]
    effect = _id(chosen["type"])
    duration = integer(chosen.get("duration", 160), ctx) * (1 if effect in _INSTANT_EFFECTS else 20)
    current = stack.component("minecraft:suspicious_stew_effects")
    value = List(current) if isinstance(current, list) else List()
    value.append(Compound(id=String(effect), duration=Int(duration)))
    set_component(stack, "minecraft:suspicious_stew_effects", value)
    return stack


def _copy_state(f, stack, ctx):
    """CopyBlockState: the named properties of the mined block into the block_state component."""
    if ctx.block_state is None or ctx.block_state.id != _id(f.get("block", "")):
        return stack
    found = dict(ctx.block_state.properties)
    current = stack.component("minecraft:block_state")
    state = Compound(current) if isinstance(current, Compound) else Compound()
    for name in f.get("properties", []):
        if name in found:
            state[name] = String(found[name])
    set_component(stack, "minecraft:block_state", state)
    return stack


def _filtered(f, stack, ctx):
    passed = item_matches(f.get("item_filter", {}), ctx, stack)
    branch = f.get("modifier") if passed else None
    if "on_pass" in f or "on_fail" in f:
        branch = f.get("on_pass") if passed else f.get("on_fail")
    return stack if branch is None else apply_modifier(branch, stack, ctx)


def _sequence(f, stack, ctx):
    return _apply_all(f.get("functions", []), stack, ctx)


def _reference(f, stack, ctx):
    name = _id(f.get("name", ""))
    modifier = ctx.resources.item_modifiers.get(name)
    if modifier is None or not ctx.visit("item_modifier " + name):
        return stack  # "Unknown function table called" (logged), the stack unchanged
    try:
        return apply_modifier(modifier, stack, ctx)
    finally:
        ctx.leave("item_modifier " + name)


FUNCTIONS: dict[str, Callable] = {f"minecraft:{k}": v for k, v in {
    "set_count": _set_count, "set_damage": _set_damage, "limit_count": _limit_count,
    "set_components": _set_components, "set_custom_data": _set_custom_data, "set_name": _set_name,
    "set_lore": _set_lore, "copy_name": _copy_name, "copy_custom_data": _copy_custom_data, "copy_nbt": _copy_custom_data,
    "copy_components": _copy_components, "set_contents": _set_contents, "set_enchantments": _set_enchantments,
    "enchant_randomly": _enchant_randomly, "enchanted_count_increase": _enchanted_count_increase,
    "looting_enchant": _enchanted_count_increase, "apply_bonus": _apply_bonus, "explosion_decay": _explosion_decay,
    "set_item": _set_item, "set_potion": _set_potion, "set_loot_table": _set_loot_table, "set_nbt": _set_nbt,
    "filtered": _filtered, "sequence": _sequence, "reference": _reference, "fill_player_head": _fill_player_head,
    "set_ominous_bottle_amplifier": _set_ominous_bottle_amplifier, "set_custom_model_data": _set_custom_model_data,
    "set_stew_effect": _set_stew_effect, "copy_state": _copy_state, "modify_contents": _modify_contents}.items()} \
    | COMPONENT_FUNCTIONS
