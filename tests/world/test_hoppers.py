"""Hoppers moving items (emulator.world.hoppers), on both backends. Sources (decompiled 1.21):
HopperBlockEntity.pushItemsTick / tryMoveItems / ejectItems / suckInItems / addItem /
tryMoveInItem / canMergeItems / getItemsAtAndAbove, Hopper.SUCK_AABB, ChestBlock.getContainer,
AbstractFurnaceBlockEntity.getSlotsForFace / canPlaceItem / canTakeItemThroughFace,
ShulkerBoxBlockEntity.canPlaceItemThroughFace."""
import pytest

from tests.world.world_emulator import emulator


def _items(emu, pos):
    nbt = emu.state.blocks.entity(pos)
    return {int(i["Slot"]): (str(i["id"]).removeprefix("minecraft:"), int(i["count"])) for i in nbt.get("Items") or []}


def _cooldown(emu, pos):
    return int(emu.state.blocks.entity(pos)["TransferCooldown"])


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_hopper_pushes_one_item_every_eight_ticks(tmp_path, backend):
    # pushItemsTick: the cooldown (0 when placed with NBT) runs out on the first tick, one item goes
    # into the chest below (ejectItems), and the next moves 8 ticks later (setCooldown(8))
    emu = emulator(tmp_path, backend, {"t:p": "setblock 0 0 0 chest\n"
                                              "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:stone',count:3}]}"})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 0, 0)) == {0: ("stone", 1)} and _cooldown(emu, (0, 1, 0)) == 8
    emu.tick(7)
    assert _items(emu, (0, 0, 0)) == {0: ("stone", 1)}
    emu.tick(1)
    assert _items(emu, (0, 0, 0)) == {0: ("stone", 2)} and _items(emu, (0, 1, 0)) == {0: ("stone", 1)}
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_a_hopper_pulls_from_the_container_above_and_pushes_on(tmp_path):
    # suckInItems: one item from the first non-empty slot of the barrel above; in the same tick the
    # hopper first pushes what it holds (tryMoveItems: eject, then suck)
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 2 0 barrel{Items:[{Slot:3b,id:'minecraft:dirt',count:2}]}",
        "setblock 0 1 0 hopper{Items:[]}",
        "setblock 0 0 0 chest"])})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 2, 0)) == {3: ("dirt", 1)} and _items(emu, (0, 1, 0)) == {0: ("dirt", 1)}
    assert _items(emu, (0, 0, 0)) == {}
    emu.tick(8)
    assert _items(emu, (0, 0, 0)) == {0: ("dirt", 1)} and _items(emu, (0, 1, 0)) == {0: ("dirt", 1)}
    assert _items(emu, (0, 2, 0)) == {}


def test_a_locked_hopper_moves_nothing(tmp_path):
    # tryMoveItems: nothing while the state's ENABLED is false (a redstone signal)
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 chest\n"
                                               "setblock 0 1 0 hopper[enabled=false]{Items:[{Slot:0b,id:'minecraft:stone',count:3}]}"})
    emu.call("t:p")
    emu.tick(20)
    assert _items(emu, (0, 0, 0)) == {} and _items(emu, (0, 1, 0)) == {0: ("stone", 3)}
    assert emu.state.blocks.entity((0, 1, 0))["TransferCooldown"] == 0


def test_stacks_merge_only_with_the_same_components_and_up_to_their_max(tmp_path):
    # tryMoveInItem / canMergeItems: onto the same item with the same components below its max stack
    # size (16 for ender pearls), else the next slot
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 chest{Items:[{Slot:0b,id:'minecraft:ender_pearl',count:16},"
        "{Slot:1b,id:'minecraft:ender_pearl',count:3,components:{'minecraft:custom_data':{a:1b}}},"
        "{Slot:3b,id:'minecraft:ender_pearl',count:15}]}",
        "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:ender_pearl',count:2}]}"])})
    emu.call("t:p")
    emu.tick(9)
    assert _items(emu, (0, 0, 0))[2] == ("ender_pearl", 2) and _items(emu, (0, 0, 0))[3] == ("ender_pearl", 15)


def test_a_hopper_fills_a_double_chest_right_half_first(tmp_path):
    # ChestBlock.getContainer: the halves joined (DoubleBlockCombiner), the type=right half's slots first
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 chest[facing=north,type=left]",
        "setblock 1 0 0 chest[facing=north,type=right]",
        "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:stone',count:1}]}"])})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (1, 0, 0)) == {0: ("stone", 1)} and _items(emu, (0, 0, 0)) == {}


def test_a_furnace_takes_items_by_face(tmp_path):
    # AbstractFurnaceBlockEntity.getSlotsForFace: from above the input (slot 0), from a side the fuel
    # (slot 1: canPlaceItem takes fuels and a bucket), from below the output (slots 2, then 1)
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 1 0 furnace{Items:[{Slot:2b,id:'minecraft:iron_ingot',count:2}]}",
        "setblock 0 2 0 hopper{Items:[{Slot:0b,id:'minecraft:iron_ore',count:1}]}",
        "setblock 1 1 0 hopper[facing=west]{Items:[{Slot:1b,id:'minecraft:coal',count:1}]}",
        "setblock 0 0 0 hopper{Items:[]}"])})
    emu.call("t:p")
    emu.tick(1)
    furnace = _items(emu, (0, 1, 0))
    assert furnace[0] == ("iron_ore", 1) and furnace[1] == ("coal", 1)
    assert _items(emu, (1, 1, 0)) == {}
    assert _items(emu, (0, 0, 0)) == {0: ("iron_ingot", 1)}


def test_item_entities_over_a_hopper_are_taken_in(tmp_path):
    # getItemsAtAndAbove (SUCK_AABB: from 11/16 up to the top of the block above) and addItem(Container,
    # ItemEntity): what fits goes in, the entity keeps the rest or is discarded; one far off stays
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 hopper{Items:[{Slot:0b,id:'minecraft:stone',count:60},{Slot:1b,id:'minecraft:dirt',count:64},"
        "{Slot:2b,id:'minecraft:dirt',count:64},{Slot:3b,id:'minecraft:dirt',count:64}]}",
        "setblock 0 -1 0 stone",
        "summon item 0.5 1.2 0.5 {NoGravity:1b,Item:{id:'minecraft:stone',count:10}}",
        "summon item 0.5 2.5 0.5 {NoGravity:1b,Item:{id:'minecraft:stone',count:1}}"])})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 0, 0))[0] == ("stone", 64) and _items(emu, (0, 0, 0))[4] == ("stone", 6)
    assert [int(e.data["Item"]["count"]) for e in emu.state.entities.entities if e.type == "minecraft:item"] == [1]


def test_a_full_cube_above_keeps_item_entities_out(tmp_path):
    # suckInItems: a block above whose collision shape is a full cube blocks the item entities
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 hopper\nsetblock 0 1 0 stone\n"
                                               "summon item 0.5 0.8 0.5 {NoGravity:1b,Item:{id:'minecraft:dirt',count:1}}"})
    emu.call("t:p")
    emu.tick(2)
    assert _items(emu, (0, 0, 0)) == {}


def test_a_hopper_filling_an_empty_hopper_delays_it(tmp_path):
    # tryMoveInItem: an empty hopper that has not ticked yet this tick gets a cooldown of 8 (its own tick
    # then counts it to 7), one that has already ticked 7: both move again on the same tick
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 hopper{Items:[]}",
        "setblock 1 0 0 hopper[facing=west]{Items:[{Slot:0b,id:'minecraft:stone',count:1}]}",
        "setblock 5 0 0 hopper[facing=east]{Items:[{Slot:0b,id:'minecraft:stone',count:1}]}",
        "setblock 6 0 0 hopper{Items:[]}"])})
    emu.call("t:p")
    emu.tick(1)  # the block entities tick in the order they were made
    assert _cooldown(emu, (0, 0, 0)) == 7 and _cooldown(emu, (6, 0, 0)) == 7


def test_shulker_boxes_refuse_shulker_boxes(tmp_path):
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 red_shulker_box\n"
                                               "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:shulker_box',count:1}]}"})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 0, 0)) == {} and _items(emu, (0, 1, 0)) == {0: ("shulker_box", 1)}


def test_containers_whose_rules_are_not_modelled_are_reported(tmp_path):
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 decorated_pot\n"
                                               "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:stone',count:1}]}"})
    emu.call("t:p")
    emu.tick(1)
    assert any("a hopper pushing items into minecraft:decorated_pot" in d.message for d in emu.diagnostics
               if d.unmodelled)


def _level(emu, pos):
    return dict(emu.state.blocks.get(pos).properties)["level"]


def test_a_hopper_fills_a_composter_from_above(tmp_path):
    # ComposterBlock.InputContainer: from above, one compostable a move; an empty composter always rises
    # (addItem: level 0 with a chance over 0); a cake's chance is 1; a stone does not compost
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 composter",
        "setblock 0 1 0 hopper{Items:[{Slot:0b,id:'minecraft:stone',count:1},{Slot:1b,id:'minecraft:cake',count:8}]}"])})
    emu.call("t:p")
    emu.tick(1)
    assert _level(emu, (0, 0, 0)) == "1" and _items(emu, (0, 1, 0)) == {0: ("stone", 1), 1: ("cake", 7)}
    emu.tick(8 * 5)
    assert _level(emu, (0, 0, 0)) == "6"
    emu.tick(8)
    assert _level(emu, (0, 0, 0)) == "7"  # full: no slot takes the next cake (EmptyContainer)
    emu.tick(19)
    assert _level(emu, (0, 0, 0)) == "7" and _items(emu, (0, 1, 0))[1] == ("cake", 1)
    emu.tick(1)
    assert _level(emu, (0, 0, 0)) == "8"  # ComposterBlock.tick, 20 ticks after reaching 7
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_a_hopper_takes_the_bone_meal_of_a_ready_composter(tmp_path):
    # ComposterBlock.OutputContainer: from below, one bone meal, and the composter is empty again
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 1 0 composter[level=8]\nsetblock 0 0 0 hopper{Items:[]}\n"
                                               "setblock 5 1 0 composter[level=5]\nsetblock 5 0 0 hopper{Items:[]}"})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 0, 0)) == {0: ("bone_meal", 1)} and _level(emu, (0, 1, 0)) == "0"
    assert _items(emu, (5, 0, 0)) == {} and _level(emu, (5, 1, 0)) == "5"


def test_a_hopper_minecart_that_would_pull_items_is_reported(tmp_path):
    emu = emulator(tmp_path, "python", {"t:p": "summon hopper_minecart 0.5 0 0.5 {NoGravity:1b}\n"
                                               "summon item 0.5 0.2 0.5 {NoGravity:1b,Item:{id:'minecraft:stone',count:1}}"})
    emu.call("t:p")
    emu.tick(1)
    assert any("a hopper minecart pulling items" in d.message for d in emu.diagnostics if d.unmodelled)


def test_farmland_above_lets_item_entities_through(tmp_path):
    # suckInItems: farmland's collision shape is 15/16 high (FarmBlock.SHAPE), no full block: an item
    # resting on it is over the hopper's suck box and is taken in
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 hopper\nsetblock 0 1 0 farmland\n"
                                               "summon item 0.5 1.9375 0.5 {NoGravity:1b,Item:{id:'minecraft:dirt',count:1}}"})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 0, 0)) == {0: ("dirt", 1)}


def test_a_beehive_above_does_not_block_item_entities(tmp_path):
    # suckInItems: a full cube above blocks item entities (here ones inside it) unless it is in
    # #does_not_block_hoppers (#beehives)
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 hopper", "setblock 0 1 0 beehive",
        "summon item 0.5 1.5 0.5 {NoGravity:1b,Item:{id:'minecraft:dirt',count:1}}",
        "setblock 4 0 0 hopper", "setblock 4 1 0 stone",
        "summon item 4.5 1.5 0.5 {NoGravity:1b,Item:{id:'minecraft:dirt',count:1}}"])})
    emu.call("t:p")
    emu.tick(1)
    assert _items(emu, (0, 0, 0)) == {0: ("dirt", 1)} and _items(emu, (4, 0, 0)) == {}
    # the only thing not modelled: the game pushes an item out of the block it is in (ItemEntity.tick)
    assert {d.message for d in emu.diagnostics if d.unmodelled} == {
        "minecraft:item moving: minecraft:item inside a block (pushed out of it)"}
