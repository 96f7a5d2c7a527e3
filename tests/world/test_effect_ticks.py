"""What the ticking effects and a player's food do each tick, on both backends: regeneration,
poison and wither act every ``interval >> amplifier`` ticks of their duration (RegenerationMobEffect
50, PoisonMobEffect 25, WitherMobEffect 40: shouldApplyEffectTickThisTick, applyEffectTick; each
tick MobEffectInstance.tickServer applies a due effect before counting it down), hunger adds
0.005 x (amplifier + 1) exhaustion a tick (HungerMobEffect; Player.causeFoodExhaustion: none in
creative), saturation feeds (SaturationMobEffect: FoodData.eat(amplifier + 1, 1.0F)), and
FoodData.tick spends exhaustion, regenerates a hurt player and starves a hungry one."""
from __future__ import annotations

import pytest

from mcfunction_parser.nbt import Float, Int
from tests.world.world_emulator import emulator

BACKENDS = ["numba", "python"]

# a player takes no damage in its first 60 ticks (ServerPlayer.spawnInvulnerableTime up to 1.21.3):
# the players here join, then wait them out
SPAWN_PROTECTION = 60


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("effect, amplifier, seconds, health", [
    ("poison", 1, 3, 5.0),  # every 12 ticks of 60: at 60, 48, 36, 24, 12 (a full hurt each: over 10 ticks apart)
    ("wither", 0, 4, 8.0),  # every 40 ticks of 80: at 80 and 40
    ("poison", 0, 30, 1.0),  # poison stops at 1 health
])
def test_damaging_effects_hurt_when_due(tmp_path, backend, effect, amplifier, seconds, health):
    emu = emulator(tmp_path, backend, {"t:go": f"summon pig 0 0 0 {{Tags:[p],NoAI:1b}}\n"
                                               f"effect give @e[tag=p] {effect} {seconds} {amplifier}"})
    emu.call("t:go")
    emu.tick(seconds * 20 + 5)
    assert _pig_health(emu) == health


def _pig_health(emu) -> float:
    return float(next(e for e in emu.state.entities.entities if "p" in e.tags).data["Health"])


@pytest.mark.parametrize("backend", BACKENDS)
def test_regeneration_heals_when_due(tmp_path, backend):
    # every 25 ticks at amplifier 1: durations 100, 75, 50, 25 of 100 heal 1 each
    emu = emulator(tmp_path, backend, {"t:go": "summon pig 0 0 0 {Tags:[p],NoAI:1b,Health:3f}\n"
                                               "effect give @e[tag=p] regeneration 5 1"})
    emu.call("t:go")
    emu.tick(10)
    assert _pig_health(emu) == 4.0  # the first heal comes in the tick it was given (duration 100)
    emu.tick(100)
    assert _pig_health(emu) == 7.0


def _player(emu):
    return next(e for e in emu.state.entities.entities if e.is_player)


def _survivor(tmp_path, backend, command: str, before: bool = False, **fields):
    """An emulator with a survival player whose NBT has ``fields`` (floats but ``foodLevel``), and
    ``command`` run before it joins (``before``) or after."""
    emu = emulator(tmp_path, backend, {"t:go": command})
    if before:
        emu.call("t:go")
    emu.add_player("Steve", gamemode="survival")
    emu.tick(SPAWN_PROTECTION)
    player = _player(emu)
    player.data.update({k: Int(v) if k == "foodLevel" else Float(v) for k, v in fields.items()})
    if not before:
        emu.call("t:go")
    return emu, player


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("gamemode, exhaustion", [("survival", 0.1), ("creative", 0.0)])
def test_hunger_exhausts_a_player_that_is_not_invulnerable(tmp_path, backend, gamemode, exhaustion):
    emu = emulator(tmp_path, backend, {"t:go": "effect give @a hunger 1 1"})
    emu.add_player("Steve", gamemode=gamemode)
    emu.call("t:go")
    emu.tick(25)
    # 20 ticks of 0.01 each, summed in float (FoodData.addExhaustion)
    assert float(_player(emu).data["foodExhaustionLevel"]) == pytest.approx(exhaustion * 2, abs=1e-5)


@pytest.mark.parametrize("backend", BACKENDS)
def test_exhaustion_spends_saturation_then_food(tmp_path, backend):
    emu, player = _survivor(tmp_path, backend, "say go", foodExhaustionLevel=4.5, foodSaturationLevel=0.5,
                            foodLevel=20)
    emu.tick(1)
    assert (float(player.data["foodExhaustionLevel"]), float(player.data["foodSaturationLevel"]),
            int(player.data["foodLevel"])) == (0.5, 0.0, 20)
    player.data["foodExhaustionLevel"] = Float(4.25)
    emu.tick(1)
    assert (float(player.data["foodExhaustionLevel"]), int(player.data["foodLevel"])) == (0.25, 19)


@pytest.mark.parametrize("backend", BACKENDS)
def test_saturation_feeds_a_player(tmp_path, backend):
    emu, player = _survivor(tmp_path, backend, "effect give @a saturation 4 2", foodLevel=10, foodSaturationLevel=0.0)
    emu.tick(1)
    # an instant effect given for 4 "seconds" lasts 4 ticks (EffectCommand), each eating 3 food and 6
    # saturation (capped at 20 and at the food level)
    assert (int(player.data["foodLevel"]), float(player.data["foodSaturationLevel"])) == (13, 6.0)
    emu.tick(3)
    assert (int(player.data["foodLevel"]), float(player.data["foodSaturationLevel"])) == (20, 20.0)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_full_food_bar_heals_a_hurt_player_from_saturation(tmp_path, backend):
    emu, player = _survivor(tmp_path, backend, "say go", Health=10.0, foodSaturationLevel=3.0)
    emu.tick(10)
    # the 10th tick heals min(3, 6) / 6 and costs 3 exhaustion
    assert float(player.data["Health"]) == 10.5 and float(player.data["foodExhaustionLevel"]) == 3.0
    assert int(player.data["foodTickTimer"]) == 0


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("difficulty, health", [("normal", 4.0), ("easy", 5.0)])
def test_an_empty_food_bar_starves(tmp_path, backend, difficulty, health):
    emu, player = _survivor(tmp_path, backend, f"difficulty {difficulty}", Health=5.0, foodLevel=0,
                            foodSaturationLevel=0.0)
    emu.tick(80)
    # every 80 ticks, 1 starve damage while over 1 health on normal (10 on easy)
    assert float(player.data["Health"]) == health


@pytest.mark.parametrize("backend", BACKENDS)
def test_peaceful_feeds_and_heals_a_player(tmp_path, backend):
    # ServerPlayer.tickRegeneration: every 20 ticks of its age 1 health and 1 saturation, every 10
    # a point of food, before FoodData.tick
    emu, player = _survivor(tmp_path, backend, "difficulty peaceful", before=True, Health=10.0, foodLevel=10,
                            foodSaturationLevel=0.0)
    emu.tick(40)
    assert (float(player.data["Health"]), int(player.data["foodLevel"]),
            float(player.data["foodSaturationLevel"])) == (12.0, 14, 2.0)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("difficulty, by_zombie, explosion, fall", [
    ("peaceful", 20.0, 20.0, 16.0), ("easy", 17.0, 17.0, 16.0), ("normal", 16.0, 16.0, 16.0),
    ("hard", 14.0, 14.0, 16.0)])
def test_a_players_damage_scales_with_the_difficulty(tmp_path, backend, difficulty, by_zombie, explosion, fall):
    # Player.hurtServer: a source that scalesWithDifficulty (a living non-player causing it, or an
    # ALWAYS type such as explosion: DamageTypes.bootstrap) deals 0 on peaceful, min(d/2+1, d) on
    # easy, d*3/2 on hard; a fall (no causing entity) does not scale
    emu = emulator(tmp_path, backend, {
        "t:go": f"difficulty {difficulty}\nsummon zombie 5 0 5 {{Tags:[z],NoAI:1b}}\n"
                "damage A 4 minecraft:mob_attack by @e[tag=z,limit=1]\n"
                "damage B 4 minecraft:explosion\ndamage C 4 minecraft:fall"})
    for name in "ABC":
        emu.add_player(name, gamemode="survival")
    emu.tick(SPAWN_PROTECTION)
    emu.call("t:go")
    healths = {e.player_name: float(e.data["Health"]) for e in emu.state.entities.entities if e.is_player}
    assert (healths["A"], healths["B"], healths["C"]) == (by_zombie, explosion, fall)


@pytest.mark.parametrize("backend", BACKENDS)
def test_damage_game_rules_spare_players(tmp_path, backend):
    # Player.isInvulnerableTo: #is_drowning, #is_fall, #is_fire and #is_freezing damage does nothing
    # to a player while drowningDamage, fallDamage, fireDamage and freezeDamage are false; mobs take it
    emu = emulator(tmp_path, backend, {
        "t:go": "gamerule fallDamage false\ngamerule fireDamage false\nsummon pig 0 0 0 {Tags:[p],NoAI:1b}\n"
                "damage A 4 minecraft:fall\ndamage A 4 minecraft:lava\ndamage A 3 minecraft:freeze\n"
                "damage @e[tag=p,limit=1] 4 minecraft:fall"})
    emu.add_player("A", gamemode="survival")
    emu.tick(SPAWN_PROTECTION)
    emu.call("t:go")
    assert float(_player(emu).data["Health"]) == 17.0  # only the freeze
    assert _pig_health(emu) == 6.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_effects_modify_attributes_while_they_last(tmp_path, backend):
    # MobEffects.register: speed adds 0.2F x (amplifier + 1) to movement_speed, multiplied total;
    # strength 3 x (amplifier + 1) attack damage; transient (AttributeMap.addTransientAttributeModifiers),
    # removed with the effect (onEffectsRemoved)
    emu = emulator(tmp_path, backend, {
        "t:go": "summon zombie 0 0 0 {Tags:[z],NoAI:1b}\neffect give @e[tag=z] speed 1 1\n"
                "effect give @e[tag=z] strength 1 0",
        "t:read": "execute store result score #speed o run attribute @e[tag=z,limit=1] generic.movement_speed get 100000\n"
                  "execute store result score #damage o run attribute @e[tag=z,limit=1] generic.attack_damage get 10"})
    emu.call("t:go")
    emu.call("t:read")
    # a zombie's 0.23 x (1 + 2 x 0.2F), its 3 attack damage + 3
    assert (emu.score("#speed", "o"), emu.score("#damage", "o")) == (32200, 60)
    emu.tick(25)
    emu.call("t:read")
    assert (emu.score("#speed", "o"), emu.score("#damage", "o")) == (23000, 30)


@pytest.mark.parametrize("backend", BACKENDS)
def test_absorption_gives_its_hearts_and_goes_with_them(tmp_path, backend):
    # AbsorptionMobEffect: max_absorption + 4 x (amplifier + 1); onEffectStarted sets the absorption
    # to max(current, 4 x (amplifier + 1)); its tick removes it once the absorption is gone
    emu = emulator(tmp_path, backend, {"t:go": "summon pig 0 0 0 {Tags:[p],NoAI:1b}\n"
                                               "effect give @e[tag=p] absorption 30 1",
                                       "t:hit": "damage @e[tag=p,limit=1] 9"})
    emu.call("t:go")
    pig = next(e for e in emu.state.entities.entities if "p" in e.tags)
    assert float(pig.data["AbsorptionAmount"]) == 8.0
    emu.call("t:hit")
    assert (float(pig.data["AbsorptionAmount"]), float(pig.data["Health"])) == (0.0, 9.0)
    emu.tick(2)
    assert "active_effects" not in pig.data


@pytest.mark.parametrize("backend", BACKENDS)
def test_fire_resistance_refuses_fire_damage(tmp_path, backend):
    # LivingEntity.hurtServer: #is_fire damage does nothing with fire resistance; other damage does
    emu = emulator(tmp_path, backend, {"t:go": "summon pig 0 0 0 {Tags:[p],NoAI:1b}\n"
                                               "effect give @e[tag=p] fire_resistance 10\n"
                                               "damage @e[tag=p,limit=1] 4 minecraft:lava\n"
                                               "damage @e[tag=p,limit=1] 3 minecraft:generic"})
    emu.call("t:go")
    assert _pig_health(emu) == 7.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_resistance_takes_a_fifth_per_level(tmp_path, backend):
    # LivingEntity.getDamageAfterMagicAbsorb: (amplifier + 1) x 5 of 25 parts less, after armour; the
    # resisted damage x 10 is the player's damage_resisted; #bypasses_resistance (generic_kill) is not
    # reduced
    emu = emulator(tmp_path, backend, {
        "t:go": "scoreboard objectives add resisted minecraft.custom:minecraft.damage_resisted\n"
                "effect give A resistance 10 1\ndamage A 10 minecraft:generic\n"
                "summon pig 0 0 0 {Tags:[p],NoAI:1b}\neffect give @e[tag=p] resistance 10 4\ndamage @e[tag=p,limit=1] 5",
        "t:kill": "damage @e[tag=p,limit=1] 3 minecraft:generic_kill"})
    emu.add_player("A", gamemode="survival")
    emu.tick(SPAWN_PROTECTION)
    emu.call("t:go")
    # 10 x 15 / 25 = 6 to the player (4 resisted), nothing to the pig at amplifier 4
    assert float(_player(emu).data["Health"]) == 14.0 and emu.score("A", "resisted") == 40
    assert _pig_health(emu) == 10.0
    emu.tick(20)
    emu.call("t:kill")
    assert _pig_health(emu) == 7.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_an_entity_refuses_the_effects_its_type_ignores(tmp_path, backend):
    # LivingEntity.canBeAffected: the undead (#ignores_poison_and_regen) take neither poison nor
    # regeneration, spiders no poison (Spider.canBeAffected); `effect give` then fails
    # (commands.effect.give.failed) and counts nothing
    emu = emulator(tmp_path, backend, {
        "t:go": "summon zombie 0 0 0 {Tags:[z],NoAI:1b}\nsummon spider 2 0 0 {Tags:[s],NoAI:1b}\n"
                "execute store success score #zp o run effect give @e[tag=z] poison 5\n"
                "execute store success score #zr o run effect give @e[tag=z] regeneration 5\n"
                "execute store success score #zs o run effect give @e[tag=z] speed 5\n"
                "execute store success score #sp o run effect give @e[tag=s] poison 5\n"
                "execute store success score #sw o run effect give @e[tag=s] weakness 5"})
    emu.call("t:go")
    assert [emu.score(h, "o") for h in ("#zp", "#zr", "#zs", "#sp", "#sw")] == [0, 0, 1, 0, 1]
