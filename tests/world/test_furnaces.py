"""Furnaces, smokers and blast furnaces burning and cooking (emulator.world.furnaces), with a pack's
own cooking recipes, on both backends. Sources (decompiled 1.21): AbstractFurnaceBlockEntity.serverTick
/ canBurn / burn / getBurnDuration / getFuel / getTotalCookTime / setItem / setRecipeUsed,
BlastFurnaceBlockEntity.getBurnDuration (half)."""
import json

import pytest

from emulator import Emulator
from tests.world.world_emulator import make_pack

RECIPES = {
    "t:glass": {"type": "minecraft:blasting", "ingredient": {"item": "minecraft:soul_sand"},
                "result": {"id": "minecraft:brown_stained_glass", "components": {"minecraft:custom_data": {"g": 1}}},
                "experience": 1.0, "cookingtime": 30},
    "t:brick": {"type": "minecraft:smelting", "ingredient": {"item": "minecraft:clay_ball"},
                "result": {"id": "minecraft:brick"}, "cookingtime": 5},
}


def _emulator(tmp_path, backend, text, version_format=48):
    root = make_pack(tmp_path / "p", {"t:p": text}, pack_format=version_format)
    for rid, body in RECIPES.items():
        ns, path = rid.split(":")
        file = root / "data" / ns / "recipe" / f"{path}.json"
        file.parent.mkdir(parents=True, exist_ok=True)
        if version_format >= 57:  # 1.21.2 writes an ingredient as the item's id (Ingredient.CODEC)
            body = {**body, "ingredient": body["ingredient"]["item"]}
        file.write_text(json.dumps(body))
    emu = Emulator(backend=backend)
    emu.load(root)
    emu.call("t:p")
    return emu


def _slots(emu, pos):
    nbt = emu.state.blocks.entity(pos)
    return {int(i["Slot"]): (str(i["id"]).removeprefix("minecraft:"), int(i["count"])) for i in nbt.get("Items") or []}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_blast_furnace_cooks_the_packs_recipe(tmp_path, backend):
    # setItem(0): the total cooking time read from the recipe (30); serverTick: a coal burns 800 ticks in a
    # blast furnace (1600 / 2), one cooking step a tick, the result with its components, RecipesUsed counted
    emu = _emulator(tmp_path, backend, "setblock 0 0 0 blast_furnace\n"
                                       "item replace block 0 0 0 container.0 with soul_sand 2\n"
                                       "item replace block 0 0 0 container.1 with coal")
    nbt = emu.state.blocks.entity((0, 0, 0))
    assert int(nbt["CookTimeTotal"]) == 30
    emu.tick(1)
    assert int(nbt["BurnTime"]) == 800 and int(nbt["CookTime"]) == 1 and 1 not in _slots(emu, (0, 0, 0))
    assert dict(emu.state.blocks.get((0, 0, 0)).properties)["lit"] == "true"
    emu.tick(29)
    assert _slots(emu, (0, 0, 0)) == {0: ("soul_sand", 1), 2: ("brown_stained_glass", 1)}
    out = [i for i in nbt["Items"] if int(i["Slot"]) == 2][0]
    assert int(out["components"]["minecraft:custom_data"]["g"]) == 1
    assert int(nbt["CookTime"]) == 0 and int(nbt["RecipesUsed"]["t:glass"]) == 1 and int(nbt["BurnTime"]) == 771  # lit on the first tick, burnt from the next


def test_the_fire_goes_out_and_progress_falls_back(tmp_path):
    # a stick burns 100 ticks (lit on the first, counted down from the second): clay needs 5 each; on the
    # 101st tick the fire is out and the lit state goes false
    emu = _emulator(tmp_path, "python", "setblock 0 0 0 furnace\n"
                                        "item replace block 0 0 0 container.0 with clay_ball 64\n"
                                        "item replace block 0 0 0 container.1 with stick")
    emu.tick(101)
    assert _slots(emu, (0, 0, 0)) == {0: ("clay_ball", 44), 2: ("brick", 20)}
    assert dict(emu.state.blocks.get((0, 0, 0)).properties)["lit"] == "false"
    nbt = emu.state.blocks.entity((0, 0, 0))
    assert int(nbt["BurnTime"]) == 0 and int(nbt["CookTime"]) == 0


def test_a_full_output_stops_the_cooking(tmp_path):
    # canBurn: the output holds another item: no fuel is taken
    emu = _emulator(tmp_path, "python", "setblock 0 0 0 furnace{Items:[{Slot:2b,id:'minecraft:stone',count:1}]}\n"
                                        "item replace block 0 0 0 container.0 with clay_ball\n"
                                        "item replace block 0 0 0 container.1 with coal")
    emu.tick(5)
    assert _slots(emu, (0, 0, 0)) == {0: ("clay_ball", 1), 1: ("coal", 1), 2: ("stone", 1)}


def test_items_written_as_nbt_keep_the_saved_total(tmp_path):
    # data commands load the NBT (no setItem): a total of 0 is never reached, so nothing is cooked
    emu = _emulator(tmp_path, "python", "setblock 0 0 0 furnace{Items:[{Slot:0b,id:'minecraft:clay_ball',count:1},"
                                        "{Slot:1b,id:'minecraft:coal',count:1}]}")
    emu.tick(10)
    nbt = emu.state.blocks.entity((0, 0, 0))
    assert _slots(emu, (0, 0, 0)) == {0: ("clay_ball", 1)} and int(nbt["CookTime"]) == 10


def test_the_keys_are_renamed_from_1_21_4(tmp_path):
    emu = _emulator(tmp_path, "python", "setblock 0 0 0 furnace\n"
                                        "item replace block 0 0 0 container.0 with clay_ball\n"
                                        "item replace block 0 0 0 container.1 with coal", version_format=61)
    emu.tick(5)
    nbt = emu.state.blocks.entity((0, 0, 0))
    assert _slots(emu, (0, 0, 0)) == {2: ("brick", 1)}
    assert int(nbt["lit_time_remaining"]) == 1596 and int(nbt["lit_total_time"]) == 1600


def test_a_furnace_that_cannot_cook_is_idle(tmp_path):
    # serverTick changes nothing while unlit with no room in the output: the ticks can be batched
    from emulator.world import block_entity_ticks
    emu = _emulator(tmp_path, "python", "setblock 0 0 0 furnace{Items:[{Slot:2b,id:'minecraft:stone',count:1}]}\n"
                                        "item replace block 0 0 0 container.0 with clay_ball\n"
                                        "item replace block 0 0 0 container.1 with coal")
    assert block_entity_ticks.tick_is_idle(emu.state)
    items = emu.state.blocks.entity((0, 0, 0))["Items"]
    items[:] = [i for i in items if int(i["Slot"]) != 2]  # the output emptied: now it can cook
    assert not block_entity_ticks.tick_is_idle(emu.state)
