"""Predicates the VM evaluates itself (emulator.vm.predicate_rows): ``@e[predicate=P]`` and
``execute if|unless predicate P`` agree with the reference backend and run no host op."""
from __future__ import annotations

import json

import pytest

from tests.backends.programs import ENTITY_SETUP, PREDICATES, run_root, write_pack
from emulator.vm.entity_arrays import SelectorTables
from emulator.vm.predicate_rows import compile_predicate
from emulator.world.entity_table import EntityTable
from emulator.world.resources import Resources
from emulator.world.state import Scoreboard

FILES = {f"t/predicate/{name}.json": json.dumps(value) for name, value in PREDICATES.items()}
SETUP = ["scoreboard objectives add o dummy", "scoreboard objectives add p dummy", *ENTITY_SETUP,
         "scoreboard players set @e[tag=m] o 2", "scoreboard players set @e[tag=n] p 3",
         "scoreboard players set @e[tag=n] o 3"]


def _both(tmp_path, lines: list[str]):
    pack = write_pack(tmp_path / "pack", {"t:f0": "\n".join(SETUP + lines)}, files=FILES)
    reference, vm = run_root("python", pack, "t:f0"), run_root("numba", pack, "t:f0")
    assert vm.scores == reference.scores
    assert (vm.cost, vm.entities) == (reference.cost, reference.entities)
    assert [m for m, _ in vm.diagnostics] == [m for m, _ in reference.diagnostics]
    return reference.scores["o"]


@pytest.mark.parametrize("predicate, found", [
    ("marker", 6),  # EntityPredicate.type: the six markers, every level's (no position argument)
    ("!not_marker", 6),  # InvertedLootItemCondition of a ConditionReference
    ("types", 3),  # a HolderSet list: two armor stands and the display
    ("stand_or_o", 7),  # AnyOfCondition: the armor stands, and whoever has o >= 1
    ("scores", 1),  # EntityHasScoreCondition: o in -5..5 and p == 3 (only the marker tagged n)
    ("!o_set", 3),  # an unset score fails EntityHasScoreCondition: the display, the stand v and its marker r
    ("all", 6),  # a list of conditions: all must hold; all_of [] is true, any_of [] false (Util.allOf/anyOf)
    ("entity", 9),  # an empty entity predicate matches any entity
    ("team", 0),  # Entity.getTeam: none has a team
    ("creative", 0),  # PlayerPredicate: a player only
])
def test_selector_predicates_agree(tmp_path, predicate, found):
    scores = _both(tmp_path, [f"execute as @e[predicate={'!' if predicate[0] == '!' else ''}t:{predicate.lstrip('!')}] "
                              "run scoreboard players add #found o 1"])
    assert scores.get("#found", 0) == found


def test_if_predicate_reads_the_executor_or_none(tmp_path):
    """ExecuteCommand.checkCustomPredicate: the executor is ``this``; run by the server there is
    none, so an entity condition fails and a condition without an entity predicate holds
    (LootItemEntityPropertyCondition: no predicate is true)."""
    scores = _both(tmp_path, [
        "execute if predicate t:entity run scoreboard players add #server o 1",
        "execute if predicate t:any_entity run scoreboard players add #any o 1",
        "execute as @e if predicate t:scores run scoreboard players add #scores o 1",
        "execute as @e unless predicate t:stand_or_o run scoreboard players add #other o 1",
        "execute as @e[tag=n] store result score #count o if predicate t:o_set",
    ])
    assert (scores.get("#server", 0), scores["#any"], scores["#scores"], scores["#other"], scores["#count"]) == (0, 1, 1, 2, 1)


def test_inline_predicates(tmp_path):
    """``execute if predicate {...}`` (1.20.5+): the inline condition, with the executor as ``this``."""
    scores = _both(tmp_path, [
        'execute as @e if predicate {condition:"entity_scores",entity:"this",scores:{o:{min:3}}} '
        "run scoreboard players add #three o 1",
        'execute as @e unless predicate [{condition:"reference",name:"t:marker"},{condition:"all_of",terms:[]}] '
        "run scoreboard players add #other o 1"])
    assert (scores["#three"], scores["#other"]) == (1, 3)


def test_vm_predicates_run_no_host_op(tmp_path):
    from emulator import Emulator
    pack = write_pack(tmp_path / "pack", {"t:main": "\n".join(
        ["execute as @e[predicate=t:stand_or_o,predicate=!t:scores] run tag @s add q",
         "execute if predicate t:all run scoreboard players add #x o 1",
         'execute if predicate {condition:"inverted",term:{condition:"reference",name:"t:scores"}} run scoreboard players add #y o 1'])},
        files=FILES)
    emu = Emulator(backend="numba")
    emu.load(pack)
    emu.call("t:main")
    assert emu.backend.host_ops_run() == []


@pytest.mark.parametrize("name", ["nbt", "loop"])
def test_what_the_vm_does_not_read_stays_with_the_host(name):
    """An entity's NBT, and a reference back to itself (which the host reports), are the host's."""
    resources = Resources(predicates={f"t:{n}": v for n, v in PREDICATES.items()})
    tables = SelectorTables(Scoreboard(), EntityTable(), resources, (1, 21, 0))
    assert compile_predicate({"condition": "reference", "name": f"t:{name}"}, tables, (1, 21, 0)) is None
    assert tables.this_predicate(f"t:{name}") is None
    assert tables.this_predicate("t:marker") is not None


def test_26_2_entity_tags_and_entity_type(tmp_path):
    """26.2's sub-predicates (EntitySubPredicates): ``entity_type`` and ``entity_tags``
    (EntityTagPredicate: all_of, any_of, none_of)."""
    resources = Resources(predicates={"t:p": {"condition": "entity_properties", "entity": "this", "predicate": {
        "minecraft:entity_type": "marker", "entity_tags": {"all_of": ["m"], "any_of": ["a", "r"], "none_of": ["n"]}}}})
    tables = SelectorTables(Scoreboard(), EntityTable(), resources, (26, 2, 0))
    assert tables.this_predicate("t:p") is not None
    assert SelectorTables(Scoreboard(), EntityTable(), resources, (1, 21, 0)).this_predicate("t:p") is None


@pytest.mark.parametrize("stage, host_runs", [
    ("as @e[tag=zz,predicate=t:nbt]", 0),  # the tags find nobody: the host's predicate would test nobody
    ("as @a[predicate=t:nbt]", 0),  # no player
    ("if entity @e[tag=zz,nbt={}]", 0),
    ("unless entity @e[tag=zz,nbt={}]", 0),  # finds nobody: the context goes on
    ("as @r[gamemode=creative,predicate=t:nbt]", 0),
    ("as @e[tag=n,predicate=t:nbt]", 1),  # someone to test: the host runs it
    ("as @e[predicate=t:nbt,tag=zz]", 1),  # the host tests the predicate before the tag
])
def test_a_host_stage_that_would_test_nobody_is_skipped(tmp_path, stage, host_runs):
    """SelectorQuery tests each candidate with the arguments in their order: when the arguments
    before the first one only the host evaluates find nobody, the selector finds nobody and no
    entity meets that argument (no predicate is evaluated, nothing is reported), so the VM drops
    the context itself (an `unless entity` keeps it)."""
    from emulator import Emulator
    from emulator.vm import loop as vm
    lines = SETUP + [f"execute {stage} run scoreboard players add #ran o 1"]
    _both(tmp_path, lines)
    pack = write_pack(tmp_path / "one", {"t:setup": "\n".join(SETUP), "t:main": lines[-1]}, files=FILES)
    emu = Emulator(backend="numba")
    emu.load(pack)
    emu.call("t:setup")
    before = len(emu.backend.host_ops_run())
    emu.call("t:main")
    assert len(emu.backend.host_ops_run()) - before == host_runs
    assert vm.OP_HOSTGUARD in {row[0] for row in emu.backend.program.rows}
