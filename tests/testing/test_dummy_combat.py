"""Dummies hurting, hurt, dying and respawning (emulator.world.combat), with what a pack observes.
Sources: the game's LivingEntity.hurtServer/actuallyHurt/die/getKillCredit, Player.actuallyHurt
(damage_taken, damage_absorbed), ServerPlayer.die/awardKillScore/restoreFrom, Player.dropEquipment
and Inventory.dropAll, ExperienceOrb.getExperienceValue, PlayerHurtEntityTrigger,
EntityHurtPlayerTrigger, KilledTrigger, DamageCommand; misode/packtest Dummy.respawn."""
import json

import pytest

from tests.conftest import OPEN_AREA
from tests.testing.test_dummy_hands import run


def advancement(trigger, conditions=None):
    return json.dumps({"criteria": {"c": {"trigger": trigger, **({"conditions": conditions} if conditions else {})}}})


HURT = {
    "demo/advancement/hit_pig.json": advancement("minecraft:player_hurt_entity", {
        "damage": {"dealt": {"min": 0.1}, "type": {"is_direct": True, "direct_entity": {"type": "minecraft:player"}}},
        "entity": {"type": "minecraft:pig"}}),
    "demo/advancement/hit_cow.json": advancement("minecraft:player_hurt_entity", {"entity": {"type": "minecraft:cow"}}),
    "demo/advancement/hurt.json": advancement("minecraft:entity_hurt_player", {"damage": {"taken": {"min": 2}}}),
    "demo/advancement/killed_pig.json": advancement("minecraft:player_killed_entity", {"entity": {"type": "minecraft:pig"}}),
    "demo/advancement/was_killed.json": advancement("minecraft:entity_killed_player", {
        "entity": {"type": "minecraft:player"}}),
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_hurting_and_being_hurt_fire_their_criteria(tmp_path, backend):
    result = run(tmp_path, (
        "scoreboard objectives add taken minecraft.custom:minecraft.damage_taken\n"
        "dummy Alex spawn\n"
        "await delay 60\n"  # spawn protection: no damage for the first 60 ticks (ServerPlayer.hurt)
        "summon pig ~1 ~ ~ {Tags:[\"p\"]}\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert entity @a[name=Alex,advancements={demo:hit_pig=true,demo:hit_cow=false,demo:hurt=false}]\n"
        "damage Alex 1\n"
        "assert entity @a[name=Alex,advancements={demo:hurt=false}]\n"
        "assert score Alex taken matches 10\n"
        "await delay 11\n"                                  # past the hurt cooldown
        "damage Alex 2.5\n"
        "assert entity @a[name=Alex,advancements={demo:hurt=true}]\n"
        "assert score Alex taken matches 35\n"), files=HURT, backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_dummy_dies_drops_its_inventory_and_experience_and_respawns(tmp_path, backend):
    # sky access and the dummy in the middle of the 1-block structure: the drops come at its eyes
    # less 0.3, where the barrier ceiling or walls would be (an item inside a block is pushed out:
    # not what this tests)
    result = run(tmp_path, "# @skyaccess\n" + (
        "scoreboard objectives add deaths deathCount\n"
        "scoreboard objectives add died minecraft.custom:minecraft.deaths\n"
        "scoreboard objectives add alive minecraft.custom:minecraft.time_since_death\n"
        "execute positioned ~0.5 ~ ~0.5 run dummy Alex spawn\n"
        "give Alex stone 5\n"
        "item replace entity Alex armor.head with leather_helmet\n"
        "xp set Alex 10 levels\n"
        "await delay 63\n"  # spawn protection: no damage for the first 60 ticks (ServerPlayer.hurt)
        "assert score Alex alive matches 63\n"
        "damage Alex 100\n"
        "assert chat \"^Alex died$\"\n"
        "assert score Alex deaths matches 1\nassert score Alex died matches 1\n"
        "assert not score Alex alive matches 0..\n"          # reset (1.20.3+: unset)
        "assert entity @a[name=Alex]\nassert not entity @e[type=player]\nassert not entity @n[type=player]\n"
        "assert data entity Alex {Health:0.0f}\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:stone\",count:5},PickupDelay:40s}]\n"
        "assert not entity @e[type=item,nbt={Thrower:[I;0,0,0,0]}]\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:leather_helmet\"}}]\n"
        # 70 points: 37, 17, 7, 7, 1, 1 (ExperienceOrb.getExperienceValue)
        "execute store result score #orbs deaths if entity @e[type=experience_orb]\n"
        "assert score #orbs deaths matches 6\n"
        "assert entity @e[type=experience_orb,nbt={Value:37s}]\n"
        "await delay 25\n"
        "assert data entity Alex {DeathTime:20s}\n"
        "assert not score Alex alive matches 0..\n"          # time_since_death counts only while alive
        "dummy Alex respawn\n"
        "assert entity @e[type=player,name=Alex]\n"
        "assert data entity Alex {Health:20.0f,XpLevel:0}\n"
        "assert not items entity Alex container.* *\n"
        "assert score Alex deaths matches 1\n"), files=HURT, backend=backend)
    assert result.status == "passed", result.report()


def test_the_recipe_book_outlives_death(tmp_path):
    # ServerPlayer.restoreFrom: recipeBook.copyOverData whatever keepInventory says
    recipe = json.dumps({"type": "minecraft:crafting_shapeless", "ingredients": ["minecraft:stick"],
                         "result": {"id": "minecraft:stick"}})
    result = run(tmp_path, (
        "dummy Alex spawn\n"
        "recipe give Alex demo:wand\n"
        "kill Alex\n"
        "dummy Alex respawn\n"
        "assert entity @a[name=Alex,nbt={recipeBook:{recipes:['demo:wand']}}]\n"), files={
        "demo/recipe/wand.json": recipe}, pack_format=61)  # the ingredient as an id: 1.21.2+
    assert result.status == "passed", result.report()


def test_keep_inventory_keeps_items_and_experience_through_death(tmp_path):
    result = run(tmp_path, (
        "gamerule keepInventory true\n"
        "dummy Alex spawn\n"
        "give Alex stone 5\nxp set Alex 3 levels\n"
        "kill Alex\n"
        "assert chat \"^Alex was killed$\"\n"
        "assert not entity @e[type=item]\nassert not entity @e[type=experience_orb]\n"
        "dummy Alex respawn\n"
        "assert items entity Alex container.0 stone[count=5]\n"
        "assert data entity Alex {XpLevel:3}\n"))
    assert result.status == "passed", result.report()


def test_a_player_killed_by_a_player_credits_the_killer(tmp_path):
    """DamageCommand ``by``: the source's entity is the killer; the victim counts killed_by:player, the
    killer player_kills, killed:player and the kill criteria; the death message names the killer."""
    result = run(tmp_path, (
        "scoreboard objectives add kills playerKillCount\n"
        "scoreboard objectives add by minecraft.killed_by:minecraft.player\n"
        "scoreboard objectives add pk minecraft.custom:minecraft.player_kills\n"
        "dummy Alex spawn\ndummy Bob spawn\n"
        "tp Bob ~2 ~ ~\n"
        "await delay 60\n"  # spawn protection: no damage for the first 60 ticks (ServerPlayer.hurt)
  # not where Alex stands: from there the hurt's knockback would be random
        "damage Bob 50 minecraft:player_attack by Alex\n"
        "assert chat \"^Bob was slain by Alex$\"\n"
        "assert score Alex kills matches 1\nassert score Alex pk matches 1\nassert score Bob by matches 1\n"
        "assert entity @a[name=Bob,advancements={demo:was_killed=true}]\n"), files=HURT)
    assert result.status == "passed", result.report()


def test_the_last_player_to_hurt_a_mob_gets_the_kill(tmp_path):
    """LivingEntity.getKillCredit: the player who hurt it within 100 ticks, whatever dealt the blow."""
    result = run(tmp_path, (
        "scoreboard objectives add pigs minecraft.killed:minecraft.pig\n"
        "dummy Alex spawn\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"],DeathLootTable:\"minecraft:empty\"}\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "await delay 20\n"
        "damage @e[tag=p,limit=1] 100\n"
        "assert not entity @e[tag=p]\n"
        "assert score Alex pigs matches 1\n"
        "assert entity @a[name=Alex,advancements={demo:killed_pig=true}]\n"), files=HURT)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("setup, reason", [
    ("give Alex diamond_sword[enchantments={fire_aspect:1}]\ndummy Alex attack @e[type=pig,limit=1]",
     "the effects of minecraft:fire_aspect on an attack"),
    # where the fall was from a ladder (FallLocation, from the last climbable position): not modelled
    ("setblock ~ ~ ~ ladder\ndamage Alex 100 minecraft:fall", "a fall from a climbable block"),
])
def test_what_combat_does_not_model_makes_the_test_inconclusive(tmp_path, setup, reason):
    result = run(tmp_path, f"dummy Alex spawn\nawait delay 60\nsummon pig ~1 ~ ~\n{setup}\nsucceed\n")
    assert result.status == "inconclusive", result.report()
    assert reason in result.message


ARMOUR_WORN = {"demo/advancement/worn.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:item_durability_changed",
    "conditions": {"item": {"items": "minecraft:iron_chestplate"}, "delta": -2}}}})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_hurt_players_armour_wears_unless_the_damage_bypasses_armour(tmp_path, backend):
    """LivingEntity.getDamageAfterArmorAbsorb -> Player.hurtArmor -> doHurtEquipment: each armour
    piece takes max(1, damage / 4) (int) through ItemStack.hurtAndBreak (item_durability_changed);
    generic damage is in #bypasses_armor; netherite resists fire damage (canBeHurtBy). A knockback
    resistance of 1 keeps off the hurt's knockback, whose direction with no source position is
    random (LivingEntity.knockback: Math.random)."""
    result = run(tmp_path, OPEN_AREA + (
        "dummy Alex spawn\n"
        "await delay 60\n"  # spawn protection: no damage for the first 60 ticks (ServerPlayer.hurt)
        "attribute Alex generic.knockback_resistance base set 1\n"
        "item replace entity Alex armor.chest with iron_chestplate\n"
        "item replace entity Alex armor.feet with netherite_boots\n"
        "item replace entity Alex armor.head with carved_pumpkin\n"
        "damage Alex 3 minecraft:mob_attack\n"
        "assert items entity Alex armor.chest iron_chestplate[damage=1]\n"
        "assert items entity Alex armor.feet netherite_boots[damage=1]\n"
        "assert entity @a[name=Alex,advancements={demo:worn=false}]\n"
        "await delay 11\n"
        "damage Alex 8.5 minecraft:mob_attack\n"             # 8.5 / 4 = 2.125 -> 2 points
        "assert items entity Alex armor.chest iron_chestplate[damage=3]\n"
        "assert entity @a[name=Alex,advancements={demo:worn=true}]\n"
        "await delay 11\n"
        "damage Alex 4\n"                                    # generic bypasses armour
        "assert items entity Alex armor.chest iron_chestplate[damage=3]\n"
        "await delay 11\n"
        "damage Alex 1 minecraft:in_fire\n"
        "assert items entity Alex armor.chest iron_chestplate[damage=4]\n"
        "assert items entity Alex armor.feet netherite_boots[damage=3]\n"), files=ARMOUR_WORN, backend=backend)
    assert result.status == "passed", result.report()


def test_protection_on_a_hurt_players_armour_is_inconclusive(tmp_path):
    result = run(tmp_path, (
        "dummy Alex spawn\nawait delay 60\n"
        "item replace entity Alex armor.chest with iron_chestplate[enchantments={protection:1}]\n"
        "damage Alex 3 minecraft:mob_attack\nsucceed\n"))
    assert result.status == "inconclusive", result.report()
    assert "minecraft:protection" in result.message


def test_death_messages_read_the_damage_types_message(tmp_path):
    """CombatTracker.getDeathMessage -> DamageSource.getLocalizedDeathMessage: death.attack.<msgId>
    of the damage type (DamageTypes.bootstrap: drown -> "drown", arrow -> "arrow", bad_respawn_point
    -> "badRespawnPoint" with its "[Intentional Game Design]" link), the ``.player`` form naming the
    killer credited when the source has no entity, the ``.item`` form when the responsible entity's
    main hand holds a named item; en_us texts of the release."""
    result = run(tmp_path, OPEN_AREA + (
        "dummy Ann spawn\ndummy Bob spawn\ndummy Cid spawn\ndummy Dee spawn\n"
        "await delay 60\n"  # spawn protection: no damage for the first 60 ticks (ServerPlayer.hurt)
        "tp Bob ~2 ~ ~\ntp Cid ~4 ~ ~\ntp Dee ~6 ~ ~\n"
        "summon skeleton ~ ~ ~3 {NoAI:1b,Tags:[\"s\"],HandItems:[{id:\"minecraft:bow\",count:1,"
        "components:{\"minecraft:custom_name\":'\"Bolt\"'}},{}]}\n"
        "damage Ann 100 minecraft:drown\n"
        "assert chat \"^Ann drowned$\"\n"
        "damage Bob 1 minecraft:player_attack by Ann\n"
        "damage Bob 100 minecraft:drown\n"
        "assert chat \"^Bob drowned while trying to escape Ann$\"\n"
        "damage Cid 100 minecraft:arrow by @e[tag=s,limit=1]\n"
        "assert chat \"^Cid was shot by Skeleton using \\\\[Bolt\\\\]$\"\n"
        "damage Dee 100 minecraft:bad_respawn_point\n"
        "assert chat \"^Dee was killed by \\\\[Intentional Game Design\\\\]$\"\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_fall_deaths_read_the_combat_trackers_most_significant_fall(tmp_path, backend):
    """CombatTracker.getDeathMessage for the fall types: the most significant fall (getMostSignificantFall:
    a fall over 5 blocks, the entry before it when there is one) gives death.fell.accident.generic, or
    when a mob's hurt (here without knockback: magic) came before the fall death.fell.assist naming it; a fall of no distance is the
    plain death.attack.fall (decompiled 1.21 CombatTracker, Entity.checkFallDamage)."""
    result = run(tmp_path, "# @skyaccess\n# @timeout 200\n" + OPEN_AREA + (
        "dummy Ann spawn\ndummy Bob spawn\ndummy Cid spawn\n"
        "await delay 60\n"  # spawn protection: no damage for the first 60 ticks (ServerPlayer.hurt)
        "tp Ann ~ ~ ~\ntp Bob ~2 ~30 ~\ntp Cid ~4 ~30 ~\n"
        "summon zombie ~6 ~ ~ {NoAI:1b,Tags:[\"z\"]}\n"
        "damage Ann 100 minecraft:fall\n"
        "assert chat \"^Ann hit the ground too hard$\"\n"
        "damage Cid 1 minecraft:magic by @e[tag=z,limit=1]\n"
        "await chat \"^Bob fell from a high place$\"\n"
        "await chat \"^Cid was doomed to fall by Zombie$\"\n"), backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("pack_format", [48, 61, 81])  # 1.21, 1.21.4 (knockback, then hurt), 1.21.7 (hurt, then knockback)
def test_a_full_sword_swing_on_the_ground_sweeps_the_mobs_beside_its_target(tmp_path, backend, pack_format):
    # Player.attack / doSweepAttack: the living entities in the target's box grown by 1, 0.25, 1 and
    # within 3 blocks take 1 + sweeping_damage_ratio (0) x the swing's damage as player_attack
    result = run(tmp_path, OPEN_AREA + (
        "dummy Alex spawn\n"
        "give Alex diamond_sword\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b}\n"
        "summon pig ~1 ~ ~1 {Tags:[\"q\"],NoAI:1b}\n"
        "summon pig ~1 ~ ~3 {Tags:[\"far\"],NoAI:1b}\n"
        "await delay 20\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert entity @e[tag=p,nbt={Health:3.0f}]\n"
        "assert entity @e[tag=q,nbt={Health:9.0f}]\n"
        "assert entity @e[tag=far,nbt={Health:10.0f}]\n"), pack_format=pack_format, backend=backend)
    assert result.status == "passed", result.report()
