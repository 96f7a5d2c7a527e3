"""Parsing many function files on every core: the main process and worker processes share the work.

The files are cut into batches (about BATCHES of them), queued for the workers in order.
Meanwhile this process parses batches itself from the back of the queue (those no worker has
started: their futures still cancel) until it meets one a worker holds, then reads the workers'
results. Pickling a batch's functions and unpickling them here costs about as much as parsing
them, so this process parsing its share without that round trip is what makes two cores faster
than one (about 15 % for a million lines). A worker writes its results to a temporary file: sent
through the pool's pipe, they wait for this process's result thread, which gets the interpreter
lock only between slices of the parsing here, and the worker idled half the time.

The results come back in the order of the files, the same as parsing them one by one here: small
inputs are parsed here, and so is everything when no worker process starts, and any batch whose
worker fails.
"""
from __future__ import annotations

import gc
import os
import pickle
import tempfile
from collections.abc import Sequence
from typing import TYPE_CHECKING

from mcfunction_parser.ast import Function
from mcfunction_parser.dialect import packtest_enabled
from mcfunction_parser.diagnostics import ERROR, Diagnostic
from mcfunction_parser.parse import parse_lines
from mcfunction_parser.pack.versions import Version

FunctionFile = tuple[list[str], str, str, str]  # (lines, shown path, function id, pack root)
Parsed = tuple[Function | None, list[Diagnostic]]

if TYPE_CHECKING:  # the process pool is imported when a large input needs it (start-up time)
    from concurrent.futures import Future, ProcessPoolExecutor

PARALLEL_MIN_LINES = 100_000  # below this, starting a worker costs about what it saves
BATCHES, MIN_BATCH_LINES = 100, 5_000  # about this many batches, of at least this many lines:
# smaller ones share the work more evenly, larger ones cost less each to send and to schedule


def parse_files(files: Sequence[FunctionFile], version: Version, workers: int | None = None) -> list[Parsed]:
    """(function, diagnostics) of each file, in order; the function is None when the parser
    failed on it (an internal error, reported as its diagnostic). ``workers``: worker processes
    beside this one (0: none); None: one per other core, for at least PARALLEL_MIN_LINES lines."""
    lines = sum(len(f[0]) for f in files)
    if workers is None:
        workers = _other_cores() if lines >= PARALLEL_MIN_LINES else 0
    if packtest_enabled():  # a worker process would not read PackTest's commands (a context variable of this one)
        workers = 0
    batches = _batches(files, max(MIN_BATCH_LINES, lines // BATCHES))
    if workers < 1 or len(batches) < 2:
        return parse_batch(files, version)
    return [parsed for batch in _shared(batches, version, workers) for parsed in batch]


def parse_batch(files: Sequence[FunctionFile], version: Version) -> list[Parsed]:
    return [_parse_file(lines, shown, fid, version, pack) for lines, shown, fid, pack in files]


def _parse_file(lines: list[str], shown: str, fid: str, version: Version, pack: str) -> Parsed:
    try:
        return parse_lines(lines, shown, fid, version, pack)
    except Exception as exc:  # a parser bug must not stop the other functions
        return None, [Diagnostic(ERROR, f"internal error while parsing this file: {type(exc).__name__}: {exc}",
                                 shown)]


def _other_cores() -> int:
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    return cores - 1


def _batches(files: Sequence[FunctionFile], size: int) -> list[list[FunctionFile]]:
    """The files in order, cut into batches of about ``size`` lines."""
    batches: list[list[FunctionFile]] = [[]]
    lines = 0
    for file in files:
        if lines >= size:
            batches.append([])
            lines = 0
        batches[-1].append(file)
        lines += len(file[0])
    return batches


def _shared(batches: list[list[FunctionFile]], version: Version, workers: int) -> list[list[Parsed]]:
    """Each batch's results, from worker processes when they start."""
    from concurrent.futures import ProcessPoolExecutor

    try:
        # the workers only build and pickle ASTs, which hold no reference cycles
        pool = ProcessPoolExecutor(workers, initializer=gc.disable)
    except (OSError, NotImplementedError, ImportError):  # no processes on this system
        return [parse_batch(batch, version) for batch in batches]
    with tempfile.TemporaryDirectory(prefix="dpemu-parse-") as folder:
        try:
            return _share(pool, batches, version, folder)
        finally:
            pool.shutdown(cancel_futures=True)


def _share(pool: ProcessPoolExecutor, batches: list[list[FunctionFile]], version: Version,
           folder: str) -> list[list[Parsed]]:
    """The workers parse the batches from the front, this process from the back."""
    from concurrent.futures.process import BrokenProcessPool

    try:
        futures = [pool.submit(_parse_to_file, batch, version, folder) for batch in batches]
    except (OSError, BrokenProcessPool):  # no worker could start
        return [parse_batch(batch, version) for batch in batches]
    here: dict[int, list[Parsed]] = {}
    for index in reversed(range(len(batches))):
        if not futures[index].cancel():  # a worker has it: the ones before are theirs too
            break
        here[index] = parse_batch(batches[index], version)
    return [here[index] if index in here else _worker_result(futures[index], batch, version)
            for index, batch in enumerate(batches)]


def _parse_to_file(batch: list[FunctionFile], version: Version, folder: str) -> str:
    """In a worker: parse the batch and pickle the results to a new file in ``folder``."""
    with tempfile.NamedTemporaryFile("wb", dir=folder, delete=False) as out:
        pickle.dump(parse_batch(batch, version), out, protocol=pickle.HIGHEST_PROTOCOL)
    return out.name


def _worker_result(future: Future, batch: list[FunctionFile], version: Version) -> list[Parsed]:
    try:
        with open(future.result(), "rb") as results:
            return pickle.load(results)
    except Exception:  # the worker died or could not write its results: parse its batch here
        return parse_batch(batch, version)
