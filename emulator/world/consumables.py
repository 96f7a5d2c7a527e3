"""What eating or drinking an item does, as the game reads it from the stack: the item's
``consumable`` (1.21.2+) or ``food`` (1.20.5 - 1.21.1) component as a pack patched it, else the
vanilla item's own properties (foods, potions, milk, honey, stews, the ominous bottle), which the
game keeps in code rather than data.

- ``consumable(stack, version) -> Consumable | None``: how long the use lasts, the food eaten,
  the consume effects, the listeners that act on consuming (potion contents, a suspicious stew's
  effects, an ominous bottle's amplifier) and the use remainder; None when the item is not eaten
  or drunk. Before 1.20.5 only the vanilla items are (their NBT ``Potion`` read for potions).
- ``drawn(effect, rng, per_effect_draw) -> list``: the (effect, duration, amplifier) one
  ``apply_effects`` consume effect gives now, with the probabilities drawn from ``rng`` (the
  emulator's random, not the entity's own).

Not modelled (raise Unmodelled where met): custom potion effects in the pre-1.20.5 NBT form;
``play_sound`` is nothing a pack observes (ignored).

Sources (decompiled 1.21.x and 26.1): world/food/Foods.java, FoodProperties.java (Builder.build:
saturation = FoodConstants.saturationByModifier = nutrition x modifier x 2), world/item/component/
Consumables.java (DEFAULT_FOOD/DEFAULT_DRINK 1.6 s, DRIED_KELP 0.8 s, HONEY_BOTTLE 2 s and its
effects), world/item/Items.java (which item has which food, consumable and ``usingConvertsTo``),
world/item/alchemy/Potions.java and PotionContents.java (onConsume: instantaneous effects at once,
the others added), SuspiciousStewEffects.onConsume, OminousBottleAmplifier.onConsume (bad_omen
120000 ticks), consume_effects/ApplyStatusEffectsConsumeEffect.java (one draw for the whole list);
before 1.20.5 Item.getUseDuration (32 ticks, 16 for fast food), HoneyBottleItem (40),
LivingEntity.addEatEffect (one draw per effect).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack, from_nbt
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Compound, Float, Int, List, String

F32 = np.float32
CONSUMABLE_VERSION = (1, 21, 2)  # the consumable component; before it, the food component made an item edible
FOOD_VERSION = (1, 20, 5)  # item components
DEFAULT_SECONDS = 1.6  # Consumables.defaultFood / defaultDrink; Item.getUseDuration's 32 ticks before

# Foods: item -> (nutrition, saturation modifier, can always eat)
_FOODS = {
    "apple": (4, 0.3), "baked_potato": (5, 0.6), "beef": (3, 0.3), "beetroot": (1, 0.6), "beetroot_soup": (6, 0.6),
    "bread": (5, 0.6), "carrot": (3, 0.6), "chicken": (2, 0.3), "chorus_fruit": (4, 0.3, True), "cod": (2, 0.1),
    "cooked_beef": (8, 0.8), "cooked_chicken": (6, 0.6), "cooked_cod": (5, 0.6), "cooked_mutton": (6, 0.8),
    "cooked_porkchop": (8, 0.8), "cooked_rabbit": (5, 0.6), "cooked_salmon": (6, 0.8), "cookie": (2, 0.1),
    "dried_kelp": (1, 0.3), "enchanted_golden_apple": (4, 1.2, True), "golden_apple": (4, 1.2, True),
    "golden_carrot": (6, 1.2), "honey_bottle": (6, 0.1, True), "melon_slice": (2, 0.3), "mushroom_stew": (6, 0.6),
    "mutton": (2, 0.3), "poisonous_potato": (2, 0.3), "porkchop": (3, 0.3), "potato": (1, 0.3),
    "pufferfish": (1, 0.1), "pumpkin_pie": (8, 0.3), "rabbit": (3, 0.3), "rabbit_stew": (10, 0.6),
    "rotten_flesh": (4, 0.1), "salmon": (2, 0.1), "spider_eye": (2, 0.8), "suspicious_stew": (6, 0.6, True),
    "sweet_berries": (2, 0.1), "glow_berries": (2, 0.1), "tropical_fish": (1, 0.1),
}
_SECONDS = {"dried_kelp": 0.8, "honey_bottle": 2.0}
_DRINKS = ("potion", "milk_bucket", "honey_bottle", "ominous_bottle")
_REMAINDERS = {"mushroom_stew": "bowl", "rabbit_stew": "bowl", "beetroot_soup": "bowl", "suspicious_stew": "bowl",
               "honey_bottle": "glass_bottle", "potion": "glass_bottle", "milk_bucket": "bucket"}


def _effects(probability: float, *effects) -> Compound:
    return Compound(type=String("minecraft:apply_effects"), probability=Float(probability), effects=List(
        Compound(id=String(e if ":" in e else "minecraft:" + e), duration=Int(d), amplifier=Int(a))
        for e, d, a in effects))


# the consume effects of the vanilla items (Consumables; FoodProperties' effects before 1.21.2)
_CONSUME_EFFECTS = {
    "chicken": [_effects(0.3, ("hunger", 600, 0))],
    "enchanted_golden_apple": [_effects(1.0, ("regeneration", 400, 1), ("resistance", 6000, 0),
                                        ("fire_resistance", 6000, 0), ("absorption", 2400, 3))],
    "golden_apple": [_effects(1.0, ("regeneration", 100, 1), ("absorption", 2400, 0))],
    "poisonous_potato": [_effects(0.6, ("poison", 100, 0))],
    "pufferfish": [_effects(1.0, ("poison", 1200, 1), ("hunger", 300, 2), ("nausea", 300, 0))],
    "rotten_flesh": [_effects(0.8, ("hunger", 600, 0))],
    "spider_eye": [_effects(1.0, ("poison", 100, 0))],
    "honey_bottle": [Compound(type=String("minecraft:remove_effects"), effects=String("minecraft:poison"))],
    "milk_bucket": [Compound(type=String("minecraft:clear_all_effects"))],
    "chorus_fruit": [Compound(type=String("minecraft:teleport_randomly"))],
}

# Potions: id -> its effects (effect, duration, amplifier)
POTIONS: dict[str, tuple] = {f"minecraft:{name}": ((name, ticks, 0),) for name, ticks in (
    ("luck", 6000), ("wind_charged", 3600), ("weaving", 3600), ("oozing", 3600), ("infested", 3600))}
for _name in ("water", "mundane", "thick", "awkward"):
    POTIONS[f"minecraft:{_name}"] = ()
for _name, _effect, _normal, _long, _strong in (
        ("night_vision", "night_vision", 3600, 9600, None), ("invisibility", "invisibility", 3600, 9600, None),
        ("leaping", "jump_boost", 3600, 9600, (1800, 1)), ("fire_resistance", "fire_resistance", 3600, 9600, None),
        ("swiftness", "speed", 3600, 9600, (1800, 1)), ("slowness", "slowness", 1800, 4800, (400, 3)),
        ("water_breathing", "water_breathing", 3600, 9600, None), ("healing", "instant_health", 1, None, (1, 1)),
        ("harming", "instant_damage", 1, None, (1, 1)), ("poison", "poison", 900, 1800, (432, 1)),
        ("regeneration", "regeneration", 900, 1800, (450, 1)), ("strength", "strength", 3600, 9600, (1800, 1)),
        ("weakness", "weakness", 1800, 4800, None), ("slow_falling", "slow_falling", 1800, 4800, None)):
    POTIONS[f"minecraft:{_name}"] = ((_effect, _normal, 0),)
    if _long is not None:
        POTIONS[f"minecraft:long_{_name}"] = ((_effect, _long, 0),)
    if _strong is not None:
        POTIONS[f"minecraft:strong_{_name}"] = ((_effect, *_strong),)
POTIONS["minecraft:turtle_master"] = (("slowness", 400, 3), ("resistance", 400, 2))
POTIONS["minecraft:long_turtle_master"] = (("slowness", 800, 3), ("resistance", 800, 2))
POTIONS["minecraft:strong_turtle_master"] = (("slowness", 400, 5), ("resistance", 400, 3))


@dataclass(frozen=True)
class Food:
    nutrition: int
    saturation: np.float32  # FoodProperties.saturation (nutrition x modifier x 2)
    can_always_eat: bool


@dataclass
class Consumable:
    ticks: int  # 0: consumed at once
    food: Food | None
    effects: list = field(default_factory=list)  # consume effects, the 1.21.2 component's form
    gives: list = field(default_factory=list)  # (effect, duration, amplifier) the listeners add
    remainder: ItemStack | None = None
    per_effect_draw: bool = False  # before 1.21.2 each food effect had its own chance



def drawn(effect: Compound, rng, per_effect_draw: bool = False) -> list:
    """What one ``apply_effects`` consume effect gives now (ApplyStatusEffectsConsumeEffect.apply:
    one draw ``nextFloat() < probability`` for its list; before 1.21.2 one per effect)."""
    chance = float(numeric_value(effect["probability"])) if is_numeric(effect.get("probability")) else 1.0
    listed = [_instance(e) for e in effect.get("effects", List())]
    if per_effect_draw:
        return [e for e in listed if F32(rng.random()) < F32(chance)]
    return listed if F32(rng.random()) < F32(chance) else []


def _instance(tag) -> tuple[str, int, int]:
    """A MobEffectInstance in its codec's form ``{id, duration (default 0), amplifier (default 0)}``."""
    if isinstance(tag, String):
        return (str(tag), 0, 0)
    effect = tag.get("effect", tag) if isinstance(tag.get("effect"), Compound) else tag
    number = lambda key: int(numeric_value(effect[key])) if is_numeric(effect.get(key)) else 0  # noqa: E731
    return (str(effect.get("id", "")), number("duration"), number("amplifier"))


def _ticks(seconds) -> int:
    """Consumable.consumeTicks: (int) (seconds * 20)."""
    value = float(numeric_value(seconds)) if is_numeric(seconds) else seconds if isinstance(seconds, float) \
        else DEFAULT_SECONDS
    return int(F32(value) * F32(20.0))


def _food(tag) -> Food | None:
    if not isinstance(tag, Compound):
        return None
    always = tag.get("can_always_eat")
    return Food(int(numeric_value(tag.get("nutrition", 0))), F32(numeric_value(tag.get("saturation", 0.0))),
                is_numeric(always) and bool(numeric_value(always)))


def _vanilla_food(name: str) -> Food | None:
    found = _FOODS.get(name)
    if found is None:
        return None
    nutrition, modifier, *always = found
    # FoodConstants.saturationByModifier: (float) nutrition * modifier * 2.0F
    return Food(nutrition, F32(nutrition) * F32(modifier) * F32(2.0), bool(always) or name == "honey_bottle")


def _patched(stack: ItemStack, name: str):
    """(found, value): the component as the stack's patch sets or removes it."""
    if "!" + name in stack.patch:
        return True, None
    return (True, stack.patch[name]) if name in stack.patch else (False, None)


def consumable(stack: ItemStack, version) -> Consumable | None:
    """How using ``stack`` consumes it in ``version``; None when it is not eaten or drunk."""
    version = tuple(version)
    name = stack.id.removeprefix("minecraft:") if stack.id.startswith("minecraft:") else None
    if version >= FOOD_VERSION:
        set_food, food_tag = _patched(stack, "minecraft:food")
        food = _food(food_tag) if set_food else (_vanilla_food(name) if name else None)
    else:
        food = _vanilla_food(name) if name else None
    if version >= CONSUMABLE_VERSION:
        found = _modern(stack, name, food)
    elif version >= FOOD_VERSION:
        found = _component_era(stack, name, food)
    else:
        found = _legacy(stack, name, food)
    if found is not None:
        found.gives = _listeners(stack, name, version)
    return found


def _modern(stack: ItemStack, name: str | None, food: Food | None) -> Consumable | None:
    """1.21.2+: the consumable component decides; the food component is one of its listeners."""
    set_consumable, tag = _patched(stack, "minecraft:consumable")
    if set_consumable:
        if not isinstance(tag, Compound):
            return None
        effects = list(tag.get("on_consume_effects", List()))
        ticks = _ticks(tag.get("consume_seconds"))
    elif name in _FOODS or name in _DRINKS:
        effects, ticks = list(_CONSUME_EFFECTS.get(name, ())), _ticks(_SECONDS.get(name, DEFAULT_SECONDS))
    else:
        return None
    return Consumable(ticks, food, effects, remainder=_remainder(stack, name, "minecraft:use_remainder"))


def _component_era(stack: ItemStack, name: str | None, food: Food | None) -> Consumable | None:
    """1.20.5 - 1.21.1: the food component makes an item edible (``eat_seconds``, ``effects``,
    ``using_converts_to``); the vanilla drinks are their own items."""
    set_food, tag = _patched(stack, "minecraft:food")
    if set_food:
        if not isinstance(tag, Compound):
            return None
        effects = [_effects(float(numeric_value(e.get("probability", 1.0))), _instance(e))
                   for e in tag.get("effects", List())]
        found = Consumable(_ticks(tag.get("eat_seconds")), food, effects, per_effect_draw=True)
        converts = tag.get("using_converts_to")
        found.remainder = _stack(converts) if converts is not None else None
        return found
    return _legacy(stack, name, food) if name in _FOODS or name in _DRINKS else None


def _legacy(stack: ItemStack, name: str | None, food: Food | None) -> Consumable | None:
    """The vanilla items' own use (Item.getUseDuration: 32 ticks, 16 for dried kelp, 40 for honey)."""
    if name not in _FOODS and name not in _DRINKS:
        return None
    return Consumable(_ticks(_SECONDS.get(name, DEFAULT_SECONDS)), food, list(_CONSUME_EFFECTS.get(name, ())),
                      remainder=_remainder(stack, name, None), per_effect_draw=True)


def _remainder(stack: ItemStack, name: str | None, component: str | None) -> ItemStack | None:
    if component is not None:
        set_it, tag = _patched(stack, component)
        if set_it:
            return _stack(tag) if tag is not None else None
    return ItemStack("minecraft:" + _REMAINDERS[name]) if name in _REMAINDERS else None


def _stack(tag) -> ItemStack | None:
    found = from_nbt(tag) if isinstance(tag, Compound) else None
    return found if found is not None and not found.is_empty else None


def _listeners(stack: ItemStack, name: str | None, version) -> list:
    """The effects the stack's consume listeners add: potion contents (its potion's then its custom
    effects), a suspicious stew's effects, an ominous bottle's bad omen."""
    gives = []
    if version >= FOOD_VERSION:
        gives += potion_effects(stack, version)
        stew = stack.component("minecraft:suspicious_stew_effects")
        if isinstance(stew, List):
            gives += [(str(e.get("id", "")), _stew_ticks(e), 0) for e in stew]
        bottle = stack.component("minecraft:ominous_bottle_amplifier")
        if name == "ominous_bottle" or bottle is not None:
            gives.append(("minecraft:bad_omen", 120000, int(numeric_value(bottle)) if is_numeric(bottle) else 0))
    elif name == "potion":
        tag = stack.tag or Compound()
        if "CustomPotionEffects" in tag or "custom_potion_effects" in tag:
            raise Unmodelled("a potion's custom effects in the NBT form before 1.20.5")
        gives += _potion(str(tag.get("Potion", "")))
    elif name == "suspicious_stew":
        raise Unmodelled("a suspicious stew's effects in the NBT form before 1.20.5")
    return gives


def potion_effects(stack: ItemStack, version) -> list:
    """PotionContents.getAllEffects (1.20.5+): the (effect, duration, amplifier) of the stack's
    potion, then its custom effects."""
    if tuple(version) < FOOD_VERSION:
        raise Unmodelled("a potion's effects in the NBT form before 1.20.5")
    contents = stack.component("minecraft:potion_contents")
    if isinstance(contents, String):
        contents = Compound(potion=contents)
    if not isinstance(contents, Compound):
        return []
    return _potion(str(contents.get("potion", ""))) + [_instance(e) for e in contents.get("custom_effects", List())]


def _stew_ticks(entry) -> int:
    """SuspiciousStewEffects.Entry: ``duration`` defaults to 160 ticks."""
    duration = entry.get("duration")
    return int(numeric_value(duration)) if is_numeric(duration) else 160


def _potion(potion_id: str) -> list:
    if not potion_id:
        return []
    potion_id = potion_id if ":" in potion_id else "minecraft:" + potion_id
    if potion_id not in POTIONS:
        raise Unmodelled(f"the effects of the potion {potion_id}")
    return [("minecraft:" + e, d, a) for e, d, a in POTIONS[potion_id]]
