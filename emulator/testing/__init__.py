"""Running PackTest-format mcfunction test files (``data/<ns>/test/**.mcfunction``) in the emulator.

discovery finds test files and their packs; directives and testfile read one file into a
:class:`~emulator.testing.testfile.TestCase`; batches orders and places them as the game test
server does; runner runs them in one world (or each in a fresh one); results and junit report
them. The format is misode/packtest's (README and PackTestFunction):

- the tests share one world (the packs loaded and ``#minecraft:load`` run), batch after batch, a
  batch's tests together; the test's commands run as the server (or its ``@dummy`` player) at its
  structure's corner on the grid ((0, 1, 0) for the first);
- ``assert [not] COND`` / ``await [not] COND`` with the conditions of ``execute if`` (checked by
  the emulator itself) and PackTest's ``chat PATTERN``; ``await delay TIME`` (``await for`` in
  older PackTest); ``fail MESSAGE``; ``succeed``; each also after ``execute ... run``;
- ``await`` ticks the world (``#minecraft:tick``, schedules) until the condition holds or the
  ``@timeout`` (100 ticks) runs out; a test that reaches its end passes;
- ``@template ID`` places the structure file's blocks and entities with its corner at the test
  source (:mod:`emulator.world.structures`);
- ``dummy <player> <action>``: simulated players (:mod:`emulator.testing.dummies` says what each
  action changes, and which actions fail the test as not modelled).

``assert``, ``fail`` and ``succeed`` run by a function the test calls are PackTest's registered
commands (:mod:`emulator.commands.packtest`; the packs load and run inside
:func:`mcfunction_parser.dialect.packtest_commands`): they reach the test through its helper.
"""
from emulator.testing.discovery import discover
from emulator.testing.results import Summary, TestResult
from emulator.testing.runner import run_suite

__all__ = ["Summary", "TestResult", "discover", "run_suite"]
