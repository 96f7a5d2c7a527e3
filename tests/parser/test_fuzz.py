"""Random and mutated input never raises: it parses or yields diagnostics with sane positions."""
from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command, parse_function
from test_mecha_agreement import INVALID, VALID

SEEDS = VALID + INVALID
ALPHABET = st.sampled_from(list(" @[]{}()=,.:;!#$^~\\\"'-+0123456789abcdefxyzABC_/\t\n") + ["\u00e9", "\u2603"])
VERSIONS = st.sampled_from([(1, 16, 5), (1, 19, 4), (1, 20, 2), (1, 20, 3), (1, 21, 0), (1, 21, 5)])


def _check(source: str, version) -> None:
    function, diags = parse_function(source, "f.mcfunction", "t:f", version)
    physical = source.split("\n")
    for d in diags:
        assert d.severity in ("error", "warning") and d.message
        assert 1 <= d.line <= len(physical)
        assert 1 <= d.col <= len(physical[d.line - 1]) + 1
        d.format()
    assert len(function.commands) <= len(physical)


@settings(max_examples=300, deadline=None)
@given(st.text(ALPHABET, max_size=80), VERSIONS)
def test_random_text(text, version):
    _check(text, version)


@st.composite
def mutated(draw):
    line = draw(st.sampled_from(SEEDS))
    for _ in range(draw(st.integers(1, 3))):
        pos = draw(st.integers(0, len(line)))
        action = draw(st.sampled_from(["insert", "delete", "replace", "truncate"]))
        char = draw(ALPHABET)
        if action == "insert":
            line = line[:pos] + char + line[pos:]
        elif action == "delete":
            line = line[:pos] + line[pos + 1:]
        elif action == "replace":
            line = line[:pos] + char + line[pos + 1:]
        else:
            line = line[:pos]
    return line


@settings(max_examples=400, deadline=None)
@given(mutated(), VERSIONS)
def test_mutated_valid_lines(line, version):
    _check(line, version)
    cmd, diags = parse_command(line.strip() or "x", Loc("m", 3, 5), version)
    assert cmd is not None or any(d.severity == "error" for d in diags)
    for d in diags:
        assert d.line == 3 and d.col >= 5


@settings(max_examples=100, deadline=None)
@given(st.lists(st.sampled_from(SEEDS + ["", "# c", "say a \\", "  \\", "$say $(k) \\"]), max_size=12), VERSIONS)
def test_whole_files(lines, version):
    _check("\n".join(lines), version)
