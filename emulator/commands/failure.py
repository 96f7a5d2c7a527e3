"""The one failure of a command: the game's ``CommandSyntaxException``, raised by every command,
argument and world rule the emulator runs, on both backends.

A failing command fails (result 0, ``store success`` 0) and the run goes on. ``report``: also
record a runtime diagnostic at the command (with the function traceback). Failures that datapacks
rely on routinely (a test that fails, ``objectives add`` of an existing objective, ``get`` of an
unset score) are silent, as in the game; failures that point at a pack bug (division by zero, an
unknown objective or function) or at a limit of the emulator (an unsupported stage) are reported.
"""
from __future__ import annotations

from emulator.world.errors import EMULATOR_MESSAGES, MESSAGES


class CommandFailure(Exception):
    """A failure with the message of ``key`` (a key of :data:`MESSAGES`, or the emulator's own
    ``dpemu.*`` of :data:`EMULATOR_MESSAGES`) filled with ``args``."""

    def __init__(self, key: str, *args, report: bool = False) -> None:
        self.key = key
        self.message = (MESSAGES.get(key) or EMULATOR_MESSAGES[key]).format(*args)
        self.report = report
        super().__init__(self.message)
