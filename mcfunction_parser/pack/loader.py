"""Loading data packs: pack.mcmeta, overlays, functions, function tags, registry tags (with the
game's own from its jar, :mod:`mcfunction_parser.gamedata`), predicates and advancements.

Several packs load together in order; a later pack overrides an earlier pack's function of the
same id and its tag files merge on top (``replace`` honoured). All packs are read for one game
version: ``mc_version`` when given, else the newest release any pack is written for (its
``pack_format``, or its ``max_format`` when it has no ``pack_format``). That version's format
decides the folder names (``function`` from 1.21, ``functions`` before; the other name is
ignored by the game, and warned about here), which overlays apply (1.20.2+) and whether
``filter.block`` hides earlier packs' files (1.19+). A pack is a folder or a .zip file.

Nothing here raises on bad input: every problem is a :class:`Diagnostic`, and a problem in one
file never stops the others.
"""
from __future__ import annotations

import re
import sys
import zipfile
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from mcfunction_parser.ast import Function, FunctionTag, TagEntry
from mcfunction_parser.diagnostics import ERROR, INFO, WARNING, Diagnostic, Loc
from mcfunction_parser.pack.meta import ANY_MINOR, FormatRange, PackMeta, read_pack_meta
from mcfunction_parser.pack.parallel import FunctionFile, parse_files
from mcfunction_parser.pack import loot
from mcfunction_parser.pack import dimensions as dimension_files
from mcfunction_parser.pack import enchantments as enchantment_files
from mcfunction_parser.pack import recipes as recipe_files
from mcfunction_parser.pack.text import JsonDocument, PackPath, load_json, read_text, split_lines
from mcfunction_parser import gamedata
from mcfunction_parser.gamedata import game_jars
from mcfunction_parser.gamedata.vanilla_tags import BUILTIN_TAGS, GameJarError, open_game_jar
from mcfunction_parser.pack import advancements, clocks, conditions, registry_tags, test_environments
from mcfunction_parser.pack.registry_tags import RegistryTag
from mcfunction_parser.pack.tags import FailedTag, merge_tag, normalise_id, read_tag_file, resolve_tag, validate_tags
from mcfunction_parser.pack.versions import (
    FILTER_FORMAT, LATEST_RELEASE, OVERLAYS_FORMAT, SINGULAR_FOLDERS_FORMAT, Format, Version, format_label,
    newer_than_known, pack_format_for_version, parse_mc_version, uses_singular_folders, version_for_pack_format,
    version_label,
)

_NAMESPACE = re.compile(r"[a-z0-9_.-]+")
_PATH = re.compile(r"[a-z0-9_./-]+")


@dataclass
class PackInfo:
    """One loaded pack. ``supported`` is None when pack.mcmeta is missing or invalid."""

    root: Path  # the folder or .zip file
    pack_format: int | None
    supported: FormatRange | None
    description: str
    overlays: list[str]  # overlay directories applied, in order
    folder_style: str  # "function" (1.21+) or "functions"


@dataclass
class LoadedPacks:
    packs: list[PackInfo]
    version: Version  # the game version the functions were parsed for
    functions: dict[str, Function]  # "ns:path" -> parsed function (macro lines kept as MacroLine)
    tags: dict[str, FunctionTag]  # "ns:path" -> merged tag, nested tags not flattened
    sources: dict[str, list[str]]  # file path -> lines (functions and tag files)
    diagnostics: list[Diagnostic]
    failed_tags: dict[str, FailedTag] = field(default_factory=dict)  # tags the game refuses to load
    advancement_rewards: dict[str, list[Loc]] = field(default_factory=dict)  # function -> where named
    # the loot tables and recipes advancement rewards name: id -> where named
    advancement_loot: dict[str, list[Loc]] = field(default_factory=dict)
    advancement_recipes: dict[str, list[Loc]] = field(default_factory=dict)
    recipes: dict[str, str] = field(default_factory=dict)  # id -> its type (the jar's, then the packs')
    recipe_bodies: dict[str, Any] = field(default_factory=dict)  # id -> its JSON, the recipes that decode
    predicates: dict[str, Any] = field(default_factory=dict)  # id -> its JSON (files that load)
    test_environments: dict[str, Any] = field(default_factory=dict)  # id -> its JSON (1.21.5+, files that load)
    advancements: dict[str, Any] = field(default_factory=dict)  # id -> its JSON (files that load)
    dimensions: dict[str, Any] = field(default_factory=dict)  # data/<ns>/dimension: id -> its JSON
    dimension_types: dict[str, Any] = field(default_factory=dict)  # data/<ns>/dimension_type: id -> its JSON
    enchantments: dict[str, Any] = field(default_factory=dict)  # data/<ns>/enchantment (1.21+): id -> its JSON
    # registry -> tag id -> flattened tag: the game's own (from a game jar) merged under the packs'
    registry_tags: dict[str, dict[str, RegistryTag]] = field(default_factory=dict)
    vanilla_data: bool = False  # the game's own tags and loot tables were read from its jar
    game_jar: str | None = None  # the jar they were read from (a reload reads it again)
    loot_tables: dict[str, JsonDocument] = field(default_factory=dict)  # id -> its file (checked: pack.loot)
    clocks: clocks.Clocks | None = None  # 26.1+: the world clocks and timelines (the game's and the packs')
    item_modifiers: dict[str, JsonDocument] = field(default_factory=dict)
    files: int = 0  # files read: pack.mcmeta, functions, tags, advancements
    # functions the game refuses whole because a line does not parse (ServerFunctionLibrary logs
    # "Failed to load function" and leaves it out): parsed for ``dpemu check``, absent from
    # ``functions``, so calling one fails as an unknown function and a tag requiring one fails
    refused: dict[str, Function] = field(default_factory=dict)
    # functions made beside the files (a test runner's test functions): a reload keeps them
    added_functions: dict[str, Function] = field(default_factory=dict)

    def add_functions(self, functions: dict[str, Function]) -> None:
        self.functions.update(functions)
        self.added_functions.update(functions)

    @property
    def format(self) -> Format:
        return pack_format_for_version(self.version)

    def read_file(self, name: str) -> bytes | None:
        """The bytes of ``name`` (a path inside a pack, e.g. ``data/ns/structure/x.nbt``) from the
        last pack that has it, as the game's resource manager stacks packs; None when none has it."""
        for pack in reversed(self.packs):
            if pack.root.is_dir():
                candidate = pack.root / name
                if candidate.is_file():
                    return candidate.read_bytes()
            elif zipfile.is_zipfile(pack.root):
                with zipfile.ZipFile(pack.root) as archive:
                    if name in archive.namelist():
                        return archive.read(name)
        return None

    def resolve_tag(self, tag_id: str) -> list[str]:
        """Function ids run by ``#tag_id``: flattened, ordered, deduplicated."""
        return resolve_tag(self.tags, self.functions, tag_id)

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == ERROR]

    @property
    def warnings(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == WARNING]

    @property
    def infos(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == INFO]


@dataclass
class _PackFiles:
    """One pack's files after overlays: path relative to the pack -> the file providing it, and
    that file's own path inside the pack (``overlay/data/...`` when an overlay provides it)."""

    info: PackInfo
    shown_root: str
    files: dict[str, tuple[PackPath, str]]
    target_label: str  # "1.21.4 (format 61)"

    def shown(self, rel: str) -> str:
        """How a path relative to the pack root appears in diagnostics."""
        return rel if self.shown_root in ("", ".") else f"{self.shown_root.rstrip('/')}/{rel}"

    def shown_file(self, rel: str) -> str:
        """The shown path of the file providing ``rel`` (inside its overlay, if any)."""
        return self.shown(self.files[rel][1])

    def read(self, rel: str) -> PackPath:
        return self.files[rel][0]


def load_packs(paths: Sequence[str | Path], mc_version: str | None = None, workers: int | None = None,
               on_function=None, game_jar: str | Path | None = None) -> LoadedPacks:
    """Load packs (folders or .zip files) in order; later ones override. ``mc_version``
    ("1.21.4") overrides the packs' own version; an unknown or malformed one raises ValueError.
    ``workers``: processes parsing functions beside this one (0: none; None: one per other core
    when there are many lines; see pack.parallel), the result the same either way.
    ``on_function(done, total)`` hears each function file parsed (a progress bar). ``game_jar``: the
    game's jar, whose vanilla tags load under the packs' (an unreadable one raises GameJarError)."""
    diagnostics: list[Diagnostic] = []
    opened = [(Path(p), str(p), _open_pack(Path(p), str(p), diagnostics)) for p in paths]
    opened = [(path, shown, root) for path, shown, root in opened if root is not None]
    metas = [read_pack_meta(root, shown, diagnostics) for _, shown, root in opened]
    version = _target_version(mc_version, [m for m in metas if m is not None])
    target = pack_format_for_version(version)
    metas_read = sum((root / "pack.mcmeta").is_file() for _, _, root in opened)
    result = LoadedPacks([], version, {}, {}, {}, diagnostics, files=metas_read)
    diagnostics.extend(Diagnostic(ERROR, why.removeprefix(path + ": "), path)
                       for path, why in gamedata.unreadable_reports(version))
    packs = [_collect(path, root, shown, meta, target, version, diagnostics)
             for (path, shown, root), meta in zip(opened, metas)]
    result.packs = [p.info for p in packs]
    if target >= FILTER_FORMAT:
        _apply_filters(packs, metas)
    jar = _open_jar(game_jar, version, diagnostics)
    result.vanilla_data = jar is not None
    result.game_jar = jar[1] if jar is not None else None
    _load_functions(packs, result, workers, on_function)
    _load_tags(packs, result)
    _load_registry_tags(packs, result, jar)
    _load_predicates(packs, result)
    _load_test_environments(packs, result)
    _load_advancements(packs, result)
    _load_loot(packs, result, jar)
    _load_recipes(packs, result, jar)
    _load_dimensions(packs, result)
    _load_enchantments(packs, result)
    _load_clocks(packs, result)
    return result


def _open_jar(game_jar: str | Path | None, version, diagnostics: list[Diagnostic]):
    """The game jar's data root and name; ``auto`` finds or downloads the release's jar
    (:mod:`mcfunction_parser.gamedata.game_jars`), an error when it cannot, the packs loading
    without it. A jar named by path that cannot be read raises GameJarError."""
    if game_jar is None:
        return None
    try:
        path = game_jars.resolve(game_jar, version, lambda note: _note(note, diagnostics))
        return open_game_jar(path), str(path)
    except GameJarError as error:
        if str(game_jar) != game_jars.AUTO:
            raise
        diagnostics.append(Diagnostic(ERROR, f"{error}; the packs load without the game's data", "--game-jar"))
    return None


def _note(note: str, diagnostics: list[Diagnostic]) -> None:
    """A step worth seeing as it happens (a download): on stderr, and kept as an info diagnostic."""
    print(note, file=sys.stderr, flush=True)
    diagnostics.append(Diagnostic(INFO, note, "--game-jar"))


def _open_pack(path: Path, shown: str, diagnostics: list[Diagnostic]) -> PackPath | None:
    """The pack's root: the folder itself, or the inside of a .zip file (as the game accepts)."""
    if path.is_dir():
        return path
    problem = zip_problem(path) if path.is_file() else "does not exist"
    if problem is None:
        return zipfile.Path(path)
    diagnostics.append(Diagnostic(ERROR, f"pack {problem}", shown))
    return None


def zip_problem(path: Path) -> str | None:
    """Why the file ``path`` cannot be read as a .zip pack, or None when it can."""
    if not zipfile.is_zipfile(path):
        return "is a corrupt .zip archive" if path.suffix.lower() == ".zip" else "is not a folder or a .zip file"
    try:
        with zipfile.ZipFile(path):  # reads the central directory; a damaged member fails when read
            pass
    except (zipfile.BadZipFile, OSError) as error:
        return f"is a corrupt .zip archive ({error})"
    return None


def _target_version(mc_version: str | None, metas: list[PackMeta]) -> Version:
    if mc_version is not None:
        version = parse_mc_version(mc_version)
        pack_format_for_version(version)  # raises ValueError for an unknown release
        return version
    wanted = [version_for_pack_format(_written_for(m)) for m in metas if m.supported is not None]
    return max(wanted, default=LATEST_RELEASE)


def _written_for(meta: PackMeta) -> Format:
    """The format the pack is written for: its ``pack_format``, unless that lies outside the
    formats it declares it supports (``pack_format: 107`` beside ``min_format: [107, 1]``), where
    the newest of those decides."""
    written = (meta.pack_format, 0) if meta.pack_format is not None else None
    return written if written is not None and written in meta.supported else meta.supported.max


def _collect(path: Path, root: PackPath, shown: str, meta: PackMeta | None, target: Format,
             version: Version, diagnostics: list[Diagnostic]) -> _PackFiles:
    """The pack's data files with the matching overlays laid over the base."""
    label = f"{version_label(version)} (format {format_label(target)})"
    if (meta is not None and meta.supported is not None and newer_than_known(meta.supported.min)
            and version == LATEST_RELEASE):  # (else --mc chose an older release: incompatible, below)
        diagnostics.append(Diagnostic(
            WARNING, f"pack format {format_label(meta.supported.min)} is newer than every release dpemu knows: "
            f"it runs as the newest, {label}", f"{shown.rstrip('/')}/pack.mcmeta"))
    elif meta is not None and meta.supported is not None and target not in meta.supported:
        diagnostics.append(Diagnostic(
            WARNING, f"pack supports formats {_range_label(meta.supported)}, not {label}: the game "
            "lists it as incompatible", f"{shown.rstrip('/')}/pack.mcmeta"))
    files = _data_files(root, "")
    applied = []
    for overlay in meta.overlays if meta is not None and target >= OVERLAYS_FORMAT else []:
        if target in overlay.formats:
            files.update(_data_files(root / overlay.directory, f"{overlay.directory}/"))
            applied.append(overlay.directory)
    style = "function" if uses_singular_folders(target) else "functions"
    info = PackInfo(path, meta.pack_format if meta else None, meta.supported if meta else None,
                    meta.description if meta else "", applied, style)
    return _PackFiles(info, shown, files, label)


def _apply_filters(packs: list[_PackFiles], metas: list[PackMeta | None]) -> None:
    """Each pack's ``filter.block`` hides matching files of the packs loaded before it."""
    for index, meta in enumerate(metas):
        if meta is None or meta.block is None:
            continue
        for earlier in packs[:index]:
            for rel in [r for r in earlier.files if meta.block.blocks(*r.split("/", 2)[1:])]:
                del earlier.files[rel]


def _range_label(formats: FormatRange) -> str:
    lo = format_label(formats.min)
    hi = str(formats.max[0]) if formats.max[1] == ANY_MINOR else format_label(formats.max)
    return lo if lo == hi else f"{lo}-{hi}"


def _data_files(base: PackPath, prefix: str) -> dict[str, tuple[PackPath, str]]:
    """``data/**`` files under ``base`` (the pack root or an overlay folder), keyed by path
    relative to ``base``, with their path inside the pack (``prefix`` + key)."""
    if isinstance(base, zipfile.Path):
        return _zip_data_files(base, prefix)
    found: dict[str, tuple[PackPath, str]] = {}
    stack = [(base / "data", "data")]
    seen: set[Path] = set()  # folders already walked: a symbolic link loop is walked once
    while stack:
        folder, rel = stack.pop()
        if not folder.is_dir():
            continue
        if isinstance(folder, Path):
            if folder.resolve() in seen:
                continue
            seen.add(folder.resolve())
        for child in folder.iterdir():
            child_rel = f"{rel}/{child.name}"
            if child.is_dir():
                stack.append((child, child_rel))
            elif child.is_file():
                found[child_rel] = (child, prefix + child_rel)
    return dict(sorted(found.items()))


def _zip_data_files(base: zipfile.Path, prefix: str) -> dict[str, tuple[PackPath, str]]:
    """:func:`_data_files` inside a .zip: one pass over the archive's names (walking its folders
    with zipfile.Path would list the whole archive once per folder)."""
    start = base.at + "data/"
    found = {name[len(base.at):]: (zipfile.Path(base.root, name), prefix + name[len(base.at):])
             for name in base.root.namelist() if name.startswith(start) and not name.endswith("/")}
    return dict(sorted(found.items()))


# ----------------------------------------------------------------------------- resources


def _resources(pack: _PackFiles, folders: tuple[str, str], suffix: str,
               diagnostics: list[Diagnostic]) -> dict[str, str]:
    """``{resource id: relative file}`` for files in ``data/<ns>/<folder>/`` ending in ``suffix``.

    ``folders`` is (1.21+ name, older name); files in the name the game ignores are warned about
    once per folder and skipped; invalid names are warned about and skipped, as the game does.
    """
    read, ignored = folders if pack.info.folder_style == "function" else folders[::-1]
    depth = read.count("/") + 1  # path segments of the folder name
    found: dict[str, str] = {}
    ignored_count: dict[str, int] = {}  # "data/<ns>" -> files in its ignored folder
    for rel in pack.files:
        parts = rel.split("/")
        if len(parts) < 3 + depth or not rel.endswith(suffix):
            continue
        folder = "/".join(parts[2:2 + depth])
        if folder == read:  # a folder the rename did not touch has one name in both
            path = "/".join(parts[2 + depth:])[: -len(suffix)]
            resource_id = _resource_id(parts[1], path, pack.shown_file(rel), diagnostics)
            if resource_id is not None:
                found[resource_id] = rel
        elif folder == ignored:
            ns_dir = f"data/{parts[1]}"
            ignored_count[ns_dir] = ignored_count.get(ns_dir, 0) + 1
    # A pack declaring formats on both sides of the rename keeps both folders on purpose.
    spans = pack.info.supported is not None and pack.info.supported.min < SINGULAR_FOLDERS_FORMAT \
        <= pack.info.supported.max
    for ns_dir, count in ignored_count.items():
        diagnostics.append(Diagnostic(
            INFO if spans else WARNING, f"{count} file(s) in '{ns_dir}/{ignored}/' ignored: "
            f"{pack.target_label} reads '{ns_dir}/{read}/' instead", pack.shown(f"{ns_dir}/{ignored}")))
    return found


def _resource_id(namespace: str, path: str, shown: str, diagnostics: list[Diagnostic]) -> str | None:
    if _NAMESPACE.fullmatch(namespace) and _PATH.fullmatch(path):
        return f"{namespace}:{path}"
    diagnostics.append(Diagnostic(
        WARNING, f"ignored by the game: invalid resource location '{namespace}:{path}' "
        "(allowed: a-z 0-9 _ . - and / in paths)", shown))
    return None


def _load_functions(packs: list[_PackFiles], result: LoadedPacks, workers: int | None, on_function=None) -> None:
    chosen: dict[str, tuple[_PackFiles, str]] = {}
    for pack in packs:
        for fid, rel in _resources(pack, ("function", "functions"), ".mcfunction",
                                   result.diagnostics).items():
            if fid in chosen:
                earlier = chosen[fid][0].shown_file(chosen[fid][1])
                result.diagnostics.append(Diagnostic(
                    INFO, f"function {fid} overrides {earlier} from an earlier pack",
                    pack.shown_file(rel)))
            chosen[fid] = (pack, rel)
    files = [_read_function(pack, rel, fid, result) for fid, (pack, rel) in chosen.items()]
    readable = [file for file, _ in files if file is not None]
    parsed = iter(parse_files(readable, result.version, workers))
    done = 0
    for file, read_problems in files:
        result.diagnostics.extend(read_problems)
        if file is None:
            continue
        function, diagnostics = next(parsed)
        done += 1
        if on_function is not None:
            on_function(done, len(readable))
        result.diagnostics.extend(diagnostics)
        if function is not None:
            parses = not any(d.severity == ERROR for d in diagnostics)  # else the game refuses it
            (result.functions if parses else result.refused)[function.id] = function


def _read_function(pack: _PackFiles, rel: str, fid: str,
                   result: LoadedPacks) -> tuple[FunctionFile | None, list[Diagnostic]]:
    """The file to parse (None when it cannot be read) and the problems reading it; its lines
    are kept in ``result.sources``."""
    shown = pack.shown_file(rel)
    problems: list[Diagnostic] = []
    text = read_text(pack.read(rel), shown, problems, json_file=False)
    result.files += 1
    if text is None:
        return None, problems
    lines = result.sources[shown] = split_lines(text)  # the game's lines (a lone \r ends one too)
    return (lines, shown, fid, str(pack.info.root)), problems


def _load_tags(packs: list[_PackFiles], result: LoadedPacks) -> None:
    for pack in packs:
        for tag_id, rel in _resources(pack, ("tags/function", "tags/functions"), ".json",
                                      result.diagnostics).items():
            shown = pack.shown_file(rel)
            result.files += 1
            parsed = read_tag_file(pack.read(rel), shown, result.diagnostics)
            if parsed is None:
                continue
            doc, replace, entries = parsed
            result.sources[shown] = split_lines(doc.text)
            merge_tag(result.tags, tag_id, replace, entries)
    result.failed_tags = validate_tags(result.tags, result.functions, result.sources,
                                       result.diagnostics, result.refused)


def _load_loot(packs: list[_PackFiles], result: LoadedPacks, jar) -> None:
    """Loot tables and item modifiers (a later pack's file replaces an earlier one), each checked
    (:mod:`mcfunction_parser.pack.loot`); one the game does not load is left out. The game's own
    tables (``jar``: its root and name) come first, as its built-in data pack does, read as the
    game ships them (not checked)."""
    if jar is not None:
        root, name = jar
        for path in _jar_files(root, ("loot_table", "loot_tables")):
            _, namespace, _, rest = path.at.split("/", 3)
            doc = load_json(path, f"{name}!/{path.at}", result.diagnostics)
            if doc is not None:
                result.loot_tables[f"{namespace}:{rest[:-len('.json')]}"] = doc
    for folders, found, check in ((("loot_table", "loot_tables"), result.loot_tables, loot.check_loot_table),
                                  (("item_modifier", "item_modifiers"), result.item_modifiers, loot.check_modifier)):
        for rid, doc in _chosen_json(packs, folders, result):
            if check(doc, result.version, result.diagnostics):
                found[rid] = doc


def _load_registry_tags(packs: list[_PackFiles], result: LoadedPacks, jar) -> None:
    """Every registry's tags: the game's own first (``jar``: its root and name), then each pack on top."""
    merged: dict[str, dict[str, FunctionTag]] = {}
    singular = uses_singular_folders(result.format)
    if jar is not None:
        root, game_jar = jar
        for path in _jar_files(root, ("tags",)):
            parts = path.at.split("/", 3)  # data/<ns>/tags/<rest>
            split = registry_tags.split_tag_path(parts[3])
            if split is None:
                continue
            registry = registry_tags.registry_for_folder(split[0], True)[0]  # the jar's own names
            registry_tags.read_registry_tag(merged, registry, f"{parts[1]}:{split[1]}", path,
                                            f"{game_jar}!/{path.at}", {}, result.diagnostics)
    else:  # the few vanilla tags the emulator knows without the game's data: the newest release's
        # members, optional so that an older release's registry leaves out the ones it lacks
        for registry, tags in BUILTIN_TAGS.items():
            for tag_id, members in tags.items():
                entries = [TagEntry(member, False, False, Loc("<built-in>", 1, 1)) for member in sorted(members)]
                merge_tag(merged.setdefault(registry, {}), tag_id, False, entries)
    for pack in packs:
        ignored_count: dict[str, tuple[int, str]] = {}
        for rel in pack.files:
            parts = rel.split("/", 3)
            if len(parts) < 4 or parts[2] != "tags":
                continue
            split = registry_tags.split_tag_path(parts[3])
            if split is None:
                continue
            folder, path = split
            registry, instead = registry_tags.registry_for_folder(folder, singular)
            if instead is not None:
                key = f"data/{parts[1]}/tags/{folder}"
                ignored_count[key] = (ignored_count.get(key, (0, ""))[0] + 1, f"data/{parts[1]}/tags/{instead}")
                continue
            tag_id = _resource_id(parts[1], path, pack.shown_file(rel), result.diagnostics)
            if tag_id is not None:
                result.files += 1
                registry_tags.read_registry_tag(merged, registry, tag_id, pack.read(rel), pack.shown_file(rel),
                                                result.sources, result.diagnostics)
        for folder, (count, instead) in ignored_count.items():
            result.diagnostics.append(Diagnostic(
                WARNING, f"{count} file(s) in '{folder}/' ignored: {pack.target_label} reads '{instead}/' instead",
                pack.shown(folder)))
    result.registry_tags = registry_tags.flatten(merged, result.vanilla_data, result.sources, result.diagnostics,
                                                  result.version)


def _jar_files(root, folders: tuple[str, ...]):
    """The jar's JSON files under ``data/<ns>/<folder>/`` for one of ``folders``, in name order."""
    archive = root.root
    return [zipfile.Path(archive, name) for name in sorted(archive.namelist())
            if name.startswith("data/") and name.endswith(".json") and name.count("/") >= 3
            and name.split("/")[2] in folders]


def _chosen_json(packs: list[_PackFiles], folders: tuple[str, str], result: LoadedPacks):
    """``(id, document)`` of each JSON resource in ``folders`` (a later pack's file of the same id
    replaces an earlier one); invalid JSON is an error with its line and column, and left out."""
    chosen: dict[str, tuple[_PackFiles, str]] = {}
    for pack in packs:
        for resource_id, rel in _resources(pack, folders, ".json", result.diagnostics).items():
            chosen[resource_id] = (pack, rel)
    for resource_id, (pack, rel) in chosen.items():
        result.files += 1
        doc = load_json(pack.read(rel), pack.shown_file(rel), result.diagnostics)
        if doc is not None:
            result.sources[doc.path] = split_lines(doc.text)
            yield resource_id, doc


def _load_predicates(packs: list[_PackFiles], result: LoadedPacks) -> None:
    """Predicate files the game loads; one it refuses (unknown condition type, missing field) is an
    error and does not exist at run time, as in the game."""
    for predicate_id, doc in _chosen_json(packs, ("predicate", "predicates"), result):
        if conditions.validate(doc, result.version, f"predicate {predicate_id}", result.diagnostics):
            result.predicates[predicate_id] = doc.value


def _load_test_environments(packs: list[_PackFiles], result: LoadedPacks) -> None:
    """Test environment files (1.21.5+); one the game refuses is an error and does not exist."""
    if result.version < test_environments.SINCE:
        return
    for environment_id, doc in _chosen_json(packs, ("test_environment", "test_environment"), result):
        if test_environments.validate(doc, result.version, f"test environment {environment_id}", result.diagnostics):
            result.test_environments[environment_id] = doc.value


def _load_dimensions(packs: list[_PackFiles], result: LoadedPacks) -> None:
    """The packs' dimension types, then dimensions (worldgen registries: only what the emulator
    reads of them, the ids and the types' coordinate scale, checked by :mod:`.dimensions`; a file
    that fails is left out)."""
    for type_id, doc in _chosen_json(packs, ("dimension_type", "dimension_type"), result):
        if dimension_files.check_dimension_type(doc, f"dimension type {type_id}", result.diagnostics):
            result.dimension_types[type_id] = doc.value
    for dimension_id, doc in _chosen_json(packs, ("dimension", "dimension"), result):
        if dimension_files.check_dimension(doc, f"dimension {dimension_id}", result.dimension_types,
                                           result.diagnostics):
            result.dimensions[dimension_id] = doc.value


def _load_enchantments(packs: list[_PackFiles], result: LoadedPacks) -> None:
    """From 1.21, the packs' enchantment definitions (checked by :mod:`.enchantments`; a file that
    fails is left out)."""
    if result.version < enchantment_files.DATA_DRIVEN:
        return
    for enchantment_id, doc in _chosen_json(packs, ("enchantment", "enchantment"), result):
        if enchantment_files.check_enchantment(doc, f"enchantment {enchantment_id}", result.version, result.diagnostics):
            result.enchantments[enchantment_id] = doc.value


def _load_clocks(packs: list[_PackFiles], result: LoadedPacks) -> None:
    """From 26.1, the world clocks and timelines; a function naming one that no registry holds
    does not load (see pack.clocks)."""
    if result.version < clocks.WORLD_CLOCKS:
        return
    clock_ids = []
    for clock_id, doc in _chosen_json(packs, ("world_clock", "world_clock"), result):
        if isinstance(doc.value, dict):
            clock_ids.append(clock_id)
        else:
            result.diagnostics.append(doc.diagnostic(ERROR, "world clock: expected a JSON object", -1))
    timelines = list(_chosen_json(packs, ("timeline", "timeline"), result))
    result.clocks = clocks.read_clocks(clock_ids, timelines, result.diagnostics)
    for function_id, function in list(result.functions.items()):
        problems = clocks.unknown_references(function, result.clocks, result.sources.get(function.path, []))
        if problems:
            result.diagnostics.extend(problems)
            result.refused[function_id] = result.functions.pop(function_id)


def _load_advancements(packs: list[_PackFiles], result: LoadedPacks) -> None:
    """Advancements the game loads (their criteria checked by :mod:`.advancements`), and what their
    rewards name: the ``function`` (reachable), the ``loot`` tables and ``recipes``."""
    for advancement_id, doc in _chosen_json(packs, ("advancement", "advancements"), result):
        if not advancements.validate(doc, result.version, f"advancement {advancement_id}", result.diagnostics):
            continue
        result.advancements[advancement_id] = doc.value
        rewards = doc.value.get("rewards")
        rewards = rewards if isinstance(rewards, dict) else {}
        after = doc.find_string("rewards")
        for key, named in (("function", result.advancement_rewards), ("loot", result.advancement_loot),
                           ("recipes", result.advancement_recipes)):
            ids = [rewards.get(key)] if key == "function" else rewards.get(key)
            for reward in ids if isinstance(ids, list) else ():
                if isinstance(reward, str):
                    loc = doc.loc_at(max(doc.find_string(reward, after), 0))
                    named.setdefault(normalise_id(reward), []).append(loc)


def _load_recipes(packs: list[_PackFiles], result: LoadedPacks, jar) -> None:
    """Recipes (``data/<ns>/recipe``, ``recipes`` before 1.21): the game's own from its jar first,
    then the packs' (a later pack's file replaces an earlier one). A recipe that does not decode
    (:func:`mcfunction_parser.pack.recipes.check_recipe`) is refused, as RecipeManager skips it:
    it does not exist (``recipe give`` fails on it, it crafts nothing)."""
    if jar is not None:
        root, name = jar
        for path in _jar_files(root, ("recipe", "recipes")):
            _, namespace, _, rest = path.at.split("/", 3)
            doc = load_json(path, f"{name}!/{path.at}", result.diagnostics)
            if doc is not None and isinstance(doc.value, dict):
                recipe_id = f"{namespace}:{rest[:-len('.json')]}"
                result.recipes[recipe_id] = normalise_id(str(doc.value.get("type", "")))
                result.recipe_bodies[recipe_id] = doc.value
    for recipe_id, doc in _chosen_json(packs, ("recipe", "recipes"), result):
        kind = doc.value.get("type") if isinstance(doc.value, dict) else None
        if not isinstance(kind, str):
            result.diagnostics.append(doc.diagnostic(ERROR, f"recipe {recipe_id}: missing the string 'type'", 0))
            continue
        result.recipes.pop(recipe_id, None)  # a pack's file replaces the jar's, even one that fails
        result.recipe_bodies.pop(recipe_id, None)
        if recipe_files.check_recipe(doc, result.version, recipe_id, result.diagnostics):
            result.recipes[recipe_id] = normalise_id(kind)
            result.recipe_bodies[recipe_id] = doc.value
