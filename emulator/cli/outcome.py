"""How every subcommand ends: one exit-code rule, progress on long work, and Ctrl-C.

- 0: clean.
- 1: the pack or the run had errors: load errors, runtime diagnostics of severity error,
  sanitizer findings, failed tests, a refused or unfinished shot, an output that could not be
  written. ``--no-fail-on-diagnostics`` turns the pack's and the run's errors back into 0 (a
  failed write still counts).
- 2: usage errors (click's own).
- 130: interrupted (Ctrl-C), after printing what was done so far.
"""
from __future__ import annotations

import sys
from contextlib import contextmanager

import click

CLEAN, PROBLEMS, USAGE, INTERRUPTED = 0, 1, 2, 130


def fail_option(command):
    """``--no-fail-on-diagnostics``, for the subcommands that run packs."""
    return click.option("--no-fail-on-diagnostics", "no_fail", is_flag=True,
                        help="Exit 0 even when the pack or the run had errors (diagnostics, wrapped values).")(command)


def exit_status(problems: bool, no_fail: bool = False, written: bool = True, interrupted: bool = False) -> int:
    if interrupted:
        return INTERRUPTED
    if not written:
        return PROBLEMS
    return PROBLEMS if problems and not no_fail else CLEAN


def has_errors(diagnostics) -> bool:
    return any(d.severity == "error" for d in diagnostics)


class _Quiet:
    """A progress bar that shows nothing (standard error is not a terminal)."""

    def update(self, n: int) -> None:
        pass


@contextmanager
def progress(length: int, label: str, minimum: int = 1):
    """A progress bar on standard error when it is a terminal and the job has ``minimum`` steps or
    more; nothing at all otherwise (no stray label in logs)."""
    if length < minimum or not sys.stderr.isatty():
        yield _Quiet()
        return
    with click.progressbar(length=length, label=label, file=sys.stderr) as bar:
        yield bar


class Passes:
    """A progress bar per pass over a job that reports ``(done, total)`` (``dpemu check`` parses
    every function once per release it checks); nothing when standard error is not a terminal."""

    def __init__(self, label: str, minimum: int = 200) -> None:
        self.label, self.minimum = label, minimum
        self._bar = None
        self.shown = sys.stderr.isatty()

    def __call__(self, done: int, total: int) -> None:
        if not self.shown or total < self.minimum:
            return
        if done == 1:
            self.close()
            self._bar = click.progressbar(length=total, label=self.label, file=sys.stderr)
            self._bar.__enter__()
        if self._bar is not None:
            self._bar.update(1)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.__exit__(None, None, None)
            self._bar = None


@contextmanager
def interruptible():
    """Ctrl-C ends the work cleanly: the body's ``stopped[0]`` becomes True and the caller goes on
    to print what was done (click would print "Aborted!" and lose it)."""
    stopped = [False]
    try:
        yield stopped
    except KeyboardInterrupt:
        stopped[0] = True
        click.echo("\ninterrupted: what ran until then follows", err=True)
