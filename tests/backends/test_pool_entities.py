"""The pool datapack (ball state on ``@e[tag=pool.ball]`` entities) on the real emulator: the
table set up by a player, one shot, then ticks; both backends must agree on every score, entity
and cost, and the hot path must not need the host for ``@s`` scores."""
from __future__ import annotations

from pathlib import Path

import pytest

from emulator.api import Emulator
from mcfunction_parser.nbt import Compound, Int

PACK = Path(__file__).resolve().parents[2] / "datapack"
SHOT = Compound(angle=Int(1500), speed=Int(1500), tip_x=Int(0), tip_y=Int(0), elevation=Int(0))
TICKS = 25


def play(backend: str) -> Emulator:
    emu = Emulator(backend=backend)
    emu.load(PACK)
    emu.add_player("Alex", (10.0, 64.0, 10.0), (0.0, 0.0))
    emu.tick()  # #minecraft:load
    emu.call("pool:table/setup", as_="Alex")
    emu.call("pool:api/shot", arguments=SHOT)
    emu.tick(TICKS)
    return emu


@pytest.fixture(scope="module")
def runs():
    if not (PACK / "pack.mcmeta").exists():
        pytest.skip("no pool datapack in this checkout")
    return play("python"), play("numba")


def test_table_is_racked_at_the_player(runs):
    reference, _ = runs
    balls = reference.entities("@e[tag=pool.ball]")
    assert len(balls) == 16
    assert all(ball["type"] == "minecraft:item_display" for ball in balls)
    assert reference.diagnostics == []


def test_both_backends_agree_on_a_shot(runs):
    reference, vm = runs
    assert vm.scores() == reference.scores()
    assert vm.entities() == reference.entities()
    assert vm.commands_per_tick == reference.commands_per_tick
    assert vm.diagnostics == reference.diagnostics == []


def test_the_cue_ball_moved(runs):
    reference, _ = runs
    cue = reference.entities("@e[tag=pool.ball,scores={pool.id=0}]")
    assert len(cue) == 1 and cue[0]["scores"]["pool.state"] in (1, 2)  # sliding or rolling


def test_score_commands_on_self_need_no_host(runs):
    # `scoreboard players ... @s ...` is most of the tick: the VM runs it (a per-context holder id)
    from emulator.vm import loop as vm_ops
    from mcfunction_parser import ast

    _, vm = runs
    program, counts = vm.backend.program, vm.backend.counts
    host_nodes = [program.host_ops[row[1]].node for pc, row in enumerate(program.rows)
                  if row[0] == vm_ops.OP_HOST and counts[pc]]
    assert host_nodes, "the pool pack still has host commands (tags, selectors)"
    def bare_self(holder) -> bool:
        return isinstance(holder, ast.Selector) and holder.variable == "s" and not holder.args

    def only_self_or_names(node) -> bool:
        holders = [getattr(node, key) for key in ("targets", "target", "sources") if hasattr(node, key)]
        return all(bare_self(h) or isinstance(h, ast.NameTarget) for h in holders) and any(map(bare_self, holders))

    score_commands = (ast.ScoreSet, ast.ScoreOperation, ast.ScoreGet, ast.ScoreReset)
    assert not [n for n in host_nodes if isinstance(n, score_commands) and only_self_or_names(n)]
