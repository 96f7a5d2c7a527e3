"""``data get|merge|modify|remove``."""
from __future__ import annotations

from .. import ast
from ..nbt_path import nbt_path
from ..reader import Reader
from ..snbt import compound, value
from .data_targets import data_target

_MODES = ("set", "append", "prepend", "insert", "merge")


def _get(r: Reader, loc):
    target = data_target(r)
    path = scale = None
    if r.optional_space():
        path = nbt_path(r)
        if r.optional_space():
            scale = r.double(what="scale")
    r.finish()
    return ast.DataGet.new(loc, target, path, scale)


def _merge(r: Reader, loc):
    target = data_target(r)
    r.space("NBT compound")
    nbt = compound(r)
    r.finish()
    return ast.DataMerge.new(loc, target, nbt)


def _remove(r: Reader, loc):
    target = data_target(r)
    r.space("NBT path")
    path = nbt_path(r)
    r.finish()
    return ast.DataRemove.new(loc, target, path)


def _modify(r: Reader, loc):
    target = data_target(r)
    r.space("NBT path")
    path = nbt_path(r)
    mode = r.keyword(_MODES, "modification mode")
    index = None
    if mode == "insert":
        r.space("index")
        index = r.integer(what="index")
    r.space("from, value or string")
    source = _source(r)
    r.finish()
    return ast.DataModify.new(loc, target, path, mode, index, source)


def _source(r: Reader) -> ast.DataSource:
    loc = r.loc()
    start = r.pos
    kind = r.literal(("from", "value", "string"), "data source")
    r.space("value" if kind == "value" else "entity, storage or block")
    if kind == "value":
        return ast.SourceValue.new(value(r), loc)
    if kind == "string":
        r.require("data modify string", start)
    source = data_target(r)
    path = nbt_path(r) if r.optional_space() else None
    if kind == "from":
        return ast.SourceFrom.new(source, path, loc)
    begin = end = None
    if path is not None and r.optional_space():
        begin = r.integer(what="start index")
        if r.optional_space():
            end = r.integer(what="end index")
    return ast.SourceString.new(source, path, begin, end, loc)


_ACTIONS = {"get": _get, "merge": _merge, "modify": _modify, "remove": _remove}


def data(r: Reader, loc) -> ast.Command:
    action = r.keyword(_ACTIONS, "data action")
    r.space("entity, storage or block")
    return _ACTIONS[action](r, loc)


PARSERS = {"data": data}
