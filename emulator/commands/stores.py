"""``execute store result|success ...`` (ExecuteCommand.wrapStores, decompiled 1.21): into scores,
storage, an entity, a block or a bossbar.

The stage resolves its target once, with its own context (:func:`store_target`: storeValue reads
the holders and the objective, storeData builds the accessor, the bossbar is looked up); a
failure there fails the stage. The command's result callback then stores into that target
(:func:`store`): ``result`` stores the value (0 when the command failed), ``success`` 1/0.
"""
from __future__ import annotations

from mcfunction_parser import ast

from . import data
from .holders import holder_names, objective


def store_target(env, st: ast.Subcommand, ctx):
    """What the store stage ``st`` writes to: holder names (a tuple), a data accessor, or a bossbar."""
    if isinstance(st, ast.StoreScore):
        names = tuple(holder_names(env, st.targets, ctx))
        objective(env, st.objective)  # read after the holders (storeValue's arguments)
        return names
    if isinstance(st, ast.StoreData):
        return data.accessor(env, st.target, ctx)
    return env.state.bossbars.find(st.bossbar)


def store(env, st: ast.Subcommand, target, success: bool, value: int) -> None:
    """The store callback for a command's ``(success, value)``; it never fails."""
    stored = (value if success else 0) if st.kind == "result" else int(success)
    if isinstance(st, ast.StoreScore):
        board = env.state.scoreboard
        if not board.exists(st.objective):
            return  # removed meanwhile: the game writes to the dropped Objective, which nothing sees
        for name in target:
            board.set(name, st.objective, stored)
    elif isinstance(st, ast.StoreData):
        data.store(target, st, stored)
    else:
        setattr(target, st.field, stored)  # value or max, unclamped


def is_store(st: ast.Subcommand) -> bool:
    return isinstance(st, (ast.StoreScore, ast.StoreData, ast.StoreBossbar))
