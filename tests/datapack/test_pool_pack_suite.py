"""The pool datapack's own PackTest suite (datapack/data/pool/test/**) as part of the pytest run,
one item per test file and backend, with ``dpemu test``'s failure message."""
from pathlib import Path

import pytest

from emulator.testing import discover
from emulator.testing.results import FAILED
from emulator.testing.runner import load_suite, run_case

PACK = Path(__file__).resolve().parents[2] / "datapack"
[(PACKS, CASES)] = list(load_suite(discover([PACK])))


def test_the_suite_covers_every_phase_every_model_and_the_controls():
    folders = {case.id.split(":", 1)[1].rpartition("/")[0] for case in CASES}
    # the test folders are function folders (datapack/README.md, "Layout"); "" is the top
    functions = PACK / "data/pool/function"
    assert folders <= {""} | {p.relative_to(functions).as_posix() for p in functions.rglob("*") if p.is_dir()}
    assert {"math", "physics/motion", "physics/detect", "physics/resolve", "physics/events", "physics/display", "cue",
            "controls", "api"} <= folders
    assert {"pool:physics/motion/sliding", "pool:physics/motion/rolling", "pool:physics/motion/side_spin",
            "pool:physics/resolve/ball_ball", "pool:physics/resolve/cushion", "pool:physics/resolve/pocket",
            "pool:cue/strike", "pool:physics/events/at_rest", "pool:physics/break",
            "pool:controls/trigger", "pool:unload"} <= {case.id for case in CASES}


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("case", CASES, ids=[case.id for case in CASES])
def test_pack_test_passes(case, backend):
    result = run_case(case, PACKS, backend)
    assert result.counts_as != FAILED, result.report()
