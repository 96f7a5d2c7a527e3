"""Sweeps: the same results in this process, over forked workers, and on a Dask cluster."""
import pytest

from poolgame.score.cases import cases
from poolgame.score.run import open_pack
from poolgame.score.sweep import sweep
from poolgame.shot import DEFAULT_PACK

PACK = str(DEFAULT_PACK)


@pytest.fixture(scope="module")
def work():
    assert open_pack(PACK) is None          # compiled here, before any worker forks
    return cases(("cushion", "cue"), 1, seed=3)[:6]


def _samples(results):
    return [(r.name, r.samples) for r in results]


def test_workers_give_the_results_of_one_process_in_order(work):
    alone, stopped = sweep(work, PACK, ("seeded",), workers=1)
    shared, _ = sweep(work, PACK, ("seeded",), workers=2)
    assert not stopped and _samples(shared) == _samples(alone)


def test_a_dask_scheduler_runs_the_same_function(work):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp://", host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        remote, _ = sweep(work, PACK, ("seeded",), scheduler=cluster.scheduler_address)
    alone, _ = sweep(work, PACK, ("seeded",), workers=1)
    assert _samples(remote) == _samples(alone)

