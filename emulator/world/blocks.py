"""A block map for ``setblock``, ``fill``, ``execute if block(s)`` and ``data ... block``.

Blocks are stored as ``BlockState(id, properties)`` (properties sorted by name) plus an optional
block entity compound; every position not set is ``minecraft:air``. A block placed by id gets its
default state with the written properties set over it (:func:`with_defaults`, from the release's
registries: ``mcfunction_parser.gamedata.default_state``); a block the registries do not know keeps
only the properties written.

Public API
- ``parse_block(text, version)``: ``id[props]{nbt}`` (an ``#tag`` too, for predicates) into
  ``BlockSpec(id, is_tag, properties, nbt)``; ``BlockSpec.state`` gives the ``BlockState``.
- ``with_defaults(spec, version)``: the spec a placement places (the block's default state under
  the written properties; a sign's block entity); ``knows_states(block_id, version)``: whether a state's properties are
  the block's whole set in that release.
- ``block_pos(source, vec3)``: ``BlockPosArgument``: the position resolved like an entity
  position but without centring, then floored.
- ``BlockMap``: ``get(pos)``, ``entity(pos)`` (block entity compound or None),
  ``setblock(pos, spec, mode="replace")``, ``fill(start, end, spec, mode="replace", filter=None)``,
  ``test(pos, spec, in_tag=None)`` (``execute if block``),
  ``compare_regions(start, end, destination, masked)`` (``execute if blocks``: the count or None),
  ``block_nbt(pos)`` and ``modify_block(pos, change)`` (the ``data`` block accessor).
Failures raise ``CommandFailure`` with the game's messages.

Sources (decompiled 1.21): server/commands/SetBlockCommand.java, FillCommand.java,
ExecuteCommand.java (checkRegions), commands/arguments/blocks/BlockPredicateArgument.java,
commands/arguments/blocks/BlockStateParser.java (a block id starts from Block.defaultBlockState,
each written property set over it), commands/arguments/blocks/BlockInput.java,
nbt/NbtUtils.java (readBlockState: a structure palette's state likewise),
server/commands/data/BlockDataAccessor.java.
"""
from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass
from typing import Callable

from mcfunction_parser import gamedata
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Compound, Int, String
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import compound as parse_compound
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world import block_entities, signs
from emulator.world.inventories import CRAFTER, crafter_loaded, normalise_items
from emulator.world.nbt_ops import compare_nbt, copy_tag, tags_equal
from emulator.world.source import Source

AIR = "minecraft:air"
AIR_TYPES = {"minecraft:air", "minecraft:cave_air", "minecraft:void_air"}
MODIFICATION_LIMIT = 32768  # gamerule commandModificationBlockLimit default
# blocks whose new block entity saves nothing (BannerBlockEntity without patterns or name,
# SkullBlockEntity without a profile, a sound or a name, LecternBlockEntity without a book,
# BrushableBlockEntity without an item or loot table)


_ID = re.compile(r"#?[a-z0-9_.\-]+(?::[a-z0-9_.\-/]+)?")
_PROPERTY = re.compile(r"\s*([a-z0-9_]+)\s*=\s*([a-z0-9_\-.+]+)\s*")


@dataclass(frozen=True)
class BlockState:
    id: str
    properties: tuple[tuple[str, str], ...] = ()

    @property
    def is_air(self) -> bool:
        return self.id in AIR_TYPES

    def __str__(self) -> str:
        props = ",".join(f"{k}={v}" for k, v in self.properties)
        return f"{self.id}[{props}]" if props else self.id

    @classmethod
    def of(cls, block_id: str, properties: dict) -> "BlockState":
        """The state with ``properties`` (in the sorted order states keep them)."""
        return cls(block_id, tuple(sorted(properties.items())))


@dataclass(frozen=True)
class BlockSpec:
    """A parsed block argument: a state to place or a predicate to test."""

    id: str
    is_tag: bool
    properties: tuple[tuple[str, str], ...]
    nbt: Compound | None

    @property
    def state(self) -> BlockState:
        return BlockState(self.id, self.properties)


def _namespaced(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


def parse_block(text: str, version=(1, 21, 0)) -> BlockSpec:
    """``id[k=v,...]{nbt}``, the NBT in the grammar of ``version`` (mixed lists from 1.21.5); raises
    ValueError on malformed text (the parser reports it first)."""
    m = _ID.match(text)
    if m is None:
        raise ValueError(f"expected a block id: {text!r}")
    is_tag = m.group().startswith("#")
    block_id, pos = _namespaced(m.group().lstrip("#")), m.end()
    properties = {}
    if text[pos:pos + 1] == "[":
        close = text.index("]", pos)
        body = text[pos + 1:close]
        for part in filter(str.strip, body.split(",")):
            pm = _PROPERTY.fullmatch(part)
            if pm is None:
                raise ValueError(f"bad block property {part!r} in {text!r}")
            properties[pm.group(1)] = pm.group(2)
        pos = close + 1
    nbt = None
    if text[pos:pos + 1] == "{":
        reader = Reader(text, Loc("<block>", 1, 1), tuple(version))
        reader.pos = pos
        try:
            nbt = parse_compound(reader)
        except ParseError as err:
            raise ValueError(err.message) from None
        pos = reader.pos
    if pos != len(text):
        raise ValueError(f"unexpected text after block: {text[pos:]!r}")
    return BlockSpec(block_id, is_tag, tuple(sorted(properties.items())), nbt)


def with_defaults(spec: BlockSpec, version) -> BlockSpec:
    """The spec placed for ``spec`` in release ``version``: the block's default state with the
    written properties set over it (BlockStateParser, NbtUtils.readBlockState); a tag, or a block
    the registries do not know, as written. A sign's NBT is the block entity it loads into
    (emulator.world.signs.loaded_entity)."""
    if spec.is_tag or not spec.id.startswith("minecraft:"):
        return spec
    if signs.is_sign(spec.id):
        spec = dataclasses.replace(spec, nbt=signs.loaded_entity(version, spec.nbt))
    default = gamedata.default_state(spec.id, version)
    if not default:
        return spec
    return dataclasses.replace(spec, properties=tuple(sorted({**default, **dict(spec.properties)}.items())))


def knows_states(block_id: str, version) -> bool:
    """Whether a placed ``block_id``'s properties are all it has in ``version``: the block is in
    that very release's registries (a later release read with older registries may have added
    properties)."""
    release, exact = gamedata.registry_release(version)
    return exact and block_id.startswith("minecraft:") and gamedata.default_state(block_id, release) is not None


def block_pos(source: Source, vec) -> tuple[int, int, int]:
    """``BlockPos.containing(coordinates.getPosition(source))``: no centring, floor each axis."""
    return tuple(math.floor(v) for v in source.position_of(vec, centre=False))


def _box(start, end):
    lo = tuple(min(a, b) for a, b in zip(start, end))
    hi = tuple(max(a, b) for a, b in zip(start, end))
    return lo, hi


def _volume(lo, hi) -> int:
    return math.prod(h - l + 1 for l, h in zip(lo, hi))


def box_positions(start, end) -> list[tuple[int, int, int]]:
    """Every position of the box between two corners."""
    return list(_positions(*_box(start, end)))


def _positions(lo, hi):
    # BlockPos.betweenClosed: x fastest, then y, then z.
    for z in range(lo[2], hi[2] + 1):
        for y in range(lo[1], hi[1] + 1):
            for x in range(lo[0], hi[0] + 1):
                yield (x, y, z)


def _loaded(block_id: str, nbt: Compound) -> None:
    """A block entity's NBT as the game loads and saves it: its stacks' components read; a crafter's
    own fields (:func:`emulator.world.inventories.crafter_loaded`)."""
    normalise_items(nbt)
    if block_id == CRAFTER:
        crafter_loaded(nbt)


WORLD_RELEASE = (1, 21, 11)  # the release a world runs as when no pack says


class BlockMap:
    def __init__(self, version_of: Callable[[], tuple] = lambda: WORLD_RELEASE) -> None:
        self.states: dict[tuple[int, int, int], BlockState] = {}
        self.entities: dict[tuple[int, int, int], Compound] = {}
        self.version_of = version_of  # the release the world runs as (what a new block entity saves)
        # AbstractFurnaceBlockEntity.setItem of an input: (block id, NBT, before, after, version),
        # set by the world (its recipes decide: emulator.world.furnaces.input_set)
        self.furnace_input_set: Callable | None = None
        self.edits = 0  # block states set so far: what is derived from the whole map is kept until it grows
        self._derived: dict[str, tuple[int, object]] = {}  # derived(): key -> (edits then, the value)

    def derived(self, key: str, make: Callable[["BlockMap"], object]):
        """``make(self)``, made again only after a block state was set (``key`` names it)."""
        known = self._derived.get(key)
        if known is None or known[0] != self.edits:
            known = self._derived[key] = (self.edits, make(self))
        return known[1]

    def get(self, pos) -> BlockState:
        return self.states.get(tuple(pos), BlockState(AIR))

    def entity(self, pos) -> Compound | None:
        return self.entities.get(tuple(pos))

    def has_any(self, block_ids) -> bool:
        return any(state.id in block_ids for state in self.states.values())

    def _place(self, pos, spec: BlockSpec) -> bool:
        """``BlockInput.place``: False when the state is already there (block entity data not applied)."""
        pos, state = tuple(pos), spec.state
        if self.get(pos) == state:
            return False
        if state.is_air:
            self.states.pop(pos, None)
        else:
            self.states[pos] = state
        self.edits += 1
        self.entities.pop(pos, None)
        triggered = dict(state.properties).get("triggered") == "true"
        nbt = block_entities.new_entity(state.id, self.version_of(), triggered)
        if spec.nbt is not None and block_entities.type_id(state.id) is not None:  # BlockInput.place: else ignored
            nbt = block_entities.placed_with(state.id, self.version_of(), spec.nbt, triggered)
            _loaded(state.id, nbt)
        if nbt is not None:
            self.entities[pos] = nbt
        return True

    def place(self, pos, spec: BlockSpec) -> bool:
        """Place ``spec`` whatever is there (``BlockInput.place`` as the game's own code calls it);
        False when that state was already there."""
        return self._place(pos, spec)

    def set_state(self, pos, state: BlockState) -> None:
        """Level.setBlock of another state of the same block: its block entity stays (a lever pulled,
        a barrel opened)."""
        self.states[tuple(pos)] = state
        self.edits += 1

    def setblock(self, pos, spec: BlockSpec, mode: str = "replace") -> int:
        """``setblock POS BLOCK [replace|keep|destroy]``: 1, or fails "Could not set the block"."""
        if mode == "keep" and not self.get(pos).is_air:
            raise CommandFailure("commands.setblock.failed")
        if not self._place(pos, spec):
            raise CommandFailure("commands.setblock.failed")
        return 1

    def fill(self, start, end, spec: BlockSpec, mode: str = "replace",
             filter: Callable[[tuple[int, int, int]], bool] | None = None,
             on_placed: Callable[[tuple[int, int, int], BlockState], None] | None = None,
             before: Callable[[tuple[int, int, int]], bool] | None = None) -> int:
        """``fill FROM TO BLOCK [replace [FILTER]|keep|hollow|outline|destroy|strict]``: blocks changed.
        ``before(pos)`` runs on each position the mode keeps, before its block is placed (the destroy
        mode's drops, Clearable.tryClear); the position counts when it returns True even if nothing
        is placed. ``on_placed(pos, state_before)`` runs after each block is set, before the next
        (Block.onPlace)."""
        lo, hi = _box(start, end)
        volume = _volume(lo, hi)
        if volume > MODIFICATION_LIMIT:
            raise CommandFailure("commands.fill.toobig", MODIFICATION_LIMIT, volume)
        air = BlockSpec(AIR, False, (), None)
        count = 0
        for pos in list(_positions(lo, hi)):
            if filter is not None and not filter(pos):
                continue
            if mode == "keep" and not self.get(pos).is_air:
                continue
            border = any(p in (l, h) for p, l, h in zip(pos, lo, hi))
            if mode == "outline" and not border:
                continue
            affected = before(pos) if before is not None else False
            state_before = self.get(pos)
            if self._place(pos, air if mode == "hollow" and not border else spec):
                count += 1
                if on_placed is not None:
                    on_placed(pos, state_before)
            elif affected:
                count += 1
        if count == 0:
            raise CommandFailure("commands.fill.failed")
        return count

    def clone_to(self, start, end, target: "BlockMap", destination, keep: Callable[[tuple[int, int, int]], bool],
                 barrier: BlockSpec, mode: str = "normal", same_level: bool = True) -> tuple[int, list, tuple]:
        """``clone`` (CloneCommands.clone): the blocks of the box between ``start`` and ``end`` that
        ``keep`` takes, with their block entities, to ``target`` from ``destination`` (its lowest
        corner); ``move`` leaves air where they were. Returns the count (each block set but a
        barrier: the game sets a barrier first, then the block), the positions changed and the
        offset (``barrier``: the barrier's default state). Fails when the boxes overlap in one level unless ``force`` or ``move``, when the
        box is over the block limit, or when nothing was cloned."""
        lo, hi = _box(start, end)
        offset = tuple(d - l for d, l in zip(destination, lo))
        if mode == "normal" and same_level and all(
                l + o <= h and l <= h + o for l, h, o in zip(lo, hi, offset)):
            raise CommandFailure("commands.clone.overlap")
        volume = _volume(lo, hi)
        if volume > MODIFICATION_LIMIT:
            raise CommandFailure("commands.clone.toobig", MODIFICATION_LIMIT, volume)
        taken = [(pos, self.get(pos), copy_tag(self.entity(pos)) if self.entity(pos) is not None else None)
                 for pos in _positions(lo, hi) if keep(pos)]
        air = BlockSpec(AIR, False, (), None)
        changed = []
        if mode == "move":
            for pos, _, _ in taken:
                self._place(pos, air)
            changed += [pos for pos, _, _ in taken]
        placed = [(tuple(p + o for p, o in zip(pos, offset)), state, nbt) for pos, state, nbt in taken]
        for pos, _, _ in reversed(placed):
            target._place(pos, barrier)
        count = sum(target._place(pos, BlockSpec(state.id, False, state.properties, nbt))
                    for pos, state, nbt in placed)
        return count, changed + [pos for pos, _, _ in placed], offset

    def test(self, pos, spec: BlockSpec, in_tag: Callable[[str, str], bool] | None = None) -> bool:
        """``execute if block``: id or tag (``in_tag(tag_id, block_id)``), every written property
        equal, NBT a partial match."""
        state = self.get(pos)
        if spec.is_tag:
            if in_tag is None or not in_tag(spec.id, state.id):
                return False
        elif state.id != spec.id:
            return False
        props = dict(state.properties)
        if any(props.get(k) != v for k, v in spec.properties):
            return False
        if spec.nbt is not None:
            return compare_nbt(spec.nbt, self.block_nbt(pos, quiet=True))
        return True

    def compare_regions(self, start, end, destination, masked: bool) -> int | None:
        """``execute if blocks``: the number of compared blocks, or None at the first difference."""
        lo, hi = _box(start, end)
        volume = _volume(lo, hi)
        if volume > MODIFICATION_LIMIT:
            raise CommandFailure("commands.execute.blocks.toobig", MODIFICATION_LIMIT, volume)
        offset = tuple(d - l for d, l in zip(destination, lo))
        count = 0
        for pos in _positions(lo, hi):
            there = tuple(p + o for p, o in zip(pos, offset))
            state = self.get(pos)
            if masked and state.is_air:
                continue
            if state != self.get(there):
                return None
            here_nbt, there_nbt = self.entity(pos), self.entity(there)
            if here_nbt is not None and (there_nbt is None or not tags_equal(here_nbt, there_nbt)):
                return None
            count += 1
        return count

    def block_nbt(self, pos, quiet: bool = False) -> Compound | None:
        """The block entity's NBT with the position and id the game adds (``saveWithFullMetadata``)."""
        block_id = self.get(pos).id
        if not block_entities.known(block_id, self.version_of()):
            raise Unmodelled(f"the block entity of {block_id} (what it saves in this release is not known)")
        stored = self.entity(pos)
        if stored is None:
            if quiet:
                return None
            raise CommandFailure("commands.data.block.invalid")
        nbt = copy_tag(stored)
        nbt.update(x=Int(pos[0]), y=Int(pos[1]), z=Int(pos[2]), id=String(block_entities.type_id(block_id) or block_id))
        return nbt

    def modify_block(self, pos, change: Callable[[Compound], object]):
        """The ``data`` block accessor: edit a copy, keep it only when ``change`` succeeds."""
        nbt = self.block_nbt(pos)
        result = change(nbt)
        for key in ("x", "y", "z", "id"):
            nbt.pop(key, None)
        _loaded(self.get(pos).id, nbt)
        self.entities[tuple(pos)] = nbt
        return result
