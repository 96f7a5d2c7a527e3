"""Helpers shared by the parser tests."""
from __future__ import annotations

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command

LOC = Loc("t.mcfunction", 1, 1)


def parse_ok(text: str, version=(1, 21, 0)):
    """The command's AST; fails the test if there is any error."""
    cmd, diags = parse_command(text, LOC, version)
    errors = [d for d in diags if d.severity == "error"]
    assert cmd is not None and not errors, [d.format() for d in diags]
    return cmd


def parse_err(text: str, version=(1, 21, 0)):
    """The first error diagnostic; fails the test if the command parses."""
    cmd, diags = parse_command(text, LOC, version)
    errors = [d for d in diags if d.severity == "error"]
    assert cmd is None and errors, f"{text!r} parsed as {cmd!r}"
    return errors[0]
