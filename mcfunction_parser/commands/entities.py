"""``tag``, ``summon``, ``kill``, ``tp``/``teleport`` and ``ride``."""
from __future__ import annotations

from .. import ast
from ..arguments import vec2, vec3
from ..game_objects import registry_id
from ..reader import ParseError, Reader
from ..selectors import target
from ..snbt import compound


def tag(r: Reader, loc) -> ast.Command:
    r.space("entities")
    who = target(r)
    action = r.keyword(("add", "remove", "list"), "tag action")
    name = None
    if action != "list":
        r.space("tag name")
        start = r.pos
        name = r.unquoted()
        if not name:
            r.fail("expected a tag name (letters, digits, _ - . +)", start)
    r.finish()
    return ast.TagCommand.new(loc, who, action, name)


def summon(r: Reader, loc) -> ast.Command:
    r.space("entity type")
    kind = registry_id(r, "entity_type")
    pos = nbt = None
    if r.optional_space():
        pos = vec3(r)
        if r.optional_space():
            nbt = compound(r)
    r.finish()
    return ast.Summon.new(loc, kind, pos, nbt)


def kill(r: Reader, loc) -> ast.Command:
    who = target(r) if r.optional_space() else None
    r.finish()
    return ast.Kill.new(loc, who)


def _try_position(r: Reader):
    """A position if the cursor holds one, else None with the cursor unchanged (``tp`` is ambiguous:
    ``tp 1 2 3`` is a position, ``tp Steve`` a player; the game tries both branches)."""
    c = r.peek()
    if c == "@":
        return None
    if c == "~" or c == "^":  # can't start a name: report the position's own error
        return vec3(r)
    start = r.pos
    try:
        return vec3(r)
    except ParseError:
        r.pos = start
        return None


def teleport(r: Reader, loc) -> ast.Command:
    r.space("entity or position")
    first_start = r.pos
    pos = _try_position(r)
    if pos is not None:
        if r.pos >= r.end or first_start < r.end and r.text[first_start] in "~^":
            r.finish()
            return ast.Teleport.new(loc, None, pos)
        r.pos = first_start  # more follows: `tp -1 ~ ~ ~` moves the player named -1 (the targets branch)
    who = target(r)
    if not r.optional_space():
        r.pos = first_start
        destination = target(r, single=True)
        return ast.Teleport.new(loc, None, destination)
    pos = _try_position(r)
    if pos is None:
        destination = target(r, single=True)
        r.finish()
        return ast.Teleport.new(loc, who, destination)
    if not r.optional_space():
        return ast.Teleport.new(loc, who, pos)
    if r.rest_word() != "facing":
        rotation = vec2(r)
        r.finish()
        return ast.Teleport.new(loc, who, pos, rotation=rotation)
    r.pos += 6
    r.space("position or 'entity'")
    if r.rest_word() != "entity":
        facing = vec3(r)
        r.finish()
        return ast.Teleport.new(loc, who, pos, facing=facing)
    r.pos += 6
    r.space("entity")
    facing_entity = target(r, single=True)
    anchor = r.literal(("eyes", "feet"), "anchor") if r.optional_space() else None
    r.finish()
    return ast.Teleport.new(loc, who, pos, facing_entity=facing_entity, facing_anchor=anchor)


def ride(r: Reader, loc) -> ast.Command:
    r.space("target entity")
    who = target(r, single=True)
    action = r.keyword(("mount", "dismount"), "ride action")
    vehicle = None
    if action == "mount":
        r.space("vehicle entity")
        vehicle = target(r, single=True)
    r.finish()
    return ast.Ride.new(loc, who, action, vehicle)


PARSERS = {"tag": tag, "summon": summon, "kill": kill, "tp": teleport, "teleport": teleport, "ride": ride}
