"""Host ops inside VM chains: context modifiers, conditions and stores the VM hands to Python."""
from __future__ import annotations

import pytest

from emulator.world.context import Context
from mcfunction_parser.nbt import Int
from tests.vm.helpers import run_main

pytestmark = pytest.mark.parametrize("backend", ["numba", "python"])  # the reference must agree

HELPERS = {"t:five": "return 5", "t:plain": "scoreboard players add #plain o 1"}


def test_modifiers_keep_the_server_context_and_run_functions(tmp_path, backend):
    emu, result = run_main(tmp_path, "execute positioned 1 2 3 align xz rotated 90 0 in minecraft:the_nether "
                                     "run function t:plain\n"
                                     "execute store result score #r o positioned ~ ~1 ~ run function t:five\n"
                                     "execute anchored eyes if function t:five run scoreboard players set #if o 1\n"
                                     "execute in minecraft:the_end run return run function t:five",
                           HELPERS, backend=backend)
    assert emu.score("#plain", "o") == 1
    assert emu.score("#r", "o") == 5
    assert emu.score("#if", "o") == 1
    assert result == 5
    assert emu.diagnostics == []


def test_entity_stages_select_nothing(tmp_path, backend):
    emu, _ = run_main(tmp_path, "execute as @e run function t:plain\n"
                                "execute store success score #s o as @a run scoreboard players set #x o 1\n"
                                "execute unless entity @e run scoreboard players set #none o 1\n"
                                "execute store result score #count o if entity @e", HELPERS, backend=backend)
    assert emu.score("#plain", "o") is None and emu.score("#x", "o") is None
    assert emu.score("#s", "o") is None  # no context ran the command: nothing stored
    assert emu.score("#none", "o") == 1
    assert emu.score("#count", "o") == 0  # the final condition failed: store result 0


def test_store_into_storage(tmp_path, backend):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 7\n"
                                "execute store result storage t:s v int 2 run scoreboard players get #a o",
                      backend=backend)
    assert emu.state.storage["t:s"]["v"] == Int(14)


def test_host_stage_costs(tmp_path, backend):
    emu, _ = run_main(tmp_path, "", {"t:f": "execute positioned 0 0 0 as @e run say hi"}, backend=backend)
    result = emu.runtime.call("t:f")
    assert result.cost == 1 + 2  # two stages, no context left to run `say`


def test_sanitizer_sees_host_arithmetic(tmp_path, backend):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 2147483647\nscoreboard players set #b o 5\n"
                                "scoreboard players add * o 1", sanitize=True, backend=backend)
    assert emu.score("#a", "o") == -2147483648
    assert [(o.function, o.loc.line, o.op, o.a, o.b, o.exact) for o in emu.overflows] == [
        ("t:main", 4, "add", 2147483647, 1, 2147483648)]


def _forking_summon(emu, n: int) -> None:
    """Make the host's ``summon`` stage (a redirect, as ``positioned`` is) give ``n`` contexts."""
    stage = emu.backend.host.run_stage

    def fork(st, ctx):
        if type(st).__name__ == "ExSummon":
            return [Context(pos=(float(i), 0.0, 0.0)) for i in range(n)]
        return stage(st, ctx)

    emu.backend.host.run_stage = fork


@pytest.mark.parametrize("body, cost, plain", [
    ("execute summon marker run function t:plain", 1 + 1 + 3 * (1 + 1), 3),
    ("execute summon marker summon marker run function t:plain", 1 + 2 + 9 * (1 + 1), 9),
    ("execute summon marker if score #one o matches 1 run scoreboard players add #plain o 1", 1 + 2 + 3, 3),
    ("execute summon marker unless score #one o matches 1 run scoreboard players add #plain o 1", 1 + 2, None),
])
def test_forked_chains_run_per_context(tmp_path, backend, body, cost, plain):
    if backend == "python":
        pytest.skip("the fork is simulated by patching the VM's host")
    emu, _ = run_main(tmp_path, "scoreboard players set #one o 1", {**HELPERS, "t:f": body}, backend=backend)
    _forking_summon(emu, 3)
    result = emu.runtime.call("t:f")
    # stages are charged once; each context runs the rest (a call and its add, or the add)
    assert (result.cost, emu.score("#plain", "o")) == (cost, plain)
    assert emu.diagnostics == []


def test_return_in_a_forked_chain_ends_the_function(tmp_path, backend):
    if backend == "python":
        pytest.skip("the fork is simulated by patching the VM's host")
    emu, _ = run_main(tmp_path, "", {**HELPERS, "t:f": "execute summon marker run function t:plain\n"
                                                       "execute summon marker run return 7\nsay never"},
                      backend=backend)
    _forking_summon(emu, 2)
    assert emu.call("t:f") == 7
    assert emu.score("#plain", "o") == 2 and emu.log == []


def test_context_modifiers_use_the_world_math(tmp_path, backend):
    if backend == "python":
        pytest.skip("reads the numba backend's context table")
    emu, _ = run_main(tmp_path, "", {"t:f": "execute positioned 1 2 3 rotated 90 0 positioned ^ ^ ^2 "
                                             "align y anchored eyes run say here"}, backend=backend)
    seen = []
    final = emu.backend.host.run_final
    emu.backend.host.run_final = lambda cmd, ctx: (seen.append(ctx), final(cmd, ctx))[1]
    emu.call("t:f")
    [ctx] = seen
    # positioned centres integer x/z; yaw 90 faces -x, so two blocks forward is x - 2
    assert ctx.pos == pytest.approx((1.5 - 2.0, 2.0, 3.5), abs=1e-6)
    assert ctx.rot == (90.0, 0.0) and ctx.anchor == "eyes"


def test_storage_data_commands(tmp_path, backend):
    emu, _ = run_main(tmp_path, "data modify storage t:s list set value [1, 2, 3]\n"
                                "data merge storage t:s {name: \"ball\", r: 2.5d}\n"
                                "execute store result score #len o run data get storage t:s list\n"
                                "execute store result score #r o run data get storage t:s r 10\n"
                                "data remove storage t:s list[0]\n"
                                "execute store result score #len2 o run data get storage t:s list\n"
                                "execute if data storage t:s name run scoreboard players set #named o 1\n"
                                "execute unless data storage t:s missing run scoreboard players set #none o 1\n"
                                "data modify storage t:s copy set from storage t:s list[-1]\n"
                                "execute store result score #copy o run data get storage t:s copy",
                      backend=backend)
    assert [emu.score(h, "o") for h in ("#len", "#r", "#len2", "#named", "#none", "#copy")] == [3, 25, 2, 1, 1, 3]
    assert emu.diagnostics == []


def test_enable_trigger(tmp_path, backend):
    emu, _ = run_main(tmp_path, "scoreboard objectives add go trigger\nscoreboard players enable Alex go\n"
                                "execute store success score #bad o run scoreboard players enable Alex o",
                      backend=backend)
    assert emu.score("Alex", "go") == 0 and emu.score("#bad", "o") == 0
    assert emu.diagnostics == []


ENTITY_BODY = """summon marker 0 0 0 {Tags:["a"]}
summon marker 1 0 0 {Tags:["a"]}
summon marker 2 0 0
execute as @e[tag=a] run scoreboard players add @s o 1
execute as @e[tag=a] run function t:count
execute store result score #c o if entity @e[tag=a]
execute as @e[tag=a] at @s run summon marker ~ ~1 ~
execute store result score #all o if entity @e
execute as @e[tag=a] store result score @s o run data get entity @s Pos[0]
execute as @e[type=marker,tag=!a] run say hi"""


def test_entities_through_the_world_library(tmp_path, backend):
    emu, _ = run_main(tmp_path, "", {"t:f": ENTITY_BODY, "t:count": "scoreboard players add #n o 1"}, backend=backend)
    root = emu.runtime.call("t:f")
    assert (emu.score("#n", "o"), emu.score("#c", "o"), emu.score("#all", "o")) == (2, 2, 5)
    assert [e["scores"] for e in emu.entities("@e[tag=a]")] == [{"o": 0}, {"o": 1}]  # x of each marker
    assert [entry.text for entry in emu.log] == ["[Marker] hi"] * 3
    # the call; 3 summons; as + 2 adds; as + 2 x (call + add); store + test; as + at + 2 summons;
    # store + test; as + store + 2 gets; as + 3 says
    assert root.cost == 1 + 3 + 3 + 5 + 2 + 4 + 2 + 4 + 4
    assert emu.diagnostics == []
