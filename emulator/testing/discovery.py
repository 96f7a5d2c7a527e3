"""Finding PackTest test files: ``data/<ns>/test/**.mcfunction`` (``tests`` in PackTest before 1.21)
inside a pack (the nearest folder holding ``pack.mcmeta``); the test id is ``ns:path``."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

TEST_FOLDERS = ("test", "tests")


@dataclass(frozen=True)
class TestFile:
    id: str  # ns:path
    path: Path
    pack_root: Path


class DiscoveryError(Exception):
    pass


def pack_root(path: Path) -> Path:
    """The pack holding ``path``: the nearest folder (``path`` itself included) with pack.mcmeta."""
    for folder in [path, *path.parents] if path.is_dir() else path.parents:
        if (folder / "pack.mcmeta").is_file():
            return folder
    raise DiscoveryError(f"{path}: not inside a datapack (no pack.mcmeta in it or above it)")


def test_id(path: Path, root: Path) -> str | None:
    """``ns:path`` for a test file, None when ``path`` is not under ``data/<ns>/test[s]/``."""
    parts = path.relative_to(root).parts
    if len(parts) < 4 or parts[0] != "data" or parts[2] not in TEST_FOLDERS or path.suffix != ".mcfunction":
        return None
    return f"{parts[1]}:" + "/".join(parts[3:])[: -len(".mcfunction")]


def discover(paths: list[str | Path]) -> list[TestFile]:
    """Every test file under ``paths`` (folders are searched; a file is taken as given), sorted by
    pack then id, each once."""
    found: dict[Path, TestFile] = {}
    for given in paths:
        path = Path(given).resolve()
        if not path.exists():
            raise DiscoveryError(f"{given}: no such file or folder")
        root = pack_root(path)
        candidates = [path] if path.is_file() else sorted(path.rglob("*.mcfunction"))
        for candidate in candidates:
            tid = test_id(candidate, root)
            if tid is None:
                if path.is_file():
                    raise DiscoveryError(f"{given}: not a test file (expected data/<ns>/test/<name>.mcfunction)")
                continue
            found.setdefault(candidate, TestFile(tid, candidate, root))
    return sorted(found.values(), key=lambda t: (str(t.pack_root), t.id))
