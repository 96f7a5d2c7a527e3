"""Builders for fixture packs in temporary folders (imported by the pack tests)."""
from __future__ import annotations

import json
from pathlib import Path


def write_pack(root: Path, files: dict[str, str | bytes], meta: dict | str | None = None) -> Path:
    """Create a pack: ``meta`` is pack.mcmeta (dict -> JSON, str -> raw text, None -> no file);
    ``files`` maps relative paths to text or raw bytes."""
    root.mkdir(parents=True, exist_ok=True)
    if meta is not None:
        (root / "pack.mcmeta").write_text(meta if isinstance(meta, str) else json.dumps(meta))
    for rel, content in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8", newline="")
    return root


def meta(pack_format: int = 61, **pack_fields) -> dict:
    return {"pack": {"pack_format": pack_format, "description": "test", **pack_fields}}


def tag(*values, replace: bool | None = None) -> str:
    body = {"values": list(values)}
    if replace is not None:
        body["replace"] = replace
    return json.dumps(body)
