"""Running PackTest-format mcfunction test files (``data/<ns>/test/**.mcfunction``) in the emulator.

discovery finds test files and their packs; directives and testfile read one file into a
:class:`~emulator.testing.testfile.TestCase`; runner runs cases in fresh worlds; results and
junit report them.
"""
from emulator.testing.discovery import discover
from emulator.testing.results import Summary, TestResult
from emulator.testing.runner import run_suite

__all__ = ["Summary", "TestResult", "discover", "run_suite"]
