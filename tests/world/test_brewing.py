"""Brewing stands brewing (emulator.world.brewing), on both backends. Sources (decompiled 1.21):
BrewingStandBlockEntity.serverTick / isBrewable / doBrew / canPlaceItem / getSlotsForFace,
PotionBrewing.addVanillaMixes / hasMix / mix."""
import pytest

from tests.world.world_emulator import emulator

WATER = "{id:'minecraft:potion',count:1,components:{'minecraft:potion_contents':{potion:'minecraft:water'}}}"


def _slots(emu, pos=(0, 0, 0)):
    nbt = emu.state.blocks.entity(pos)
    found = {}
    for i in nbt.get("Items") or []:
        contents = (i.get("components") or {}).get("minecraft:potion_contents")
        found[int(i["Slot"])] = (str(i["id"]).removeprefix("minecraft:"), int(i["count"]),
                                 str(contents["potion"]).removeprefix("minecraft:") if contents else None)
    return found


def _with(slot: int, item: str) -> str:
    return item.replace("{id:", f"{{Slot:{slot}b,id:", 1)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_water_and_nether_wart_brew_awkward_potions_in_400_ticks(tmp_path, backend):
    # serverTick: a blaze powder gives 20 fuel, starting a brew uses one (19) and sets BrewTime 400; at 0
    # doBrew mixes each bottle (PotionBrewing: water + nether wart -> awkward) and uses one ingredient
    items = ",".join([_with(0, WATER), _with(2, WATER), "{Slot:3b,id:'minecraft:nether_wart',count:2}",
                      "{Slot:4b,id:'minecraft:blaze_powder',count:1}"])
    emu = emulator(tmp_path, backend, {"t:p": f"setblock 0 0 0 brewing_stand{{Items:[{items}]}}"})
    emu.call("t:p")
    emu.tick(1)
    nbt = emu.state.blocks.entity((0, 0, 0))
    assert int(nbt["Fuel"]) == 19 and int(nbt["BrewTime"]) == 400 and 4 not in _slots(emu)
    emu.tick(400)
    assert _slots(emu) == {0: ("potion", 1, "awkward"), 2: ("potion", 1, "awkward"), 3: ("nether_wart", 1, None)}
    assert int(nbt["BrewTime"]) == 0
    props = dict(emu.state.blocks.get((0, 0, 0)).properties)
    assert (props["has_bottle_0"], props["has_bottle_1"], props["has_bottle_2"]) == ("true", "false", "true")
    emu.tick(1)  # awkward + nether wart is no mix: nothing starts
    assert int(nbt["BrewTime"]) == 0 and int(nbt["Fuel"]) == 19
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_gunpowder_makes_a_splash_potion_of_the_same_potion(tmp_path):
    # PotionBrewing.mix: a container mix keeps the potion (PotionContents.createItemStack)
    swift = "{id:'minecraft:potion',count:1,components:{'minecraft:potion_contents':{potion:'minecraft:swiftness'}}}"
    items = ",".join([_with(1, swift), "{Slot:3b,id:'minecraft:gunpowder',count:1}"])
    emu = emulator(tmp_path, "python", {"t:p": f"setblock 0 0 0 brewing_stand{{Items:[{items}],Fuel:3b}}"})
    emu.call("t:p")
    emu.tick(401)
    assert _slots(emu) == {1: ("splash_potion", 1, "swiftness")}


def test_taking_the_ingredient_out_stops_the_brew(tmp_path):
    # serverTick: while counting, no ingredient left to brew sets BrewTime to 0
    items = ",".join([_with(0, WATER), "{Slot:3b,id:'minecraft:redstone',count:1}"])
    emu = emulator(tmp_path, "python", {"t:p": f"setblock 0 0 0 brewing_stand{{Items:[{items}],Fuel:3b}}",
                                        "t:take": "item replace block 0 0 0 container.3 with air"})
    emu.call("t:p")
    emu.tick(10)
    assert int(emu.state.blocks.entity((0, 0, 0))["BrewTime"]) == 391
    emu.call("t:take")
    emu.tick(1)
    assert int(emu.state.blocks.entity((0, 0, 0))["BrewTime"]) == 0
    assert _slots(emu) == {0: ("potion", 1, "water")}


def test_a_hopper_feeds_the_ingredient_from_above_and_bottles_from_a_side(tmp_path):
    # BrewingStandBlockEntity.getSlotsForFace: up -> the ingredient slot, sides -> bottles and fuel;
    # canPlaceItem: only an ingredient in slot 3, only blaze powder in slot 4, a bottle into an empty slot
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 brewing_stand",
        "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:stone_bricks',count:1},{Slot:1b,id:'minecraft:sugar',count:1}]}",
        f"setblock 1 0 0 hopper[facing=west]{{Items:[{_with(0, WATER)},{{Slot:1b,id:'minecraft:blaze_powder',count:1}}]}}"])})
    emu.call("t:p")
    emu.tick(1)
    found = _slots(emu)
    assert found[3] == ("sugar", 1, None) and found[0] == ("potion", 1, "water")
    assert _slots(emu, (0, 1, 0)) == {0: ("stone_bricks", 1, None)}
