"""Biomes where the world knows them: the cells ``fillbiome`` set, read by ``execute if biome`` and
the location predicate's ``biomes`` through the game's zoom (BiomeManager.getBiome), on both
backends; a biome the world generated is not modelled."""
from __future__ import annotations

import json

import pytest

from emulator import Emulator
from emulator.world import biomes, predicates
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.loot_context import LootContext
from emulator.world.state import WorldState
from tests.conftest import write_pack

BACKENDS = ["python", "numba"]


def test_the_zoom_matches_the_game_for_known_seeds():
    # BiomeManager.obfuscateSeed (Guava's sha256().hashLong(seed).asLong()) and getBiome's choice
    # among the eight cells around the block, against the same code run on OpenJDK 17 (the seed's
    # SHA-256 from java.security.MessageDigest over its little-endian bytes)
    positions = [(0, 64, 0), (1, 1, 1), (-1, -64, -1), (5, 70, -3), (2, 2, 2), (-13, 100, 29), (3, -61, 7)]
    expected = {
        0: (8794265229978523055, ["0,15,0", "-1,0,0", "-1,-16,-1", "1,17,-2", "0,0,0", "-4,24,6", "0,-16,1"]),
        12345: (293737985876514017, ["-1,16,-1", "0,0,0", "-1,-17,-1", "1,17,-2", "0,0,0", "-4,24,6", "0,-16,1"]),
        -7: (-4631370985026637155, ["0,16,-1", "0,0,0", "-1,-16,0", "1,17,-2", "0,0,0", "-4,24,7", "0,-16,1"]),
    }
    for seed, (zoom, cells) in expected.items():
        assert biomes.zoom_seed(seed) == zoom
        assert [",".join(map(str, biomes.zoomed_cell(zoom, p))) for p in positions] == cells


def test_fillbiome_sets_whole_cells_and_counts_them():
    # FillBiomeCommand.fill: the corners quantized to their cells' corners; each cell whose corner is
    # in the box set; the volume of the quantized box (in blocks) against the modification limit
    state = WorldState()
    assert biomes.fill(state, "minecraft:overworld", (1, 60, 1), (9, 67, 3), "minecraft:desert") == 3 * 2 * 1
    assert state.biomes.cells("minecraft:overworld")[(2, 16, 0)] == "minecraft:desert"
    assert (0, 15, 0) in state.biomes.cells("minecraft:overworld")
    assert biomes.fill(state, "minecraft:overworld", (3, 3, 3), (0, 0, 0), "minecraft:desert") == 1
    with pytest.raises(CommandFailure, match="maximum 32768, specified 35937"):  # 33 x 33 x 33
        biomes.fill(state, "minecraft:overworld", (0, 0, 0), (35, 34, 33), "minecraft:desert")
    # replace: the filter reads each cell's biome; a cell the generator made is not known
    assert biomes.fill(state, "minecraft:overworld", (5, 61, 2), (4, 60, 0), "minecraft:swamp") == 1
    assert biomes.fill(state, "minecraft:overworld", (0, 60, 0), (4, 64, 0), "minecraft:plains",
                       keep=lambda b: b == "minecraft:desert") == 3
    with pytest.raises(Unmodelled, match="generator"):
        biomes.fill(state, "minecraft:overworld", (0, 0, 0), (40, 0, 0), "minecraft:plains", keep=lambda b: True)


def test_a_biome_the_world_generated_is_not_modelled():
    state = WorldState()
    with pytest.raises(Unmodelled, match="generator"):
        biomes.biome_at(state, "minecraft:overworld", (0, 64, 0))
    biomes.fill(state, "minecraft:overworld", (-8, 56, -8), (8, 72, 8), "minecraft:desert")
    assert biomes.biome_at(state, "minecraft:overworld", (0, 64, 0)) == "minecraft:desert"
    # the level's cells end at its build limits: ChunkAccess.getNoiseBiome clamps the cell's y
    biomes.fill(state, "minecraft:overworld", (0, -64, 0), (12, -64, 12), "minecraft:swamp")
    assert biomes.biome_at(state, "minecraft:overworld", (3, -64, 7)) == "minecraft:swamp"
    # a location predicate's biomes (LocationPredicate.matches: level.getBiome(BlockPos.containing))
    check = lambda wanted: predicates.test({"condition": "location_check", "predicate": {  # noqa: E731
        "biomes": wanted}}, LootContext(state, (0.5, 64.2, 0.5)))
    assert check("minecraft:desert") and check(["minecraft:plains", "desert"]) and not check("minecraft:plains")
    with pytest.raises(Unmodelled, match="generator"):
        predicates.test({"condition": "location_check", "predicate": {"biomes": "minecraft:desert"}},
                        LootContext(state, (100.0, 64.0, 100.0)))
    # before 1.20.5 the field is one biome, ``biome``
    state.version = (1, 20, 4)
    assert predicates.test({"condition": "location_check", "predicate": {"biome": "minecraft:desert"}},
                           LootContext(state, (0.5, 64.2, 0.5)))


def _pack(tmp_path):
    biome_tag = {"values": ["minecraft:desert", "minecraft:badlands"]}
    table = {"pools": [{"rolls": 1, "entries": [
        {"type": "minecraft:alternatives", "children": [
            {"type": "minecraft:item", "name": "minecraft:stone", "conditions": [
                {"condition": "minecraft:location_check", "predicate": {"biomes": "#t:dry"}}],
             "functions": [{"function": "minecraft:set_custom_data", "tag": "{biome:'dry'}"}]},
            {"type": "minecraft:item", "name": "minecraft:stone", "functions": [
                {"function": "minecraft:set_custom_data", "tag": "{biome:'other'}"}]}]}]}]}
    return write_pack(tmp_path / "p", {
        "t/tags/worldgen/biome/dry.json": json.dumps(biome_tag),
        "t/loot_table/get_biome.json": json.dumps(table),
        # a library's biome getter: fill the area, read it back through a loot table into storage
        "t/function/setup.mcfunction": "\n".join([
            "scoreboard objectives add o dummy",
            "summon minecraft:item_display 0 64 0 {Tags:['reader']}",
            "execute store result score #cells o run fillbiome -8 56 -8 7 71 7 minecraft:desert",
            "execute store result score #other o run fillbiome 32 56 32 47 71 47 minecraft:plains"]),
        "t/function/read.mcfunction": "\n".join([
            "execute store result score #desert o if biome 0 64 0 minecraft:desert",
            "execute store result score #tagged o if biome 0 64 0 #t:dry",
            "execute store result score #plains o if biome 40 64 40 minecraft:desert",
            "loot replace entity @e[tag=reader,limit=1] contents loot t:get_biome",
            "data modify storage t:out biome set from entity @e[tag=reader,limit=1] item.components.\"minecraft:custom_data\".biome",
            "execute positioned 40 64 40 run loot replace entity @e[tag=reader,limit=1] contents loot t:get_biome",
            "data modify storage t:out far set from entity @e[tag=reader,limit=1] item.components.\"minecraft:custom_data\".biome"]),
        "t/function/unknown.mcfunction": "execute store result score #unknown o if biome 200 64 200 minecraft:desert",
    })


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_pack_reads_the_biomes_it_filled(tmp_path, backend):
    emu = Emulator(backend=backend)
    emu.load([_pack(tmp_path)])
    emu.call("t:setup")
    emu.call("t:read", at=(0.5, 64.0, 0.5))
    assert emu.score("#cells", "o") == 4 * 4 * 4 and emu.score("#other", "o") == 64
    assert (emu.score("#desert", "o"), emu.score("#tagged", "o"), emu.score("#plains", "o")) == (1, 1, 0)
    out = emu.state.storage.get("t:out")
    assert (str(out["biome"]), str(out["far"])) == ("dry", "other")
    assert not emu.diagnostics
    emu.call("t:unknown")
    assert any("generator" in d.message and d.unmodelled for d in emu.diagnostics)
