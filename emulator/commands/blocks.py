"""Block commands and conditions over the world's block map: ``setblock``, ``fill`` (``replace
FILTER`` too), ``clone``, ``execute if block`` and ``execute if blocks``; ``fillbiome`` and ``execute if
biome`` over the biome cells the world knows (:mod:`emulator.world.biomes`).

The parser keeps ``setblock``/``fill``/``clone``/``fillbiome`` as generic commands (their text); they are
read here. Sources (decompiled 1.21): server/commands/SetBlockCommand.java, FillCommand.java, CloneCommands.java,
FillBiomeCommand.java, ExecuteCommand.java (checkRegions; ``if biome``: the ResourceOrTagArgument
tests Level.getBiome at getLoadedBlockPos).
"""
from __future__ import annotations

import math

from emulator.world import biomes, block_breaking, block_rotation, command_blocks, crafters, inventories, rails, structures
from emulator.world.blocks import BlockSpec, block_pos, parse_block, with_defaults
from mcfunction_parser import ast
from mcfunction_parser.arguments import vec3
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import compound as parse_compound

from .entities import world_source
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.loot_context import namespaced

# the blocks that read their neighbours' signal when a neighbour changes
NEIGHBOUR_READERS = command_blocks.COMMAND_BLOCKS | {crafters.CRAFTER}


def block_argument(env, text: str) -> BlockSpec:
    try:
        return parse_block(text, env.state.version)
    except ValueError as error:
        raise CommandFailure("dpemu.block.invalid", text, error, report=True) from None


def block_tag_test(env):
    """Membership in the world's block tags; an unknown pack tag fails the command
    (BlockPredicateArgument: "Unknown block tag")."""
    resources = env.state.resources

    def in_tag(tag_id: str, block_id: str) -> bool:
        if resources.tag("block", tag_id) is None and (resources.vanilla_data or not tag_id.startswith("minecraft:")):
            raise CommandFailure("arguments.block.tag.unknown", tag_id, report=True)
        return resources.in_tag("block", tag_id, block_id)
    return in_tag


def if_block(env, cond: ast.IfBlock, ctx) -> int:
    """``if block POS BLOCK``: 1 when the block matches."""
    pos = loaded_block_pos(env.state, ctx, cond.pos)
    return int(env.state.blocks_in(ctx.dimension).test(pos, block_argument(env, cond.block), block_tag_test(env)))


def if_blocks(env, cond: ast.IfBlocks, ctx) -> int:
    """``if blocks START END DESTINATION all|masked``: the matching block count, or 0."""
    source = world_source(env.state, ctx)
    start, end, destination = (loaded_block_pos(env.state, ctx, corner, source)
                               for corner in (cond.start, cond.end, cond.destination))
    found = env.state.blocks_in(ctx.dimension).compare_regions(start, end, destination, cond.mode == "masked")
    return found or 0


def if_biome(env, cond: ast.IfBiome, ctx) -> int:
    """``if biome POS BIOME``: 1 when the biome there is BIOME or in tag ``#BIOME``."""
    pos = loaded_block_pos(env.state, ctx, cond.pos)
    return int(biomes.matches(env.state.resources, cond.biome, biomes.biome_at(env.state, ctx.dimension, pos)))


# Level.isInWorldBoundsHorizontal: x and z in [-30,000,000, 30,000,000)
_WORLD_BORDER = 30_000_000


def if_loaded(env, cond: ast.IfLoaded, ctx) -> int:
    """``if loaded POS``: 1 when POS's chunk is loaded and ticks entities (ExecuteCommand.isChunkLoaded;
    the position is read by BlockPosArgument.getBlockPos, unchecked). Every chunk of the world is
    loaded here, as ``forceload`` would keep them, so any column inside the world's 30,000,000
    blocks is; past them no chunk exists."""
    x, _, z = block_pos(world_source(env.state, ctx), cond.pos)
    return int(-_WORLD_BORDER <= x < _WORLD_BORDER and -_WORLD_BORDER <= z < _WORLD_BORDER)


def loaded_block_pos(state, ctx, vec, source=None, dimension: str | None = None) -> tuple[int, int, int]:
    """BlockPosArgument.getLoadedBlockPos, which every command reading a block position uses (setblock,
    fill, fillbiome, clone, place, ``data … block``, ``execute if block|blocks|biome``, ``execute
    store … block``, ``item … block``, ``loot`` with a block; only spawn points take any position):
    the position, checked by ``in_world``. ``dimension`` is the position's level when it is not the
    context's (clone's ``from``/``to``)."""
    pos = block_pos(source or world_source(state, ctx), vec)
    in_world(state, dimension or ctx.dimension, pos)
    return pos


def in_world(state, dimension: str, pos: tuple[int, int, int]) -> None:
    """A position outside the level's build height (Level.isOutsideBuildHeight) or past 30,000,000
    on x or z fails the command, "That position is out of this world!" (Level.isInWorldBounds);
    every chunk is loaded here, so the game's "not loaded" never happens."""
    x, y, z = pos
    height = state.entities.table.levels.build_height(dimension, state.version)
    if not (height[0] <= y < height[1] and -_WORLD_BORDER <= x < _WORLD_BORDER and -_WORLD_BORDER <= z < _WORLD_BORDER):
        raise CommandFailure("argument.pos.outofworld")


def fillbiome_command(env, cmd: ast.GenericCommand, ctx) -> int:
    """``fillbiome FROM TO BIOME [replace FILTER]``: the cells set (FillBiomeCommand.fill)."""
    corners, words = _read(cmd, env.state.version)
    source = world_source(env.state, ctx)
    start, end = (loaded_block_pos(env.state, ctx, corner, source) for corner in corners)
    keep = None
    if len(words) > 2 and words[1] == "replace":
        resources, wanted = env.state.resources, words[2]
        keep = lambda found: biomes.matches(resources, wanted, found)  # noqa: E731 - the filter
    return biomes.fill(env.state, ctx.dimension, start, end, biomes.namespaced(words[0]), keep)


def block_command(env, cmd: ast.GenericCommand, ctx) -> int:
    """``setblock POS BLOCK [MODE]`` / ``fill FROM TO BLOCK [replace [FILTER]] [MODE]``."""
    corners, words = _read(cmd, env.state.version)
    spec = with_defaults(block_argument(env, words[0]), env.state.version)
    mode, filter_word = _mode(words[1:])
    source = world_source(env.state, ctx)
    positions = [loaded_block_pos(env.state, ctx, corner, source) for corner in corners]
    blocks = env.state.blocks_in(ctx.dimension)
    if cmd.name == "setblock":
        count = _setblock(env, ctx, blocks, positions[0], spec, mode)
        changed = positions[:1]
    else:
        count, changed = _fill(env, ctx, blocks, positions, spec, mode, filter_word)
    if mode != "strict":  # strict: UPDATE_KNOWN_SHAPE and no updateNeighboursOnBlockSet
        _neighbours_updated(blocks, changed, spec)  # blockUpdated for each block placed
        if cmd.name == "setblock" or spec.id in NEIGHBOUR_READERS or blocks.has_any(NEIGHBOUR_READERS):
            command_blocks.after_change(env.state, ctx.dimension, changed)
            crafters.after_change(env.state, ctx.dimension, changed)
    return count


def _mode(words: list[str]) -> tuple[str, str | None]:
    """The mode and the ``replace`` filter after the block: ``MODE``, or ``replace [FILTER]`` then,
    from 1.21.5 on, a mode after the filter (``fill … replace stone destroy``)."""
    if words[:1] == ["replace"] and len(words) > 1:
        return (words[2] if len(words) > 2 else "replace"), words[1]
    return (words[0] if words else "replace"), None


def _fill(env, ctx, blocks, positions, spec: BlockSpec, mode: str, filter_word: str | None):
    """FillCommand.fillBlocks: the count and the positions whose block was placed."""
    block_filter = None
    if filter_word is not None:
        kept, in_tag = block_argument(env, filter_word), block_tag_test(env)
        block_filter = lambda pos: blocks.test(pos, kept, in_tag)  # noqa: E731 - FillCommand's filter
    changed = []
    placed = _placed(env, ctx, spec, mode)

    def on_placed(pos, before):
        changed.append(pos)
        placed(pos, before)
    count = blocks.fill(positions[0], positions[1], spec, mode, block_filter, on_placed,
                        lambda pos: _clear_or_destroy(env, ctx, blocks, pos, mode))
    return count, changed


def clone_command(env, cmd: ast.GenericCommand, ctx) -> int:
    """``clone [from DIM] BEGIN END [to DIM] DESTINATION [strict] [replace|masked|filtered FILTER]
    [force|move|normal]`` (CloneCommands): the blocks copied, then the block ticks pending in the box
    (LevelTicks.copyAreaFrom) and, unless ``strict``, the neighbours told (Level.blockUpdated)."""
    read = _clone_words(cmd, env.state.version)
    levels = env.state.entities.table.levels
    source_level = _namespaced(read["from"]) if read["from"] else ctx.dimension
    target_level = _namespaced(read["to"]) if read["to"] else ctx.dimension
    for level in (source_level, target_level):
        levels.level_id(level)  # DimensionArgument: an unknown level fails the command
    source = world_source(env.state, ctx)
    start, end, destination = (loaded_block_pos(env.state, ctx, corner, source, level) for corner, level
                               in zip(read["corners"], (source_level, source_level, target_level)))
    blocks, target = env.state.blocks_in(source_level), env.state.blocks_in(target_level)
    keep = lambda pos: True  # noqa: E731 - replace
    if read["mask"] == "masked":
        keep = lambda pos: not blocks.get(pos).is_air  # noqa: E731
    elif read["mask"] == "filtered":
        wanted, in_tag = block_argument(env, read["filter"]), block_tag_test(env)
        keep = lambda pos: blocks.test(pos, wanted, in_tag)  # noqa: E731
    barrier = with_defaults(parse_block("minecraft:barrier"), env.state.version)
    count, changed, offset = blocks.clone_to(start, end, target, destination, keep, barrier, read["mode"],
                                             source_level == target_level)
    lo, hi = (tuple(min(a, b) for a, b in zip(start, end)), tuple(max(a, b) for a, b in zip(start, end)))
    env.state.block_ticks.copy_area(source_level, lo, hi, offset, target_level)
    if not read["strict"]:
        moved = [pos for pos in changed[:len(changed) - count]] if read["mode"] == "move" else []
        for level, positions in ((source_level, moved), (target_level, changed[len(moved):])):
            _neighbours_updated(env.state.blocks_in(level), positions, BlockSpec("minecraft:air", False, (), None))
            command_blocks.after_change(env.state, level, positions)
            crafters.after_change(env.state, level, positions)
    if count == 0:
        raise CommandFailure("commands.clone.failed")
    return count


def _clone_words(cmd: ast.GenericCommand, version) -> dict:
    """The parts of a ``clone`` command (its grammar checked by the parser for the release)."""
    reader = Reader(cmd.text, cmd.loc, tuple(version))
    found = {"from": None, "to": None, "corners": [], "strict": False, "mask": "replace", "filter": None,
             "mode": "normal"}
    try:
        reader.pos = len(cmd.name) + 1
        if _peek_word(reader) == "from":
            _word(reader), reader.skip_ws()
            found["from"] = _word(reader)
            reader.skip_ws()
        for _ in range(2):
            found["corners"].append(vec3(reader, block=True))
            reader.skip_ws()
        if _peek_word(reader) == "to":
            _word(reader), reader.skip_ws()
            found["to"] = _word(reader)
            reader.skip_ws()
        found["corners"].append(vec3(reader, block=True))
        reader.skip_ws()
        words = []
        while reader.more():
            words.append(_word(reader))
            reader.skip_ws()
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error, report=True) from None
    if words[:1] == ["strict"]:
        found["strict"], words = True, words[1:]
    if words and words[0] in ("replace", "masked", "filtered"):
        found["mask"], words = words[0], words[1:]
        if found["mask"] == "filtered":
            found["filter"], words = words[0], words[1:]
    if words:
        found["mode"] = words[0]
    return found


def _peek_word(reader: Reader) -> str:
    end = reader.pos
    while end < reader.end and not reader.text[end].isspace():
        end += 1
    return reader.text[reader.pos:end]


def _namespaced(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


def _placed(env, ctx, spec: BlockSpec, mode: str):
    """What Block.onPlace does after BlockInput.place set ``spec`` at a position: a rail replacing
    another block joins its neighbours (BaseRailBlock.onPlace -> updateState), each in turn as
    ``fill`` places them (in BlockPos.betweenClosed order); ``strict`` skips it (UPDATE_SKIP_ON_PLACE)."""
    if spec.id not in rails.RAILS or mode == "strict":
        return lambda pos, before: None
    blocks, level = env.state.blocks_in(ctx.dimension), env.state.level(ctx.dimension)

    def join(pos, before) -> None:
        if before.id != spec.id and blocks.get(pos).id == spec.id:
            rails.join(blocks, pos, command_blocks.has_neighbour_signal(level, pos))
    return join


def _setblock(env, ctx, blocks, pos, spec: BlockSpec, mode: str) -> int:
    """SetBlockCommand.setBlock: ``keep`` fails on a block that is not air; ``destroy`` breaks the
    block with its drops and places nothing when both it and the new block are air (still a
    success); before 1.21.5 the other modes empty the block's contents first, so replacing a chest
    by the same chest fails with the chest emptied (:func:`_clear_or_destroy`)."""
    if mode == "keep" and not blocks.get(pos).is_air:
        raise CommandFailure("commands.setblock.failed")
    _clear_or_destroy(env, ctx, blocks, pos, mode)
    if mode == "destroy" and spec.state.is_air and blocks.get(pos).is_air:
        return 1
    before = blocks.get(pos)
    count = blocks.setblock(pos, spec)
    _placed(env, ctx, spec, mode)(pos, before)
    return count


# 1.21.5 (with ``strict``): setblock and fill place with UPDATE_SKIP_BLOCK_ENTITY_SIDEEFFECTS instead
# of Clearable.tryClear, and fill counts a position its mode affected (destroyed) even when nothing
# could be placed there (FillCommand.Mode's affector)
SIDE_EFFECT_FLAGS_VERSION = (1, 21, 5)


def _clear_or_destroy(env, ctx, blocks, pos, mode: str) -> bool:
    """What setblock and fill do to a block before placing theirs: ``destroy`` breaks it with its
    drops (Level.destroyBlock); before 1.21.5 every mode then empties what is there
    (Clearable.tryClear: a container's items, a lectern's book, ...). True when the position counts
    for fill whatever the placing does (1.21.5+: a block destroyed)."""
    modern = tuple(env.state.version) >= SIDE_EFFECT_FLAGS_VERSION
    destroyed = mode == "destroy" and block_breaking.destroy(env.state, pos, ctx.dimension)
    if not modern:
        inventories.try_clear(blocks, pos, env.state.version)
    return destroyed and modern


def _neighbours_updated(blocks, positions, spec: BlockSpec) -> None:
    """Level.blockUpdated after the command's blocks are down: the rails beside them check they
    may stay (:func:`emulator.world.rails.notify`)."""
    # a look at six neighbours each, or first one over the level's blocks for a large fill
    if spec.id in rails.RAILS or len(positions) < 64 or blocks.has_any(rails.RAILS):
        for pos in positions:
            rails.notify(blocks, [pos], blocks.get(pos).id)


def _read(cmd: ast.GenericCommand, version) -> tuple[list, list[str]]:
    """The corner positions and the words after them (the block, a mode, a filter), read in the
    grammar of the packs' release."""
    reader = Reader(cmd.text, cmd.loc, tuple(version))
    try:
        reader.pos = len(cmd.name) + 1
        corners = [vec3(reader, block=True)]
        if cmd.name in ("fill", "fillbiome"):
            reader.pos += 1
            corners.append(vec3(reader, block=True))
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error, report=True) from None
    words = []
    try:
        reader.skip_ws()
        while reader.more():
            words.append(_word(reader))
            reader.skip_ws()
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error, report=True) from None
    if not words:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected a block", report=True)
    return corners, words


def _word(reader: Reader) -> str:
    """One argument: a word, or a block whose ``[states]`` and ``{nbt}`` may hold spaces and
    quoted strings (BlockStateParser reads the NBT with the SNBT parser, not up to a space)."""
    start, text = reader.pos, reader.text
    while reader.pos < reader.end and not text[reader.pos].isspace() and text[reader.pos] not in "[{":
        reader.pos += 1
    if reader.pos < reader.end and text[reader.pos] == "[":
        close = text.find("]", reader.pos)
        if close < 0:
            reader.fail("expected ']' to close the block states", reader.pos)
        reader.pos = close + 1
    if reader.pos < reader.end and text[reader.pos] == "{":
        parse_compound(reader)
    return text[start:reader.pos]




def place_command(env, cmd: ast.GenericCommand, ctx) -> int:
    """``place template TEMPLATE [POS [ROTATION [MIRROR [INTEGRITY [SEED]]]]]`` (PlaceCommand.
    placeTemplate): the pack's ``structure`` file with its corner at POS (the source's block by
    default) in the context's level, mirrored then turned about it; "There is no template with id"
    when no pack has it, "Failed to place template" when it holds nothing. An integrity below 1
    (random blocks left out) is not modelled, nor ``place feature|jigsaw|structure`` (world
    generation)."""
    reader = Reader(cmd.text, cmd.loc, tuple(env.state.version))
    try:
        reader.pos = len(cmd.name) + 1
        kind = reader.word()
        if kind != "template":
            raise Unmodelled(f"'place {kind}' (the emulator does not generate features, jigsaw pieces or structures)")
        reader.skip_ws()
        template_id = namespaced(reader.word())
        reader.skip_ws()
        corner = vec3(reader, block=True) if reader.more() else None
        options = reader.text[reader.pos:reader.end].split()
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error, report=True) from None
    rotation, mirror, integrity = (options + ["none", "none", "1"][len(options):])[:3]
    if rotation not in block_rotation.ROTATIONS or mirror not in block_rotation.MIRRORS:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, f"unknown rotation or mirror in {options}", report=True)
    if float(integrity) < 1.0:
        raise Unmodelled("place template with an integrity below 1 (BlockRotProcessor's random)")
    source = world_source(env.state, ctx)  # the position is an argument: read before the template
    origin = loaded_block_pos(env.state, ctx, corner, source) if corner is not None else \
        tuple(math.floor(v) for v in source.pos)
    data = env.state.resources.template_file(template_id)
    if data is None:
        raise CommandFailure("commands.place.template.invalid", template_id)
    try:
        template = structures.read_template(data)
    except structures.StructureError as error:
        raise CommandFailure("dpemu.structure.invalid", template_id, error, report=True) from None
    if not structures.place(env.state, template, origin, ctx.dimension, block_rotation.MIRRORS.index(mirror),
                            block_rotation.ROTATIONS.index(rotation)):
        raise CommandFailure("commands.place.template.failed")
    return 1


# generic commands by name
HANDLERS = {"setblock": block_command, "fill": block_command, "fillbiome": fillbiome_command, "place": place_command,
            "clone": clone_command}
