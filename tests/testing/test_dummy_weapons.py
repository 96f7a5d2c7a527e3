"""Equipment's attribute modifiers and attacking with a weapon (emulator.world.equipment,
emulator.world.combat.attack). Sources (decompiled 1.21): LivingEntity.collectEquipmentChanges,
AttributeInstance.addTransientModifier/save, SwordItem/DiggerItem.createAttributes, Tiers,
ArmorItem/ArmorMaterials, Player.attack, ItemStack.hurtEnemy/postHurtEnemy/hurtAndBreak,
CombatRules.getDamageAfterAbsorb, the sharpness enchantment's data."""
import json
import zipfile

import pytest

from emulator.testing import discover, run_suite
from tests.conftest import OPEN_AREA, write_pack
from tests.parser.pack.packbuild import tag
from tests.testing.test_dummy_hands import run


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_held_weapons_modifiers_count_from_the_next_tick_and_are_not_saved(tmp_path, backend):
    """LivingEntity.tick -> collectEquipmentChanges adds the iron sword's base_attack_damage (6 - 1:
    SwordItem.createAttributes(IRON, 3, -2.4F), Tiers.IRON bonus 2) and base_attack_speed (-2.4F as
    a double) as transient modifiers; removed when the hand empties; AttributeInstance.save leaves
    them out of the NBT."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "dummy Alex spawn\n"
        "item replace entity Alex weapon.mainhand with iron_sword\n"
        "execute store result score #now v run attribute Alex generic.attack_damage get 10\n"
        "assert score #now v matches 10\n"
        "await delay 1\n"
        "execute store result score #held v run attribute Alex generic.attack_damage get 10\n"
        "assert score #held v matches 60\n"
        "execute store result score #mod v run attribute Alex generic.attack_damage modifier value get "
        "minecraft:base_attack_damage 10\n"
        "assert score #mod v matches 50\n"
        "execute store result score #speed v run attribute Alex generic.attack_speed get 1000000\n"
        "assert score #speed v matches 1599999\n"                # 4 + (double) -2.4F, truncated
        "assert not data entity Alex attributes[{id:\"minecraft:generic.attack_damage\"}].modifiers[0]\n"
        "item replace entity Alex weapon.mainhand with air\n"
        "await delay 1\n"
        "execute store result score #empty v run attribute Alex generic.attack_damage get 10\n"
        "assert score #empty v matches 10\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_worn_armour_counts_its_defense_and_toughness(tmp_path):
    """ArmorItem's defaults (ArmorMaterials.DIAMOND chestplate: 8 armor, 2 toughness) reduce a
    mob attack: CombatRules.getDamageAfterAbsorb: 10 x (1 - min(max(8 - 10 / 2.5, 1.6), 20) / 25)
    = 8.400001 in float math, so 11.599999 health is left (a knockback resistance of 1 keeps off the
    hurt's knockback, random with no source position)."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "dummy Alex spawn\n"
        "attribute Alex generic.knockback_resistance base set 1\n"
        "item replace entity Alex armor.chest with diamond_chestplate\n"
        "await delay 60\n"  # past its spawn protection (ServerPlayer.hurt: spawnInvulnerableTime)
        "execute store result score #armor v run attribute Alex generic.armor get\n"
        "assert score #armor v matches 8\n"
        "damage Alex 10 minecraft:mob_attack\n"
        "execute store result score #health v run data get entity Alex Health 1000\n"
        "assert score #health v matches 11599\n"))
    assert result.status == "passed", result.report()


USED = {"demo/advancement/worn.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:item_durability_changed",
    "conditions": {"item": {"items": "minecraft:iron_sword"}, "delta": -1}}}})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_full_swing_with_a_sharp_sword_deals_its_damage_and_wears_it(tmp_path, backend):
    """Player.attack: attack_damage 6 (iron sword) at full strength plus sharpness II (1 + 0.5);
    the pig (10 health) keeps 2.5; damage_dealt 75; ItemStack.hurtEnemy counts used:iron_sword and
    postHurtEnemy wears it by 1 (item_durability_changed)."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add dealt minecraft.custom:minecraft.damage_dealt\n"
        "scoreboard objectives add used minecraft.used:minecraft.iron_sword\n"
        "dummy Alex spawn\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"]}\n"
        "item replace entity Alex weapon.mainhand with iron_sword[enchantments={sharpness:2}]\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert entity @e[tag=p,nbt={Health:2.5f}]\n"
        "assert score Alex dealt matches 75\n"
        "assert score Alex used matches 1\n"
        "assert items entity Alex weapon.mainhand iron_sword[damage=1]\n"
        "assert entity @a[name=Alex,advancements={demo:worn=true}]\n"), files=USED, backend=backend)
    assert result.status == "passed", result.report()


def test_a_weapon_breaks_at_its_maximum_damage_unless_unbreakable(tmp_path):
    """ItemStack.hurtAndBreak: a golden sword (max 32) at 31 breaks (broken:golden_sword); an
    unbreakable axe takes no damage but still counts as used (DiggerItem.hurtEnemy)."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add broken minecraft.broken:minecraft.golden_sword\n"
        "scoreboard objectives add axe minecraft.used:minecraft.iron_axe\n"
        "dummy Alex spawn\n"
        "summon cow ~1 ~ ~ {Tags:[\"p\"],DeathLootTable:\"minecraft:empty\"}\n"
        "item replace entity Alex weapon.mainhand with golden_sword[damage=31]\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert score Alex broken matches 1\n"
        "assert not items entity Alex weapon.mainhand *\n"
        "item replace entity Alex weapon.mainhand with iron_axe[unbreakable={}]\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert score Alex axe matches 1\n"
        "assert items entity Alex weapon.mainhand iron_axe[damage=0]\n"))
    assert result.status == "passed", result.report()


def test_a_sweep_between_1_21_5_and_1_21_6_is_inconclusive(tmp_path):
    """Player.attack's sweep knocks back before the hurt in 1.21.4 and after a hurt that went
    through in 1.21.7: which holds in between is not known here."""
    result = run(tmp_path, OPEN_AREA + (
        "dummy Alex spawn\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"]}\nsummon pig ~1.5 ~ ~0.5\n"
        "item replace entity Alex weapon.mainhand with iron_sword\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\nsucceed\n"), pack_format=71)
    assert result.status == "inconclusive", result.report()
    assert "a sweep attack in 1.21.5" in result.message


def test_body_armour_on_a_mob_is_inconclusive(tmp_path):
    """Wolf armour's default modifiers (ArmorItem.Type.BODY) are not modelled: the wolf's tick says so."""
    result = run(tmp_path, OPEN_AREA + (
        "summon wolf ~1 ~ ~ {Tags:[\"w\"]}\n"
        "item replace entity @e[tag=w,limit=1] armor.body with wolf_armor\n"
        "await delay 2\nsucceed\n"))
    assert result.status == "inconclusive", result.report()
    assert "minecraft:wolf_armor" in result.message


def _with_jar(tmp_path, text, backend):
    """The test run with a game jar holding #minecraft:sensitive_to_smite (the zombie) and, as the
    game's does, #minecraft:no_knockback with generic_kill (``kill``)."""
    jar = tmp_path / "client.jar"
    with zipfile.ZipFile(jar, "w") as archive:
        archive.writestr("data/minecraft/tags/entity_type/sensitive_to_smite.json", tag("minecraft:zombie"))
        archive.writestr("data/minecraft/tags/damage_type/no_knockback.json", tag("minecraft:generic_kill"))
    root = write_pack(tmp_path / "pack", {"demo/test/t.mcfunction": text})
    [result] = run_suite(discover([root]), backend, game_jar=str(jar)).results
    return result


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_smite_adds_its_bonus_against_the_undead_only(tmp_path, backend):
    """Enchantments.SMITE (1.21 data): damage + 2.5 a level against #sensitive_to_smite. A full swing
    with a smite II stone sword (5) hits a zombie for 10 (its 2 armor: CombatRules leaves
    10 x (1 - max(2 - 10 / 2, 0.4) / 25) = 9.84, float math) and a pig for 5."""
    result = _with_jar(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "dummy Alex spawn\n"
        "summon zombie ~1 ~ ~ {Tags:[\"z\"],NoAI:1b}\n"
        "item replace entity Alex weapon.mainhand with stone_sword[enchantments={smite:2}]\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=z,limit=1]\n"
        "execute store result score #zombie v run data get entity @e[tag=z,limit=1] Health 1000\n"
        "assert score #zombie v matches 10159\n"                # 10.16f is 10.1599998...; data get floors
        "kill @e[tag=z]\n"
        "kill @e[type=experience_orb]\n"  # the zombie's
        "summon pig ~1 ~ ~ {Tags:[\"p\"]}\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert entity @e[tag=p,nbt={Health:5.0f}]\n"), backend)
    assert result.status == "passed", result.report()


def test_smite_without_the_games_tags_is_inconclusive(tmp_path):
    result = run(tmp_path, OPEN_AREA + (
        "dummy Alex spawn\nsummon pig ~1 ~ ~\n"
        "item replace entity Alex weapon.mainhand with stone_sword[enchantments={smite:1}]\n"
        "dummy Alex attack @e[type=pig,limit=1]\nsucceed\n"))
    assert result.status == "inconclusive", result.report()
    assert "#minecraft:sensitive_to_smite" in result.message


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_the_weapons_attack_speed_sets_the_swings_recharge(tmp_path, backend):
    """Player.getAttackStrengthScale(0.5): (ticks + 0.5) / (20 / attack_speed); the iron sword's
    1.6 speed (4 - 2.4F) recharges in 12.5 ticks, so 5 ticks after the last swing the strength is
    0.44 and the hit deals 6 x (0.2 + 0.8 x 0.44²) = 2.129 (float math): the pig keeps 7.871."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "dummy Alex spawn\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b}\n"
        "summon pig ~-3 ~ ~ {Tags:[\"q\"],NoAI:1b}\n"
        "item replace entity Alex weapon.mainhand with iron_sword\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=q,limit=1]\n"
        "await delay 5\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "execute store result score #health v run data get entity @e[tag=p,limit=1] Health 1000\n"
        "assert score #health v matches 7870\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_a_swing_with_attack_knockback_is_inconclusive(tmp_path):
    """Player.attack -> LivingEntity.knockback for getKnockback > 0: the Motion it sets is not modelled."""
    result = run(tmp_path, OPEN_AREA + (
        "dummy Alex spawn\nsummon pig ~1 ~ ~\n"
        "attribute Alex generic.attack_knockback base set 1\n"
        "dummy Alex attack @e[type=pig,limit=1]\nsucceed\n"))
    assert result.status == "inconclusive", result.report()
    assert "attack_knockback" in result.message


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_another_item_in_hand_restarts_the_swings_recharge(tmp_path, backend):
    """Player.tick: a main hand item that is not the same item as last tick's resets the attack
    strength ticker in the player's first tick after the sword is taken (after its ++), so of the 5
    player ticks before the swing 4 count: strength (4 + 0.5) / 12.5 = 0.36, the hit deals
    6 x (0.2 + 0.8 x 0.36²) = 1.82208 and the pig keeps 8.17792; a changed damage on the same item
    does not reset it (a full swing: 6 of the new pig's 10)."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "dummy Alex spawn\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b,DeathLootTable:\"minecraft:empty\"}\n"
        "await delay 20\n"
        "item replace entity Alex weapon.mainhand with iron_sword\n"
        "await delay 5\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "execute store result score #health v run data get entity @e[tag=p,limit=1] Health 1000\n"
        "assert score #health v matches 8177\n"
        "await delay 20\n"
        "item replace entity Alex weapon.mainhand with iron_sword[damage=5]\n"
        "await delay 5\n"
        "kill @e[tag=p]\nsummon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b}\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert entity @e[tag=p,nbt={Health:4.0f}]\n"), backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, hand, attribute", [(48, "HandItems[0]", "generic.attack_damage"),
                                                          (71, "equipment.mainhand", "attack_damage")])
@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_mobs_weapon_changed_in_place_in_its_nbt_changes_its_modifiers(tmp_path, backend, pack_format, hand,
                                                                          attribute):
    """LivingEntity.collectEquipmentChanges compares each slot's stack with the one its last tick
    kept (ItemStack.matches), however the stack came to change: here ``data modify`` edits the held
    sword's id and then its count in place (1.21: ``HandItems``; 1.21.5: ``equipment``, and the
    attribute's name without ``generic.`` from 1.21.2). The iron
    sword's base_attack_damage is 5 (SwordItem.createAttributes(IRON, 3, -2.4F), Tiers.IRON bonus
    2), the diamond sword's 6 (Tiers.DIAMOND bonus 3); an emptied hand has none."""
    zombie = "@e[tag=z,limit=1]"
    modifier = (f"execute store result score #mod v run attribute {zombie} {attribute} modifier value "
                "get minecraft:base_attack_damage 1\n")
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "summon zombie ~ ~ ~ {Tags:[\"z\"],NoAI:1b,PersistenceRequired:1b}\n"
        f"item replace entity {zombie} weapon.mainhand with iron_sword\n"
        "await delay 1\n" + modifier +
        "assert score #mod v matches 5\n"
        f"data modify entity {zombie} {hand}.id set value \"minecraft:diamond_sword\"\n"
        "await delay 1\n" + modifier +
        "assert score #mod v matches 6\n"
        f"data modify entity {zombie} {hand}.count set value 0\n"
        "await delay 1\n"
        f"execute store success score #has v run attribute {zombie} {attribute} modifier value get "
        "minecraft:base_attack_damage 1\n"
        "assert score #has v matches 0\n"), pack_format=pack_format, backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_attack_knocks_a_mob_back_but_leaves_a_players_motion_on_the_server(tmp_path, backend):
    """LivingEntity.hurtServer knocks the hurt entity away from the attacker (knockback 0.4F from
    the source position, the attacker's); Player.attack then sets a player target's motion back
    (its client gets the knockback: ServerPlayer.hurtMarked), so the server's Motion of Bob stays."""
    result = run(tmp_path, OPEN_AREA + (
        "scoreboard objectives add v dummy\n"
        "dummy Alex spawn\ndummy Bob spawn\n"
        "tp Bob ~1 ~ ~\n"
        "summon pig ~-1 ~ ~ {Tags:[\"p\"],NoAI:1b}\n"
        "await delay 60\n"  # past Bob's spawn protection (ServerPlayer.hurt: spawnInvulnerableTime)
        "dummy Alex attack Bob\n"
        "execute store result score #bob v run data get entity Bob Motion[0] 1000\n"
        "assert score #bob v matches 0\n"
        "assert entity @a[name=Bob,nbt={HurtTime:10s}]\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "execute store result score #pig v run data get entity @e[tag=p,limit=1] Motion[0] 1000\n"
        "assert score #pig v matches -401\n"), backend=backend)  # -0.4F as a double x 1000, floored
    assert result.status == "passed", result.report()
