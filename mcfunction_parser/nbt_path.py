"""NBT paths (``a.b[0].c[{x:1b}]{y:2}``, ``"quoted key"``, ``[]``, ``[-1]``, root ``{..}``)."""
from __future__ import annotations

import re

from .ast import NbtPath, PathAll, PathFilter, PathIndex, PathKey, PathMatch
from .reader import INT_MAX, INT_MIN, Reader, brief, integer_value
from .snbt import compound

# NbtPathArgument.isAllowedInUnquotedName: anything but space, quotes, brackets, braces and '.'
_KEY = re.compile(r"[^ \"'\[\]{}.]+")
_INDEX = re.compile(r"-?[0-9]+")


def nbt_path(r: Reader) -> NbtPath:
    loc = r.loc()
    start = r.pos
    text = r.text
    nodes = []
    first = True
    while True:
        c = r.peek()
        if c == "{":
            if not first:
                r.fail("a compound filter '{...}' must follow a key or start the path")
            nodes.append(PathFilter.new(compound(r)))
        elif c == "[":
            nodes.append(_bracket(r))
        elif c == '"' or c == "'":
            nodes.append(PathKey.new(r.quoted()))
        else:
            m = _KEY.match(text, r.pos)
            if m is None:
                r.fail(f"expected an NBT path, got {r.found()}")
            r.pos = m.end()
            nodes.append(PathKey.new(m.group()))
        first = False
        # a key may be followed by a {filter}, [index] or '.'
        while True:
            c = r.peek()
            if c == "{" and isinstance(nodes[-1], PathKey):
                nodes.append(PathFilter.new(compound(r)))
            elif c == "[":
                nodes.append(_bracket(r))
            else:
                break
        if c == ".":
            r.pos += 1
            if r.pos >= r.end or text[r.pos] == " ":
                r.fail("expected an NBT path node after '.'")
            continue
        if c == "" or c == " ":
            return NbtPath.new(tuple(nodes), text[start:r.pos], loc)
        r.fail(f"unexpected '{c}' in NBT path")


def _bracket(r: Reader):
    r.pos += 1  # '['
    c = r.peek()
    if c == "]":
        r.pos += 1
        return PathAll.new()
    if c == "{":
        node = PathMatch.new(compound(r))
    else:
        start = r.pos
        m = _INDEX.match(r.text, start)
        if m is None:
            r.fail(f"expected an index, '{{' or ']' in NBT path, got {r.found()}")
        index = integer_value(m.group())
        if not INT_MIN <= index <= INT_MAX:
            r.fail(f"index {brief(m.group())} is out of range for a 32-bit int", start)
        r.pos = m.end()
        node = PathIndex.new(index)
    r.expect("]")
    return node
