"""Arrows and snowballs moved tick by tick (emulator.world.projectile_flight). Sources: decompiled
1.21 AbstractArrow.tick / onHitBlock / tickDespawn / shouldFall, ThrowableProjectile.tick,
Projectile.lerpRotation, and their 1.21.2+ forms (AbstractArrow.stepMoveAndHit: the arrow stands at
the hit less 0.05F per axis moved with no motion; ThrowableProjectile.tick: gravity and drag
before the move)."""
import numpy as np
import pytest

from emulator import Emulator
from emulator.world import ray
from emulator.world.blocks import BlockMap, BlockSpec
from tests.conftest import write_pack

F32 = np.float32
STONE = BlockSpec("minecraft:stone", False, (), None)


def world(tmp_path, setup: str, mc: str = "1.21", backend: str = "python") -> Emulator:
    emu = Emulator(backend=backend)
    emu.load([write_pack(tmp_path / "p", {"demo/function/f.mcfunction": setup})], mc_version=mc)
    emu.call("demo:f")
    return emu


def only(emu, type_id):
    found = [e for e in emu.state.entities.entities if e.type == type_id]
    assert len(found) == 1, found
    return found[0]


def test_ray_cells_and_a_full_cube_hit():
    # BlockGetter.traverseBlocks: the cells in the order the segment enters them
    assert list(ray.cells((0.5, 0.5, 0.5), (2.5, 1.5, 0.5))) == [(0, 0, 0), (1, 0, 0), (1, 1, 0), (2, 1, 0)]
    blocks = BlockMap()
    blocks.setblock((2, 0, 0), STONE)
    location, cell = ray.clip_blocks(blocks, (0.5, 0.5, 0.5), (3.5, 0.5, 0.5))
    assert cell == (2, 0, 0) and location == (2.0, 0.5, 0.5)  # AABB.clip: the west face
    # VoxelShape.clip: a start that a thousandth of the way in is inside the cube hits there
    location, cell = ray.clip_blocks(blocks, (1.9999, 0.5, 0.5), (2.9999, 0.5, 0.5))
    assert cell == (2, 0, 0) and location == (1.9999 + 0.001, 0.5, 0.5)
    assert ray.clip_blocks(blocks, (0.5, 1.5, 0.5), (3.5, 1.5, 0.5)) is None


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_an_arrow_moves_by_its_motion_then_drags_and_falls(tmp_path, backend):
    # AbstractArrow.tick: the position takes the motion, then the motion is scaled by 0.99F and
    # 0.05 of gravity taken from it (the same order in 1.21 and 1.21.2+)
    emu = world(tmp_path, "summon arrow 0.5 10 0.5 {Motion:[1.0,0.0,0.0]}\n", backend=backend)
    emu.tick()
    arrow = only(emu, "minecraft:arrow")
    assert arrow.pos == (1.5, 10.0, 0.5)
    assert arrow.motion == (float(F32(0.99)), -0.05, 0.0)
    emu.tick()
    assert arrow.pos == (1.5 + float(F32(0.99)), 9.95, 0.5)
    assert arrow.motion == (float(F32(0.99)) * float(F32(0.99)), -0.05 * float(F32(0.99)) - 0.05, 0.0)


@pytest.mark.parametrize("mc,yaw", [("1.21", 90.0), ("1.21.4", 18.0)])
def test_the_arrows_rotation_turns_to_its_motion(tmp_path, mc, yaw):
    # Projectile.lerpRotation: a fifth of the way from the current rotation; 1.21's AbstractArrow
    # takes the motion's rotation at once when the previous one is 0, 0. A projectile's yaw is
    # atan2(x, z): moving +x is 90.
    emu = world(tmp_path, "summon arrow 0.5 10 0.5 {Motion:[1.0,0.0,0.0]}\n", mc)
    emu.tick()
    assert abs(float(only(emu, "minecraft:arrow").yaw) - yaw) < 1e-4


def test_an_arrow_sticks_in_the_block_it_hits_and_despawns_after_1200_ticks(tmp_path):
    # 1.21.2+ stepMoveAndHit: the arrow goes to the hit, onHitBlock steps it back 0.05F along each
    # axis it moved on and stops it (inGround, shake 7, crit 0); stuck, life counts to 1200 and the
    # arrow is discarded (tickDespawn); shake counts down
    emu = world(tmp_path, "fill 3 5 -1 3 15 1 stone\nsummon arrow 0.5 10.5 0.5 {Motion:[1.0,0.0,0.0],crit:1b}\n",
                "1.21.4")
    emu.tick(3)
    arrow = only(emu, "minecraft:arrow")
    # at the face x = 3 (y between the third tick's ends), back 0.05F on x and up 0.05F (it fell)
    assert arrow.pos[0] == 3.0 - float(F32(0.05)) and arrow.pos[2] == 0.5
    assert 10.35 + 0.05 < arrow.pos[1] < 10.45 + 0.05
    assert arrow.motion == (0.0, 0.0, 0.0)
    data = arrow.data
    assert (int(data["inGround"]), int(data["crit"]), str(data["inBlockState"]["Name"])) == (1, 0, "minecraft:stone")
    emu.tick()
    assert int(data["shake"]) == 6 and int(data["life"]) == 1
    emu.tick(1198)
    assert arrow.alive and int(data["life"]) == 1199
    emu.tick()
    assert not arrow.alive


def test_in_1_21_the_hit_turns_the_motion_toward_it(tmp_path):
    # 1.21 onHitBlock: motion = hit - position, the arrow steps back 0.05F along it, then moves by it:
    # it ends 0.05 short of the face with that motion dragged and fallen
    emu = world(tmp_path, "fill 2 5 -1 2 15 1 stone\nsummon arrow 0.5 10.5 0.5 {Motion:[2.0,0.0,0.0]}\n", "1.21")
    emu.tick()
    arrow = only(emu, "minecraft:arrow")
    assert arrow.pos == (2.0 - float(F32(0.05)), 10.5, 0.5)
    assert arrow.motion == (1.5 * float(F32(0.99)), -0.05, 0.0)
    assert int(arrow.data["inGround"]) == 1


def test_an_arrow_left_in_the_air_falls_again(tmp_path):
    # AbstractArrow.shouldFall: stuck (inGround) but not in the block it hit and nothing within 0.06:
    # startFalling (its still motion stays still), then it falls with gravity
    emu = world(tmp_path, "summon arrow 0.5 10 0.5 {inGround:1b}\n")
    emu.tick()
    arrow = only(emu, "minecraft:arrow")
    assert int(arrow.data["inGround"]) == 0 and arrow.pos == (0.5, 10.0, 0.5)
    emu.tick(2)
    assert arrow.pos == (0.5, 9.95, 0.5)
    emu = world(tmp_path / "2", "setblock 0 9 0 stone\nsummon arrow 0.5 10.03 0.5 {inGround:1b}\n")
    emu.tick(5)
    arrow = only(emu, "minecraft:arrow")
    assert int(arrow.data["inGround"]) == 1 and int(arrow.data["life"]) == 5  # the stone is within 0.06


@pytest.mark.parametrize("mc,x,y", [
    ("1.21", 1.5, 10.0),  # moves, then drag and gravity
    ("1.21.4", 0.5 + float(F32(0.99)), 10.0 - 0.03 * float(F32(0.99))),  # gravity and drag, then the move
])
def test_a_snowball_moves_and_a_hit_removes_it(tmp_path, mc, x, y):
    emu = world(tmp_path, "fill 4 5 -1 4 15 1 stone\nsummon snowball 0.5 10 0.5 {Motion:[1.0,0.0,0.0]}\n", mc)
    emu.tick()
    snowball = only(emu, "minecraft:snowball")
    assert snowball.pos == (x, y, 0.5)
    emu.tick(3)
    assert not snowball.alive  # Snowball.onHit: discard


@pytest.mark.parametrize("speed,damage", [(1.0, 2), (1.2, 3), (1.5, 3)])
def test_an_arrow_hurts_the_mob_in_its_way_by_ceil_speed_x_damage_and_is_gone(tmp_path, speed, damage):
    # AbstractArrow.onHitEntity: Mth.ceil((float) motion length x baseDamage 2.0) as arrow damage
    # (its owner, else the arrow, responsible), then discard; (float)1.2 x 2.0 = 2.4000001 -> 3
    emu = world(tmp_path, "summon pig 3.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          f"summon arrow 0.5 10.5 0.5 {{Motion:[{speed}d,0.0d,0.0d]}}\n")
    emu.tick(3)
    pig = only(emu, "minecraft:pig")
    assert float(pig.data["Health"]) == 10.0 - damage
    assert not any(e.type == "minecraft:arrow" for e in emu.state.entities.entities)
    assert not any(d.unmodelled for d in emu.diagnostics)


def test_a_snowball_breaks_on_an_interaction_entity(tmp_path):
    # Interaction.isPickable: a projectile hits it; Entity.hurt does nothing to it; Snowball.onHit: discard
    emu = world(tmp_path, "summon interaction 2.5 9.5 0.5 {width:1f,height:1f}\n"
                          "summon snowball 0.5 10 0.5 {Motion:[1.0d,0.0d,0.0d]}\n")
    emu.tick(2)
    assert not any(e.type == "minecraft:snowball" for e in emu.state.entities.entities)
    assert not any(d.unmodelled for d in emu.diagnostics)


def test_a_spectral_arrow_makes_its_target_glow(tmp_path):
    # SpectralArrow.doPostHurtEffects: glowing for its Duration (200 unless set), amplifier 0
    emu = world(tmp_path, "summon pig 3.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          "summon spectral_arrow 0.5 10.5 0.5 {Motion:[1.0d,0.0d,0.0d],Duration:60}\n")
    emu.tick(3)
    pig = only(emu, "minecraft:pig")
    [glowing] = pig.data["active_effects"]
    assert str(glowing["id"]) == "minecraft:glowing" and int(glowing["duration"]) == 60
    assert float(pig.data["Health"]) == 8.0


@pytest.mark.parametrize("setup,reason", [
    ("summon pig 3.5 10 0.5 {NoAI:1b}\nsummon arrow 0.5 10 0.5 {Motion:[1.0,0.0,0.0],crit:1b}\n",
     "a critical arrow's bonus damage"),
    ("summon armor_stand 3.5 10 0.5\n", "hitting minecraft:armor_stand"),
    ("setblock 1 10 0 cobweb\n", "in or through minecraft:cobweb"),
    ("setblock 1 10 0 oak_slab\n", "the shape of minecraft:oak_slab"),
])
def test_what_is_not_modelled_makes_the_arrow_stay_and_is_reported(tmp_path, setup, reason):
    emu = world(tmp_path, setup + "summon arrow 0.5 10 0.5 {Motion:[1.0,0.0,0.0]}\n")
    emu.tick(4)
    assert any(d.unmodelled and reason in d.message for d in emu.diagnostics), [d.message for d in emu.diagnostics]


@pytest.mark.parametrize("summon,inertia,gravity", [
    ("arrow", 0.6, 0.05),  # AbstractArrow.getWaterInertia
    ("potion", 0.8, 0.05),  # ThrowableProjectile.tick: 0.8F in water
])
def test_still_water_slows_a_projectile_by_its_water_inertia(tmp_path, summon, inertia, gravity):
    # isInWater from where it stands at the start of the tick: a pool of sources (no current)
    emu = world(tmp_path, "fill -2 8 -2 6 12 2 water\n"
                          f"summon {summon} 0.5 10 0.5 {{Motion:[1.0d,0.0d,0.0d]}}\n")
    emu.tick()
    [flying] = [e for e in emu.state.entities.entities if e.type == "minecraft:" + summon]
    assert flying.pos == (1.5, 10.0, 0.5)
    assert flying.motion == (float(F32(inertia)), -gravity, 0.0)
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_flowing_water_is_reported(tmp_path):
    emu = world(tmp_path, "setblock 0 10 0 water[level=3]\nsummon arrow 0.5 10 0.5 {Motion:[1.0d,0.0d,0.0d]}\n")
    emu.tick()
    assert any(d.unmodelled and "flowing water" in d.message for d in emu.diagnostics)
