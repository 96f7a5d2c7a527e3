"""The benchmark's physics pack (bench/physics) on both backends: a short run with fewer bodies
must leave the same scores, entities, storage and costs, and its quicksort must rank by key."""
from __future__ import annotations

from pathlib import Path

import pytest

from emulator.api import Emulator
from emulator.world.entities import entity_nbt

PACK = Path(__file__).resolve().parents[2] / "bench" / "physics"
BODIES, TICKS = 40, 3  # the sort runs on tick 1


def play(backend: str) -> Emulator:
    emu = Emulator(backend=backend)
    emu.load(PACK)
    emu.start()
    emu.call("phys:setup/world", arguments={"bodies": BODIES})
    emu.tick(TICKS)
    return emu


@pytest.fixture(scope="module")
def runs():
    return play("python"), play("numba")


def test_the_pack_loads_and_runs_cleanly(runs):
    reference, _ = runs
    assert reference.load_diagnostics == [] and reference.diagnostics == []
    assert len(reference.entities("@e[tag=phys.body]")) == BODIES
    assert reference.score("#tick", "phys.tmp") == TICKS
    assert reference.entities("@e[tag=phys.near]"), "no body found a neighbour in its volume"
    assert reference.state.storage["phys:flags"]["contact"] == 1


def test_both_backends_agree(runs):
    reference, vm = runs
    assert vm.scores() == reference.scores()
    assert vm.entities() == reference.entities()
    nbt = [[entity_nbt(e) for e in emu._select("@e")] for emu in runs]  # the transformations too
    assert nbt[0] == nbt[1]
    assert vm.state.storage == reference.state.storage
    assert vm.commands_per_tick == reference.commands_per_tick
    assert vm.diagnostics == reference.diagnostics == []


def test_the_quicksort_ranks_the_sortable_bodies_by_key(runs):
    reference, _ = runs
    bodies = reference.entities("@e[tag=phys.sortable]")
    by_key = sorted(bodies, key=lambda e: e["scores"]["phys.key"])
    assert [e["scores"]["phys.rank"] for e in by_key] == list(range(len(bodies)))
    assert not reference.entities("@e[tag=phys.sort]")
