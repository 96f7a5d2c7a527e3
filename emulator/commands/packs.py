"""The commands on the server's data packs: ``datapack enable|disable|list`` and ``reload``.

Sources (decompiled 26.1.2; the same in 1.16.5, 1.20.4, 1.21.3): server/commands/DataPackCommand.java
(getPack's checks; enablePack/disablePack return the size of the new selection, before the required
vanilla pack is put back; listPacks adds the two lists' sizes), ReloadCommand.java (result 0; the packs
selected now, and any new one not disabled). Both end in MinecraftServer.reloadResources, which
the server thread waits for: the new packs are in place when the command returns. Here the runtime
puts them in place when the root sequence running the command ends (a function called after it in
that root whose definition the reload changes is reported not modelled:
:mod:`emulator.runtime.reloads`), or, for a tick or load function,
after the rest of the functions that tick had started (as ServerFunctionManager.tick goes on with the
list it began): :meth:`emulator.runtime.server.Runtime.apply_reload`. The next tick runs
``#minecraft:load`` first (ServerFunctionManager.replaceLibrary sets postReload).
"""
from __future__ import annotations

from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.pack_repository import FILE_PREFIX, VANILLA
from mcfunction_parser import ast
from mcfunction_parser.reader import Reader

from .level import Words

# The game's feature packs (its jar's data/minecraft/datapacks): enabling one needs its feature flag
FEATURE_PACKS = frozenset({"bundle", "trade_rebalance", "redstone_experiments", "minecart_improvements",
                           "update_1_20", "update_1_21", "winter_drop"})


def datapack(env, cmd: ast.GenericCommand, ctx) -> int:
    words = Words(env, cmd)
    action = words.word()
    repository = env.state.pack_repository
    if action == "list":
        which = words.word() if words.more() else None
        enabled = len(repository.current) if which != "available" else 0
        # listAvailablePacks: the available packs not selected whose feature flags are enabled
        available = sum(p not in repository.current for p in repository.ids()) if which != "enabled" else 0
        return enabled + available
    if action == "create":
        raise Unmodelled("datapack create (writing a new pack into the world's datapacks folder)")
    name = _pack(env, cmd, repository, words.read(Reader.string), enabling=action == "enable")
    selection = list(repository.current)
    if action == "disable":
        selection.remove(name)
    else:
        where = words.word() if words.more() else "last"
        if where in ("before", "after"):
            existing = _pack(env, cmd, repository, words.read(Reader.string), enabling=False)
            selection.insert(selection.index(existing) + (where == "after"), name)
        else:  # a world pack's default position is the top
            selection.insert(0 if where == "first" else len(selection), name)
    repository.reload(selection, env.frames(cmd))
    return len(selection)


def _pack(env, cmd, repository, name: str, enabling: bool) -> str:
    """DataPackCommand.getPack: a known pack, not yet enabled when ``enabling``, else enabled. An
    unknown ``file/`` id fails as in the game, with a warning naming the ids loaded (a pack's id is
    its folder's or zip file's name, which a world may not share with the folder tested here)."""
    if name in FEATURE_PACKS:
        raise Unmodelled(f"the game's feature pack '{name}' (its feature flags)")
    if not repository.knows(name):
        if name.startswith(FILE_PREFIX):
            env.warn(cmd, f"no loaded pack is '{name}'; the packs loaded are "
                          f"{', '.join(p for p in repository.ids() if p != VANILLA)}")
        raise CommandFailure("commands.datapack.unknown", name)
    enabled = name in repository.current
    if enabling and enabled:
        raise CommandFailure("commands.datapack.enable.failed", name)
    if not enabling and not enabled:
        raise CommandFailure("commands.datapack.disable.failed", name)
    return name


def reload(env, cmd: ast.GenericCommand, ctx) -> int:
    """ReloadCommand: the packs selected now reload (every other available pack was disabled, so
    discoverNewPacks adds none)."""
    repository = env.state.pack_repository
    repository.reload(list(repository.current), env.frames(cmd))
    return 0


GENERIC_HANDLERS = {"datapack": datapack, "reload": reload}
