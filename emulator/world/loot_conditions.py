"""Loot conditions (predicates inside loot tables and item modifiers) and JSON item predicates.

``holds(condition, ctx)`` evaluates one condition; ``CONDITIONS`` maps a type to its evaluator
``(condition, ctx) -> bool``: the predicate engine registers the types it models here (one
registry, read by loot tables and item modifiers alike). A type with no evaluator raises a
reported ``CommandFailure`` naming it, never a silent pass or fail.

Modelled here: inverted, any_of, all_of, alternative, random_chance, random_chance_with_looting /
random_chance_with_enchanted_bonus (no enchantment level: the unenchanted chance), killed_by_player,
entity_scores, value_check, time_check, survives_explosion, match_tool, table_bonus,
block_state_property (the mined block).
``item_matches(predicate, stack, ctx)``: the JSON item predicate (``items``, ``count``,
``components``, ``predicates`` with custom_data and damage) of match_tool and filtered.

Sources (decompiled 1.21): world/level/storage/loot/predicates/*.java (InvertedLootItemCondition,
AnyOfCondition, LootItemRandomChanceCondition, LootItemKilledByPlayerCondition,
EntityHasScoreCondition, ValueCheckCondition, TimeCheck, ExplosionCondition, MatchTool,
BonusLevelTableCondition), advancements/critereon/ItemPredicate.java.
"""
from __future__ import annotations

from typing import Callable

from mcfunction_parser.nbt import Compound
from emulator.world.items import ItemStack, enchantment_level, sub_predicate, value_equal
from emulator.world.loot_context import LootContext, int_range, namespaced, not_modelled, number, snbt_or_tag, to_tag


def holds(condition, ctx: LootContext) -> bool:
    if isinstance(condition, list):  # an inline all_of
        return all(holds(c, ctx) for c in condition)
    kind = namespaced(condition.get("condition", ""))
    evaluator = CONDITIONS.get(kind)
    if evaluator is None:
        raise not_modelled("loot condition", kind)
    return evaluator(condition, ctx)


def conditions_pass(conditions, ctx: LootContext) -> bool:
    return all(holds(c, ctx) for c in conditions)


def _in_range(value: float, bounds, ctx: LootContext) -> bool:
    lo, hi = int_range(bounds, ctx) if not isinstance(bounds, (int, float)) else (bounds, bounds)
    return (lo is None or value >= lo) and (hi is None or value <= hi)


def _entity_scores(c, ctx):
    entity = ctx.entity(c.get("entity", "this"))
    if entity is None:
        return False
    for objective, bounds in c.get("scores", {}).items():
        value = ctx.scores(entity.score_holder, objective)
        if value is None or not _in_range(value, bounds, ctx):
            return False
    return True


def _time_check(c, ctx):
    time = ctx.daytime
    period = c.get("period")
    if period is not None:
        time %= int(period)
    return _in_range(time, c.get("value", {}), ctx)


def _chance_with_bonus(c, ctx):
    chance = c.get("unenchanted_chance", c.get("chance", 0.0))
    return ctx.random.random() < number(chance, ctx)


def _table_bonus(c, ctx):
    level = enchantment_level(ctx.tool, c.get("enchantment", ""))
    chances = c.get("chances", [])
    return bool(chances) and ctx.random.random() < chances[min(level, len(chances) - 1)]


def _match_tool(c, ctx):
    return ctx.tool is not None and item_matches(c.get("predicate", {}), ctx.tool, ctx)


def _block_state_property(c, ctx):
    """LootItemBlockStatePropertyCondition: the mined block is that block, with those properties
    (a value, or {min, max} compared as numbers)."""
    state = ctx.block_state
    if state is None or state.id != namespaced(c.get("block", "")):
        return False
    found = dict(state.properties)
    for name, wanted in c.get("properties", {}).items():
        value = found.get(name)
        if value is None:
            return False
        if isinstance(wanted, dict):
            if not value.lstrip("-").isdigit() or not _in_range(int(value), wanted, ctx):
                return False
        elif str(wanted).lower() != value:
            return False
    return True


CONDITIONS: dict[str, Callable[[dict, LootContext], bool]] = {f"minecraft:{k}": v for k, v in {
    "inverted": lambda c, ctx: not holds(c["term"], ctx),
    "any_of": lambda c, ctx: any(holds(t, ctx) for t in c.get("terms", [])),
    "alternative": lambda c, ctx: any(holds(t, ctx) for t in c.get("terms", [])),
    "all_of": lambda c, ctx: all(holds(t, ctx) for t in c.get("terms", [])),
    "random_chance": lambda c, ctx: ctx.random.random() < number(c.get("chance", 0.0), ctx),
    "random_chance_with_looting": _chance_with_bonus,
    "random_chance_with_enchanted_bonus": _chance_with_bonus,
    "killed_by_player": lambda c, ctx: (ctx.killer is not None and ctx.killer.is_player) != c.get("inverse", False),
    "entity_scores": _entity_scores,
    "value_check": lambda c, ctx: _in_range(float(number(c["value"], ctx)), c.get("range", {}), ctx),
    "time_check": _time_check,
    "survives_explosion": lambda c, ctx: ctx.explosion_radius is None or ctx.random.random() <= 1.0 / ctx.explosion_radius,
    "match_tool": _match_tool,
    "table_bonus": _table_bonus,
    "block_state_property": _block_state_property,
}.items()}


def item_matches(predicate: dict, stack: ItemStack, ctx: LootContext) -> bool:
    """ItemPredicate (JSON): items (id, list or #tag), count, exact components, sub-predicates."""
    items = predicate.get("items")
    if items is not None:
        if isinstance(items, str) and items.startswith("#"):
            allowed = ctx.resources.item_tag(namespaced(items[1:]))
        else:
            allowed = {namespaced(i) for i in ([items] if isinstance(items, str) else items)}
        if stack.id not in allowed:
            return False
    if "count" in predicate and not _in_range(stack.count, predicate["count"], ctx):
        return False
    for name, value in predicate.get("components", {}).items():
        found = stack.component(namespaced(name))
        if found is None or not value_equal(to_tag(value), found):
            return False
    for name, value in predicate.get("predicates", {}).items():
        name = namespaced(name)
        if name == "minecraft:custom_data" and isinstance(value, str):
            value = snbt_or_tag(value)
        if not sub_predicate(name, to_tag(value) if not isinstance(value, Compound) else value, stack):
            return False
    if "nbt" in predicate or "enchantments" in predicate:
        raise not_modelled("item predicate field", "nbt" if "nbt" in predicate else "enchantments")
    return True
