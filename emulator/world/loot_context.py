"""What a loot roll reads and the values it computes: the :class:`LootContext`, number providers,
int ranges, and JSON values made NBT. Shared by :mod:`emulator.world.loot` (tables, functions)
and :mod:`emulator.world.loot_conditions`.

Sources (decompiled 1.21): world/level/storage/loot/LootContext.java, providers/number/*.java
(ConstantValue, UniformGenerator, BinomialDistributionGenerator, ScoreboardValue, StorageValue),
IntRange.java.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from typing import Any, Callable

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Byte, Compound, Double, Int, List, String
from mcfunction_parser.nbt_path import nbt_path
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import compound as parse_compound
from emulator.world import nbt_ops
from emulator.world.errors import CommandFailure
from emulator.world.items import ItemStack
from emulator.world.nbt_ops import copy_tag

MAX_DEPTH = 64  # a reference chain deeper than this is a cycle (LootContext.hasVisitedElement)

def namespaced(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


def not_modelled(kind: str, name: str) -> CommandFailure:
    return CommandFailure("dpemu.loot.not_modelled", kind, name, report=True)


@dataclass
class LootContext:
    random: random.Random
    resources: Any  # emulator.world.resources.Resources
    version: tuple[int, int, int] = (1, 21, 11)  # the release (item NBT and text forms follow it)
    this: Any = None
    killer: Any = None
    tool: ItemStack | None = None
    origin: tuple[float, float, float] | None = None
    block_entity: Compound | None = None
    block_state: Any = None  # the mined block (emulator.world.blocks.BlockState)
    explosion_radius: float | None = None
    daytime: int = 0
    scores: Callable[[str, str], int | None] = lambda holder, objective: None
    # a text component resolved for an entity (ComponentUtils.updateForEntity); None: kept as written
    resolve_text: Callable[[Any, Any], Any] | None = None
    storage: Callable[[str], Compound] = lambda storage_id: Compound()
    depth: int = 0
    visited: list = field(default_factory=list)

    def entity(self, which: str):
        """LootContext.EntityTarget: this, attacker/killer, direct_attacker, attacking_player/killer_player."""
        if which == "this":
            return self.this
        if which in ("killer", "attacker", "direct_killer", "direct_attacker"):
            return self.killer
        if which in ("killer_player", "attacking_player", "last_damage_player"):
            return self.killer if self.killer is not None and self.killer.is_player else None
        raise not_modelled("entity target", which)

    def visit(self, key: str) -> None:
        if key in self.visited or len(self.visited) >= MAX_DEPTH:
            raise CommandFailure("dpemu.loot.not_modelled", "a reference cycle", key, report=True)
        self.visited.append(key)


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
    value = None if holder is None else ctx.scores(holder, provider.get("score"))
    return 0.0 if value is None else value * float(provider.get("scale", 1.0))


def _storage_values(provider: dict, ctx: LootContext) -> list:
    path = path_of(provider.get("path", ""))
    try:
        return nbt_ops.get(ctx.storage(namespaced(provider.get("storage", ""))), path)
    except CommandFailure:
        return []


def path_of(text: str):
    try:
        return nbtpath_of(Reader(text, Loc("<loot>", 1, 1), (1, 21, 0)))
    except ParseError as error:
        raise CommandFailure("dpemu.loot.not_modelled", "an NBT path", f"{text} ({error.message})", report=True) from None


def int_range(value, ctx: LootContext) -> tuple[int | None, int | None]:
    """IntRange: a number, or {min, max} of number providers."""
    if isinstance(value, (int, float)):
        return int(value), int(value)
    lo, hi = value.get("min"), value.get("max")
    return (None if lo is None else integer(lo, ctx)), (None if hi is None else integer(hi, ctx))


# ---------------------------------------------------------------------- JSON to NBT
def to_tag(value):
    """A JSON value as NBT (ints Int, decimals Double, booleans Byte)."""
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
    if isinstance(value, (Compound, List)):
        return copy_tag(value)
    raise not_modelled("value", repr(value))


def snbt_or_tag(value) -> Compound:
    """A compound given as an SNBT string (or, from 1.21.5, as an object)."""
    if isinstance(value, dict):
        return to_tag(value)
    try:
        return parse_compound(Reader(str(value), Loc("<loot>", 1, 1), (1, 21, 4)))
    except ParseError as error:
        raise CommandFailure("dpemu.loot.not_modelled", "an SNBT tag", f"{value} ({error.message})", report=True) from None


