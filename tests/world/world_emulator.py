"""A small pack written from ``{"ns:path": text}`` and an Emulator on it, for tests run on both
backends (``t:setup`` creates the dummy objective ``o`` and has already run)."""
from __future__ import annotations

import json

from emulator import Emulator


def make_pack(root, functions: dict[str, str], tags: dict[str, list[str]] | None = None, pack_format: int = 48):
    """The pack (``pack_format`` 48: 1.21)."""
    root.mkdir(parents=True, exist_ok=True)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": "t"}}))
    for fid, text in functions.items():
        ns, path = fid.split(":", 1)
        file = root / "data" / ns / "function" / f"{path}.mcfunction"
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(text + "\n")
    for tid, values in (tags or {}).items():
        ns, path = tid.split(":", 1)
        file = root / "data" / ns / "tags" / "function" / f"{path}.json"
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(json.dumps({"values": values}))
    return root


def emulator(tmp_path, backend: str, functions: dict[str, str], tags: dict[str, list[str]] | None = None,
             pack_format: int = 48) -> Emulator:
    emu = Emulator(backend=backend)
    emu.load(make_pack(tmp_path / "p", {"t:setup": "scoreboard objectives add o dummy", **functions}, tags, pack_format))
    emu.call("t:setup")
    return emu
