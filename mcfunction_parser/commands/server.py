"""``gamerule``, ``random``, ``time`` and ``trigger``."""
from __future__ import annotations

import re

from .. import ast
from ..arguments import duration, objective
from ..features import FEATURES, gamerule_type, version_text
from ..primitives import int_range, resource_location
from ..reader import ParseError, Reader, show
from .tree import root_for, tree_command

_RULE = re.compile(r"[A-Za-z_][A-Za-z0-9_:.]*\Z")
TIME_NAMES = {"day": 1000, "noon": 6000, "night": 13000, "midnight": 18000}


def gamerule(r: Reader, loc) -> ast.Command:
    r.space("game rule")
    start = r.pos
    rule = r.word()
    if not _RULE.match(rule):
        r.fail(f"expected a game rule name, got {show(rule)}", start)
    kind, problem = gamerule_type(rule, r.version)
    if problem:
        r.fail(problem, start)
    if kind is None:
        r.warnings.append((f"unknown game rule '{rule}' (not in the rule table for {version_text(r.version)})", start))
    value = None
    if r.optional_space():
        if kind == "int":
            value = str(r.integer(**_int_bounds(rule, r.version), what="game rule value"))
        elif kind == "bool":
            value = "true" if r.boolean() else "false"
        elif r.rest_word() in ("true", "false"):
            value = r.word()
        else:
            value = str(r.integer(what="game rule value (true, false or an integer)"))
    r.finish()
    return ast.Gamerule.new(loc, rule, value)


def _int_bounds(rule: str, version) -> dict:
    """The bounds the release's command tree gives an integer rule's value (1.21.11: min and max)."""
    root = root_for(version)
    node = root["children"]["gamerule"].get("children", {}).get(rule) if root is not None else None
    value = (node or {}).get("children", {}).get("value", {})
    props = value.get("properties") or {} if value.get("parser") == "brigadier:integer" else {}
    return {name: props[key] for name, key in (("lo", "min"), ("hi", "max")) if key in props}


def _sequence(r: Reader) -> str | None:
    return resource_location(r, "random sequence") if r.optional_space() else None


def random(r: Reader, loc) -> ast.Command:
    r.space("value, roll or reset")
    start = r.pos
    action = r.literal(("value", "roll", "reset"), "random action")
    r.space("range" if action != "reset" else "sequence or '*'")
    if action != "reset":
        rng = int_range(r)
        seq = _sequence(r)
        r.finish()
        return ast.RandomCommand.new(loc, action, rng, seq)
    r.require("random reset", start)
    if r.peek() == "*" and r.rest_word() == "*":
        r.pos += 1
        seq = "*"
    else:
        seq = resource_location(r, "random sequence")
    seed = None
    include_world = include_seq = True
    if r.optional_space():
        seed = r.integer(what="seed")
        if r.optional_space():
            include_world = r.boolean()
            r.space("includeSequenceId")
            include_seq = r.boolean()
    r.finish()
    return ast.RandomCommand.new(loc, "reset", None, seq, seed, include_world, include_seq)


def time(r: Reader, loc) -> ast.Command:
    if r.version >= FEATURES["world clocks"][0]:
        return _time_with_clocks(r, loc)
    action = r.keyword(("add", "set", "query"), "time action")
    r.space("time" if action != "query" else "daytime, gametime or day")
    if action == "query":
        query = r.literal(("daytime", "gametime", "day"), "time query")
        r.finish()
        return ast.Time.new(loc, action, None, query)
    word = r.rest_word()
    if action == "set" and word in TIME_NAMES:
        r.pos += len(word)
        value = TIME_NAMES[word]
    else:
        value = duration(r)
    r.finish()
    return ast.Time.new(loc, action, value, None)


def _time_with_clocks(r: Reader, loc) -> ast.Command:
    """``time`` from 26.1 (world clocks). ``time add|set <ticks>`` (add takes a negative time from
    26.1) and ``time query gametime`` keep their AST and meaning here; the clock forms (``of
    <clock>``, ``pause``, ``resume``, ``rate``, ``query time|<timeline>``, ``set <time marker>``,
    which took the place of ``set day`` ...) are checked against the release's command tree and
    kept as text: their clocks are not modelled."""
    text, start = r.text, r.pos
    if text.startswith(" query gametime", start) and start + 15 == r.end:
        r.pos = r.end
        return ast.Time.new(loc, "query", None, "gametime")
    for action, minimum in (("add", -2**31), ("set", 0)):
        value_at = start + len(action) + 2
        if text.startswith(f" {action} ", start) and value_at < r.end and text[value_at] in "-.0123456789":
            try:  # Brigadier tries <time> first; what it refuses may still be a time marker id
                r.pos = value_at
                value = duration(r, minimum)
                r.finish()
                return ast.Time.new(loc, action, value, None)
            except ParseError:
                r.pos = start
    return tree_command(r, loc, "time")


def trigger(r: Reader, loc) -> ast.Command:
    r.space("objective")
    name = objective(r)
    action = value = None
    if r.optional_space():
        action = r.literal(("add", "set"), "trigger action")
        r.space("value")
        value = r.integer(what="value")
    r.finish()
    return ast.Trigger.new(loc, name, action, value)


PARSERS = {"gamerule": gamerule, "random": random, "time": time, "trigger": trigger}
