"""No silent gaps: a test that runs something the emulator does not model (a command with effects a
pack can read back, a predicate condition, an unknown vanilla tag) is inconclusive with the reason,
counted apart; ``--allow-unmodelled`` turns it back into pass/fail. Commands whose only effect is
shown to players (particle, playsound) keep the test conclusive."""
import json
import xml.etree.ElementTree as ET

import pytest

from emulator.testing import discover, run_suite
from emulator.testing.junit import junit_xml
from tests.conftest import write_pack

FILES = {
    "demo/test/frozen.mcfunction": "tick freeze\nsucceed\n",
    "demo/test/frozen_fails.mcfunction": "tick freeze\nfail \"boom\"\n",
    "demo/test/sounds.mcfunction": "particle flame ~ ~ ~\nplaysound minecraft:block.note_block.harp master @a\n"
                                   "forceload add 0 0\nsucceed\n",
    "demo/test/locate.mcfunction": "locate structure minecraft:village_plains\nsucceed\n",
    "demo/test/vanilla_tag.mcfunction": "summon pig ~ ~ ~\nassert entity @e[type=#minecraft:logs]\n",
    # the game's own advancements are not loaded: granting or reading one is not modelled, and a
    # pack's unknown one is the game's error
    "demo/test/vanilla_advancement.mcfunction": "# @dummy\nadvancement grant @s only minecraft:story/root\n"
                                                "assert entity @s[advancements={minecraft:story/root=true}]\n",
    "demo/test/own_advancement.mcfunction": "# @dummy\nassert not entity @s[advancements={demo:nope=true}]\n",
    # light from a block whose shape (and so its light) is not kept here: a fence beside the dummy
    "demo/test/condition.mcfunction": "# @dummy ~ ~ ~\nsetblock ~1 ~ ~ minecraft:oak_fence\n"
                                      "assert predicate demo:equipped\n",
    "demo/predicate/equipped.json": json.dumps({"condition": "minecraft:entity_properties", "entity": "this",
                                                "predicate": {"location": {"light": {"light": {"min": 1}}}}}),
}


def run(tmp_path, backend="numba", **options):
    root = write_pack(tmp_path / "pack", FILES)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "t"}}))
    summary = run_suite(discover([root]), backend, **options)
    return summary, {r.id: r for r in summary.results}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_unmodelled_effects_make_tests_inconclusive_with_the_reason(tmp_path, backend):
    summary, results = run(tmp_path, backend)
    status = {k: r.status for k, r in results.items()}
    assert status == {"demo:frozen": "inconclusive", "demo:frozen_fails": "inconclusive",
                      "demo:sounds": "passed", "demo:vanilla_tag": "inconclusive", "demo:condition": "inconclusive",
                      "demo:locate": "inconclusive", "demo:vanilla_advancement": "inconclusive",
                      "demo:own_advancement": "passed"}
    assert "the game's own advancement minecraft:story/root" in results["demo:vanilla_advancement"].message
    assert "'tick' is not emulated" in results["demo:frozen"].message
    assert results["demo:frozen"].message.endswith("the test passed")
    assert "failed (boom)" in results["demo:frozen_fails"].message
    assert "#minecraft:logs is not known" in results["demo:vanilla_tag"].message
    assert "location predicate field 'light'" in results["demo:condition"].message
    assert summary.line() == "2 passed, 0 failed, 6 inconclusive"
    skipped = ET.fromstring(junit_xml(summary)).find(".//testcase[@name='frozen']/skipped")
    assert skipped is not None and skipped.get("type") == "inconclusive"


def test_allow_unmodelled_gives_pass_and_fail_back(tmp_path):
    summary, results = run(tmp_path, "python", allow_unmodelled=True)
    assert results["demo:frozen"].status == "passed"
    assert results["demo:frozen_fails"].status == "failed"
    assert results["demo:condition"].status == "failed"  # the command failed as not modelled


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_lines_of_releases_newer_than_the_model_make_their_tests_inconclusive(tmp_path, backend):
    # a 26.2 pack (format 107.1: no command tree of its own here) may use syntax no reader knows:
    # the line is a warning, the function still loads, and running the line is not modelled rather
    # than skipped; 26.1's world clocks are modelled (tests/world/test_clocks.py), so a test using
    # one has a verdict
    def suite(name, fmt, files):
        root = write_pack(tmp_path / name, files)
        (root / "pack.mcmeta").write_text(json.dumps({"pack": {"description": "t", "min_format": fmt,
                                                               "max_format": fmt}}))
        return {r.id: r for r in run_suite(discover([root]), backend).results}
    results = suite("clock", 101, {"demo/test/clock.mcfunction": "time of the_end add 1t\nsucceed\n",
                                   "demo/test/plain.mcfunction": "time add -5\nsucceed\n"})
    assert results["demo:plain"].status == "passed" and results["demo:clock"].status == "passed"
    results = suite("newer", [107, 1], {"demo/test/new.mcfunction": "frobnicate 1\nsucceed\n"})
    assert results["demo:new"].status == "inconclusive"
    assert ("'frobnicate' is not emulated here: the line was not read (unknown command 'frobnicate' (checked "
            "against the 26.1 command tree: dpemu has none for 26.2))") in results["demo:new"].message
