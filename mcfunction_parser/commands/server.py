"""``gamerule``, ``random``, ``time`` and ``trigger``."""
from __future__ import annotations

import re

from .. import ast
from ..arguments import duration, objective
from ..features import FEATURES
from ..primitives import int_range, resource_location
from ..reader import ParseError, Reader, show
from ..snbt import to_float32
from .gamerules import int_bounds, rule_type, unknown_warning
from .tree import tree_command

_RULE = re.compile(r"[A-Za-z_][A-Za-z0-9_:.]*\Z")
TIME_NAMES = {"day": 1000, "noon": 6000, "night": 13000, "midnight": 18000}


def gamerule(r: Reader, loc) -> ast.Command:
    r.space("game rule")
    start = r.pos
    rule = r.word()
    if not _RULE.match(rule):
        r.fail(f"expected a game rule name, got {show(rule)}", start)
    kind, problem = rule_type(rule, r.version)
    if problem:
        r.fail(problem, start)
    if kind is None:
        r.warnings.append((unknown_warning(rule, r.version), start))
    value = None
    if r.optional_space():
        if kind == "int":
            value = str(r.integer(**int_bounds(rule, r.version), what="game rule value"))
        elif kind == "bool":
            value = "true" if r.boolean() else "false"
        elif r.rest_word() in ("true", "false"):
            value = r.word()
        else:
            value = str(r.integer(what="game rule value (true, false or an integer)"))
    r.finish()
    return ast.Gamerule.new(loc, rule, value)


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
            if r.optional_space():  # includeWorldSeed is executable (RandomCommand.register)
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
    """``time`` from 26.1 (TimeCommand.register, 26.1.2): ``time query gametime`` is :class:`ast.Time`;
    every other form works on a world clock (:class:`ast.ClockCommand`), the executing dimension's
    default clock or the one ``time of <clock>`` names. The release's command tree checks the line."""
    text, start = r.text, r.pos
    if text.startswith(" query gametime", start) and start + 15 == r.end:
        r.pos = r.end
        return ast.Time.new(loc, "query", None, "gametime")
    tree_command(r, loc, "time")
    words, at = [], start + 1
    for word in text[start + 1:r.end].split(" "):
        words.append((word, at))
        at += len(word) + 1

    def need(count: int, what: str) -> None:  # the tree refused short lines, but a stand-in tree only warns
        if len(words) < count or not words[count - 1][0]:
            r.pos = r.end
            r.fail(f"incomplete command: expected {what}")
    need(1, "a time action")
    clock = clock_loc = None
    if words[0][0] == "of":
        need(3, "<clock> and a time action")
        clock, clock_loc = _id_at(r, words[1][1]), r.loc_at(words[1][1])
        words = words[2:]
    action = words[0][0]
    fields = {"clock": clock, "clock_loc": clock_loc}
    if action in ("set", "add", "rate", "query"):
        need(2, f"the {action} argument")
    if action in ("set", "add"):
        ticks = _ticks_at(r, words[1][1], len(words[1][0]), 0 if action == "set" else -2**31)
        if ticks is None:  # Brigadier tries <time> first: what it refuses is a time marker's id
            action, fields["value"] = "marker", _id_at(r, words[1][1])
        else:
            fields["value"] = ticks
    elif action == "rate":
        fields["value"] = to_float32(float(words[1][0]))  # FloatArgumentType: a Java float
    elif action == "query" and words[1][0] != "time":
        fields.update(timeline=_id_at(r, words[1][1]), timeline_loc=r.loc_at(words[1][1]), repetition=len(words) == 3)
    r.pos = r.end
    return ast.ClockCommand.new(loc, action, **fields)


def _id_at(r: Reader, pos: int) -> str:
    r.pos = pos
    return resource_location(r)


def _ticks_at(r: Reader, pos: int, length: int, minimum: int) -> int | None:
    """The time argument written at ``pos`` in ticks, None if TimeArgument refuses it."""
    r.pos = pos
    try:
        ticks = duration(r, minimum)
    except ParseError:
        return None
    return ticks if r.pos == pos + length else None


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
