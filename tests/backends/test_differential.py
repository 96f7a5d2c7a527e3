"""Differential fuzzing: random scoreboard programs must behave identically on the numba VM and
the reference backend (scores, the function's result, command cost, quota cut, overflow reports
under the sanitizer, log, entities, command storage, pending schedules, gamerules, diagnostic messages).

300 programs by default; set DPEMU_FUZZ_EXAMPLES for more (e.g. 5000 in a nightly job).
A failing program is printed in full by hypothesis (the ``note``), ready to paste into a pack.
"""
from __future__ import annotations

import os
import re

import pytest
from hypothesis import HealthCheck, assume, given, note, settings
from hypothesis import strategies as st

from tests.backends.programs import programs, run_root, write_pack

EXAMPLES = int(os.environ.get("DPEMU_FUZZ_EXAMPLES", "300"))

settings.register_profile(
    "differential",
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.function_scoped_fixture],
)

PROGRAMS = programs()


# Programs with a construct the VM gets wrong (see VM_GAPS in test_java_edge_cases.py) are
# skipped until it is fixed; everything else must agree.
KNOWN_VM_GAPS: dict[str, re.Pattern] = {
    # The game instantiates every member of a tag call before running any: a macro member that
    # cannot be instantiated fails the command first, then the members before it run. The VM
    # instantiates each member just before calling it: the same scores and result, but a quota
    # cut (or a log line) in an earlier member comes before the failure instead of after it.
    "tag call whose macro member fails": re.compile(r"function #t:macs$", re.M),
}


def _compare(tmp_path_factory, program, sanitize: bool, limit: int | None = None) -> None:
    assume(not any(gap.search(program.text()) for gap in KNOWN_VM_GAPS.values()))
    note(program.text())
    pack = write_pack(tmp_path_factory.mktemp("pack"), program.functions, program.tags, files=program.files)
    reference = run_root("python", pack, program.entry, sanitize=sanitize, limit=limit)
    vm = run_root("numba", pack, program.entry, sanitize=sanitize, limit=limit)
    assert not [m for m, _ in reference.diagnostics if m.startswith("internal error")]
    _assert_agree(vm, reference, sanitize)


def _assert_agree(vm, reference, sanitize: bool) -> None:
    assert vm.scores == reference.scores
    assert vm.result == reference.result
    assert (vm.cost, vm.cut) == (reference.cost, reference.cut)
    assert vm.roots == reference.roots
    assert vm.line_costs == reference.line_costs
    assert vm.log == reference.log
    assert vm.entities == reference.entities
    assert vm.storage == reference.storage
    assert (vm.schedules, vm.gamerules) == (reference.schedules, reference.gamerules)
    # the messages (a quota cut on a root's last command has its frame on the VM only)
    assert [m for m, _ in vm.diagnostics] == [m for m, _ in reference.diagnostics]
    if sanitize:
        # the VM names a macro instance "ns:f#N"; the reference names the function. Sorted: '*'
        # walks holders in interning order, which differs between the backends (the VM interns
        # the names in its code at compile time) and is a hash order in the game anyway
        vm_overflows = sorted((o[0].split("#")[0],) + o[1:] for o in vm.overflows)
        assert vm_overflows == sorted(reference.overflows)


@settings.get_profile("differential")
@given(program=PROGRAMS)
def test_random_programs_agree(tmp_path_factory, program):
    _compare(tmp_path_factory, program, sanitize=False)


@settings(settings.get_profile("differential"), max_examples=max(EXAMPLES // 3, 20))
@given(program=PROGRAMS)
def test_random_programs_agree_under_sanitizer(tmp_path_factory, program):
    _compare(tmp_path_factory, program, sanitize=True)


# Execute chains with context modifiers (positioned, align, in, as @e ...) around calls and returns
@settings(settings.get_profile("differential"), max_examples=max(EXAMPLES // 3, 20))
@given(program=programs(modifiers=True))
def test_random_programs_with_context_modifiers_agree(tmp_path_factory, program):
    _compare(tmp_path_factory, program, sanitize=False)


# A small maxCommandChainLength cuts programs anywhere: the same partial work must be done
@settings(settings.get_profile("differential"), max_examples=max(EXAMPLES // 3, 20))
@given(program=programs(modifiers=True), limit=st.integers(1, 60))
def test_quota_cuts_agree(tmp_path_factory, program, limit):
    _compare(tmp_path_factory, program, sanitize=False, limit=limit)


# Runtime problems read the same on both backends: message and function traceback
FAILING_LINES = [
    "function t:missing", "function #t:missing", "function #t:empty", "function t:macro", "function t:macro {x:1}",
    "scoreboard players operation #a o /= #z o", "scoreboard players set #a nope 1",
    "execute if function t:missing run say x",
    "schedule function t:missing 1t", "schedule function t:f 0t", "locate biome minecraft:plains",
    "execute if biome ~ ~ ~ minecraft:plains run say x",
    "function t:macro with storage t:none args",
]


@pytest.mark.parametrize("line", FAILING_LINES)
def test_runtime_diagnostics_agree(tmp_path, line):
    functions = {"t:main": "scoreboard objectives add o dummy\nfunction t:f", "t:f": line, "t:macro": "$say $(y)"}
    pack = write_pack(tmp_path / "pack", functions, {"t:empty": []})
    reference, vm = run_root("python", pack, "t:main"), run_root("numba", pack, "t:main")
    assert reference.diagnostics, "the reference reports the problem"
    # the messages (a quota cut on a root's last command has its frame on the VM only)
    assert [m for m, _ in vm.diagnostics] == [m for m, _ in reference.diagnostics]
    assert vm.cost == reference.cost


# Entities: markers selected (by the VM's own selectors and by the host's), tagged, killed, moved
# by store ... Pos[i], read by data get and used as score holders; several contexts per stage
# exercise the per-context costs, return-run's first context and if function per context
@settings(settings.get_profile("differential"), max_examples=max(EXAMPLES // 3, 20))
@given(program=programs(modifiers=True, entities=True))
def test_random_programs_with_entities_agree(tmp_path_factory, program):
    _compare(tmp_path_factory, program, sanitize=False)


# ExecuteCommand.storeValue resolves a store's holders once, at the stage: a random holder is one
# draw, so every later random pick agrees with the reference (a second draw shifts them all)
def test_store_into_a_random_holder_draws_once(tmp_path):
    markers = "".join(f"summon marker {i} 0 0\n" for i in range(8))
    pick = "@e[type=marker,sort=random,limit=1]"
    body = (f"scoreboard objectives add o dummy\nscoreboard objectives add p dummy\n{markers}"
            f"execute store result score {pick} o run scoreboard players set #x o 7\n"
            f"execute store result entity {pick} Air short 1 run scoreboard players set #y o 9\n"
            + f"execute as {pick} run scoreboard players add @s p 1\n" * 6)
    pack = write_pack(tmp_path / "pack", {"t:main": body})
    reference, vm = run_root("python", pack, "t:main"), run_root("numba", pack, "t:main")
    assert sum(v == 7 for v in reference.scores["o"].values()) == 2  # #x and the one marker
    assert vm.scores == reference.scores


# The auto backend (emulator.runtime.auto) runs the reference backend, then moves to the VM between
# two roots: the entry run as three roots on one world, the switch after the first or the second,
# leaves what the reference alone leaves (the VM compiles the packs into a world already changed)
@settings(settings.get_profile("differential"), max_examples=max(EXAMPLES // 3, 20))
@given(program=programs(modifiers=True, entities=True), switch=st.sampled_from([1, 2]), sanitize=st.booleans())
def test_switching_to_the_vm_between_roots_agrees(tmp_path_factory, program, switch, sanitize):
    from emulator.runtime.auto import ROOT_WORK

    assume(not any(gap.search(program.text()) for gap in KNOWN_VM_GAPS.values()))
    note(program.text())
    pack = write_pack(tmp_path_factory.mktemp("pack"), program.functions, program.tags, files=program.files)
    reference = run_root("python", pack, program.entry, sanitize=sanitize, roots=3)
    work = sum(cost + ROOT_WORK for _, cost, _ in reference.roots[:switch])
    switched = run_root("auto", pack, program.entry, sanitize=sanitize, roots=3, switch_after=work)
    assert switched.ran.startswith("python, then numba from tick 0")
    assert not [m for m, _ in reference.diagnostics if m.startswith("internal error")]
    _assert_agree(switched, reference, sanitize)
