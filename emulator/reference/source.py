"""Command sources (the game's ``CommandSourceStack``) and call traces.

A :class:`Source` is who runs a command and where (:class:`emulator.world.state.Context`), the callback
its result goes to (``execute store`` chains callbacks), and the :class:`Activation` it runs in,
which serves diagnostics (the function traceback of a runtime error) and the call stack each quota
unit is charged in (:class:`emulator.runtime.backend.CallRecorder`).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from emulator.world.context import Context
from emulator.world.records import Frame
from mcfunction_parser.diagnostics import Loc

from .queue import Callback


@dataclass(frozen=True, slots=True)
class Activation:
    """A function being run: its id, and where it was called from (None for a root).

    A linked list so that a 100,000-deep chain costs O(1) per call; frames are built only when
    a diagnostic needs them.
    """

    function: str
    parent: "Activation | None" = None
    call_loc: Loc | None = None

    def frames(self, loc: Loc | None) -> tuple[Frame, ...]:
        """Root first; the innermost frame is this function at ``loc`` (the failing command)."""
        out: list[Frame] = []
        here, at = self, loc
        while here is not None:
            if at is not None:
                out.append(Frame(here.function, at))
            here, at = here.parent, here.call_loc
        return tuple(reversed(out))

    def stack(self) -> tuple[str, ...]:
        """The functions from the root to this one."""
        out: list[str] = []
        here = self
        while here is not None:
            out.append(here.function)
            here = here.parent
        return tuple(reversed(out))


@dataclass(frozen=True, slots=True)
class Source:
    context: Context
    callback: Callback
    activation: Activation

    def with_callback(self, callback: Callback) -> "Source":
        return dataclasses.replace(self, callback=callback)

    def in_context(self, context: Context) -> "Source":
        return dataclasses.replace(self, context=context)

    def in_function(self, activation: Activation) -> "Source":
        return dataclasses.replace(self, activation=activation)
