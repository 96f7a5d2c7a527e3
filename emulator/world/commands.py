"""Whole entity commands over the world, from their AST nodes: the glue both backends share.

- ``resolve_entities(target, store, source, **options)``: an entity argument (``entities()``):
  a selector's matches, or the player named / the entity with the UUID; none fails
  "No entity was found".
- ``resolve_entity(target, ...)``: a single-entity argument (``entity()``).
- ``teleport_command(cmd, store, source, **options)``: every ``tp`` form; returns the count.
- ``summon_command(cmd, store, source)``: ``summon TYPE [POS] [NBT]`` at the execution position by
  default (``Passengers`` summoned riding it); returns the new entity.
- ``kill_command(cmd, store, source, **options)``: ``kill [TARGETS]`` (the executor by default);
  entities leave the store, players stay (they respawn); returns the count.
- ``tag_command(cmd, store, source, **options)``: ``tag TARGETS add|remove NAME`` (the number of
  entities changed; none fails with the game's message) and ``tag TARGETS list`` (the tag count).
``options`` are the selector options (``scores``, ``type_tags``) of :func:`selectors.select`.

Source: decompiled 1.21 commands/arguments/EntityArgument.java, server/commands/TeleportCommand.java,
server/commands/SummonCommand.java, java.util.UUID.fromString.
"""
from __future__ import annotations

from mcfunction_parser import ast
from emulator.world import relations, teleport
from emulator.world.entities import Entity, EntityStore, add_tag, remove_tag
from emulator.world.errors import CommandFailure
from emulator.world.selectors import select
from emulator.world.source import Source


def parse_uuid(text: str) -> tuple[int, int, int, int]:
    """``UUID.fromString``: five hex groups, masked to 32/16/16/16/48 bits, as int[4]."""
    groups = [int(g, 16) for g in text.split("-")]
    most = ((groups[0] & 0xFFFFFFFF) << 32) | ((groups[1] & 0xFFFF) << 16) | (groups[2] & 0xFFFF)
    least = ((groups[3] & 0xFFFF) << 48) | (groups[4] & 0xFFFFFFFFFFFF)
    return tuple(((v + 2**31) & 0xFFFFFFFF) - 2**31 for v in (most >> 32, most, least >> 32, least))


def _named(target: ast.NameTarget, store: EntityStore) -> list[Entity]:
    if target.is_uuid:
        found = store.by_uuid(parse_uuid(target.name))
    else:
        found = next((p for p in store.players() if p.player_name == target.name), None)
    return [] if found is None else [found]


def resolve_entities(target, store: EntityStore, source: Source, **options) -> list[Entity]:
    found = select(store, target, source, **options) if isinstance(target, ast.Selector) else _named(target, store)
    if not found:
        raise CommandFailure("argument.entity.notfound.entity")
    return found


def resolve_entity(target, store: EntityStore, source: Source, **options) -> Entity:
    found = resolve_entities(target, store, source, **options)
    if len(found) > 1:
        raise CommandFailure("argument.entity.toomany")
    return found[0]


def teleport_command(cmd: ast.Teleport, store: EntityStore, source: Source, **options) -> int:
    if cmd.targets is None:
        entity = source.entity
        if entity is None:
            raise CommandFailure("permissions.requires.entity")
        if isinstance(cmd.destination, ast.Vec3):
            teleport.apply(entity, teleport.to_position_self(source, cmd.destination))
        else:
            teleport.apply(entity, teleport.to_entity(resolve_entity(cmd.destination, store, source, **options)))
        return 1
    targets = resolve_entities(cmd.targets, store, source, **options)
    if not isinstance(cmd.destination, ast.Vec3):
        destination = resolve_entity(cmd.destination, store, source, **options)
        return teleport.teleport(source, targets, destination_entity=destination)
    facing_entity = None
    if cmd.facing_entity is not None:
        facing_entity = resolve_entity(cmd.facing_entity, store, source, **options)
    return teleport.teleport(source, targets, cmd.destination, rotation_arg=cmd.rotation, facing=cmd.facing,
                             facing_entity=facing_entity, facing_anchor=cmd.facing_anchor or "feet")


def summon_command(cmd: ast.Summon, store: EntityStore, source: Source) -> Entity:
    pos = source.pos if cmd.pos is None else source.position_of(cmd.pos)
    return relations.summon_with_passengers(store, cmd.entity_type, pos, cmd.nbt)


def kill_command(cmd: ast.Kill, store: EntityStore, source: Source, **options) -> int:
    if cmd.targets is None:
        if source.entity is None:
            raise CommandFailure("permissions.requires.entity")
        targets = [source.entity]
    else:
        targets = resolve_entities(cmd.targets, store, source, **options)
    for entity in targets:
        if not entity.is_player and entity.alive:
            store.kill(entity)
    return len(targets)


def tag_command(cmd: ast.TagCommand, store: EntityStore, source: Source, **options) -> int:
    targets = resolve_entities(cmd.targets, store, source, **options)
    if cmd.action == "list":
        return len({tag for entity in targets for tag in entity.tags})
    change = add_tag if cmd.action == "add" else remove_tag
    changed = sum(change(entity, cmd.name) for entity in targets)
    if changed == 0:
        raise CommandFailure("commands.tag.add.failed" if cmd.action == "add" else "commands.tag.remove.failed")
    return changed
