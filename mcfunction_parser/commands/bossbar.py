"""``bossbar`` (BossBarCommands, 1.21): add, remove, list, set and get."""
from __future__ import annotations

from .. import ast
from ..arguments import text_component
from ..primitives import resource_location
from ..reader import Reader
from ..selectors import target

COLORS = ("pink", "blue", "red", "green", "yellow", "purple", "white")
STYLES = ("progress", "notched_6", "notched_10", "notched_12", "notched_20")
_SET_FIELDS = ("name", "color", "style", "value", "max", "visible", "players")
_GET_FIELDS = ("value", "max", "visible", "players")


def bossbar(r: Reader, loc) -> ast.Command:
    action = r.keyword(("add", "remove", "list", "set", "get"), "bossbar action")
    if action == "list":
        r.finish()
        return ast.Bossbar.new(loc, action, None)
    r.space("bossbar id")
    bar = resource_location(r, "bossbar id")
    if action == "add":
        r.space("bossbar name (a text component)")
        node = ast.Bossbar.new(loc, action, bar, text=text_component(r))
    elif action == "remove":
        node = ast.Bossbar.new(loc, action, bar)
    elif action == "get":
        node = ast.Bossbar.new(loc, action, bar, r.keyword(_GET_FIELDS, "bossbar property"))
    else:
        node = _set(r, loc, bar)
    r.finish()
    return node


def _set(r: Reader, loc, bar: str) -> ast.Bossbar:
    field = r.keyword(_SET_FIELDS, "bossbar property")
    if field == "players":  # no targets: nobody sees it
        who = target(r, players=True) if r.optional_space() else None
        return ast.Bossbar.new(loc, "set", bar, field, targets=who)
    r.space(f"bossbar {field}")
    if field == "name":
        return ast.Bossbar.new(loc, "set", bar, field, text=text_component(r))
    if field in ("color", "style"):
        return ast.Bossbar.new(loc, "set", bar, field, text=r.literal(COLORS if field == "color" else STYLES, field))
    if field == "visible":
        return ast.Bossbar.new(loc, "set", bar, field, flag=r.boolean())
    low = 0 if field == "value" else 1  # IntegerArgumentType.integer(0) / integer(1)
    return ast.Bossbar.new(loc, "set", bar, field, number=r.integer(lo=low, what=f"bossbar {field}"))


PARSERS = {"bossbar": bossbar}
