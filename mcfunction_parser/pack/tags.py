"""Function tags: reading tag files, merging them across packs, validating and flattening them.

Rules (minecraft.wiki "Tag", JSON format):
- ``values`` holds ``"ns:f"``, ``"#ns:tag"`` or ``{"id": ..., "required": false}``;
  ``required`` defaults to true: "whether or not loading this tag should fail if this entry is
  not found". A tag that fails to load does not exist for the game.
- ``replace: true`` drops the entries of lower-priority (earlier) packs; otherwise entries append.
- Nested tags are allowed, "a circular reference causes a loading failure".
- Flattening keeps the first occurrence of each function, in order (the game collects members
  into an insertion-ordered set).
"""
from __future__ import annotations

import re
from collections.abc import Collection
from dataclasses import dataclass
from typing import Any

from mcfunction_parser.ast import FunctionTag, TagEntry
from mcfunction_parser.diagnostics import ERROR, Diagnostic, Loc
from mcfunction_parser.pack.text import JsonDocument, PackPath, load_json

# ResourceLocation.read: either part may be empty (isValidNamespace and isValidPath find no
# character to refuse in ""; an empty namespace is minecraft's)
_RESOURCE_LOCATION = re.compile(r"(?:[a-z0-9_.-]*:)?[a-z0-9_./-]*")


@dataclass
class FailedTag:
    """A tag the game refuses to load: its merged entries and the first reason."""

    tag: FunctionTag
    reason: str


def normalise_id(text: str) -> str:
    """``foo`` and ``:foo`` -> ``minecraft:foo``; a namespaced id is unchanged."""
    if ":" not in text:
        return f"minecraft:{text}"
    return f"minecraft{text}" if text.startswith(":") else text


def read_tag_file(path: PackPath, shown: str, diagnostics: list[Diagnostic], kind: str = "function tag"
                  ) -> tuple[JsonDocument, bool, list[TagEntry]] | None:
    """Parse one tag file: (document, replace flag, entries); None if unusable (diagnosed).
    ``kind`` names the tag in every message (``invalid function tag: ...``, ``invalid item tag:
    ...``)."""
    doc = load_json(path, shown, diagnostics)
    if doc is None:
        return None
    root = doc.value
    if not isinstance(root, dict) or not isinstance(root.get("values"), list):
        diagnostics.append(doc.diagnostic(
            ERROR, f'invalid {kind}: expected an object with a "values" list',
            doc.find_string("values")))
        return None
    replace = root.get("replace", False)
    if not isinstance(replace, bool):
        diagnostics.append(doc.diagnostic(ERROR, f'invalid {kind}: "replace" must be true or false',
                                          doc.find_string("replace")))
        return None
    entries = _entries(root["values"], doc, diagnostics, kind)
    return (doc, replace, entries) if entries is not None else None


def _entries(values: list[Any], doc: JsonDocument, diagnostics: list[Diagnostic], kind: str) -> list[TagEntry] | None:
    entries = []
    cursor = doc.find_string("values")
    for value in values:
        if isinstance(value, dict):
            raw, required = value.get("id"), value.get("required", True)
            if isinstance(raw, str):
                cursor = _advance(doc, raw, _advance(doc, "id", cursor))
            if not isinstance(raw, str) or not isinstance(required, bool):
                diagnostics.append(doc.diagnostic(
                    ERROR, f'invalid {kind}: an entry object needs "id" (a string) and optional "required" '
                    '(true or false)', cursor))
                return None
        elif isinstance(value, str):
            raw, required = value, True
            cursor = _advance(doc, raw, cursor)
        else:
            diagnostics.append(doc.diagnostic(
                ERROR, f"invalid {kind}: an entry must be a string or an object with \"id\"", cursor))
            return None
        is_tag = raw.startswith("#")
        name = raw[1:] if is_tag else raw
        if not _RESOURCE_LOCATION.fullmatch(name):
            diagnostics.append(doc.diagnostic(
                ERROR, f"invalid {kind}: invalid resource location '{raw}' (allowed: a-z 0-9 _ . - and / in "
                "paths)", cursor))
            return None
        entries.append(TagEntry(normalise_id(name), is_tag, required, doc.loc_at(max(cursor, 0))))
    return entries


def _advance(doc: JsonDocument, token: str, cursor: int) -> int:
    """Offset of the next ``token`` string after ``cursor``; ``cursor`` itself if there is none."""
    found = doc.find_string(token, cursor)
    return found if found >= 0 else cursor


def merge_tag(tags: dict[str, FunctionTag], tag_id: str, replace: bool, entries: list[TagEntry]) -> None:
    """Add one pack's file for ``tag_id`` on top of the earlier packs' entries."""
    tag = tags.setdefault(tag_id, FunctionTag(tag_id))
    if replace:
        tag.entries.clear()
    tag.entries.extend(entries)


def validate_tags(tags: dict[str, FunctionTag], functions: Collection[str],
                  sources: dict[str, list[str]], diagnostics: list[Diagnostic],
                  refused: Collection[str] = ()) -> dict[str, FailedTag]:
    """Remove the tags the game would refuse to load and return them with the reason.
    ``refused``: functions whose file exists but fails to load (a line does not parse)."""
    failed: dict[str, str] = {}
    for tag in tags.values():
        for entry in tag.entries:
            if entry.required and not entry.is_tag and entry.id in refused:
                _fail(failed, tag.id, f"function {entry.id} fails to load (a line of it does not parse)",
                      entry, sources, diagnostics)
            elif entry.required and not entry.is_tag and entry.id not in functions:
                _fail(failed, tag.id, f"function {entry.id} does not exist", entry, sources, diagnostics)
            elif entry.required and entry.is_tag and entry.id not in tags:
                _fail(failed, tag.id, f"function tag #{entry.id} does not exist", entry, sources,
                      diagnostics)
    for cycle, entry in _cycles(tags):
        reason = "circular reference " + " -> ".join(f"#{t}" for t in cycle)
        _fail(failed, cycle[-2], reason, entry, sources, diagnostics)  # the tag holding ``entry``
        for tag_id in cycle:
            failed.setdefault(tag_id, reason)
    _propagate(tags, failed, sources, diagnostics)
    return {tag_id: FailedTag(tags.pop(tag_id), reason) for tag_id, reason in failed.items()}


def _fail(failed: dict[str, str], tag_id: str, reason: str, entry: TagEntry,
          sources: dict[str, list[str]], diagnostics: list[Diagnostic]) -> None:
    hint = ' (mark the entry {"id": ..., "required": false} to make it optional)' \
        if "does not exist" in reason else ""
    diagnostics.append(_at(ERROR, f"function tag #{tag_id} fails to load: {reason}{hint}",
                           entry.loc, sources))
    failed.setdefault(tag_id, reason)


def _propagate(tags: dict[str, FunctionTag], failed: dict[str, str],
               sources: dict[str, list[str]], diagnostics: list[Diagnostic]) -> None:
    """A tag that requires a tag which failed to load fails too."""
    changed = True
    while changed:
        changed = False
        for tag in tags.values():
            if tag.id in failed:
                continue
            for entry in tag.entries:
                if entry.is_tag and entry.required and entry.id in failed:
                    _fail(failed, tag.id, f"it includes #{entry.id}, which fails to load", entry,
                          sources, diagnostics)
                    changed = True
                    break


def _cycles(tags: dict[str, FunctionTag]) -> list[tuple[list[str], TagEntry]]:
    """Each cycle once, as the tag ids around it and the entry that closes it."""
    state: dict[str, int] = {}  # 1 on the current path, 2 finished
    found = []

    def visit(tag_id: str, path: list[str]) -> None:
        state[tag_id] = 1
        path.append(tag_id)
        for entry in tags[tag_id].entries:
            if not entry.is_tag or entry.id not in tags:
                continue
            if state.get(entry.id) == 1:
                found.append((path[path.index(entry.id):] + [entry.id], entry))
            elif entry.id not in state:
                visit(entry.id, path)
        path.pop()
        state[tag_id] = 2

    for tag_id in tags:
        if tag_id not in state:
            visit(tag_id, [])
    return found


def resolve_tag(tags: dict[str, FunctionTag], functions: Collection[str], tag_id: str) -> list[str]:
    """The functions a tag runs: nested tags flattened in order, duplicates and absent optional
    entries dropped. An unknown tag gives an empty list."""
    result: dict[str, None] = {}
    seen: set[str] = set()  # a tag reached again adds nothing new: each is walked once

    def visit(current: str) -> None:
        tag = tags.get(current)
        if tag is None or current in seen:
            return
        seen.add(current)
        for entry in tag.entries:
            if entry.is_tag:
                visit(entry.id)
            elif entry.id in functions:
                result.setdefault(entry.id, None)

    visit(normalise_id(tag_id.removeprefix("#")))
    return list(result)


def _at(severity: str, message: str, loc: Loc, sources: dict[str, list[str]]) -> Diagnostic:
    lines = sources.get(loc.path, [])
    return Diagnostic.at(severity, message, loc, lines[loc.line - 1] if loc.line <= len(lines) else None)
