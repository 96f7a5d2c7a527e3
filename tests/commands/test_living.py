"""``xp``, ``effect``, ``attribute`` and ``damage`` run by :mod:`emulator.commands.living` on the
state :mod:`emulator.world.living` keeps in the entities' NBT.

Sources (decompiled 1.21): server/commands/ExperienceCommand.java, EffectCommands.java,
AttributeCommand.java, DamageCommand.java; world/entity/player/Player.java
(giveExperiencePoints, getXpNeededForNextLevel), world/entity/ai/attributes/AttributeInstance.java
(calculateValue), world/damagesource/CombatRules.java (getDamageAfterAbsorb).
"""
from __future__ import annotations

import pytest

from emulator.commands.dispatch import run_command
from emulator.commands.entities import entity_context, new_state
from emulator.commands.env import Env
from emulator.world import living
from emulator.world.context import Context
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, List, String
from mcfunction_parser.parse import parse_command


@pytest.fixture
def env():
    return Env(new_state(), {}, set())


def run(env, text: str, ctx: Context | None = None, version=(1, 21, 4)) -> int:
    cmd, diagnostics = parse_command(text, Loc("t.mcfunction", 1, 1), version)
    assert not diagnostics, diagnostics
    return run_command(env, cmd, ctx or Context())


def player(env, name="Steve"):
    entity = env.state.entities.add_player(name, (0.0, 0.0, 0.0))
    return entity, entity_context(env.state, entity)


# ---------------------------------------------------------------------- xp
def test_points_carry_into_levels_as_the_game_counts_them(env):
    steve, ctx = player(env)
    # level 0 needs 7 points, level 1 needs 9: 10 points are level 1 and 3 of 9
    assert run(env, "xp add @s 10 points", ctx) == 1
    assert run(env, "xp query @s levels", ctx) == 1 and run(env, "xp query @s points", ctx) == 3
    assert steve.data["XpTotal"] == 10 and steve.data["Score"] == 10
    assert float(steve.data["XpP"]) == pytest.approx(3 / 9, rel=1e-6)


def test_negative_points_take_levels_back_and_stop_at_zero(env):
    steve, ctx = player(env)
    run(env, "xp add @s 3 levels", ctx)
    # -12 points at level 3 (13 to the next): back through level 2 (11 points) to level 1 with
    # 8 of 9 in exact arithmetic; the game's float steps leave 7.9999 there, which query floors to 7
    run(env, "xp add @s -12 points", ctx)
    assert run(env, "xp query @s levels", ctx) == 1 and run(env, "xp query @s points", ctx) == 7
    run(env, "xp add @s -100 levels", ctx)
    assert (steve.data["XpLevel"], float(steve.data["XpP"]), steve.data["XpTotal"]) == (0, 0.0, 0)


def test_set_points_is_refused_at_the_levels_maximum(env):
    _, ctx = player(env)
    with pytest.raises(CommandFailure, match="Cannot set experience points above the maximum"):
        run(env, "xp set @s 7 points", ctx)  # level 0 holds 0..6
    assert run(env, "xp set @s 6 points", ctx) == 1 and run(env, "xp query @s points", ctx) == 6
    assert run(env, "experience set @s 30 levels", ctx) == 1 and run(env, "xp query @s levels", ctx) == 30


@pytest.mark.parametrize("entity, command, refusal", [
    ("minecraft:marker", "effect give @e speed", "Unable to apply this effect"),  # not living
    ("minecraft:marker", "attribute @e[limit=1] max_health get", "is not a valid entity"),
])
def test_commands_refuse_entities_they_cannot_act_on(env, entity, command, refusal):
    uuid = env.state.entities.summon(entity, (0, 0, 0)).uuid_string
    with pytest.raises(CommandFailure, match=refusal):
        run(env, command.format(uuid=uuid))


# ---------------------------------------------------------------------- effect
def test_effect_counts_down_and_ends(env):
    steve, ctx = player(env)
    assert run(env, "effect give @s minecraft:speed 2 1 true", ctx) == 1
    [speed] = steve.data["active_effects"]
    assert (speed["duration"], speed["amplifier"], speed["show_particles"]) == (40, 1, 0)
    for _ in range(39):
        living.tick_living(env.state)
    assert steve.data["active_effects"][0]["duration"] == 1
    living.tick_living(env.state)
    assert "active_effects" not in steve.data  # saved only while there is one


def test_weaker_or_shorter_effect_changes_nothing(env):
    _, ctx = player(env)
    run(env, "effect give @s speed 10 2", ctx)
    with pytest.raises(CommandFailure, match="something stronger"):
        run(env, "effect give @s speed 5 2", ctx)
    with pytest.raises(CommandFailure, match="something stronger"):
        run(env, "effect give @s speed 60 1", ctx)
    assert run(env, "effect give @s speed infinite 2", ctx) == 1


def test_effect_clear(env):
    steve, ctx = player(env)
    with pytest.raises(CommandFailure, match="no effects to remove"):
        run(env, "effect clear @s", ctx)
    run(env, "effect give @s speed", ctx)
    assert steve.data["active_effects"][0]["duration"] == 600  # 30 s by default
    with pytest.raises(CommandFailure, match="doesn't have the requested effect"):
        run(env, "effect clear @s minecraft:glowing", ctx)
    assert run(env, "effect clear", ctx) == 1  # no targets: the executor


# ---------------------------------------------------------------------- attribute
def test_attribute_defaults_modifiers_and_scale(env):
    _, ctx = player(env)
    assert run(env, "attribute @s minecraft:movement_speed get 1000", ctx) == 100  # player base 0.1
    assert run(env, "attribute @s minecraft:generic.max_health base get", ctx, (1, 21, 1)) == 20  # the pre-1.21.2 name
    run(env, "attribute @s movement_speed modifier add t:a 0.05 add_value", ctx)
    run(env, "attribute @s movement_speed modifier add t:b 1 add_multiplied_base", ctx)
    run(env, "attribute @s movement_speed modifier add t:c 0.5 add_multiplied_total", ctx)
    # (0.1 + 0.05) + 0.15 x 1, then x 1.5
    assert run(env, "attribute @s movement_speed get 1000", ctx) == 450
    assert run(env, "attribute @s movement_speed modifier value get t:b 10", ctx) == 10
    with pytest.raises(CommandFailure, match="already present"):
        run(env, "attribute @s movement_speed modifier add t:a 1 add_value", ctx)
    assert run(env, "attribute @s movement_speed modifier remove t:a", ctx) == 1
    with pytest.raises(CommandFailure, match="has no modifier t:a"):
        run(env, "attribute @s movement_speed modifier remove t:a", ctx)


def test_attribute_range_and_reset(env):
    steve, ctx = player(env)
    run(env, "attribute @s max_health base set 5000", ctx)
    assert run(env, "attribute @s max_health get", ctx) == 1024  # RangedAttribute's maximum
    assert run(env, "attribute @s max_health base get", ctx) == 5000
    run(env, "attribute @s max_health base set 4", ctx)
    assert float(steve.data["Health"]) == 4.0  # the health follows a lower maximum
    run(env, "attribute @s max_health base reset", ctx)
    assert run(env, "attribute @s max_health base get", ctx) == 20


def test_attribute_a_mob_does_not_have(env):
    env.state.entities.summon("minecraft:pig", (0, 0, 0))
    with pytest.raises(CommandFailure, match="has no attribute"):
        run(env, "attribute @e[type=pig,limit=1] luck get")  # players have luck, mobs do not


def test_an_attribute_saved_under_its_older_name_is_read(env):
    # before 1.21.2 the game saves ``minecraft:generic.max_health`` (Attributes' older ids); the
    # instance is the same attribute whichever name it was given by
    env.state.entities.summon("minecraft:pig", (0, 0, 0), Compound(attributes=List([Compound(
        id=String("minecraft:generic.max_health"), base=Double(30.0))])))
    assert run(env, "attribute @e[type=pig,limit=1] max_health base get") == 30


def _at(env, release):
    env.state.version = env.state.entities.version = release  # as the runtime sets them at load
    return env


def test_attributes_are_saved_in_the_releases_layout(env):
    # AttributeInstance.save writes the registry key: ``minecraft:max_health`` from 1.21.2 (24w36a
    # dropped the prefixes), ``minecraft:generic.max_health`` and ``minecraft:player.block_
    # interaction_range`` in 1.20.5 - 1.21.1; LivingEntity.addAdditionalSaveData writes
    # ``attributes`` [{id, base}] from 1.20.5 and ``Attributes`` [{Name, Base}] before
    saved = {}
    for release, name in (((1, 21, 4), "max_health"), ((1, 21, 1), "generic.max_health"),
                          ((1, 20, 4), "generic.max_health")):
        state_env = _at(Env(new_state(), {}, set()), release)
        steve, ctx = player(state_env)
        run(state_env, f"attribute @s {name} base set 30", ctx, release)
        if release == (1, 21, 1):
            run(state_env, "attribute @s player.block_interaction_range base get", ctx, release)
        saved[release] = steve.data
    assert {str(i["id"]) for i in saved[(1, 21, 4)]["attributes"]} >= {"minecraft:max_health"}
    assert {str(i["id"]) for i in saved[(1, 21, 1)]["attributes"]} >= {
        "minecraft:generic.max_health", "minecraft:player.block_interaction_range"}
    old = saved[(1, 20, 4)]
    assert "attributes" not in old and [(str(i["Name"]), float(i["Base"])) for i in old["Attributes"]] == [
        ("minecraft:generic.max_health", 30.0)]


def test_scale_is_no_attribute_before_1_20_5(env):
    # generic.scale came with 1.20.5: a zombie's size reads no instance of it before, and saves none
    zombie = _at(env, (1, 20, 4)).state.entities.summon("minecraft:zombie", (0, 0, 0))
    assert "Attributes" not in zombie.data and "attributes" not in zombie.data
    zombie = _at(Env(new_state(), {}, set()), (1, 20, 6)).state.entities.summon("minecraft:zombie", (0, 0, 0))
    assert [str(i["id"]) for i in zombie.data["attributes"]] == ["minecraft:generic.scale"]


def test_modifiers_saved_before_1_20_5_count(env):
    # AttributeModifier.load before 1.20.5: Amount and Operation 0 (add), 1 (multiply_base), 2 (multiply)
    _at(env, (1, 20, 4)).state.entities.summon("minecraft:pig", (0, 0, 0), Compound(Attributes=List([Compound(
        Name=String("minecraft:generic.max_health"), Base=Double(10.0), Modifiers=List([
            Compound(Name=String("a"), Amount=Double(2.0), Operation=Int(0)),
            Compound(Name=String("b"), Amount=Double(0.5), Operation=Int(2))]))])))
    assert run(env, "attribute @e[type=pig,limit=1] generic.max_health get", version=(1, 20, 4)) == 18


def test_reading_an_attribute_writes_no_empty_modifiers(env):
    # AttributeInstance.save writes ``modifiers`` only when there is one
    steve, ctx = player(env)
    run(env, "attribute @s luck get", ctx)
    with pytest.raises(CommandFailure, match="has no modifier"):
        run(env, "attribute @s luck modifier value get t:x", ctx)
    assert [sorted(i) for i in steve.data["attributes"] if str(i["id"]) == "minecraft:luck"] == [["base", "id"]]


def test_attribute_modifiers_before_1_21_are_known_by_a_uuid(env):
    # AttributeCommand of 1.16 - 1.20.4: `modifier add UUID NAME VALUE add|multiply_base|multiply`,
    # `remove UUID`, `value get UUID [SCALE]` (UuidArgument, StringArgumentType.string());
    # AttributeModifier.save writes {Name, Amount, Operation 0 - 2, UUID (UUIDUtil: four ints)};
    # AttributeInstance.addPermanentModifier refuses a second modifier of a UUID
    release = (1, 20, 4)
    steve, ctx = player(_at(env, release))
    assert run(env, 'attribute @s generic.max_health modifier add 1-2-3-4-5 "my  boost" 4 add', ctx, release) == 1
    assert run(env, "attribute @s generic.max_health modifier add 0-0-0-0-6 half 0.5 multiply", ctx, release) == 1
    assert run(env, "attribute @s generic.max_health get", ctx, release) == 36  # (20 + 4) x 1.5
    assert run(env, "attribute @s generic.max_health modifier value get 1-2-3-4-5 10", ctx, release) == 40
    [instance] = [i for i in steve.data["Attributes"] if str(i["Name"]) == "minecraft:generic.max_health"]
    assert [dict(m) for m in instance["Modifiers"]] == [
        {"Name": "my  boost", "Amount": 4.0, "Operation": 0, "UUID": [1, 2 << 16 | 3, 4 << 16, 5]},
        {"Name": "half", "Amount": 0.5, "Operation": 2, "UUID": [0, 0, 0, 6]}]
    assert type(instance["Modifiers"][0]["UUID"]).__name__ == "IntArray"
    with pytest.raises(CommandFailure, match="Modifier 00000001-0002-0003-0004-000000000005 is already present"):
        run(env, "attribute @s generic.max_health modifier add 1-2-3-4-5 other 1 add", ctx, release)
    assert run(env, "attribute @s generic.max_health modifier remove 00000001-0002-0003-0004-000000000005", ctx,
               release) == 1
    with pytest.raises(CommandFailure, match="has no modifier 00000001-0002-0003-0004-000000000005"):
        run(env, "attribute @s generic.max_health modifier remove 1-2-3-4-5", ctx, release)
    assert run(env, "attribute @s generic.max_health get", ctx, release) == 30


def test_attribute_modifiers_of_1_20_5_are_saved_by_the_codec(env):
    # 1.20.5 - 1.20.6: the operations are named add_value, add_multiplied_base, add_multiplied_total
    # (AttributeModifier.Operation), and AttributeModifier.CODEC saves {uuid, name, amount, operation}
    release = (1, 20, 6)
    steve, ctx = player(_at(env, release))
    run(env, "attribute @s generic.armor modifier add 0-0-0-0-1 plates 2 add_multiplied_base", ctx, release)
    run(env, "attribute @s generic.armor base set 4", ctx, release)
    assert run(env, "attribute @s generic.armor get", ctx, release) == 12  # 4 + 4 x 2
    [instance] = [i for i in steve.data["attributes"] if str(i["id"]) == "minecraft:generic.armor"]
    assert [dict(m) for m in instance["modifiers"]] == [
        {"uuid": [0, 0, 0, 1], "name": "plates", "amount": 2.0, "operation": "add_multiplied_base"}]


# ---------------------------------------------------------------------- damage
def test_damage_lowers_health_and_respects_the_hurt_cooldown(env):
    pig = env.state.entities.summon("minecraft:pig", (0, 0, 0))
    assert float(pig.data["Health"]) == 10.0
    assert run(env, "damage @e[type=pig,limit=1] 3") == 1
    assert float(pig.data["Health"]) == 7.0 and pig.data["HurtTime"] == 10
    with pytest.raises(CommandFailure, match="invulnerable"):
        run(env, "damage @e[type=pig,limit=1] 2")  # within the cooldown, not more than the last hurt
    run(env, "damage @e[type=pig,limit=1] 5")  # only the excess over 3 applies
    assert float(pig.data["Health"]) == 5.0
    run(env, "damage @e[type=pig,limit=1] 100 minecraft:out_of_world")
    assert not pig.alive  # a mob at 0 health dies


def test_creative_players_and_invulnerable_mobs_take_no_damage(env):
    steve, ctx = player(env)
    steve.gamemode = "creative"
    with pytest.raises(CommandFailure, match="invulnerable"):
        run(env, "damage @s 1", ctx)
    env.state.entities.summon("minecraft:cow", (0, 0, 0), Compound(Invulnerable=Byte(1)))
    with pytest.raises(CommandFailure, match="invulnerable"):
        run(env, "damage @e[type=cow,limit=1] 1")


def test_armour_absorbs_damage_unless_the_type_bypasses_it(env):
    """LivingEntity.getDamageAfterArmorAbsorb: damage types in #bypasses_armor (generic, magic ...:
    DamageTypeTagsProvider) skip CombatRules.getDamageAfterAbsorb."""
    zombie = env.state.entities.summon("minecraft:zombie", (0, 0, 0))  # 2 armour points
    run(env, "damage @e[type=zombie,limit=1] 5 minecraft:mob_attack")
    assert float(zombie.data["Health"]) == pytest.approx(20 - 5 * (1 - 0.4 / 25), rel=1e-6)
    other = env.state.entities.summon("minecraft:zombie", (0, 0, 0))
    other.tags.add("second")
    run(env, "damage @e[tag=second,limit=1] 5")
    assert float(other.data["Health"]) == 15.0


def test_set_points_compares_as_ints_at_huge_levels(env):
    """A library's trick for a full bar: at level 111111129 the level holds 1000000003 points, so
    ``xp set 1000000000 points`` is allowed (int compare) and the float progress reads 1.0f."""
    steve, ctx = player(env)
    run(env, "xp set @s 111111129 levels", ctx)
    assert run(env, "xp set @s 1000000000 points", ctx) == 1
    assert float(steve.data["XpP"]) == 1.0


def test_instant_effects_shift_as_java_ints(env):
    """HealOrHarmMobEffect: heal max(4 << amplifier, 0) with Java's int shift (distance mod 32):
    amplifier 255 heals nothing, 28 heals 2^30; instant damage heals the undead. Each acts in the
    entity's next tick (MobEffectInstance.tickServer), not in the command."""
    pig = env.state.entities.summon("minecraft:pig", (0, 0, 0), Compound(Health=Float(2.0)))
    run(env, "effect give @e[type=pig] minecraft:instant_health 1 255")
    living.tick_living(env.state)
    assert float(pig.data["Health"]) == 2.0
    run(env, "effect give @e[type=pig] minecraft:instant_health 1 28")
    assert float(pig.data["Health"]) == 2.0 and "active_effects" in pig.data
    living.tick_living(env.state)
    assert float(pig.data["Health"]) == 10.0  # up to its max health
    assert "active_effects" not in pig.data
    zombie = env.state.entities.summon("minecraft:zombie", (0, 0, 0), Compound(Health=Float(5.0)))
    run(env, "effect give @e[type=zombie] minecraft:instant_damage 1 0")
    living.tick_living(env.state)
    assert float(zombie.data["Health"]) == 9.0  # healed by 4 << 0, as instant health would


def test_an_instant_effect_waits_for_the_tick_and_a_weaker_one_changes_nothing(env):
    """EffectCommands.giveEffect: an instant effect's seconds are ticks, each tick applies it once;
    MobEffectInstance.update: a lower amplifier does not replace the waiting one (the command
    fails), which is why libraries clear a stronger one first."""
    pig = env.state.entities.summon("minecraft:pig", (0, 0, 0), Compound(Health=Float(1.0)))
    run(env, "effect give @e[type=pig] minecraft:instant_health 3 0")
    assert [int(e["duration"]) for e in pig.data["active_effects"]] == [3]
    with pytest.raises(CommandFailure, match="has something stronger"):
        run(env, "effect give @e[type=pig] minecraft:instant_health 2 0")
    healths = []
    for _ in range(4):
        living.tick_living(env.state)
        healths.append(float(pig.data["Health"]))
    assert healths == [5.0, 9.0, 10.0, 10.0]


# ---------------------------------------------------------------------- gamemode
def test_gamemode_counts_the_players_it_changed(env):
    """GameModeCommand.setMode: ServerPlayer.setGameMode is false for the mode a player has, which
    is not counted and does not fail the command; no target: the executor."""
    steve, ctx = player(env)
    alex, _ = player(env, "Alex")
    assert run(env, "gamemode creative", ctx) == 1
    assert (steve.gamemode, alex.gamemode) == ("creative", "survival")
    assert run(env, "gamemode creative @a") == 1
    assert run(env, "gamemode creative @a") == 0
    assert run(env, "execute if entity @a[gamemode=creative,name=Alex]") == 1
    with pytest.raises(CommandFailure):
        run(env, "gamemode survival")  # the server is no player


@pytest.mark.parametrize("command, message", [
    # EntityArgument.getPlayers / getPlayer (EntitySelector.findSinglePlayer): NO_PLAYERS_FOUND
    ("xp add @a 1", "No player was found"), ("xp query @p levels", "No player was found"),
    ("gamemode creative @a", "No player was found"), ("recipe give @a *", "No player was found"),
    ("give @a stone", "No player was found"),
    ("xp add Nobody 1", "No player was found"), ("damage Nobody 1", "No entity was found"),
    # a UUID parses in an entity argument only (EntitySelectorParser.parseNameOrUUID: includesEntities)
    ("damage {uuid} 1", "commands.damage.invulnerable"),
    # EntityArgument.getEntities / getEntity: NO_ENTITIES_FOUND
    ("effect give @e[type=pig] speed", "No entity was found"), ("damage @e[type=pig,limit=1] 1", "No entity was found"),
    ("attribute @e[type=pig,limit=1] scale get", "No entity was found"),
])
def test_an_empty_target_fails_with_its_argument_types_message(env, command, message):
    uuid = env.state.entities.summon("minecraft:marker", (0.0, 0.0, 0.0)).uuid_string
    with pytest.raises(CommandFailure) as failure:
        run(env, command.format(uuid=uuid))
    assert message in (failure.value.message, failure.value.key)


def test_attribute_messages_name_the_attribute_as_en_us_does(env):
    # Attribute.getDescriptionId: attribute.name.<its registry path>, whose en_us text names it in the
    # failures (movement_speed reads Speed, follow_range Mob Follow Range; 1.21.1's keep generic.)
    _, ctx = player(env)
    with pytest.raises(CommandFailure, match="^Attribute Speed for entity Steve has no modifier minecraft:x$"):
        run(env, "attribute @s movement_speed modifier remove x", ctx)
    env.state.entities.summon("minecraft:pig", (0, 0, 0))
    with pytest.raises(CommandFailure, match="^Entity Pig has no attribute Block Interaction Range$"):
        run(env, "attribute @e[type=pig,limit=1] block_interaction_range get")


# ---------------------------------------------------------------------- waypoint
def test_waypoint_modify_saves_the_locator_bar_icon(env):
    """WaypointCommand.mutateIcon (1.21.6+): the icon's colour and style, saved by LivingEntity as
    locator_bar_icon while either differs from the default (Waypoint.Icon.hasData); the result is 0."""
    steve, ctx = player(env)
    version = (1, 21, 6)
    assert run(env, "waypoint modify Steve color red", ctx, version) == 0
    assert steve.data["locator_bar_icon"] == Compound(style=String("minecraft:default"), color=Int(0xFF5555))
    run(env, "waypoint modify Steve style set ns:ring", ctx, version)
    run(env, "waypoint modify Steve color hex 00FF00", ctx, version)
    assert steve.data["locator_bar_icon"] == Compound(style=String("ns:ring"), color=Int(0x00FF00))
    run(env, "waypoint modify Steve color reset", ctx, version)
    run(env, "waypoint modify Steve style reset", ctx, version)
    assert "locator_bar_icon" not in steve.data
    env.state.entities.summon("minecraft:marker", (0.0, 0.0, 0.0), Compound(Tags=List([String("m")])))
    with pytest.raises(CommandFailure, match="Selected entity is not a waypoint"):
        run(env, "waypoint modify @e[tag=m,limit=1] color red", ctx, version)
    with pytest.raises(Unmodelled):
        run(env, "waypoint list", ctx, version)
