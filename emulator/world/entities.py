"""Entities: types and hitboxes, the entity store, UUIDs, the entity NBT view and loading NBT back.

Public API
- Sizes come from :mod:`emulator.world.entity_types` (the game's EntityType table); an entity's own
  size (``sizes()``, kept in the table for the VM) follows its pose and age: a sneaking player
  crouches (0.6 x 1.5, eyes at 1.27), a baby (``Age`` below 0, ``IsBaby``, a ``Small`` armor stand)
  is smaller, a marker armor stand has no size, and a living entity's ``scale`` attribute scales it.
- ``Entity``: ``uuid`` (4 signed ints), ``type``, ``pos`` (3 doubles), ``yaw``/``pitch`` (float32),
  ``motion``, ``tags`` (set), ``custom_name`` (text as stored), ``data`` (every other NBT field),
  ``order`` (creation index), ``alive``, ``dimension`` (its level's id); players also have
  ``player_name``, ``gamemode``, ``level``.
  Properties: ``uuid_string`` (Java ``UUID.toString``), ``score_holder`` (player name or UUID
  string, what the scoreboard uses), ``is_player``, ``eye_height``, ``bounding_box`` (min/max
  corners), ``display_name`` (what ``name=`` compares), ``anchor(anchor)`` (feet or eyes position).
- ``EntityStore(seed)``: entities level by level (overworld, nether, end, the packs' own), each
  level's in the order they came into it; ``summon(type, pos, nbt=None, yaw=0, pitch=0,
  dimension=OVERWORLD)`` (fails for players, outside the spawnable bounds, or on a duplicate UUID),
  ``add_player(name, pos, ..., dimension=OVERWORLD)``, ``move_to_level(entity, dimension)`` (a
  teleport between levels), ``kill(entity)``, ``by_uuid(uuid)``, ``by_holder(name)``, ``living()``,
  ``players()`` (in join order), ``rng`` (a seeded ``random.Random`` for UUIDs); ``sort=random``
  shuffles with the table's ``random``, seeded with the same seed.
- ``in_spawnable_bounds(pos)``: ``Level.isInSpawnableBounds`` (summon and tp refuse positions outside).
- ``add_tag(entity, name)`` / ``remove_tag(entity, name)``: the ``tag`` command's per-entity step
  (False when nothing changed; an entity holds at most 1024 tags).
- ``entity_nbt(entity)``: the compound ``data get entity`` shows and ``nbt=`` matches against
  (a vehicle's riders in ``Passengers``, as Entity.saveWithoutId writes them).
- ``load_nbt(entity, compound)``: ``Entity.load`` (Pos clamped, Motion over 10 dropped, Rotation % 360,
  Tags and CustomName only when present, the common fields read with typed getters, display render
  fields as ``Display`` reads them, the rest kept as is). ``EntityStore.modify(entity, change)``: the ``data`` entity
  accessor: ``change`` edits a fresh NBT view, which is loaded back with the UUID kept; players fail
  "Unable to modify player data".

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): world/entity/Entity.java (saveWithoutId/load,
getEyeHeight, makeBoundingBox, addTag limit 1024), world/entity/LivingEntity.java (getDimensions:
the default dimensions scaled by getScale), world/entity/decoration/ArmorStand.java (MARKER_DIMENSIONS,
BABY_DIMENSIONS: eyes at 0.9875 since 1.20.5), util/Mth.java (createInsecureUUID),
server/commands/data/EntityDataAccessor.java.
"""
from __future__ import annotations


import math
import random
from collections.abc import MutableSet
from typing import Callable

import numpy as np

from mcfunction_parser import gamedata
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, IntArray, List, Short, String, to_snbt
from emulator.world import display, frames, items, java_random, living, random_sequences, rotation
from emulator.world.dimensions import OVERWORLD
from emulator.world.entity_types import BABY_EYE_HEIGHT, PLAYER_CROUCHING, baby_scale, entity_type, settle_knot
from emulator.world.entity_table import (
    EF_EYE, EF_HALF, EF_HEIGHT, EF_MX, EF_MZ, EF_PITCH, EF_TRANSFORM, EF_WIDTH, EF_X, EF_YAW, EF_Z, EI_ALIVE, EI_DIM,
    EI_GAMEMODE, EI_JOIN, EI_LIVING, EI_NAME, EI_SEAT, EI_TEAM, EI_VEHICLE, EI_XP, GAMEMODES, LATEST_RELEASE, EntityTable,
    TagSet,
)
from emulator.world.errors import CommandFailure
from emulator.world.inventories import equipment_defaults, normalise_items, player_defaults, selected_item
from emulator.world.text import plain_text
from emulator.world.nbt_ops import copy_tag, is_numeric, narrow, numeric_value

F32 = np.float32
MAX_TAGS = 1024
POS_LIMIT_XZ = 3.0000512e7
POS_LIMIT_Y = 2.0e7
MAX_LOADED_MOTION = 10.0


HORIZONTAL_LIMIT = 30_000_000
VERTICAL_LIMIT = 20_000_000


def in_spawnable_bounds(pos) -> bool:
    """``Level.isInSpawnableBounds(BlockPos.containing(pos))``: x/z in [-3e7, 3e7), y in [-2e7, 2e7)."""
    if not all(math.isfinite(v) for v in pos):
        return False
    x, y, z = (math.floor(v) for v in pos)
    return (-HORIZONTAL_LIMIT <= x < HORIZONTAL_LIMIT and -HORIZONTAL_LIMIT <= z < HORIZONTAL_LIMIT
            and -VERTICAL_LIMIT <= y < VERTICAL_LIMIT)


def uuid_string(uuid: tuple[int, int, int, int]) -> str:
    """Java's ``UUID.toString()`` of the int[4] form (most significant int first)."""
    value = 0
    for part in uuid:
        value = (value << 32) | (part & 0xFFFFFFFF)
    text = f"{value:032x}"
    return f"{text[:8]}-{text[8:12]}-{text[12:16]}-{text[16:20]}-{text[20:]}"


def _signed32(x: int) -> int:
    return ((x + 2**31) & 0xFFFFFFFF) - 2**31


def insecure_uuid(rng: random.Random) -> tuple[int, int, int, int]:
    """``Mth.createInsecureUUID``: two random longs with the version-4 and variant-2 bits set."""
    most = (rng.getrandbits(64) & ~0xF000) | 0x4000
    least = (rng.getrandbits(64) & 0x3FFFFFFFFFFFFFFF) | 0x8000000000000000
    return tuple(_signed32(x) for x in (most >> 32, most, least >> 32, least))


class _Column:
    """An entity field kept in the table's ``floats`` (``width`` 3: a tuple of doubles, 1: a float32),
    or in the entity's ``_own[own]`` until the store adds it."""

    def __init__(self, own: int, column: int, width: int) -> None:
        self.own, self.column, self.width = own, column, width

    def __get__(self, entity, owner=None):
        if entity is None:
            return self
        table = entity._table
        if table is None:
            return entity._own[self.own]
        if self.width == 1:
            return F32(table.floats[entity.order, self.column])
        return tuple(table.floats[entity.order, self.column:self.column + 3].tolist())

    def __set__(self, entity, value) -> None:
        value = F32(value) if self.width == 1 else tuple(value)
        if entity._table is None:
            entity._own[self.own] = value
        else:
            entity._table.floats[entity.order, self.column:self.column + self.width] = value


class TextTag(str):
    """A custom name saved as a compound or a list (a text component in SNBT, 1.21.5+): its SNBT as
    the text (what :func:`plain_text` reads), the tag kept to be saved back as it was."""

    def __new__(cls, tag):
        text = super().__new__(cls, to_snbt(tag))
        text.tag = copy_tag(tag)
        return text


class _Selected:
    """An entity field that selectors compare: the entity's own, written to its table row as well
    (:meth:`Entity._write_selected`) whenever it changes."""

    def __set_name__(self, owner, name: str) -> None:
        self.slot = "_" + name

    def __get__(self, entity, owner=None):
        return self if entity is None else getattr(entity, self.slot)

    def __set__(self, entity, value) -> None:
        setattr(entity, self.slot, value)
        entity._write_selected()


class Entity:
    """One entity: a handle on its row of the store's :class:`EntityTable` (``pos``, ``yaw``,
    ``pitch``, ``motion``, ``tags``, ``alive`` read and write the arrays; the other fields are its
    own). Until the store adds it, the entity keeps those values itself."""

    __slots__ = ("_uuid", "type", "_custom_name", "data", "order", "player_name", "_gamemode", "_level", "_team",
                 "_sneaking", "sprinting", "flying", "_vehicle", "passengers", "_table", "_own", "born", "equipment_modifiers",
                 "equipment_seen", "max_health_seen", "food_seen", "levitation_start",
                 "__weakref__")

    def __init__(self, uuid: tuple[int, int, int, int], type: str, pos: tuple[float, float, float],
                 yaw=F32(0.0), pitch=F32(0.0), motion=(0.0, 0.0, 0.0), tags: set[str] | None = None,
                 custom_name: str | None = None, data: Compound | None = None, order: int = 0, alive: bool = True,
                 player_name: str | None = None, gamemode: str = "survival", level: int = 0,
                 team: str | None = None, dimension: str = OVERWORLD) -> None:
        self._uuid = uuid
        self.type = type
        self._table: EntityTable | None = None
        self.custom_name = custom_name
        self.data = Compound() if data is None else data
        self.order = order
        self.player_name = player_name
        self.gamemode = gamemode
        self.level = level
        self.team = team
        # a player's inputs (not saved in its NBT; predicates' flags and sneak_time read them)
        self._sneaking = False
        self.sprinting = False
        self.flying = gamemode == "spectator"  # a player's abilities.flying (entity_flags.flying_after)
        # riding (Entity.vehicle / Entity.passengers), kept by emulator.world.relations
        self._vehicle: Entity | None = None
        self.passengers: list = []
        # the transient attribute modifiers its equipment gives: {attribute: {id: (amount, operation)}}
        # (LivingEntity.collectEquipmentChanges; AttributeInstance.save leaves them out of the NBT)
        self.equipment_modifiers: dict | None = None
        # what its last equipment check saw (LivingEntity's lastHandItemStacks, lastArmorItemStacks:
        # emulator.world.equipment)
        self.equipment_seen = None
        self.max_health_seen = None  # a player's max_health attribute, until it changes (living.max_health)
        self.food_seen = None  # what a player's last food tick that changed nothing read (living.tick_food)
        self.levitation_start = None  # a player's (position, tickCount) when levitation began (ServerPlayer)
        self.born = 0  # the server tick it came into the world (EntityStore._add; tickCount counts from it)
        # the table's fields until the store adds the entity: [pos, yaw, pitch, motion, tags, alive, dimension]
        self._own = [tuple(pos), F32(yaw), F32(pitch), tuple(motion), set(tags or ()), alive, dimension]

    def tick_count(self, now: int) -> int:
        """Entity.tickCount at server tick ``now``: the ticks finished since it came into the world
        (every entity ticks every tick here, as where a player is near)."""
        return now - self.born

    def attach(self, table: EntityTable) -> None:
        """Move the entity's fields into a new row of ``table`` (its slot becomes ``order``)."""
        pos, yaw, pitch, motion, tags, alive, dimension = self._own
        level = table.levels.level_id(dimension)
        self.order = slot = table.new_slot(self, self.type, self.score_holder)
        table.ints[slot, EI_DIM] = level
        table.floats[slot, EF_X:EF_Z + 1] = pos
        table.floats[slot, EF_MX:EF_MZ + 1] = motion
        table.floats[slot, EF_YAW] = yaw
        table.floats[slot, EF_PITCH] = pitch
        table.ints[slot, EI_ALIVE] = int(alive)
        table.ints[slot, EI_LIVING] = int(living.is_living(self.type))
        self._table = table
        table.floats[slot, EF_HALF:EF_EYE + 1] = self.sizes()  # with the table's release (its attributes' ids)
        self._write_selected()
        if self.type in display.DISPLAY_TYPES:
            table.floats[slot, EF_TRANSFORM:EF_WIDTH] = display.transformation_columns(self.data["transformation"])
        self._own = TagSet(table, slot)
        self._own.replace(tags)
        self.vehicle = self._vehicle
        table.index_uuid(self, None, self._uuid)

    @property
    def uuid(self) -> tuple[int, int, int, int]:
        return self._uuid

    @uuid.setter
    def uuid(self, value) -> None:
        old, self._uuid = self._uuid, tuple(value)
        if self._table is not None:
            self._table.index_uuid(self, old, self._uuid)

    pos = _Column(0, EF_X, 3)  # tuple of 3 doubles
    yaw = _Column(1, EF_YAW, 1)  # float32
    pitch = _Column(2, EF_PITCH, 1)
    motion = _Column(3, EF_MX, 3)

    @property
    def tags(self) -> MutableSet:
        """The tag names (a view on the bitset once stored)."""
        return self._own[4] if self._table is None else self._own

    @tags.setter
    def tags(self, names) -> None:
        if self._table is None:
            self._own[4] = set(names)
        else:
            self._own.replace(list(names))

    @property
    def alive(self) -> bool:
        return self._own[5] if self._table is None else bool(self._table.ints[self.order, EI_ALIVE])

    @alive.setter
    def alive(self, value: bool) -> None:
        if self._table is None:
            self._own[5] = bool(value)
        else:
            self._table.ints[self.order, EI_ALIVE] = int(value)
            self._table.alive_writes += 1

    # what the selector arguments name, team, gamemode and level compare (a player's ``level`` is its
    # experience level): kept in the table's EI_NAME, EI_TEAM, EI_GAMEMODE and EI_XP too (the VM's
    # selectors read them there)
    custom_name = _Selected()
    team = _Selected()
    gamemode = _Selected()
    level = _Selected()

    def _write_selected(self) -> None:
        """The table's copy of the fields selectors compare (once the entity is in a table)."""
        table = self._table
        if table is None:
            return
        row = table.ints[self.order]
        row[EI_NAME] = table.name_id(self.display_name)
        row[EI_TEAM] = table.name_id(self._team or None)
        row[EI_GAMEMODE] = GAMEMODES.index(self._gamemode) if self._gamemode in GAMEMODES else -1
        row[EI_XP] = self._level

    @property
    def vehicle(self) -> Entity | None:
        return self._vehicle

    @vehicle.setter
    def vehicle(self, vehicle: Entity | None) -> None:
        """Get on ``vehicle`` (None: off); the table's EI_VEHICLE and EI_SEAT follow (the VM's ``on``)."""
        self._vehicle = vehicle
        table = self._table
        if table is not None:
            table.seats += 1
            table.ints[self.order, EI_VEHICLE] = 0 if vehicle is None else vehicle.order + 1
            table.ints[self.order, EI_SEAT] = table.seats

    @property
    def dimension(self) -> str:
        """The id of the level the entity is in (``EntityStore.move_to_level`` changes it)."""
        return self._own[6] if self._table is None else self._table.levels.names[self.dimension_id]

    @property
    def dimension_id(self) -> int:
        return int(self._table.ints[self.order, EI_DIM])

    def __repr__(self) -> str:
        return f"Entity({self.type}, {self.uuid_string}, pos={self.pos})"

    @property
    def is_player(self) -> bool:
        return self.type == "minecraft:player"

    @property
    def uuid_string(self) -> str:
        return uuid_string(self.uuid)

    @property
    def score_holder(self) -> str:
        """``getScoreboardName``: a player's name, any other entity's UUID string."""
        return self.player_name if self.is_player else self.uuid_string

    @property
    def display_name(self) -> str:
        """``getName().getString()``: the custom name's text, a player's name, else the type's name
        (EntityType.getDescription: ``entity.minecraft.zombie_villager``'s en_us text)."""
        if self.is_player:
            return self.player_name or ""
        if self.custom_name is not None:
            return plain_text(self.custom_name, self.release)
        if self.type == "minecraft:item":
            return self._item_name()
        namespace, path = self.type.split(":", 1)
        return gamedata.language(self.release).get(f"entity.{namespace}.{path}") or path.replace("_", " ").title()

    def _item_name(self) -> str:
        """ItemEntity.getName: the stack's item name (:func:`emulator.world.items.item_name`), not its
        custom name."""
        item = self.data.get("Item")
        components = item.get("components") if isinstance(item, Compound) else None
        named = components.get("minecraft:item_name") if isinstance(components, Compound) else None
        item_id = str(item.get("id", "minecraft:air")) if isinstance(item, Compound) else "minecraft:air"
        return items.item_name(item_id, named, self.release)

    @property
    def sneaking(self) -> bool:
        return self._sneaking

    @sneaking.setter
    def sneaking(self, value: bool) -> None:
        self._sneaking = bool(value)
        self.refresh_sizes()  # a player crouches

    def dimensions(self) -> tuple[np.float32, np.float32, np.float32]:
        """Width, height and eye height (float32, as EntityDimensions holds them): an interaction's
        ``width`` and ``height`` (1 by 1 unless set, eyes at 0.85 of the height);
        LivingEntity.getDimensions, the pose's or age's dimensions scaled by the ``scale``
        attribute; ArmorStand's marker (no size, fixed) and small (baby) dimensions."""
        kind = entity_type(self.type)
        width, height, eyes = kind.width, kind.height, kind.eye_height
        if self.type == "minecraft:interaction":  # Interaction.getDimensions: scalable(width, height)
            width, height = (F32(numeric_value(v)) if is_numeric(v := self.data.get(k)) else F32(1.0)
                             for k in ("width", "height"))
            return width, height, height * F32(0.85)
        if self.type == "minecraft:armor_stand" and self.data.get("Marker"):
            return F32(0.0), F32(0.0), F32(0.0)  # EntityDimensions.fixed: the scale does not change it
        if self.is_player and self._sneaking:
            width, height, eyes = PLAYER_CROUCHING.width, PLAYER_CROUCHING.height, PLAYER_CROUCHING.eye_height
        elif living.is_baby(self):
            age = baby_scale(self.type)
            width, height, eyes = width * age, height * age, BABY_EYE_HEIGHT.get(self.type, eyes * age)
        if living.has_attribute(self.type, "scale", self.release):  # scale: 1.20.5+
            scale = F32(living.attribute_value(self, "scale"))
            width, height, eyes = width * scale, height * scale, eyes * scale
        return width, height, eyes

    def sizes(self) -> tuple[float, float, float]:
        """The hitbox's half width and height and the eye height (``width / 2.0F`` and the others
        are floats, widened to double): the table's copy, which both backends read."""
        width, height, eyes = self.dimensions()
        return float(width / F32(2.0)), float(height), float(eyes)

    @property
    def release(self) -> tuple[int, int, int]:
        """The release the entity's world runs as (the layout its NBT is written in)."""
        return self._table.release if self._table is not None else LATEST_RELEASE

    def refresh_sizes(self) -> None:
        """Keep the table's sizes: after anything that changes them (NBT, pose, attributes)."""
        if self._table is not None:
            self._table.floats[self.order, EF_HALF:EF_EYE + 1] = self.sizes()

    @property
    def eye_height(self) -> np.float32:
        if self._table is None:
            return self.dimensions()[2]
        return F32(self._table.floats[self.order, EF_EYE])

    def box_extent(self) -> tuple[float, float]:
        """The hitbox's half width and height."""
        if self._table is None:
            return self.sizes()[:2]
        return tuple(self._table.floats[self.order, EF_HALF:EF_HEIGHT + 1].tolist())

    @property
    def bounding_box(self) -> tuple[float, float, float, float, float, float]:
        """``EntityDimensions.makeBoundingBox``: half the width around x/z, the height up from y."""
        half, height = self.box_extent()
        x, y, z = self.pos
        return (x - half, y, z - half, x + half, y + height, z + half)

    def anchor(self, anchor: str) -> tuple[float, float, float]:
        """``EntityAnchorArgument.Anchor.apply(entity)``: feet, or eyes (y + eye height)."""
        x, y, z = self.pos
        return (x, y + float(self.eye_height), z) if anchor == "eyes" else self.pos


def add_tag(entity: Entity, name: str) -> bool:
    """``Entity.addTag``: refused at 1024 tags; False if the tag was there."""
    if len(entity.tags) >= MAX_TAGS or name in entity.tags:
        return False
    entity.tags.add(name)
    return True


def remove_tag(entity: Entity, name: str) -> bool:
    if name not in entity.tags:
        return False
    entity.tags.remove(name)
    return True


def entity_nbt(entity: Entity) -> Compound:
    """The entity's NBT as ``saveWithoutId`` writes it (modelled fields plus the kept ones)."""
    nbt = Compound()
    nbt["Pos"] = List(Double(v) for v in entity.pos)
    nbt["Motion"] = List(Double(v) for v in entity.motion)
    nbt["Rotation"] = List([Float(float(entity.yaw)), Float(float(entity.pitch))])
    nbt.update(copy_tag(entity.data))
    if _columns_hold_transformation(entity):
        nbt["transformation"] = _saved_transformation(entity)
    nbt["UUID"] = IntArray(Int(v) for v in entity.uuid)
    if entity.custom_name is not None:
        name = entity.custom_name
        nbt["CustomName"] = copy_tag(name.tag) if isinstance(name, TextTag) else String(name)
    if entity.tags:
        nbt["Tags"] = List(String(t) for t in sorted(entity.tags))
    riders = List(_passenger_nbt(p) for p in entity.passengers if p.alive and not p.is_player)
    if riders:
        nbt["Passengers"] = riders
    if entity.is_player:
        nbt["Dimension"] = String(entity.dimension)  # ServerPlayer.addAdditionalSaveData
    if entity.is_player and (held := selected_item(entity.data)) is not None:
        nbt["SelectedItem"] = held  # NbtPredicate.getEntityTagForPredicate, what data and nbt= read
    return nbt


def _columns_hold_transformation(entity: Entity) -> bool:
    """A stored display entity keeps its transformation in the table (the VM writes it there):
    ``data["transformation"]`` only marks its place among the saved fields."""
    return entity._table is not None and entity.type in display.DISPLAY_TYPES


def _saved_transformation(entity: Entity) -> Compound:
    return display.transformation_tag(entity._table.floats[entity.order, EF_TRANSFORM:EF_WIDTH].tolist())


def _passenger_nbt(entity: Entity) -> Compound:
    """Entity.saveAsPassenger: ``id`` then saveWithoutId (riders of riders included). Players have
    no encode id: they are left out of their vehicle's ``Passengers``."""
    nbt = Compound(id=String(entity.type))
    nbt.update(entity_nbt(entity))
    return nbt


# Written by entity_nbt from the entity's own fields; Entity.load does not read Passengers (riders
# come only from summon's NBT and ride), so a data change on a vehicle keeps its riders.
_MODELLED = ("Pos", "Motion", "Rotation", "UUID", "CustomName", "Tags", "id", "Passengers", "Dimension")
# Saved by every entity, read back with typed getters (Entity.saveWithoutId / Entity.load).
BASE_FIELDS = {"FallDistance": Float, "Fire": Short, "Air": Short, "OnGround": Byte,
               "Invulnerable": Byte, "PortalCooldown": Int}
# Per type: compound fields always saved, read with getCompound (a missing or wrong value reads {}).
TYPE_COMPOUNDS = {"minecraft:marker": ("data",)}
# Read with getBoolean and saved only when true (as 1b).
FLAG_FIELDS = ("CustomNameVisible", "Silent", "NoGravity", "Glowing", "HasVisualFire")


def _typed_list(nbt: Compound, key: str, element: type) -> list:
    """``CompoundTag.getList(key, type)``: the list if its elements have that type, else empty."""
    value = nbt.get(key)
    if isinstance(value, List) and all(type(v) is element for v in value):
        return list(value)
    return []


def _component(values: list, i: int) -> float:
    return float(values[i]) if i < len(values) else 0.0


def _base_fields(type_id: str, nbt: Compound, previous: Compound) -> Compound:
    """The fields ``Entity.load`` reads with typed getters and ``saveWithoutId`` writes back: a
    missing or non-numeric value reads as 0 (``Air`` only changes when present), numbers are
    converted to the saved type (``getShort``, ``getBoolean`` ...)."""
    fields = Compound()
    for key, kind in BASE_FIELDS.items():
        value = nbt.get(key)
        if key == "Air" and value is None:
            fields[key] = previous.get(key, Short(300))
        elif not is_numeric(value):
            fields[key] = kind(0)
        elif kind is Float:
            fields[key] = Float(float(F32(numeric_value(value))))
        elif kind is Byte:
            fields[key] = Byte(1 if narrow(value, Byte) != 0 else 0)  # getBoolean: getByte() != 0
        else:
            fields[key] = kind(narrow(value, kind))
    for key in FLAG_FIELDS:
        if is_numeric(nbt.get(key)) and narrow(nbt[key], Byte) != 0:
            fields[key] = Byte(1)
    for key in TYPE_COMPOUNDS.get(type_id, ()):
        value = nbt.get(key)
        fields[key] = copy_tag(value) if isinstance(value, Compound) else Compound()
    if type_id in display.DISPLAY_TYPES:
        fields.update(display.read_fields(type_id, nbt, previous))
    return fields


def load_nbt(entity: Entity, nbt: Compound, keep_uuid: bool = False) -> None:
    """``Entity.load``: read a full compound back into the entity.

    Pos (clamped), Motion (components over 10 dropped) and Rotation (finite values, % 360) read
    0 when missing or of the wrong list type; ``Tags`` and ``CustomName`` only change when present
    (a ``Tags`` list of another type clears the tags); every other field is kept as given.
    """
    pos = _typed_list(nbt, "Pos", Double)
    x, y, z = (_component(pos, i) for i in range(3))
    clamp = lambda v, lim: max(-lim, min(v, lim))  # noqa: E731 - Mth.clamp(double)
    entity.pos = (clamp(x, POS_LIMIT_XZ), clamp(y, POS_LIMIT_Y), clamp(z, POS_LIMIT_XZ))
    motion = _typed_list(nbt, "Motion", Double)
    entity.motion = tuple(0.0 if abs(v) > MAX_LOADED_MOTION else v for v in (_component(motion, i) for i in range(3)))
    rot = _typed_list(nbt, "Rotation", Float)
    entity.yaw, entity.pitch = rotation.load_rotation(
        (entity.yaw, entity.pitch), (F32(_component(rot, 0)), F32(_component(rot, 1))))
    uuid = nbt.get("UUID")
    if not keep_uuid and isinstance(uuid, IntArray) and len(uuid) == 4:
        entity.uuid = tuple(int(v) for v in uuid)
    name = nbt.get("CustomName")
    if isinstance(name, String):
        entity.custom_name = str(name)
    elif isinstance(name, (Compound, List)):  # ComponentSerialization.CODEC reads SNBT from 1.21.5
        entity.custom_name = TextTag(name)
    if isinstance(nbt.get("Tags"), List):
        entity.tags = set(str(t) for t in _typed_list(nbt, "Tags", String)[:MAX_TAGS])
    previous = entity.data
    if _columns_hold_transformation(entity):
        previous = Compound(previous)
        previous["transformation"] = _saved_transformation(entity)
    data = _base_fields(entity.type, nbt, previous)
    dropped = set(_MODELLED) | set(FLAG_FIELDS) | (set(display.NOT_SAVED) if entity.type in display.DISPLAY_TYPES else set())
    data.update((k, copy_tag(v)) for k, v in nbt.items() if k not in data and k not in dropped)
    normalise_items(data)
    entity.data = data
    if _columns_hold_transformation(entity):
        entity._table.floats[entity.order, EF_TRANSFORM:EF_WIDTH] = display.transformation_columns(data["transformation"])
    entity.refresh_sizes()  # an armor stand's Marker or Small, a baby's Age, the scale attribute


def _base_data(type_id: str, version=(1, 21, 11)) -> Compound:
    """The fields every entity saves besides the modelled ones, at their spawn values (in the
    layout of the release ``version``)."""
    data = Compound(FallDistance=Float(0.0), Fire=Short(-1), Air=Short(300), OnGround=Byte(0),
                    Invulnerable=Byte(0), PortalCooldown=Int(0))
    data.update((key, Compound()) for key in TYPE_COMPOUNDS.get(type_id, ()))
    if type_id in display.DISPLAY_TYPES:
        data.update(display.default_fields(type_id))
    if type_id == "minecraft:player":
        data.update(player_defaults())
    data.update(living.base_fields(type_id))
    if type_id != "minecraft:player" and living.is_living(type_id):
        data.update(equipment_defaults(version))
    return data


class EntityStore:
    """Every entity of the world: its :class:`EntityTable` (``table``), and the living ones in the
    order unsorted ``@e`` visits them (``entities``, the same as ``table.order``'s slots): level by
    level, each level's in the order they came into it (creation, or a teleport from another level)."""

    def __init__(self, seed: int = 0) -> None:
        self.rng = random.Random(seed)
        self.entities: list[Entity] = []
        self.table = EntityTable()
        # java.util.Random started from nearby seeds draws alike at first: the seed is mixed first
        # (RandomSupport.mixStafford13 of the seed's upgrade to 128 bits), as Random() mixes the time
        java_random.set_seed(self.table.random, random_sequences.mix_stafford13(seed + random_sequences.GOLDEN_RATIO_64))
        self.joined = 0  # players that joined so far (EI_JOIN)
        self.team_of: Callable[[str], str | None] = lambda holder: None  # a score holder's team (WorldState.teams)
        self.join_team: Callable[[str, str], None] = lambda holder, team: None  # (WorldState.teams)
        self.clock: Callable[[], int] = lambda: 0  # the server ticks run so far (WorldState.tick)
        self.changes = 0  # entities that came into ``entities`` or left it so far
        self._mobs: tuple[tuple, list[Entity]] = ((0, 0), [])  # ((changes, alive writes) then, ``living_mobs()``)
        self._players: tuple[int, list[Entity]] = (0, [])  # (changes then, ``players()``)
        self._carts: tuple[int, list[Entity]] = (0, [])  # (changes then, ``minecarts()``)
        self._picked: dict[str, tuple[int, list[Entity]]] = {}  # ``picked()``'s lists by key

    @property
    def version(self) -> tuple[int, int, int]:
        """The release the packs run as: what new entities save (kept on the table, which the
        entities' NBT writers read through :attr:`Entity.release`)."""
        return self.table.release

    @version.setter
    def version(self, release) -> None:
        self.table.release = tuple(release)

    def bind_scoreboard(self, scoreboard) -> None:
        """Intern each new entity's score holder in ``scoreboard`` (the VM reads its scores by holder id)."""
        self.table.intern_holder = scoreboard.holder_id

    def _add(self, entity: Entity) -> Entity:
        """Into the store, at the end of its level's entities (``born``: the server tick it came in)."""
        entity.born = self.clock()
        entity.attach(self.table)
        self._enter_level(entity)
        return entity

    def _enter_level(self, entity: Entity) -> None:
        index = self._place(*self.table.level_span(entity.dimension_id))
        self.entities.insert(index, entity)
        self.table.insert(index, entity.order)
        self.changes += 1

    def _place(self, start: int, end: int) -> int:
        """Where in its level's span ``[start, end]`` of the order a new entity goes."""
        return end

    def summon(self, type_id: str, pos, nbt: Compound | None = None, yaw=0.0, pitch=0.0,
               dimension: str = OVERWORLD) -> Entity:
        """``summon TYPE POS NBT`` in ``dimension``: a new entity; the NBT is loaded over the spawn state.

        Fails for players (not summonable), outside the spawnable bounds, or when the NBT's UUID
        is already taken (SummonCommand.createEntity).
        """
        if type_id == "minecraft:player":
            raise CommandFailure("entity.not_summonable", type_id)
        if not in_spawnable_bounds(pos):
            raise CommandFailure("commands.summon.invalidPosition")
        entity = Entity(insecure_uuid(self.rng), type_id, tuple(float(v) for v in pos), F32(yaw), F32(pitch),
                        data=_base_data(type_id, self.version), dimension=dimension)
        if nbt:
            full = entity_nbt(entity)
            full.update(copy_tag(nbt))
            self._load(entity, full)
            if self.by_uuid(entity.uuid) is not None:
                raise CommandFailure("commands.summon.failed.uuid")
        entity.pos = tuple(float(v) for v in pos)  # SummonCommand: load the NBT, then moveTo(pos)
        if type_id in frames.FRAMES:  # BlockAttachedEntity.setPos: hung on that position's block
            frames.settle(entity, self.version)
        elif type_id == "minecraft:leash_knot":
            settle_knot(entity, self.version)
        entity.team = self.team_of(entity.score_holder)  # a UUID a team already names
        return self._add(entity)

    def modify(self, entity: Entity, change: Callable[[Compound], object]):
        """Run a ``data`` change on the entity's NBT view and load the result back (UUID kept).

        ``change`` may raise ``CommandFailure``; then the entity is untouched. Returns its result.
        """
        nbt = entity_nbt(entity)
        result = change(nbt)
        if entity.is_player:
            raise CommandFailure("commands.data.entity.invalid")
        hung = frames.block_of(entity) if entity.type in frames.FRAMES else None
        self._load(entity, nbt, keep_uuid=True)
        if hung is not None:
            frames.rehang(entity, hung, self.version)
        return result

    def _load(self, entity: Entity, nbt: Compound, keep_uuid: bool = False) -> None:
        """Entity.load: ``load_nbt``, and a living entity's ``Team`` joins that team
        (LivingEntity.readAdditionalSaveData; nothing saves it back)."""
        load_nbt(entity, nbt, keep_uuid=keep_uuid)
        team = entity.data.pop("Team", None) if living.is_living(entity.type) else None
        if isinstance(team, String):
            self.join_team(entity.score_holder, str(team))

    def add_player(self, name: str, pos, yaw=0.0, pitch=0.0, gamemode: str = "survival", level: int = 0,
                   dimension: str = OVERWORLD) -> Entity:
        player = Entity(insecure_uuid(self.rng), "minecraft:player", tuple(float(v) for v in pos), F32(yaw),
                        F32(pitch), data=_base_data("minecraft:player"), player_name=name, gamemode=gamemode,
                        level=level, dimension=dimension, team=self.team_of(name))
        self._add(player)
        self.joined += 1
        self.table.ints[player.order, EI_JOIN] = self.joined
        return player

    def move_to_level(self, entity: Entity, dimension: str) -> None:
        """The entity goes to level ``dimension``, at the end of that level's entities (a teleport
        between levels: ServerLevel.addDuringTeleport)."""
        level = self.table.levels.level_id(dimension)
        if level == entity.dimension_id:
            return
        index = self.entities.index(entity)
        del self.entities[index]
        self.changes += 1
        self.table.remove(index)
        self.table.ints[entity.order, EI_DIM] = level
        self._enter_level(entity)

    def kill(self, entity: Entity) -> None:
        entity.alive = False
        index = self.entities.index(entity)
        del self.entities[index]
        self.changes += 1
        self.table.remove(index)
        self.table.index_uuid(entity, entity.uuid, None)

    def by_uuid(self, uuid) -> Entity | None:
        """The first living entity with that UUID, in the store's order."""
        found = self.table.uuids.get(tuple(uuid))
        if not found:
            return None
        return found[0] if len(found) == 1 else min(found, key=self.entities.index)

    def by_holder(self, name: str) -> Entity | None:
        """The entity whose score holder name is ``name`` (player name or UUID string)."""
        return next((e for e in self.entities if e.score_holder == name), None)

    def players(self) -> list[Entity]:
        """The players online, in the server's player list order (the order they joined); found
        again only when entities came or left (selectors and advancements ask every tick)."""
        if self._players[0] != self.changes:
            ints = self.table.ints
            self._players = (self.changes, sorted((e for e in self.entities if e.is_player),
                                                  key=lambda e: ints[e.order, EI_JOIN]))
        return list(self._players[1])

    def living(self) -> list[Entity]:
        alive = self.table.ints[:, EI_ALIVE].tolist()  # one read of the column: this runs every tick
        return [e for e in self.entities if alive[e.order]]

    def minecarts(self) -> list[Entity]:
        """The minecarts in the store's order, found again only when entities came or left."""
        if self._carts[0] != self.changes:
            self._carts = (self.changes, [e for e in self.entities if e.type.endswith("minecart")])
        return self._carts[1]

    def picked(self, key: str, test) -> list[Entity]:
        """The entities whose type ``test(type)`` accepts, in the store's order (the dead too),
        found again only when entities came or left; ``key`` names the test."""
        found = self._picked.get(key)
        if found is None or found[0] != self.changes:
            found = (self.changes, [e for e in self.entities if test(e.type)])
            self._picked[key] = found
        return found[1]

    def living_mobs(self) -> list[Entity]:
        """The living LivingEntities (mobs, players, armor stands: :func:`living.is_living`), in the
        store's order; the few that tick effects, found again only when entities came or left or
        one's alive flag was written (the list is the store's: not to be changed)."""
        stamp = (self.changes, self.table.alive_writes)
        if self._mobs[0] != stamp:
            self._mobs = (stamp, [e for e in self.entities if living.is_living(e.type) and e.alive])
        return self._mobs[1]
