"""``scoreboard objectives ...`` and ``scoreboard players ...``."""
from __future__ import annotations

import re

from .. import ast
from ..arguments import (PLAIN_HOLDER, PLAIN_OBJECTIVE, objective, objective_too_long, plain_holder,
                         score_holder, single_score_holder, text_component)
from ..features import version_text
from ..reader import INT_MAX, INT_MIN, Reader, integer_value, show

_SIMPLE_CRITERIA = frozenset((
    "dummy", "trigger", "deathCount", "playerKillCount", "totalKillCount", "health", "xp", "level",
    "food", "air", "armor"))
_COLORS = frozenset((
    "black", "dark_blue", "dark_green", "dark_aqua", "dark_red", "dark_purple", "gold", "gray", "dark_gray",
    "blue", "green", "aqua", "red", "light_purple", "yellow", "white"))
# statistic criteria: <stat type>:<id>, each part a resource location written with '.' for ':'
_STAT_CRITERION = re.compile(r"[a-z0-9_.\-]+:[a-z0-9_.\-/]+\Z")
BELOW_NAME_RENAMED = (1, 20, 2)
OPERATIONS = frozenset(("=", "+=", "-=", "*=", "/=", "%=", "<", ">", "><"))


def criterion(r: Reader) -> str:
    start = r.pos
    word = r.word()
    if word in _SIMPLE_CRITERIA or _STAT_CRITERION.match(word):
        return word
    prefix, _, color = word.partition(".")
    if prefix in ("teamkill", "killedByTeam") and color in _COLORS:
        return word
    r.fail(f"unknown criterion {show(word)}", start)


def display_slot(r: Reader) -> str:
    start = r.pos
    word = r.word()
    if word in ("list", "sidebar"):
        return word
    if word in ("belowName", "below_name"):
        # renamed to below_name in 1.20.2 (23w31a)
        if (word == "below_name") != (r.version >= BELOW_NAME_RENAMED):
            spelled = "below_name" if word == "belowName" else "belowName"
            r.fail(f"display slot '{word}' is spelled '{spelled}' in Minecraft {version_text(r.version)}", start)
        return word
    prefix, _, color = word.partition(".team.")
    if prefix == "sidebar" and color in _COLORS:
        return word
    r.fail(f"unknown display slot {show(word)}", start)


def _obj_add(r, loc, action):
    r.space("objective name")
    name = objective(r)
    r.space("criterion")
    chosen = criterion(r)
    display = text_component(r) if r.optional_space() else None
    r.finish()
    return ast.ObjectivesAdd.new(loc, name, chosen, display)


def _obj_remove(r, loc, action):
    r.space("objective name")
    name = objective(r)
    r.finish()
    return ast.ObjectivesRemove.new(loc, name)


def _obj_modify(r, loc, action):
    r.space("objective name")
    name = objective(r)
    r.space("property to modify")
    start = r.pos
    field = r.literal(("displayname", "rendertype", "displayautoupdate", "numberformat"), "objective property")
    if field in ("displayautoupdate", "numberformat"):
        r.require("objectives modify " + field, start)
    if field == "numberformat":
        start = r.pos + 1
        _number_format(r)
        return ast.ObjectivesModify.new(loc, name, field, r.text[start:])
    r.space("value")
    if field == "displayname":
        value = text_component(r)
    elif field == "rendertype":
        value = r.literal(("hearts", "integer"), "render type")
    else:
        value = "true" if r.boolean() else "false"
    r.finish()
    return ast.ObjectivesModify.new(loc, name, field, value)


def _obj_setdisplay(r, loc, action):
    r.space("display slot")
    slot = display_slot(r)
    name = objective(r) if r.optional_space() else None
    r.finish()
    return ast.ObjectivesSetdisplay.new(loc, slot, name)


def _obj_list(r, loc, action):
    r.finish()
    return ast.ObjectivesList.new(loc)


_OBJECTIVE_ACTIONS = {
    "add": _obj_add, "remove": _obj_remove, "modify": _obj_modify, "setdisplay": _obj_setdisplay, "list": _obj_list,
}


# Fast paths for the two commands that dominate real packs, when every holder is a plain word or
# an option-less selector: one regex, then the same helpers the general path uses. Anything else
# (selectors with options, out-of-range numbers, errors) takes the general path.
_FAST_OPERATION = re.compile(rf" {PLAIN_HOLDER} {PLAIN_OBJECTIVE} ([^ ]+) {PLAIN_HOLDER} {PLAIN_OBJECTIVE}\Z")
_FAST_SET = re.compile(rf" {PLAIN_HOLDER} {PLAIN_OBJECTIVE} (-?[0-9]{{1,10}})\Z")


def _fast_operation(r: Reader, loc):
    m = _FAST_OPERATION.match(r.text, r.pos)
    if m is None or m.group(3) not in OPERATIONS:
        return None
    name, source_name = m.group(2), m.group(5)
    if objective_too_long(name, r.version) or objective_too_long(source_name, r.version):
        return None
    r.pos = r.end
    return ast.ScoreOperation.new(loc, plain_holder(r, m, 1), name, m.group(3), plain_holder(r, m, 4), source_name)


def _fast_set(r: Reader, loc, action: str):
    m = _FAST_SET.match(r.text, r.pos)
    if m is None or objective_too_long(m.group(2), r.version):
        return None
    value = integer_value(m.group(3))
    if not (INT_MIN if action == "set" else 0) <= value <= INT_MAX:
        return None
    r.pos = r.end
    return ast.ScoreSet.new(loc, action, plain_holder(r, m, 1), m.group(2), value)


def _pl_set(r, loc, action):
    fast = _fast_set(r, loc, action)
    if fast is not None:
        return fast
    r.space("score holder")
    holder = score_holder(r)
    r.space("objective")
    name = objective(r)
    r.space("score")
    value = r.integer(what="score") if action == "set" else r.integer(0, INT_MAX, what="score")
    r.finish()
    return ast.ScoreSet.new(loc, action, holder, name, value)


def _pl_reset(r, loc, action):
    r.space("score holder")
    holder = score_holder(r)
    name = objective(r) if r.optional_space() else None
    r.finish()
    return ast.ScoreReset.new(loc, holder, name)


def _pl_get(r, loc, action):
    r.space("score holder")
    holder = single_score_holder(r)
    r.space("objective")
    name = objective(r)
    r.finish()
    return ast.ScoreGet.new(loc, holder, name)


def _pl_enable(r, loc, action):
    r.space("score holder")
    holder = score_holder(r)
    r.space("objective")
    name = objective(r)
    r.finish()
    return ast.ScoreEnable.new(loc, holder, name)


def _pl_operation(r, loc, action):
    fast = _fast_operation(r, loc)
    if fast is not None:
        return fast
    r.space("score holder")
    targets = score_holder(r)
    r.space("objective")
    name = objective(r)
    op = r.keyword(OPERATIONS, "operation")
    r.space("score holder")
    sources = score_holder(r)
    r.space("objective")
    source_name = objective(r)
    r.finish()
    return ast.ScoreOperation.new(loc, targets, name, op, sources, source_name)


def _pl_list(r, loc, action):
    holder = single_score_holder(r) if r.optional_space() else None
    r.finish()
    return ast.ScoreList.new(loc, holder)


def _number_format(r: Reader) -> None:
    """``[blank | fixed <component> | styled <style>]`` to the end (ScoreboardCommand.register's
    numberformat branches; a style is read as a text component's JSON or SNBT is)."""
    if r.optional_space():
        kind = r.literal(("blank", "fixed", "styled"), "number format")
        if kind != "blank":
            r.space("text component" if kind == "fixed" else "style")
            text_component(r)
    r.finish()


def _pl_display(r, loc, action):
    """``scoreboard players display name <targets> <objective> [<text>]`` and ``... numberformat
    <targets> <objective> [<number format>]``, checked and kept as text after ``display``."""
    r.require("scoreboard players display", r.pos - len(action))
    r.space("display property")
    start = r.pos
    kind = r.literal(("name", "numberformat"), "display property")
    r.space("score holders")
    score_holder(r)
    r.space("objective")
    objective(r)
    if kind == "numberformat":
        _number_format(r)
    else:
        if r.optional_space():
            text_component(r)
        r.finish()
    return ast.ScoreDisplay.new(loc, r.text[start:])


_PLAYER_ACTIONS = {
    "set": _pl_set, "add": _pl_set, "remove": _pl_set, "reset": _pl_reset, "get": _pl_get,
    "enable": _pl_enable, "operation": _pl_operation, "list": _pl_list, "display": _pl_display,
}


_ACTIONS = {"objectives": _OBJECTIVE_ACTIONS, "players": _PLAYER_ACTIONS}
_BRANCH_ACTION = re.compile(r" (objectives|players) ([a-z]+)")


def scoreboard(r: Reader, loc) -> ast.Command:
    m = _BRANCH_ACTION.match(r.text, r.pos)
    if m is not None:
        actions = _ACTIONS[m.group(1)]
        action = m.group(2)
        if action in actions:
            r.pos = m.end()
            return actions[action](r, loc, action)
    branch = r.keyword(_ACTIONS, "scoreboard branch")
    action = r.keyword(_ACTIONS[branch], branch + " action")
    return _ACTIONS[branch][action](r, loc, action)


PARSERS = {"scoreboard": scoreboard}
