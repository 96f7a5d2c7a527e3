"""pytest plugin (entry point ``pytest11``): fixtures and assertion helpers for packs, and
PackTest-format mcfunction test files collected as pytest items.

Fixtures: ``dpemu_pack(*paths, backend=None, load=True)`` returns a fresh :class:`Emulator` with
the packs loaded (and ``#minecraft:load`` run); ``emulator`` is a fresh emulator with no pack.
``--dpemu-backend numba|python`` picks the default backend; an mcfunction test that meets what the
emulator does not model is skipped as inconclusive, with the reason (``--dpemu-allow-unmodelled``
judges it by its assertions, as ``dpemu test --allow-unmodelled``); ``--dpemu-game-jar JAR|auto`` loads
the game's vanilla data under the packs (as ``--game-jar``).

mcfunction tests are opt-in: ``--mcfunction-tests PATH`` (repeatable) or the ini option
``mcfunction_tests`` (paths relative to the rootdir) name packs, folders or test files.

Helpers: :func:`assert_score`, :func:`assert_position`, :func:`assert_entity_position`.
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest


def pytest_addoption(parser) -> None:
    group = parser.getgroup("dpemu")
    group.addoption("--mcfunction-tests", action="append", default=[], metavar="PATH",
                    help="collect PackTest-format test files (data/<ns>/test/**.mcfunction) under PATH")
    group.addoption("--dpemu-backend", choices=["numba", "python"], default="numba",
                    help="emulator backend for the dpemu fixtures and mcfunction tests (default numba)")
    group.addoption("--dpemu-game-jar", metavar="JAR|auto", default=None,
                    help="the game's jar whose vanilla tags, loot tables and recipes load under the packs "
                         "('auto': the launcher's jar of the packs' release, else downloaded and cached)")
    group.addoption("--dpemu-allow-unmodelled", action="store_true",
                    help="judge a test that meets behaviour the emulator does not model by its assertions "
                         "(by default it is skipped as inconclusive, with the reason)")
    parser.addini("mcfunction_tests", type="paths", default=[],
                  help="packs or folders whose PackTest-format test files are collected")


# ---------------------------------------------------------------------- fixtures and helpers
@pytest.fixture
def emulator(request):
    from emulator.api import Emulator

    return Emulator(backend=request.config.getoption("dpemu_backend"))


@pytest.fixture
def dpemu_pack(request):
    from emulator.api import Emulator
    from emulator.testing.runner import run_load

    def load(*paths, backend: str | None = None, load: bool = True) -> Emulator:
        emu = Emulator(backend=backend or request.config.getoption("dpemu_backend"))
        emu.load(list(paths), game_jar=request.config.getoption("dpemu_game_jar"))
        errors = [d.format() for d in emu.load_diagnostics if d.severity == "error"]
        if errors:
            pytest.fail("the pack has errors:\n" + "\n".join(errors), pytrace=False)
        return run_load(emu) if load else emu

    return load


def assert_score(emu, holder: str, objective: str, expected: int, tolerance: int = 0) -> None:
    """Fail unless the score is set and within ``tolerance`` of ``expected``."""
    __tracebackhide__ = True
    value = emu.score(holder, objective)
    wanted = f"{expected}" + (f" ± {tolerance}" if tolerance else "")
    if value is None or abs(value - expected) > tolerance:
        found = "undefined" if value is None else value
        raise AssertionError(f"Expected score {holder} {objective} to be {wanted}, found {found}")


def assert_position(entity, expected, tolerance: float = 1e-6) -> None:
    """Fail unless ``entity`` (an :meth:`Emulator.entities` dict, anything with ``pos``, or an
    (x, y, z) tuple) is within ``tolerance`` blocks (Euclidean) of ``expected``."""
    __tracebackhide__ = True
    pos = entity["pos"] if isinstance(entity, dict) else getattr(entity, "pos", entity)
    pos = tuple(pos)
    distance = math.dist(pos, tuple(expected))
    if not distance <= tolerance:
        raise AssertionError(f"Expected position {tuple(expected)} ± {tolerance}, found {pos} (off by {distance:.6g})")


def assert_entity_position(emu, selector: str, expected, tolerance: float = 1e-6) -> None:
    """Fail unless ``selector`` finds exactly one entity and it is within ``tolerance`` of ``expected``."""
    __tracebackhide__ = True
    found = emu.entities(selector)
    if len(found) != 1:
        raise AssertionError(f"Expected one entity for {selector}, found {len(found)}")
    assert_position(found[0], expected, tolerance)


# ---------------------------------------------------------------------- mcfunction test items
class McfunctionTestFailure(Exception):
    pass


class McfunctionItem(pytest.Item):
    def __init__(self, *, case, packs, backend: str, allow_unmodelled: bool = False, **kwargs) -> None:
        super().__init__(**kwargs)
        self.case, self.packs, self.backend, self.allow_unmodelled = case, packs, backend, allow_unmodelled

    def runtest(self) -> None:
        from emulator.testing.results import FAILED, INCONCLUSIVE, SKIPPED
        from emulator.testing.runner import run_case

        result = run_case(self.case, self.packs, self.backend, allow_unmodelled=self.allow_unmodelled)
        if result.log:  # shown with a failure, as pytest shows captured output
            self.add_report_section("call", "chat", "\n".join(result.log))
        if result.status == INCONCLUSIVE:  # it met what is not modelled: neither passed nor failed
            pytest.skip(f"inconclusive: {result.where}: {result.message}")
        if result.status == SKIPPED or (result.status == FAILED and result.optional):
            pytest.skip(f"{result.where}: {result.message}" + (" (optional test)" if result.optional else ""))
        if result.status == FAILED:
            raise McfunctionTestFailure(result)

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, McfunctionTestFailure):
            return excinfo.value.args[0].report()
        return super().repr_failure(excinfo, style)

    def reportinfo(self):
        return self.path, None, self.case.id


@pytest.hookimpl(tryfirst=True)  # before -k and -m deselect
def pytest_collection_modifyitems(session, config, items) -> None:
    paths = config.getoption("mcfunction_tests") or config.getini("mcfunction_tests")
    if not paths:
        return
    from emulator.testing.discovery import DiscoveryError, discover
    from emulator.testing.runner import load_suite
    from mcfunction_parser.dialect import packtest_commands

    try:
        files = discover([Path(p) for p in paths])
    except DiscoveryError as error:
        raise pytest.UsageError(f"--mcfunction-tests: {error}") from None
    backend, allow = config.getoption("dpemu_backend"), config.getoption("dpemu_allow_unmodelled")
    with packtest_commands():  # as run_suite loads them: on a server with PackTest
        suite = list(load_suite(files, game_jar=config.getoption("dpemu_game_jar")))
    for packs, cases in suite:
        for case in cases:
            path = Path(case.path).resolve()
            nodeid = f"{_relative(path, config.rootpath)}::{case.id}"
            items.append(McfunctionItem.from_parent(session, name=case.id, nodeid=nodeid, path=path,
                                                    case=case, packs=packs, backend=backend, allow_unmodelled=allow))


def _relative(path: Path, root: Path) -> str:
    try:
        return path.relative_to(root).as_posix()
    except ValueError:
        return path.as_posix()
