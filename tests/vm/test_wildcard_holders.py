"""``*`` as a score holder in the VM (OP_SELHOLDERS with SEL_TRACKED): every tracked holder, as
ScoreHolderArgument.getNamesWithDefaultWildcard names them, checked against the reference backend.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): commands/arguments/ScoreHolderArgument.java (``*``
is Scoreboard.getTrackedPlayers; an empty list fails "argument.scoreHolder.empty"),
world/scores/Scoreboard.java (removeObjective empties a holder's scores but keeps it in the map;
resetSinglePlayerScore drops a holder left without a score), server/commands/
ScoreboardCommand.java (set: the value times the targets; add: the sum of the new values; reset:
the count; the targets read before the objective).
"""
from __future__ import annotations

import pytest

from tests.vm.helpers import emulator_for

SETUP = ("scoreboard objectives add o dummy\nscoreboard objectives add p dummy\nscoreboard objectives add t trigger\n"
         "scoreboard objectives add gone dummy\n"
         "scoreboard players set #a o 1\nscoreboard players set #b p 2\nscoreboard players set #k gone 5\n"
         'summon marker 0 0 0 {Tags:["x"]}\nscoreboard players set @e[tag=x] p 7\n'
         "scoreboard objectives remove gone\n")  # #k stays tracked without a score


def _run_both(tmp_path, body: str):
    emus = []
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, {"t:main": SETUP + body}, backend=backend)
        emu.call("t:main")
        emus.append(emu)
    numba, python = emus
    assert numba.scores() == python.scores()
    assert numba.state.scoreboard.tracked_holders() == python.state.scoreboard.tracked_holders()
    return numba


def _host_lines(emu) -> list[str]:
    """The scoreboard commands (the score holders' kind) the host ran."""
    return [name for run in emu.backend.host_ops_run() if (name := type(run.node).__name__).startswith("Score")]


def test_set_add_remove_reach_every_tracked_holder(tmp_path):
    emu = _run_both(tmp_path, "execute store result score #r1 p run scoreboard players set * o 3\n"
                              "execute store result score #r2 p run scoreboard players add * o 4\n"
                              "scoreboard players remove * o 1")
    assert _host_lines(emu) == []
    # #a, #b, #k (kept) and the marker: 3 x 4 targets; then those at 7 and #r1 (tracked since the
    # store) at 4; then #r2 as well
    assert (emu.score("#r1", "p"), emu.score("#r2", "p")) == (12, 32)
    assert emu.scores()["o"] == {"#a": 6, "#b": 6, "#k": 6, emu.entities()[0]["uuid"]: 6, "#r1": 3, "#r2": -1}


def test_reset_drops_holders_left_without_a_score(tmp_path):
    emu = _run_both(tmp_path, "execute store result storage t:s n int 1 run scoreboard players reset * o\n"
                              "scoreboard players reset *\n"
                              "execute store success score #empty p run scoreboard players set * o 1\n"
                              "execute store result score #count p run data get storage t:s n")
    assert _host_lines(emu) == []
    assert sorted(emu.state.scoreboard.tracked_holders()) == ["#count", "#empty"]
    # reset * o: #a, #b, #k and the marker (4); reset *: #b and the marker; nothing left for set *
    assert (emu.score("#count", "p"), emu.score("#empty", "p")) == (4, 0)


def test_enable_unlocks_every_tracked_holder(tmp_path):
    emu = _run_both(tmp_path, "execute store result score #n p run scoreboard players enable * t")
    assert _host_lines(emu) == []
    assert emu.score("#n", "p") == 4


@pytest.mark.parametrize("line, in_vm", [
    ("scoreboard players operation * o += #b p", True),
    ("scoreboard players operation * o = @e[tag=x] p", True),
    ("scoreboard players operation * o *= #b p", True),
    ("scoreboard players operation #b p > * o", True),
    ("scoreboard players operation #b p < * o", True),
    # the order of the hash map matters: the host walks it
    ("scoreboard players operation * o += #a o", False),
    ("scoreboard players operation * o >< #b p", False),
    ("scoreboard players operation * o /= #b p", False),
    ("scoreboard players operation #b p += * o", False),
    ("scoreboard players operation * o = * p", False),
])
def test_operations_run_in_the_vm_where_the_order_changes_nothing(tmp_path, line, in_vm):
    emu = _run_both(tmp_path, "scoreboard players set #a o 1000\n" + line)
    assert (_host_lines(emu) == []) == in_vm


def test_an_empty_wildcard_fails_the_command(tmp_path):
    emu = _run_both(tmp_path, "scoreboard players reset *\n"
                              "execute store success score #s p run scoreboard players add * nope 1")
    assert emu.score("#s", "p") == 0  # the targets are read first: no report about the objective
    assert not emu.diagnostics


@pytest.mark.parametrize("line, in_vm", [
    ("execute store result score * o run scoreboard players get #b p", True),
    ("execute as @e[tag=x] store success score * o if entity @s[tag=x]", True),
    ("execute store result score * o run data get entity @e[tag=x,limit=1] Pos[0] 10", True),
    # the chain may give a holder its first score: the stage's holders are not known at the store
    ("execute store result score * o run scoreboard players set #new p 3", False),
    ("execute store result score * o store result score #new p run scoreboard players get #b p", False),
])
def test_stores_into_every_holder(tmp_path, line, in_vm):
    emu = _run_both(tmp_path, "scoreboard players set #b p 9\n" + line)
    stores = [run for run in emu.backend.host_ops_run() if type(run.node).__name__ == "StoreScore"]
    assert (stores == []) == in_vm
    assert len(emu.scores()["o"]) >= 4  # #a, #b, #k, the marker


def test_a_store_into_nobody_fails_its_stage(tmp_path):
    # after `reset *`, `*` names nobody: the store stage fails (no report); then #none alone
    emu = _run_both(tmp_path, "scoreboard players reset *\n"
                              "execute store success score * o run scoreboard players get #b p\n"
                              "execute store success score #none o run scoreboard players get #b p\n"
                              "execute store success score * o run scoreboard players get #none o")
    assert [run for run in emu.backend.host_ops_run() if type(run.node).__name__ == "StoreScore"] == []
    assert emu.scores()["o"] == {"#none": 1}
    assert not emu.diagnostics

