"""Arguments that name the game's objects, checked against its registries for the target release
(:mod:`.gamedata`): block states and predicates and ids of a registry (item stacks and predicates
are :mod:`.items`, particles :mod:`.particles`).

An id missing from registries that are exactly the target release's is an error (the game parses
functions with its registries at hand: BlockStateParser.readBlock, ItemParser.readItem and
ResourceArgument.parse fail on an unknown id). Against an older release's registries (the target
is newer than the data) it is a warning saying so.
"""
from __future__ import annotations

import re
from functools import lru_cache

from . import gamedata, snbt
from .features import version_text
from .primitives import resource_location, resource_or_tag
from .reader import Reader

# registries no data pack can add to: an id in any namespace must be in them
STATIC = frozenset(("block", "item", "entity_type", "particle_type", "mob_effect", "attribute"))
# the registries became data-driven (a pack may add entries) from these releases
_DATA_DRIVEN_FROM = {"enchantment": (1, 21, 0), "worldgen/biome": (1, 16, 2)}
_DATA_NAMES = {"block": "block", "item": "item", "entity_type": "entity type", "particle_type": "particle type",
               "mob_effect": "effect", "enchantment": "enchantment", "worldgen/biome": "biome",
               "attribute": "attribute"}


@lru_cache(maxsize=None)
def _known(registry: str, version) -> tuple[frozenset[str], bool] | None:
    try:
        release, exact = gamedata.registry_release(version)
    except gamedata.GameDataMissing:
        return None
    ids = gamedata.registry(registry, release)
    return (ids, exact) if ids else None


def check_id(r: Reader, registry: str, rid: str, start: int) -> None:
    """Fail (or warn, when the data is an older release's) if ``rid`` is not in ``registry``."""
    namespace, _, path = rid.partition(":")
    if namespace != "minecraft" and registry not in STATIC:
        return  # a pack's own entry of a data-driven registry
    since = _DATA_DRIVEN_FROM.get(registry)
    if since is not None and r.version >= since and namespace != "minecraft":
        return
    known = _known(registry, r.version)
    if known is None or (namespace == "minecraft" and path in known[0]):
        return
    ids, exact = known
    name = _DATA_NAMES.get(registry, registry)
    if exact:
        r.fail(f"unknown {name} '{rid}'", start)
    release, _ = gamedata.registry_release(r.version)
    r.warnings.append((f"{name} '{rid}' is not in the {version_text(release)} registry, the newest dpemu has",
                       start))


def registry_id(r: Reader, registry: str) -> str:
    start = r.pos
    rid = resource_location(r, _DATA_NAMES.get(registry, registry))
    check_id(r, registry, rid, start)
    return rid


def _another(r: Reader, where: str) -> bool:
    """After an entry of a ``[...]`` list: True past a ',' (another entry follows), False past the ']'."""
    c = r.peek()
    if c == "," or c == "]":
        r.pos += 1
        return c == ","
    r.fail(f"expected ',' or ']' {where}, got {r.found()}")


# ----------------------------------------------------------------------------- blocks

_STATE_NAME = re.compile(r"[ ]*([0-9A-Za-z_\-.+]*)[ ]*")


def _block_states(r: Reader, block: str | None) -> None:
    """``[name=value,...]`` (BlockStateParser.readProperties), checked against ``block``'s states."""
    states = None
    if block is not None and block.startswith("minecraft:") and _known("block", r.version):
        release, exact = gamedata.registry_release(r.version)
        states = gamedata.block_states(block, release) if exact else None
    r.pos += 1
    seen = set()
    text = r.text
    while True:
        m = _STATE_NAME.match(text, r.pos)
        name = m.group(1)
        name_pos = r.pos + m.group().find(name) if name else m.end()
        r.pos = m.end()
        if not name:
            if r.peek() == "]" and not seen:
                r.pos += 1
                return
            r.fail(f"expected a block state name, got {r.found()}")
        if states is not None and name not in states:
            r.fail(f"block {block} has no state '{name}'", name_pos)
        if name in seen:
            r.fail(f"block state '{name}' is given twice", name_pos)
        seen.add(name)
        r.expect("=")
        m = _STATE_NAME.match(text, r.pos)
        value = m.group(1)
        value_pos = r.pos + m.group().find(value) if value else m.end()
        if not value:
            r.pos = m.end()
            r.fail(f"expected a value for block state '{name}', got {r.found()}")
        if states is not None and value not in states[name]:
            r.fail(f"block {block} does not accept '{value}' for its '{name}' state "
                   f"({', '.join(states[name])})", value_pos)
        r.pos = m.end()
        if not _another(r, "to close the block states"):
            return


def block(r: Reader, tags: bool) -> str:
    """A block state (``tags``: a block predicate, ``#tag`` allowed) with ``[states]`` and ``{nbt}``,
    returned as written."""
    start = r.pos
    rid, is_tag = resource_or_tag(r, "block") if tags else (resource_location(r, "block"), False)
    if not is_tag:
        check_id(r, "block", rid, start)
    if r.peek() == "[":
        _block_states(r, None if is_tag else rid)
    if r.peek() == "{":
        snbt.compound(r)
    return r.text[start:r.pos]
