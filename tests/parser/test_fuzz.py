"""Random and mutated input never raises: it parses or yields diagnostics with sane positions."""
from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command, parse_function
from tests.parser.test_mecha_agreement import INVALID, VALID

# lines exercising the fast paths, caches and the 1.21.5 SNBT grammar, whose mutations reach new branches
FAST_PATH_SEEDS = [
    "execute if score @s obj matches 1..5 unless score #a obj matches ..-1 run scoreboard players set @s o 1",
    "execute as @e[tag=a,limit=1] positioned ~1 ~.5 ~ run tp @s 1 2 3",
    "data merge storage a:b {h:0xFFub,b:0b101,u:1_000,e:1e3,f:-1.5e-3f,l:[B;1,2],i:[I;1b,2s],g:[L;1,0x7Fl]}",
    "summon marker ~ ~ ~ {Tags:[\"a\"],data:{x:[1,2b,{y:TRUE}]}}",
]
SEEDS = VALID + INVALID + FAST_PATH_SEEDS
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
