"""The server's levels (dimensions): which exist, their order, their coordinate scale and build height.

``Levels(custom=())``: the three vanilla dimensions, then the packs' own (``data/<ns>/dimension/``),
each with a number (``id(name)``, ``names[i]``) that the entity table stores per entity (``EI_DIM``)
and the VM's contexts carry (``CI_DIM``). The numbers follow the server's level order
(MinecraftServer.getAllLevels: the overworld, the nether, the end, then the others; the game
orders the packs' dimensions by identity hashes, here they come in id order), which is the order
a selector that is not limited to one level visits them in.
``Levels.from_packs(dimensions, dimension_types)``: the packs' dimension files (id -> JSON) and
dimension type files, for each dimension its type's ``coordinate_scale``.
``default_clock(name)``: the level's dimension type's default clock (26.1) and that type's name.
``build_height(name, version)``: the level's build height, from its type's ``min_y`` and ``height``.
``level_id(name)``: DimensionArgument.getDimension: an unknown dimension fails the command
("Unknown dimension"). ``teleportation_scale(a, b)``: DimensionType.getTeleportationScale, what
``execute in`` multiplies x and z by (CommandSourceStack.withLevel).
"""
from __future__ import annotations

from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.pack.clocks import DEFAULT_CLOCKS

OVERWORLD = "minecraft:overworld"
VANILLA = (OVERWORLD, "minecraft:the_nether", "minecraft:the_end")
# DimensionType.coordinateScale of the vanilla dimension types (data/minecraft/dimension_type)
VANILLA_TYPE_SCALE = {"minecraft:overworld": 1.0, "minecraft:overworld_caves": 1.0, "minecraft:the_nether": 8.0,
                      "minecraft:the_end": 1.0}
# their (min_y, height) from 1.18 (BuiltinDimensionTypes); before it every vanilla level was 0 – 255
VANILLA_TYPE_HEIGHT = {"minecraft:overworld": (-64, 384), "minecraft:overworld_caves": (-64, 384),
                       "minecraft:the_nether": (0, 256), "minecraft:the_end": (0, 256)}


def _id(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


class Levels:
    def __init__(self, custom: dict[str, float] | None = None, clocks: dict[str, tuple] | None = None,
                 heights: dict[str, tuple | None] | None = None) -> None:
        """``custom``: the packs' dimensions (id -> coordinate scale); a pack may redefine a vanilla
        one. ``clocks``: theirs -> (default clock or None, dimension type name). ``heights``: theirs
        -> their type's (min_y, height), None when it does not say."""
        custom = custom or {}
        self.names: list[str] = list(VANILLA) + sorted(n for n in custom if n not in VANILLA)
        self.ids = {name: i for i, name in enumerate(self.names)}
        self.scales = [custom.get(n, VANILLA_TYPE_SCALE.get(n, 1.0)) for n in self.names]
        self.clocks = {name: (DEFAULT_CLOCKS.get(name), name) for name in VANILLA} | (clocks or {})
        self.heights = {name: VANILLA_TYPE_HEIGHT[name] for name in VANILLA} | (heights or {})

    @classmethod
    def from_packs(cls, dimensions: dict, dimension_types: dict) -> "Levels":
        """The dimension files (``type``: a dimension type id or an inline type) with their scales
        and default clocks (a type's ``default_clock``)."""
        custom, clocks, heights = {}, {}, {}
        for name, value in dimensions.items():
            kind = value.get("type") if isinstance(value, dict) else None
            type_name = _id(kind) if isinstance(kind, str) else "[unregistered]"  # Holder.getRegisteredName
            if isinstance(kind, str):
                kind = dimension_types.get(_id(kind), _id(kind))
            if isinstance(kind, dict):
                scale = kind.get("coordinate_scale", 1.0)
                clock = kind.get("default_clock")
                clocks[name] = (_id(clock) if isinstance(clock, str) else None, type_name)
                low, height = kind.get("min_y"), kind.get("height")
                heights[name] = (low, height) if type(low) is int and type(height) is int else None
            else:
                scale = VANILLA_TYPE_SCALE.get(kind, 1.0)
                clocks[name] = (DEFAULT_CLOCKS.get(kind), type_name)
                heights[name] = VANILLA_TYPE_HEIGHT.get(kind)
            custom[name] = float(scale) if isinstance(scale, (int, float)) else 1.0
        return cls(custom, clocks, heights)

    def build_height(self, name: str, version) -> tuple[int, int]:
        """Level ``name``'s build height as (lowest y, highest y + 1); not modelled when its type does
        not say (a vanilla type name dpemu does not know, an inline type without ``min_y`` and ``height``)."""
        found = self.heights.get(name)
        if found is None:
            raise Unmodelled(f"the build height of {name} (its dimension type's min_y and height)")
        if tuple(version) < (1, 18, 0) and name in VANILLA:
            return 0, 256
        return found[0], found[0] + found[1]

    def default_clock(self, name: str) -> tuple[str | None, str]:
        """DimensionType.defaultClock of level ``name``'s type, and the type's name."""
        return self.clocks.get(name, (None, name))

    def level_id(self, name: str) -> int:
        index = self.ids.get(name)
        if index is None:
            raise CommandFailure("argument.dimension.invalid", name)
        return index

    def teleportation_scale(self, origin: str, destination: str) -> float:
        return self.scales[self.level_id(origin)] / self.scales[self.level_id(destination)]
