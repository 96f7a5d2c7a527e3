"""``give``, ``clear``, ``item replace|modify`` and ``loot``.

Sources (decompiled 1.21): server/commands/GiveCommand.java, ClearInventoryCommands.java,
ItemCommands.java, LootCommand.java, commands/arguments/ResourceOrIdArgument.java.
"""
from __future__ import annotations

from .. import ast
from ..arguments import vec3
from ..items import COMPONENTS_VERSION, item_argument, item_predicate, slot
from ..primitives import resource_location
from ..reader import Reader
from ..selectors import target
from ..snbt import value

INT_MAX = 2**31 - 1


def resource_or_inline(r: Reader, what: str) -> ast.ResourceOrInline:
    """ResourceOrIdArgument: an id, or from 1.20.5 an inline SNBT definition."""
    start = r.pos
    if r.peek() in ("{", "[") and r.version >= COMPONENTS_VERSION:
        return ast.ResourceOrInline.new(None, value(r), r.text[start:r.pos])
    name = resource_location(r, what)
    return ast.ResourceOrInline.new(name, None, r.text[start:r.pos])


def item_target(r: Reader, what: str, single: bool = False) -> ast.ItemTarget:
    kind = r.literal(("entity", "block"), f"{what} (entity|block)")
    r.space("entity" if kind == "entity" else "position")
    if kind == "entity":
        return ast.ItemTarget.new(kind, target(r, single=single))
    return ast.ItemTarget.new(kind, vec3(r, block=True))


def give(r: Reader, loc) -> ast.Command:
    r.space("players")
    who = target(r, players=True)
    r.space("item")
    item = item_argument(r)
    count = r.integer(1, INT_MAX, "count") if r.optional_space() else 1
    r.finish()
    return ast.Give.new(loc, who, item, count)


def clear(r: Reader, loc) -> ast.Command:
    who = item = max_count = None
    if r.optional_space():
        who = target(r, players=True)
        if r.optional_space():
            item = item_predicate(r)
            if r.optional_space():
                max_count = r.integer(0, INT_MAX, "maximum count")
    r.finish()
    return ast.Clear.new(loc, who, item, max_count)


def item(r: Reader, loc) -> ast.Command:
    r.space("item action")
    action = r.literal(("replace", "modify"), "item action")
    r.space("target")
    where = item_target(r, "target")
    r.space("slot")
    target_slot = slot(r)
    if action == "modify":
        r.space("item modifier")
        modifier = resource_or_inline(r, "item modifier")
        r.finish()
        return ast.ItemModify.new(loc, where, target_slot, modifier)
    r.space("with|from")
    how = r.literal(("with", "from"), "with|from")
    r.space("item" if how == "with" else "source")
    if how == "with":
        created = item_argument(r)
        count = r.integer(1, 99 if r.version >= COMPONENTS_VERSION else 64, "count") if r.optional_space() else None
        r.finish()
        return ast.ItemReplace.new(loc, where, target_slot, item=created, count=count)
    source = item_target(r, "source", single=True)
    r.space("source slot")
    source_slot = slot(r)
    modifier = resource_or_inline(r, "item modifier") if r.optional_space() else None
    r.finish()
    return ast.ItemReplace.new(loc, where, target_slot, source=source, source_slot=source_slot, modifier=modifier)


def loot(r: Reader, loc) -> ast.Command:
    r.space("loot target")
    action = r.literal(("give", "insert", "spawn", "replace"), "loot target")
    r.space("destination")
    loot_slot = count = None
    if action == "give":
        destination = target(r, players=True)
    elif action == "insert":
        destination = vec3(r, block=True)
    elif action == "spawn":
        destination = vec3(r)
    else:
        destination = item_target(r, "destination")
        r.space("slot")
        loot_slot = slot(r)
        r.space("loot source")
        if r.peek().isdigit():
            count = r.integer(0, INT_MAX, "count")
            r.space("loot source")
        return _loot_source(r, loc, action, destination, loot_slot, count)
    r.space("loot source")
    return _loot_source(r, loc, action, destination, loot_slot, count)


def _loot_source(r: Reader, loc, action, destination, loot_slot, count) -> ast.Loot:
    source = r.literal(("fish", "loot", "kill", "mine"), "loot source")
    r.space("argument")
    table = pos = tool = entity = None
    if source in ("fish", "loot"):
        table = resource_or_inline(r, "loot table")
    if source == "fish":
        r.space("position")
    if source in ("fish", "mine"):
        pos = vec3(r, block=True)
        if r.optional_space():
            tool = r.word() if r.rest_word() in ("mainhand", "offhand") else item_argument(r)
    if source == "kill":
        entity = target(r, single=True)
    r.finish()
    return ast.Loot.new(loc, action, destination, source, loot_slot, count, table, pos, tool, entity)


PARSERS = {"give": give, "clear": clear, "item": item, "loot": loot}
