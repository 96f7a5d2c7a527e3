"""``function``, ``return`` and ``schedule``."""
from __future__ import annotations

from .. import ast
from ..arguments import duration
from ..nbt_path import nbt_path
from ..primitives import resource_or_tag
from ..reader import Reader
from ..snbt import compound
from .data_targets import data_target
from .dispatch import rest_command


def function(r: Reader, loc) -> ast.Command:
    r.space("function")
    name, is_tag = resource_or_tag(r, "function")
    if not r.optional_space():
        return ast.FunctionCall.new(loc, name, is_tag)
    r.require("function arguments", r.pos)
    if r.peek() == "{":
        args = compound(r)
        r.finish()
        return ast.FunctionCall.new(loc, name, is_tag, arguments=args)
    r.literal(("with",), "arguments '{...}' or 'with'")
    r.space("entity, storage or block")
    source = data_target(r)
    path = nbt_path(r) if r.optional_space() else None
    r.finish()
    return ast.FunctionCall.new(loc, name, is_tag, with_source=source, with_path=path)


def return_(r: Reader, loc) -> ast.Command:
    r.space("return value, 'run' or 'fail'")
    start = r.pos
    word = r.rest_word()
    if word == "run":
        r.require("return run", start)
        r.pos += 3
        r.space("command")
        return ast.Return.new(loc, "run", command=rest_command(r))
    if word == "fail":
        r.require("return fail", start)
        r.pos += 4
        r.finish()
        return ast.Return.new(loc, "fail")
    value = r.integer(what="return value")
    r.finish()
    return ast.Return.new(loc, "value", value=value)


def schedule(r: Reader, loc) -> ast.Command:
    action = r.keyword(("function", "clear"), "schedule action")
    r.space("function")
    if action == "clear":
        # a greedy string compared textually with the scheduled ids ("ns:path" or "#ns:path"),
        # so it is kept as written: `schedule clear foo` does not clear minecraft:foo's event
        text = r.rest()
        return ast.ScheduleClear.new(loc, text[1:] if text.startswith("#") else text, text.startswith("#"))
    name, is_tag = resource_or_tag(r, "function")
    r.space("time")
    time_pos = r.pos
    ticks = duration(r)
    if ticks == 0:
        # ScheduleCommand parses 0 and fails when run ("Can't schedule for current tick")
        r.warnings.append(("schedule time 0 fails every time it runs: the game can't schedule for the current tick",
                           time_pos))
    mode = r.literal(("append", "replace"), "schedule mode") if r.optional_space() else "replace"
    r.finish()
    return ast.Schedule.new(loc, name, is_tag, ticks, mode)


PARSERS = {"function": function, "return": return_, "schedule": schedule}
