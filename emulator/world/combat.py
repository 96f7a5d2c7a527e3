"""What follows a living entity's hurt: who gets the credit, the advancement triggers, and death
(a mob leaves the world; a player dies where it stands until it respawns), with what a datapack
observes of each.

- ``DamageSource`` (:class:`emulator.world.loot_context.DamageSource`, loot tables read it too).
- ``hurt(state, entity, amount, source, bypasses=False) -> bool``: LivingEntity.hurtServer: the
  health taken (emulator.world.living.hurt), the kill credit, death at 0 health, the triggers.
- ``attack(state, player, target) -> bool``: Player.attack (1.21+ for weapons): the attack damage
  attribute with the equipment's modifiers (emulator.world.equipment), the swing's strength, the
  sharpness/smite bonus, a critical hit (x 1.5) while falling, the weapon counted as used and
  damaged (1 for swords, tridents and maces, 2 for axes, pickaxes, shovels and hoes), the damage
  dealt, 0.1 exhaustion. A full hurt knocks the entity back from the source's position
  (LivingEntity.hurtServer -> knockback 0.4, not for #no_knockback types). Not modelled
  (Unmodelled): the sprinting full swing's and the knockback enchantment's knockback, a
  sweep that would hit another entity, other enchantments' attack effects (fire aspect, bane of
  arthropods' slowness, knockback, sweeping edge, a pack's own), the mace's smash, the weapon
  component, weapons before 1.21.
- ``remember_attacker(state, entity, source)``: the kill credit (the last player, else mob, to hurt
  it, for 100 ticks); ``hurt_triggers(state, entity, source, amount)``: LivingEntity.hurtServer's
  end: ``entity_hurt_player`` and ``player_hurt_entity``.
- ``die(state, entity, source)``: LivingEntity.die / ServerPlayer.die.
- ``respawn_keeps(state, old, new)``: what PlayerList.respawn carries to the new player.
- ``tick_dead(state)``: a dead player's ``DeathTime`` counts to 20; ``tick_is_idle(state)``: whether
  it would do nothing (a batch of ticks needs it idle).

A dead player stays in the player list (``@a``, ``@p``, ``@r``, ``@s`` find it; ``@e`` and ``@n`` do
not: EntitySelectorParser's isAlive test) at the place it died, with ``Health`` 0, until it respawns.
Its death (ServerPlayer.die): the death message to every player (``showDeathMessages``), its
inventory dropped (each stack thrown around from its eyes, pickup delay 40; cursed with vanishing:
destroyed) and experience orbs worth min(7 x level, 100) unless ``keepInventory``, the
``deathCount`` criterion and ``minecraft.custom:minecraft.deaths``, ``time_since_death`` and
``time_since_rest`` reset, ``minecraft.killed_by:<type>`` of its killer, the killer's kill
statistics, ``entity_killed_player``/``player_killed_entity``, and ``LastDeathLocation``.

Sources (decompiled 1.21.x): world/entity/LivingEntity.java (hurtServer, die, getKillCredit,
dropAllDeathLoot, dropExperience, setLastHurtByPlayer: 100 ticks), server/level/ServerPlayer.java
(die, awardKillScore, restoreFrom), world/entity/player/Player.java (dropEquipment,
getBaseExperienceReward), world/entity/player/Inventory.java (dropAll), world/entity/
ExperienceOrb.java (award, getExperienceValue), server/players/PlayerList.java (respawn),
advancements/critereon/{PlayerHurtEntityTrigger,EntityHurtPlayerTrigger,KilledTrigger}.java,
DamagePredicate.java, DamageSourcePredicate.java, EntityPredicate.createContext (the player's
position as origin); the death messages' en_us texts.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from emulator.world import (advancements, death_protection, equipment, fluids, inventories, items, living, loot, mth,
                            predicates, statistics, teams, tools, translations)
from emulator.world.entities import Entity
from emulator.world.entity_types import PROJECTILES
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, enchantment_level, enchantment_levels
from emulator.world.nbt_ops import is_numeric, numeric_value
from emulator.world.loot_context import DamageSource, LootContext
from mcfunction_parser.nbt import Compound, Double, Int, IntArray, List, Short, String

F32 = np.float32
CREDIT_TICKS = 100  # LivingEntity.setLastHurtByPlayer / setLastHurtByMob
EMPTY_TABLE = "minecraft:empty"  # BuiltInLootTables.EMPTY: no drops
MAX_DEATH_TIME = 20
ORB_VALUES = (2477, 1237, 617, 307, 149, 73, 37, 17, 7, 3, 1)  # ExperienceOrb.getExperienceValue
# Animal.getBaseExperienceReward (1 + nextInt(3)) and Monster's (5, without equipment)
ANIMALS = frozenset("pig cow sheep chicken rabbit mooshroom goat llama horse donkey mule camel turtle fox "
                    "panda polar_bear wolf cat ocelot frog sniffer armadillo".split())
MONSTERS = frozenset("zombie husk drowned skeleton stray bogged creeper spider cave_spider witch enderman "
                     "silverfish endermite vindicator pillager evoker ravager zombified_piglin piglin_brute "
                     "wither_skeleton blaze guardian".split())
# the vanilla damage types' message ids (DamageTypes.bootstrap, decompiled 1.21.x: DamageType.msgId);
# the death message is the en_us text of death.attack.<id> (CombatTracker.getDeathMessage)
MESSAGE_IDS = {f"minecraft:{pair.split('=')[0]}": pair.split("=")[1] for pair in (
    "in_fire=inFire campfire=inFire lightning_bolt=lightningBolt on_fire=onFire lava=lava hot_floor=hotFloor "
    "in_wall=inWall cramming=cramming drown=drown starve=starve cactus=cactus fall=fall ender_pearl=fall "
    "fly_into_wall=flyIntoWall out_of_world=outOfWorld generic=generic magic=magic wither=wither "
    "dragon_breath=dragonBreath dry_out=dryout sweet_berry_bush=sweetBerryBush freeze=freeze "
    "stalagmite=stalagmite falling_block=fallingBlock falling_anvil=anvil falling_stalactite=fallingStalactite "
    "sting=sting mob_attack=mob mob_attack_no_aggro=mob player_attack=player arrow=arrow trident=trident "
    "mob_projectile=mob spit=mob fireworks=fireworks unattributed_fireball=onFire fireball=fireball "
    "wither_skull=witherSkull thrown=thrown indirect_magic=indirectMagic thorns=thorns explosion=explosion "
    "player_explosion=explosion.player sonic_boom=sonic_boom bad_respawn_point=badRespawnPoint "
    "outside_border=outsideBorder generic_kill=genericKill wind_charge=mob mace_smash=mace_smash"
).split()}
FALL_VARIANTS = frozenset({"minecraft:fall", "minecraft:ender_pearl"})  # DeathMessageType.FALL_VARIANTS
INTENTIONAL_GAME_DESIGN = "minecraft:bad_respawn_point"  # DeathMessageType.INTENTIONAL_GAME_DESIGN


NO_ANGER = frozenset({"minecraft:mob_attack_no_aggro"})  # the game's #minecraft:no_anger damage types


def kill_credit(state, entity) -> Entity | None:
    """LivingEntity.getKillCredit: the last attacker within 100 ticks."""
    found = state.last_hurt_by.get(entity)
    if found is None or state.gametime - found[1] > CREDIT_TICKS:
        return None
    return found[0]


def last_attacker(state, entity) -> Entity | None:
    """LivingEntity.getLastAttacker (getLastHurtByMob): the last living entity to hurt it, until it
    dies or 100 ticks pass (LivingEntity.baseTick clears it)."""
    found = state.last_attacker.get(entity)
    if found is None or not found[0].alive or state.gametime - found[1] > CREDIT_TICKS:
        return None
    return found[0]


def hurt(state, entity, amount: float, source: DamageSource = DamageSource(), bypasses: bool = False) -> bool:
    """LivingEntity.hurtServer: False when the hurt does not go through (a player its teammate hurts
    without friendly fire: ServerPlayer.hurt -> canHarmPlayer; a player's damage scaled to nothing
    on peaceful); else the attacker gets the credit, an entity at 0 health dies, then the hurt's
    triggers fire."""
    attacker = source.attacker
    if entity.is_player and attacker is not None and attacker.is_player and not teams.can_harm(
            state.teams, entity, attacker):
        return False
    if (living.effect_amplifier(entity, "minecraft:fire_resistance") is not None
            and state.resources.in_tag("damage_type", "minecraft:is_fire", source.type)):
        return False  # LivingEntity.hurtServer: fire resistance refuses #is_fire damage
    if entity.is_player:
        if _ruled_out(state, source):
            return False
        amount = _difficulty_scaled(state, source, amount)
        if amount == 0.0:
            return False
    full = living.takes_full_hurt(state, entity, bypasses)
    if not living.hurt(state, entity, amount, bypasses, source.type, _armour_wear,
                       lambda damage: record_damage(state, entity, source, damage), source.attacker):
        return False
    remember_attacker(state, entity, source)
    if full:
        _hurt_knockback(state, entity, source)
    if living.health(entity) <= 0 and not death_protection.saves(state, entity, source.type, effect_harm):
        die(state, entity, source)
    hurt_triggers(state, entity, source, amount)
    return True


# DamageTypes.bootstrap: the types whose damage to a player always scales with the difficulty; every
# other vanilla type scales only when a living entity that is not a player causes it
# (DamageScaling.WHEN_CAUSED_BY_LIVING_NON_PLAYER)
ALWAYS_SCALED = frozenset("minecraft:" + t for t in ("explosion", "player_explosion", "sonic_boom", "bad_respawn_point"))


# Player.isInvulnerableTo: the damage type tags a game rule turns off for players
_DAMAGE_RULES = (("minecraft:is_drowning", "drowningDamage"), ("minecraft:is_fall", "fallDamage"),
                 ("minecraft:is_fire", "fireDamage"), ("minecraft:is_freezing", "freezeDamage"))


def _ruled_out(state, source: DamageSource) -> bool:
    """Whether a game rule spares players this damage (the first of the type's tags decides)."""
    for tag, rule in _DAMAGE_RULES:
        if state.resources.in_tag("damage_type", tag, source.type):
            return state.gamerules.get(rule) == "false"
    return False


def _difficulty_scaled(state, source: DamageSource, amount: float) -> float:
    """Player.hurtServer: damage from a source that scales with the difficulty
    (DamageSource.scalesWithDifficulty) is none on peaceful, min(d / 2 + 1, d) on easy, d * 3 / 2 on
    hard (float math). A pack's own damage type scales as its ``scaling`` says, which is not read:
    reported off normal, where nothing changes."""
    difficulty = state.level_settings.difficulty
    if difficulty == "normal":
        return amount
    if source.type not in living.EXHAUSTION:  # the vanilla types
        state.error(f"the difficulty scaling of damage type {source.type} is not modelled", severity="warning",
                    unmodelled=True)
        return amount
    attacker = source.attacker
    if source.type not in ALWAYS_SCALED and not (attacker is not None and living.is_living(attacker.type)
                                                 and not attacker.is_player):
        return amount
    damage = F32(amount)
    if difficulty == "peaceful":
        return 0.0
    if difficulty == "easy":
        return float(min(damage / F32(2.0) + F32(1.0), damage))
    return float(damage * F32(3.0) / F32(2.0))


KNOCKBACK_VERSION = (1, 21, 0)  # the hurt's knockback read from the source position (the 1.21 rule)
HURT_KNOCKBACK = float(F32(0.4))  # LivingEntity.hurtServer: knockback(0.4F, ...); a sweep's too
SWEEP_KNOCKBACK_FIRST = (1, 21, 4)  # up to it a swept entity is knocked back, then hurt (decompiled 1.21.3, 1.21.4)
SWEEP_HURT_FIRST = (1, 21, 7)  # from it hurt, then knocked back if the hurt went through (1.21.7, 26.1.2)


def _hurt_knockback(state, entity, source: DamageSource) -> None:
    """LivingEntity.hurtServer after a full hurt, unless the type is in #no_knockback: knockback
    0.4 away from the source position, or along a projectile's flight
    (:func:`emulator.world.living.knockback`); a player's motion is set as the server sets it
    (what moves it is its client's, or a dummy's tick). An armor stand's own hurt has none.
    Reported as not modelled: one with no source position or from the entity's own place (the
    game draws a random direction), and the rule before 1.21."""
    if entity.type == "minecraft:armor_stand" or state.resources.in_tag(
            "damage_type", "minecraft:no_knockback", source.type):
        return
    if tuple(state.version) < KNOCKBACK_VERSION:
        state.error(f"the knockback of {entity.display_name}'s hurt before 1.21", severity="warning", unmodelled=True)
        return
    if not living.knockback(entity, HURT_KNOCKBACK, *_knockback_direction(entity, source)):
        state.error(f"the knockback of {entity.display_name}'s hurt in a random direction (no source position)",
                    severity="warning", unmodelled=True)


def _knockback_direction(entity, source: DamageSource) -> tuple[float, float]:
    """LivingEntity.hurtServer's (x, z) for knockback: a projectile's own motion reversed
    (Projectile.calculateHorizontalHurtKnockbackDirection, negated), else the source position
    less the entity's, else (0, 0)."""
    if source.direct is not None and source.direct.type in PROJECTILES:
        motion = source.direct.motion
        return -motion[0], -motion[2]
    where = source.source_position
    return (0.0, 0.0) if where is None else (where[0] - entity.pos[0], where[2] - entity.pos[2])


def _armour_wear(state, entity, amount: float, damage_type: str) -> None:
    """Player.hurtArmor -> LivingEntity.doHurtEquipment: each worn armour item (ArmorItem; from
    1.21.2 an equippable item that takes damage when hurt) takes max(1, damage / 4) points through
    ItemStack.hurtAndBreak (Unbreaking, item_durability_changed, breaking), unless it resists fire
    and the damage is fire (ItemStack.canBeHurtBy). A mob's armour (from 1.21.2), a pack's
    equippable component and enchanted armour's hurt effects (protection, thorns ...) are not
    modelled."""
    version = tuple(state.version)
    worn = [inventories.entity_slot(entity, slot, version) for slot in inventories.ARMOR_SLOTS.values()]
    worn = [access for access in worn if access is not None and _wears(access.get())]
    if not worn or amount <= 0:
        return
    if not entity.is_player:
        if version >= MOB_ARMOUR_WEAR_VERSION:
            state.error(f"the wear of {entity.display_name}'s armour (LivingEntity.doHurtEquipment from 1.21.2)",
                        severity="warning", unmodelled=True)
        return
    for access in worn:
        stack = access.get()
        if stack.component("minecraft:equippable") is not None:
            raise Unmodelled(f"the wear of {stack.id} with its equippable component")
        enchanted = [e for e in _enchantments(stack, version) if e not in _INERT_ON_HURT]
        if enchanted:
            raise Unmodelled(f"the effects of {enchanted[0]} on armour when its wearer is hurt")
    points = int(max(F32(1.0), F32(amount) / F32(4.0)))
    fire = state.resources.in_tag("damage_type", "minecraft:is_fire", damage_type)
    for access in worn:
        stack = access.get()
        if fire and (stack.id.startswith("minecraft:netherite_") or stack.component("minecraft:fire_resistant")
                     is not None or stack.component("minecraft:damage_resistant") is not None):
            if stack.component("minecraft:damage_resistant") is not None:
                raise Unmodelled(f"the damage_resistant component of {stack.id}")
            continue
        tools.hurt_and_break(state, entity, access, points)


MOB_ARMOUR_WEAR_VERSION = (1, 21, 2)  # LivingEntity.hurtArmor wears any living entity's equipment
_ARMOUR_ITEMS = ("_helmet", "_chestplate", "_leggings", "_boots")  # ArmorItem's vanilla members (turtle_helmet too)
# enchantments with no effect when the wearer is hurt
_INERT_ON_HURT = frozenset("minecraft:" + e for e in ("unbreaking", "mending", "binding_curse", "vanishing_curse"))


def _wears(stack) -> bool:
    return not stack.is_empty and stack.id.endswith(_ARMOUR_ITEMS) and stack.component("minecraft:max_damage") is not None


def _enchantments(stack, version) -> list[str]:
    """The ids of the stack's enchantments (the ``Enchantments`` tag before 1.20.5)."""
    if version >= tools.COMPONENTS_VERSION:
        found = [str(e) for e in enchantment_levels(stack)]
    else:
        found = [str(e.get("id", "")) for e in (stack.tag or {}).get("Enchantments") or () if isinstance(e, Compound)]
    return [e if ":" in e else "minecraft:" + e for e in found]


def effect_harm(state, entity, amount: float, damage_type: str = "minecraft:magic") -> bool:
    """An effect's or hunger's hurt, with its death and triggers (HealOrHarmMobEffect: magic;
    PoisonMobEffect: magic; WitherMobEffect: wither; FoodData.tick: starve)."""
    return hurt(state, entity, amount, DamageSource(damage_type))


def attack(state, player, target) -> bool:
    """Player.attack: the attack damage attribute (with the equipment's modifiers the player's last
    tick collected, emulator.world.equipment) scaled by the swing's strength (living.swing_damage),
    the weapon's enchantment bonus (scaled by the strength), a critical hit (x 1.5) while falling,
    hurt as ``player_attack`` by the player; then the weapon's hurtEnemy/postHurtEnemy
    (:func:`_weapon_used`), ``minecraft.custom:minecraft.damage_dealt`` (the health taken x 10,
    rounded) and 0.1 exhaustion. A target that is not living is not attackable: nothing happens.
    What is not modelled raises Unmodelled (:func:`_unmodelled_weapon`, a sweep that would hit
    another entity, a sprinting full swing's knockback). Returns whether the target was hurt."""
    if not living.is_living(target.type) or target is player:
        return False
    access = inventories.entity_slot(player, inventories.MAINHAND, state.version)
    held = access.get()
    _unmodelled_weapon(state, player, held)
    bonus = _enchanted_damage(state, held, target)
    damage, strength = living.swing_damage(state, player)
    bonus = bonus * strength
    full = strength > F32(0.9)
    if (player.sprinting and full) or living.attribute_value(player, "attack_knockback") > 0:
        raise Unmodelled("the knockback of a sprinting full swing or of the attack_knockback attribute "
                         "(Player.attack -> LivingEntity.knockback)")
    if not (damage > 0 or bonus > 0):
        return False
    critical = _critical(state, player, strength)
    if critical:
        damage = damage * F32(1.5)
    sweep = full and not critical and int(player.data.get("OnGround", 0)) and _sweeps(held)
    before, motion = F32(living.health(target)), target.motion
    if not hurt(state, target, float(damage + bonus), DamageSource("minecraft:player_attack", player, player)):
        return False
    if target.is_player:  # Player.attack: the knockback goes to the target's client, the server keeps its motion
        target.motion = motion
    if sweep:
        _sweep(state, player, target, held, damage, strength)
    _weapon_used(state, player, access)
    dealt = before - F32(living.health(target))
    statistics.award(state, player, statistics.stat_name("custom", "damage_dealt"),
                     math.floor(dealt * F32(10.0) + F32(0.5)))
    living.exhaust(player, F32(0.1))
    return True


# Item.hurtEnemy returns true (the item counts as used) and postHurtEnemy's damage to it:
# SwordItem 1, DiggerItem (axes, pickaxes, shovels, hoes) 2, TridentItem 1, MaceItem 1
_DIGGERS = ("_axe", "_pickaxe", "_shovel", "_hoe")
# enchantments with no effect on the attack itself (durability, mining, the loot: read where it drops)
_INERT_ON_ATTACK = frozenset("minecraft:" + e for e in (
    "unbreaking", "mending", "vanishing_curse", "looting", "efficiency", "silk_touch", "fortune"))
# Enchantments (1.21 data): damage add linear(base, per level above the first) against a target
_DAMAGE_ENCHANTMENTS = {"minecraft:sharpness": (F32(1.0), F32(0.5), None),
                        "minecraft:smite": (F32(2.5), F32(2.5), "minecraft:sensitive_to_smite")}


def _enemy_damage(item_id: str) -> int:
    """The damage postHurtEnemy does to the weapon; 0 for an item whose hurtEnemy returns false."""
    name = item_id.removeprefix("minecraft:")
    if name.endswith("_sword") or name in ("trident", "mace"):
        return 1
    return 2 if name.endswith(_DIGGERS) else 0


def _sweeps(held) -> bool:
    """Player.attack's sweep: a SwordItem in the main hand."""
    return not held.is_empty and held.id.endswith("_sword")


def _unmodelled_weapon(state, player, held) -> None:
    """What the emulator does not model of the held item's attack: before 1.21 any weapon or item
    with components; the mace's smash (fall distance > 1.5, MaceItem.canSmashAttack); a pack's own
    or redefined enchantments; vanilla enchantments acting on attack other than sharpness and smite."""
    if held.is_empty:
        return
    version = tuple(state.version)
    if version < equipment.MODIFIERS_VERSION:
        if _enemy_damage(held.id) or any(held.component(c) is not None for c in (
                "minecraft:max_damage", "minecraft:attribute_modifiers", "minecraft:enchantments")):
            raise Unmodelled(f"attacking with {held.id} before 1.21 (its damage, enchantments and durability)")
        return
    if held.component("minecraft:weapon") is not None:
        raise Unmodelled(f"the weapon component of {held.id}")
    if held.id == "minecraft:mace" and float(player.data.get("FallDistance", 0.0)) > 1.5:
        raise Unmodelled("the mace's smash attack (MaceItem.getAttackDamageBonus, hurtEnemy)")
    for enchantment in _enchantments(held, version):
        if enchantment in _INERT_ON_ATTACK:
            continue
        if enchantment not in _DAMAGE_ENCHANTMENTS or enchantment in state.resources.redefined_enchantments:
            raise Unmodelled(f"the effects of {enchantment} on an attack (enchantment files are not read)")


def _enchanted_damage(state, held, target):
    """ServerPlayer.getEnchantedDamage -> EnchantmentHelper.modifyDamage: each damage enchantment
    adds its level-based amount (sharpness 1 + 0.5 per level above the first, smite 2.5 a level
    against #sensitive_to_smite)."""
    bonus = F32(0.0)
    if held.is_empty:
        return bonus
    for enchantment, level in enchantment_levels(held).items():
        found = _DAMAGE_ENCHANTMENTS.get(str(enchantment))
        level = int(numeric_value(level)) if is_numeric(level) else 0
        if found is None or level <= 0:
            continue
        first, per_level, tag = found
        if tag is None or state.resources.in_tag("entity_type", tag, target.type):
            bonus = bonus + first + per_level * F32(level - 1)
    return bonus


def _sweep(state, player, target, held, damage, strength) -> None:
    """Player.attack's sweep (doSweepAttack in 26.1) after the target was hurt: each living entity
    it reaches (:func:`_sweep_targets`) is hurt by 1 + sweeping_damage_ratio x the swing's damage
    (its enchantment bonus against that entity added, the whole scaled by the swing's strength) as
    ``player_attack`` and knocked back 0.4 along the player's facing (Mth.sin/cos of its yaw). Up
    to 1.21.4 the knockback comes first and always; from 1.21.7 only after a hurt that went
    through; in between which rule holds is not known here."""
    version = tuple(state.version)
    others = _sweep_targets(state, player, target)
    if not others:
        return
    if SWEEP_KNOCKBACK_FIRST < version < SWEEP_HURT_FIRST:
        raise Unmodelled(f"a sweep attack in {'.'.join(map(str, version))} (its knockback before or after the hurt)")
    base = F32(1.0) + F32(living.attribute_value(player, "sweeping_damage_ratio")) * F32(damage)
    yaw = F32(player.yaw) * F32(math.pi / 180.0)
    x, z = float(mth.sin(yaw)), -float(mth.cos(yaw))
    source = DamageSource("minecraft:player_attack", player, player)
    for other in others:
        amount = float((base + _enchanted_damage(state, held, other)) * strength)
        if version <= SWEEP_KNOCKBACK_FIRST:
            living.knockback(other, HURT_KNOCKBACK, x, z)
            hurt(state, other, amount, source)
        elif hurt(state, other, amount, source):
            living.knockback(other, HURT_KNOCKBACK, x, z)


def _sweep_targets(state, player, target) -> list:
    """The living entities in the target's box grown by 1, 0.25, 1 within 3 blocks of the player
    (not it, not the target, not an ally, not a marker armour stand)."""
    x0, y0, z0, x1, y1, z1 = target.bounding_box
    px, py, pz = player.pos
    found = []
    for other in state.entities.living_mobs():
        if other is player or other is target or other.dimension != target.dimension:
            continue
        if player.team is not None and other.team == player.team:
            continue
        if other.type == "minecraft:armor_stand" and int(other.data.get("Marker", 0)):
            continue
        a0, b0, c0, a1, b1, c1 = other.bounding_box
        inside = a0 < x1 + 1 and a1 > x0 - 1 and b0 < y1 + 0.25 and b1 > y0 - 0.25 and c0 < z1 + 1 and c1 > z0 - 1
        ox, oy, oz = other.pos
        if inside and (ox - px) ** 2 + (oy - py) ** 2 + (oz - pz) ** 2 < 9.0:
            found.append(other)
    return found


def _weapon_used(state, player, access) -> None:
    """ItemStack.hurtEnemy: an item whose hurtEnemy returns true counts ``minecraft.used:<item>``;
    postHurtEnemy: its damage through ItemStack.hurtAndBreak (Unbreakable, Unbreaking, breaking)."""
    held = access.get()
    points = 0 if held.is_empty else _enemy_damage(held.id)
    if not points:
        return
    statistics.award(state, player, statistics.stat_name("used", held.id))
    tools.hurt_and_break(state, player, access, points)


# BlockTags.CLIMBABLE (LivingEntity.onClimbable: the block at the feet)
CLIMBABLE = frozenset("minecraft:" + n for n in (
    "ladder vine scaffolding weeping_vines weeping_vines_plant twisting_vines twisting_vines_plant cave_vines "
    "cave_vines_plant").split())


def _critical(state, player, strength) -> bool:
    """Player.attack's critical hit (x 1.5): a full swing (strength > 0.9) while falling (fall
    distance > 0, not on the ground), not climbing, not in water, not blind, not riding, not
    sprinting (the target is living here)."""
    if not (strength > F32(0.9) and float(player.data.get("FallDistance", 0.0)) > 0.0
            and not int(player.data.get("OnGround", 0)) and not player.sprinting):
        return False
    feet = state.blocks_in(player.dimension).get(tuple(math.floor(c) for c in player.pos)).id
    return (feet not in CLIMBABLE and feet not in ("minecraft:water", "minecraft:bubble_column")
            and living.effect_amplifier(player, "minecraft:blindness") is None and player.vehicle is None)


def remember_attacker(state, entity, source: DamageSource) -> None:
    """LivingEntity.hurtServer: a living attacker becomes the last to hurt it (setLastHurtByMob /
    setLastHurtByPlayer; getKillCredit prefers the player)."""
    attacker = source.attacker
    if attacker is None or attacker is entity or attacker.type in inventories.NOT_LIVING:
        return
    if source.type not in NO_ANGER:  # setLastHurtByMob, unless the damage type angers no one
        state.last_attacker[entity] = (attacker, state.gametime)
    previous = state.last_hurt_by.get(entity)
    if attacker.is_player or previous is None or not previous[0].is_player or \
            state.gametime - previous[1] > CREDIT_TICKS:
        state.last_hurt_by[entity] = (attacker, state.gametime)


def hurt_triggers(state, entity, source: DamageSource, amount: float) -> None:
    """The end of LivingEntity.hurtServer: EntityHurtPlayerTrigger (a hurt player) and
    PlayerHurtEntityTrigger (the attacking player) with the damage."""
    attacker = source.attacker
    if entity.is_player:
        advancements.trigger(state, entity, "entity_hurt_player",
                             lambda c, ctx: _damage_matches(state, c.get("damage"), entity, source, amount))
    if attacker is not None and attacker.is_player:
        player_hurt_entity(state, attacker, entity, source, amount)


def player_hurt_entity(state, player, entity, source: DamageSource, amount: float) -> None:
    """PlayerHurtEntityTrigger.trigger: the damage (dealt and taken alike) and the hurt entity."""
    advancements.trigger(state, player, "player_hurt_entity", lambda c, ctx: (
        _damage_matches(state, c.get("damage"), player, source, amount)
        and advancements.entity_condition(state, c.get("entity"), player, entity)))


# ---------------------------------------------------------------------- death
def die(state, entity, source: DamageSource) -> None:
    """LivingEntity.die: once; the killer's credit, then a mob leaves the world and a player dies."""
    if entity in state.dead_players or not entity.alive:
        return
    killer = kill_credit(state, entity)
    if entity.is_player:
        _player_dies(state, entity, source, killer)
    if killer is not None and killer.is_player:
        _award_kill(state, killer, entity, source)
    if killer is not None and entity.is_player:
        statistics.award(state, entity, statistics.stat_name("killed_by", killer.type))
        advancements.trigger(state, entity, "entity_killed_player", lambda c, ctx: (
            advancements.entity_condition(state, c.get("entity"), entity, killer)
            and _source_matches(state, c.get("killing_blow"), entity, source)))
    if not entity.is_player:
        if state.gamerules.get("doMobLoot") != "false" and entity.type != "minecraft:armor_stand":
            _mob_drops(state, entity, killer, source)
        state.discard(entity)
    tracker = state.combat_trackers.get(entity)
    if tracker is not None:  # LivingEntity.die / ServerPlayer.die end by rechecking: the dead forget
        recheck(state, entity, tracker)


def _mob_drops(state, mob, killer, source: DamageSource) -> None:
    """LivingEntity.dropAllDeathLoot: the mob's loot table (``DeathLootTable``, else
    ``entities/<type>``: a pack's, or the game's from ``--game-jar``) rolled with its killer and
    dropped where it died;
    experience when a player hurt it within 100 ticks (Mob.getBaseExperienceReward: animals 1-3,
    monsters 5); its equipment by its drop chances (:func:`_equipment_drops`)."""
    table_id = str(mob.data.get("DeathLootTable") or "minecraft:entities/" + mob.type.split(":", 1)[-1])
    try:  # a table that does not exist drops nothing (LootTable.EMPTY)
        table = {} if table_id == EMPTY_TABLE else state.resources.loot_table(table_id) or {}
    except Unmodelled as unknown:
        state.error(f"the drops of a dying {mob.type}: {unknown}", severity="warning", unmodelled=True)
    else:
        ctx = LootContext(state, mob.pos, this=mob, dimension=mob.dimension, damage_source=source,
                          random=state.resources.random).killed_by(killer)
        for stack in loot.roll_table(table, ctx):
            inventories.drop_item(state.entities, mob.pos, stack, state.version, state.resources.random,
                                  dimension=mob.dimension)
    _equipment_drops(state, mob, killer, killer is not None and killer.is_player)
    if killer is not None and killer.is_player:
        name = mob.type.split(":", 1)[-1]
        if name in ANIMALS:
            award_orbs(state, mob.pos, 1 + state.resources.random.randrange(3), mob.dimension)
        elif name in MONSTERS:
            award_orbs(state, mob.pos, 5, mob.dimension)
        else:
            state.error(f"the experience a {mob.type} killed by a player drops", severity="warning", unmodelled=True)


# EquipmentSlot.values(): the order a dying mob's equipment drops in; the drop chance lists' indices
_EQUIPMENT = ((inventories.MAINHAND, "mainhand", "HandDropChances", 0), (inventories.OFFHAND, "offhand", "HandDropChances", 1),
              *((slot, name, "ArmorDropChances", i) for i, (slot, name) in enumerate(inventories.ARMOR.items())),
              (inventories.BODY, "body", None, 0))
DEFAULT_DROP_CHANCE = np.float32(0.085)  # Mob.DEFAULT_EQUIPMENT_DROP_CHANCE
DROP_CHANCES_VERSION = (1, 21, 5)  # one ``drop_chances`` map of the slots whose chance is not the default
# mobs that drop more than their equipment on death (Mob subclasses' dropCustomDeathLoot, dropEquipment,
# dropAllDeathLoot: saddles, inventories, a carried block, a nether star, heads ...): not modelled
_OWN_DEATH_DROPS = frozenset("minecraft:" + n for n in (
    "fox pig strider allay horse donkey mule llama trader_llama skeleton_horse zombie_horse camel wither "
    "creeper enderman skeleton wither_skeleton zombie husk drowned zombie_villager piglin").split())


def _equipment_drops(state, mob, killer, recently_hit: bool) -> None:
    """Mob.dropCustomDeathLoot: each slot whose drop chance is not 0 and holds an item not cursed
    with vanishing drops when a player hurt the mob lately or the chance is over 1 (an item it
    picked up: 2), and a draw under the chance (nextFloat, here from the emulator's seeded random);
    one dropped by chance alone is worn to a random damage (max - nextInt(1 + nextInt(max(max - 3,
    1)))). The killer's Looting (EnchantmentHelper.processEquipmentDropChance) is not modelled."""
    version = tuple(state.version)
    held = [(slot, inventories.entity_slot(mob, slot, version)) for slot, *_ in _EQUIPMENT]
    if not any(access is not None and not access.get().is_empty for _, access in held):
        return
    if mob.type in _OWN_DEATH_DROPS:
        state.error(f"the equipment a dying {mob.type} may drop", severity="warning", unmodelled=True)
        return
    if killer is not None and enchantment_level(
            inventories.entity_slot(killer, inventories.MAINHAND, version).get(), "minecraft:looting") > 0:
        state.error("the equipment drop chance Looting adds", severity="warning", unmodelled=True)
        return
    rng = state.resources.random
    for (slot, name, legacy, index), (_, access) in zip(_EQUIPMENT, held):
        chance = _drop_chance(mob.data, name, legacy, index, version)
        if access is None or chance == 0:
            continue
        stack = access.get()
        guaranteed = chance > 1
        if (stack.is_empty or enchantment_level(stack, "minecraft:vanishing_curse") > 0
                or not (recently_hit or guaranteed) or not rng.random() < chance):
            continue
        if not guaranteed:
            tools.wear_at_random(stack, rng, version)
        inventories.drop_item(state.entities, mob.pos, stack, version, rng, dimension=mob.dimension)
        access.set(EMPTY.copy())


def _drop_chance(data, name: str, legacy: str | None, index: int, version) -> float:
    """The slot's saved drop chance: ``drop_chances`` from 1.21.5, ``HandDropChances`` /
    ``ArmorDropChances`` / ``body_armor_drop_chance`` before; 0.085 when not saved."""
    if version >= DROP_CHANCES_VERSION:
        found = data.get("drop_chances")
        found = found.get(name) if isinstance(found, Compound) else None
    elif legacy is None:
        found = data.get("body_armor_drop_chance")
    else:
        listed = data.get(legacy)
        found = listed[index] if isinstance(listed, List) and index < len(listed) else None
    return float(np.float32(numeric_value(found))) if is_numeric(found) else float(DEFAULT_DROP_CHANCE)


def _award_kill(state, killer, victim, source: DamageSource) -> None:
    """ServerPlayer.awardKillScore: killed:<type>, player_kills or mob_kills, the kill criteria,
    and player_killed_entity."""
    statistics.award(state, killer, statistics.stat_name("killed", victim.type))
    statistics.award(state, killer, statistics.stat_name("custom", "player_kills" if victim.is_player else "mob_kills"))
    statistics.award(state, killer, "totalKillCount")
    if victim.is_player:
        statistics.award(state, killer, "playerKillCount")
    advancements.trigger(state, killer, "player_killed_entity", lambda c, ctx: (
        advancements.entity_condition(state, c.get("entity"), killer, victim)
        and _source_matches(state, c.get("killing_blow"), killer, source)))


def _player_dies(state, player, source: DamageSource, killer) -> None:
    _death_message(state, player, source, killer)
    if player.gamemode != "spectator":
        keep = state.gamerules.get("keepInventory") == "true"
        if not keep:
            _drop_inventory(state, player)
            _drop_experience(state, player)
    statistics.award(state, player, "deathCount")
    statistics.award(state, player, statistics.stat_name("custom", "deaths"))
    for stat in ("time_since_death", "time_since_rest"):
        statistics.reset(state, player, statistics.stat_name("custom", stat))
    x, y, z = player.pos
    player.data["LastDeathLocation"] = Compound(
        dimension=String(player.dimension),
        pos=IntArray(Int(math.floor(c)) for c in (x, y, z)))
    player.data["DeathTime"] = Short(0)
    state.dead_players.add(player)
    player.alive = False
    if state.gamerules.get("doImmediateRespawn") == "true":
        state.error(f"{player.display_name} died with doImmediateRespawn on: the respawn that follows is not "
                    "modelled (the player stays dead until 'dummy ... respawn')", severity="warning",
                    unmodelled=True)


# ---------------------------------------------------------------------- the combat tracker
RESET_DAMAGE_STATUS_TIME, RESET_COMBAT_STATUS_TIME = 100, 300  # CombatTracker
CLIMBABLE = frozenset("minecraft:" + b for b in (  # the blocks FallLocation names, and the other climbables
    "ladder vine weeping_vines weeping_vines_plant twisting_vines twisting_vines_plant scaffolding cave_vines "
    "cave_vines_plant").split())


@dataclass
class CombatEntry:
    source: DamageSource
    damage: float
    location: str | None  # FallLocation's id (water, ...), None where it had none
    fall_distance: float


@dataclass
class CombatTracker:
    """A living entity's record of its recent hurts, read for its death message."""
    entries: list = field(default_factory=list)
    last_damage: int = 0  # its tickCount at the last hurt
    in_combat: bool = False
    taking_damage: bool = False


def record_damage(state, entity, source: DamageSource, damage: float) -> None:
    """CombatTracker.recordDamage (LivingEntity.actuallyHurt, when health is lost): the entry keeps
    where the entity is (FallLocation.getCurrentFallLocation: water here; climbing is not modelled,
    an entity in a climbable block records that it is) and its fall distance."""
    tracker = state.combat_trackers.get(entity)
    if tracker is None:
        tracker = state.combat_trackers[entity] = CombatTracker()
    recheck(state, entity, tracker)
    blocks = state.blocks_in(entity.dimension)
    x, y, z = entity.pos
    if blocks.get((math.floor(x), math.floor(y), math.floor(z))).id in CLIMBABLE:
        location = "climbable"
    else:
        location = "water" if fluids.in_water(blocks, entity.bounding_box) else None
    fall = entity.data.get("FallDistance")
    tracker.entries.append(CombatEntry(source, damage, location, float(fall) if is_numeric(fall) else 0.0))
    tracker.last_damage, tracker.taking_damage = entity.tick_count(state.tick), True
    if not tracker.in_combat and entity.alive and source.attacker is not None and living.is_living(source.attacker.type):
        tracker.in_combat = True  # shouldEnterCombat: the source's entity is living


def recheck(state, entity, tracker: CombatTracker) -> None:
    """CombatTracker.recheckStatus: the record is cleared once the entity is dead, or 100 ticks after
    its last hurt (300 in combat)."""
    limit = RESET_COMBAT_STATUS_TIME if tracker.in_combat else RESET_DAMAGE_STATUS_TIME
    if tracker.taking_damage and (not entity.alive or living.health(entity) <= 0
                                  or entity.tick_count(state.tick) - tracker.last_damage > limit):
        tracker.taking_damage = tracker.in_combat = False
        tracker.entries.clear()


def tick_trackers(state) -> None:
    """LivingEntity.tick: each living entity rechecks its tracker when its tickCount is a multiple of 20."""
    for entity, tracker in list(state.combat_trackers.items()):
        if tracker.taking_damage and entity.tick_count(state.tick) % 20 == 0:
            recheck(state, entity, tracker)


def trackers_idle(state) -> bool:
    return not state.combat_trackers or not any(t.taking_damage for t in state.combat_trackers.values())


def _most_significant_fall(state, entries: list) -> CombatEntry | None:
    """CombatTracker.getMostSignificantFall: the entry before the longest fall (the fall itself when
    it is the first) when that fall is over 5 blocks, else the hardest hurt taken somewhere it had a
    fall location when that hurt was over 5."""
    fall_entry = placed = None
    longest = hardest = 0.0
    for i, entry in enumerate(entries):
        always = state.resources.in_tag("damage_type", "minecraft:always_most_significant_fall", entry.source.type)
        distance = float(np.float32(3.4028235e38)) if always else entry.fall_distance
        if (always or state.resources.in_tag("damage_type", "minecraft:is_fall", entry.source.type)) \
                and distance > 0 and (fall_entry is None or distance > longest):
            fall_entry, longest = (entries[i - 1] if i > 0 else entry), distance
        if entry.location is not None and (placed is None or entry.damage > hardest):
            placed, hardest = entry, entry.damage
    if longest > 5.0 and fall_entry is not None:
        return fall_entry
    return placed if hardest > 5.0 and placed is not None else None


def _fall_text(state, player, entry: CombatEntry, killer) -> str | None:
    """CombatTracker.getFallMessage: a fall's own place (death.fell.accident.<location>), else who
    doomed it to fall (death.fell.assist, .finish, .killer)."""
    source = entry.source
    if state.resources.in_tag("damage_type", "minecraft:is_fall", source.type) or state.resources.in_tag(
            "damage_type", "minecraft:always_most_significant_fall", source.type):
        if entry.location == "climbable":
            state.error("the death message of a fall from a climbable block (FallLocation) is not modelled: none "
                        "was sent", severity="warning", unmodelled=True)
            return None
        return _translated(state, f"death.fell.accident.{entry.location or 'generic'}", [player.display_name])
    doomer = source.attacker
    if doomer is not None and doomer is not killer:
        return _assisted(state, player, doomer, "death.fell.assist")
    if killer is not None:
        return _assisted(state, player, killer, "death.fell.finish")
    return _translated(state, "death.fell.killer", [player.display_name])


def _assisted(state, player, entity, key: str) -> str:
    """getMessageForAssistedFall: ``.item`` when the entity's main hand holds a named item."""
    weapon = inventories.entity_slot(entity, inventories.MAINHAND, state.version)
    held = weapon.get() if weapon is not None else None
    if held is not None and not held.is_empty and held.component("minecraft:custom_name") is not None:
        return _translated(state, f"{key}.item", [player.display_name, entity.display_name,
                                                   "[" + items.hover_name(held, state.version) + "]"])
    return _translated(state, key, [player.display_name, entity.display_name])


def _death_message(state, player, source: DamageSource, killer) -> None:
    """CombatTracker.getDeathMessage, broadcast when ``showDeathMessages`` is on: the killing blow's
    DamageSource.getLocalizedDeathMessage (death.attack.<message id> with the victim and the
    responsible entity, ``.item`` when that entity's main hand holds a named item; without an entity,
    ``.player`` naming the killer credited), or the bed and anchor's "[Intentional Game Design]"."""
    if state.gamerules.get("showDeathMessages") == "false":
        return
    message = _death_text(state, player, source, killer)
    if message is None:
        return
    state.broadcast("chat", message)


def _death_text(state, player, source: DamageSource, killer) -> str | None:
    message_id = MESSAGE_IDS.get(source.type)
    if message_id is None:  # a pack's own damage type: its message id is not read
        state.error(f"the death message of damage type {source.type} is not modelled: none was sent",
                    severity="warning", unmodelled=True)
        return None
    tracker = state.combat_trackers.get(player)
    if source.type in FALL_VARIANTS and tracker is not None:
        fall = _most_significant_fall(state, tracker.entries)
        if fall is not None:
            return _fall_text(state, player, fall, source.attacker)
    responsible = source.attacker or source.direct
    others = [e for e in (responsible, killer) if e is not None]
    if player.team is not None or any(e.team is not None for e in others):
        state.error("the death message naming an entity in a team (the team's prefix, suffix and colour, its "
                    "deathMessageVisibility) is not modelled: none was sent", severity="warning", unmodelled=True)
        return None
    key = f"death.attack.{message_id}"
    if source.type == INTENTIONAL_GAME_DESIGN:
        link = "[" + _translated(state, f"{key}.link", []) + "]"  # ComponentUtils.wrapInSquareBrackets
        return _translated(state, f"{key}.message", [player.display_name, link])
    if responsible is not None:  # the causing entity's main hand (an arrow with no owner holds none)
        weapon = inventories.entity_slot(source.attacker, inventories.MAINHAND, state.version) if source.attacker else None
        held = weapon.get() if weapon is not None else None
        if held is not None and not held.is_empty and held.component("minecraft:custom_name") is not None:
            shown = "[" + items.hover_name(held, state.version) + "]"  # ItemStack.getDisplayName
            return _translated(state, f"{key}.item", [player.display_name, responsible.display_name, shown])
        return _translated(state, key, [player.display_name, responsible.display_name])
    if killer is not None:
        return _translated(state, f"{key}.player", [player.display_name, killer.display_name])
    return _translated(state, key, [player.display_name])


def _translated(state, key: str, arguments: list[str]) -> str:
    return translations.translated({"translate": key, "with": arguments}, state.version, str)


def _drop_inventory(state, player) -> None:
    """Player.dropEquipment -> Inventory.dropAll: every stack thrown around (Player.drop with
    dropAround, no thrower); items cursed with vanishing are destroyed first."""
    slots = [*range(inventories.PLAYER_INVENTORY_SIZE), *inventories.ARMOR, inventories.OFFHAND]
    for slot in slots:
        access = inventories.entity_slot(player, slot, state.version)
        stack = access.get()
        if stack.is_empty:
            continue
        access.set(EMPTY.copy())
        if enchantment_level(stack, "minecraft:vanishing_curse") > 0:
            continue
        rng = state.resources.random
        strength, angle = rng.random() * 0.5, rng.random() * math.pi * 2
        motion = List([Double(-math.sin(angle) * strength), Double(0.2), Double(math.cos(angle) * strength)])
        x, y, z = player.pos
        inventories.drop_item(state.entities, (x, y + float(player.eye_height) - 0.30000001192092896, z), stack,
                              state.version, rng, Compound(PickupDelay=Short(40), Motion=motion),
                              dimension=player.dimension)


def _drop_experience(state, player) -> None:
    """LivingEntity.dropExperience: a player always drops min(7 x level, 100) points, split into orbs
    by ExperienceOrb.getExperienceValue (the game merges an orb into an equal one nearby one time in
    40, depending on entity ids: not here)."""
    level = int(player.data.get("XpLevel", Int(0)))
    award_orbs(state, player.pos, min(level * 7, 100), player.dimension)


def award_orbs(state, pos, amount: int, dimension: str) -> None:
    """ExperienceOrb.award: orbs of getExperienceValue's sizes (no merging) at ``pos``, each with the
    constructor's random motion."""
    rng = state.resources.random
    while amount > 0:
        value = next(v for v in ORB_VALUES if amount >= v)
        amount -= value
        state.entities.summon("minecraft:experience_orb", pos, Compound(
            Value=Short(value), Count=Int(1), Age=Short(0), Health=Short(5),
            Motion=List([Double((rng.random() * 0.2 - 0.1) * 2), Double(rng.random() * 0.4),
                         Double((rng.random() * 0.2 - 0.1) * 2)])), dimension=dimension)


def tick_is_idle(state) -> bool:
    """Whether :func:`tick_dead` would do nothing now: no dead player's DeathTime still counts."""
    return not state.dead_players or not any(p.is_player and not p.alive and int(p.data.get("DeathTime", Short(0))) < MAX_DEATH_TIME
                   for p in state.dead_players)


def tick_dead(state) -> None:
    """LivingEntity.tickDeath: ``DeathTime`` counts up to 20 (then the game takes the body away)."""
    if not state.dead_players:  # every tick: an empty set is the common case
        return
    for player in list(state.dead_players):
        if player.is_player and not player.alive:
            player.data["DeathTime"] = Short(min(int(player.data.get("DeathTime", Short(0))) + 1, MAX_DEATH_TIME))


def respawn_keeps(state, old, new) -> None:
    """ServerPlayer.restoreFrom (not keeping everything): the ender chest, the recipe book, the
    tags, and with ``keepInventory`` (or from a spectator) the inventory and experience."""
    new.tags = set(old.tags)
    for key in ("EnderItems", "LastDeathLocation", "recipeBook"):
        if key in old.data:
            new.data[key] = old.data[key]
    if state.gamerules.get("keepInventory") == "true" or old.gamemode == "spectator":
        for key in ("Inventory", "equipment", "XpLevel", "XpP", "XpTotal", "Score", "SelectedItemSlot"):
            if key in old.data:
                new.data[key] = old.data[key]


# ---------------------------------------------------------------------- trigger conditions
def _damage_matches(state, wanted, player, source: DamageSource, amount: float) -> bool:
    """DamagePredicate: dealt and taken (the same here: no shield, no freezing), blocked (never),
    the source entity, the damage source."""
    if wanted is None:
        return True
    for key in ("dealt", "taken"):
        if key in wanted and not predicates.in_range(wanted[key], amount):
            return False
    if wanted.get("blocked") is True:
        return False
    if "source_entity" in wanted and not advancements.entity_condition(state, wanted["source_entity"], player,
                                                                       source.attacker):
        return False
    return _source_matches(state, wanted.get("type"), player, source)


def _source_matches(state, wanted, player, source: DamageSource) -> bool:
    """DamageSourcePredicate.matches(player): its entity predicates from the player's position."""
    return predicates.damage_source_matches(wanted, source, state.resources, lambda predicate, entity: (
        advancements.entity_condition(state, predicate, player, entity)))
