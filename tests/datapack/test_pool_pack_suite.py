"""The pool datapack's own PackTest suite (datapack/data/pool/test/**) as part of the pytest run,
one item per test file and backend, with ``dpemu test``'s failure message."""
from pathlib import Path

import pytest

from emulator.testing import discover
from emulator.testing.results import FAILED
from emulator.testing.runner import load_suite, run_case

PACK = Path(__file__).resolve().parents[2] / "datapack"
[(PACKS, CASES)] = list(load_suite(discover([PACK])))


def test_the_suite_covers_every_model_and_the_controls():
    folders = {case.id.split(":", 1)[1].split("/", 1)[0] for case in CASES}
    assert {"math", "model", "table", "controls", "api"} <= folders
    assert {"pool:model/sliding", "pool:model/rolling", "pool:model/side_spin", "pool:model/ball_ball",
            "pool:model/cushion", "pool:model/cue_strike", "pool:table/pockets", "pool:table/at_rest",
            "pool:table/break", "pool:controls/trigger"} <= {case.id for case in CASES}


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("case", CASES, ids=[case.id for case in CASES])
def test_pack_test_passes(case, backend):
    result = run_case(case, PACKS, backend)
    assert result.counts_as != FAILED, result.report()
