"""The equipment step of the entity tick (emulator.world.equipment.tick, LivingEntity.tick ->
detectEquipmentUpdates) as a batch of ticks sees it: idle while no slot changed."""
from emulator.world import equipment
from tests.world.world_emulator import emulator


def test_equipment_is_idle_until_a_slot_changes_and_again_once_a_tick_saw_it(tmp_path):
    # a zombie's sword is seen by its next tick (collectEquipmentChanges); until a slot changes,
    # whether by a command or in the NBT, the step changes nothing and quiet ticks may be batched;
    # a change elsewhere in the NBT (its tags) leaves it idle
    emu = emulator(tmp_path, "numba", {
        "t:go": "summon zombie 0.5 5 0.5 {NoAI:1b,Tags:[\"z\"]}\nitem replace entity @e[tag=z] weapon.mainhand with iron_sword",
        "t:swap": "data modify entity @e[tag=z,limit=1] HandItems[0].id set value \"minecraft:golden_sword\"",
        "t:tag": "tag @e[tag=z] add other"})
    emu.call("t:go")
    assert not equipment.tick_is_idle(emu.state)
    emu.tick()
    assert equipment.tick_is_idle(emu.state)
    emu.call("t:tag")
    assert equipment.tick_is_idle(emu.state)
    emu.call("t:swap")
    assert not equipment.tick_is_idle(emu.state)
    emu.tick()
    assert equipment.tick_is_idle(emu.state)
