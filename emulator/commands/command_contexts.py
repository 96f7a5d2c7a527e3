"""The contexts an ``execute`` command's stages make before its ``run``, for a command block's
result callback, which counts a success per context (BaseCommandBlock.performCommand's
``withCallback``): ``forked(state, packs, text, ctx) -> (run text, [contexts]) | None``.

Only stages that pick contexts without changing the world are evaluated here (``as``, ``at``,
``positioned``, ``rotated``, ``facing``, ``anchored``, ``align``, ``in``, ``on`` and the conditions
but ``if function``); None for any other command, one of these that makes exactly one context, or
one the emulator cannot evaluate here (the command then runs whole, as one).
"""
from __future__ import annotations

import functools

from mcfunction_parser import ast
from mcfunction_parser.parse import parse_function

from . import stages
from .env import Env

_PURE = (ast.ExAs, ast.ExAt, ast.ExPositioned, ast.ExPositionedAs, ast.ExRotated, ast.ExRotatedAs, ast.ExFacing,
         ast.ExFacingEntity, ast.ExAnchored, ast.ExAlign, ast.ExIn, ast.ExOn)


@functools.lru_cache(maxsize=256)
def _chain(text: str, version: tuple[int, int, int]):
    """``(stages, run text)`` of an ``execute ... run`` whose stages are all pure, else None."""
    function, errors = parse_function(text, "<command block>", "dpemu:command_block", version)
    if errors or len(function.commands) != 1 or not isinstance(function.commands[0], ast.Execute):
        return None
    node = function.commands[0]
    if node.run is None or not all(isinstance(st, _PURE) or (isinstance(st, ast.Condition)
                                                           and not isinstance(st, ast.IfFunction))
                                   for st in node.subcommands):
        return None
    return node.subcommands, text[node.run.loc.col - 1:]


def forked(state, packs, text: str, ctx):
    found = _chain(text, tuple(state.version))
    if found is None:
        return None
    subcommands, run = found
    env = Env(state, packs.functions, packs.tags)
    contexts = [ctx]
    try:
        for st in subcommands:
            contexts = [made for c in contexts for made in stages.stage(env, st, c)]
    except Exception:  # a stage the emulator cannot evaluate here: the command runs whole
        return None
    return None if len(contexts) == 1 else (run, contexts)
