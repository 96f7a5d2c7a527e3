"""Fixtures shared by the suite: small packs written to a temporary folder."""
import json
import zipfile
from pathlib import Path

import pytest

from mcfunction_parser.frozen_init import guard_nodes

# The AST's nodes are immutable by convention when dpemu runs (frozen_init); the suite runs with
# the frozen guard on, so code that assigns to a node's field fails here.
guard_nodes()


# A PackTest test without a template is a 1x1x1 structure encased in barriers: walls one block out
# and a ceiling one block up (StructureUtils.encaseStructure, TestInstanceBlockEntity). A mob or dummy
# whose eyes are in one suffocates (Entity.isInWall: a barrier is a full, suffocating cube), so a test
# standing them round its origin first clears the barriers there.
OPEN_AREA = "fill ~-1 ~ ~-1 ~1 ~1 ~1 air\n"


def write_pack(root: Path, files: dict[str, str], tick: list[str] | None = None, load: list[str] | None = None) -> Path:
    """A pack at ``root`` with ``files`` (path under data/ -> text) and optional tick/load tags."""
    root.mkdir(parents=True, exist_ok=True)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "t"}}))
    for rel, text in files.items():
        path = root / "data" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    for name, members in (("tick", tick), ("load", load)):
        if members:
            tag = root / "data/minecraft/tags/function" / f"{name}.json"
            tag.parent.mkdir(parents=True, exist_ok=True)
            tag.write_text(json.dumps({"values": members}))
    return root


@pytest.fixture
def pack(tmp_path):
    def make(files, **tags):
        return write_pack(tmp_path / "pack", files, **tags)
    return make


def zip_folder(folder: Path, archive: Path) -> Path:
    """``folder``'s files in a .zip at ``archive`` (a pack as players download it)."""
    with zipfile.ZipFile(archive, "w") as z:
        for path in folder.rglob("*"):
            if path.is_file():
                z.write(path, path.relative_to(folder).as_posix())
    return archive
