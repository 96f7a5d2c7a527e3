"""``execute``: every subcommand, conditions, ``store`` and ``run``.

The chain may end without ``run`` only after a condition (the game's command tree makes
``if``/``unless`` leaves executable, and nothing else).
"""
from __future__ import annotations

import re

from .. import ast
from ..arguments import (PLAIN_HOLDER, PLAIN_OBJECTIVE, objective, objective_too_long, plain_holder, score_holder,
                         single_score_holder, vec2, vec3)
from ..game_objects import block, registry_id
from ..nbt_path import nbt_path
from ..primitives import float_range, int_range, json_span, resource_location, resource_or_tag
from ..reader import Reader, show
from ..selectors import target
from ..items import item_predicate, slot
from .data_targets import data_target
from .items import item_target
from ..relocate import READ, READ_MAX, NotRelocatable, relocate
from .dispatch import rest_command

_ANCHORS = ("eyes", "feet")
_HEIGHTMAPS = ("world_surface", "motion_blocking", "motion_blocking_no_leaves", "ocean_floor")
_RELATIONS = ("attacker", "controller", "leasher", "origin", "owner", "passengers", "target", "vehicle")
_COMPARISONS = ("<", "<=", "=", ">=", ">")
_SCORE_TESTS = frozenset(_COMPARISONS + ("matches",))
STORE_TYPES = ("byte", "short", "int", "long", "float", "double")
_AXES = re.compile(r"[xyz]{1,3}")


def _as(r, loc):
    return ast.ExAs.new(loc, target(r))


def _at(r, loc):
    return ast.ExAt.new(loc, target(r))


def _positioned(r, loc):
    word = r.rest_word()
    if word == "as":
        r.pos += 2
        r.space("entity")
        return ast.ExPositionedAs.new(loc, target(r))
    if word == "over":
        r.require("execute positioned over", r.pos)
        r.pos += 4
        return ast.ExPositionedOver.new(loc, r.keyword(_HEIGHTMAPS, "heightmap"))
    return ast.ExPositioned.new(loc, vec3(r))


def _rotated(r, loc):
    if r.rest_word() == "as":
        r.pos += 2
        r.space("entity")
        return ast.ExRotatedAs.new(loc, target(r))
    return ast.ExRotated.new(loc, vec2(r))


def _facing(r, loc):
    if r.rest_word() == "entity":
        r.pos += 6
        r.space("entity")
        who = target(r)
        return ast.ExFacingEntity.new(loc, who, r.keyword(_ANCHORS, "anchor"))
    return ast.ExFacing.new(loc, vec3(r))


def _anchored(r, loc):
    return ast.ExAnchored.new(loc, r.literal(_ANCHORS, "anchor"))


def _align(r, loc):
    start = r.pos
    word = r.word()
    if not _AXES.fullmatch(word) or len(set(word)) != len(word):
        r.fail(f"expected a swizzle of x, y and z without repeats, got {show(word)}", start)
    return ast.ExAlign.new(loc, word)


def _in(r, loc):
    return ast.ExIn.new(loc, resource_location(r, "dimension"))


def _on(r, loc):
    r.require("execute on", r.pos - 3)
    return ast.ExOn.new(loc, r.literal(_RELATIONS, "relation"))


def _summon(r, loc):
    r.require("execute summon", r.pos - 7)
    return ast.ExSummon.new(loc, registry_id(r, "entity_type"))


# ----------------------------------------------------------------------------- conditions


def _score_test_follows(op: str) -> str:
    return "range" if op == "matches" else "score holder"


def _if_score(r, loc, negated):
    holder = single_score_holder(r)
    r.space("objective")
    obj = objective(r)
    op = r.keyword_then_space(_SCORE_TESTS, "comparison", _score_test_follows)
    if op == "matches":
        return ast.IfScoreMatches.new(loc, negated, holder, obj, int_range(r))
    source = single_score_holder(r)
    r.space("objective")
    return ast.IfScore.new(loc, negated, holder, obj, op, source, objective(r))


def _if_entity(r, loc, negated):
    return ast.IfEntity.new(loc, negated, target(r))


def _if_data(r, loc, negated):
    source = data_target(r)
    r.space("NBT path")
    return ast.IfData.new(loc, negated, source, nbt_path(r))


def _if_block(r, loc, negated):
    pos = vec3(r, block=True)
    r.space("block")
    return ast.IfBlock.new(loc, negated, pos, block(r, tags=True))


def _if_blocks(r, loc, negated):
    start = vec3(r, block=True)
    r.space("end position")
    end = vec3(r, block=True)
    r.space("destination")
    dest = vec3(r, block=True)
    return ast.IfBlocks.new(loc, negated, start, end, dest, r.keyword(("all", "masked"), "mode"))


def _if_function(r, loc, negated):
    name, is_tag = resource_or_tag(r, "function")
    return ast.IfFunction.new(loc, negated, name, is_tag)


def _if_predicate(r, loc, negated):
    if r.peek() in "{[":  # inline predicate (1.20.5+)
        return ast.IfPredicate.new(loc, negated, json_span(r, "predicate"))
    return ast.IfPredicate.new(loc, negated, resource_location(r, "predicate"))


def _if_biome(r, loc, negated):
    pos = vec3(r, block=True)
    r.space("biome")
    name, is_tag = resource_or_tag(r, "biome")
    return ast.IfBiome.new(loc, negated, pos, ("#" if is_tag else "") + name)


def _if_loaded(r, loc, negated):
    return ast.IfLoaded.new(loc, negated, vec3(r, block=True))


def _if_dimension(r, loc, negated):
    return ast.IfDimension.new(loc, negated, resource_location(r, "dimension"))


def _if_items(r, loc, negated):
    """``items entity|block SOURCE SLOTS ITEM_PREDICATE`` (SlotsArgument: ranges allowed)."""
    source = item_target(r, "items source")
    r.space("slots")
    slots = slot(r, ranges=True)
    r.space("item predicate")
    return ast.IfItems.new(loc, negated, source, slots, item_predicate(r))


def _if_stopwatch(r, loc, negated):
    name = resource_location(r, "stopwatch")
    r.space("range")
    return ast.IfStopwatch.new(loc, negated, name, float_range(r))


_CONDITIONS = {
    "score": (_if_score, None), "entity": (_if_entity, None), "data": (_if_data, None),
    "block": (_if_block, None), "blocks": (_if_blocks, None), "predicate": (_if_predicate, None),
    "function": (_if_function, "execute if function"), "biome": (_if_biome, "execute if biome"),
    "loaded": (_if_loaded, "execute if loaded"), "dimension": (_if_dimension, "execute if dimension"),
    "items": (_if_items, "execute if items"), "stopwatch": (_if_stopwatch, "execute if stopwatch"),
}


def condition(r, loc, negated):
    """An ``execute if|unless`` test (the text after the keyword)."""
    start = r.pos
    kind = r.word_then_space(_CONDITIONS, "condition", _what_follows)
    parser, feature = _CONDITIONS[kind]
    if feature:
        r.require(feature, start)
    return parser(r, loc, negated)


def _if(r, loc):
    return condition(r, loc, False)


def _unless(r, loc):
    return condition(r, loc, True)


# ----------------------------------------------------------------------------- store


def _store(r, loc):
    kind = r.literal(("result", "success"), "store kind")
    r.space("store target")
    start = r.pos
    where = r.literal(("score", "entity", "storage", "block", "bossbar"), "store target")
    r.space("store target")
    if where == "score":
        holder = score_holder(r)
        r.space("objective")
        return ast.StoreScore.new(loc, kind, holder, objective(r))
    if where == "bossbar":
        bar = resource_location(r, "bossbar")
        return ast.StoreBossbar.new(loc, kind, bar, r.keyword(("value", "max"), "bossbar field"))
    r.pos = start
    dest = data_target(r)
    r.space("NBT path")
    path = nbt_path(r)
    kind_type = r.keyword(STORE_TYPES, "NBT type")
    r.space("scale")
    return ast.StoreData.new(loc, kind, dest, path, kind_type, r.double(what="scale"))


_SUBCOMMANDS = {
    "as": _as, "at": _at, "positioned": _positioned, "rotated": _rotated, "facing": _facing,
    "anchored": _anchored, "align": _align, "in": _in, "on": _on, "summon": _summon,
    "if": _if, "unless": _unless, "store": _store,
}
_ALL = tuple(_SUBCOMMANDS) + ("run",)
_CONDITION_SUBCOMMANDS = ("if", "unless")


def _what_follows(name: str) -> str:
    return "command" if name == "run" else name + " arguments"


# ``if|unless score HOLDER OBJ matches RANGE``, the commonest subcommand, read by one regex when the
# holder is plain (see scoreboard's fast paths); the range goes through int_range as usual.
_FAST_SCORE_MATCHES = re.compile(rf" (if|unless) score {PLAIN_HOLDER} {PLAIN_OBJECTIVE} matches (?=[^ ])")


def _fast_score_matches(r: Reader, m, sub_loc):
    """The subcommand for a _FAST_SCORE_MATCHES match, or None to take the general path."""
    holder_text = m.group(2)
    if holder_text in ("@a", "@e") or objective_too_long(m.group(3), r.version):
        return None
    holder = plain_holder(r, m, 2)
    r.pos = m.end()
    return ast.IfScoreMatches.new(sub_loc, m.group(1) == "unless", holder, m.group(3), int_range(r))


# Where a subcommand may end: a space, a subcommand's name (or run) and a space before more text.
# A subcommand read cleanly up to such a boundary is remembered with its text, the space before it
# included (so no command text, which starts without one, is taken for it); see _recall.
_BOUNDARY = re.compile(r" (?:as|at|positioned|rotated|facing|anchored|align|in|on|summon|if|unless|store|run) (?=.)")


def _recall(r: Reader, read: dict, pos: int, key: str):
    """The subcommand at ``pos`` (its space) when its text ``key``, up to the next boundary, was
    read cleanly as one subcommand before, moved here (the cursor put at the boundary); else None.

    A subcommand's reader reads a fixed number of arguments and never looks past the space that ends
    the last one, so the same text followed by any boundary reads the same. The first boundary may be
    an argument (``positioned as @s``): such a subcommand is not found, and read as usual."""
    known = read.get(key)
    if not known:
        return None
    try:
        found = relocate(known[0], r.path, r.line, r.col + pos + 1 - known[1])
    except NotRelocatable:
        read[key] = False
        return None
    r.pos = pos + len(key)
    return found


def _may_end(subcommand: ast.Subcommand) -> bool:
    """Whether the chain may end after ``subcommand``: a condition, except ``if|unless function``, whose
    node only forks on (ExecuteCommand.addConditionals: no ``executes``; the command tree reports it
    not executable)."""
    return isinstance(subcommand, ast.Condition) and not isinstance(subcommand, ast.IfFunction)


def execute(r: Reader, loc) -> ast.Command:
    subcommands = []
    text = r.text
    read = READ.get(r.version) if type(r) is Reader else None  # a joined line's offsets span lines
    condition_last = False  # the chain may end after a condition
    while True:
        pos = r.pos
        if pos == r.end and condition_last:
            return ast.Execute.new(loc, tuple(subcommands), None)
        if text.startswith(" run ", pos) and pos + 5 < r.end:
            r.pos = pos + 5
            return ast.Execute.new(loc, tuple(subcommands), rest_command(r))
        boundary = _BOUNDARY.search(text, pos + 1) if read is not None else None
        if boundary is not None:
            key = text[pos:boundary.start()]
            recalled = _recall(r, read, pos, key)
            if recalled is not None:
                subcommands.append(recalled)
                condition_last = _may_end(recalled)
                continue
        warned = len(r.warnings)
        m = _FAST_SCORE_MATCHES.match(text, pos)
        fast = _fast_score_matches(r, m, r.loc_at(pos + 1)) if m is not None else None
        if fast is not None:
            subcommands.append(fast)
            condition_last = True
        else:
            name = r.keyword_then_space(_ALL, "execute subcommand", _what_follows)
            if name == "run":
                return ast.Execute.new(loc, tuple(subcommands), rest_command(r))
            subcommands.append(_SUBCOMMANDS[name](r, r.loc_at(pos + 1)))
            condition_last = name in _CONDITION_SUBCOMMANDS and _may_end(subcommands[-1])
            if r.pos == r.end and not condition_last:
                r.fail(f"incomplete execute: expected another subcommand or 'run' after '{name}'")
        if (boundary is not None and pos + len(key) == r.pos and len(r.warnings) == warned
                and len(read) < READ_MAX):
            read.setdefault(key, (subcommands[-1], r.col + pos + 1))  # False stays


PARSERS = {"execute": execute}
