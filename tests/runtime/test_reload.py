"""``datapack enable|disable|list`` and ``reload``: the packs selected, the reload, and when the new
packs are in place (decompiled 26.1.2: DataPackCommand, ReloadCommand, MinecraftServer.reloadResources,
PackRepository.rebuildSelected, ServerFunctionManager.tick/replaceLibrary, FunctionCallback.handle)."""
from __future__ import annotations

import pytest

from emulator.api import Emulator
from tests.conftest import write_pack

BACKENDS = ["numba", "python"]
SETUP = "scoreboard objectives add o dummy\n"


def two_packs(tmp_path, a_files=None, b_files=None):
    """Packs ``a`` and ``b`` (folders of those names: ids file/a and file/b), a beneath b."""
    a = write_pack(tmp_path / "a", {"a/function/load.mcfunction": SETUP + "scoreboard players add #a_loads o 1",
                                    "a/function/tick.mcfunction": "scoreboard players add #a_ticks o 1",
                                    **(a_files or {})}, tick=["a:tick"], load=["a:load"])
    b = write_pack(tmp_path / "b", {"b/function/load.mcfunction": SETUP + "scoreboard players add #b_loads o 1",
                                    "b/function/tick.mcfunction": "scoreboard players add #b_ticks o 1",
                                    **(b_files or {})}, tick=["b:tick"], load=["b:load"])
    return [a, b]


def started(paths, backend):
    emu = Emulator(backend=backend)
    emu.load(paths)
    emu.start()
    return emu


@pytest.mark.parametrize("backend", BACKENDS)
def test_disable_stops_ticking_and_the_load_functions_run_again(tmp_path, backend):
    paths = two_packs(tmp_path, b_files={"b/function/off.mcfunction":
                                         'execute store result score #size o run datapack disable "file/b"'})
    emu = started(paths, backend)
    emu.tick(2)
    emu.call("b:off")
    # enablePack/disablePack return the size of the new selection: vanilla and file/a
    assert emu.score("#size", "o") == 2
    emu.tick(3)
    assert emu.score("#b_ticks", "o") == 2  # b's tick stopped
    assert emu.score("#a_ticks", "o") == 5
    # postReload: the next tick ran #minecraft:load first, now only a's load
    assert (emu.score("#a_loads", "o"), emu.score("#b_loads", "o")) == (2, 1)
    assert emu.state.pack_repository.selected == ["vanilla", "file/a"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_list_counts_enabled_and_available(tmp_path, backend):
    paths = two_packs(tmp_path, a_files={"a/function/lists.mcfunction": """
datapack disable "file/b"
execute store result score #all o run datapack list
execute store result score #enabled o run datapack list enabled
execute store result score #available o run datapack list available
"""})
    emu = started(paths, backend)
    emu.call("a:lists")
    # listPacks: the enabled (vanilla, file/a) plus the available ones not selected (file/b); the
    # disable's reload is in place when its command returns
    assert (emu.score("#all", "o"), emu.score("#enabled", "o"), emu.score("#available", "o")) == (3, 2, 1)


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_failures_of_get_pack(tmp_path, backend):
    paths = two_packs(tmp_path, a_files={"a/function/fails.mcfunction": """
execute store success score #unknown o run datapack disable "file/nope"
execute store success score #on o run datapack enable "file/b"
datapack disable "file/b"
execute store success score #off o run datapack disable "file/b"
execute store success score #before o run datapack enable "file/b" before "file/b"
"""})
    emu = started(paths, backend)
    emu.call("a:fails")
    # getPack: unknown, already enabled, not enabled (also for `before EXISTING`, which must be enabled)
    assert [emu.score(h, "o") for h in ("#unknown", "#on", "#off", "#before")] == [0, 0, 0, 0]
    assert emu.state.pack_repository.selected == ["vanilla", "file/a"]
    # the game's failure, and a warning naming the ids loaded (a world's pack may be named otherwise)
    assert [d.message for d in emu.diagnostics if "no loaded pack" in d.message] == [
        "no loaded pack is 'file/nope'; the packs loaded are file/a, file/b"]


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("where,winner", [("", "b"), ("last", "b"), ("first", "a"), ('before "file/a"', "a"),
                                           ('after "file/a"', "b")])
def test_enable_places_the_pack_as_asked(tmp_path, backend, where, winner):
    """Both packs define shared:which; the pack higher in the selection wins (the resource manager
    stacks packs): enable's default position for a world pack is the top."""
    which = "shared/function/which.mcfunction"
    paths = two_packs(tmp_path, a_files={which: "scoreboard players set #which o 1",
                                         "a/function/on.mcfunction": f'datapack enable "file/b" {where}'.rstrip()},
                      b_files={which: "scoreboard players set #which o 2",
                               "b/function/off.mcfunction": 'datapack disable "file/b"'})
    emu = started(paths, backend)
    emu.call("b:off")
    emu.call("a:on")
    emu.call("shared:which")
    assert emu.score("#which", "o") == {"a": 1, "b": 2}[winner]


@pytest.mark.parametrize("backend", BACKENDS)
def test_vanilla_stays_selected(tmp_path, backend):
    paths = two_packs(tmp_path, a_files={"a/function/off.mcfunction":
                                         'execute store result score #size o run datapack disable "vanilla"\n'
                                         'execute store result score #enabled o run datapack list enabled'})
    emu = started(paths, backend)
    emu.call("a:off")
    # the size returned is the list without vanilla; rebuildSelected puts the required pack back
    assert (emu.score("#size", "o"), emu.score("#enabled", "o")) == (2, 3)


@pytest.mark.parametrize("backend", BACKENDS)
def test_reload_reads_the_files_again_and_runs_load_next_tick(tmp_path, backend):
    paths = two_packs(tmp_path, a_files={"a/function/reload.mcfunction":
                                         "execute store result score #reload o run reload"})
    emu = started(paths, backend)
    (paths[0] / "data/a/function/tick.mcfunction").write_text("scoreboard players add #a_ticks o 10")
    emu.call("a:reload")
    assert emu.score("#reload", "o") == 0  # ReloadCommand returns 0
    emu.tick(1)
    assert emu.score("#a_ticks", "o") == 10  # the file as it is now
    assert (emu.score("#a_loads", "o"), emu.score("#b_loads", "o")) == (2, 2)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_tick_goes_on_with_the_functions_it_began(tmp_path, backend):
    """ServerFunctionManager.tick runs the tick list it started with: b's tick function still runs
    in the tick a's tick function disabled b; from the next tick it is gone."""
    paths = two_packs(tmp_path, a_files={"a/function/tick.mcfunction":
                                         "scoreboard players add #a_ticks o 1\n"
                                         'execute if score #a_ticks o matches 2 run datapack disable "file/b"'})
    emu = started(paths, backend)
    emu.tick(4)
    assert emu.score("#b_ticks", "o") == 2
    assert emu.score("#a_loads", "o") == 2


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_reload_in_a_load_function_gives_that_tick_the_new_tick_functions(tmp_path, backend):
    """ServerFunctionManager.tick reads its ticking list after the load functions ran: a reload they
    asked for is in place for that tick's tick functions (and postReload runs load again next tick)."""
    paths = two_packs(tmp_path, a_files={"a/function/load.mcfunction":
                                         SETUP + "scoreboard players add #a_loads o 1\n"
                                         'execute if score #a_loads o matches 1 run datapack disable "file/b"'})
    emu = Emulator(backend=backend)
    emu.load(paths)
    emu.tick(1)  # the first tick runs the load functions: a's disables b, b's still runs (the list began)
    assert (emu.score("#a_loads", "o"), emu.score("#b_loads", "o")) == (1, 1)
    assert (emu.score("#a_ticks", "o"), emu.score("#b_ticks", "o")) == (1, None)
    emu.tick(1)
    assert emu.score("#a_loads", "o") == 2  # postReload


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_scheduled_function_of_a_disabled_pack_does_not_run(tmp_path, backend):
    paths = two_packs(tmp_path, b_files={"b/function/later.mcfunction": "scoreboard players set #later o 1",
                                         "b/function/off.mcfunction": "schedule function b:later 2t\n"
                                                                      'datapack disable "file/b"'})
    emu = started(paths, backend)
    emu.call("b:off")
    emu.tick(3)
    # FunctionCallback.handle: the function is looked up when due, and nothing runs without one
    assert emu.score("#later", "o") is None
    assert not [d for d in emu.diagnostics if "later" in d.message]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_new_world_runs_the_packs_loaded(tmp_path, backend):
    paths = two_packs(tmp_path, b_files={"b/function/off.mcfunction": 'datapack disable "file/b"'})
    emu = started(paths, backend)
    emu.call("b:off")
    emu.new_world()
    emu.tick(1)
    assert emu.score("#b_ticks", "o") == 1
    assert emu.state.pack_repository.selected == ["vanilla", "file/a", "file/b"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_what_is_not_modelled_says_so(tmp_path, backend):
    paths = two_packs(tmp_path, a_files={"a/function/features.mcfunction": 'datapack enable "trade_rebalance"'})
    emu = started(paths, backend)
    emu.call("a:features")
    assert [d.message for d in emu.diagnostics if d.unmodelled] == [
        "not modelled: the game's feature pack 'trade_rebalance' (its feature flags)"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_profile_keeps_what_ran_before_a_reload(tmp_path, backend):
    paths = two_packs(tmp_path, b_files={"b/function/off.mcfunction": 'datapack disable "file/b"'})
    emu = started(paths, backend)
    emu.tick(2)
    emu.call("b:off")
    emu.tick(2)
    lines = emu.profile.lines
    assert lines[(str(paths[1] / "data/b/function/tick.mcfunction"), 1)] == 2  # b ticked twice, then left
    assert lines[(str(paths[0] / "data/a/function/tick.mcfunction"), 1)] == 4


def _unmodelled(emu) -> list[str]:
    return [d.message for d in emu.diagnostics if d.unmodelled]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_call_after_the_reload_to_what_it_changed_is_not_modelled(tmp_path, backend):
    # MinecraftServer.reloadResources waits inside the command, so the game's `function b:hello`
    # after it meets the new packs (no b:hello: the command fails); here the root runs on as it was
    paths = two_packs(tmp_path, b_files={"b/function/hello.mcfunction": "scoreboard players add #hello o 1",
                                         "b/function/off.mcfunction": 'datapack disable "file/b"\n'
                                                                      "tellraw @a \"bye\"\nfunction b:hello"})
    emu = started(paths, backend)
    emu.call("b:off")
    [message] = _unmodelled(emu)
    assert "b:hello called or read after this reload" in message
    [diagnostic] = [d for d in emu.diagnostics if d.unmodelled]
    assert diagnostic.frames[-1].loc.line == 1  # the command that asked


@pytest.mark.parametrize("backend", BACKENDS)
def test_what_runs_after_the_reload_as_the_game_runs_it_is_not_reported(tmp_path, backend):
    # an uninstaller's message after `datapack disable`, and a call to a function the reload left as
    # it was: the same in the game
    paths = two_packs(tmp_path, a_files={"a/function/again.mcfunction": "reload\nfunction a:tick"},
                      b_files={"b/function/off.mcfunction": 'datapack disable "file/b"\ntellraw @a "bye"'})
    emu = started(paths, backend)
    emu.call("a:again")
    emu.call("b:off")
    assert _unmodelled(emu) == []


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_later_tick_function_calling_what_the_reload_removed_is_not_modelled(tmp_path, backend):
    # ServerFunctionManager.tick runs b's tick function (the list began), but what it calls comes
    # from the new packs in the game
    paths = two_packs(tmp_path, a_files={"a/function/tick.mcfunction": 'datapack disable "file/b"'},
                      b_files={"b/function/tick.mcfunction": "function b:hello",
                               "b/function/hello.mcfunction": "scoreboard players add #hello o 1"})
    emu = started(paths, backend)
    emu.tick(1)
    assert emu.score("#hello", "o") == 1
    assert ["b:hello called or read after this reload" in m for m in _unmodelled(emu)] == [True]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_predicate_read_after_the_reload_removed_it_is_not_modelled(tmp_path, backend):
    # the game's `execute if predicate b:always` after the disable meets no such predicate
    paths = two_packs(tmp_path, b_files={"b/predicate/always.json": '{"condition": "minecraft:value_check", '
                                         '"value": 1, "range": 1}',
                                         "b/function/off.mcfunction": 'datapack disable "file/b"\n'
                                                                      "execute if predicate b:always run say yes"})
    emu = started(paths, backend)
    emu.call("b:off")
    assert ["b:always called or read after this reload" in m for m in _unmodelled(emu)] == [True]


def test_a_line_names_an_id_whole():
    from emulator.runtime.reloads import _names
    assert _names("execute if predicate b:always run say", "b:always")
    assert not _names("execute if predicate b:always_not run say", "b:always")
    assert not _names("loot give @s loot a:b:always", "b:always")
    assert _names("loot give @s loot chests/x", "minecraft:chests/x")
    assert _names("execute if block ~ ~ ~ #logs run say", "#minecraft:logs")
    assert not _names("execute if block ~ ~ ~ logs run say", "#minecraft:logs")
