"""A line read before is relocated, not read again: the same AST and diagnostics as a fresh read."""
from __future__ import annotations

import dataclasses
import random
import sys
from pathlib import Path

import pytest

from mcfunction_parser import relocate as memory
from mcfunction_parser.parse import forget_read_lines, parse_function
from mcfunction_parser.relocate import NotRelocatable, relocate

from .mecha_corpus import BY_COMMAND

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
from corpus import _command  # noqa: E402


def _mutables(node, found: dict) -> dict:
    """id -> object of every dict and list reachable from ``node`` (NBT compounds and lists)."""
    if isinstance(node, (dict, list)):
        found[id(node)] = node
        for item in (node.values() if isinstance(node, dict) else node):
            _mutables(item, found)
    elif isinstance(node, tuple):
        for item in node:
            _mutables(item, found)
    elif dataclasses.is_dataclass(node) and not isinstance(node, type):
        for f in dataclasses.fields(node):
            _mutables(getattr(node, f.name), found)
    return found


def _check_relocated(lines: list[str], version) -> int:
    """Each line, read where it is and then again elsewhere (another file, line 3, indented): the
    second read equals a fresh read there and shares no mutable value with the first. Returns how
    many lines were relocated."""
    relocated = 0
    for text in lines:
        forget_read_lines()
        expected = parse_function(f"\n\n  {text}\n", "b.mcfunction", "t:b", version)
        forget_read_lines()
        first, _ = parse_function(f"{text}\n", "a.mcfunction", "t:a", version)
        again = parse_function(f"\n\n  {text}\n", "b.mcfunction", "t:b", version)
        assert again == expected, text
        assert not _mutables(first.commands, {}).keys() & _mutables(again[0].commands, {}).keys(), text
        relocated += type(memory.READ[version].get(text)) is tuple
    return relocated


def test_every_accepted_mecha_corpus_line_relocates_to_a_fresh_read():
    lines = [line for accepted, _ in BY_COMMAND.values() for line in accepted]
    relocated = _check_relocated(lines, (1, 21, 11))
    assert relocated > len(lines) // 2  # not a vacuous test: most lines are relocated


def test_generated_corpus_lines_relocate_to_a_fresh_read():
    rng = random.Random(7)
    lines = list(dict.fromkeys(_command(rng) for _ in range(1500)))
    relocated = _check_relocated(lines, (1, 21, 0))
    assert relocated > len(lines) // 2


def test_the_pool_pack_relocates_to_a_fresh_read():
    lines = {line.strip() for path in (ROOT / "datapack").rglob("*.mcfunction")
             for line in path.read_text().splitlines()}
    lines = sorted(line for line in lines if line and not line.startswith(("#", "$")) and not line.endswith("\\"))
    assert _check_relocated(lines, (1, 21, 4)) > len(lines) // 2


def test_a_line_with_nbt_is_read_each_time():
    # an NBT compound is mutable: two commands never share one
    forget_read_lines()
    text = "summon marker ~ ~ ~ {Tags:[\"a\"]}\n"
    function, _ = parse_function(text * 3, "a.mcfunction", "t:a", (1, 21, 0))
    compounds = [cmd.nbt for cmd in function.commands]
    assert compounds[0] == compounds[1] == compounds[2] and len({id(c) for c in compounds}) == 3
    assert memory.READ[(1, 21, 0)][text.strip()] is False
    with pytest.raises(NotRelocatable):
        relocate(function.commands[0], "b.mcfunction", 4, 0)


def test_a_line_with_a_diagnostic_reports_it_every_time():
    forget_read_lines()
    # an unknown rule is a warning in a release checked against a stand-in tree (1.15.2: 1.16.5's)
    function, diagnostics = parse_function("gamerule noSuchRule true\n  gamerule noSuchRule true\n", "a.mcfunction",
                                           "t:a", (1, 15, 2))
    assert [(d.severity, d.line, d.col) for d in diagnostics] == [("warning", 1, 10), ("warning", 2, 12)]
    assert len(function.commands) == 2 and function.commands[1].loc.line == 2


def test_relocation_moves_every_location_and_keeps_the_rest():
    forget_read_lines()
    text = "execute as @e[tag=a,limit=1] if score @s o matches 1.. run scoreboard players set #x o 1"
    function, _ = parse_function(f"{text}\n    {text}\n", "a.mcfunction", "t:a", (1, 21, 0))
    first, second = function.commands
    assert second.loc == first.loc.__class__("a.mcfunction", 2, 5)
    assert second.subcommands[0].targets.args[0].loc.col == first.subcommands[0].targets.args[0].loc.col + 4
    assert second.subcommands[1].range is first.subcommands[1].range  # immutable, no location: shared
    assert second.run.targets.loc.line == 2 and second.run.value == 1


def test_the_memory_holds_the_release_read_last():
    # a check over many releases keeps one release's lines alive, not every release's
    forget_read_lines()
    parse_function("say a\n", "a.mcfunction", "t:a", (1, 20, 4))
    parse_function("say a\n", "a.mcfunction", "t:a", (1, 21, 4))
    assert list(memory.READ) == [(1, 21, 4)] and "say a" in memory.READ[(1, 21, 4)]


def test_the_command_after_run_is_relocated_when_read_before():
    # the rest of an `execute ... run` (or `return run`) line read cleanly before, as a line or as
    # such a rest, is moved there: equal to a fresh read, sharing no mutable value with the first
    version = (1, 21, 0)
    tail = "scoreboard players operation @s a += #t b"
    modify = "data modify storage a:b x set value {a:[1]}"
    lines = [tail, f"execute as @e[tag=x] run {tail}", f"  execute if score @s a matches 1.. run {tail}",
             f"return run {tail}", f"execute run {modify}", f"execute as @s run {modify}"]
    fresh = []
    for i, line in enumerate(lines):  # each line alone, where it is in the file below
        forget_read_lines()
        fresh.append(parse_function("\n" * i + line + "\n", "a.mcfunction", "t:a", version)[0].commands[0])
    forget_read_lines()
    function, diagnostics = parse_function("".join(f"{line}\n" for line in lines), "a.mcfunction", "t:a", version)
    assert not diagnostics and list(function.commands) == fresh
    assert type(memory.READ[version][tail]) is tuple  # remembered as read cleanly
    assert memory.READ[version][modify] is False  # an NBT value: read each time
    assert not _mutables(function.commands[4], {}).keys() & _mutables(function.commands[5], {}).keys()


def test_a_rest_with_a_warning_or_on_joined_lines_is_read_each_time():
    version = (1, 21, 0)
    forget_read_lines()
    text = "execute as @s run gamerule noSuchRule true\nexecute as @e run gamerule noSuchRule true\n"
    _, diagnostics = parse_function(text, "a.mcfunction", "t:a", (1, 15, 2))  # a warning there (a stand-in tree)
    assert [(d.severity, d.line, d.col) for d in diagnostics] == [("warning", 1, 28), ("warning", 2, 28)]
    assert "gamerule noSuchRule true" not in memory.READ[(1, 15, 2)]
    forget_read_lines()
    joined = "scoreboard players set @s a 1\nexecute as @s \\\n  run scoreboard players set @s a 1\n"
    function, _ = parse_function(joined, "a.mcfunction", "t:a", version)
    assert function.commands[1].run.loc[1:] == (3, 7) and function.commands[1].run.targets.loc[1:] == (3, 30)


def test_a_subcommand_read_before_is_relocated_to_a_fresh_read():
    # a subcommand read cleanly up to a boundary (a space, a subcommand's name or run, a space) is
    # remembered with its text and moved where the same text comes again before any boundary
    version = (1, 21, 0)
    lines = ["execute as @e[tag=a,limit=2] at @s run say x",
             "execute as @e[tag=a,limit=2] if score @s o matches 1.. run say y",
             "  execute positioned as @s as @e[tag=a,limit=2] store result score @s o run say z",
             "execute if score @s o matches 1.. as @e[tag=a,limit=2] run say w",
             "execute store result score @s o if entity @e[nbt={a:1b}] as @s positioned as @s run say v",
             "execute if entity @e[nbt={a:1b}] unless score @s o matches 1..",
             "execute positioned as @s if score @s o matches 1.. run say u"]
    fresh = []
    for i, line in enumerate(lines):
        forget_read_lines()
        fresh.append(parse_function("\n" * i + line + "\n", "a.mcfunction", "t:a", version)[0].commands[0])
    forget_read_lines()
    function, diagnostics = parse_function("".join(f"{line}\n" for line in lines), "a.mcfunction", "t:a", version)
    assert not diagnostics and list(function.commands) == fresh
    read = memory.READ[version]
    assert type(read[" as @e[tag=a,limit=2]"]) is tuple and type(read[" if score @s o matches 1.."]) is tuple
    assert read[" if entity @e[nbt={a:1b}]"] is False  # an NBT value: read each time
    assert not _mutables(function.commands[4], {}).keys() & _mutables(function.commands[5], {}).keys()
    assert " positioned" not in read and " positioned as @s" not in read  # its first boundary is its argument


def test_a_subcommand_with_a_warning_is_read_each_time():
    # 1.21.7 has no registries of its own here: an id missing from 1.21.6's is a warning, every time
    version = (1, 21, 7)
    forget_read_lines()
    line = "execute summon minecraft:no_such_mob as @s run say a"
    _, diagnostics = parse_function(f"{line}\n  {line}\n", "a.mcfunction", "t:a", version)
    assert [(d.severity, d.line, d.col) for d in diagnostics] == [("warning", 1, 16), ("warning", 2, 18)]
    assert " summon minecraft:no_such_mob" not in memory.READ[version]
