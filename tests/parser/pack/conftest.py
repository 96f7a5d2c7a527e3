"""The ``make_pack`` fixture."""
from pathlib import Path

import pytest

from tests.parser.pack.packbuild import meta, write_pack


@pytest.fixture
def make_pack(tmp_path):
    def make(name: str = "pack", files: dict | None = None, meta_json=None, *, fmt: int = 61) -> Path:
        return write_pack(tmp_path / name, files or {}, meta(fmt) if meta_json is None else meta_json)
    return make
