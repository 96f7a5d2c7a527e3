"""Parsing in worker processes gives what parsing in this one gives: the same check, to the byte."""
import concurrent.futures
import json
import random
import shutil
import sys
import zipfile
from pathlib import Path

import pytest

from mcfunction_parser.check import check_releases
from mcfunction_parser.pack import parallel
from mcfunction_parser.pack.loader import load_packs

sys.path.insert(0, str(Path(__file__).parents[3] / "bench"))
bench = pytest.importorskip("bench_check_scale")

# Lines that give every kind of finding: parse errors (the function is then refused), unknown
# functions, tags and predicates, macro calls without their arguments, objectives never created.
BROKEN = ["execute as @e[tag=a run say x", "function m0:nope", "function #m1:missing_tag",
          "schedule function m0:macro/apply 1t", "function m1:macro/apply {other:1}",
          "execute if predicate m0:absent run say x", "scoreboard players set @s never_created 1",
          "$function m2:$(name)", "/say slash", "say \u00e9 \\", "function elsewhere:thing"]


@pytest.fixture(scope="module")
def packs(tmp_path_factory):
    """Three generated packs with broken lines here and there, the last one zipped."""
    root = tmp_path_factory.mktemp("packs")
    made = bench.write_packs(root, 3, 6000)
    rng = random.Random(1)
    for pack in made:
        for path in sorted(pack.rglob("*.mcfunction"))[::7]:
            lines = path.read_text().split("\n")
            lines.insert(rng.randrange(len(lines)), rng.choice(BROKEN))
            path.write_text("\n".join(lines))
    (made[0] / "data/m0/function/crlf.mcfunction").write_bytes(b"say a\r\nsay b\rsay \xff\n")
    archive = root / "m2.zip"
    with zipfile.ZipFile(archive, "w") as out:
        for path in sorted(made[2].rglob("*")):
            out.write(path, path.relative_to(made[2]).as_posix())
    shutil.rmtree(made[2])
    return [*made[:2], archive]


@pytest.fixture
def shares(monkeypatch):
    """Many small batches; counts those parsed in this process and those a worker held."""
    monkeypatch.setattr(parallel, "MIN_BATCH_LINES", 500)
    counts = {"here": 0, "worker": 0}
    parse_batch, worker_result = parallel.parse_batch, parallel._worker_result

    def parsed_here(files, version):
        counts["here"] += 1  # a worker counts in its own copy of this dict
        return parse_batch(files, version)

    def from_worker(future, batch, version):
        counts["worker"] += 1
        return worker_result(future, batch, version)
    monkeypatch.setattr(parallel, "parse_batch", parsed_here)
    monkeypatch.setattr(parallel, "_worker_result", from_worker)
    return counts


def checked(packs, workers):
    result = check_releases(packs, workers=workers)
    found = result.to_json()
    del found["seconds"]
    return json.dumps(found), [d.format() for d in result.diagnostics], result.loaded


def test_parallel_and_serial_checks_are_identical(packs, shares):
    serial_json, serial_text, serial = checked(packs, 0)
    assert shares == {"here": 1, "worker": 0}  # one batch: all the files
    for workers in (1, 2):
        shares.update(here=0, worker=0)
        parallel_json, parallel_text, loaded = checked(packs, workers)
        assert shares["here"] > 0 and shares["worker"] > 0
        assert parallel_json == serial_json and parallel_text == serial_text
        assert loaded.functions == serial.functions and list(loaded.functions) == list(serial.functions)
        assert loaded.refused == serial.refused and loaded.sources == serial.sources
        assert loaded.diagnostics == serial.diagnostics
    found = json.loads(serial_json)
    assert found["errors"] and found["warnings"] and found["infos"] and found["lines"] > 18000


def test_many_lines_are_parsed_in_workers_by_default(packs, monkeypatch):
    monkeypatch.setattr(parallel, "PARALLEL_MIN_LINES", 1000)
    monkeypatch.setattr(parallel, "_other_cores", lambda: 1)
    shared = []

    def share(batches, version, workers):
        shared.append((len(batches), workers))
        return [parallel.parse_batch(batch, version) for batch in batches]
    monkeypatch.setattr(parallel, "_shared", share)
    assert load_packs(packs).functions == load_packs(packs, workers=0).functions
    assert len(shared) == 1 and shared[0][0] > 1 and shared[0][1] == 1


def test_without_worker_processes_everything_is_parsed_here(packs, shares, monkeypatch):
    serial = checked(packs, 0)[:2]
    shares.update(here=0)

    def unavailable(*args, **kwargs):
        raise OSError("no processes here")
    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", unavailable)  # imported when needed
    assert checked(packs, 1)[:2] == serial and shares["worker"] == 0 and shares["here"] > 1


def test_a_batch_whose_worker_fails_is_parsed_here(packs, shares, monkeypatch):
    serial = checked(packs, 0)[:2]

    def failing(batch, version, folder):
        raise MemoryError("a worker out of memory")
    monkeypatch.setattr(parallel, "_parse_to_file", failing)  # forked workers see it too
    assert checked(packs, 1)[:2] == serial and shares["worker"] > 0
