"""PackTest-format test files run by emulator.testing (format: misode/packtest README)."""

import pytest

from emulator.testing import discover, run_suite
from emulator.testing.discovery import DiscoveryError

SETUP = "scoreboard objectives add o dummy\nscoreboard players set $x o 4\n"


def run(root, backend="numba", pattern=None, isolate=True):
    """Each test in a world of its own (the tests here pin one feature each; tests/testing/test_batches.py
    runs them as the game test server does)."""
    return run_suite(discover([root]), backend, pattern, isolate=isolate)


def by_id(summary):
    return {r.id: r for r in summary.results}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_failing_assert_names_file_line_expected_and_found(pack, backend):
    root = pack({"demo/test/fails.mcfunction": SETUP + "assert score $x o matches 4\nassert score $x o matches 5\n"})
    result = run(root, backend).results[0]
    assert result.status == "failed"
    # PackTest's ScoreAssertion message
    assert result.message == "Expected score $x o to match 5, found 4"
    assert result.where.endswith("data/demo/test/fails.mcfunction:4")
    assert result.report().splitlines()[0] == "FAIL demo:fails"


def test_messages_for_not_comparison_and_unset(pack):
    root = pack({
        "demo/test/a.mcfunction": SETUP + "assert not score $x o matches 4\n",
        "demo/test/b.mcfunction": SETUP + "scoreboard players set $y o 9\nassert score $x o >= $y o\n",
        "demo/test/c.mcfunction": SETUP + "assert score $nobody o matches 0\n",
    })
    results = by_id(run(root))
    assert results["demo:a"].message == "Did not expect score $x o to match 4, found 4"
    assert results["demo:b"].message == "Expected score $x o >= $y o, found 4 >= 9"
    assert results["demo:c"].message == "Expected score $nobody o to match 0, found undefined"


def test_unknown_directive_is_reported_and_the_rest_still_runs(pack):
    root = pack({
        "demo/test/bad.mcfunction": "# @timout 5\n" + SETUP,
        "demo/test/good.mcfunction": SETUP + "assert score $x o matches 4\n",
    })
    results = by_id(run(root))
    bad = results["demo:bad"]
    assert bad.status == "failed" and bad.line == 1
    assert bad.message.startswith("unknown directive '@timout': expected one of @template, @timeout")
    assert results["demo:good"].status == "passed"


@pytest.mark.parametrize("line,col,message", [
    ("assert score $x o matchez 4", 19, "matchez"),
    ("assert scroe $x o matches 4", 8, "unknown condition 'scroe'"),
    ("await delay soon", 13, "expected a time"),
    ("fail", 5, "expected a message"),
])
def test_malformed_test_command_is_reported_at_its_column(pack, line, col, message):
    root = pack({"demo/test/bad.mcfunction": SETUP + line + "\n",
                 "demo/test/good.mcfunction": SETUP})
    results = by_id(run(root))
    bad = results["demo:bad"]
    assert bad.status == "failed" and bad.line == 3
    assert message in bad.message
    assert f"bad.mcfunction:3:{col}:" in bad.details[0]
    assert results["demo:good"].status == "passed"


def test_a_test_that_never_finishes_stops_at_its_timeout(pack):
    root = pack({"demo/test/hang.mcfunction": "# @timeout 5\n" + SETUP + "await score $x o matches 1\n"})
    result = run(root).results[0]
    assert result.status == "failed"
    assert result.message == "Timed out after 5 ticks: Expected score $x o to match 1, found 4"
    assert result.ticks == 5 and result.line == 4


def test_default_timeout_is_100_ticks(pack):
    root = pack({"demo/test/hang.mcfunction": SETUP + "await delay 6s\n"})
    result = run(root).results[0]
    assert result.message.startswith("Timed out after 100 ticks") and result.ticks == 100


def test_await_ticks_the_world_until_the_condition_holds(pack):
    root = pack({
        "demo/function/count.mcfunction": "scoreboard players add $t o 1\n",
        "demo/function/init.mcfunction": "scoreboard objectives add o dummy\n",
        # the tick function ran before the test started (see test_a_test_starts_ticks_after_the_load): count from 0
        "demo/test/wait.mcfunction": "scoreboard players set $t o 0\nawait score $t o matches 3\nassert score $t o matches 3\n"
                                     "await delay 1s\nassert score $t o matches 23\n",
    }, tick=["demo:count"], load=["demo:init"])
    result = run(root).results[0]
    assert result.status == "passed", result.message
    assert result.ticks == 23


def test_fail_succeed_and_execute_prefixes(pack):
    root = pack({
        "demo/test/fail_json.mcfunction": SETUP + 'fail {"text": "Oh ", "extra": ["no"]}\n',
        "demo/test/fail_plain.mcfunction": SETUP + "fail nope\n",
        "demo/test/succeed.mcfunction": SETUP + "succeed\nfail \"not reached\"\n",
        "demo/test/gated.mcfunction": SETUP + "execute if score $x o matches 5 run fail \"gate\"\n"
                                      "execute if score $x o matches 4 run succeed\nfail \"after\"\n",
        "demo/test/gated_assert.mcfunction": SETUP + "execute if score $x o matches 4 run "
                                                     "assert score $x o matches 3\n",
    })
    results = by_id(run(root))
    assert results["demo:fail_json"].message == "Oh no"
    assert results["demo:fail_plain"].message == "nope"
    assert results["demo:succeed"].status == "passed"
    assert results["demo:gated"].status == "passed"
    assert results["demo:gated_assert"].message == "Expected score $x o to match 3, found 4"


def test_fail_resolves_its_message_for_the_source(pack):
    # FailCommand: ComponentUtils.getResolvedComponent (scores, selectors, NBT) for the source's
    # entity (the dummy here); a selector that must find one entity and finds two fails the line,
    # which FailCommand ignores, and the test goes on
    root = pack({
        "demo/test/resolved.mcfunction": "# @dummy\n" + SETUP + 'fail [{"score":{"name":"$x","objective":"o"}}," ",{"selector":"@s"}," ",'
                                '{"nbt":"Health","entity":"@s"}]\n',
        "demo/test/ambiguous.mcfunction": SETUP + "summon marker\nsummon marker\nscoreboard players set @e o 1\n"
                                                  'fail {"score":{"name":"@e","objective":"o"}}\nsucceed\n',
    })
    results = by_id(run(root))
    assert results["demo:resolved"].message.startswith("4 Dummy") and results["demo:resolved"].message.endswith(" 20.0f")
    assert results["demo:ambiguous"].status == "passed"


def test_isolated_each_test_runs_in_a_fresh_world_after_load(pack):
    root = pack({
        "demo/function/init.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set $loaded o 1\n",
        "demo/test/a.mcfunction": "scoreboard players set $leak o 1\nassert score $loaded o matches 1\n",
        "demo/test/b.mcfunction": "assert not score $leak o matches 1\nassert score $loaded o matches 1\n",
    }, load=["demo:init"])
    assert [r.status for r in run(root).results] == ["passed", "passed"]


def test_optional_and_summary(pack):
    root = pack({
        "demo/test/opt.mcfunction": "# @optional\nfail \"allowed\"\n",
        "demo/test/opt_false.mcfunction": "# @optional false\nsucceed\n",
        "demo/test/ok.mcfunction": "succeed\n",
    })
    summary = run(root)
    results = by_id(summary)
    assert results["demo:opt"].report().startswith("FAIL (optional) demo:opt")
    assert not results["demo:opt_false"].optional
    assert summary.line() == "2 passed, 0 failed, 1 skipped" and summary.ok


def test_batches_run_their_before_command_and_allow_only_one(pack):
    root = pack({
        "demo/test/a.mcfunction": "# @batch b1\n# @beforebatch scoreboard objectives add o dummy\n"
                                  "scoreboard players set $x o 1\nassert score $x o matches 1\n",
        "demo/test/b.mcfunction": "# @batch b1\n# @beforebatch say other\nsucceed\n",
        "demo/test/c.mcfunction": "# @batch b1\nscoreboard players set $x o 1\nassert score $x o matches 1\n",
        "demo/test/d.mcfunction": "# @timeout 0\nsucceed\n",
    })
    results = by_id(run(root))
    assert results["demo:a"].status == "passed"
    assert results["demo:b"].message == "@beforebatch: batch 'b1' already has 'scoreboard objectives add o dummy'"
    assert results["demo:c"].status == "passed"  # the batch's before command ran in its world too
    assert "expected a positive number of ticks" in results["demo:d"].message


def test_discovery_ids_filter_and_errors(pack, tmp_path):
    root = pack({"demo/test/sub/a.mcfunction": "succeed\n", "old/tests/b.mcfunction": "succeed\n",
                 "demo/function/f.mcfunction": "say hi\n"})
    assert [t.id for t in discover([root])] == ["demo:sub/a", "old:b"]
    assert [r.id for r in run(root, pattern="SUB").results] == ["demo:sub/a"]
    assert [t.id for t in discover([root / "data/old/tests/b.mcfunction"])] == ["old:b"]
    with pytest.raises(DiscoveryError, match="not a test file"):
        discover([root / "data/demo/function/f.mcfunction"])
    (tmp_path / "loose").mkdir()
    with pytest.raises(DiscoveryError, match="not inside a datapack"):
        discover([tmp_path / "loose"])


def test_chat_conditions_see_messages_since_the_test_started(pack):
    # messages and wording as PackTest's ChatAssertion (regex find over the received messages);
    # ChatRecorder keeps the system messages sent to players (ServerPlayer.sendSystemMessage),
    # one record per receiving player: tellraw is one, `say` (a chat message) is not
    root = pack({
        "demo/function/init.mcfunction": "tellraw @a \"from load\"\n",
        "demo/test/chat.mcfunction": '# @dummy\ntellraw @a "hello world"\nassert chat "hello w.rld"\n'
                                     'assert not chat "from load"\ntellraw @a {"text": "json msg"}\nassert chat ^json\n'
                                     'say a said line\nassert chat bye\n',
        "demo/test/not.mcfunction": "# @dummy\ntellraw @a \"hi\"\nassert not chat hi\n",
        "demo/test/say.mcfunction": "# @dummy\nsay hi\nassert chat hi\n",
        "demo/test/nobody.mcfunction": "tellraw @a \"hi\"\nassert not chat hi\n",
    }, load=["demo:init"])
    results = by_id(run(root))
    assert results["demo:chat"].message == 'Expected chat message matching bye, received "hello world", "json msg"'
    assert results["demo:chat"].line == 8
    assert results["demo:not"].message == "Did not expect chat message matching hi, found 1"
    assert results["demo:say"].message == "Expected chat message matching hi, received nothing"
    assert results["demo:nobody"].status == "passed", results["demo:nobody"].message  # nobody received it


def test_chat_reads_translated_messages_as_the_server_does(pack):
    # ChatAssertion matches Component.getString(): a translate component reads as the release's en_us
    # string with its arguments (TranslatableContents.decompose), a pack's own key as its fallback,
    # a selector as the entity type's en_us name (EntityType.getDescription)
    root = pack({
        "demo/test/translated.mcfunction":
            '# @dummy\nsummon tnt_minecart ~ ~ ~\n'
            'tellraw @a {"translate":"chat.type.text","with":["Alex",{"selector":"@e[type=tnt_minecart]"}]}\n'
            'tellraw @a {"translate":"demo.hello","fallback":"Hello, %s!","with":[{"translate":"item.minecraft.diamond"}]}\n'
            'assert chat "^<Alex> Minecart with TNT$"\nassert chat "^Hello, Diamond!$"\n',
    })
    result = by_id(run(root))["demo:translated"]
    assert result.status == "passed", result.message


def test_chat_receivers_see_their_own_messages(pack):
    # ChatAssertion with players: each receiver's messages (ChatRecorder.since with a recipient),
    # flat-mapped over the players; no player found is an error, failing `assert not` too
    root = pack({
        "demo/test/receivers.mcfunction":
            "dummy Ann spawn\ndummy Bob spawn\ntellraw Ann \"to ann\"\ntellraw @a \"to all\"\n"
            "assert chat \"to ann\" Ann\nassert not chat \"to ann\" Bob\nassert chat \"to all\" Bob\n"
            "execute as @a run assert chat \"to all\" @s\nassert chat \"to ann\" Bob\n",
        "demo/test/count.mcfunction": "dummy Ann spawn\ndummy Bob spawn\ntellraw @a \"x\"\nassert not chat x\n",
        "demo/test/nobody.mcfunction": "assert not chat hi @a\n",
        "demo/test/bad.mcfunction": "assert chat hi @a[\n",
    })
    results = by_id(run(root))
    assert results["demo:receivers"].message == 'Expected chat message matching to ann, received "to all"'
    assert results["demo:receivers"].line == 9
    assert results["demo:count"].message == "Did not expect chat message matching x, found 2"  # one per receiver
    assert results["demo:nobody"].message == "No player was found"
    assert results["demo:bad"].status == "failed" and "receivers: bad selector" in results["demo:bad"].message


def test_failure_details_show_the_runtime_diagnostics(pack):
    root = pack({"demo/test/obj.mcfunction": "scoreboard players set $x nope 1\nassert score $x nope matches 1\n"})
    result = run(root).results[0]
    assert result.message == "Expected score $x nope to match 1, found undefined"
    assert any("obj.mcfunction:1:1" in d and "Unknown scoreboard objective 'nope'" in d for d in result.details)


def test_macro_lines_and_unreadable_files_are_reported(pack):
    root = pack({"demo/test/macro.mcfunction": "$say $(x)\n", "demo/test/ok.mcfunction": "succeed\n"})
    (root / "data/demo/test/binary.mcfunction").write_bytes(b"\xff\xfe\x00say")
    results = by_id(run(root))
    assert results["demo:macro"].message == "a macro line needs arguments, and a test runs without any"
    assert results["demo:macro"].line == 1
    assert results["demo:binary"].message.startswith("cannot read the test file")
    assert results["demo:ok"].status == "passed"


def test_chat_patterns_are_brigadier_strings(pack):
    root = pack({"demo/test/esc.mcfunction": '# @dummy\ntellraw @a "[Server] a.b (c)"\n'
                                             'assert chat "^\\\\[Server\\\\] a\\\\.b \\\\(c\\\\)$"\n',
                 "demo/test/bad_escape.mcfunction": 'assert chat "a\\.b"\n'})
    results = by_id(run(root))
    assert results["demo:esc"].status == "passed", results["demo:esc"].message
    assert results["demo:bad_escape"].message == "Invalid escape sequence '\\.' in quoted string"
    assert "bad_escape.mcfunction:1:15:" in results["demo:bad_escape"].details[0]


def test_dummy_directive_spawns_a_player_as_the_test_source(pack):
    # PackTestFunction: the source is the test origin + (0, 1, 0); @dummy defaults to ~0.5 ~ ~0.5
    root = pack({
        "demo/test/default.mcfunction": "# @dummy\nassert entity @s[type=player]\n"
                                        "assert entity @a[x=0.5,y=1,z=0.5,distance=..0.001]\n",
        "demo/test/placed.mcfunction": "# @dummy ~2 ~ 5\nassert entity @a[x=2,y=1,z=5,distance=..0.001]\n"
                                       "assert entity @s[name=Dummy4]\n",
        "demo/test/server.mcfunction": "assert not entity @s\nassert not entity @a\n",
        "demo/test/bad.mcfunction": "# @dummy here\nsucceed\n",
    })
    results = by_id(run(root))
    assert results["demo:default"].status == "passed", results["demo:default"].message
    assert results["demo:placed"].message == "Expected entity matching @s[name=Dummy4]"  # named Dummy100..999
    assert results["demo:server"].status == "passed", results["demo:server"].message
    assert results["demo:bad"].message == "Failed to initialize test with dummy"


def test_directives_are_the_leading_comment_lines(pack):
    # PackTestFunction.fromLines stops at the first line not starting with '#'
    root = pack({"demo/test/late.mcfunction": "# @timeout 3\n\n# @timeout 50\nawait delay 10\n",
                 "demo/test/flag.mcfunction": "#@optional\nfail no\n"})
    results = by_id(run(root))
    assert results["demo:late"].message.startswith("Timed out after 3 ticks")
    assert results["demo:flag"].optional


def test_await_for_is_the_old_spelling_of_await_delay(pack):
    root = pack({"demo/test/old.mcfunction": "await for 2s\n"})
    assert run(root).results[0].ticks == 40


def test_entity_and_data_messages_follow_packtest(pack):
    root = pack({
        "demo/test/ent.mcfunction": "assert entity @e[type=marker]\n",
        "demo/test/not_ent.mcfunction": "summon marker\nsummon marker\nassert not entity @e[type=marker]\n",
        "demo/test/data.mcfunction": "data modify storage demo:s x set value 3\nassert data storage demo:s y\n",
        "demo/test/not_data.mcfunction": "data modify storage demo:s x set value 3\nassert not data storage demo:s x\n",
    })
    results = by_id(run(root))
    assert results["demo:ent"].message == "Expected entity matching @e[type=marker]"
    assert results["demo:not_ent"].message == "Did not expect entity matching @e[type=marker], found 2"
    assert results["demo:data"].message == "Expected data at y, found {x:3}"
    assert results["demo:not_data"].message == "Did not expect data at x"


def test_score_messages_resolve_selector_holders(pack):
    root = pack({
        "demo/test/dummy.mcfunction": "# @dummy\nscoreboard objectives add o dummy\nscoreboard players set @s o 7\n"
                                      "assert score @s o matches 8\n",
        "demo/test/marker.mcfunction": "scoreboard objectives add o dummy\nsummon marker ~ ~ ~ {Tags:[\"m\"]}\n"
                                       "scoreboard players set @e[tag=m] o 3\n"
                                       "assert score @e[tag=m,limit=1] o matches 4\n",
    })
    results = by_id(run(root))
    assert results["demo:dummy"].message == "Expected score @s o to match 8, found 7"
    assert results["demo:marker"].message == "Expected score @e[tag=m,limit=1] o to match 4, found 3"


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_execute_run_assert_asserts_in_every_context(pack, backend):
    # PackTestExecutor runs each line as a command: an assert after `execute as ...` runs once per
    # context and the first failing one fails the test; with no context it never runs
    setup = ("scoreboard objectives add o dummy\n" + "summon marker ~ ~ ~ {Tags:[\"m\"]}\n" * 2
             + "scoreboard players set @e[tag=m,limit=1] o 1\n")
    root = pack({
        "demo/test/each.mcfunction": setup + "execute as @e[tag=none] run assert score @s o matches 5\n"
                                             "execute as @e[tag=m,limit=1] run assert score @s o matches 1\n"
                                             "execute as @e[tag=m] run assert not score @s o matches 2\n"
                                             "execute as @e[tag=m] run assert score @s o matches 1\n",
    })
    result = run(root, backend).results[0]
    assert (result.status, result.line) == ("failed", 8)
    assert result.message == "Expected score @s o matches 1 (in every context of the execute prefix)"


# PackTestExecutor (misode/packtest): a test command after `execute ... run` runs in each context of
# the prefix; each `await` that does not hold yet registers a poll (frozen with its context), and
# the polls are tried one at a time, the first after each tick, before the next step runs
PER_CONTEXT_TICK = ("scoreboard players add $t o 1\n"
                    "execute if score $t o matches 3.. run tag @e[tag=m1] add done\n"
                    "execute if score $t o matches 1.. run tag @e[tag=m2] add done\n")


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_await_after_execute_polls_each_context_in_turn(pack, backend):
    root = pack({
        "demo/function/init.mcfunction": "scoreboard objectives add o dummy\n",
        "demo/function/tick.mcfunction": PER_CONTEXT_TICK,
        "demo/test/each.mcfunction": "scoreboard players set $t o 0\n"
                                     "summon marker ~ ~ ~ {Tags:[m1]}\nsummon marker ~ ~ ~ {Tags:[m2]}\n"
                                     "execute as @e[type=marker] run await entity @s[tag=done]\n"
                                     "assert score $t o matches 4\n",
        # each: m1's poll passes after tick 3, m2's (true since tick 1) is tried after the next tick:
        # 4 ticks, not the 3 a re-evaluated prefix would take; delays: 2 contexts x 2 ticks
        "demo/test/delays.mcfunction": "scoreboard players set $t o 0\nsummon marker\nsummon marker\nexecute as @e[type=marker] run await delay 2\n"
                                       "assert score $t o matches 4\n",
        "demo/test/none.mcfunction": "scoreboard players set $t o 0\n"
                                     "execute as @e[type=marker] run await entity @s[tag=never]\n"
                                     "assert not score $t o matches 1..\n",  # no context: no tick waited
        "demo/test/timeout.mcfunction": "# @timeout 5\nsummon marker ~ ~ ~ {Tags:[m3]}\n"
                                        "execute as @e[type=marker] run await entity @s[tag=done]\n",
    }, load=["demo:init"], tick=["demo:tick"])
    results = by_id(run(root, backend))
    for test in ("each", "delays", "none"):
        assert results[f"demo:{test}"].status == "passed", (test, results[f"demo:{test}"].message)
    assert results["demo:timeout"].message.startswith("Timed out after 5 ticks: Expected entity matching @s[tag=done]")
    assert "(1 context(s) of the execute prefix waiting)" in results["demo:timeout"].message


def test_dummy_after_execute_runs_in_each_context(pack):
    # DummyCommand.spawn puts the dummy at the source's position: the prefix's, not the test's
    # (Vec3Argument centres integer x and z: 5 1 7 is 5.5 1 7.5)
    root = pack({
        "demo/test/spawn.mcfunction": "execute positioned 5 1 7 run dummy Bob spawn\n"
                                      "assert entity @a[name=Bob,x=5.5,y=1,z=7.5,distance=..0.001]\n",
        "demo/test/none.mcfunction": "execute if entity @e[type=marker] run dummy Bob spawn\nassert not entity @a\n",
        # conditions run as the emulator's `execute if` (here `if function`), per context
        "demo/test/function.mcfunction": "execute if function demo:yes positioned 1 1 1 unless function demo:no "
                                         "run dummy Bob spawn\nexecute if function demo:no run dummy Ann spawn\n"
                                         "assert entity @a[name=Bob,x=1.5,y=1,z=1.5,distance=..0.001]\n"
                                         "assert not entity @a[name=Ann]\n",
        "demo/function/yes.mcfunction": "return 1\n",
        "demo/function/no.mcfunction": "return 0\n",
        "demo/test/bad.mcfunction": "execute if function demo:yes if nonsense run dummy Bob spawn\n",
    })
    results = by_id(run(root))
    for test in ("spawn", "none", "function"):
        assert results[f"demo:{test}"].status == "passed", (test, results[f"demo:{test}"].message)
    assert results["demo:bad"].status == "failed" and results["demo:bad"].line == 1
