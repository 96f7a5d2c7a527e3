"""Loading the VM from numba's cache without numba's whole set-up (emulator.vm.jit_cache): a second
process with the same cache runs the VM without importing numba's registries, with the same results
as the first, which compiled it."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from tests.backends.programs import write_pack

FUNCTIONS = {  # the tiny loop's families: cheap to compile
    "t:main": "scoreboard objectives add o dummy\nscoreboard players set #a o 7\nfunction t:add\n"
              "scoreboard players remove #a o 1\nsay hello\nreturn run function t:add",
    "t:add": "scoreboard players add #b o 2\nreturn 9",
}
SCRIPT = """
import json, sys
from emulator import Emulator
emu = Emulator(); emu.load(sys.argv[1]); result = emu.call("t:main")
print(json.dumps({"scores": emu.scores(), "result": result, "lean": "numba.np.linalg" not in sys.modules}))
"""


def test_a_warm_start_loads_the_vm_without_numbas_registries(tmp_path):
    pack = write_pack(tmp_path / "pack", FUNCTIONS)
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    runs = []
    for _ in range(2):  # an empty cache (numba compiles, set up in full), then the cache it wrote
        run = subprocess.run([sys.executable, "-c", SCRIPT, str(pack)], env=env, capture_output=True, text=True,
                             timeout=600)
        assert run.returncode == 0, run.stderr
        runs.append(json.loads(run.stdout))
    cold, warm = runs
    assert not cold["lean"] and warm["lean"]  # numba's refresh imports numba.np.linalg, among others
    assert warm["scores"] == cold["scores"] == {"o": {"#a": 6, "#b": 4}}
    assert warm["result"] == cold["result"] == 9
