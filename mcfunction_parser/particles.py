"""The particle argument (ParticleArgument): a particle type and its options, per release.

Before 1.20.5 the options are words after the name (each type's ParticleOptions.Deserializer
.fromCommand: ``dust 1 0 0 1``); from 1.20.5 (24w13a) an SNBT compound right after it, decoded
with the type's codec (ParticleArgument.readParticle: ``{}`` when none is written, so a type whose
options have required fields fails without them: ``particle dust ~ ~ ~``). Sources: the decompiled
1.21 and 1.21.11 core/particles classes (DustParticleOptions, DustColorTransitionOptions,
ScalableParticleOptionsBase, ColorParticleOption, BlockParticleOption, ItemParticleOption,
VibrationParticleOption, SculkChargeParticleOptions, ShriekParticleOption, TrailParticleOption).
"""
from __future__ import annotations

from . import codecs, gamedata, snbt
from .game_objects import block, check_id
from .items import item_argument
from .nbt import Compound
from .primitives import resource_location
from .reader import Reader

PARTICLE_SNBT = (1, 20, 5)  # 24w13a: particle options are SNBT


def _known_id(registry: str, what: str, forbidden: str = "") -> codecs.Shape:
    """A registry's byNameCodec: an id the release's registry has (unchecked without exact data)."""
    def shape(value, version):
        if not isinstance(value, str):
            return f"expected a {what} id, got {codecs.kind(value)}"
        rid = value if ":" in value else "minecraft:" + value
        namespace, _, path = rid.partition(":")
        if rid == forbidden:
            return f"the {what} may not be {forbidden}"
        try:
            release, exact = gamedata.registry_release(version)
        except gamedata.GameDataMissing:
            return None
        ids = gamedata.registry(registry, release)
        if exact and ids and (namespace != "minecraft" or path not in ids):
            return f"unknown {what} '{rid}'"
        return None
    return shape


_BLOCK_ID = _known_id("block", "block")
_ITEM_ID = _known_id("item", "item", forbidden="minecraft:air")
# BlockParticleOption: BlockState.CODEC ({Name, Properties}) or a block id
_BLOCK_STATE = codecs.either(_BLOCK_ID, codecs.fields(("Name", _BLOCK_ID)), what="a block id or {Name: id, ...}")
# ItemParticleOption: ItemStack.SINGLE_ITEM_CODEC ({id, components}) or an item id other than air
_ITEM = codecs.either(_ITEM_ID, codecs.fields(("id", _ITEM_ID)), what="an item id or {id: id, ...}")
_SCALE = codecs.float_between(0.01, 4.0)  # ScalableParticleOptionsBase.SCALE
_VEC3 = codecs.numbers(3)

# particle type -> the codec of its options, for the types whose options have required fields
SNBT_OPTIONS: dict[str, codecs.Shape] = {
    "dust": codecs.fields(("color", codecs.RGB), ("scale", _SCALE)),
    "dust_color_transition": codecs.fields(("from_color", codecs.RGB), ("to_color", codecs.RGB), ("scale", _SCALE)),
    "entity_effect": codecs.fields(("color", codecs.ARGB)),
    "tinted_leaves": codecs.fields(("color", codecs.ARGB)),
    **{name: codecs.fields(("block_state", _BLOCK_STATE))
       for name in ("block", "block_marker", "falling_dust", "dust_pillar", "block_crumble")},
    "item": codecs.fields(("item", _ITEM)),
    "vibration": codecs.fields(("destination", codecs.compound), ("arrival_in_ticks", codecs.int_at_least(-2**31))),
    "sculk_charge": codecs.fields(("roll", codecs.number)),
    "shriek": codecs.fields(("delay", codecs.int_at_least(-2**31))),
    "trail": codecs.fields(("target", _VEC3), ("color", codecs.RGB)),
}


def _floats(r: Reader, count: int) -> None:
    for _ in range(count):
        r.space("particle option")
        r.double()


def _word_options(r: Reader, name: str) -> None:
    """Before 1.20.5: the options after the name (ParticleOptions.Deserializer.fromCommand)."""
    if name == "dust":
        _floats(r, 4)  # red green blue scale (the scale is clamped, not refused)
    elif name == "dust_color_transition":
        _floats(r, 7)
    elif name in ("block", "block_marker", "falling_dust", "dust_pillar"):
        r.space("block")
        block(r, False)
    elif name == "item":
        r.space("item")
        item_argument(r)
    elif name == "vibration":
        _floats(r, 6 if r.version < (1, 19, 0) else 3)  # 1.19: the destination only
        r.space("ticks")
        r.integer()
    elif name == "sculk_charge":
        _floats(r, 1)
    elif name == "shriek":
        r.space("delay")
        r.integer()


def particle(r: Reader) -> str:
    """A particle type and its options, returned as written."""
    start = r.pos
    rid = resource_location(r, "particle type")
    check_id(r, "particle_type", rid, start)
    if r.version < PARTICLE_SNBT:
        if rid.startswith("minecraft:"):
            _word_options(r, rid[10:])
        return r.text[start:r.pos]
    options_at = r.pos
    options = snbt.compound(r) if r.peek() == "{" else Compound()
    shape = SNBT_OPTIONS.get(rid.removeprefix("minecraft:")) if rid.startswith("minecraft:") else None
    problem = shape(options, r.version) if shape is not None else None
    if problem:
        r.fail(f"invalid options for particle {rid}: {problem}", options_at if options else start)
    return r.text[start:r.pos]
