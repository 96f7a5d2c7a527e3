"""Structure templates (``data/<ns>/structure/<path>.nbt``, ``structures`` before 1.21): finding one
in the loaded packs, reading it, placing its blocks and entities in the world.

- ``find_template(packs, id)``: the file's bytes from the last pack holding it (later packs
  override), or None. Folders and ``.zip`` packs; overlays are not searched.
- ``read_template(data)``: a :class:`Template` (size, blocks with their palette state and block
  entity NBT, entities with their relative position and NBT); :class:`StructureError` says what is
  wrong with a corrupt or malformed file.
- ``place(state, template, origin, dimension, mirror, rotation)``: ``StructureTemplate.placeInWorld``:
  every block at origin + its position (its block entity NBT kept), every entity summoned at
  origin + its position from its NBT with a new UUID (``placeEntities`` removes the saved one),
  mirrored then turned about the origin (:mod:`emulator.world.block_rotation`); a turned item
  frame or painting is not modelled.

The file (decompiled 1.21 StructureTemplate.save/load): a gzipped NBT compound with ``size`` (3 ints),
``palette`` (block states ``{Name, Properties}``; or ``palettes``, a list of palettes, the first of
which is used), ``blocks`` (``{pos: [x, y, z], state: palette index, nbt?}``) and ``entities``
(``{pos: [x, y, z] doubles, blockPos, nbt: {id, ...}}``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from emulator.world import block_rotation, inventories, projectiles
from emulator.world.blocks import BlockSpec, parse_block, with_defaults
from emulator.world.entity_types import BLOCK_ATTACHED, set_attached_block
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.nbt_binary import NbtFormatError, read_nbt
from mcfunction_parser.nbt import Compound, Double, Float, Int, List, Long, String
from mcfunction_parser.pack.versions import uses_singular_folders


class StructureError(ValueError):
    pass


@dataclass(frozen=True)
class Template:
    size: tuple[int, int, int]
    blocks: list[tuple[tuple[int, int, int], BlockSpec]]
    entities: list[tuple[tuple[float, float, float], Compound]]


def template_file(packs, template_id: str) -> str:
    """The path of template ``ns:path`` inside a pack for the packs' game version."""
    namespace, _, path = template_id.partition(":") if ":" in template_id else ("minecraft", "", template_id)
    folder = "structure" if uses_singular_folders(packs.format) else "structures"
    return f"data/{namespace}/{folder}/{path}.nbt"


def find_template(packs, template_id: str) -> bytes | None:
    return packs.read_file(template_file(packs, template_id))


def read_template(data: bytes) -> Template:
    try:
        _, root = read_nbt(data)
    except NbtFormatError as error:
        raise StructureError(f"not a valid NBT file: {error}") from None
    size = _ints(root.get("size"), "size")
    palette = _palette(root)
    blocks = []
    for i, block in enumerate(_list(root.get("blocks", List()), "blocks")):
        where = f"blocks[{i}]"
        block = _compound(block, where)
        state = block.get("state")
        if not isinstance(state, Int) or not 0 <= state < len(palette):
            raise StructureError(f"{where}.state: expected a palette index 0..{len(palette) - 1}, got {state!r}")
        nbt = block.get("nbt")
        if nbt is not None:
            nbt = _compound(nbt, f"{where}.nbt")
        spec = palette[state]
        blocks.append((_ints(block.get("pos"), f"{where}.pos"), BlockSpec(spec.id, False, spec.properties, nbt)))
    entities = []
    for i, entity in enumerate(_list(root.get("entities", List()), "entities")):
        where = f"entities[{i}]"
        entity = _compound(entity, where)
        pos = entity.get("pos")
        if not (isinstance(pos, List) and len(pos) == 3 and all(isinstance(v, Double) for v in pos)):
            raise StructureError(f"{where}.pos: expected 3 doubles, got {pos!r}")
        nbt = _compound(entity.get("nbt"), f"{where}.nbt")
        if not isinstance(nbt.get("id"), String):
            raise StructureError(f"{where}.nbt: expected an entity id (id:\"minecraft:...\")")
        entities.append((tuple(float(v) for v in pos), nbt))
    return Template(size, blocks, entities)


def _palette(root: Compound) -> list[BlockSpec]:
    if "palette" in root:
        states = _list(root["palette"], "palette")
        where = "palette"
    elif "palettes" in root and _list(root["palettes"], "palettes"):
        states = _list(root["palettes"][0], "palettes[0]")
        where = "palettes[0]"
    else:
        raise StructureError("no palette: expected a 'palette' list of block states")
    specs = []
    for i, state in enumerate(states):
        state = _compound(state, f"{where}[{i}]")
        name = state.get("Name")
        if not isinstance(name, String):
            raise StructureError(f"{where}[{i}].Name: expected a block id")
        properties = _compound(state.get("Properties", Compound()), f"{where}[{i}].Properties")
        block_id = str(name) if ":" in name else f"minecraft:{name}"
        specs.append(BlockSpec(block_id, False, tuple(sorted((k, str(v)) for k, v in properties.items())), None))
    return specs


def _list(value, where: str) -> List:
    if not isinstance(value, List):
        raise StructureError(f"{where}: expected a list, got {type(value).__name__}")
    return value


def _compound(value, where: str) -> Compound:
    if not isinstance(value, Compound):
        raise StructureError(f"{where}: expected a compound, got {type(value).__name__}")
    return value


def _ints(value, where: str) -> tuple[int, int, int]:
    if not (isinstance(value, List) and len(value) == 3 and all(isinstance(v, Int) for v in value)):
        raise StructureError(f"{where}: expected 3 ints, got {value!r}")
    return tuple(int(v) for v in value)


def _with_loot_seed(state, spec: BlockSpec) -> BlockSpec:
    """A RandomizableContainer placed with a ``LootTable`` gets a fresh ``LootTableSeed`` (the
    placement's random's nextLong; the emulator's random stands in for the structure's)."""
    if spec.nbt is None or "LootTable" not in spec.nbt or spec.id not in inventories.RANDOMIZABLE_CONTAINERS:
        return spec
    nbt = Compound(spec.nbt)
    nbt["LootTableSeed"] = Long(state.resources.random.getrandbits(64) - 2**63)
    return replace(spec, nbt=nbt)


def place(state, template: Template, origin: tuple[int, int, int], dimension: str = "minecraft:overworld",
          mirror: int = 0, rotation: int = 0) -> bool:
    """Put ``template``'s blocks and entities into level ``dimension`` with its corner at
    ``origin``, mirrored then turned about it (:mod:`emulator.world.block_rotation`); False,
    placing nothing, when it has neither blocks nor entities or a size of 0
    (StructureTemplate.placeInWorld)."""
    if not (template.blocks or template.entities) or min(template.size) < 1:
        return False
    if (mirror or rotation) and any(str(nbt["id"]) in BLOCK_ATTACHED for _, nbt in template.entities):
        raise Unmodelled("a turned or mirrored template's item frames and paintings (HangingEntity.rotate)")
    blocks = state.blocks_in(dimension)
    barrier = with_defaults(parse_block("minecraft:barrier"), state.version)
    for relative, spec in template.blocks:
        pos = _offset(origin, block_rotation.turned_pos(relative, mirror, rotation))
        if spec.nbt is not None:  # the old contents cleared and a barrier set first: the block and its data always load
            inventories.try_clear(blocks, pos, state.version)
            blocks.place(pos, barrier)
            spec = _with_loot_seed(state, spec)
        spec = block_rotation.turned_state(with_defaults(spec, state.version), mirror, rotation)
        blocks.place(pos, spec)  # else the same state already there stays as it is
    for relative, nbt in template.entities:
        data = Compound((k, v) for k, v in nbt.items() if k not in ("id", "UUID", "Pos"))
        if mirror or rotation:
            _turn_entity(data, mirror, rotation)
        pos = _offset(origin, block_rotation.turned_entity_pos(relative, mirror, rotation))
        if str(nbt["id"]) in BLOCK_ATTACHED:  # BlockAttachedEntity.setPos: its block is its new position's
            set_attached_block(data, tuple(math.floor(c) for c in pos), state.version)
        try:
            projectiles.launched(state, state.entities.summon(str(nbt["id"]), pos, data, dimension=dimension))
        except CommandFailure:
            pass  # createEntityIgnoreException: an entity that cannot be created is left out
    return True


def _offset(origin, relative):
    return tuple(o + r for o, r in zip(origin, relative))


def _turn_entity(data: Compound, mirror: int, rotation: int) -> None:
    """placeEntities: the entity snapped to its turned yaw (its pitch kept)."""
    angles = data.get("Rotation")
    yaw = float(angles[0]) if isinstance(angles, List) and len(angles) == 2 else 0.0
    pitch = angles[1] if isinstance(angles, List) and len(angles) == 2 else Float(0.0)
    data["Rotation"] = List([Float(float(block_rotation.turned_yaw(yaw, mirror, rotation))), pitch])
