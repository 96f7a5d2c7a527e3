"""Finding PackTest test files: ``data/<ns>/test/**.mcfunction`` (``tests`` in PackTest before 1.21)
inside a pack (the nearest folder holding ``pack.mcmeta``, or a .zip pack); the test id is ``ns:path``."""
from __future__ import annotations

import zipfile
from dataclasses import dataclass
from pathlib import Path

from mcfunction_parser.pack.loader import zip_problem

TEST_FOLDERS = ("test", "tests")


@dataclass(frozen=True)
class TestFile:
    id: str  # ns:path
    path: Path | zipfile.Path  # inside a .zip pack: the member
    pack_root: Path  # the pack's folder or .zip file


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
    return _member_id(path.relative_to(root).parts)


def _member_id(parts: tuple[str, ...]) -> str | None:
    if len(parts) < 4 or parts[0] != "data" or parts[2] not in TEST_FOLDERS or not parts[-1].endswith(".mcfunction"):
        return None
    return f"{parts[1]}:" + "/".join(parts[3:])[: -len(".mcfunction")]


def _zip_tests(archive: Path) -> list[TestFile]:
    """The test files of a .zip pack."""
    problem = zip_problem(archive)
    if problem:
        raise DiscoveryError(f"{archive} {problem}")
    with zipfile.ZipFile(archive) as z:
        names = z.namelist()
    if "pack.mcmeta" not in names:
        raise DiscoveryError(f"{archive}: not a datapack (no pack.mcmeta at the top of the archive)")
    found = [(_member_id(tuple(name.split("/"))), name) for name in names]
    return [TestFile(tid, zipfile.Path(archive, name), archive) for tid, name in found if tid is not None]


def discover(paths: list[str | Path]) -> list[TestFile]:
    """Every test file under ``paths`` (folders are searched; a file is taken as given), sorted by
    pack then id, each once."""
    found: dict[Path, TestFile] = {}
    for given in paths:
        path = Path(given).resolve()
        if not path.exists():
            raise DiscoveryError(f"{given}: no such file or folder")
        if path.is_file() and (path.suffix.lower() == ".zip" or zipfile.is_zipfile(path)):
            for tf in _zip_tests(path):
                found.setdefault(tf.path, tf)
            continue
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


def selected(files: list[TestFile], pattern: str | None) -> list[TestFile]:
    """The tests ``-k PATTERN`` keeps: those whose id contains it, ignoring case."""
    if pattern is None:
        return files
    return [f for f in files if pattern.lower() in f.id.lower()]
