"""tests/packs/gated: a pack using predicates and registry tags the way libraries do (a
predicate-gated tick, location/time/score predicates, references, block and entity type tags),
its PackTest suite run on both backends."""
from pathlib import Path

import pytest

from emulator.testing import discover
from emulator.testing.results import PASSED
from emulator.testing.runner import load_suite, run_case

PACK = Path(__file__).resolve().parent / "gated"
[(PACKS, CASES)] = list(load_suite(discover([PACK])))


def test_the_pack_loads_clean():
    assert PACKS.errors == []
    assert set(PACKS.predicates) == {"gated:marked_undead", "gated:in_water", "gated:night", "gated:healthy",
                                     "gated:on_soft_ground"}
    undead = PACKS.registry_tags["entity_type"]["gated:undead"]
    # the built-in #minecraft:zombies nested, the optional missing tag skipped (TagLoader)
    assert {"minecraft:husk", "minecraft:zombie", "minecraft:skeleton"} <= undead.members
    assert undead.unknown == ()


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("case", CASES, ids=[case.id for case in CASES])
def test_pack_test_passes(case, backend):
    result = run_case(case, PACKS, backend)
    assert result.status == PASSED, result.report()
