"""Living entities' state: health, attributes, status effects, experience and hunger, kept in the
entity's NBT fields as the game saves them (``Health``, ``attributes``, ``active_effects``,
``XpLevel``/``XpP``/``XpTotal``/``Score``, ``foodLevel`` ...), so ``data get``, ``nbt=`` and
``data merge`` on a mob see and change the same values the commands use.

- ``is_living(type_id)``: a LivingEntity (mobs, players, armor stands); ``base_fields(type_id)``:
  the fields such an entity saves from its spawn (the player's hunger and experience too).
- Attributes (AttributeInstance, RangedAttribute): ``attribute_value``, ``base_value``,
  ``set_base``, ``reset_base``, ``add_modifier``, ``remove_modifier``, ``modifier_value``; vanilla
  defaults for the common attributes (``DEFAULTS``, per type ``TYPE_BASES``). An instance appears in
  the ``attributes`` list when a command first reads or changes it (the game's AttributeMap creates
  instances on demand).
- Health and damage (LivingEntity.hurtServer/actuallyHurt, no AI): ``health``, ``hurt`` (the
  health taken; who did it, death and the triggers are emulator.world.combat's, which calls it).
- Effects (LivingEntity.addEffect, MobEffectInstance.update/tick): ``give_effect``, ``clear_effects``;
  ``tick_living(state, harm)`` counts every effect down once per tick (an instant effect acts then,
  its damage dealt by ``harm``: emulator.world.combat's, which also kills) and drops the expired ones.
- A player's swing (Player.attack's damage): ``swing_damage``; ``reset_attack_strength`` when it
  joins (the attack itself: emulator.world.combat).
- Experience (Player.giveExperiencePoints/giveExperienceLevels/setExperiencePoints):
  ``add_points``, ``add_levels``, ``set_points``, ``set_levels``, ``query_points``, ``xp_needed``.

Sources (decompiled 1.21): world/entity/LivingEntity.java, world/entity/player/Player.java,
world/entity/ai/attributes/{Attributes,AttributeInstance,RangedAttribute,DefaultAttributes}.java,
world/effect/MobEffectInstance.java, world/food/FoodData.java, server/commands/AttributeCommand.java,
ExperienceCommand.java, EffectCommands.java, DamageCommand.java.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from mcfunction_parser import gamedata
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, IntArray, List, Short, String
from emulator.world import recipes, spawn_protection, statistics
from emulator.world.nbt_ops import is_numeric, numeric_value
from emulator.world.semantics import wrap32

F32 = np.float32
INFINITE = -1  # MobEffectInstance.INFINITE_DURATION

# Entities that are not LivingEntity (the rest of the types a pack summons are).
NOT_LIVING = frozenset(f"minecraft:{n}" for n in (
    "marker", "item_display", "block_display", "text_display", "interaction", "item", "experience_orb",
    "area_effect_cloud", "arrow", "spectral_arrow", "trident", "snowball", "egg", "ender_pearl", "potion",
    "experience_bottle", "fireball", "small_fireball", "dragon_fireball", "wither_skull", "wind_charge",
    "breeze_wind_charge", "shulker_bullet", "llama_spit", "firework_rocket", "fishing_bobber", "eye_of_ender",
    "falling_block", "tnt", "end_crystal", "evoker_fangs", "lightning_bolt", "painting", "item_frame",
    "glow_item_frame", "leash_knot", "boat", "chest_boat", "minecart", "chest_minecart", "furnace_minecart",
    "hopper_minecart", "tnt_minecart", "spawner_minecart", "command_block_minecart", "bamboo_raft",
    "bamboo_chest_raft", "ominous_item_spawner")) | frozenset(  # the boats of each wood (1.21.2+)
    f"minecraft:{wood}_{kind}" for wood in "oak spruce birch jungle acacia dark_oak mangrove cherry pale_oak".split()
    for kind in ("boat", "chest_boat"))

# Attributes.java: (default value, min, max) of the registered attributes (1.21.2+ ids).
DEFAULTS: dict[str, tuple[float, float, float]] = {
    "armor": (0.0, 0.0, 30.0), "armor_toughness": (0.0, 0.0, 20.0), "attack_damage": (2.0, 0.0, 2048.0),
    "attack_knockback": (0.0, 0.0, 5.0), "attack_speed": (4.0, 0.0, 1024.0), "block_break_speed": (1.0, 0.0, 1024.0),
    "block_interaction_range": (4.5, 0.0, 64.0), "burning_time": (1.0, 0.0, 1024.0),
    "entity_interaction_range": (3.0, 0.0, 64.0), "explosion_knockback_resistance": (0.0, 0.0, 1.0),
    "fall_damage_multiplier": (1.0, 0.0, 100.0), "flying_speed": (0.4, 0.0, 1024.0),
    "follow_range": (32.0, 0.0, 2048.0), "gravity": (0.08, -1.0, 1.0), "jump_strength": (0.42, 0.0, 32.0),
    "knockback_resistance": (0.0, 0.0, 1.0), "luck": (0.0, -1024.0, 1024.0), "max_absorption": (0.0, 0.0, 2048.0),
    "max_health": (20.0, 1.0, 1024.0), "mining_efficiency": (0.0, 0.0, 1024.0),
    "movement_efficiency": (0.0, 0.0, 1.0), "movement_speed": (0.7, 0.0, 1024.0), "oxygen_bonus": (0.0, 0.0, 1024.0),
    "safe_fall_distance": (3.0, -1024.0, 1024.0), "scale": (1.0, 0.0625, 16.0), "sneaking_speed": (0.3, 0.0, 1.0),
    "spawn_reinforcements": (0.0, 0.0, 1.0), "step_height": (0.6, 0.0, 10.0),
    "submerged_mining_speed": (0.2, 0.0, 20.0), "sweeping_damage_ratio": (0.0, 0.0, 1.0),
    "tempt_range": (10.0, 0.0, 2048.0), "water_movement_efficiency": (0.0, 0.0, 1.0),
}
# LivingEntity.createLivingAttributes: what every living entity has.
_LIVING = ("max_health", "knockback_resistance", "movement_speed", "armor", "armor_toughness", "max_absorption",
           "step_height", "scale", "gravity", "safe_fall_distance", "fall_damage_multiplier", "jump_strength",
           "oxygen_bonus", "burning_time", "explosion_knockback_resistance", "water_movement_efficiency",
           "movement_efficiency", "attack_knockback")
# Player.createAttributes and the mobs' createAttributes (DefaultAttributes): bases that differ
# from the registry default, and the extra attributes each type has.
_PLAYER = {"attack_damage": 1.0, "movement_speed": 0.1, "attack_speed": 4.0, "luck": 0.0,
           "block_interaction_range": 4.5, "entity_interaction_range": 3.0, "block_break_speed": 1.0,
           "submerged_mining_speed": 0.2, "sneaking_speed": 0.3, "mining_efficiency": 0.0,
           "sweeping_damage_ratio": 0.0}
_MOB = {"follow_range": 16.0}
TYPE_BASES: dict[str, dict[str, float]] = {
    "minecraft:player": _PLAYER,
    "minecraft:zombie": {**_MOB, "follow_range": 35.0, "movement_speed": 0.23, "attack_damage": 3.0, "armor": 2.0,
                         "spawn_reinforcements": 0.0},
    "minecraft:husk": {**_MOB, "follow_range": 35.0, "movement_speed": 0.23, "attack_damage": 3.0, "armor": 2.0,
                       "spawn_reinforcements": 0.0},
    "minecraft:skeleton": {**_MOB, "movement_speed": 0.25}, "minecraft:creeper": {**_MOB, "movement_speed": 0.25},
    "minecraft:spider": {**_MOB, "max_health": 16.0, "movement_speed": 0.3},
    "minecraft:cow": {**_MOB, "max_health": 10.0, "movement_speed": 0.2},
    "minecraft:pig": {**_MOB, "max_health": 10.0, "movement_speed": 0.25},
    "minecraft:sheep": {**_MOB, "max_health": 8.0, "movement_speed": 0.23},
    "minecraft:chicken": {**_MOB, "max_health": 4.0, "movement_speed": 0.25},
    "minecraft:villager": {**_MOB, "movement_speed": 0.5, "follow_range": 48.0},
    "minecraft:iron_golem": {**_MOB, "max_health": 100.0, "movement_speed": 0.25, "knockback_resistance": 1.0,
                             "attack_damage": 15.0, "step_height": 1.0},
    "minecraft:armor_stand": {},
}


def is_living(type_id: str) -> bool:
    return type_id not in NOT_LIVING


def attribute_id(text: str) -> str:
    """``minecraft:max_health``, ``max_health`` and the pre-1.21.2 ``generic.max_health`` name one
    attribute: its short id."""
    name = text.split(":", 1)[-1]
    for prefix in ("generic.", "player.", "zombie."):
        if name.startswith(prefix):
            return name[len(prefix):]
    return name


def is_baby(entity) -> bool:
    """LivingEntity.isBaby as saved: an ageable mob's ``Age`` below 0, the zombies' and piglins'
    ``IsBaby``, a ``Small`` armor stand (ArmorStand.isBaby)."""
    data = entity.data
    if entity.type == "minecraft:armor_stand":
        return _number(data.get("Small")) != 0
    return _number(data.get("Age")) < 0 or _number(data.get("IsBaby")) != 0


def has_attribute(type_id: str, name: str, release=None) -> bool:
    """Whether entities of the type have the attribute (in ``release``, when given: one its registry
    lacks, such as ``scale`` before 1.20.5, none has)."""
    return (is_living(type_id) and (name in _LIVING or name in TYPE_BASES.get(type_id, _MOB))
            and (release is None or registered(name, release)))


def registered(name: str, release) -> bool:
    """Whether ``release`` registers the attribute (its registry; every one of :data:`DEFAULTS`
    when dpemu has no registry data of it)."""
    names = _registry_names(tuple(release))
    return name in (DEFAULTS if names is None else names)


@lru_cache(maxsize=None)
def _registry_names(release) -> dict[str, str] | None:
    """The release's attribute registry names by short id (``max_health`` -> ``generic.max_health``
    before 1.21.2); None without its registry data."""
    try:
        return {attribute_id(entry): entry for entry in gamedata.registry("attribute", release)}
    except gamedata.GameDataMissing:
        return None


def default_base(type_id: str, name: str) -> float:
    return TYPE_BASES.get(type_id, _MOB).get(name, DEFAULTS[name][0])


def base_fields(type_id: str) -> Compound:
    """What a living entity saves from its spawn: Health at its max health, no effects, the
    player's hunger (FoodData), experience and empty recipe book."""
    if not is_living(type_id):
        return Compound()
    data = Compound(Health=Float(default_base(type_id, "max_health")), HurtTime=Short(0), DeathTime=Short(0),
                    AbsorptionAmount=Float(0.0))
    if type_id == "minecraft:player":
        data.update(foodLevel=Int(20), foodSaturationLevel=Float(5.0), foodExhaustionLevel=Float(0.0),
                    foodTickTimer=Int(0), XpLevel=Int(0), XpP=Float(0.0), XpTotal=Int(0), XpSeed=Int(0), Score=Int(0),
                    recipeBook=recipes.EMPTY_BOOK())
    return data


# ---------------------------------------------------------------------- attributes
CODEC_ATTRIBUTES = (1, 20, 5)  # the codec layout: ``attributes`` [{id, base, modifiers}]
MODIFIER_IDS = (1, 21, 0)  # modifiers named by an id (before: a UUID and a name)
# (list, id, base, modifiers) keys: LivingEntity.addAdditionalSaveData and AttributeInstance.save,
# before 1.20.5 ``Attributes`` [{Name, Base, Modifiers}]
_CODEC_KEYS = ("attributes", "id", "base", "modifiers")
_OLD_KEYS = ("Attributes", "Name", "Base", "Modifiers")
# AttributeModifier.Operation by its saved number before 1.20.5
_OPERATIONS = ("add_value", "add_multiplied_base", "add_multiplied_total")


def _keys(entity) -> tuple[str, str, str, str]:
    return _CODEC_KEYS if entity.release >= CODEC_ATTRIBUTES else _OLD_KEYS


def _instances(entity) -> List:
    key = _keys(entity)[0]
    found = entity.data.get(key)
    if not isinstance(found, List):
        found = entity.data[key] = List()
    return found


UNPREFIXED_ATTRIBUTES = (1, 21, 2)  # 24w36a: the ids lost their generic., player. and zombie. prefixes


def saved_attribute_id(name: str, release) -> str:
    """The id an attribute instance is saved under in ``release`` (AttributeInstance.save writes its
    registry key): ``minecraft:max_health`` from 1.21.2, the release's registry name before it
    (``minecraft:generic.max_health``, ``minecraft:player.block_interaction_range``)."""
    if tuple(release) < UNPREFIXED_ATTRIBUTES:
        return f"minecraft:{(_registry_names(tuple(release)) or {}).get(name, 'generic.' + name)}"
    return f"minecraft:{name}"


def _instance(entity, name: str) -> Compound:
    """The entity's instance of the attribute (created at its default base on first use)."""
    _, id_key, base_key, _ = _keys(entity)
    for inst in _instances(entity):  # read under either name (a pack may write the other)
        if isinstance(inst, Compound) and attribute_id(str(inst.get(id_key, ""))) == name:
            return inst
    inst = Compound(**{id_key: String(saved_attribute_id(name, entity.release)),
                       base_key: Double(default_base(entity.type, name))})
    _instances(entity).append(inst)
    return inst


def _number(tag, default: float = 0.0) -> float:
    return float(numeric_value(tag)) if is_numeric(tag) else default


def base_value(entity, name: str) -> float:
    return _number(_instance(entity, name).get(_keys(entity)[2]), default_base(entity.type, name))


def set_base(entity, name: str, value: float) -> None:
    _instance(entity, name)[_keys(entity)[2]] = Double(value)
    _changed(entity)


def reset_base(entity, name: str) -> None:
    set_base(entity, name, default_base(entity.type, name))


def _modifiers(entity, name: str) -> List:
    inst = _instance(entity, name)
    key = _keys(entity)[3]
    if not isinstance(inst.get(key), List):
        inst[key] = List()
    return inst[key]


def _saved_modifiers(entity, name: str) -> list[tuple[str, float]]:
    """(operation, amount) of the modifiers saved on the attribute, in any release's layout
    (before 1.20.5 ``Amount`` and ``Operation`` 0, 1 or 2)."""
    found = []
    for m in _saved(entity, name):
        if not isinstance(m, Compound):
            continue
        operation = m.get("operation")
        if operation is None and is_numeric(m.get("Operation")) and 0 <= int(numeric_value(m["Operation"])) < 3:
            operation = _OPERATIONS[int(numeric_value(m["Operation"]))]
        found.append((str(operation or ""), _number(m.get("amount", m.get("Amount")))))
    return found


def _saved(entity, name: str) -> list:
    """The modifiers saved on the attribute (read only: no empty list is written)."""
    saved = _instance(entity, name).get(_keys(entity)[3])
    return saved if isinstance(saved, List) else []


def _key_field(entity) -> str:
    """The field a saved modifier is known by: its id from 1.21, its UUID before (``uuid`` in the
    1.20.5 codec, ``UUID`` before it)."""
    if entity.release >= MODIFIER_IDS:
        return "id"
    return "uuid" if entity.release >= CODEC_ATTRIBUTES else "UUID"


def _find_modifier(entity, name: str, key) -> Compound | None:
    """The saved modifier of ``key``: an id from 1.21, before it a UUID as four ints
    (AttributeInstance.getModifier)."""
    field = _key_field(entity)
    if isinstance(key, str):
        return next((m for m in _saved(entity, name) if isinstance(m, Compound) and str(m.get(field, "")) == key),
                    None)
    return next((m for m in _saved(entity, name) if isinstance(m, Compound) and isinstance(m.get(field), IntArray)
                 and tuple(m[field]) == tuple(key)), None)


def _saved_modifier(entity, key, label: str, amount: float, operation: str) -> Compound:
    """AttributeModifier as the entity's release saves it: {id, amount, operation} from 1.21; {uuid,
    name, amount, operation} in 1.20.5 - 1.20.6 (AttributeModifier.CODEC); before, AttributeModifier.save:
    {Name, Amount, Operation (0 - 2), UUID}."""
    if entity.release >= MODIFIER_IDS:
        return Compound(id=String(key), amount=Double(amount), operation=String(operation))
    if entity.release >= CODEC_ATTRIBUTES:
        return Compound(uuid=IntArray(key), name=String(label), amount=Double(amount), operation=String(operation))
    return Compound(Name=String(label), Amount=Double(amount), Operation=Int(_OPERATIONS.index(operation)),
                    UUID=IntArray(key))


def _transient(entity, name: str) -> dict:
    """The equipment's (transient) modifiers on the attribute: {id: (amount, operation)}."""
    found = entity.equipment_modifiers
    return found.get(name, {}) if found else {}


def set_transient(entity, name: str, modifier_id: str, amount_operation: tuple[float, str] | None) -> None:
    """AttributeInstance.addTransientModifier (after removeModifier of the id) or, with None, the
    removal: the equipment's modifiers are not saved with the entity."""
    found = entity.equipment_modifiers if entity.equipment_modifiers is not None else {}
    entity.equipment_modifiers = found
    permanent = _find_modifier(entity, name, modifier_id)
    if permanent is not None:  # removeModifier(id) removes any modifier of the id first
        _modifiers(entity, name).remove(permanent)
    if amount_operation is None:
        found.get(name, {}).pop(modifier_id, None)
    else:
        found.setdefault(name, {})[modifier_id] = amount_operation
    _changed(entity)


def add_modifier(entity, name: str, key, amount: float, operation: str, label: str = "") -> bool:
    """A permanent modifier (AttributeInstance.addPermanentModifier): ``key`` its id, before 1.21 its
    UUID as four ints, ``label`` its name then. False when one of that key is already on the
    attribute (the equipment's too)."""
    if _find_modifier(entity, name, key) is not None or key in _transient(entity, name):
        return False
    _modifiers(entity, name).append(_saved_modifier(entity, key, label, amount, operation))
    _changed(entity)
    return True


def remove_modifier(entity, name: str, modifier_id) -> bool:
    found = _find_modifier(entity, name, modifier_id)
    if found is None:
        if modifier_id in _transient(entity, name):
            set_transient(entity, name, modifier_id, None)
            return True
        return False
    _modifiers(entity, name).remove(found)
    _changed(entity)
    return True


def _changed(entity) -> None:
    """After an attribute change: the health and the absorption within their new maximums
    (LivingEntity.onAttributeUpdated), the size at the new scale."""
    entity.max_health_seen = None
    _sync_health(entity)
    absorption = entity.data.get("AbsorptionAmount")
    if (is_living(entity.type) and is_numeric(absorption) and numeric_value(absorption) > 0  # else read nothing
            and numeric_value(absorption) > attribute_value(entity, "max_absorption")):
        entity.data["AbsorptionAmount"] = Float(float(F32(attribute_value(entity, "max_absorption"))))
    entity.refresh_sizes()


def modifier_value(entity, name: str, modifier_id) -> float | None:
    found = _find_modifier(entity, name, modifier_id)
    if found is None:
        transient = _transient(entity, name).get(modifier_id)
        return None if transient is None else transient[0]
    return _number(found.get("amount", found.get("Amount")))


def attribute_value(entity, name: str) -> float:
    """AttributeInstance.calculateValue: the base plus add_value modifiers, then each
    add_multiplied_base adds base x amount, each add_multiplied_total multiplies by 1 + amount;
    clamped to the attribute's range (RangedAttribute.sanitizeValue: NaN reads the minimum)."""
    base = base_value(entity, name)
    modifiers = _saved_modifiers(entity, name)
    modifiers += [(op, amount) for amount, op in _transient(entity, name).values()]
    base += sum(a for op, a in modifiers if op == "add_value")
    value = base + sum(base * a for op, a in modifiers if op == "add_multiplied_base")
    for op, a in modifiers:
        if op == "add_multiplied_total":
            value *= 1.0 + a
    _, lo, hi = DEFAULTS[name]
    return lo if math.isnan(value) else min(max(value, lo), hi)


# ---------------------------------------------------------------------- health and damage

def max_health(entity) -> float:
    """The max_health attribute's value. A player's is kept until an attribute of it changes
    (:func:`_changed`): only the emulator's own paths change a player's NBT (the game refuses
    ``data`` on players), and the food's tick asks each tick."""
    if not entity.is_player:
        return attribute_value(entity, "max_health")
    if entity.max_health_seen is None:
        entity.max_health_seen = attribute_value(entity, "max_health")
    return entity.max_health_seen


def health(entity) -> float:
    return _number(entity.data.get("Health"), default_base(entity.type, "max_health"))


def set_health(entity, value: float) -> None:
    """LivingEntity.setHealth: clamped to [0, max health], stored as a float."""
    entity.data["Health"] = Float(float(F32(min(max(value, 0.0), attribute_value(entity, "max_health")))))


def _sync_health(entity) -> None:
    """A lower max health lowers the health with it (LivingEntity.getHealth stays <= getMaxHealth)."""
    if is_living(entity.type) and health(entity) > attribute_value(entity, "max_health"):
        set_health(entity, health(entity))


def heal(entity, amount: float) -> None:
    if health(entity) > 0:
        set_health(entity, health(entity) + amount)


# Player.actuallyHurt: the food exhaustion of the damage types modelled (DamageType.exhaustion)
EXHAUSTION = {**{"minecraft:" + t: 0.0 for t in (
    "on_fire in_wall cramming drown starve fall fly_into_wall out_of_world generic magic wither dragon_breath "
    "freeze stalagmite indirect_magic sonic_boom outside_border generic_kill").split()}, **{"minecraft:" + t: 0.1 for t in (
    "in_fire campfire lightning_bolt lava hot_floor cactus dry_out sweet_berry_bush falling_block falling_anvil "
    "falling_stalactite sting mob_attack mob_attack_no_aggro player_attack arrow trident mob_projectile spit "
    "fireworks unattributed_fireball fireball wither_skull thrown thorns explosion player_explosion "
    "bad_respawn_point wind_charge").split()}}  # DamageTypes.bootstrap (1.21)


def hurt(state, entity, amount: float, bypasses_invulnerability: bool = False,
         damage_type: str = "minecraft:generic", wear=None, record=None, attacker=None) -> bool:
    """LivingEntity.hurtServer without AI: refused for invulnerable entities, creative and
    spectator players (unless the type bypasses invulnerability), a player just joined
    (:mod:`emulator.world.spawn_protection`) and the dead; within the 10 ticks
    after a hurt only the excess over the last hurt applies. Returns whether it hurt. Unless the
    type is in #bypasses_armor, ``wear(state, entity, damage, type)`` wears the armour
    (hurtArmor) and armour points reduce the damage as CombatRules.getDamageAfterAbsorb does, then absorption
    (LivingEntity.actuallyHurt); a player counts ``damage_absorbed``/``damage_taken`` and the
    type's food exhaustion; ``record(damage)`` hears the damage to health when there is some
    (CombatTracker.recordDamage). The resistance effect reduces it after the armour
    (:func:`_after_resistance`; ``attacker``: the responsible entity)."""
    invulnerable = entity.data.get("Invulnerable") or (entity.is_player and entity.gamemode in ("creative", "spectator"))
    if (invulnerable and not bypasses_invulnerability) or health(entity) <= 0:
        return False
    if entity.is_player and spawn_protection.refuses(state, entity, bypasses_invulnerability):
        return False  # just joined: ServerPlayer.hurt (spawnInvulnerableTime) / isInvulnerableTo (!hasClientLoaded())
    timers = state.hurt_timers.setdefault(entity, [0, 0.0])  # LivingEntity.invulnerableTime, lastHurt
    if not takes_full_hurt(state, entity, bypasses_invulnerability):
        if amount <= timers[1]:
            return False
        dealt, timers[1] = amount - timers[1], amount
    else:
        dealt, timers[0], timers[1] = amount, 20, amount
        entity.data["HurtTime"] = Short(10)
    armoured = not state.resources.in_tag("damage_type", "minecraft:bypasses_armor", damage_type)
    if armoured and wear is not None:  # LivingEntity.getDamageAfterArmorAbsorb: hurtArmor, then the reduction
        wear(state, entity, dealt, damage_type)
    after = _after_resistance(state, entity, _after_armour(entity, dealt, not armoured), damage_type, attacker)
    _actually_hurt(state, entity, after, damage_type, record)
    return True


def _after_resistance(state, entity, damage, damage_type: str, attacker):
    """LivingEntity.getDamageAfterMagicAbsorb's resistance effect: (amplifier + 1) x 5 of 25 parts
    less (float math; none for #bypasses_effects and #bypasses_resistance); the damage resisted x 10,
    rounded, counts as a player's ``damage_resisted``, else as the attacking player's
    ``damage_dealt_resisted``."""
    effect = _effect(entity, "minecraft:resistance")
    if effect is None or any(state.resources.in_tag("damage_type", tag, damage_type)
                             for tag in ("minecraft:bypasses_effects", "minecraft:bypasses_resistance")):
        return damage
    old = F32(damage)
    damage = max(F32(old * F32(25 - (_amplifier(effect) + 1) * 5)) / F32(25.0), F32(0.0))
    resisted = F32(old - damage)
    counted = entity if entity.is_player else attacker if attacker is not None and attacker.is_player else None
    if counted is not None and F32(0.0) < resisted < F32(3.4028235e37):
        stat = "damage_resisted" if counted is entity else "damage_dealt_resisted"
        statistics.award(state, counted, statistics.stat_name("custom", stat), math.floor(resisted * F32(10.0) + F32(0.5)))
    return damage


def takes_full_hurt(state, entity, bypasses_invulnerability: bool = False) -> bool:
    """LivingEntity.hurtServer's tookFullDamage: not within the first 10 of the 20 ticks after the
    last full hurt (then only the excess counts, and there is no knockback)."""
    timers = state.hurt_timers.get(entity)
    return timers is None or timers[0] <= 10 or bypasses_invulnerability


KNOCKBACK_MIN_SQUARED = F32(1.0e-5)  # LivingEntity.knockback: below it the direction is random


def knockback(entity, strength: float, x: float, z: float) -> bool:
    """LivingEntity.knockback: the strength less the knockback_resistance share; the motion halved
    less the (x, z) direction normalised and scaled by it (Vec3.normalize), and on the ground
    min(0.4, y / 2 + strength) up. False (nothing done) when the direction is too short: the game
    then draws one from Math.random, which no pack can reproduce."""
    strength *= 1.0 - attribute_value(entity, "knockback_resistance")
    if strength <= 0.0:
        return True
    if x * x + z * z < KNOCKBACK_MIN_SQUARED:
        return False
    length = math.sqrt(x * x + z * z)
    push_x, push_z = x / length * strength, z / length * strength
    mx, my, mz = entity.motion
    on_ground = bool(int(_number(entity.data.get("OnGround"))))
    entity.motion = (mx / 2.0 - push_x, min(0.4, my / 2.0 + strength) if on_ground else my, mz / 2.0 - push_z)
    return True


def _actually_hurt(state, entity, amount: float, damage_type: str, record=None) -> None:
    """LivingEntity/Player.actuallyHurt after armour: absorption first, then health, the damage to
    health told to ``record`` first (CombatTracker.recordDamage comes before setHealth)."""
    amount = F32(amount)
    absorption = F32(_number(entity.data.get("AbsorptionAmount")))
    left = max(amount - absorption, F32(0.0))
    absorbed = amount - left
    if absorbed > 0:
        entity.data["AbsorptionAmount"] = Float(float(absorption - absorbed))
    if entity.is_player and 0 < absorbed < F32(3.4028235e37):
        statistics.award(state, entity, statistics.stat_name("custom", "damage_absorbed"), round(float(absorbed) * 10))
    if left == 0:
        return
    if entity.is_player:
        if damage_type not in EXHAUSTION:
            state.error(f"the food exhaustion of damage type {damage_type} is not modelled", severity="warning",
                        unmodelled=True)
        else:
            exhaust(entity, F32(EXHAUSTION[damage_type]))
        if left < F32(3.4028235e37):
            statistics.award(state, entity, statistics.stat_name("custom", "damage_taken"),
                             math.floor(left * F32(10.0) + F32(0.5)))
    if record is not None:
        record(float(left))
    set_health(entity, health(entity) - float(left))


def exhaust(player, amount) -> None:
    """FoodData.addExhaustion: min(exhaustion + amount, 40)."""
    current = F32(_number(player.data.get("foodExhaustionLevel")))
    player.data["foodExhaustionLevel"] = Float(float(min(current + amount, F32(40.0))))


def cause_exhaustion(player, amount) -> None:
    """Player.causeFoodExhaustion: none while the player's abilities make it invulnerable
    (creative, spectator)."""
    if player.gamemode not in ("creative", "spectator"):
        exhaust(player, amount)


def eat(player, nutrition: int, saturation) -> None:
    """FoodData.add(nutrition, saturation): the food level clamped to 0..20, the saturation to 0..the
    food level."""
    level = min(max(nutrition + int(_number(player.data.get("foodLevel"), 20)), 0), 20)
    current = F32(_number(player.data.get("foodSaturationLevel"), 5.0))
    player.data["foodLevel"] = Int(level)
    player.data["foodSaturationLevel"] = Float(float(min(max(F32(saturation) + current, F32(0.0)), F32(level))))


def _food_busy(state, player) -> bool:
    """Whether :func:`tick_food` would change something now."""
    data = player.data
    food = int(_number(data.get("foodLevel"), 20))
    hurt_now = 0.0 < health(player) < max_health(player)
    if (state.level_settings.difficulty == "peaceful" and state.gamerules.get("naturalRegeneration") != "false"
            and (hurt_now or food < 20 or F32(_number(data.get("foodSaturationLevel"), 5.0)) < F32(20.0))):
        return True
    return (F32(_number(data.get("foodExhaustionLevel"))) > F32(4.0) or int(_number(data.get("foodTickTimer"))) != 0
            or food <= 0 or (food >= 18 and hurt_now))


def _peaceful_regeneration(state, player) -> None:
    """ServerPlayer.tickRegeneration (Player.aiStep, before the food's tick): on peaceful every 20
    ticks of its age 1 health below the maximum and a point of saturation below 20, every 10 a point
    of food below 20."""
    age, data = player.tick_count(state.tick), player.data
    if age % 20 == 0:
        if health(player) < max_health(player):
            heal(player, 1.0)
        saturation = F32(_number(data.get("foodSaturationLevel"), 5.0))
        if saturation < F32(20.0):
            data["foodSaturationLevel"] = Float(float(saturation + F32(1.0)))
    food = int(_number(data.get("foodLevel"), 20))
    if age % 10 == 0 and food < 20:
        data["foodLevel"] = Int(food + 1)


def tick_food(state, player, harm) -> None:
    """:func:`food_tick`, unless it changed nothing last tick and reads the same now (a player's
    food is read each tick: most ticks, nothing moves; the same tag objects, rule and difficulty)."""
    data, seen = player.data, player.food_seen
    food, saturation, exhaustion = data.get("foodLevel"), data.get("foodSaturationLevel"), data.get("foodExhaustionLevel")
    timer, now = data.get("foodTickTimer"), data.get("Health")
    rule, difficulty = state.gamerules.values.get("naturalRegeneration"), state.level_settings.difficulty
    if (seen is not None and seen[0] is food and seen[1] is saturation and seen[2] is exhaustion and seen[3] is timer
            and seen[4] is now and seen[5] == player.max_health_seen and seen[6] is rule and seen[7] == difficulty):
        return
    food_tick(state, player, harm)
    quiet = (data.get("foodLevel") is food and data.get("foodSaturationLevel") is saturation
             and data.get("foodExhaustionLevel") is exhaustion and data.get("foodTickTimer") is timer
             and data.get("Health") is now and difficulty != "peaceful")  # peaceful's regeneration counts the age
    player.food_seen = (food, saturation, exhaustion, timer, now, player.max_health_seen, rule, difficulty) if quiet else None


def food_tick(state, player, harm) -> None:
    """Peaceful's regeneration, then FoodData.tick: exhaustion over 4 takes a point of saturation,
    else (not on peaceful) of food;
    with the naturalRegeneration rule a hurt player heals from a full food bar with saturation
    (every 10 ticks, min(saturation, 6) / 6, costing that much exhaustion) or from 18 food points
    (every 80 ticks, 1, costing 6); with no food it starves every 80 ticks (magic-free ``starve``
    damage, down to 10 health on easy and 1 on normal). ``harm(state, player, amount, type)``."""
    data, peaceful = player.data, state.level_settings.difficulty == "peaceful"
    regenerates = state.gamerules.get("naturalRegeneration") != "false"
    if peaceful and regenerates:
        _peaceful_regeneration(state, player)
    exhaustion = F32(_number(data.get("foodExhaustionLevel")))
    saturation = F32(_number(data.get("foodSaturationLevel"), 5.0))
    food = int(_number(data.get("foodLevel"), 20))
    if exhaustion > F32(4.0):
        data["foodExhaustionLevel"] = Float(float(exhaustion - F32(4.0)))
        if saturation > F32(0.0):
            saturation = max(saturation - F32(1.0), F32(0.0))
            data["foodSaturationLevel"] = Float(float(saturation))
        elif not peaceful:
            food = max(food - 1, 0)
            data["foodLevel"] = Int(food)
    hurt_now = 0.0 < health(player) < max_health(player)  # Player.isHurt
    timer = before = int(_number(data.get("foodTickTimer")))
    if regenerates and saturation > F32(0.0) and hurt_now and food >= 20:
        timer += 1
        if timer >= 10:
            amount = min(saturation, F32(6.0))
            heal(player, float(amount / F32(6.0)))
            exhaust(player, amount)
            timer = 0
    elif regenerates and food >= 18 and hurt_now:
        timer += 1
        if timer >= 80:
            heal(player, 1.0)
            exhaust(player, F32(6.0))
            timer = 0
    elif food <= 0:
        timer += 1
        if timer >= 80:
            difficulty, now = state.level_settings.difficulty, health(player)
            if now > 10.0 or difficulty == "hard" or (now > 1.0 and difficulty == "normal"):
                harm(state, player, 1.0, "minecraft:starve")
            timer = 0
    else:
        timer = 0
    if timer != before:
        data["foodTickTimer"] = Int(timer)


def _after_armour(entity, amount: float, bypass: bool) -> float:
    """CombatRules.getDamageAfterAbsorb (float math) with the entity's armour attributes, unless the
    damage type is in #bypasses_armor."""
    if bypass:
        return amount
    armour, toughness = F32(attribute_value(entity, "armor")), F32(attribute_value(entity, "armor_toughness"))
    if armour <= 0:
        return amount
    damage = F32(amount)
    strength = F32(2.0) + toughness / F32(4.0)
    reduced = min(max(armour - damage / strength, armour * F32(0.2)), F32(20.0))
    return float(damage * (F32(1.0) - reduced / F32(25.0)))


# ---------------------------------------------------------------------- effects
LEVITATION = "minecraft:levitation"  # its start is kept for the levitation trigger (ServerPlayer)
INSTANT = {"minecraft:instant_health", "minecraft:instant_damage", "minecraft:saturation"}


def effects(entity) -> List:
    found = entity.data.get("active_effects")
    if not isinstance(found, List):
        found = entity.data["active_effects"] = List()
    return found


def _effect(entity, effect_id: str) -> Compound | None:
    """The entity's effect ``effect_id`` (reading it saves no empty ``active_effects``)."""
    found = entity.data.get("active_effects")
    return next((e for e in found if str(e.get("id", "")) == effect_id), None) if isinstance(found, List) else None


def _longer(a: int, b: int) -> bool:
    """Duration ``a`` outlasts ``b`` (infinite outlasts everything)."""
    return b != INFINITE and (a == INFINITE or a > b)


# MobEffects.register: the attribute modifier an effect adds while it lasts, transient (not saved),
# its amount x (amplifier + 1) (MobEffect.AttributeTemplate.create): (attribute, id, amount, operation)
EFFECT_MODIFIERS = {
    "minecraft:speed": ("movement_speed", "effect.speed", float(F32(0.2)), "add_multiplied_total"),
    "minecraft:slowness": ("movement_speed", "effect.slowness", float(F32(-0.15)), "add_multiplied_total"),
    "minecraft:haste": ("attack_speed", "effect.haste", float(F32(0.1)), "add_multiplied_total"),
    "minecraft:mining_fatigue": ("attack_speed", "effect.mining_fatigue", float(F32(-0.1)), "add_multiplied_total"),
    "minecraft:strength": ("attack_damage", "effect.strength", 3.0, "add_value"),
    "minecraft:weakness": ("attack_damage", "effect.weakness", -4.0, "add_value"),
    "minecraft:health_boost": ("max_health", "effect.health_boost", 4.0, "add_value"),
    "minecraft:absorption": ("max_absorption", "effect.absorption", 4.0, "add_value"),
    "minecraft:luck": ("luck", "effect.luck", 1.0, "add_value"),
    "minecraft:unluck": ("luck", "effect.unluck", -1.0, "add_value"),
    "minecraft:jump_boost": ("safe_fall_distance", "effect.jump_boost", 1.0, "add_value"),
}


def _effect_modifier(entity, effect_id: str, amplifier: int | None) -> None:
    """MobEffect.addAttributeModifiers (removeAttributeModifiers with no amplifier) of the effect's
    modifier, on an entity that has the attribute."""
    found = EFFECT_MODIFIERS.get(effect_id)
    if found is None or not has_attribute(entity.type, found[0], entity.release):
        return
    name, modifier_id, amount, operation = found
    set_transient(entity, name, "minecraft:" + modifier_id,
                  None if amplifier is None else (amount * (amplifier + 1), operation))


def _absorb(entity, amount: float) -> None:
    """LivingEntity.setAbsorptionAmount: clamped to 0..the max_absorption attribute."""
    entity.data["AbsorptionAmount"] = Float(float(F32(min(max(amount, 0.0), attribute_value(entity, "max_absorption")))))


def give_effect(state, entity, effect_id: str, duration: int, amplifier: int, visible: bool) -> bool:
    """LivingEntity.addEffect: a new effect, or MobEffectInstance.update of the one there (a higher
    amplifier replaces it, the same amplifier with a longer duration extends it, a change of
    particles shows); False when nothing changed. Instant effects are kept like the others: the
    entity's tick applies them (:func:`tick_living`), so a weaker one given while a stronger one
    waits changes nothing. An effect the entity's type refuses (:data:`REFUSED_EFFECTS`) is not
    added."""
    if entity.type in REFUSED_EFFECTS.get(effect_id, ()):
        return False
    current = _effect(entity, effect_id)
    if current is None:
        effects(entity).append(Compound(id=String(effect_id), amplifier=Byte(amplifier), duration=Int(duration),
                                        ambient=Byte(0), show_particles=Byte(int(visible)), show_icon=Byte(1)))
        _effect_modifier(entity, effect_id, amplifier & 0xFF)  # onEffectAdded
        if effect_id == LEVITATION and entity.is_player:  # ServerPlayer.onEffectAdded
            entity.levitation_start = (entity.pos, entity.tick_count(state.tick))
        changed = True
    else:
        old_amp, old_duration = _amplifier(current), int(_number(current.get("duration")))
        changed = False
        if amplifier > old_amp or (amplifier == old_amp and _longer(duration, old_duration)):
            current["amplifier"], current["duration"] = Byte(amplifier), Int(duration)
            _effect_modifier(entity, effect_id, _amplifier(current))  # onEffectUpdated: removed, added again
            changed = True
        if bool(_number(current.get("show_particles"), 1)) != visible:
            current["show_particles"] = Byte(int(visible))
            changed = True
    if effect_id == "minecraft:absorption":  # AbsorptionMobEffect.onEffectStarted, for every addEffect
        _absorb(entity, max(_number(entity.data.get("AbsorptionAmount")), float(4 * (1 + (amplifier & 0xFF)))))
    return changed


def effect_amplifier(entity, effect_id: str) -> int | None:
    """The amplifier of the entity's effect ``effect_id``, None without it."""
    found = _effect(entity, effect_id)
    return None if found is None else _amplifier(found)


def _amplifier(effect: Compound) -> int:
    """The saved amplifier is a byte; the game reads it back unsigned (0-255)."""
    return int(_number(effect.get("amplifier"))) & 0xFF


UNDEAD = frozenset(f"minecraft:{n}" for n in (
    "zombie", "husk", "drowned", "zombie_villager", "zombified_piglin", "zoglin", "zombie_horse", "skeleton",
    "stray", "wither_skeleton", "bogged", "skeleton_horse", "phantom", "wither"))

# LivingEntity.canBeAffected (#ignores_poison_and_regen: #undead; #immune_to_infested,
# #immune_to_oozing) and its overrides (Spider, AbstractNautilus, WitherBoss, WitherSkeleton,
# Parched): the effects an entity type refuses
REFUSED_EFFECTS = {
    "minecraft:regeneration": UNDEAD,
    "minecraft:poison": UNDEAD | {"minecraft:spider", "minecraft:cave_spider", "minecraft:nautilus",
                                  "minecraft:zombie_nautilus"},
    "minecraft:wither": frozenset({"minecraft:wither", "minecraft:wither_skeleton"}),
    "minecraft:infested": frozenset({"minecraft:silverfish"}),
    "minecraft:oozing": frozenset({"minecraft:slime"}),
    "minecraft:weakness": frozenset({"minecraft:parched"}),
}


def _harm(state, entity, amount: float, damage_type: str = "minecraft:magic") -> bool:
    return hurt(state, entity, amount, damage_type=damage_type)


def apply_instant(state, entity, effect_id: str, amplifier: int, harm) -> None:
    """HealOrHarmMobEffect.applyInstantenousEffect: heal ``max(4 << amplifier, 0)`` or hurt
    ``6 << amplifier`` (Java int shifts: the distance is taken mod 32 and the result wraps, so
    amplifier 255 heals nothing); the undead take them the other way round."""
    heals = (effect_id == "minecraft:instant_health") != (entity.type in UNDEAD)
    if effect_id == "minecraft:saturation":  # SaturationMobEffect: FoodData.eat(amplifier + 1, 1.0F)
        if entity.is_player:
            nutrition = amplifier + 1
            eat(entity, nutrition, F32(nutrition) * F32(1.0) * F32(2.0))  # FoodConstants.saturationByModifier
        return
    if heals:
        heal(entity, float(max(wrap32(4 << (amplifier & 31)), 0)))
    elif wrap32(6 << (amplifier & 31)) > 0:
        harm(state, entity, float(wrap32(6 << (amplifier & 31))))


def clear_effects(entity, effect_id: str | None = None) -> bool:
    """Remove every effect, or the one given; False when there was none to remove."""
    kept = List(e for e in effects(entity) if effect_id is not None and str(e.get("id", "")) != effect_id)
    removed = len(effects(entity)) != len(kept)
    for effect in effects(entity):
        if effect not in kept:  # onEffectsRemoved
            _effect_modifier(entity, str(effect.get("id", "")), None)
    entity.data["active_effects"] = kept
    _drop_if_empty(entity)
    return removed


def _drop_if_empty(entity) -> None:
    """LivingEntity.addAdditionalSaveData writes ``active_effects`` only when there is one."""
    if not entity.data.get("active_effects", True):
        del entity.data["active_effects"]


def _not_hurt(hurt_time) -> bool:
    """No ``HurtTime`` to count down: none, or a number not above 0 (a cheap first look)."""
    return hurt_time is None or (is_numeric(hurt_time) and hurt_time <= 0)


def tick_is_idle(state) -> bool:
    """Whether :func:`tick_living` would change nothing now: no effect counting down, no hurt
    time or hurt timer running."""
    hurting = bool(state.hurt_timers)
    for entity in state.entities.living_mobs():
        found, hurt_time = entity.data.get("active_effects"), entity.data.get("HurtTime")
        if found is None and not hurting and _not_hurt(hurt_time) and not entity.is_player:
            continue  # the common case, every tick: no effect, no hurt time, no hurt timer anywhere
        if isinstance(found, List) and any(int(_number(e.get("duration"))) != INFINITE or str(e.get("id", "")) in TICKING
                                           or str(e.get("id", "")) == "minecraft:absorption" for e in found):
            return False
        if entity.is_player and _food_busy(state, entity):
            return False
        if (is_numeric(hurt_time) and numeric_value(hurt_time) > 0) or (hurting and entity in state.hurt_timers):
            return False
    return True


def tick_living(state, harm=None) -> list:
    """Each living entity's tick, as far as a pack can see it: a player's food (:func:`tick_food`),
    then every effect ticks (LivingEntity.tickEffects, MobEffectInstance.tickServer: an instant
    effect acts each tick it has left, regeneration, poison, wither and hunger when due, see
    TICKING; then the duration counts down) and an expired one is removed; hurt timers run out.
    ``harm(state, entity, amount, damage_type)`` deals an effect's damage (default: :func:`hurt`,
    no death). Returns the entities that lost an
    effect (the game tells their players' ``effects_changed`` trigger, ServerPlayer.onEffectsRemoved)."""
    mobs = state.entities.living_mobs()  # a display or a marker reads no active_effects (Entity.load)
    if not mobs:  # a pack of markers and displays: every tick
        return mobs
    lost = []
    hurting = bool(state.hurt_timers)  # only the entity ticking adds itself (an instant effect's harm)
    harm = harm or _harm
    for entity in mobs:
        found, hurt_time = entity.data.get("active_effects"), entity.data.get("HurtTime")
        if found is not None or hurting or not _not_hurt(hurt_time):  # else, as usual, nothing to count down
            if _tick_body(state, entity, found, hurt_time, harm):
                lost.append(entity)
        if entity.is_player:  # after its living tick, dead or alive (ServerPlayer.doTick)
            tick_food(state, entity, harm)
    return lost


def _tick_body(state, entity, found, hurt_time, harm) -> bool:
    """The entity's effects (True when one expired), hurt time and hurt timers."""
    expired = False
    if isinstance(found, List) and found:
        expired = _tick_effects(state, entity, found, harm)
        _drop_if_empty(entity)
        hurt_time = entity.data.get("HurtTime")  # an instant effect's harm may have set it
    if is_numeric(hurt_time) and numeric_value(hurt_time) > 0:
        entity.data["HurtTime"] = Short(int(numeric_value(hurt_time)) - 1)
    timers = state.hurt_timers.get(entity) if state.hurt_timers else None
    if timers is not None:
        timers[0] -= 1
        if timers[0] <= 0:
            del state.hurt_timers[entity]
    return expired


# the effects whose tick a pack can see besides the instant ones, and how often it comes: every
# ``interval >> amplifier`` ticks of the count (MobEffect.shouldApplyEffectTickThisTick), 1 = every tick
TICKING = {"minecraft:regeneration": 50, "minecraft:poison": 25, "minecraft:wither": 40, "minecraft:hunger": 1}


def _due(effect_id: str, count: int, amplifier: int) -> bool:
    """Whether the effect acts at this count (its duration, or the entity's age when infinite)."""
    if effect_id in INSTANT:
        return count >= 1  # InstantenousMobEffect
    interval = TICKING.get(effect_id, 0) >> (amplifier & 31)  # a Java int shift
    return interval <= 0 or count % interval == 0


def _apply_tick(state, entity, effect_id: str, amplifier: int, harm) -> None:
    """MobEffect.applyEffectTick of the effects in TICKING (Regeneration-, Poison-, Wither- and
    HungerMobEffect)."""
    if effect_id == "minecraft:regeneration":
        if health(entity) < max_health(entity):
            heal(entity, 1.0)
    elif effect_id == "minecraft:poison":
        if health(entity) > 1.0:
            harm(state, entity, 1.0, "minecraft:magic")
    elif effect_id == "minecraft:wither":
        harm(state, entity, 1.0, "minecraft:wither")
    elif entity.is_player:  # hunger
        cause_exhaustion(entity, F32(0.005) * F32(amplifier + 1))


def _tick_effects(state, entity, found: List, harm) -> bool:
    """One tick of each effect (MobEffectInstance.tickServer: it acts when due, then counts down);
    True when one expired."""
    expired = False
    for effect in list(found):
        duration = int(_number(effect.get("duration")))
        effect_id = str(effect.get("id", ""))
        if effect_id in INSTANT or effect_id in TICKING:
            count = entity.tick_count(state.tick) if duration == INFINITE else duration
            if duration != 0 and _due(effect_id, count, _amplifier(effect)):
                if effect_id in INSTANT:
                    apply_instant(state, entity, effect_id, _amplifier(effect), harm)
                else:
                    _apply_tick(state, entity, effect_id, _amplifier(effect), harm)
        spent = effect_id == "minecraft:absorption" and duration != 0 and _number(entity.data.get("AbsorptionAmount")) <= 0
        if duration == INFINITE and not spent:
            continue
        if duration <= 1 or spent:  # AbsorptionMobEffect.applyEffectTick: gone with the absorption
            found.remove(effect)
            _effect_modifier(entity, effect_id, None)
            expired = True
        else:
            effect["duration"] = Int(duration - 1)
    return expired


# ---------------------------------------------------------------------- experience
def xp_needed(level: int) -> int:
    """Player.getXpNeededForNextLevel."""
    if level >= 30:
        return wrap32(112 + (level - 30) * 9)  # int arithmetic: wraps for huge levels
    return 37 + (level - 15) * 5 if level >= 15 else 7 + level * 2


def _xp(player) -> tuple[int, np.float32, int]:
    """The level (the entity's ``level``, what ``level=`` selects), progress and total."""
    data = player.data
    return player.level, F32(_number(data.get("XpP"))), int(_number(data.get("XpTotal")))


def _store_xp(player, level: int, progress, total: int) -> None:
    player.level = level
    player.data.update(XpLevel=Int(level), XpP=Float(float(F32(progress))), XpTotal=Int(total))


def add_levels(player, amount: int) -> None:
    """Player.giveExperienceLevels: below 0 the level, progress and total reset to 0."""
    level, progress, total = _xp(player)
    level = wrap32(level + amount)
    if level < 0:
        level, progress, total = 0, F32(0.0), 0
    _store_xp(player, level, progress, total)


def add_points(player, amount: int) -> None:
    """Player.giveExperiencePoints: the score and total grow, the progress moves by
    amount / needed (float), carrying whole levels up or down."""
    level, progress, total = _xp(player)
    player.data["Score"] = Int(wrap32(int(_number(player.data.get("Score"))) + amount))
    progress = F32(progress + F32(amount) / F32(xp_needed(level)))
    total = min(max(total + amount, 0), 2**31 - 1)
    _store_xp(player, level, progress, total)
    while progress < 0:
        points = F32(progress * F32(xp_needed(level)))
        if level > 0:
            add_levels(player, -1)
            level = _xp(player)[0]
            progress = F32(F32(1.0) + points / F32(xp_needed(level)))
        else:
            add_levels(player, -1)
            level, progress = 0, F32(0.0)
        _store_xp(player, level, progress, _xp(player)[2])
    while progress >= 1:
        progress = F32((progress - F32(1.0)) * F32(xp_needed(level)))
        add_levels(player, 1)
        level = _xp(player)[0]
        progress = F32(progress / F32(xp_needed(level)))
        _store_xp(player, level, progress, _xp(player)[2])


def set_levels(player, amount: int) -> None:
    """Player.setExperienceLevels (ExperienceCommand's ``set ... levels``)."""
    level, progress, total = _xp(player)
    _store_xp(player, amount, progress, total)


def set_points(player, amount: int) -> bool:
    """ExperienceCommand's ``set ... points``: refused at or above the points of the current
    level; else Player.setExperiencePoints (progress = amount / needed, at most (needed - 1) / needed)."""
    level, _, total = _xp(player)
    if amount >= xp_needed(level):  # compared as ints
        return False
    needed = F32(xp_needed(level))
    _store_xp(player, level, min(max(F32(amount) / needed, F32(0.0)), (needed - F32(1.0)) / needed), total)
    return True


def query_points(player) -> int:
    """``xp query ... points``: Mth.floor(progress x needed)."""
    level, progress, _ = _xp(player)
    return math.floor(F32(progress * F32(xp_needed(level))))


def query_levels(player) -> int:
    return _xp(player)[0]


# ---------------------------------------------------------------------- a player's attack
def reset_attack_strength(state, player) -> None:
    """Player.resetAttackStrengthTicker (join, attack): the game time is kept (WorldState.swung)."""
    state.swung[player] = state.gametime


def swing_damage(state, player) -> tuple[np.float32, np.float32]:
    """Player.attack's base damage and the swing's strength: the attack damage attribute times
    0.2 + 0.8 x strength², the strength (getAttackStrengthScale(0.5)) growing with the ticks since
    the last swing or join over 20 / attack_speed; the swing resets it."""
    ticker = state.gametime - state.swung.get(player, state.gametime)
    delay = F32(1.0 / attribute_value(player, "attack_speed") * 20.0)
    strength = min(max(F32((F32(ticker) + F32(0.5)) / delay), F32(0.0)), F32(1.0))
    reset_attack_strength(state, player)
    return F32(attribute_value(player, "attack_damage")) * (F32(0.2) + strength * strength * F32(0.8)), strength
