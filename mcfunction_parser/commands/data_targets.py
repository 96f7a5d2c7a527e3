"""``entity TARGET | storage ID | block POS``: the data sources and destinations of data, execute and function."""
from __future__ import annotations

from .. import ast
from ..arguments import vec3
from ..primitives import resource_location
from ..reader import Reader
from ..selectors import target

_KINDS = ("entity", "storage", "block")


def data_target(r: Reader) -> ast.DataTarget:
    loc = r.loc()
    kind = r.literal(_KINDS, "entity, storage or block")
    r.space(kind)
    if kind == "entity":
        return ast.EntityData.new(target(r, single=True), loc)
    if kind == "storage":
        return ast.StorageData.new(resource_location(r, "storage id"), loc)
    return ast.BlockData.new(vec3(r, block=True), loc)
