"""Command semantics the two backends once disagreed on (each wrote its own copy of the command),
pinned on both: the game's behaviour, with the decompiled 1.21 class and method that decides it.

Selectors with ``sort=`` keep a command on the VM's host side (emulator.commands), the same code
the reference runs; the cases pin that code against the game.
"""
from __future__ import annotations

import pytest

from tests.backends.programs import run_root, write_pack

BACKENDS = ["python", "numba"]
SETUP = "scoreboard objectives add o dummy\nscoreboard objectives add hp health\nsummon marker\n"
MARKER = "@e[type=marker,sort=nearest,limit=1]"
NOBODY = "@e[tag=nobody,sort=nearest,limit=1]"


def run(tmp_path, backend: str, body: str, functions: dict[str, str] | None = None):
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + body, "t:g": "scoreboard players add #g o 1",
                                          **(functions or {})})
    return run_root(backend, pack, "t:main")


def messages(outcome) -> list[str]:
    return [message for message, _ in outcome.diagnostics]


@pytest.mark.parametrize("backend", BACKENDS)
def test_schedule_for_the_current_tick_fails(tmp_path, backend):
    # ScheduleCommand.schedule: `if (time == 0) throw ERROR_SAME_TICK` (TimeArgument.time() accepts
    # 0t, so the command parses and fails when it runs); reported, as the function would never run
    outcome = run(tmp_path, backend, "execute store success score #now o run schedule function t:g 0t\n"
                                     "execute store success score #next o run schedule function t:g 1t")
    assert (outcome.scores["o"].get("#now"), outcome.scores["o"].get("#next")) == (0, 1)
    assert messages(outcome) == ["Can't schedule for current tick"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_writing_a_read_only_objective_fails(tmp_path, backend):
    # ObjectiveArgument.getWritableObjective: ERROR_OBJECTIVE_READ_ONLY, "arguments.objective.readonly"
    # ("Scoreboard objective '%s' is read-only") for set/add/remove and the target of operation;
    # reported like an unknown objective (such a write can never succeed)
    outcome = run(tmp_path, backend, f"execute store success score #set o run scoreboard players set {MARKER} hp 1\n"
                                     f"execute store success score #add o run scoreboard players add {MARKER} hp 1\n"
                                     "scoreboard players set #b o 4\n"
                                     f"execute store success score #op o run scoreboard players operation {MARKER} hp "
                                     "= #b o")
    scores = outcome.scores["o"]
    assert (scores["#set"], scores["#add"], scores["#op"]) == (0, 0, 0)
    assert outcome.scores.get("hp", {}) == {}
    assert messages(outcome) == ["Scoreboard objective 'hp' is read-only"] * 3


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_read_only_objective_is_read_and_stored_into(tmp_path, backend):
    # ExecuteCommand's store score and if score, ScoreboardCommand.getScore and the source of
    # performOperation read the objective with getObjective: read-only ones too
    outcome = run(tmp_path, backend, f"execute store result score {MARKER} hp run scoreboard players set #b o 6\n"
                                     f"execute store result score #get o run scoreboard players get {MARKER} hp\n"
                                     f"scoreboard players operation #sum o += {MARKER} hp\n"
                                     f"execute if score {MARKER} hp matches 6 run scoreboard players set #if o 1")
    scores = outcome.scores["o"]
    assert (scores["#get"], scores["#sum"], scores["#if"]) == (6, 6, 1)
    assert messages(outcome) == []


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("line", [
    # ScoreboardCommand's executes lambdas read the targets before the objective
    # (setScore(source, getNamesWithDefaultWildcard(targets), getWritableObjective(objective), ...)):
    # no holder fails first, silently ("No entity was found")
    f"scoreboard players set {NOBODY} hp 1",
    f"scoreboard players add {NOBODY} nope 1",
    # performOperation(source, targets, getWritableObjective(targetObjective), operation, sources,
    # getObjective(sourceObjective)): targets, their objective, then the sources
    f"scoreboard players operation {NOBODY} nope += #a o",
    f"scoreboard players operation #a o += {NOBODY} nope",
    f"scoreboard players get {NOBODY} nope",
    f"scoreboard players reset {NOBODY} nope",
    # ExecuteCommand.checkScore: target, targetObjective, source, sourceObjective
    f"execute if score {NOBODY} nope matches 1",
    f"execute if score #a o = {NOBODY} nope",
    # ExecuteCommand.storeValue(source, getNamesWithDefaultWildcard(targets), getObjective(objective), ...)
    f"execute store result score {NOBODY} nope run scoreboard players set #a o 1",
    # TriggerCommand.simpleTrigger(source, source.getPlayerOrException(), getObjective(objective)):
    # the server is no player, before the objective is looked up
    "trigger nope",
])
def test_arguments_are_read_in_the_games_order(tmp_path, backend, line):
    # the unknown or read-only objective is never reached: no diagnostic, nothing changed
    outcome = run(tmp_path, backend, line)
    assert outcome.scores["o"] == {}
    assert messages(outcome) == []


@pytest.mark.parametrize("backend", BACKENDS)
def test_return_run_of_a_function_whose_arguments_fail_returns_failure(tmp_path, backend):
    # FunctionCommand: no element at the `with` path throws; CustomCommandExecutor.WithErrorHandling
    # calls source.callback().onFailure(), which after `return run` is chained with the frame's
    # return value consumer (BuildContexts.execute), so the calling function fails: store success 0
    outcome = run(tmp_path, backend, "scoreboard players set #s o -5\n"
                                     "execute store success score #s o run function t:h",
                  {"t:h": "return run function t:n with storage t:s nothing", "t:n": "$return $(v)"})
    assert outcome.scores["o"]["#s"] == 0
