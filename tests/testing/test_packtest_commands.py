"""PackTest's ``assert``, ``fail`` and ``succeed`` run by a function the test calls: a library
running a test's callback from a macro line, or a helper function of the pack's own.

Sources (misode/packtest): commands/AssertCommand.java (registered in the dispatcher; a failed
assert calls the source's GameTestHelper.fail), FailCommand.java, SucceedCommand.java,
mixin/CommandSourceStackMixin.java (every source made from the test's keeps its helper).
"""
import pytest

from emulator import Emulator
from emulator.testing import discover, run_suite

SETUP = "scoreboard objectives add o dummy\nscoreboard players set $x o 4\n"
FILES = {
    # a library: runs the callback it is given for each element, as Bookshelf's for_each does
    "lib/function/each.mcfunction": "$$(run)\n",
    "lib/function/check.mcfunction": "assert score $x o matches 4\nscoreboard players set $checked o 1\n",
    "lib/function/boom.mcfunction": 'fail ["the library gave up at ",{"score":{"name":"$x","objective":"o"}}]\n',
    "lib/function/done.mcfunction": "succeed\n",
    "demo/test/callback_holds.mcfunction": SETUP + 'function lib:each {run: "assert score $x o matches 4"}\n'
                                                   "assert score $x o matches 4\n",
    "demo/test/callback_fails.mcfunction": SETUP + 'function lib:each {run: "assert score $x o matches 5"}\n'
                                                   "scoreboard players set $x o 5\n",
    "demo/test/not_held.mcfunction": SETUP + 'function lib:each {run: "assert not score $x o matches 4"}\n',
    "demo/test/static.mcfunction": SETUP + "function lib:check\nassert score $checked o matches 1\n",
    "demo/test/fails.mcfunction": SETUP + "function lib:boom\n",
    "demo/test/succeeds.mcfunction": SETUP + "function lib:done\nassert score $x o matches 99\n",
    "demo/test/chat.mcfunction": SETUP + 'function lib:each {run: "assert chat \\"hi\\""}\n',
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_function_runs_packtests_commands_for_its_test(pack, backend):
    results = {r.id: r for r in run_suite(discover([pack(FILES)]), backend, isolate=True).results}
    assert results["demo:callback_holds"].status == "passed"
    failed = results["demo:callback_fails"]
    # the message a test file's own line gets, at the test's line that called the function
    assert (failed.status, failed.message) == ("failed", "Expected score $x o to match 5, found 4")
    assert failed.where.endswith("data/demo/test/callback_fails.mcfunction:3")
    assert results["demo:not_held"].message == "Did not expect score $x o to match 4, found 4"
    assert results["demo:static"].status == "passed"
    assert (results["demo:fails"].status, results["demo:fails"].message) == ("failed", "the library gave up at 4")  # resolved (FailCommand)
    assert results["demo:succeeds"].status == "passed"  # GameTestHelper.succeed: the later line is not reached
    chat = results["demo:chat"]  # PackTest's own conditions are read as a test file's lines only
    assert chat.status == "inconclusive" and "assert chat" in chat.message
    # the reason printed once (the message), its call stack under it; at the test's line running then
    details = "\n".join(chat.details)
    assert "not modelled" not in details and "in lib:each" in details and chat.line == 3


def test_outside_a_test_server_they_are_unknown_commands(pack):
    # a game without the PackTest mod does not know them: the function fails to load
    emu = Emulator(backend="python")
    emu.load([pack(FILES)])
    errors = [d for d in emu.load_diagnostics if d.severity == "error"]
    assert any(d.message.startswith("unknown command 'assert' (PackTest's") and d.path.endswith("check.mcfunction")
               for d in errors)


def test_the_parsers_memory_of_lines_does_not_carry_the_dialect_out():
    # a line read as PackTest's command inside the dialect is an unknown command after it
    from mcfunction_parser.dialect import packtest_commands
    from mcfunction_parser.parse import parse_function

    text = "execute if score a o matches 1 run assert score a o matches 1\nassert score a o matches 1\n"
    with packtest_commands():
        function, diagnostics = parse_function(text, "f.mcfunction", "demo:f", (1, 21, 4))
    assert not diagnostics and len(function.commands) == 2
    function, diagnostics = parse_function(text, "f.mcfunction", "demo:f", (1, 21, 4))
    assert [d.message.split(" (")[0] for d in diagnostics] == ["unknown command 'assert'"] * 2


def test_check_reads_them_with_packtest(pack):
    from click.testing import CliRunner

    from emulator.cli.check import check

    root = pack(FILES)
    assert CliRunner().invoke(check, [str(root)]).exit_code == 1
    result = CliRunner().invoke(check, [str(root), "--packtest"])
    assert result.exit_code == 0, result.output
