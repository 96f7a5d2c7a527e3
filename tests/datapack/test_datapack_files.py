"""Every function of the pool datapack parses with mecha's 1.21 grammar, and the pack's
metadata, tags and function references are consistent."""
import json
import re
from pathlib import Path

import pytest
from mecha import Mecha

from tests.datapack.pack_paths import FUNCTIONS, PACK, function_id

MACRO_VARIABLE = re.compile(r"\$\(([A-Za-z0-9_]+)\)")
FUNCTION_REF = re.compile(r"function (#?[a-z0-9_.-]+:[a-z0-9_./-]+)")


@pytest.fixture(scope="module")
def mecha():
    return Mecha(version="1.21")


def test_pack_has_functions():
    assert FUNCTIONS


@pytest.mark.parametrize("path", FUNCTIONS, ids=function_id)
def test_function_parses_with_mecha(mecha, path):
    text = path.read_text()
    mecha.parse(text, multiline=True)
    # mecha keeps macro lines as opaque text: parse each one again with a sample value
    for line in text.splitlines():
        if line.startswith("$"):
            mecha.parse(MACRO_VARIABLE.sub("0", line[1:]) + "\n", multiline=True)


@pytest.mark.parametrize("path", FUNCTIONS, ids=function_id)
def test_function_has_header_comment(path):
    first = path.read_text().splitlines()[0]
    assert first.startswith(f"# {function_id(path)} "), first


def test_every_called_function_exists():
    known = {function_id(p) for p in FUNCTIONS}
    missing = set()
    for path in FUNCTIONS:
        for ref in FUNCTION_REF.findall(path.read_text()):
            if not ref.startswith("#") and ref not in known:
                missing.add((function_id(path), ref))
    assert not missing


def test_pack_mcmeta_covers_every_1_21_release():
    pack = json.loads((PACK / "pack.mcmeta").read_text())["pack"]
    # minecraft.wiki "Pack format": data pack 48 is 1.21-1.21.1, 94.1 is 1.21.11. Since 1.21.9
    # min_format/max_format are required; a pack that also supports formats below 82 must keep
    # pack_format and a matching supported_formats for the older releases.
    assert pack["pack_format"] == 48
    assert pack["supported_formats"] == {"min_inclusive": 48, "max_inclusive": 94}
    assert pack["min_format"] == 48 and pack["max_format"] == 94


@pytest.mark.parametrize("tag,member", [("load", "pool:load"), ("tick", "pool:tick")])
def test_function_tags(tag, member):
    tag_file = PACK / "data" / "minecraft" / "tags" / "function" / f"{tag}.json"
    assert json.loads(tag_file.read_text())["values"] == [member]


OBJECTIVE_USES = [
    re.compile(r"\b(?:set|add|remove|reset|get|enable|operation) \S+ (pool\.[a-z0-9_]+)"),
    re.compile(r"\bscore \S+ (pool\.[a-z0-9_]+)"),
    re.compile(r"(?:[-+*/%]?=|<|>|><) \S+ (pool\.[a-z0-9_]+)"),
    re.compile(r"\"objective\":\"(pool\.[a-z0-9_]+)\""),
]


def test_load_creates_every_objective_used():
    load = (PACK / "data/pool/function/load.mcfunction").read_text()
    created = set(re.findall(r"^scoreboard objectives add (\S+)", load, re.M))
    used = set()
    for path in FUNCTIONS:
        commands = "\n".join(l for l in path.read_text().splitlines() if not l.startswith("#"))
        for pattern in OBJECTIVE_USES:
            used |= set(pattern.findall(commands))
        for scores in re.findall(r"scores=\{([^}]*)\}", commands):
            used |= {item.split("=")[0] for item in scores.split(",")}
    assert "pool.x" in used and "pool.power" in used
    assert used - created == set()


def test_the_pytest_folders_are_function_folders():
    # tests/datapack mirrors data/pool/function (datapack/README.md, "Layout"); pack-wide tests sit at the top
    here = Path(__file__).parent
    folders = {p.parent.relative_to(here).as_posix() for p in here.rglob("test_*.py")} - {"."}
    functions = PACK / "data" / "pool" / "function"
    assert {"math", "physics/motion", "physics/detect", "physics/resolve", "physics/events"} <= folders
    assert all((functions / folder).is_dir() for folder in folders), folders
