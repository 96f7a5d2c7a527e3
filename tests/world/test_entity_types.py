"""Entity sizes and eye heights: the game's EntityType table and the poses, ages and scale that
change a living entity's dimensions.

Sources: decompiled 1.21.11 world/entity/EntityType.java (sized, eyeHeight; EntityDimensions.scalable
puts the eyes at height * 0.85F), 1.21 world/entity/player/Player.java (POSES: crouching 0.6 x 1.5,
eyes 1.27), world/entity/LivingEntity.java (getDimensions: scaled by getAgeScale and the scale
attribute), world/entity/monster/Zombie.java, piglin/Piglin.java (BABY_DIMENSIONS), HappyGhast.getAgeScale.
"""
from __future__ import annotations

import numpy as np
import pytest

from emulator.world import living
from emulator.world.entities import EntityStore
from emulator.world.entity_types import ENTITY_TYPES, entity_type
from mcfunction_parser.snbt import compound
from mcfunction_parser.reader import Reader
from mcfunction_parser.diagnostics import Loc

F32 = np.float32


def nbt(text: str):
    return compound(Reader(text, Loc("t", 1, 1), (1, 21, 11)))


@pytest.mark.parametrize("type_id, width, height, eyes", [
    ("player", 0.6, 1.8, 1.62), ("zombie", 0.6, 1.95, 1.74), ("skeleton", 0.6, 1.99, 1.74),
    ("villager", 0.6, 1.95, 1.62), ("armor_stand", 0.5, 1.975, 1.7775), ("oak_boat", 1.375, 0.5625, 0.5625),
    ("item", 0.25, 0.25, 0.2125), ("tadpole", 0.4, 0.3, 0.19500001), ("camel_husk", 1.7, 2.375, 2.275),
    ("copper_golem", 0.49, 0.98, 0.8125), ("marker", 0.0, 0.0, 0.0), ("wind_charge", 0.3125, 0.3125, 0.0),
])
def test_builder_eye_heights(type_id, width, height, eyes):
    kind = ENTITY_TYPES["minecraft:" + type_id]
    assert (kind.width, kind.height, kind.eye_height) == (F32(width), F32(height), F32(eyes))


@pytest.mark.parametrize("type_id, height", [("creeper", 1.7), ("pig", 0.9), ("blaze", 1.8), ("warden", 2.9),
                                             ("minecart", 0.7), ("ender_dragon", 8.0)])
def test_without_eye_height_the_eyes_are_at_0_85_of_the_height(type_id, height):
    assert entity_type("minecraft:" + type_id).eye_height == F32(height) * F32(0.85)  # float math


def test_an_unknown_type_has_the_builder_default():
    kind = entity_type("mymod:thing")
    assert (kind.width, kind.height, kind.eye_height) == (F32(0.6), F32(1.8), F32(1.8) * F32(0.85))


def test_a_sneaking_player_crouches():
    store = EntityStore()
    player = store.add_player("Steve", (0.0, 64.0, 0.0))
    player.sneaking = True
    assert player.eye_height == F32(1.27) and player.bounding_box[4] == 64.0 + float(F32(1.5))
    player.sneaking = False
    assert player.eye_height == F32(1.62)


@pytest.mark.parametrize("type_id, data, eyes, height", [
    ("zombie", "{IsBaby:1b}", F32(0.93), F32(1.95) * F32(0.5)),  # Zombie.BABY_DIMENSIONS
    ("husk", "{IsBaby:1b}", F32(0.93), F32(1.95) * F32(0.5)),
    ("piglin", "{IsBaby:1b}", F32(0.97), F32(1.95) * F32(0.5)),  # Piglin.BABY_DIMENSIONS
    ("cow", "{Age:-24000}", F32(1.3) * F32(0.5), F32(1.4) * F32(0.5)),  # getAgeScale 0.5
    ("happy_ghast", "{Age:-1}", F32(2.6) * F32(0.2375), F32(4.0) * F32(0.2375)),
    ("cow", "{Age:10}", F32(1.3), F32(1.4)),
])
def test_babies(type_id, data, eyes, height):
    mob = EntityStore().summon("minecraft:" + type_id, (0.0, 0.0, 0.0), nbt(data))
    assert (mob.eye_height, mob.bounding_box[4]) == (eyes, float(height))


def test_the_scale_attribute_scales_a_living_entity():
    store = EntityStore()
    zombie = store.summon("minecraft:zombie", (0.0, 0.0, 0.0), nbt('{attributes:[{id:"minecraft:scale",base:2.0d}]}'))
    assert zombie.eye_height == F32(1.74) * F32(2.0)
    living.set_base(zombie, "scale", 0.5)  # the attribute command: the table's copy follows
    assert zombie.eye_height == F32(1.74) * F32(0.5) and zombie.bounding_box[4] == float(F32(1.95) * F32(0.5))
    marker = store.summon("minecraft:marker", (0.0, 0.0, 0.0), nbt('{attributes:[{id:"minecraft:scale",base:2.0d}]}'))
    assert marker.eye_height == 0.0  # not living: no attributes
