"""Biomes where the world can know them: the cells ``fillbiome`` set. The emulator generates no
terrain, so a biome it did not set is the generator's and is not modelled (Unmodelled), never a
silent yes or no.

- ``BiomeCells``: per level, quart cell (x >> 2, y >> 2, z >> 2) -> biome id, as fillbiome writes
  them into the chunks' noise biomes.
- ``fill(state, dimension, start, end, biome, keep=None) -> int``: FillBiomeCommand.fill: the
  corners quantized to their cells' corners, the box's volume checked against the modification
  limit, each cell whose corner lies in the box (and whose biome ``keep`` accepts, for
  ``replace FILTER``) set; the count of cells set.
- ``biome_at(state, dimension, pos) -> str``: Level.getBiome (BiomeManager.getBiome): the block's
  position shifted by 2 and zoomed with the world seed's fiddled distances to one of the eight
  cells around it (y clamped to the level's cells, ChunkAccess.getNoiseBiome); what that cell holds.

Sources (decompiled 1.21): server/commands/FillBiomeCommand.java (quantize, makeResolver, fill),
world/level/biome/BiomeManager.java (obfuscateSeed: SHA-256 of the seed's eight little-endian
bytes, the first eight bytes of the digest read little-endian; getBiome; getFiddledDistance;
getFiddle), util/LinearCongruentialGenerator.java, world/level/chunk/ChunkAccess.getNoiseBiome,
gametest/framework/GameTestServer (a test server's world seed: 0), data/minecraft/dimension_type
(the vanilla levels' heights).
"""
from __future__ import annotations

import hashlib
import math

from emulator.world.blocks import MODIFICATION_LIMIT
from emulator.world.errors import CommandFailure, Unmodelled

_MASK = (1 << 64) - 1
# the vanilla levels' cells in y (min_y / 4, (min_y + height) / 4 - 1): DimensionType min_y and height
_QUART_Y = {"minecraft:overworld": (-16, 79), "minecraft:the_nether": (0, 63), "minecraft:the_end": (0, 63)}
NOT_SET = "the emulator generates no terrain: a biome fillbiome did not set is the generator's"


def _signed(value: int) -> int:
    value &= _MASK
    return value - (1 << 64) if value >> 63 else value


def zoom_seed(seed: int) -> int:
    """BiomeManager.obfuscateSeed: Hashing.sha256().hashLong(seed).asLong()."""
    digest = hashlib.sha256((seed & _MASK).to_bytes(8, "little")).digest()
    return _signed(int.from_bytes(digest[:8], "little"))


def _lcg(value: int, add: int) -> int:
    """LinearCongruentialGenerator.next (long arithmetic)."""
    return _signed(value * (value * 6364136223846793005 + 1442695040888963407) + add)


def _fiddle(value: int) -> float:
    return ((value >> 24) % 1024 / 1024.0 - 0.5) * 0.9


def _fiddled_distance(seed: int, x: int, y: int, z: int, dx: float, dy: float, dz: float) -> float:
    value = seed
    for coordinate in (x, y, z, x, y, z):
        value = _lcg(value, coordinate)
    fx = _fiddle(value)
    value = _lcg(value, seed)
    fy = _fiddle(value)
    value = _lcg(value, seed)
    fz = _fiddle(value)
    return (dz + fz) ** 2 + (dy + fy) ** 2 + (dx + fx) ** 2


def zoomed_cell(seed: int, pos) -> tuple[int, int, int]:
    """The cell BiomeManager.getBiome reads for block ``pos`` (``seed``: the zoom seed)."""
    i, j, k = (p - 2 for p in pos)
    base = (i >> 2, j >> 2, k >> 2)
    fractions = ((i & 3) / 4.0, (j & 3) / 4.0, (k & 3) / 4.0)
    best, best_distance = 0, math.inf
    for corner in range(8):
        steps = ((corner >> 2) & 1, (corner >> 1) & 1, corner & 1)
        cell = tuple(b + s for b, s in zip(base, steps))
        offsets = tuple(f - s for f, s in zip(fractions, steps))
        distance = _fiddled_distance(seed, *cell, *offsets)
        if best_distance > distance:
            best, best_distance = corner, distance
    return tuple(b + ((best >> shift) & 1) for b, shift in zip(base, (2, 1, 0)))


class BiomeCells:
    """The cells fillbiome set, per level."""

    def __init__(self) -> None:
        self.levels: dict[str, dict[tuple[int, int, int], str]] = {}

    def cells(self, dimension: str) -> dict[tuple[int, int, int], str]:
        return self.levels.setdefault(dimension, {})


def _quantize(pos) -> tuple[int, int, int]:
    return tuple((p >> 2) << 2 for p in pos)


def fill(state, dimension: str, start, end, biome: str, keep=None) -> int:
    """FillBiomeCommand.fill (``keep(biome_id) -> bool``: the ``replace`` filter)."""
    a, b = _quantize(start), _quantize(end)
    lo, hi = tuple(map(min, a, b)), tuple(map(max, a, b))
    volume = math.prod(h - l + 1 for l, h in zip(lo, hi))
    if volume > MODIFICATION_LIMIT:
        raise CommandFailure("commands.fillbiome.toobig", MODIFICATION_LIMIT, volume)
    cells = state.biomes.cells(dimension)
    chosen = [(x, y, z) for x in range(lo[0] >> 2, (hi[0] >> 2) + 1) for y in range(lo[1] >> 2, (hi[1] >> 2) + 1)
              for z in range(lo[2] >> 2, (hi[2] >> 2) + 1)]
    if keep is not None:
        unknown = [cell for cell in chosen if cell not in cells]
        if unknown:
            raise Unmodelled(f"fillbiome replace over cells whose biome is the generator's ({NOT_SET})")
        chosen = [cell for cell in chosen if keep(cells[cell])]
    for cell in chosen:
        cells[cell] = biome
    return len(chosen)


def namespaced(biome: str) -> str:
    return biome if ":" in biome else "minecraft:" + biome


def matches(resources, wanted: str, found: str) -> bool:
    """ResourceOrTagArgument's test: ``wanted`` an id, or ``#tag`` of the biome tags."""
    if wanted.startswith("#"):
        return resources.in_tag("worldgen/biome", namespaced(wanted[1:]), found)
    return namespaced(wanted) == found


def biome_at(state, dimension: str, pos) -> str:
    """Level.getBiome at block ``pos``: the biome fillbiome set in the cell it zooms to."""
    x, y, z = zoomed_cell(zoom_seed(state.random_sequences.world_seed), pos)
    low, high = _QUART_Y.get(dimension, (y, y))
    found = state.biomes.cells(dimension).get((x, min(max(y, low), high), z))
    if found is None:
        raise Unmodelled(f"the biome at {' '.join(map(str, pos))} ({NOT_SET})")
    return found
