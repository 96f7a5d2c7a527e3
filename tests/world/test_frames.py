"""An item frame summoned hangs as the game hangs it (decompiled 26.1.2: SummonCommand.createEntity
loads the NBT then snaps to the position; BlockAttachedEntity.setPos, HangingEntity.recalculateBoundingBox,
ItemFrame.setDirection/createBoundingBox/readAdditionalSaveData/addAdditionalSaveData)."""
import pytest

from emulator.api import Emulator
from emulator.world.entities import EntityStore
from mcfunction_parser.nbt import Byte, Compound, Double, List
from tests.conftest import write_pack

BACKENDS = ["numba", "python"]


def frame(tmp_path, backend, nbt: str, mc: str):
    pack = write_pack(tmp_path / "pack", {"t/function/go.mcfunction": f"summon item_frame 1.2 64.7 1.9 {nbt}"})
    emu = Emulator(backend=backend)
    emu.load(pack, mc_version=mc)
    emu.start()
    emu.call("t:go")
    return emu._one_entity("@e[type=item_frame,limit=1]")


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_summoned_frame_hangs_on_its_positions_block(tmp_path, backend):
    # facing north: the block's centre less 0.46875 north; yaw 180; the defaults saved
    entity = frame(tmp_path, backend, "{Facing:2b,ItemRotation:3b}", "1.21.5")
    assert entity.pos == (1.5, 64.5, 1.96875)
    assert (float(entity.yaw), float(entity.pitch)) == (180.0, 0.0)
    data = entity.data
    assert list(data["block_pos"]) == [1, 64, 1] and "TileX" not in data
    assert (int(data["ItemRotation"]), float(data["ItemDropChance"]), int(data["Fixed"]), int(data["Invisible"])) == \
        (3, 1.0, 0, 0)


@pytest.mark.parametrize("backend", BACKENDS)
def test_without_a_facing_it_faces_down(tmp_path, backend):
    # ItemFrame.readAdditionalSaveData: Facing missing reads as down; pitch -90 x the step (down: 90)
    entity = frame(tmp_path, backend, "{}", "1.21.4")
    assert entity.pos == (1.5, 64.96875, 1.5)
    assert (float(entity.yaw), float(entity.pitch)) == (0.0, 90.0)
    assert (int(entity.data["Facing"]), int(entity.data["TileX"]), int(entity.data["TileY"])) == (0, 1, 64)


@pytest.mark.parametrize("version, y", [((1, 21, 4), 64.375), ((1, 16, 5), 64.5)])
def test_a_summoned_leash_knot_sits_on_its_blocks_centre(version, y):
    # BlockAttachedEntity.setPos -> LeashFenceKnotEntity.recalculateBoundingBox: the block's centre
    # x/z, 0.375 up (1.16.5: 0.5); its block saved as TileX/Y/Z (block_pos from 1.21.5)
    store = EntityStore()
    store.version = version
    knot = store.summon("minecraft:leash_knot", (3.9, 64.8, -2.2))
    assert knot.pos == (3.5, y, -2.5)
    assert (int(knot.data["TileX"]), int(knot.data["TileY"]), int(knot.data["TileZ"])) == (3, 64, -3)


@pytest.mark.parametrize("version", [(1, 21, 4), (1, 21, 5)])
def test_data_on_a_frame_hangs_it_from_its_saved_block_and_facing(version):
    # Entity.load reads Pos, then BlockAttachedEntity.readAdditionalSaveData its block (within 16 of
    # Pos) and ItemFrame.setDirection its Facing: a new Facing turns it on its block, a new Pos alone
    # puts it back
    store = EntityStore()
    store.version = version
    frame = store.summon("minecraft:item_frame", (2.5, 65.0, 2.5), Compound(Facing=Byte(1)))
    assert frame.pos == (2.5, 65.03125, 2.5)
    store.modify(frame, lambda nbt: nbt.update(Facing=Byte(2)))  # north: on the block's south face
    assert frame.pos == (2.5, 65.5, 2.96875) and float(frame.yaw) == 180.0
    store.modify(frame, lambda nbt: nbt.update(Pos=List([Double(9.0), Double(70.0), Double(9.0)])))
    assert frame.pos == (2.5, 65.5, 2.96875)
