"""PackTest dummies fall (emulator.world.falling): PackTest's Dummy.tick runs doTick, so the server
ticks the dummy as Player.tick -> LivingEntity.aiStep -> travel does (gravity 0.08, drag 0.98F),
Entity.move lands it on a block (OnGround), Entity.checkFallDamage sums the fall distance and
LivingEntity.calculateFallDamage takes ceil(distance - 3) on landing (Player.causeFallDamage: none
for creative players; fall_one_cm). Sources: misode/packtest Dummy.java (tick); decompiled 1.21
LivingEntity.java, Entity.java, Player.java, HayBlock.java (fallOn x 0.2)."""
import pytest

from emulator.testing import discover, run_suite

SKY = "# @skyaccess\n"
# a player takes no damage for 60 ticks after it joins (ServerPlayer.spawnInvulnerableTime up to
# 1.21.3; from 1.21.4 a dummy's client-load timeout): a test that hurts it waits them out first
SPAWN_PROTECTED = "await delay 60\n"  # no barrier ceiling over the 1-block test structure: the dummies start above it
STATS = ("scoreboard objectives add fell minecraft.custom:minecraft.fall_one_cm\n"
         "scoreboard objectives add jumps minecraft.custom:minecraft.jump\n")


def run(pack, text, backend="numba"):
    [result] = run_suite(discover([pack({"demo/test/t.mcfunction": text})]), backend).results
    return result


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_dummy_spawned_in_the_air_falls_lands_and_takes_fall_damage(pack, backend):
    # 4.5 blocks: Entity.checkFallDamage adds a move to the fall distance only in the air, so the
    # landing takes the distance before its last move (4.06 here): ceil(4.06 - 3) = 2 damage and
    # fall_one_cm = round(distance x 100), under the 450 of the whole drop
    result = run(pack, SKY + "# @timeout 200\n" + STATS + (
        "fill ~-1 ~ ~-1 ~1 ~ ~1 stone\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        + SPAWN_PROTECTED +
        "tp Alex ~0.5 ~5.5 ~0.5\n"
        "await delay 3\n"
        "assert data entity Alex {OnGround:0b}\n"
        "execute store result score Alex fell run data get entity Alex FallDistance 1000\n"
        "assert score Alex fell matches 1..4499\n"            # still falling: part of the way
        "scoreboard players reset Alex fell\n"
        "await entity @a[name=Alex,nbt={OnGround:1b}]\n"
        "execute positioned ~0.5 ~1 ~0.5 unless entity @a[name=Alex,distance=..0.0000001] run fail \"not on top\"\n"
        "assert data entity Alex {Health:18.0f,FallDistance:0.0f}\n"
        "assert score Alex fell matches 400..449\n"
        "await delay 2\n"                                      # standing: the game's resting motion
        "assert data entity Alex {OnGround:1b,Motion:[0.0d,-0.0784000015258789d,0.0d]}\n"
        "assert data entity Alex {Health:18.0f}\n"), backend)
    assert result.status == "passed", result.report()


def test_the_landing_puts_the_feet_on_the_top_of_the_block(pack):
    result = run(pack, SKY + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~3.25 ~0.5 run dummy Alex spawn\n"
        "await entity @a[name=Alex,nbt={OnGround:1b}]\n"
        "execute positioned ~0.5 ~1 ~0.5 unless entity @a[name=Alex,distance=..0.0000001] run fail \"not at ~0.5 ~1 ~0.5\"\n"
        "assert data entity Alex {Health:20.0f}\n"), )
    assert result.status == "passed", result.report()


def test_a_hay_block_takes_a_fifth_of_the_fall(pack):
    # 10.5 blocks onto hay: ceil((10.5 - 3) x 0.2) = 2; onto stone it would be 8
    result = run(pack, SKY + "# @timeout 200\n" + (
        "setblock ~ ~ ~ hay_block\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        + SPAWN_PROTECTED +
        "tp Alex ~0.5 ~11.5 ~0.5\n"
        "await entity @a[name=Alex,nbt={OnGround:0b}]\n"
        "await entity @a[name=Alex,nbt={OnGround:1b}]\n"
        "assert data entity Alex {Health:18.0f}\n"))
    assert result.status == "passed", result.report()


def test_a_creative_dummy_takes_no_fall_damage_and_no_fall_statistic(pack):
    result = run(pack, SKY + STATS + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~8.5 ~0.5 run dummy Alex spawn\n"
        "gamemode creative Alex\n"
        "await entity @a[name=Alex,nbt={OnGround:1b}]\n"
        "assert data entity Alex {Health:20.0f}\n"
        "assert not score Alex fell matches 0..\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_jump_rises_and_lands_again_without_damage(pack, backend):
    # LivingEntity.jumpFromGround: motion y 0.42F; the game's jump tops out at 1.2522 blocks after 6
    # ticks and lands 12 ticks after the jump
    result = run(pack, SKY + STATS + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        "await delay 3\n"
        "assert data entity Alex {OnGround:1b}\n"
        "dummy Alex jump\n"
        "assert score Alex jumps matches 1\n"
        "await delay 1\n"
        "assert data entity Alex {OnGround:0b}\n"
        "execute positioned ~0.5 ~1.42 ~0.5 unless entity @a[name=Alex,distance=..0.0001] run fail \"not at ~0.5 ~1.42 ~0.5\"\n"  # 0.42F
        "dummy Alex jump\n"                                    # refused in the air
        "assert score Alex jumps matches 1\n"
        "await delay 5\n"
        "execute positioned ~0.5 ~2.2522 ~0.5 unless entity @a[name=Alex,distance=..0.0001] run fail \"not at the top\"\n"  # the jump height
        "await delay 5\n"
        "assert data entity Alex {OnGround:0b}\n"
        "await delay 1\n"
        "assert data entity Alex {OnGround:1b,Health:20.0f}\n"
        "execute positioned ~0.5 ~1 ~0.5 unless entity @a[name=Alex,distance=..0.0000001] run fail \"not at ~0.5 ~1 ~0.5\"\n"), backend)
    assert result.status == "passed", result.report()


def test_falling_into_water_is_reported_not_modelled(pack):
    result = run(pack, SKY + (
        "fill ~ ~ ~ ~ ~1 ~ water\n"
        "execute positioned ~0.5 ~4.5 ~0.5 run dummy Alex spawn\n"
        "await delay 20\n"
        "assert entity Alex\n"))
    assert result.status == "inconclusive", result.report()
    assert "a player's fall: moving through minecraft:water" in result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_full_swing_while_falling_is_a_critical_hit(pack, backend):
    # Player.attack: strength > 0.9, fall distance > 0, not on the ground, not sprinting: damage x 1.5
    # (an empty hand's 1 becomes 1.5); the same swing on the ground stays 1
    result = run(pack, SKY + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        "summon pig ~2.5 ~1 ~0.5 {NoAI:1b,NoGravity:1b,Tags:[\"ground\"]}\n"
        "summon pig ~2.5 ~2 ~0.5 {NoAI:1b,NoGravity:1b,Tags:[\"air\"]}\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=ground,limit=1]\n"
        "assert data entity @e[tag=ground,limit=1] {Health:9.0f}\n"
        "await delay 20\n"
        "dummy Alex jump\n"
        "await delay 8\n"                                     # past the top: falling
        "assert data entity Alex {OnGround:0b}\n"
        "dummy Alex attack @e[tag=air,limit=1]\n"
        "assert data entity @e[tag=air,limit=1] {Health:8.5f}\n"), backend)
    assert result.status == "passed", result.report()


def test_a_swing_while_rising_is_no_critical_hit(pack):
    result = run(pack, SKY + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        "summon pig ~2.5 ~2 ~0.5 {NoAI:1b,NoGravity:1b,Tags:[\"air\"]}\n"
        "await delay 20\n"
        "dummy Alex jump\n"
        "await delay 2\n"                                     # rising: no fall distance yet
        "dummy Alex attack @e[tag=air,limit=1]\n"
        "assert data entity @e[tag=air,limit=1] {Health:9.0f}\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_levitating_dummy_rises_and_lands_softly_with_slow_falling(pack, backend):
    # LivingEntity.travelInAir: levitation lifts; LivingEntity.aiStep: slow falling and levitation reset
    # the fall distance, so the drop after it lands with no damage
    result = run(pack, SKY + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        "effect give Alex levitation 1 4\n"
        "effect give Alex slow_falling 60\n"
        "await delay 15\n"
        "execute positioned ~0.5 ~4 ~0.5 unless entity @a[name=Alex,dy=100] run fail \"not lifted\"\n"
        "await entity @a[name=Alex,nbt={OnGround:1b}]\n"
        "assert data entity Alex {Health:20.0f}\n"), backend)
    assert result.status == "passed", result.report()


def test_a_spectator_dummy_with_no_motion_stays(pack):
    # Player.travel flying with no physics: no input, no motion, no move
    result = run(pack, SKY + (
        "execute positioned ~0.5 ~5 ~0.5 run dummy Alex spawn\n"
        "gamemode spectator Alex\n"
        "await delay 10\n"
        "execute positioned ~0.5 ~5 ~0.5 unless entity @a[name=Alex,distance=..0.5] run fail \"moved\"\n"
        "succeed\n"))
    assert result.status == "passed", result.report()


LEVITATED = {"demo/advancement/up.json": (
    '{"criteria": {"c": {"trigger": "minecraft:levitation", "conditions": '
    '{"distance": {"y": {"min": 2}}, "duration": {"min": 10}}}}}')}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_the_levitation_trigger_measures_from_where_it_began(pack, backend):
    # ServerPlayer.onEffectAdded keeps the start; ServerPlayer.tick fires levitation with the
    # distance from it and the ticks since (LevitationTrigger: both must match)
    [result] = run_suite(discover([pack({"demo/test/t.mcfunction": SKY + (
        "setblock ~ ~ ~ stone\n"
        "execute positioned ~0.5 ~1 ~0.5 run dummy Alex spawn\n"
        "effect give Alex levitation 3 4\n"
        "await delay 5\n"
        "assert not entity @a[name=Alex,advancements={demo:up=true}]\n"
        "await entity @a[name=Alex,advancements={demo:up=true}]\n"), **LEVITATED})]), backend).results
    assert result.status == "passed", result.report()
