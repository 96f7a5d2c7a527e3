"""The data components an entity exposes (1.21.5+, Entity.get and its overrides), for the
``components`` field of entity predicates (DataComponentExactPredicate: each listed component
equal to the entity's).

- ``component(entity, name) -> value | None``: the component as the predicate compares it (a
  namespaced id, or a dye colour's name), read from the NBT the entity saves; None when the entity
  has no such component. A variant the entity was given by its spawn (``summon`` without the
  field: Mob.finalizeSpawn picks it from the spawn conditions) is not modelled (Unmodelled), nor
  are the components not listed here (``custom_data``, the other mobs' variants ...).
  ``custom_name`` is Entity.get's: the entity's custom name, compared as the game compares
  Components (:func:`emulator.world.text.component_value`).
- ``components_match(expected, entity) -> bool``.

Sources (decompiled 1.21.7): world/entity/animal/Cat.java (get: ``cat/variant``, ``cat/collar``;
``variant`` and ``CollarColor``, red by default), wolf/Wolf.java (``wolf/variant``,
``wolf/sound_variant``, ``wolf/collar``), frog/Frog.java, Pig.java, Cow.java, Chicken.java
(``<mob>/variant`` from ``variant``), sheep/Sheep.java (``sheep/color`` from ``Color``),
Fox.java and MushroomCow.java (``Type``), npc/Villager.java (``villager/variant``:
``VillagerData.type``), decoration/Painting.java (``painting/variant``), world/item/DyeColor.java
(the legacy ids 0 - 15), advancements/critereon/EntityPredicate.matches (``components.test``).
"""
from __future__ import annotations

from emulator.world.entities import TextTag
from emulator.world.errors import Unmodelled
from emulator.world.nbt_ops import is_numeric, numeric_value
from emulator.world.text import component_value
from mcfunction_parser.nbt import Compound, String

DYES = ("white orange magenta light_blue yellow lime pink gray light_gray cyan purple blue brown green red "
        "black").split()
# component -> (entity type, NBT key, default when the key is absent: None when the spawn picks it)
_REGISTRY_VARIANTS = {f"minecraft:{m}/variant": (f"minecraft:{m}", "variant")
                      for m in ("cat", "wolf", "frog", "pig", "cow", "chicken", "painting")}
_REGISTRY_VARIANTS["minecraft:wolf/sound_variant"] = ("minecraft:wolf", "sound_variant")
_NAMED = {"minecraft:fox/variant": ("minecraft:fox", "Type"), "minecraft:mooshroom/variant": ("minecraft:mooshroom", "Type")}
_COLLARS = {"minecraft:cat/collar": "minecraft:cat", "minecraft:wolf/collar": "minecraft:wolf"}


def _namespaced(value: str) -> str:
    return value if ":" in value else "minecraft:" + value


def _spawn_picked(entity, name: str):
    raise Unmodelled(f"the {name} component of a {entity.type} its spawn chose (summoned without the field: "
                     "Mob.finalizeSpawn picks it from the spawn conditions)")


def component(entity, name: str):
    name = _namespaced(name)
    data = entity.data
    if name in _REGISTRY_VARIANTS or name in _NAMED:
        kind, key = (_REGISTRY_VARIANTS.get(name) or _NAMED[name])
        if entity.type != kind:
            return None
        value = data.get(key)
        if not isinstance(value, String):
            return _spawn_picked(entity, name)
        return _namespaced(str(value)) if name in _REGISTRY_VARIANTS else str(value)
    if name in _COLLARS:
        if entity.type != _COLLARS[name]:
            return None
        value = data.get("CollarColor")  # DyeColor.LEGACY_ID_CODEC; red when absent
        return DYES[int(numeric_value(value)) % 16] if is_numeric(value) else "red"
    if name == "minecraft:sheep/color":
        if entity.type != "minecraft:sheep":
            return None
        value = data.get("Color")
        return DYES[int(numeric_value(value)) % 16] if is_numeric(value) else _spawn_picked(entity, name)
    if name == "minecraft:villager/variant":
        if entity.type not in ("minecraft:villager", "minecraft:zombie_villager"):
            return None
        villager = data.get("VillagerData")
        kind = villager.get("type") if isinstance(villager, Compound) else None
        return _namespaced(str(kind)) if isinstance(kind, String) else _spawn_picked(entity, name)
    if name == "minecraft:custom_name":
        stored = entity.custom_name
        if stored is None:
            return None
        return component_value(stored.tag if isinstance(stored, TextTag) else String(stored))
    raise Unmodelled(f"the entity component '{name}' in an entity predicate")


def _expected(name: str, value):
    """The predicate's value in the form :func:`component` gives (ids namespaced, dyes by name, a
    custom name as a Component)."""
    if name == "minecraft:custom_name":
        return component_value(value)
    if isinstance(value, str) and name not in ("minecraft:fox/variant", "minecraft:mooshroom/variant") \
            and not name.endswith(("/collar", "/color")):
        return _namespaced(value)
    return value


def components_match(expected: dict, entity) -> bool:
    """DataComponentExactPredicate.test(entity): every listed component present and equal."""
    for name, value in expected.items():
        found = component(entity, name)
        wanted = _expected(_namespaced(name), value)
        if found is None or found != wanted:
            return False
    return True
