"""Scoreboard semantics in the VM, from mcfunction text (ScoreboardCommand, OperationArgument,
Math.floorDiv/floorMod in the decompiled 1.21 sources)."""
from __future__ import annotations

import pytest

from tests.vm.helpers import host_kinds, run_both, run_main

MIN, MAX = -2147483648, 2147483647


@pytest.mark.parametrize("a, op, b, expected", [
    (MIN, "/=", -1, MIN),        # floorDiv overflow: MIN / -1 stays MIN
    (MIN, "%=", -1, 0),
    (-7, "/=", 2, -4),           # floor, not truncation
    (-5, "%=", 4, 3),            # floorMod takes the divisor's sign
    (7, "%=", -2, -1),
    (MAX, "*=", MAX, 1),         # wraps: (2^31-1)^2 mod 2^32 = 1
    (MAX, "+=", 1, MIN),
    (MIN, "-=", 1, MAX),
    (3, "<", -9, -9),
    (3, ">", -9, 3),
    (3, "=", -9, -9),
])
def test_operation_edge_cases(tmp_path, a, op, b, expected):
    emu, _ = run_main(tmp_path, f"scoreboard players set #a o {a}\nscoreboard players set #b o {b}\n"
                                f"scoreboard players operation #a o {op} #b o")
    assert emu.score("#a", "o") == expected
    assert emu.score("#b", "o") == b


def test_swap(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 1\nscoreboard players set #b o 2\n"
                                "scoreboard players operation #a o >< #b o")
    assert (emu.score("#a", "o"), emu.score("#b", "o")) == (2, 1)


@pytest.mark.parametrize("op", ["/=", "%="])
def test_division_by_zero_fails_and_leaves_target(tmp_path, op):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 7\n"
                                f"execute store success score #ok o run scoreboard players operation #a o {op} #zero o\n"
                                "scoreboard players set #after o 1")
    assert emu.score("#a", "o") == 7
    assert emu.score("#zero", "o") == 0  # the source was get-or-created
    assert emu.score("#ok", "o") == 0
    assert emu.score("#after", "o") == 1  # the function went on
    [diag] = emu.diagnostics
    assert diag.message == "Cannot divide by zero"
    assert [(f.function, f.loc.line) for f in diag.frames] == [("t:main", 3)]


def test_operation_creates_unset_target_and_source(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players operation #t o += #s o")
    assert (emu.score("#t", "o"), emu.score("#s", "o")) == (0, 0)


def test_add_remove_wrap(tmp_path):
    emu, _ = run_main(tmp_path, f"scoreboard players set #a o {MAX - 1}\nscoreboard players add #a o 5\n"
                                "scoreboard players remove #b o 2147483647\nscoreboard players remove #b o 2")
    assert emu.score("#a", "o") == MIN + 3
    assert emu.score("#b", "o") == MAX


def test_reset_and_get(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 5\nscoreboard players reset #a o\n"
                                "execute store result score #r o run scoreboard players get #a o\n"
                                "execute store success score #s o run scoreboard players get #a o\n"
                                "scoreboard players set #c o 4\nscoreboard players reset #c\n")
    assert emu.score("#a", "o") is None
    assert (emu.score("#r", "o"), emu.score("#s", "o")) == (0, 0)  # failure stores 0
    assert emu.score("#c", "o") is None
    assert emu.diagnostics == []  # get on an unset score fails silently, as in the game


@pytest.mark.parametrize("condition, passes", [
    ("if score #u o matches ..0", False),       # unset: if fails ...
    ("unless score #u o matches ..0", True),    # ... so unless passes
    ("if score #a o < #u o", False),
    ("unless score #a o = #u o", True),
    ("if score #a o matches 5", True),
    ("if score #a o matches 6..", False),
    ("if score #a o matches ..5", True),
    ("if score #a o >= #b o", True),
    ("if score #a o > #b o", False),
    ("if score #a o <= #b o", True),
    ("unless score #a o < #b o", True),
])
def test_score_conditions(tmp_path, condition, passes):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 5\nscoreboard players set #b o 5\n"
                                f"execute {condition} run scoreboard players set #hit o 1")
    assert emu.score("#hit", "o") == (1 if passes else None)


def test_condition_as_final_command_result(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 5\n"
                                "execute store result score #yes o if score #a o matches 5\n"
                                "execute store success score #no o if score #a o matches 6\n")
    assert (emu.score("#yes", "o"), emu.score("#no", "o")) == (1, 0)


def test_store_results(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 5\nscoreboard players set #b o 3\n"
                                "execute store result score #r o store success score #s o "
                                "run scoreboard players operation #a o += #b o\n"
                                "execute store result score #set o run scoreboard players set #x o -4\n"
                                "execute if score #a o matches 0 store result score #never o run scoreboard players set #y o 1")
    assert (emu.score("#r", "o"), emu.score("#s", "o")) == (8, 1)
    assert emu.score("#set", "o") == -4
    assert emu.score("#never", "o") is None and emu.score("#y", "o") is None


def test_unknown_objective_is_reported(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players set #a nope 1\nscoreboard players set #b o 2")
    assert emu.score("#b", "o") == 2
    [diag] = emu.diagnostics
    assert diag.message == "Unknown scoreboard objective 'nope'"
    assert diag.frames[-1].loc.line == 2


def test_wildcard_and_selectors_run_on_the_host(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 1\nscoreboard players set #b o 2\n"
                                "scoreboard players add * o 10\n"
                                "execute store success score #s o run scoreboard players set @s o 1")
    assert (emu.score("#a", "o"), emu.score("#b", "o")) == (11, 12)
    assert emu.score("#s", "o") == 0  # @s run by the server names no holder


def test_objectives_add_remove(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard objectives add p dummy\nscoreboard players set #a p 1\n"
                                "scoreboard objectives remove p\nscoreboard objectives add p dummy")
    assert emu.scores()["p"] == {}


def test_objectives_add_of_an_existing_one_and_remove_run_in_the_vm(tmp_path):
    """ScoreboardCommand.addObjective fails when the name exists (ERROR_OBJECTIVE_ALREADY_EXISTS, not
    reported) and removeObjective needs an existing one (ObjectiveArgument.getObjective: reported);
    both return the count of objectives (Scoreboard.getObjectives().size()). Scoreboard.removeObjective
    keeps a holder whose only scores went in the map, so `*` still names it. Only a new objective
    goes to the host (its criterion and display name)."""
    body = ("scoreboard objectives add o dummy\nscoreboard objectives add p dummy\nscoreboard players set #a o 1\nscoreboard players set #b p 5\n"
            "execute store result score #dup o run scoreboard objectives add p trigger\n"
            "execute store success score #dup_ok o run scoreboard objectives add o dummy\n"
            "execute store result score #left o run scoreboard objectives remove p\n"
            "scoreboard objectives remove p\n"
            "scoreboard objectives add p dummy\nscoreboard players add * p 3")
    emu = run_both(tmp_path, body)
    assert [emu.score(h, "o") for h in ("#dup", "#dup_ok", "#left")] == [0, 0, 1]
    assert emu.scores()["p"] == {"#a": 3, "#b": 3, "#dup": 3, "#dup_ok": 3, "#left": 3}  # #b kept, then named by `*`
    assert [d.message for d in emu.diagnostics] == ["Unknown scoreboard objective 'p'"]
    assert host_kinds(emu).count("ObjectivesAdd") == 3  # o, and p twice
    assert "ObjectivesRemove" not in host_kinds(emu)


def test_list_results(tmp_path):
    emu, _ = run_main(tmp_path, "scoreboard objectives add p dummy\nscoreboard players set #a o 1\n"
                                "scoreboard players set #a p 1\nscoreboard players set #b p 1\n"
                                "execute store result score #objectives o run scoreboard objectives list\n"
                                "execute store result score #holders o run scoreboard players list\n"
                                "execute store result score #of_a o run scoreboard players list #a")
    # holders listed before #holders and #of_a are stored: #a, #b, #objectives
    assert [emu.score(h, "o") for h in ("#objectives", "#holders", "#of_a")] == [2, 3, 2]
