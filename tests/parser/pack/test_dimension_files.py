"""Dimensions and dimension types as the loader reads them: what the emulator reads of them checked
as the game decodes it (LevelStem.CODEC: a ``type`` that exists and a ``generator``;
DimensionType.DIRECT_CODEC: ``coordinate_scale`` from 1e-5 to 3e7), each problem at its line and
column, the file left out, the rest of the pack loaded."""
from __future__ import annotations

import json

from mcfunction_parser import load_packs
from tests.conftest import write_pack

FLAT = {"type": "minecraft:flat", "settings": {"layers": [], "biome": "minecraft:plains"}}


def test_dimension_problems_at_their_place(tmp_path):
    root = write_pack(tmp_path / "p", {
        "a/dimension/good.json": json.dumps({"type": "a:deep", "generator": FLAT}),
        "a/dimension/vanilla.json": json.dumps({"type": "the_nether", "generator": FLAT}),
        "a/dimension/lost.json": json.dumps({"type": "a:nowhere", "generator": FLAT}),
        "a/dimension/bare.json": json.dumps({"type": "minecraft:overworld"}),
        "a/dimension/inline.json": json.dumps({"type": {"coordinate_scale": 0}, "generator": FLAT}),
        "a/dimension_type/deep.json": json.dumps({"coordinate_scale": 8}),
        "a/dimension_type/huge.json": json.dumps({"coordinate_scale": 1e9})})
    packs = load_packs([root], mc_version="1.21")
    found = sorted((e.path.rsplit("/", 1)[-1], e.col, e.message) for e in packs.errors)
    assert found == [
        ("bare.json", 1, 'dimension a:bare fails to load: a dimension needs "generator": an object with its "type"'),
        ("huge.json", 2, 'dimension type a:huge fails to load: "coordinate_scale" must be a number from 1e-05 to 3e+07'),
        ("inline.json", 11, 'dimension a:inline fails to load: "coordinate_scale" must be a number from 1e-05 to 3e+07'),
        ("lost.json", 10, "dimension a:lost fails to load: unknown dimension type 'a:nowhere'")]
    assert set(packs.dimensions) == {"a:good", "a:vanilla"} and set(packs.dimension_types) == {"a:deep"}
