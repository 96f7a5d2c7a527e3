"""The reference backend end to end through ``Emulator(backend="python")`` and ``dpemu run``,
and tick by tick against the numba backend (load, tick, schedule)."""
from __future__ import annotations

import json

import pytest

from emulator.api import Emulator
from tests.backends.programs import write_pack

FUNCTIONS = {
    "t:load": "scoreboard objectives add o dummy\nscoreboard players set #t o 0\nschedule function t:later 3t",
    "t:tick": "scoreboard players add #t o 1\nexecute if score #t o matches 2 run say two\n"
              "execute store result score #fib o run function t:fib",
    "t:fib": "scoreboard players operation #x o += #y o\nscoreboard players operation #x o >< #y o\n"
             "execute if score #y o matches 0 run scoreboard players set #y o 1\nreturn run scoreboard players get #y o",
    "t:later": "say later\nschedule function t:later 2t append",
}
TAGS = {"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]}


@pytest.fixture
def pack(tmp_path):
    return write_pack(tmp_path / "pack", FUNCTIONS, TAGS)


def _run(backend: str, pack, ticks: int) -> Emulator:
    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.tick(ticks)
    return emu


def test_python_backend_through_the_api(pack):
    emu = _run("python", pack, 6)
    assert emu.score("#t", "o") == 6
    assert emu.score("#fib", "o") == emu.score("#y", "o") == 8
    # t:later is due at gametime 3 (tick 2), then every 2 ticks
    assert [(e.tick, e.text) for e in emu.log] == [(1, "[Server] two"), (2, "[Server] later"), (4, "[Server] later")]
    assert emu.call("t:fib") == 13
    assert not emu.diagnostics


def test_ticks_agree_with_the_numba_backend(pack):
    python, numba = _run("python", pack, 12), _run("numba", pack, 12)
    assert python.scores() == numba.scores()
    assert [(e.tick, e.kind, e.text) for e in python.log] == [(e.tick, e.kind, e.text) for e in numba.log]
    assert python.commands_per_tick == numba.commands_per_tick
    assert python.call("t:fib") == numba.call("t:fib")


def test_dpemu_run_with_the_python_backend(pack):
    from click.testing import CliRunner

    from emulator.cli import main

    result = CliRunner().invoke(main, ["run", str(pack), "--ticks", "4", "--backend", "python", "--json", "-"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output[result.output.index("{"):])
    assert report["scores"]["o"]["#t"] == 4
    assert report["ticks"] == 4
