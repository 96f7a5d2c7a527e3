"""What a reload asked for inside a root leaves from the packs before it.

The game reloads inside the command (MinecraftServer.reloadResources: the server thread waits in
managedBlock until the new packs are in place), so a function the root calls after ``reload`` or
``datapack enable|disable`` comes from the new packs. Here the new packs are put in place when the
root ends (a compiled root runs on as it was compiled): the commands after the reload in each
function on its call stack call the functions as they were.

A reload asked by a tick function waits until the tick's other functions have run (as
ServerFunctionManager.tick runs the list it began); those bodies are the old ones in the game too,
but what they call comes from the new packs.

- ``stale_calls(old, new, frames) -> list[str]``: the functions and function tags (``#id``) that
  the commands after ``frames`` (the call stack that asked, the root first; ``whole(function)``
  for a root run after it) may call, and that the new packs define otherwise (changed, removed or
  added). Empty: running them from the old packs is what the game does. A macro line after it may
  call anything: ``$`` stands for it.
"""
from __future__ import annotations

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
