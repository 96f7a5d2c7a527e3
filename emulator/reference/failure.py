"""Command failures: the reference backend's ``CommandSyntaxException``."""
from __future__ import annotations


class CommandFailure(Exception):
    """A command failed with the game's message.

    ``report``: also record a runtime diagnostic (with the function traceback). Failures that
    datapacks rely on routinely (a test that fails, ``objectives add`` of an existing objective,
    ``get`` of an unset score) are silent, as in the game; failures that point at a bug or at a
    limit of the emulator (division by zero, unknown objective or function, unsupported command)
    are reported.
    """

    def __init__(self, message: str, report: bool = False) -> None:
        super().__init__(message)
        self.message = message
        self.report = report


def unknown_objective(name: str) -> CommandFailure:
    return CommandFailure(f"Unknown scoreboard objective '{name}'", report=True)


def unsupported(what: str) -> CommandFailure:
    """A command or stage the emulator cannot run yet (worded as the numba backend's host does)."""
    return CommandFailure(f"{what} is not supported yet", report=True)
