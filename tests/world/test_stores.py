"""``data get`` results and ``execute store`` into NBT (decompiled 1.21
server/commands/data/DataCommands.java getData/getNumeric, ExecuteCommand.java storeData)."""
from __future__ import annotations

import pytest

from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, IntArray, List, Long, String
from emulator.world import stores
from emulator.world.errors import CommandFailure
from tests.world.world_paths import path


def test_data_get_numbers_floor_not_truncate():
    root = Compound(d=Double(-2.5), f=Float(1.75), l=Long(2**40), b=Byte(-3))
    assert stores.data_get(root, path("d", "d")) == -3  # Mth.floor, not (int)
    assert stores.data_get(root, path("f", "f")) == 1
    assert stores.data_get(root, path("l", "l")) == 2**31 - 1  # Mth.floor saturates
    assert stores.data_get(root, path("b", "b")) == -3


def test_data_get_sizes_of_non_numbers():
    root = Compound(l=List([Int(1), Int(2)]), a=IntArray([1, 2, 3]), c=Compound(x=Int(1)), s=String("a\U0001F600"))
    assert stores.data_get(root, path("l", "l")) == 2
    assert stores.data_get(root, path("a", "a")) == 3
    assert stores.data_get(root, path("c", "c")) == 1
    assert stores.data_get(root, path("s", "s")) == 3  # String.length counts UTF-16 units


def test_data_get_scaled():
    root = Compound(d=Double(0.3), s=String("x"), l=List([Int(1), Int(2)]))
    assert stores.data_get_scaled(root, path("d", "d"), 10.0) == 3  # floor(0.3 * 10.0) = floor(3.0)
    assert stores.data_get_scaled(root, path("d", "d"), -10.0) == -3
    with pytest.raises(CommandFailure) as err:
        stores.data_get_scaled(root, path("s", "s"), 1.0)
    assert err.value.message == "Can't get s; only numeric tags are allowed"
    with pytest.raises(CommandFailure, match="single NBT value"):
        stores.data_get(root, path("l[]", "l", "[]"))
    with pytest.raises(CommandFailure, match="Found no elements matching x"):
        stores.data_get(root, path("x", "x"))


def test_store_writes_the_cast_tag_and_swallows_path_errors():
    root = Compound(s=String("text"))
    assert stores.store(root, path("a.b", "a", "b"), "short", 70000, 1.0) == 1
    assert root["a"]["b"] == 70000 - 65536
    assert stores.store(root, path("v", "v"), "double", 3, 0.5) == 1 and root["v"] == 1.5
    # A key under a string selects nothing to set; a failing path (nothing found for a parent
    # that cannot be created) is caught by the game's store callback: both store nothing.
    assert stores.store(root, path("s.x", "s", "x"), "int", 1, 1.0) == 0
    assert stores.store(root, path("s.x.y", "s", "x", "y"), "int", 1, 1.0) == 0
    assert root["s"] == "text"


def test_store_into_entities():
    from emulator.commands.data import EntityAccessor
    from emulator.world.entities import EntityStore

    def store_entity(entity, p, type_name, value, scale):
        """ExecuteCommand.storeData through the entity's accessor: the tags changed, 0 on a failure."""
        try:
            return EntityAccessor(entity, store).change(lambda root: stores.store(root, p, type_name, value, scale))
        except CommandFailure:
            return 0

    store = EntityStore()
    marker = store.summon("minecraft:marker", (0.0, 0.0, 0.0))
    assert store_entity(marker, path("Pos[1]", "Pos", 1), "double", 5, 0.5) == 1
    assert marker.pos == (0.0, 2.5, 0.0)
    assert store_entity(marker, path("Rotation[0]", "Rotation", 0), "float", 725, 1.0) == 1
    assert marker.yaw == 5.0  # loading Rotation keeps yaw % 360
    # An int into a list of doubles is refused by ListTag.setTag: nothing stored.
    assert store_entity(marker, path("Pos[0]", "Pos", 0), "int", 7, 1.0) == 0
    player = store.add_player("Steve", (0.0, 0.0, 0.0))
    assert store_entity(player, path("Pos[1]", "Pos", 1), "double", 5, 1.0) == 0
    assert player.pos == (0.0, 0.0, 0.0)


def test_command_storage_accessor():
    from emulator.world import nbt_ops
    from emulator.world.storage import CommandStorage

    storage = CommandStorage()
    # A failing change on a new id stores nothing.
    with pytest.raises(CommandFailure, match="Nothing changed"):
        storage.modify("ns:a", lambda root: nbt_ops.data_remove(root, path("x", "x")))
    assert storage.ids() == []
    storage.modify("ns:a", lambda root: nbt_ops.modify(root, path("l", "l"), "append", [Int(1)]))
    assert storage.get("ns:a") == {"l": [1]}
    # On an existing storage the game edits the live compound: a later failure keeps earlier edits.
    with pytest.raises(CommandFailure, match="Invalid list index"):
        storage.modify("ns:a", lambda root: nbt_ops.modify(root, path("m.l", "m", "l"), "insert", [Int(1)], index=3))
    assert storage.get("ns:a") == {"l": [1], "m": {"l": []}}
    # Emptying a storage removes its id (CommandStorage.Container.put).
    storage.modify("ns:a", lambda root: [nbt_ops.data_remove(root, path(k, k)) for k in ("l", "m")])
    assert storage.ids() == []
