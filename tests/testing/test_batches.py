"""The game test server's run: one world, batches in the game's order, a batch's tests together on a
grid (emulator.testing.batches, the runner's _World)."""

import pytest

from emulator.testing import discover, run_suite
from emulator.testing.batches import Grid, cleared_box, plan
from emulator.testing.directives import Directives
from emulator.testing import testfile
from emulator.world.hash_order import java_hash_map_order as hashmap_order, java_string_hash
from emulator.world.hash_order import resource_location_hash as identifier_hash


def run(root, backend="numba", **options):
    return run_suite(discover([root]), backend, **options)


def by_id(summary):
    return {r.id: r for r in summary.results}


def test_hashmap_order_is_javas():
    # printed by java.util.HashMap.keySet() (OpenJDK 17) after putting the keys in this order; a
    # record whose hashCode is ResourceLocation.hashCode's (31 * namespace + path) for the ids
    assert hashmap_order(["b1", "alpha", "packtestBatch", "zeta"], java_string_hash) == \
        ["zeta", "packtestBatch", "alpha", "b1"]
    ids = ["demo:a", "demo:b", "demo:sub/c", "other:a", "one:two"]
    assert hashmap_order(ids, java_string_hash) == ["demo:sub/c", "other:a", "demo:b", "one:two", "demo:a"]
    assert hashmap_order(ids, identifier_hash) == ["one:two", "demo:sub/c", "other:a", "demo:a", "demo:b"]
    assert hashmap_order(["apple", "banana", "cherry"], java_string_hash) == ["banana", "apple", "cherry"]


def case(test_id, batch="packtestBatch", environment="minecraft:default"):
    return testfile.TestCase(test_id, test_id, Directives(batch=batch, environment=environment))


def test_plan_groups_by_batch_before_1_21_5_and_by_environment_after():
    # GameTestBatchFactory.fromTestFunction (1.21): groupingBy(batchName) into a HashMap, lists of
    # 50 (MAX_TESTS_PER_BATCH) named "<batch>:<index>"; divideIntoBatches (1.21.5+) by environment
    cases = [case("demo:a", "b1", "x:e"), case("demo:b", "zeta", "x:f"), case("demo:sub/c", "b1", "x:e")]
    old = plan(cases, test_instances=False)
    assert [(b.name, [c.id for c in b.cases]) for b in old] == [("zeta:0", ["demo:b"]), ("b1:0", ["demo:sub/c", "demo:a"])]
    new = plan(cases, test_instances=True)
    assert [(b.name, [c.id for c in b.cases]) for b in new] == [("x:e:0", ["demo:sub/c", "demo:a"]), ("x:f:0", ["demo:b"])]
    many = plan([case(f"demo:t{i}") for i in range(120)], test_instances=False)
    assert [len(b.cases) for b in many] == [50, 50, 20] and many[2].name == "packtestBatch:2"


def test_grid_rows_of_eight():
    # StructureGridSpawner: the next corner 5 blocks past the structure's far side; after 8 tests
    # a new row south of the deepest structure of the row plus 6
    grid = Grid((0, 1, 0))
    corners = [grid.place((3, 2, 4 if i == 2 else 1)) for i in range(9)]
    assert corners[:3] == [(0, 1, 0), (8, 1, 0), (16, 1, 0)]
    assert corners[8] == (0, 1, 10)
    assert cleared_box((0, 1, 0), (1, 1, 1)) == ((-2, -2, -3), (3, 21, 3))


def test_tests_share_one_world_unless_isolated(pack):
    root = pack({
        "demo/function/init.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set $loaded o 1\n",
        "demo/test/a.mcfunction": "scoreboard players set $leak o 1\nassert score $loaded o matches 1\n",
        "demo/test/b.mcfunction": "assert score $leak o matches 1\nassert score $loaded o matches 1\n",
    }, load=["demo:init"])
    shared = by_id(run(root))  # demo:a starts first (HashMap order), in the same tick as demo:b
    assert shared["demo:a"].status == shared["demo:b"].status == "passed"
    isolated = by_id(run(root, isolate=True))
    assert isolated["demo:b"].message == "Expected score $leak o to match 1, found undefined"


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_batchs_tests_run_together(pack, backend):
    # GameTestTicker.tick: every test of the batch takes its turn each tick, so one waits for what
    # another does later; a batch starts only when the one before has ended
    root = pack({
        "demo/test/a.mcfunction": "# @batch one\nawait score $b o matches 1\nscoreboard players set $a o 1\n",
        "demo/test/b.mcfunction": "# @batch one\nscoreboard objectives add o dummy\nawait delay 3t\n"
                                  "scoreboard players set $b o 1\nawait score $a o matches 1\n",
        "demo/test/later.mcfunction": "# @batch two\nassert score $a o matches 1\nassert score $b o matches 1\n",
    })
    results = by_id(run(root, backend))
    assert [results[t].status for t in ("demo:a", "demo:b", "demo:later")] == ["passed"] * 3
    # demo:a's turn comes before demo:b's in a tick: it sees $b set by demo:b's turn of tick 3 at tick 4
    assert results["demo:a"].ticks == 4 and results["demo:b"].ticks == 4


def test_a_passed_test_takes_its_entities_with_it_and_the_next_place_is_cleared(pack):
    # GameTestInfo.succeed removes the entities (not players) in the structure's bounds grown by
    # a block; an entity elsewhere stays for the tests after it. StructureUtils.clearSpaceForStructure
    # clears round each test's place: stone under it, air above, no entities (1.21's layout: the
    # first corner (0, 1, 0), the second 6 blocks east; the structure block under each corner)
    root = pack({
        "demo/test/a.mcfunction": "# @batch one\nsummon marker ~ ~ ~ {Tags:[\"in\"]}\n"
                                  "summon marker ~ ~ ~20 {Tags:[\"out\"]}\nsetblock 30 5 30 stone\n"
                                  "setblock 6 5 0 gold_block\n",
        "demo/test/z.mcfunction": "# @batch two\nassert entity @e[tag=out]\nassert not entity @e[tag=in]\n"
                                  "assert block 30 5 30 stone\nassert block ~ ~4 ~ air\nassert block ~ ~-2 ~ stone\n"
                                  "assert block ~ ~-1 ~ structure_block\n",
    })  # pack format 48: 1.21
    results = by_id(run(root))
    assert results["demo:z"].status == "passed", results["demo:z"].message


def test_a_dummy_name_already_online_is_drawn_again(pack):
    # Dummy.createRandom: up to ten draws until the name is free. demo:a and demo:t828 draw the same
    # first name here (Dummy460); demo:a fails, so its dummy stays online for demo:t828's batch
    root = pack({"demo/test/a.mcfunction": "# @dummy\n# @batch one\nfail \"keeps its dummy\"\n",
                 "demo/test/t828.mcfunction": "# @dummy\n# @batch two\nassert entity @a[name=Dummy460]\n"
                                              "assert entity @s[name=!Dummy460]\n"})
    results = by_id(run(root))
    assert results["demo:a"].status == "failed"
    assert results["demo:t828"].status == "passed", results["demo:t828"].message
