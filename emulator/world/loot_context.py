"""What loot tables, item modifiers, predicates and advancement criteria read, and the values they
compute: the one :class:`LootContext`, number providers, ranges, and JSON values made NBT. Read by
:mod:`emulator.world.predicates` (conditions) and :mod:`emulator.world.loot` (tables, functions).

- ``number(provider, ctx)`` / ``integer(provider, ctx)``: NumberProvider.getFloat / getInt
  (constant, uniform, binomial, score, storage).
- ``in_range(bounds, value)`` / ``in_ints(bounds, value)``: MinMaxBounds.Doubles / Ints, an exact
  number or ``{min, max}`` (``min_max(bounds, ints)``: the bounds as the codec reads them).
  ``in_int_range(bounds, value, ctx)`` / ``int_range(bounds, ctx)``: IntRange, whose bounds are
  number providers read with getInt (a bound written 1.2 is Math.round(1.2F) = 1).
- ``to_tag(json)`` / ``snbt_or_tag(value)`` / ``json_nbt(json)`` / ``component_tag(name, json)``:
  JSON values and SNBT strings as NBT (``json_nbt``: as the codecs taking any NBT convert JSON,
  DataFixerUpper's JsonOps.convertTo).
- ``not_modelled(kind, name)``: the :class:`~emulator.world.errors.Unmodelled` failure naming what
  the emulator does not model (reported; a test meeting it is inconclusive).
- ``DamageSource(type, attacker=None, direct=None)``: the damage type and the entity responsible
  (DamageSource.getEntity) and the one that dealt it (getDirectEntity); ``is_direct``.

Sources (decompiled 1.21): world/damagesource/DamageSource.java (isDirect: the causing entity is
the direct one, both absent included), world/level/storage/loot/LootContext.java (EntityTarget, visited
elements), LootParams.java, providers/number/*.java (ConstantValue, UniformGenerator,
BinomialDistributionGenerator, ScoreboardValue, StorageValue), IntRange.java,
advancements/critereon/MinMaxBounds.java, server/commands/LootCommand.java (dropKillLoot).
"""
from __future__ import annotations

import json
import math
import random as _random
from dataclasses import dataclass, field
from typing import Any, Callable

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import (Byte, ByteArray, Compound, Double, Float, Int, IntArray, List, Long, LongArray, Short,
                                  String)
from mcfunction_parser.nbt_path import nbt_path
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import compound as parse_compound
from emulator.world import mth, nbt_ops
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.items import ItemStack
from emulator.world.nbt_ops import copy_tag
from emulator.world.semantics import wrap32

_TARGETS = {"this": "this", "attacker": "attacker", "direct_attacker": "direct_attacker",
            "attacking_player": "attacking_player",  # the 1.21 names; before 1.21:
            "killer": "attacker", "direct_killer": "direct_attacker", "killer_player": "attacking_player"}


def namespaced(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


def not_modelled(kind: str, name: str) -> Unmodelled:
    return Unmodelled(f"{kind} '{name}'")


@dataclass(frozen=True)
class DamageSource:
    type: str = "minecraft:generic"
    attacker: Any = None  # DamageSource.getEntity: the responsible entity
    direct: Any = None  # getDirectEntity
    position: tuple[float, float, float] | None = None  # damageSourcePosition (``damage ... at POS``)

    @property
    def source_position(self) -> tuple[float, float, float] | None:
        """DamageSource.getSourcePosition: the position given, else the direct entity's."""
        if self.position is not None:
            return self.position
        return self.direct.pos if self.direct is not None else None

    @property
    def is_direct(self) -> bool:
        return self.attacker is self.direct


@dataclass
class LootContext:
    """LootContext: the world (``state``) and the parameters the game's LootParams carry. Loot
    tables, item modifiers, predicates and advancement criteria all read this one context.

    ``random`` defaults to the level's (``state.random``); the ``loot`` command passes the seeded
    loot source. ``resolve_text(component, entity)`` resolves a text component as an entity
    (given by the commands, which own selectors); None keeps it as written."""
    state: Any  # emulator.world.state.WorldState
    origin: tuple[float, float, float] | None = None
    this: Any = None  # an emulator.world.entities.Entity
    attacker: Any = None
    direct_attacker: Any = None
    attacking_player: Any = None
    tool: ItemStack | None = None
    block_state: Any = None  # the mined block (emulator.world.blocks.BlockState)
    block_entity: Compound | None = None  # the mined block entity's NBT
    explosion_radius: float | None = None
    damage_source: DamageSource | None = None
    dimension: str = "minecraft:overworld"
    random: _random.Random | None = None
    resolve_text: Callable[[Any, Any], Any] | None = None
    visited: set[str] = field(default_factory=set)  # LootContext.visitedElements

    def __post_init__(self) -> None:
        if self.random is None:
            self.random = self.state.random

    @property
    def resources(self):
        return self.state.resources

    @property
    def version(self) -> tuple[int, int, int]:
        return self.state.version

    def killed_by(self, killer) -> "LootContext":
        """LootCommand.dropKillLoot: the killer is the attacker and direct attacker, and the
        attacking player when it is one."""
        self.attacker = self.direct_attacker = killer
        self.attacking_player = killer if killer is not None and killer.is_player else None
        return self

    def entity(self, which: str):
        """LootContext.EntityTarget: this, attacker, direct_attacker, attacking_player (and their
        pre-1.21 names killer, direct_killer, killer_player)."""
        if which not in _TARGETS:
            raise not_modelled("entity target", which)
        return getattr(self, _TARGETS[which])

    def for_entity(self, entity) -> "LootContext":
        """A context of the same world with ``entity`` as ``this`` at its position (an entity
        predicate given as loot conditions)."""
        return LootContext(self.state, entity.pos, this=entity, dimension=entity.dimension, random=self.random,
                           resolve_text=self.resolve_text, visited=self.visited)

    def score(self, holder: str, objective: str) -> int | None:
        """The holder's score, None when unset or the objective does not exist."""
        board = self.state.scoreboard
        return board.get(holder, objective) if board.exists(objective) else None

    def storage(self, storage_id: str) -> Compound:
        return self.state.storage.get(storage_id, Compound())

    def visit(self, key: str) -> bool:
        """LootContext.pushVisitedElement: False (and a logged warning, as the game logs "Detected
        infinite loop in loot tables") when ``key`` is already being evaluated."""
        if key in self.visited:
            self.state.error(f"{key} refers back to itself: the game logs an infinite loop and skips it",
                             severity="warning")
            return False
        self.visited.add(key)
        return True

    def leave(self, key: str) -> None:
        self.visited.discard(key)


# ---------------------------------------------------------------------- numbers
def number(provider, ctx: LootContext) -> float:
    """NumberProvider.getFloat."""
    if isinstance(provider, bool) or provider is None:
        raise not_modelled("number provider", repr(provider))
    if isinstance(provider, (int, float)):
        return float(provider)
    if not isinstance(provider, dict):
        raise not_modelled("number provider", repr(provider))
    kind = namespaced(provider.get("type", "uniform" if "min" in provider or "max" in provider else "constant"))
    if kind == "minecraft:constant":
        return float(provider.get("value", 0))
    if kind == "minecraft:uniform":
        lo, hi = number(provider["min"], ctx), number(provider["max"], ctx)
        return lo if lo >= hi else lo + ctx.random.random() * (hi - lo)  # Mth.randomBetween
    if kind == "minecraft:binomial":
        n, p = integer(provider["n"], ctx), number(provider["p"], ctx)
        return float(sum(ctx.random.random() < p for _ in range(n)))
    if kind == "minecraft:score":
        return _score(provider, ctx)
    if kind == "minecraft:storage":
        found = _storage_values(provider, ctx)
        return float(found[0]) if len(found) == 1 and nbt_ops.is_numeric(found[0]) else 0.0
    raise not_modelled("number provider", kind)


def integer(provider, ctx: LootContext) -> int:
    """NumberProvider.getInt: uniform ints are Mth.nextInt(min, max); otherwise round(getFloat)."""
    if isinstance(provider, dict) and namespaced(provider.get("type", "uniform" if "min" in provider else "")) == "minecraft:uniform":
        lo, hi = integer(provider["min"], ctx), integer(provider["max"], ctx)
        return lo if lo >= hi else lo + ctx.random.randrange(hi - lo + 1)
    if isinstance(provider, dict) and namespaced(provider.get("type", "")) == "minecraft:storage":
        found = _storage_values(provider, ctx)
        return int(found[0]) if len(found) == 1 and nbt_ops.is_numeric(found[0]) else 0
    value = number(provider, ctx)
    return int(math.floor(value + 0.5))  # Mth.floor(getFloat + 0.5F)


def _score(provider: dict, ctx: LootContext) -> float:
    target = provider.get("target", "this")
    if isinstance(target, dict) and namespaced(target.get("type", "")) == "minecraft:fixed":
        holder = target.get("name")
    else:
        name = target.get("target", "this") if isinstance(target, dict) else target
        entity = ctx.entity(name)
        holder = None if entity is None else entity.score_holder
    value = None if holder is None else ctx.score(holder, provider.get("score"))
    return 0.0 if value is None else value * float(provider.get("scale", 1.0))


def _storage_values(provider: dict, ctx: LootContext) -> list:
    path = path_of(provider.get("path", ""))
    try:
        return nbt_ops.get(ctx.storage(namespaced(provider.get("storage", ""))), path)
    except CommandFailure:
        return []


def path_of(text: str):
    try:
        return nbt_path(Reader(text, Loc("<loot>", 1, 1), (1, 21, 0)))
    except ParseError as error:
        raise CommandFailure("dpemu.loot.invalid", f"the NBT path '{text}'", error.message, report=True) from None


def int_range(value, ctx: LootContext) -> tuple[int | None, int | None]:
    """IntRange: an int (Codec.INT reads a JSON number with Number.intValue), or ``{min, max}``
    whose bounds are number providers read with getInt: IntRange's predicate compares the value
    with ``getInt`` of each bound, so ``{"min": 1.2}`` means at least Math.round(1.2F) = 1."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return int(value), int(value)
    if not isinstance(value, dict):
        raise not_modelled("range", repr(value))
    lo, hi = value.get("min"), value.get("max")
    return (None if lo is None else integer(lo, ctx)), (None if hi is None else integer(hi, ctx))


def in_int_range(bounds, value: int, ctx: LootContext) -> bool:
    """IntRange.test: inclusive, each bound optional."""
    lo, hi = int_range(bounds, ctx)
    return (lo is None or value >= lo) and (hi is None or value <= hi)


def in_range(bounds, value: float) -> bool:
    """MinMaxBounds.Doubles.matches: an exact number or ``{min, max}``, inclusive, each bound optional."""
    lo, hi = min_max(bounds, ints=False)
    return (lo is None or value >= lo) and (hi is None or value <= hi)


def in_ints(bounds, value: int) -> bool:
    """MinMaxBounds.Ints.matches: as :func:`in_range`, the bounds read by Codec.INT (a bound written
    1.9 is 1, -1.9 is -1)."""
    lo, hi = min_max(bounds, ints=True)
    return (lo is None or value >= lo) and (hi is None or value <= hi)


def min_max(bounds, ints: bool) -> tuple:
    """MinMaxBounds.createCodec: ``{min, max}`` (each optional), else one number for both bounds."""
    if isinstance(bounds, dict):
        lo, hi = bounds.get("min"), bounds.get("max")
        return (None if lo is None else _codec_number(lo, ints)), (None if hi is None else _codec_number(hi, ints))
    point = _codec_number(bounds, ints)
    return point, point


def _codec_number(value, ints: bool):
    """A bound as Codec.INT / Codec.DOUBLE decode a JSON value: JsonOps.getNumberValue gives a
    boolean as 1 or 0 and a number as Gson's LazilyParsedNumber, whose intValue truncates a
    decimal toward zero (BigDecimal.intValue) and keeps the low 32 bits of a number past an int
    (Long.parseLong then the int cast, or BigDecimal.intValue). Anything else fails the codec."""
    if isinstance(value, bool):
        value = int(value)
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        raise not_modelled("range bound", repr(value))
    if not ints:
        return value
    return wrap32(math.trunc(value))


# ---------------------------------------------------------------------- JSON to NBT
_TAGS = (Byte, Short, Int, Long, Float, Double, String, List, Compound, ByteArray, IntArray, LongArray)


def to_tag(value):
    """A JSON value as NBT (ints Int, decimals Double, booleans Byte); NBT (an inline definition's,
    read through NbtOps) as it is."""
    if isinstance(value, _TAGS):
        return copy_tag(value)
    if isinstance(value, bool):
        return Byte(value)
    if isinstance(value, int):
        return Int(value)
    if isinstance(value, float):
        return Double(value)
    if isinstance(value, str):
        return String(value)
    if isinstance(value, list):
        return List(to_tag(v) for v in value)
    if isinstance(value, dict):
        return Compound((k, to_tag(v)) for k, v in value.items())
    raise not_modelled("value", repr(value))


def stored_text(value, version):
    """A text component as an item's component stores it: JSON text before 1.21.5, an NBT value
    from then."""
    if tuple(version) >= (1, 21, 5):
        return to_tag(value)
    return String(json.dumps(value, separators=(",", ":"), ensure_ascii=False))


def json_nbt(value):
    """JsonOps.convertTo(NbtOps): JSON as the codecs that take any NBT read it (CompoundTag.CODEC:
    custom data, NBT predicates). A whole number is the narrowest of byte, short, int and long
    that holds it (1 is 1b, 1.0 too: BigDecimal.longValueExact), another number a float when
    the float is exact, else a double; a boolean a byte. A list of bytes, ints or longs is that
    array (NbtOps.createList); a list of other tags of one type a list; a mixed one is not
    modelled. NBT (an inline definition's: the codec reads it through NbtOps, nothing converted)
    keeps its types: ``{v:3}`` is an int there, ``{"v": 3}`` in a file a byte."""
    if isinstance(value, _TAGS):
        return copy_tag(value)
    if isinstance(value, bool):
        return Byte(value)
    if isinstance(value, float) and value.is_integer() and -2**63 <= value < 2**63:
        value = int(value)
    if isinstance(value, int):
        return _narrowest(value)
    if isinstance(value, float):
        return Float(value) if float(mth.f32(value)) == value else Double(value)
    if isinstance(value, str):
        return String(value)
    if isinstance(value, dict):
        return Compound((k, json_nbt(v)) for k, v in value.items())
    if isinstance(value, list):
        return _json_list([json_nbt(v) for v in value])
    raise not_modelled("value", repr(value))


_NARROW = ((Byte, 2**7), (Short, 2**15), (Int, 2**31), (Long, 2**63))
_ARRAYS = {Byte: ByteArray, Int: IntArray, Long: LongArray}


def _narrowest(value: int):
    for tag_type, bound in _NARROW:
        if -bound <= value < bound:
            return tag_type(value)
    return Double(value)  # longValueExact fails: BigDecimal.doubleValue


def _json_list(tags: list):
    kinds = {type(t) for t in tags}
    if len(kinds) > 1:
        raise not_modelled("value", "a JSON list of several NBT types (NbtOps' heterogeneous list)")
    kind = next(iter(kinds), None)
    return _ARRAYS[kind](tags) if kind in _ARRAYS else List(tags)


# the components whose codec reads any compound, or its SNBT text (CustomData.CODEC)
COMPOUND_COMPONENTS = frozenset("minecraft:" + n for n in (
    "custom_data", "entity_data", "bucket_entity_data", "block_entity_data"))


def component_tag(name: str, value):
    """A component's JSON value (``set_components``, a recipe's result, an item predicate) as
    NBT: a compound component as its codec reads it (:func:`snbt_or_tag`), another by
    :func:`to_tag`."""
    return snbt_or_tag(value) if name in COMPOUND_COMPONENTS else to_tag(value)


def snbt_or_tag(value) -> Compound:
    """A compound given as an SNBT string, or as an object (:func:`json_nbt`: CompoundTag.CODEC
    converts the JSON)."""
    if isinstance(value, dict):
        return json_nbt(value)
    try:
        return parse_compound(Reader(str(value), Loc("<loot>", 1, 1), (1, 21, 4)))
    except ParseError as error:
        raise CommandFailure("dpemu.loot.invalid", f"the SNBT '{value}'", error.message, report=True) from None


