"""The entity table (emulator.world.entity_table): entities are views on its arrays."""
from __future__ import annotations

import numpy as np

from emulator.world.entities import EntityStore, add_tag
from emulator.world.entity_table import EF_X, EF_YAW, EI_ALIVE


def test_fields_are_views_on_the_arrays():
    store = EntityStore()
    a = store.summon("minecraft:marker", (1.0, 2.0, 3.0), yaw=370.0)
    table = store.table
    a.pos = (4.0, 5.0, 6.0)
    assert table.floats[a.order, EF_X] == 4.0
    table.floats[a.order, EF_X] = 7.5
    assert a.pos == (7.5, 5.0, 6.0)
    assert a.yaw == np.float32(370.0) and table.floats[a.order, EF_YAW] == 370.0
    store.kill(a)
    assert table.ints[a.order, EI_ALIVE] == 0 and not a.alive and table.count == 0


def test_tags_have_no_limit_per_pack():
    store = EntityStore()
    a, b = (store.summon("minecraft:marker", (0, 0, 0)) for _ in range(2))
    for i in range(200):
        add_tag(a if i % 2 else b, f"t{i}")
    assert store.table.tags.shape[1] == 4  # 200 tags: four 64-bit words
    assert "t199" in a.tags and "t199" not in b.tags and len(a.tags) == 100
    a.tags.discard("t199")
    assert "t199" not in a.tags and set(b.tags) == {f"t{i}" for i in range(0, 200, 2)}
    b.tags = {"t63", "t64"}
    assert sorted(b.tags) == ["t63", "t64"] and len(b.tags) == 2


def test_uuid_index_follows_changes_and_kills():
    store = EntityStore()
    a = store.summon("minecraft:marker", (0, 0, 0))
    b = store.summon("minecraft:marker", (0, 0, 0))
    assert store.by_uuid(a.uuid) is a
    old = a.uuid
    a.uuid = (1, 2, 3, 4)
    assert store.by_uuid(old) is None and store.by_uuid((1, 2, 3, 4)) is a
    store.kill(b)
    assert store.by_uuid(b.uuid) is None


def test_the_order_array_follows_the_store():
    store = EntityStore()
    entities = [store.summon("minecraft:marker", (i, 0, 0)) for i in range(40)]
    for e in entities[::3]:
        store.kill(e)
    assert store.table.living().tolist() == [e.order for e in store.entities]
