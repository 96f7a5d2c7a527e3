"""``spectate``: a spectator behind another entity's eyes follows it each tick (decompiled 26.1.2:
SpectateCommand.spectate, ServerPlayer.setCamera, ServerPlayer.tick, ServerPlayer.setGameMode,
ServerPlayer.teleportTo with resetCamera)."""
from __future__ import annotations

import pytest

from emulator.api import Emulator
from tests.conftest import write_pack

BACKENDS = ["numba", "python"]
CAMERA = "summon armor_stand 10 70 10 {Tags:[cam],Rotation:[90f,20f],NoGravity:1b}\n"


def world(tmp_path, backend, functions: dict[str, str], mc: str | None = None) -> Emulator:
    files = {f"s/function/{name}.mcfunction": body for name, body in functions.items()}
    files["s/function/load.mcfunction"] = "scoreboard objectives add o dummy"
    emu = Emulator(backend=backend)
    emu.load(write_pack(tmp_path / "pack", files, load=["s:load"]), mc_version=mc)
    emu.start()
    emu.add_player("Alex", pos=(0.0, 64.0, 0.0), rotation=(5.0, 6.0))
    return emu


def alex(emu) -> tuple[list, list]:
    player = emu.entities("@a")[0]
    return player["pos"], player["rotation"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_spectator_follows_its_camera(tmp_path, backend):
    emu = world(tmp_path, backend, {
        "go": "gamemode spectator Alex\n" + CAMERA + "execute store result score #r o run spectate @e[tag=cam,limit=1] Alex",
        "move": "tp @e[tag=cam] 20 75 20 -30 10"})
    emu.call("s:go")
    assert emu.score("#r", "o") == 1
    # setCamera: at once at the camera, in its level, with the player's own rotation
    assert alex(emu) == ([10.5, 70.0, 10.5], [5.0, 6.0])
    emu.tick(1)
    assert alex(emu) == ([10.5, 70.0, 10.5], [90.0, 20.0])  # ServerPlayer.tick: absSnapTo the camera
    emu.call("s:move")
    emu.tick(1)
    assert alex(emu) == ([20.5, 75.0, 20.5], [-30.0, 10.0])  # yRot % 360 keeps Java's sign


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("end", ["tp Alex 0 100 0", "gamemode creative Alex", "kill @e[tag=cam]", "spectate"])
def test_what_ends_spectating(tmp_path, backend, end):
    """A teleport (resetCamera), another game mode (setGameMode), a dead camera (tick) and
    ``spectate`` without a target each end it: the camera moving then leaves the player behind."""
    emu = world(tmp_path, backend, {
        "go": "gamemode spectator Alex\n" + CAMERA + "spectate @e[tag=cam,limit=1] Alex",
        "end": end, "move": "tp @e[tag=cam] 20 75 20"})
    emu.call("s:go")
    emu.tick(1)
    if end == "spectate":
        emu.call("s:end", as_="Alex")
    else:
        emu.call("s:end")
    where = alex(emu)[0]
    emu.call("s:move")
    emu.tick(2)
    assert alex(emu)[0] == where
    assert not emu.state.cameras


@pytest.mark.parametrize("backend", BACKENDS)
def test_sneaking_ends_it(tmp_path, backend):
    emu = world(tmp_path, backend, {"go": "gamemode spectator Alex\n" + CAMERA + "spectate @e[tag=cam,limit=1] Alex"})
    emu.call("s:go")
    emu.state.entities.players()[0].sneaking = True  # ServerPlayer.wantsToStopRiding: the shift key
    emu.tick(1)
    assert not emu.state.cameras


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("mc,marker_fails", [("1.21.8", False), ("1.21.9", True)])
def test_the_failures(tmp_path, backend, mc, marker_fails):
    emu = world(tmp_path, backend, {
        "survival": CAMERA + "execute store success score #survival o run spectate @e[tag=cam,limit=1] Alex",
        "self": "gamemode spectator Alex\nexecute store success score #self o run spectate Alex Alex",
        "marker": "summon marker 1 70 1 {Tags:[m]}\n"
                  "execute store success score #marker o run spectate @e[tag=m,limit=1] Alex"}, mc=mc)
    for name in ("survival", "self", "marker"):
        emu.call(f"s:{name}")
    # not a spectator; yourself; from 1.21.9 a type the client does not track (clientTrackingRange 0)
    assert (emu.score("#survival", "o"), emu.score("#self", "o")) == (0, 0)
    assert emu.score("#marker", "o") == (0 if marker_fails else 1)
