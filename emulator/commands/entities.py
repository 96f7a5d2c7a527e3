"""Entity arguments, execution contexts and the entity commands (``summon kill tag tp ride``) on a
:class:`~emulator.world.state.WorldState`.

A :class:`~emulator.world.state.Context` names its executor by an integer id: the entity's
creation index (``Entity.order``, its slot in the store's table, which keeps killed entities), so
``@s`` keeps reaching an entity even after it was killed (as the game's source keeps its entity
object).

- ``select(state, target, ctx)``: EntityArgument.getOptionalEntities: what a selector, player name
  or UUID finds (maybe none); ``found`` (EntityArgument.getEntities: none fails) and ``single``
  (getEntity: exactly one); ``holder_names``: a selector's score holders.
- ``executor``, ``context_as``, ``entity_stage_context``, ``entity_context``, ``world_source``:
  contexts made for entities (the numba VM makes its ``as``/``at`` contexts with these too).
- ``HANDLERS``: ``summon kill tag tp ride``, each ``(env, cmd, ctx) -> int``; ``GENERIC_HANDLERS``:
  ``rotate`` (kept as text by the parser).
- ``new_state(shuffle)``, ``parse_target(text)``, ``describe(state, entity)``: the API's side.

Entities live in the store's arrays (:mod:`emulator.world.entity_table`), which the numba VM reads
and writes itself: what a command changes here, the VM sees, with nothing to notify.

Sources (decompiled 1.21): commands/arguments/EntityArgument.java, server/commands/TeleportCommand.java,
SummonCommand.java, KillCommand.java, TagCommand.java, RideCommand.java, java.util.UUID.fromString;
RotateCommand.java (1.21.2).
"""
from __future__ import annotations

import random
from dataclasses import replace
from functools import lru_cache

import numpy as np

from emulator.world import combat, living, projectiles, relations, teleport
from emulator.world.entities import Entity, EntityStore, add_tag, remove_tag
from emulator.world.entity_types import ENTITY_TYPES
from emulator.world import advancement_progress, advancements, predicates
from emulator.world.loot_context import LootContext
from emulator.world.selectors import SelectorQuery, SelectorWorld
from emulator.world.source import Source
from emulator.world.context import Context, SERVER
from emulator.world.state import WorldState
from mcfunction_parser import ast, selectors
from mcfunction_parser.arguments import holder_from_word, vec2, vec3
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.reader import ParseError, Reader

from emulator.world.errors import CommandFailure

# The stages that make one context per entity from the entity alone, by the VM's kind number
# (OP_ASSTAGE's operand): as, at, positioned as, rotated as
ENTITY_CONTEXT_STAGES = (ast.ExAs, ast.ExAt, ast.ExPositionedAs, ast.ExRotatedAs)


class ShuffledEntityStore(EntityStore):
    """``--shuffle SEED``: each new entity goes to a random place among its level's entities in the
    iteration order, so unsorted ``@e`` visits entities in a seeded permutation instead of creation
    order (order-dependent packs show up as different results)."""

    def __init__(self, seed: int = 0, shuffle_seed: int = 0) -> None:
        super().__init__(seed)
        self.shuffle_rng = random.Random(shuffle_seed)

    def _place(self, start: int, end: int) -> int:
        return self.shuffle_rng.randint(start, end)


# ---------------------------------------------------------------------- contexts
def executor(state: WorldState, ctx: Context) -> Entity | None:
    return None if ctx.executor == SERVER else state.entities.table.handles[ctx.executor]


def world_source(state: WorldState, ctx: Context) -> Source:
    """The world library's view of a context (its executor, float32 rotation and local-coordinate math)."""
    return Source(pos=ctx.pos, yaw=np.float32(ctx.rot[0]), pitch=np.float32(ctx.rot[1]), entity=executor(state, ctx),
                  anchor=ctx.anchor, dimension=ctx.dimension)


def context_as(state: WorldState, ctx: Context, entity: Entity) -> Context:
    return replace(ctx, executor=entity.order)


def context_at(ctx: Context, entity: Entity) -> Context:
    """``execute at``: the entity's level, position and rotation (the executor stays)."""
    return replace(ctx, pos=entity.pos, rot=(float(entity.yaw), float(entity.pitch)), dimension=entity.dimension)


def entity_stage_context(kind: int, state: WorldState, ctx: Context, entity: Entity) -> Context:
    """The context stage ``ENTITY_CONTEXT_STAGES[kind]`` makes from ``ctx`` for ``entity``."""
    if kind == 0:
        return context_as(state, ctx, entity)
    if kind == 1:
        return context_at(ctx, entity)
    if kind == 2:
        return replace(ctx, pos=entity.pos)
    return replace(ctx, rot=(float(entity.yaw), float(entity.pitch)))


def entity_context(state: WorldState, entity: Entity, anchor: str = "feet") -> Context:
    """A context run by ``entity`` at its position and rotation (``Emulator.call(as_=...)``)."""
    return Context(entity.order, entity.pos, (float(entity.yaw), float(entity.pitch)), anchor, entity.dimension)


# ---------------------------------------------------------------------- entity arguments
def parse_uuid(text: str) -> tuple[int, int, int, int]:
    """``UUID.fromString``: five hex groups, masked to 32/16/16/16/48 bits, as int[4]."""
    groups = [int(g, 16) for g in text.split("-")]
    most = ((groups[0] & 0xFFFFFFFF) << 32) | ((groups[1] & 0xFFFF) << 16) | (groups[2] & 0xFFFF)
    least = ((groups[3] & 0xFFFF) << 48) | (groups[4] & 0xFFFFFFFFFFFF)
    return tuple(((v + 2**31) & 0xFFFFFFFF) - 2**31 for v in (most >> 32, most, least >> 32, least))


def _named(target: ast.NameTarget, store: EntityStore) -> list[Entity]:
    """The online player of that name, or the entity of that UUID."""
    if target.is_uuid:
        found = store.by_uuid(parse_uuid(target.name))
    else:
        found = next((p for p in store.players() if p.player_name == target.name), None)
    return [] if found is None else [found]


def _query(state: WorldState, selector: ast.Selector) -> SelectorQuery:
    """A selector's tests are built once per AST node (nodes are immutable and live for the run)."""
    query = state.selector_cache.get(id(selector))
    if query is None or query[0] is not selector:
        query = state.selector_cache[id(selector)] = (selector, SelectorQuery(selector, selector_world(state)))
    return query[1]


def selector_world(state: WorldState) -> SelectorWorld:
    """The world's entity type tags and predicates, as selectors read them (``predicate=``:
    EntitySelectorOptions, the entity as ``this`` at its own position, in its own level)."""
    resources = state.resources

    def predicate(predicate_id: str, entity: Entity) -> bool:
        where = LootContext(state, entity.pos, this=entity, dimension=entity.dimension)
        return predicates.test_predicate(predicate_id, where)
    def advancements(text: str, entity: Entity) -> bool:
        return advancement_progress.matches(state, entity, advancement_progress.parse_selector_value(text))
    return SelectorWorld(lambda tag, type_id: resources.in_tag("entity_type", tag, type_id), predicate, advancements)


def select(state: WorldState, target, ctx: Context) -> list[Entity]:
    """EntityArgument.getOptionalEntities: what a selector, player name or UUID finds."""
    if isinstance(target, ast.Selector):
        return _query(state, target).run(state.entities, world_source(state, ctx), state.scoreboard.get)
    return _named(target, state.entities)


def found(state: WorldState, target, ctx: Context) -> list[Entity]:
    """EntityArgument.getEntities: none found fails."""
    entities = select(state, target, ctx)
    if not entities:
        raise CommandFailure("argument.entity.notfound.entity")
    return entities


def single(state: WorldState, target, ctx: Context) -> Entity:
    """EntityArgument.getEntity: exactly one."""
    entities = found(state, target, ctx)
    if len(entities) > 1:
        raise CommandFailure("argument.entity.toomany")
    return entities[0]


def players_found(state: WorldState, target, ctx: Context) -> list[Entity]:
    """EntityArgument.getPlayers: the players found (EntitySelector.findPlayers: a UUID names a
    player only); none fails "No player was found"."""
    players = [e for e in select(state, target, ctx) if e.is_player]
    if not players:
        raise CommandFailure("argument.entity.notfound.player")
    return players


def single_player(state: WorldState, target, ctx: Context) -> Entity:
    """EntityArgument.getPlayer (EntitySelector.findSinglePlayer): anything but one player fails
    "No player was found"."""
    players = [e for e in select(state, target, ctx) if e.is_player]
    if len(players) != 1:
        raise CommandFailure("argument.entity.notfound.player")
    return players[0]


def holder_names(state: WorldState, selector: ast.Selector, ctx: Context) -> list[str]:
    """ScoreHolderArgument with a selector: each entity's holder name (UUID, or player name)."""
    return [e.score_holder for e in found(state, selector, ctx)]


def _executor_required(state: WorldState, ctx: Context) -> Entity:
    """CommandSourceStack.getEntityOrException."""
    entity = executor(state, ctx)
    if entity is None:
        raise CommandFailure("permissions.requires.entity")
    return entity


# ---------------------------------------------------------------------- commands
def summon(env, cmd: ast.Summon, ctx: Context) -> int:
    """``summon TYPE [POS] [NBT]`` at the execution position by default (``Passengers`` summoned
    riding it)."""
    if cmd.entity_type not in ENTITY_TYPES:
        env.warn(cmd, f"unknown entity type '{cmd.entity_type}': summoned with the default size 0.6 x 1.8")
    source = world_source(env.state, ctx)
    pos = source.pos if cmd.pos is None else source.position_of(cmd.pos)
    made = relations.summon_with_passengers(env.state.entities, cmd.entity_type, pos, cmd.nbt, ctx.dimension)
    projectiles.launched(env.state, made)
    if made.type == "minecraft:painting":
        env.unmodelled(cmd, "where a summoned painting hangs (the game centres it on its block by its variant's "
                            "size): it keeps the position given")
    return 1


MAX_FLOAT = 3.4028234663852886e38  # Float.MAX_VALUE


def kill(env, cmd: ast.Kill, ctx: Context) -> int:
    """``kill [TARGETS]`` (the executor by default): a living entity is hurt by ``generic_kill`` past
    any protection and dies (emulator.world.combat: a mob leaves the store, a player dies to
    respawn later); other entities and armor stands leave the store, losing their scores and team
    (:meth:`WorldState.discard`)."""
    state = env.state
    targets = [_executor_required(state, ctx)] if cmd.targets is None else found(state, cmd.targets, ctx)
    for entity in targets:
        if not entity.alive:
            continue
        if living.is_living(entity.type) and entity.type != "minecraft:armor_stand":
            # LivingEntity.kill: hurt by generic_kill past every protection (an armor stand is removed)
            if combat.hurt(state, entity, MAX_FLOAT, combat.DamageSource("minecraft:generic_kill"), True):
                continue
        if not entity.is_player:
            state.discard(entity)
    return len(targets)


def tag(env, cmd: ast.TagCommand, ctx: Context) -> int:
    """``tag TARGETS add|remove NAME``: the number of entities changed (none fails);
    ``tag TARGETS list``: the number of distinct tags."""
    targets = found(env.state, cmd.targets, ctx)
    if cmd.action == "list":
        return len({name for entity in targets for name in entity.tags})
    change = add_tag if cmd.action == "add" else remove_tag
    changed = sum(change(entity, cmd.name) for entity in targets)
    if changed == 0:
        raise CommandFailure("commands.tag.add.failed" if cmd.action == "add" else "commands.tag.remove.failed")
    return changed


def tp(env, cmd: ast.Teleport, ctx: Context) -> int:
    """Every ``tp`` form; the result is the number of entities moved. A player taken to another
    level fires ``changed_dimension``."""
    if not env.state.resources.advancements:
        return _teleport(env, cmd, ctx)
    players = {p: p.dimension for p in env.state.entities.players()}
    try:
        return _teleport(env, cmd, ctx)
    finally:
        for player, origin in players.items():
            if player.dimension != origin:
                advancements.changed_dimension(env.state, player, origin)


def _teleport(env, cmd: ast.Teleport, ctx: Context) -> int:
    state = env.state
    source = world_source(state, ctx)
    if cmd.targets is None:
        entity = _executor_required(state, ctx)
        if isinstance(cmd.destination, ast.Vec3):
            teleport.apply(entity, teleport.to_position_self(source, cmd.destination), state.entities, state.version)
        else:
            teleport.apply(entity, teleport.to_entity(single(state, cmd.destination, ctx)), state.entities,
                           state.version)
        return 1
    targets = found(state, cmd.targets, ctx)
    if not isinstance(cmd.destination, ast.Vec3):
        return teleport.teleport(source, targets, destination_entity=single(state, cmd.destination, ctx),
                                 store=state.entities, version=state.version)
    facing_entity = None if cmd.facing_entity is None else single(state, cmd.facing_entity, ctx)
    return teleport.teleport(source, targets, cmd.destination, rotation_arg=cmd.rotation, facing=cmd.facing,
                             facing_entity=facing_entity, facing_anchor=cmd.facing_anchor or "feet",
                             store=state.entities, version=state.version)


def ride(env, cmd: ast.Ride, ctx: Context) -> int:
    """RideCommand: ``ride TARGET mount VEHICLE`` / ``ride TARGET dismount``; 1 on success."""
    rider = single(env.state, cmd.target, ctx)
    vehicle = single(env.state, cmd.vehicle, ctx) if cmd.action == "mount" else None
    current = relations.vehicle_of(rider)
    if cmd.action == "dismount":
        if current is None:
            raise CommandFailure("commands.ride.not_riding", rider.display_name)
        relations.stop_riding(rider)
        return 1
    if current is not None:
        raise CommandFailure("commands.ride.already_riding", rider.display_name, current.display_name)
    if vehicle.is_player:
        raise CommandFailure("commands.ride.mount.failure.cant_ride_players")
    if vehicle in relations.self_and_passengers(rider):
        raise CommandFailure("commands.ride.mount.failure.loop")
    if not relations.start_riding(rider, vehicle):
        raise CommandFailure("commands.ride.mount.failure.generic", rider.display_name, vehicle.display_name)
    relations.started_riding(env.state, vehicle)
    return 1


def rotate(env, cmd: ast.GenericCommand, ctx: Context) -> int:
    """RotateCommand (1.21.2+): ``rotate TARGET ROTATION | facing POS | facing entity E [eyes|feet]``
    on one entity; the result is 1.

    ``rotate(source, entity, Coordinates)``: the rotation argument against the execution rotation
    (as ``tp``'s), set by Entity.forceSetRotation -> setYRot/setXRot: neither wrapped nor clamped
    (``tp`` wraps and clamps), a non-finite angle discarded. ``rotate(source, entity, LookAt)``:
    LookAt.perform -> Entity.lookAt from the entity's own position and the execution anchor, the
    same turn as ``tp ... facing`` (:func:`emulator.world.teleport.look_at`). A player is turned at
    once (the game sends it a rotation packet its client answers)."""
    state = env.state
    reader = Reader(cmd.text, cmd.loc, tuple(state.version))
    reader.pos = len(cmd.name)
    try:
        reader.skip_ws()
        target_arg = selectors.target(reader, single=True)
        reader.skip_ws()
        if cmd.text.startswith("facing", reader.pos):
            reader.pos += len("facing")
            reader.skip_ws()
            if cmd.text.startswith("entity ", reader.pos):
                reader.pos += len("entity")
                reader.skip_ws()
                facing_arg = selectors.target(reader, single=True)
                reader.skip_ws()
                anchor = reader.word() if reader.more() else "feet"
                rotation_arg = facing_pos = None
            else:
                facing_pos, facing_arg, rotation_arg = vec3(reader), None, None
        else:
            rotation_arg, facing_pos, facing_arg = vec2(reader), None, None
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error.message, report=True) from None
    entity = single(state, target_arg, ctx)
    source = world_source(state, ctx)
    if rotation_arg is not None:
        yaw, pitch = source.rotation_of(rotation_arg)
        teleport.set_rotation(entity, yaw, pitch)
        return 1
    target = source.position_of(facing_pos) if facing_pos is not None else single(state, facing_arg, ctx).anchor(anchor)
    teleport.set_rotation(entity, *teleport.look_at(source, entity.pos, entity, target))
    return 1


HANDLERS = {ast.Summon: summon, ast.Kill: kill, ast.TagCommand: tag, ast.Teleport: tp, ast.Ride: ride}
GENERIC_HANDLERS = {"rotate": rotate}


# ---------------------------------------------------------------------- the API's view
def new_state(shuffle: int | None = None) -> WorldState:
    """A fresh world; with ``shuffle``, unsorted ``@e`` visits entities in a seeded permutation."""
    state = WorldState()
    if shuffle is not None:
        state.entities = ShuffledEntityStore(shuffle_seed=shuffle)
        state.entities.bind_scoreboard(state.scoreboard)
    return state


@lru_cache(maxsize=4096)
def arguments(cmd: ast.GenericCommand) -> tuple[list, object]:
    """The command's words after its name, with an entity argument read as a selector (brackets may
    hold spaces): ``(words, target)``; the target's place in ``words`` holds None."""
    words, target, _ = argument_spans(cmd)
    return words, target


def argument_spans(cmd: ast.GenericCommand) -> tuple[list, object, list[int]]:
    """:func:`arguments`, and where each word starts in ``cmd.text`` (for an argument that may hold
    spaces, such as a quoted string, to be read again from there)."""
    reader = Reader(cmd.text, cmd.loc, (26, 2, 0))
    reader.pos = len(cmd.name)
    words, target, starts = [], None, []
    try:
        reader.skip_ws()
        while reader.more():
            starts.append(reader.pos)
            if reader.peek() == "@" and target is None:
                target = selectors.selector(reader)
                words.append(None)
            else:
                start = reader.pos
                while reader.more() and not reader.peek().isspace():
                    reader.pos += 1
                words.append(cmd.text[start:reader.pos])
            reader.skip_ws()
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error.message, report=True) from None
    return words, target, starts


def target_word(cmd, words: list, index: int, target):
    """The entity argument at ``index`` of :func:`arguments`' words (a selector, name or UUID)."""
    if index >= len(words):
        raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected an entity", report=True)
    return target if words[index] is None else holder_from_word(words[index], cmd.loc)


@lru_cache(maxsize=4096)
def parse_target(text: str):
    """A selector, player name or UUID written as in a command (ValueError when malformed), read
    once per text: a text component's selector is read each time the text is shown, and one node
    keeps its compiled query (:func:`_query`) where a new node each time made another."""
    reader = Reader(text, Loc("<selector>", 1, 1), (1, 21, 0))
    try:
        target = selectors.selector(reader) if text.startswith("@") else holder_from_word(text, reader.loc())
    except ParseError as error:
        raise ValueError(f"bad selector {text!r}: {error.message}") from None
    if isinstance(target, ast.Selector) and reader.pos != len(text):
        raise ValueError(f"bad selector {text!r}: unexpected text {text[reader.pos:]!r}")
    return target


def describe(state: WorldState, entity: Entity) -> dict:
    """What ``Emulator.entities`` and ``dpemu run --json`` show of an entity."""
    board = state.scoreboard
    hid = board.holder_ids.get(entity.score_holder)
    n = len(board.objectives)
    scores = {} if hid is None else {board.objectives[o]: int(board.values[hid, o])
                                     for o in np.flatnonzero(board.present[hid, :n] & board.alive[:n])}
    return {"uuid": entity.uuid_string, "type": entity.type, "name": entity.player_name,
            "tags": sorted(entity.tags), "pos": list(entity.pos),
            "rotation": [float(entity.yaw), float(entity.pitch)], "dimension": entity.dimension, "scores": scores}
