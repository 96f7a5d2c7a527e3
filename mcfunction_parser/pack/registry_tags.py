"""Registry tags other than function tags: ``data/<ns>/tags/<registry>/<path>.json`` for blocks,
items, entity types, fluids, game events, damage types, biomes (``worldgen/biome``) and every other
tag registry.

Rules (minecraft.wiki "Tag"; TagLoader.build / TagLoader.tryBuildTag, decompiled 1.21):
- Folder names: 1.21 (format 48) renamed ``blocks items entity_types fluids game_events`` to the
  singular (TagManager.getTagDir: ``Registries.tagsDirPath``); the other registries were always
  singular. The name the target version does not read is ignored (warned about).
- The game's own tags load first (its built-in data pack), then each pack on top: ``replace``
  drops what came before, otherwise entries append (the same merge as function tags).
- Entries are ids or ``#tags``; a required entry that is missing makes the whole tag fail to load
  (TagLoader logs "Couldn't load tag ... as it is missing following references") and a tag that
  fails does not exist; ``"required": false`` entries are skipped when absent. A plain id is
  checked against the release's registry for the static registries dpemu has (items, blocks,
  entity types: TagEntry.build looks the element up); a pack may add to the others.
- A nested ``#minecraft:`` tag the emulator does not know (no game jar was given) is kept as
  *unknown*: a tag holding one matches its known members and says it is not modelled otherwise.
"""
from __future__ import annotations

from dataclasses import dataclass

from mcfunction_parser.ast import FunctionTag
from mcfunction_parser.diagnostics import ERROR, Diagnostic
from mcfunction_parser.pack.predicate_ids import unknown_id
from mcfunction_parser.pack.text import split_lines
from mcfunction_parser.pack.tags import merge_tag, read_tag_file

# Registries whose tag folder 1.21 renamed from the plural.
RENAMED = {"block": "blocks", "item": "items", "entity_type": "entity_types", "fluid": "fluids",
           "game_event": "game_events"}
_PLURAL = {plural: singular for singular, plural in RENAMED.items()}


@dataclass(frozen=True)
class RegistryTag:
    """A loaded tag, flattened: its member ids and the nested vanilla tags the emulator does not
    know (non-empty only without a game jar)."""

    members: frozenset[str]
    unknown: tuple[str, ...] = ()


def split_tag_path(rest: str) -> tuple[str, str] | None:
    """``block/a/b.json`` -> (``block``, ``a/b``); ``worldgen/biome/x.json`` -> (``worldgen/biome``,
    ``x``): the registry folder and the tag's path. None for function tags and stray files."""
    if not rest.endswith(".json"):
        return None
    parts = rest[: -len(".json")].split("/")
    depth = 2 if parts[0] == "worldgen" else 1
    if len(parts) <= depth:
        return None
    registry = "/".join(parts[:depth])
    if registry in ("function", "functions"):
        return None
    return registry, "/".join(parts[depth:])


def registry_for_folder(folder: str, singular: bool) -> tuple[str, str | None]:
    """(the registry a folder holds, the folder the version reads instead when it ignores this one,
    else None). ``singular``: the version reads the 1.21 names."""
    if folder in _PLURAL:
        return _PLURAL[folder], _PLURAL[folder] if singular else None
    if folder in RENAMED and not singular:
        return folder, RENAMED[folder]
    return folder, None


def read_registry_tag(merged: dict[str, dict[str, FunctionTag]], registry: str, tag_id: str, path, shown: str,
                      sources: dict[str, list[str]], diagnostics: list[Diagnostic]) -> None:
    """One tag file merged on top of what earlier packs gave ``registry``."""
    parsed = read_tag_file(path, shown, diagnostics, kind=f"{registry} tag")
    if parsed is None:
        return
    doc, replace, entries = parsed
    sources[shown] = split_lines(doc.text)
    merge_tag(merged.setdefault(registry, {}), tag_id, replace, entries)


def flatten(merged: dict[str, dict[str, FunctionTag]], known_vanilla: bool, sources: dict[str, list[str]],
            diagnostics: list[Diagnostic], version=None) -> dict[str, dict[str, RegistryTag]]:
    """Every tag of every registry flattened; tags the game refuses to load are left out, with an
    error at the entry that breaks them. ``known_vanilla``: the game's own tags were loaded (a
    missing ``#minecraft:`` tag is then missing, not unknown). ``version``: the release whose registries the plain ids are checked
    against (None: not checked)."""
    out: dict[str, dict[str, RegistryTag]] = {}
    for registry, tags in merged.items():
        resolved: dict[str, RegistryTag | None] = {}
        for tag_id in tags:
            _resolve(registry, tags, tag_id, resolved, [], known_vanilla, sources, diagnostics, version)
        out[registry] = {tag_id: tag for tag_id, tag in resolved.items() if tag is not None}
    return out


def _resolve(registry: str, tags: dict[str, FunctionTag], tag_id: str, resolved: dict, trail: list[str],
             known_vanilla: bool, sources, diagnostics, version=None) -> RegistryTag | None:
    if tag_id in resolved:
        return resolved[tag_id]
    if tag_id in trail:
        return None
    members: dict[str, None] = {}
    unknown: list[str] = []
    failure = None
    for entry in tags[tag_id].entries:
        if not entry.is_tag:
            if _missing(registry, entry.id, version):
                if not entry.required:
                    continue
                failure = (entry, f"{entry.id} is not in the {registry} registry of this release")
                break
            members.setdefault(entry.id, None)
            continue
        if entry.id in trail or entry.id == tag_id:
            failure = (entry, "circular reference " + " -> ".join(f"#{t}" for t in [*trail, tag_id, entry.id]))
            break
        if entry.id not in tags:
            if not known_vanilla and entry.id.startswith("minecraft:"):
                unknown.append(entry.id)
            elif entry.required:
                failure = (entry, f"#{entry.id} does not exist")
                break
            continue
        nested = _resolve(registry, tags, entry.id, resolved, [*trail, tag_id], known_vanilla, sources, diagnostics,
                          version)
        if nested is None:
            if entry.required:
                failure = (entry, f"it includes #{entry.id}, which fails to load")
                break
            continue
        members.update(dict.fromkeys(nested.members))
        unknown.extend(nested.unknown)
    if failure is not None:
        entry, reason = failure
        lines = sources.get(entry.loc.path, [])
        line = lines[entry.loc.line - 1] if entry.loc.line <= len(lines) else None
        diagnostics.append(Diagnostic.at(ERROR, f"{registry} tag #{tag_id} fails to load: {reason}", entry.loc, line))
        resolved[tag_id] = None
        return None
    tag = resolved[tag_id] = RegistryTag(frozenset(members), tuple(dict.fromkeys(unknown)))
    return tag


def _missing(registry: str, entry_id: str, version) -> bool:
    return version is not None and registry in ("item", "block", "entity_type") and \
        unknown_id(registry, entry_id, version) is not None
