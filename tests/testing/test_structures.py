"""``@template``: structure files read (binary NBT, gzipped) and placed for a test, so ``assert
block`` and entity conditions see them; clear errors for missing and corrupt files. The fixtures
are written here with struct and gzip, independently of the reader (format: the game's NbtIo and
StructureTemplate.save)."""
import gzip
import json
import struct

import pytest

from emulator.testing import discover, run_suite
from emulator.world.nbt_binary import NbtFormatError, read_nbt
from mcfunction_parser.nbt import Byte, Double, Int, List, String


# ---------------------------------------------------------------------- a tiny NBT writer
def _string(text: str) -> bytes:
    raw = text.encode("utf-8").replace(b"\x00", b"\xc0\x80")
    return struct.pack(">H", len(raw)) + raw


def _payload(kind: str, value) -> bytes:
    if kind in ("b", "s", "i", "l", "f", "d"):
        return struct.pack(">" + {"b": "b", "s": "h", "i": "i", "l": "q", "f": "f", "d": "d"}[kind], value)
    if kind == "str":
        return _string(value)
    if kind == "list":
        element, items = value
        return bytes([TYPES[element]]) + struct.pack(">i", len(items)) + b"".join(_payload(element, v) for v in items)
    if kind == "compound":
        return b"".join(bytes([TYPES[k]]) + _string(name) + _payload(k, v) for name, (k, v) in value.items()) + b"\0"
    raise ValueError(kind)


TYPES = {"b": 1, "s": 2, "i": 3, "l": 4, "f": 5, "d": 6, "str": 8, "list": 9, "compound": 10}


def nbt_file(root: dict, name: str = "") -> bytes:
    return gzip.compress(b"\x0a" + _string(name) + _payload("compound", root))


def ints(*values):
    return ("list", ("i", list(values)))


def structure(blocks, palette, entities=()) -> bytes:
    return nbt_file({
        "DataVersion": ("i", 3953),
        "size": ints(3, 2, 1),
        "palette": ("list", ("compound", palette)),
        "blocks": ("list", ("compound", blocks)),
        "entities": ("list", ("compound", list(entities))),
    })


PALETTE = [
    {"Name": ("str", "minecraft:stone")},
    {"Name": ("str", "minecraft:oak_stairs"), "Properties": ("compound", {"facing": ("str", "east"),
                                                                          "half": ("str", "bottom")})},
    {"Name": ("str", "minecraft:chest")},
]
BLOCKS = [
    {"pos": ints(0, 0, 0), "state": ("i", 0)},
    {"pos": ints(1, 0, 0), "state": ("i", 1)},
    {"pos": ints(2, 1, 0), "state": ("i", 2), "nbt": ("compound", {"Lock": ("str", "key")})},
]
ENTITY = {"pos": ("list", ("d", [1.5, 1.0, 0.5])), "blockPos": ints(1, 1, 0),
          "nbt": ("compound", {"id": ("str", "minecraft:armor_stand"), "Tags": ("list", ("str", ["from_template"])),
                               "Pos": ("list", ("d", [100.5, 64.0, 100.5])),
                               "UUID": ("list", ("i", [1, 2, 3, 4]))})}


def write(tmp_path, files: dict, pack_format: int = 48):
    root = tmp_path / "pack"
    (root).mkdir()
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": "t"}}))
    for rel, content in files.items():
        path = root / "data" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        (path.write_bytes if isinstance(content, bytes) else path.write_text)(content)
    return root


def results(root, backend="numba"):
    return {r.id: r for r in run_suite(discover([root]), backend).results}


# the structure's corner is the test source's block (GameTest: the structure block places it at
# its own position + (0, 1, 0), where PackTest 1.x runs the test; PackTest 2: the test origin)
TEST = ("# @template demo:room\n"
        "assert block ~ ~ ~ stone\n"
        "assert block ~1 ~ ~ oak_stairs[facing=east]\n"
        "assert block ~2 ~1 ~ chest{Lock:\"key\"}\n"
        "assert block ~1 ~1 ~ air\n"
        "assert block ~ ~-1 ~ structure_block\n"  # the test's own, under the corner (1.21)
        "assert entity @e[type=armor_stand,tag=from_template,x=1.5,y=2,z=0.5,distance=..0.001]\n"
        "assert not entity @e[type=armor_stand,nbt={UUID:[I;1,2,3,4]}]\n")


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_template_blocks_and_entities_are_placed_at_the_test_source(tmp_path, backend):
    root = write(tmp_path, {"demo/structure/room.nbt": structure(BLOCKS, PALETTE, [ENTITY]),
                            "demo/test/room.mcfunction": TEST})
    result = results(root, backend)["demo:room"]
    assert result.status == "passed", result.report()


def test_a_pack_before_1_21_keeps_its_templates_in_structures(tmp_path):
    root = write(tmp_path, {"demo/structures/room.nbt": structure(BLOCKS, PALETTE, [ENTITY]),
                            "demo/functions/f.mcfunction": "say hi\n",
                            "demo/tests/room.mcfunction": TEST}, pack_format=41)
    result = results(root)["demo:room"]
    assert result.status == "passed", result.report()


def test_a_missing_template_fails_the_test_with_its_name(tmp_path):
    root = write(tmp_path, {"demo/test/t.mcfunction": "# @template demo:nowhere\nsucceed\n"})
    result = results(root)["demo:t"]
    assert result.status == "failed"
    assert result.message == "Missing test structure: demo:nowhere (no data/demo/structure/nowhere.nbt)"


@pytest.mark.parametrize("content, message", [
    (nbt_file({"size": ints(1, 1, 1)})[:-6], "not a valid NBT file: broken gzip data"),
    (gzip.compress(b"\x0a\x00\x00\x03\x00\x04size\x00\x00"), "not a valid NBT file: the file ends at byte 12 "
                                                              "inside Int (at byte 10)"),
    (gzip.compress(b"\x09\x00\x00"), "not a valid NBT file: the root tag must be a compound (type 10), "
                                     "found type 9"),
    (nbt_file({"size": ints(1, 1)}), "size: expected 3 ints"),
    (nbt_file({"size": ints(1, 1, 1), "blocks": ("list", ("compound", []))}), "no palette"),
    (structure([{"pos": ints(0, 0, 0), "state": ("i", 7)}], PALETTE), "blocks[0].state: expected a palette "
                                                                        "index 0..2, got 7"),
], ids=["truncated gzip", "truncated tag", "list root", "bad size", "no palette", "bad state"])
def test_a_corrupt_template_fails_the_test_saying_what_is_wrong(tmp_path, content, message):
    root = write(tmp_path, {"demo/structure/bad.nbt": content,
                            "demo/test/t.mcfunction": "# @template demo:bad\nsucceed\n"})
    result = results(root)["demo:t"]
    assert result.status == "failed"
    assert result.message.startswith(f"Test structure demo:bad: {message}")


def test_binary_nbt_values_and_modified_utf8():
    data = nbt_file({"b": ("b", -2), "name": ("str", "a\0b"), "l": ("list", ("d", [0.5])),
                     "nested": ("compound", {"x": ("i", 7)}), "empty": ("list", ("i", []))}, name="root")
    name, root = read_nbt(data)
    assert name == "root"
    assert root == {"b": -2, "name": "a\0b", "l": [0.5], "nested": {"x": 7}, "empty": []}
    assert type(root["b"]) is Byte and type(root["l"]) is List and type(root["l"][0]) is Double
    assert type(root["nested"]["x"]) is Int and type(root["name"]) is String
    assert read_nbt(gzip.decompress(data))[1] == root          # uncompressed files read too


def test_a_list_longer_than_the_file_is_an_error_not_a_hang():
    with pytest.raises(NbtFormatError, match="runs past the end of the file"):
        read_nbt(b"\x0a\x00\x00\x09\x00\x01l\x03\x7f\xff\xff\xff\x00")


@pytest.mark.parametrize("template", ["minecraft:empty", "packtest:empty"])
def test_the_empty_template_needs_no_file(tmp_path, template):
    # PackTestFunction: a test without @template gets minecraft:empty, "an empty 1x1x1 structure"
    # (PackTest's README; packtest:empty, which its jar ships, before): naming it is the same, walls
    # one block round that one block
    root = write(tmp_path, {"demo/test/t.mcfunction": f"# @template {template}\n"
                                                      "assert block ~1 ~ ~ minecraft:barrier\n"
                                                      "assert block ~ ~ ~ minecraft:air\n"})
    result = results(root)["demo:t"]
    assert result.status == "passed", result.report()
