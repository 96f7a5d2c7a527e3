"""What a reload asked for inside a root leaves from the packs before it.

The game reloads inside the command (MinecraftServer.reloadResources: the server thread waits in
managedBlock until the new packs are in place), so a function the root calls after ``reload`` or
``datapack enable|disable`` comes from the new packs. Here the new packs are put in place when the
root ends (a compiled root runs on as it was compiled): the commands after the reload in each
function on its call stack call the functions as they were.

A reload asked by a tick function waits until the tick's other functions have run (as
ServerFunctionManager.tick runs the list it began); those bodies are the old ones in the game too,
but what they call comes from the new packs.

- ``stale_reads(old, old_resources, new_resources, frames) -> list[str]``: likewise the loot
  tables, item modifiers, predicates, advancements, recipes, enchantments and registry tags
  (``#id``) the reload changed that a command after ``frames`` names in its text (a macro line
  after it: ``$``). What a command reads through a name it builds otherwise is not seen.
- ``stale_calls(old, new, frames) -> list[str]``: the functions and function tags (``#id``) that
  the commands after ``frames`` (the call stack that asked, the root first; ``whole(function)``
  for a root run after it) may call, and that the new packs define otherwise (changed, removed or
  added). Empty: running them from the old packs is what the game does. A macro line after it may
  call anything: ``$`` stands for it.
"""
from __future__ import annotations

import re

from emulator.world.records import Frame
from mcfunction_parser import ast
from mcfunction_parser.check import walk
from mcfunction_parser.diagnostics import Loc


def stale_calls(old, new, frames) -> list[str]:
    stale = []
    for ref in _later_calls(old.functions, frames):
        if ref == "$" or _definition(old, ref) != _definition(new, ref):
            stale.append(ref)
    return stale


def whole(function_id: str) -> Frame:
    """A frame before every command of ``function_id`` (a root that ran after the reload's)."""
    return Frame(function_id, Loc("", 0, 0))


def _later_calls(functions, frames) -> list[str]:
    """The functions (``#`` for a tag) the commands after each frame's own command name, in order."""
    refs: list[str] = []
    for frame in frames:
        function = functions.get(frame.function)
        if function is None:
            continue
        for command in function.commands:
            if command.loc.line <= frame.loc.line:
                continue
            nodes: list = []
            walk(command, nodes)
            for node in nodes:
                ref = _called(node)
                if ref is not None and ref not in refs:
                    refs.append(ref)
    return refs


def _called(node) -> str | None:
    if isinstance(node, ast.MacroLine):
        return "$"
    if isinstance(node, (ast.FunctionCall, ast.Schedule, ast.IfFunction)):
        return ("#" if node.is_tag else "") + node.function
    return None


def _definition(packs, ref: str):
    """What ``ref`` is in ``packs``: a function's commands, or a tag's entries (None: not defined)."""
    if ref.startswith("#"):
        tag = packs.tags.get(ref[1:])
        return None if tag is None else [(e.id, e.is_tag, e.required) for e in tag.entries]
    function = packs.functions.get(ref)
    return None if function is None else function.commands


_READ = ("loot_tables", "item_modifiers", "predicates", "advancements", "recipe_bodies", "enchantments")


def stale_reads(old, old_resources, new_resources, frames) -> list[str]:
    changed = _changed(old_resources, new_resources)
    if not changed:
        return []
    lines = _later_lines(old, frames)
    if any(line.lstrip().startswith("$") for line in lines):
        return ["$"]
    return [ref for ref in changed if any(_names(line, ref) for line in lines)]


def _changed(old, new) -> list[str]:
    """The ids (``#`` for a registry tag) whose definitions differ between two Resources."""
    out = []
    for kind in _READ:
        before, after = getattr(old, kind), getattr(new, kind)
        out += sorted(k for k in before.keys() | after.keys() if before.get(k) != after.get(k))
    for registry in old.tags.keys() | new.tags.keys():
        before, after = old.tags.get(registry, {}), new.tags.get(registry, {})
        out += sorted("#" + k for k in before.keys() | after.keys()
                      if getattr(before.get(k), "members", None) != getattr(after.get(k), "members", None))
    return out


def _later_lines(packs, frames) -> list[str]:
    """The source lines after each frame's own command."""
    lines = []
    for frame in frames:
        function = packs.functions.get(frame.function)
        if function is not None:
            lines += packs.sources.get(function.path, [])[frame.loc.line:]
    return lines


def _names(line: str, ref: str) -> bool:
    """Whether ``line`` names ``ref`` (a ``minecraft:`` id also without its namespace)."""
    tag, name = ("#", ref[1:]) if ref.startswith("#") else ("", ref)
    forms = [name] + ([name.removeprefix("minecraft:")] if name.startswith("minecraft:") else [])
    return any(re.search(rf"(?<![\w:/.-]){re.escape(tag + form)}(?![\w:/.-])", line) for form in forms)
