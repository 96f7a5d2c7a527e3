"""Many cases at once, each an independent world: in this process, over local worker processes
(forked after the pack is loaded and compiled, so they share that one program), or on a Dask
distributed cluster (``scheduler``: its address; ``pip install dpemu[distributed]``) through the
same function, :func:`poolgame.score.run.score_case`."""
from __future__ import annotations

import multiprocessing
import signal
from functools import partial

from poolgame.score.run import CaseResult, score_case


class MissingExtra(RuntimeError):
    """An optional dependency is not installed."""


def sweep(cases, pack: str, modes, workers: int = 1, scheduler: str | None = None, paths: bool = False,
          on_done=None) -> tuple[list[CaseResult], bool]:
    """The cases' results in their order and whether Ctrl-C stopped the sweep (then the results are
    those finished). ``on_done`` hears each finished case (a progress bar)."""
    work = partial(score_case, pack=pack, modes=tuple(modes), paths=paths)
    done: list[CaseResult] = []
    try:
        for result in _results(work, cases, workers, scheduler):
            done.append(result)
            if on_done is not None:
                on_done(result)
    except KeyboardInterrupt:
        return done, True
    return done, False


def _results(work, cases, workers: int, scheduler: str | None):
    if scheduler:
        yield from _dask(work, cases, scheduler)
    elif workers <= 1 or len(cases) <= 1:
        yield from map(work, cases)
    else:
        with multiprocessing.get_context("fork").Pool(min(workers, len(cases)), _ignore_interrupt) as pool:
            yield from pool.imap(work, cases, chunksize=1)


def _ignore_interrupt() -> None:
    """Ctrl-C reaches every process of the terminal's group: the workers leave it to this one, which
    stops the pool and reports what finished."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _dask(work, cases, scheduler: str):
    try:
        from distributed import Client
    except ImportError:
        raise MissingExtra("--scheduler needs Dask's distributed scheduler: pip install 'dpemu[distributed]'") from None
    with Client(scheduler) as client:
        futures = client.map(work, cases, pure=False)
        for future in futures:
            yield future.result()
