"""How the game test server orders and places a run's tests: one world, batches one after another,
the tests of a batch side by side on a grid and run together.

- The tests' order is PackTest's: it reads the test files into a ``java.util.HashMap`` keyed by
  id (PackTestLibrary.reload) and registers them in that map's iteration order
  (:func:`emulator.world.hash_order.java_hash_map_order`).
- Before 1.21.5 (GameTestBatchFactory.fromTestFunction) the tests are grouped by ``@batch`` name
  into a HashMap, so the batches run in that map's order; from 1.21.5 (divideIntoBatches) by test
  environment and dimension, a HashMap keyed by registry holders whose hash is their identity:
  the game's order of environments changes from one start to the next, the emulator takes the
  order in which the tests name them. Either way a group is split into batches of 50.
- StructureGridSpawner (built by GameTestServer.startTests with 8 tests a row and no clearing
  between batches): each test's corner is 5 blocks east of the previous structure's far side,
  and after 8 tests the row moves south by its depth plus 6. The game starts the grid at y -59
  of its superflat world (grass at -61, dirt, bedrock at -64), x and z random (GameTestServer.
  startTests; PackTest's GameTestServerMixin draws them within the world border) and makes that
  the world spawn; the emulator starts at (0, 1, 0) with no ground beyond the cleared space.
- StructureUtils.clearSpaceForStructure: before a test's structure is placed, the box from 2
  blocks west, 3 below and 3 north to 3 east, 20 above and 3 south of it becomes air, stone
  below the structure's floor less one, and the entities in it other than players are removed
  (PackTest's StructureUtilsMixin makes the dummies in it leave).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from emulator.world.hash_order import java_hash_map_order, java_string_hash, resource_location_hash

BATCH_SIZE = 50  # GameTestBatchFactory.MAX_TESTS_PER_BATCH
TESTS_PER_ROW = 8  # GameTestRunner.DEFAULT_TESTS_PER_ROW
SPACE_BETWEEN_COLUMNS, SPACE_BETWEEN_ROWS = 5, 6  # StructureGridSpawner


@dataclass
class Batch:
    name: str  # as the game logs it: the @batch name or the environment, and the index
    cases: list = field(default_factory=list)


def plan(cases: list, test_instances: bool) -> list[Batch]:
    """The run's batches in the order the game runs them, each with its tests in order.
    ``test_instances``: 1.21.5 and later (grouped by environment, else by ``@batch``)."""
    by_id = {case.id: case for case in cases}
    ordered = [by_id[i] for i in java_hash_map_order(list(by_id), resource_location_hash)]
    groups: dict[str, list] = {}
    for case in ordered:
        key = case.directives.environment if test_instances else case.directives.batch
        groups.setdefault(key, []).append(case)
    keys = list(groups) if test_instances else java_hash_map_order(list(groups), java_string_hash)
    return [Batch(f"{key}:{i // BATCH_SIZE}", groups[key][i:i + BATCH_SIZE])
            for key in keys for i in range(0, len(groups[key]), BATCH_SIZE)]


class Grid:
    """StructureGridSpawner.spawnStructure: the corner of each next test's structure."""

    def __init__(self, first: tuple[int, int, int]) -> None:
        self.first = first
        self.next = list(first)
        self.row_count = 0
        self.row_depth = 1  # rowBounds starts as the unit box at the row's first corner

    def place(self, size: tuple[int, int, int]) -> tuple[int, int, int]:
        corner = tuple(self.next)
        self.row_depth = max(self.row_depth, size[2])
        self.next[0] += size[0] + SPACE_BETWEEN_COLUMNS
        self.row_count += 1
        if self.row_count >= TESTS_PER_ROW:
            self.row_count = 0
            self.next[2] += self.row_depth + SPACE_BETWEEN_ROWS
            self.next[0] = self.first[0]
            self.row_depth = 1
        return corner


def cleared_box(corner, size) -> tuple[tuple[int, int, int], tuple[int, int, int]]:
    """The inclusive box clearSpaceForStructure clears round a structure."""
    x, y, z = corner
    far = (x + size[0] - 1, y + size[1] - 1, z + size[2] - 1)
    return (x - 2, y - 3, z - 3), (far[0] + 3, far[1] + 20, far[2] + 3)
