"""One tick of the entities the server moves (emulator.world.motion), read exactly through the API on
both backends. Each test names the decompiled 1.21 source it pins."""
import numpy as np
import pytest

from emulator.testing import discover, run_suite
from emulator.world import motion
from tests.world.world_emulator import emulator

F32 = np.float32
BACKENDS = ["numba", "python"]
STONE_FLOOR = "fill -2 0 -2 2 0 2 stone\n"


def world(tmp_path, backend, setup):
    emu = emulator(tmp_path, backend, {"t:go": STONE_FLOOR + setup})
    emu.call("t:go")
    return emu


def one(emu, type_id):
    [entity] = [e for e in emu.state.entities.entities if e.type == type_id]
    return entity


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_item_on_the_ground_slides_by_its_motion_and_loses_it_to_the_blocks_friction(tmp_path, backend):
    # ItemEntity.tick: on the ground (and moving) it moves, then x and z are scaled by the friction of
    # the block under it (Block.getFriction: 0.6 stone, 0.98 ice) x 0.98F, both floats
    emu = world(tmp_path, backend, (
        "setblock 0 0 2 ice\n"
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:1},OnGround:1b,Motion:[0.1d,0.0d,0.0d]}\n"
        "summon item 0.5 1 2.5 {Item:{id:\"minecraft:dirt\",count:1},OnGround:1b,Motion:[0.1d,0.0d,0.0d]}"))
    emu.tick()
    stone, ice = sorted((e for e in emu.state.entities.entities if e.type == "minecraft:item"), key=lambda e: e.pos[2])
    assert stone.pos == (0.6, 1.0, 0.5) and ice.pos == (0.6, 1.0, 2.5)
    assert stone.motion == (0.1 * float(F32(0.6) * F32(0.98)), 0.0, 0.0)
    assert ice.motion == (0.1 * float(F32(0.98) * F32(0.98)), 0.0, 0.0)
    assert int(stone.data["OnGround"]) == 1


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_item_at_rest_moves_only_every_fourth_tick_of_its_life(tmp_path, backend):
    # ItemEntity.tick: on the ground with no horizontal motion it moves only when (tickCount + id) % 4
    # == 0; between, the gravity piles up in its motion, and the move's landing zeroes it
    # (Block.updateEntityAfterFallOn)
    emu = world(tmp_path, backend, "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:1},OnGround:1b}")
    item = one(emu, "minecraft:item")
    seen = []
    for _ in range(5):
        emu.tick()
        seen.append(item.motion[1])
    assert seen == [-0.04, -0.08, -0.12, 0.0, -0.04]
    assert item.pos == (0.5, 1.0, 0.5)


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_items_age_and_pickup_delay_count_and_it_despawns_at_6000(tmp_path, backend):
    # ItemEntity.tick: pickupDelay counts down unless 32767, age counts up unless -32768, gone at 6000
    emu = world(tmp_path, backend, (
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:1},OnGround:1b,Age:5998s,PickupDelay:3s,Tags:[\"old\"]}\n"
        "summon item 1.5 1 0.5 {Item:{id:\"minecraft:stone\",count:1},OnGround:1b,Age:-32768s,PickupDelay:32767s,Tags:[\"kept\"]}"))
    old, kept = (next(e for e in emu.state.entities.entities if tag in e.tags) for tag in ("old", "kept"))
    emu.tick()
    assert (int(old.data["Age"]), int(old.data["PickupDelay"])) == (5999, 2)
    emu.tick()
    assert not old.alive
    assert (int(kept.data["Age"]), int(kept.data["PickupDelay"])) == (-32768, 32767) and kept.alive


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_item_sliding_into_a_wall_stops_there(tmp_path, backend):
    # Entity.move: a horizontal axis the blocks stop (Shapes.collide) ends at the wall and its motion is 0
    emu = world(tmp_path, backend, (
        "setblock 1 1 0 stone\n"
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:1},OnGround:1b,Motion:[0.5d,0.0d,0.0d]}"))
    item = one(emu, "minecraft:item")
    emu.tick()
    assert item.pos == (1.0 - 0.125, 1.0, 0.5)  # an item is 0.25 wide
    assert item.motion[0] == 0.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_mob_falls_lands_and_takes_fall_damage_and_rests_with_the_games_motion(tmp_path, backend):
    # LivingEntity.travel with no input: gravity 0.08, x 0.98F; LivingEntity.causeFallDamage: from
    # 10.5 blocks the fall distance at the landing is 9.667 (Entity.checkFallDamage adds a move only
    # in the air: the last move is not in it), so ceil(9.667 - 3) = 7 damage, as for players
    emu = world(tmp_path, backend, "summon zombie 0.5 11.5 0.5")
    zombie = one(emu, "minecraft:zombie")
    emu.tick(40)
    assert zombie.pos == (0.5, 1.0, 0.5)
    assert float(zombie.data["Health"]) == 13.0
    assert zombie.motion == (0.0, -0.0784000015258789, 0.0) and int(zombie.data["OnGround"]) == 1


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_mob_on_the_ground_loses_its_motion_to_friction_times_0_91(tmp_path, backend):
    # LivingEntity.travel: on the ground (before the move) x and z are scaled by friction x 0.91F
    emu = world(tmp_path, backend, "summon pig 0.5 1 0.5 {OnGround:1b,Motion:[0.2d,0.0d,0.0d]}")
    pig = one(emu, "minecraft:pig")
    emu.tick()
    assert pig.pos == (0.7, 1.0, 0.5)
    assert pig.motion[0] == 0.2 * float(F32(0.6) * F32(0.91))


@pytest.mark.parametrize("backend", BACKENDS)
def test_mobs_without_ai_and_armor_stands_without_physics_hang_losing_motion(tmp_path, backend):
    # Mob.isEffectiveAi is false with NoAI, ArmorStand's with NoGravity or Marker (hasPhysics): no
    # travel, LivingEntity.aiStep only scales the motion by 0.98; an armor stand with physics falls
    emu = world(tmp_path, backend, (
        "summon pig 0.5 5 0.5 {NoAI:1b,Motion:[0.5d,0.0d,0.0d]}\n"
        "summon armor_stand 1.5 5 0.5 {NoGravity:1b,Tags:[\"ng\"]}\n"
        "summon armor_stand 1.5 5 1.5 {Marker:1b,Tags:[\"marker\"]}\n"
        "summon armor_stand -1.5 5 0.5 {Tags:[\"falls\"]}"))
    pig = one(emu, "minecraft:pig")
    stands = {next(iter(e.tags)): e for e in emu.state.entities.entities if e.type == "minecraft:armor_stand"}
    emu.tick()
    assert pig.pos == (0.5, 5.0, 0.5) and pig.motion == (0.5 * 0.98, 0.0, 0.0)
    assert stands["ng"].pos == (1.5, 5.0, 0.5) and stands["marker"].pos == (1.5, 5.0, 1.5)
    emu.tick(40)
    assert stands["falls"].pos == (-1.5, 1.0, 0.5) and float(stands["falls"].data["Health"]) == 20.0  # no fall damage
    assert pig.pos == (0.5, 5.0, 0.5)


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_void_removes_items_and_hurts_mobs(tmp_path, backend):
    # Entity.checkBelowWorld: below the bottom (-64) - 64 an item is discarded (onBelowWorld), a living
    # entity takes 4 out_of_world damage a tick (LivingEntity.onBelowWorld)
    emu = world(tmp_path, backend, (
        "summon item 0.5 -129 0.5 {Item:{id:\"minecraft:stone\",count:1},NoGravity:1b}\n"
        "summon zombie 0.5 -129 0.5 {NoGravity:1b}"))
    item, zombie = one(emu, "minecraft:item"), one(emu, "minecraft:zombie")
    emu.tick()
    assert not item.alive
    assert float(zombie.data["Health"]) == 16.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_primed_tnt_falls_and_counts_its_fuse_and_its_explosion_is_reported(tmp_path, backend):
    # PrimedTnt.tick: gravity 0.04, the move, x 0.98, the fuse; the explosion is not modelled
    emu = world(tmp_path, backend, "summon tnt 0.5 3 0.5 {fuse:2s}")
    tnt = one(emu, "minecraft:tnt")
    emu.tick()
    assert tnt.pos == (0.5, 3.0 - 0.04, 0.5) and int(tnt.data["fuse"]) == 1
    emu.tick()
    assert not tnt.alive
    assert any("TNT exploding" in d.message and d.unmodelled for d in emu.state.diagnostics)


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_item_in_water_is_reported_and_left_where_it_is(tmp_path, backend):
    emu = world(tmp_path, backend, (
        "setblock 0 1 0 water\n"
        "summon item 0.5 1.5 0.5 {Item:{id:\"minecraft:stone\",count:1}}"))
    item = one(emu, "minecraft:item")
    emu.tick(3)
    assert item.pos == (0.5, 1.5, 0.5)
    assert [d.message for d in emu.state.diagnostics if d.unmodelled] == ["minecraft:item moving: an entity in minecraft:water"]


def test_still_entities_leave_the_ticks_idle_and_moving_ones_do_not(tmp_path):
    # Runtime.run_ticks batches only ticks whose steps are idle: a mob without AI, an armor stand
    # without gravity, a marker, a display with no motion change nothing; a mob given motion or a
    # falling item does
    emu = emulator(tmp_path, "numba", {
        "t:go": ("summon pig 0.5 5 0.5 {NoAI:1b}\nsummon armor_stand 0.5 5 0.5 {NoGravity:1b}\n"
                 "summon marker 0.5 5 0.5\nsummon item_display 0.5 5 0.5"),
        "t:drop": "summon item 0.5 5 0.5 {Item:{id:\"minecraft:stone\",count:1}}"})
    emu.call("t:go")
    assert motion.tick_is_idle(emu.state)
    pig = one(emu, "minecraft:pig")
    pig.motion = (0.1, 0.0, 0.0)
    assert not motion.tick_is_idle(emu.state)
    pig.motion = (0.0, 0.0, 0.0)
    emu.call("t:drop")
    assert not motion.tick_is_idle(emu.state)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_falling_block_lands_as_its_block(tmp_path, backend):
    # FallingBlockEntity.tick: on the ground, where it is can be replaced (air) and the block under
    # it is not free: the block is set there and the entity is gone; Time counted its ticks
    emu = world(tmp_path, backend, "summon falling_block 0.5 4 0.5 {BlockState:{Name:\"minecraft:gravel\"}}")
    block = one(emu, "minecraft:falling_block")
    emu.tick()
    assert int(block.data["Time"]) == 1 and block.pos == (0.5, 4.0 - 0.04, 0.5)
    emu.tick(30)
    assert not block.alive
    assert emu.state.blocks.get((0, 1, 0)).id == "minecraft:gravel"


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_falling_block_that_cannot_land_breaks(tmp_path, backend):
    # FallingBlockEntity.tick: a torch where it lands is not replaceable: it breaks; with DropItem
    # false it is just gone, with it (the default) its item drops there (spawnAtLocation: pickup
    # delay 10, ItemEntity's motion: 0.2 up)
    emu = world(tmp_path, backend, (
        "setblock 0 1 0 torch\nsetblock 1 1 0 torch\n"
        "summon falling_block 0.5 3 0.5 {BlockState:{Name:\"minecraft:sand\"},DropItem:0b}\n"
        "summon falling_block 1.5 3 0.5 {BlockState:{Name:\"minecraft:sand\"}}"))
    quiet, dropping = sorted((e for e in emu.state.entities.entities if e.type == "minecraft:falling_block"),
                             key=lambda e: e.pos[0])
    for _ in range(30):
        emu.tick()
        if not dropping.alive:
            break
    assert not quiet.alive and not dropping.alive and emu.state.blocks.get((0, 1, 0)).id == "minecraft:torch"
    [item] = [e for e in emu.state.entities.entities if e.type == "minecraft:item"]
    assert item.pos == dropping.pos and item.motion[1] == 0.2
    assert str(item.data["Item"]["id"]) == "minecraft:sand" and int(item.data["PickupDelay"]) == 10
    assert not [d for d in emu.state.diagnostics if d.unmodelled]


def test_a_mob_resting_on_a_block_leaves_the_ticks_idle_until_it_is_moved(tmp_path):
    # at rest LivingEntity.travel changes nothing (the landing zeroes the motion, gravity and drag
    # give it back): batches of ticks stay possible; a teleport into the air ends the batch (the VM
    # stops after that root) and the mob falls from the next tick, as tick by tick
    emu = emulator(tmp_path, "numba", {
        "t:go": "fill -2 0 -2 2 0 2 stone\nsummon zombie 0.5 1 0.5",
        "t:up": "tp @e[type=zombie] 0.5 5 0.5"}, tags={"minecraft:tick": []})
    emu.call("t:go")
    zombie = one(emu, "minecraft:zombie")
    emu.tick(3)
    assert zombie.motion == (0.0, -0.0784000015258789, 0.0)
    assert motion.tick_is_idle(emu.state)
    emu.call("t:up")
    assert not motion.tick_is_idle(emu.state)
    emu.tick(40)
    assert zombie.pos == (0.5, 1.0, 0.5) and float(zombie.data["Health"]) == 19.0  # 4 blocks: ceil(3.x - 3)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_teleport_inside_a_batch_of_ticks_makes_the_mob_fall_on_both_backends(tmp_path, backend):
    # the tick function lifts the mob at tick 10: batched (numba) and tick by tick (python) agree
    emu = emulator(tmp_path, backend, {
        "t:go": "fill -2 0 -2 2 0 2 stone\nsummon zombie 0.5 1 0.5\nscoreboard players set #t o 0",
        "t:tick": ("scoreboard players add #t o 1\n"
                   "execute if score #t o matches 10 run tp @e[type=zombie] 0.5 3 0.5")},
        tags={"minecraft:tick": ["t:tick"]})
    emu.call("t:go")
    emu.tick(12)
    zombie = one(emu, "minecraft:zombie")
    assert zombie.pos[1] == 3.0 - 0.0784000015258789 - (0.0784000015258789 + 0.08) * float(F32(0.98))


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_packtest_sees_an_item_summoned_in_the_air_land_on_the_block(pack, backend):
    # ItemEntity.tick: from 3 blocks up the item lands on the stone's top (Entity.move: OnGround) and
    # rests there (a test that waits for an item to fall, as Gamemode 4's everstone test does)
    at_top = "execute positioned ~0.5 ~1 ~0.5 unless entity @e[type=item,distance=..0.0000001] run fail \"not on top\"\n"
    [result] = run_suite(discover([pack({"demo/test/t.mcfunction": (
        "# @skyaccess\n"
        "setblock ~ ~ ~ stone\n"
        "summon item ~0.5 ~3 ~0.5 {Item:{id:\"minecraft:stone\",count:1}}\n"
        "await entity @e[type=item,nbt={OnGround:1b}]\n"
        + at_top + "await delay 5\n" + at_top)})]), backend).results
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_flying_mob_with_ai_stays_where_it_is_unless_given_motion(tmp_path, backend):
    # a bat's flight is all AI (Bat.customServerAiStep): not modelled and, while nothing would move
    # it, not reported; given motion it would fly off by it (reported); with NoAI it hangs
    emu = world(tmp_path, backend, "summon bat 0.5 5 0.5\nsummon parrot 1.5 5 0.5 {Motion:[0.3d,0.0d,0.0d]}")
    bat, parrot = one(emu, "minecraft:bat"), one(emu, "minecraft:parrot")
    emu.tick(5)
    assert bat.pos == (0.5, 5.0, 0.5) and parrot.pos == (1.5, 5.0, 0.5)
    assert [d.message for d in emu.state.diagnostics if d.unmodelled] == [
        "minecraft:parrot moving: minecraft:parrot's flight (a flying mob with AI given motion)"]
    assert motion.tick_is_idle(emu.state)


@pytest.mark.parametrize("backend", BACKENDS)
def test_items_that_cannot_merge_are_not_reported(tmp_path, backend):
    # ItemEntity.areMergable: stone beside dirt, or two stacks of 40 (80 is over the stack's 64), do
    # not merge
    emu = world(tmp_path, backend, (
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:40},OnGround:1b}\n"
        "summon item 0.7 1 0.5 {Item:{id:\"minecraft:stone\",count:40},OnGround:1b}\n"
        "summon item 0.9 1 0.5 {Item:{id:\"minecraft:dirt\",count:1},OnGround:1b}"))
    emu.tick(40)
    assert not [d for d in emu.state.diagnostics if d.unmodelled]
    emu.tick(40)
    assert not [d for d in emu.state.diagnostics if d.unmodelled]


def _items(emu):
    return [e for e in emu.state.entities.entities if e.type == "minecraft:item"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_two_like_items_side_by_side_merge_into_the_neighbour_on_the_40th_tick(tmp_path, backend):
    # ItemEntity.tick: every 40th tick of its life at rest, mergeWithNeighbours -> tryToMerge: equal
    # counts go into the neighbour (merge(other, ..., this, ...)), which keeps the longer pickup delay
    # and the younger age; the emptied first item is discarded
    emu = world(tmp_path, backend, (
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:2},OnGround:1b,Age:100s,PickupDelay:500s}\n"
        "summon item 0.7 1 0.5 {Item:{id:\"minecraft:stone\",count:2},OnGround:1b,Age:10s}\n"
        "summon item 0.9 1 0.5 {Item:{id:\"minecraft:dirt\",count:1},OnGround:1b}"))
    first, second, dirt = _items(emu)
    emu.tick(39)
    assert first.alive and int(second.data["Item"]["count"]) == 2
    emu.tick(1)
    assert not first.alive and dirt.alive
    assert int(second.data["Item"]["count"]) == 4 and int(dirt.data["Item"]["count"]) == 1
    # merged in the first's tick (its delay 500 - 40, the second's age 10 + 39: ItemEntity.tick
    # counts the age after merging), then the second's own tick counts both on
    assert int(second.data["PickupDelay"]) == 460 - 1 and int(second.data["Age"]) == 49 + 1
    assert not [d for d in emu.state.diagnostics if d.unmodelled]


@pytest.mark.parametrize("backend", BACKENDS)
def test_items_merge_only_within_a_stack_of_the_same_owner_into_the_larger(tmp_path, backend):
    # ItemEntity.areMergable: the counts' sum within the max stack size (60 + 5 > 64 stays apart);
    # tryToMerge: the same target (Owner); the fewer go into the more (ItemEntity.merge)
    emu = world(tmp_path, backend, (
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:5},OnGround:1b}\n"
        "summon item 0.6 1 0.5 {Item:{id:\"minecraft:stone\",count:60},OnGround:1b}\n"
        "summon item 1.5 1 1.5 {Item:{id:\"minecraft:stone\",count:3},OnGround:1b,Owner:[I;1,2,3,4]}\n"
        "summon item 1.6 1 1.5 {Item:{id:\"minecraft:stone\",count:1},OnGround:1b}\n"
        "summon item 1.7 1 1.5 {Item:{id:\"minecraft:stone\",count:2},OnGround:1b}"))
    five, sixty, owned, one_, two = _items(emu)
    emu.tick(40)
    assert five.alive and sixty.alive and int(five.data["Item"]["count"]) == 5
    assert owned.alive and int(owned.data["Item"]["count"]) == 3
    assert not one_.alive and int(two.data["Item"]["count"]) == 3  # 1 -> the 2 (the fewer into the more)


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_item_inside_a_block_is_reported_not_dropped_through_it(tmp_path, backend):
    # ItemEntity.tick: an item whose box meets a block (noCollision of the box less 1.0E-7) is pushed
    # out of it (moveTowardsClosestSpace), not modelled; it must not fall through the stone
    emu = world(tmp_path, backend, "summon item 0.5 0.5 0.5 {Item:{id:\"minecraft:stone\",count:1}}")
    item = one(emu, "minecraft:item")
    emu.tick(3)
    assert item.pos == (0.5, 0.5, 0.5)
    assert [d.message for d in emu.state.diagnostics if d.unmodelled] == [
        "minecraft:item moving: minecraft:item inside a block (pushed out of it)"]


def _inventory(emu, name):
    player = emu.state.entities.by_holder(name)
    return [(str(e["id"]), int(e["count"]), int(e["Slot"])) for e in player.data["Inventory"]]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_player_picks_up_an_item_it_touches_once_its_pickup_delay_is_over(tmp_path, backend):
    # Player.aiStep touches what its box inflated by (1, 0.5, 1) meets; ItemEntity.playerTouch takes
    # an item whose pickup delay is 0 into the inventory (Inventory.add), the item is gone and
    # picked_up counts its 5
    emu = world(tmp_path, backend, (
        "scoreboard objectives add got minecraft.picked_up:minecraft.stone\n"
        "summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:5},OnGround:1b,PickupDelay:3s}"))
    emu.add_player("Alex", (1.5, 1.0, 0.5))
    item = one(emu, "minecraft:item")
    emu.tick(2)
    assert item.alive and _inventory(emu, "Alex") == []
    emu.tick(1)
    assert not item.alive and _inventory(emu, "Alex") == [("minecraft:stone", 5, 0)]
    assert emu.score("Alex", "got") == 5
    assert not [d for d in emu.state.diagnostics if d.unmodelled]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_partial_pickup_leaves_the_rest_and_counts_nothing(tmp_path, backend):
    # Inventory.add moves what fits (every slot full but 4 free in the first stack) out of the item
    # entity's own stack, then answers false: its last pass moved nothing and it compares with that
    # pass's count. So 6 stay on the ground and ItemEntity.playerTouch awards no picked_up; an item
    # owned by another player (Owner) stays whole
    fill = "".join(f"item replace entity Alex container.{n} with stone {60 if n == 0 else 64}\n" for n in range(36))
    emu = emulator(tmp_path, backend, {
        "t:fill": STONE_FLOOR + "scoreboard objectives add got minecraft.picked_up:minecraft.stone\n" + fill,
        "t:drop": ("summon item 0.5 1 0.5 {Item:{id:\"minecraft:stone\",count:10},OnGround:1b}\n"
                   "summon item 0.5 1 0.6 {Item:{id:\"minecraft:dirt\",count:1},OnGround:1b,Owner:[I;1,2,3,4]}")})
    emu.add_player("Alex", (1.5, 1.0, 0.5))
    emu.call("t:fill")
    emu.call("t:drop")
    stone, dirt = sorted((e for e in emu.state.entities.entities if e.type == "minecraft:item"), key=lambda e: e.pos[2])
    emu.tick(1)
    assert stone.alive and int(stone.data["Item"]["count"]) == 6
    assert _inventory(emu, "Alex")[0] == ("minecraft:stone", 64, 0)
    assert emu.score("Alex", "got") is None
    assert dirt.alive and int(dirt.data["Item"]["count"]) == 1


@pytest.mark.parametrize("backend", BACKENDS)
def test_levitation_lifts_a_mob_towards_its_speed(tmp_path, backend):
    # LivingEntity.travelInAir: levitating, the vertical motion after the move moves a fifth of the way
    # to 0.05 x (amplifier + 1) instead of losing the gravity, then x 0.98F
    emu = world(tmp_path, backend, "summon zombie 0.5 1 0.5 {OnGround:1b,active_effects:[{id:\"minecraft:levitation\","
                                   "amplifier:1b,duration:100}]}")
    zombie = one(emu, "minecraft:zombie")
    y, height = 0.0, 1.0
    for _ in range(3):
        emu.tick()
        height += y
        y = (y + (0.1 - y) * 0.2) * float(F32(0.98))
        assert zombie.motion[1] == y and zombie.pos[1] == height
    assert int(zombie.data["OnGround"]) == 0


@pytest.mark.parametrize("backend", BACKENDS)
def test_slow_falling_keeps_the_fall_distance_short(tmp_path, backend):
    # LivingEntity.aiStep: slow falling (and levitation) reset the fall distance before travel, so a
    # slow fall from 10 blocks lands with no damage; gravity at most 0.01 while falling
    emu = world(tmp_path, backend, "summon zombie 0.5 11 0.5 {active_effects:[{id:\"minecraft:slow_falling\","
                                   "duration:10000}]}")
    zombie = one(emu, "minecraft:zombie")
    emu.tick(400)
    assert zombie.pos == (0.5, 1.0, 0.5) and int(zombie.data["OnGround"]) == 1
    assert float(zombie.data["Health"]) == 20.0 and float(zombie.data["FallDistance"]) == 0.0
