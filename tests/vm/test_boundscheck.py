"""The VM under NUMBA_BOUNDSCHECK=1 (in a subprocess with its own cache): an out-of-bounds index
raises instead of reading garbage; the results must equal the normal build's."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from emulator import Emulator
from tests.backends.programs import write_pack

FUNCTIONS = {
    "t:main": "scoreboard objectives add o dummy\nscoreboard players set #a o -7\nscoreboard players set #b o 2\n"
              "scoreboard players operation #a o /= #b o\nscoreboard players operation #c o %= #b o\n"
              "scoreboard players operation #a o /= #zero o\n"
              "execute store result score #r o run function #t:all\n"
              "execute if function t:five unless score #u o matches 1 store success score #s o run say x\n"
              "function t:m {v:5}\nscoreboard players set #n o 300\nfunction t:down\n"
              "scoreboard players add * o 1\nscoreboard players set #x nope 1\nfunction t:missing\n"
              "return run function t:five",
    "t:five": "return 5",
    "t:two": "return run scoreboard players get #b o",
    "t:m": "$scoreboard players add #m o $(v)",
    "t:down": "scoreboard players remove #n o 1\nexecute if score #n o matches 1.. run function t:down",
}
TAGS = {"t:all": ["t:five", "t:two"]}
SCRIPT = """
import json, sys
from emulator import Emulator
emu = Emulator(); emu.load(sys.argv[1]); result = emu.call("t:main")
print(json.dumps({"scores": emu.scores(), "result": result, "diagnostics": [d.message for d in emu.diagnostics]}))
"""


def test_same_results_with_boundscheck(tmp_path):
    pack = write_pack(tmp_path / "pack", FUNCTIONS, TAGS)
    emu = Emulator()
    emu.load(pack)
    result = emu.call("t:main")
    expected = {"scores": emu.scores(), "result": result, "diagnostics": [d.message for d in emu.diagnostics]}
    env = {**os.environ, "NUMBA_BOUNDSCHECK": "1", "NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    run = subprocess.run([sys.executable, "-c", SCRIPT, str(pack)], env=env, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout) == json.loads(json.dumps(expected))
    assert expected["result"] == 5 and expected["scores"]["o"]["#r"] == 7 + 1 and expected["scores"]["o"]["#n"] == 1
    assert len(expected["diagnostics"]) == 3  # division by zero, unknown objective, unknown function
