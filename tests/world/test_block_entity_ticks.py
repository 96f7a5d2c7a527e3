"""What block entities do each tick, as far as modelled (emulator.world.block_entity_ticks), on both
backends. Sources (decompiled 1.21): TheEndGatewayBlockEntity.portalTick, HopperBlockEntity.
pushItemsTick / tryMoveItems, AbstractFurnaceBlockEntity.serverTick, BrewingStandBlockEntity.
serverTick, BaseSpawner.serverTick / isNearPlayer, BlockInput.place (loadWithComponents)."""
import pytest

from mcfunction_parser.nbt import Byte, Long, Short
from tests.world.world_emulator import emulator

SETUP = "\n".join([
    "setblock 0 0 0 end_gateway",
    "setblock 2 0 0 hopper",
    "setblock 4 0 0 furnace{CookTime:7s,CookTimeTotal:200s}",
    "setblock 6 0 0 brewing_stand{Items:[{Slot:4b,id:'minecraft:blaze_powder',count:2},{Slot:1b,id:'minecraft:potion',count:1}]}",
    "setblock 8 0 0 spawner",
    "setblock 40 0 0 spawner",
])


def _entity(emu, x):
    return emu.state.blocks.entity((x, 0, 0))


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_block_entities_tick_their_counters(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:setup2": SETUP})
    emu.call("t:setup2")
    emu.add_player("Alex", (8.5, 1.0, 12.0))  # 11 blocks from the first spawner's centre, 33 from the other
    assert _entity(emu, 2)["TransferCooldown"] == -1
    emu.tick(3)
    assert _entity(emu, 0)["Age"] == Long(3)  # portalTick: ++age every tick
    assert _entity(emu, 2)["TransferCooldown"] == 0  # -1, then -2: not on cooldown, set to 0; nothing to move
    assert _entity(emu, 4)["CookTime"] == Short(1)  # unlit, no fuel: 7 -> 5 -> 3 -> 1
    brewing = _entity(emu, 6)
    assert brewing["Fuel"] == Byte(20) and [int(i["count"]) for i in brewing["Items"] if int(i["Slot"]) == 4] == [1]
    assert dict(emu.state.blocks.get((6, 0, 0)).properties)["has_bottle_1"] == "true"
    assert _entity(emu, 8)["Delay"] == Short(17) and _entity(emu, 40)["Delay"] == Short(20)
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_a_block_placed_with_nbt_loads_only_that_nbt(tmp_path):
    # BlockInput.place: loadWithComponents(the written NBT): a spawner's Delay is read as 0 and its one
    # potential spawn is the SpawnData; a hopper's TransferCooldown 0 (getInt of nothing)
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 spawner{SpawnData:{entity:{id:'minecraft:bat'}}}\n"
                                                 "setblock 2 0 0 hopper{Items:[]}"})
    emu.call("t:p")
    spawner = _entity(emu, 0)
    assert spawner["Delay"] == Short(0) and spawner["MinSpawnDelay"] == Short(200)
    assert [str(p["data"]["entity"]["id"]) for p in spawner["SpawnPotentials"]] == ["minecraft:bat"]
    assert _entity(emu, 2)["TransferCooldown"] == 0


def test_work_the_emulator_does_not_model_is_reported(tmp_path):
    emu = emulator(tmp_path, "python", {"t:w": "\n".join([
        "setblock 0 -1 0 crafter",
        "setblock 0 0 0 hopper{Items:[{Slot:0b,id:'minecraft:stone',count:1}]}",
        "setblock 2 0 0 furnace{Items:[{Slot:0b,id:'minecraft:iron_ore',count:1},{Slot:1b,id:'minecraft:coal',count:1}]}",
        "setblock 4 0 0 spawner{Delay:1s,SpawnData:{entity:{id:'minecraft:bat'}}}"])})
    emu.call("t:w")
    emu.add_player("Alex", (4.5, 1.0, 0.5))
    emu.tick(2)
    reported = " | ".join(d.message for d in emu.diagnostics if d.unmodelled)
    for what in ("a hopper pushing items into minecraft:crafter", "a spawner spawning working",
                 "minecraft:furnace cooking minecraft:iron_ore: the game's own smelting recipes are not known"):
        assert what in reported, reported
