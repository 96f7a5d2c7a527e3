"""PackTest directives: ``# @name [value]`` comments at the start of a test file, as documented in
misode/packtest's README. As PackTestFunction.fromLines reads them: only the leading run of lines
that start with ``#`` (a blank or indented line ends it); a name alone means ``true``.

- ``@template ID``: the structure (``data/<ns>/structure/<path>.nbt``) placed for the test with its
  corner at the test source, (0, 1, 0) (default: an empty 1x1x1 structure, nothing to place).
- ``@timeout N``: ticks before the test fails (default 100).
- ``@optional [true|false]``: the test may fail without failing the run (no value: true).
- ``@dummy [POS]``: spawn a dummy player as ``@s`` (default ``~0.5 ~ ~0.5``).
- ``@batch NAME``: the batch (default ``packtestBatch``).
- ``@beforebatch CMD`` / ``@afterbatch CMD``: a command run before / after the batch, one per batch.
- ``@environment ID`` (PackTest 2, 1.21.5+): the test environment (default ``minecraft:default``;
  see :mod:`emulator.testing.environments`).
- ``@skyaccess [true|false]`` (PackTest 2): false (the default) puts a barrier ceiling over the
  test as well as its walls and floor (TestInstanceBlockEntity.encaseStructure).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from mcfunction_parser.diagnostics import Diagnostic, Loc

DEFAULT_TIMEOUT = 100
DEFAULT_BATCH = "packtestBatch"
DEFAULT_DUMMY_POS = "~0.5 ~ ~0.5"
DEFAULT_ENVIRONMENT = "minecraft:default"
KNOWN = ("template", "timeout", "optional", "dummy", "batch", "beforebatch", "afterbatch", "environment", "skyaccess")
_DIRECTIVE = re.compile(r"#\s*@(\w+)(?:\s+(.+))?$")  # PackTestFunction.DIRECTIVE_PATTERN
_RESOURCE = re.compile(r"(?:[a-z0-9_.-]+:)?[a-z0-9_./-]+")


@dataclass
class Directives:
    template: str | None = None
    timeout: int = DEFAULT_TIMEOUT
    optional: bool = False
    dummy: str | None = None  # the spawn position when @dummy is given
    batch: str = DEFAULT_BATCH
    before_batch: tuple[str, Loc] | None = None
    after_batch: tuple[str, Loc] | None = None
    environment: str = DEFAULT_ENVIRONMENT
    sky_access: bool = False
    errors: list[Diagnostic] = field(default_factory=list)


def directive_match(line: str) -> re.Match | None:
    return _DIRECTIVE.match(line)


def apply(directives: Directives, match: re.Match, loc: Loc, source_line: str) -> None:
    """Apply one ``# @name value`` line; a bad one becomes an error in ``directives.errors``."""
    name, value = match.group(1), (match.group(2) or "").strip()
    error = _apply(directives, name, value, loc)
    if error:
        directives.errors.append(Diagnostic.at("error", error, loc, source_line))


def _apply(d: Directives, name: str, value: str, loc: Loc) -> str | None:
    if name == "template":
        if not _RESOURCE.fullmatch(value):
            return f"@template: expected a resource location, got {value!r}"
        d.template = value
    elif name == "timeout":
        if not value.isdigit() or int(value) <= 0:
            return f"@timeout: expected a positive number of ticks, got {value!r}"
        d.timeout = int(value)
    elif name in ("optional", "skyaccess"):
        if value.lower() not in ("", "true", "false"):
            return f"@{name}: expected true, false or nothing, got {value!r}"
        setattr(d, "optional" if name == "optional" else "sky_access", value.lower() != "false")
    elif name == "environment":
        if not _RESOURCE.fullmatch(value):
            return f"@environment: expected a resource location, got {value!r}"
        d.environment = value if ":" in value else "minecraft:" + value
    elif name == "dummy":
        d.dummy = value or DEFAULT_DUMMY_POS
    elif name == "batch":
        if not value:
            return "@batch: expected a batch name"
        d.batch = value
    elif name in ("beforebatch", "afterbatch"):
        if not value:
            return f"@{name}: expected a command"
        setattr(d, "before_batch" if name == "beforebatch" else "after_batch", (value, loc))
    else:
        return f"unknown directive '@{name}': expected one of " + ", ".join("@" + k for k in KNOWN)
    return None
