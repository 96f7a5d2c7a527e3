"""Inline loot tables and item modifiers (1.20.5+) keep the NBT types they are written with.

Sources (decompiled 1.21): commands/arguments/ResourceOrIdArgument.java (parseInline: the SNBT tag
is decoded with ``codec.parse(NbtOps, tag)``, nothing converted), world/item/component/CustomData.java
(CODEC: CompoundTag.CODEC, which takes the compound as it is from NbtOps), DataFixerUpper
JsonOps.convertTo (a file's JSON number becomes the narrowest NBT number: 3 is 3b).
"""
import json

import pytest

from emulator import Emulator
from mcfunction_parser.nbt import to_snbt
from tests.conftest import write_pack

ENTRY = '{type:"item",name:"cod",functions:[{function:"set_custom_data",tag:{v:3,w:[1,2],s:2s}}]}'
FILES = {
    "demo/loot_table/file.json": json.dumps({"pools": [{"rolls": 1, "entries": [
        {"type": "item", "name": "cod", "functions": [{"function": "set_custom_data", "tag": {"v": 3}}]}]}]}),
    "demo/function/setup.mcfunction": "setblock 0 0 0 minecraft:chest\n",
    "demo/function/inline.mcfunction":
        f"loot replace block 0 0 0 container.0 loot {{pools:[{{rolls:1,entries:[{ENTRY}]}}]}}\n"
        "data modify storage t:r inline set from block 0 0 0 Items[0].components.\"minecraft:custom_data\"\n",
    "demo/function/file.mcfunction":
        "loot replace block 0 0 0 container.1 loot demo:file\n"
        "data modify storage t:r file set from block 0 0 0 Items[{Slot:1b}].components.\"minecraft:custom_data\"\n",
    "demo/function/modify.mcfunction":
        "item replace block 0 0 0 container.2 with minecraft:stick\n"
        "item modify block 0 0 0 container.2 {function:\"set_custom_data\",tag:{v:3}}\n"
        "data modify storage t:r modified set from block 0 0 0 Items[{Slot:2b}].components.\"minecraft:custom_data\"\n",
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_inline_table_keeps_its_types_a_file_reads_json(tmp_path, backend):
    emu = Emulator(backend=backend)
    emu.load([write_pack(tmp_path / "pack", FILES)])
    for name in ("setup", "inline", "file", "modify"):
        emu.call(f"demo:{name}")
    assert not [d for d in emu.diagnostics if d.severity == "error"]
    assert to_snbt(emu.state.storage["t:r"]) == '{file:{v:3b},inline:{s:2s,v:3,w:[1,2]},modified:{v:3}}'
