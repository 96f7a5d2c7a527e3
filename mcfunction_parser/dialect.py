"""Whether PackTest's commands are read (``assert``, ``fail``, ``succeed`` in any function): on a
server with the PackTest mod they are registered commands, elsewhere unknown ones. The parsers ask
:func:`packtest_enabled`; ``dpemu test`` and the pytest plugin load and run packs inside
:func:`packtest_commands` (see :mod:`mcfunction_parser.commands.packtest`)."""
from __future__ import annotations

import contextlib
from contextvars import ContextVar

from .relocate import forget_read_lines

_PACKTEST: ContextVar[bool] = ContextVar("packtest_commands", default=False)


def packtest_enabled() -> bool:
    return _PACKTEST.get()


@contextlib.contextmanager
def packtest_commands():
    """Read PackTest's commands inside the block. The parser's memory of texts read
    (:mod:`mcfunction_parser.relocate`) is emptied when it ends: a text read there as one of them
    is an unknown command outside (the texts read before read the same inside: the dialect only
    adds commands)."""
    token = _PACKTEST.set(True)
    try:
        yield
    finally:
        _PACKTEST.reset(token)
        forget_read_lines()
