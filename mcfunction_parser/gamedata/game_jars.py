"""Finding the game's jar for a release, for ``--game-jar auto``: the vanilla tags, loot tables and
recipes a pack reads come from the jar of the release it targets (:mod:`.vanilla_tags` reads it).

    resolve(spec, version, log)  -> the jar to read: ``spec`` itself, or for ``auto`` the first of
                                    the launcher's jar of that release, dpemu's cached download, a
                                    new download from Mojang (written to the cache)
    launcher_jars(version)       -> where the game's launchers keep that release's client jar

The launchers' folders: the official launcher's ``.minecraft`` (``%APPDATA%`` on Windows,
``~/Library/Application Support/minecraft`` on macOS, ``~/.minecraft`` elsewhere; its jar is
``versions/<v>/<v>.jar``) and Prism Launcher / MultiMC's libraries
(``libraries/com/mojang/minecraft/<v>/minecraft-<v>-client.jar``).

A download follows the launcher's own path: the version manifest (``version_manifest_v2.json``)
names the release's version document, whose ``downloads.client`` gives the jar's address and
SHA-1; the jar is checked against that SHA-1 before it is kept (in
``<DPEMU_GAMEDATA's parent>/jars/<v>.jar``, written whole or not at all). ``DPEMU_VERSION_MANIFEST``
names another manifest (a mirror).
"""
from __future__ import annotations

import hashlib
import json
import os
import sys
import tempfile
import urllib.error
import urllib.request
from pathlib import Path
from typing import Callable

from ..pack.versions import version_label
from .vanilla_tags import GameJarError

AUTO = "auto"
MANIFEST = "https://piston-meta.mojang.com/mc/game/version_manifest_v2.json"
TIMEOUT = 60  # seconds per request


class JarNotFound(GameJarError):
    """No jar of that release here and none could be downloaded; ``str()`` says what was tried."""


def resolve(spec: str | Path, version: tuple[int, int, int], log: Callable[[str], None] = lambda _: None) -> Path:
    """The jar named by ``spec``: a path as given, or for ``auto`` the release's jar found or fetched."""
    if str(spec) != AUTO:
        return Path(spec)
    label = version_label(version)
    for jar in (*launcher_jars(label), cached_jar(label)):
        if jar.is_file():
            return jar
    log(f"downloading the Minecraft {label} client jar from Mojang to {cached_jar(label)}")
    return download(label, cached_jar(label))


def launcher_jars(label: str) -> list[Path]:
    """Where the launchers keep release ``label``'s client jar, most common first."""
    found = [root / "versions" / label / f"{label}.jar" for root in _official_roots()]
    client = Path("libraries", "com", "mojang", "minecraft", label, f"minecraft-{label}-client.jar")
    found += [root / client for root in _prism_roots()]
    return found


def cached_jar(label: str) -> Path:
    from . import user_dir

    return user_dir().parent / "jars" / f"{label}.jar"


def _official_roots() -> list[Path]:
    home = Path.home()
    if sys.platform == "win32":
        return [Path(os.environ.get("APPDATA", home / "AppData" / "Roaming")) / ".minecraft"]
    if sys.platform == "darwin":
        return [home / "Library" / "Application Support" / "minecraft"]
    return [home / ".minecraft"]


def _prism_roots() -> list[Path]:
    home = Path.home()
    data = Path(os.environ.get("XDG_DATA_HOME") or home / ".local" / "share")
    roots = [data / "PrismLauncher", data / "multimc", home / ".var" / "app" / "org.prismlauncher.PrismLauncher" / "data" / "PrismLauncher"]
    if sys.platform == "win32":
        roots.insert(0, Path(os.environ.get("APPDATA", home / "AppData" / "Roaming")) / "PrismLauncher")
    elif sys.platform == "darwin":
        roots.insert(0, home / "Library" / "Application Support" / "PrismLauncher")
    return roots


def download(label: str, dest: Path) -> Path:
    """Release ``label``'s client jar from Mojang, checked by its SHA-1 and written to ``dest``."""
    manifest_url = os.environ.get("DPEMU_VERSION_MANIFEST") or MANIFEST
    manifest = _json(manifest_url, "the version manifest")
    entry = next((v for v in manifest.get("versions", ()) if v.get("id") == label), None)
    if entry is None:
        raise JarNotFound(f"Minecraft {label} is not in the version manifest {manifest_url}")
    client = _json(entry["url"], f"the {label} version document").get("downloads", {}).get("client")
    if not client or "url" not in client:
        raise JarNotFound(f"the {label} version document names no client jar")
    data = _get(client["url"], f"the {label} client jar")
    if "sha1" in client and hashlib.sha1(data).hexdigest() != client["sha1"]:
        raise JarNotFound(f"the {label} client jar from {client['url']} does not match its SHA-1 {client['sha1']}")
    dest.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.NamedTemporaryFile(dir=dest.parent, prefix=f".{label}-", suffix=".part", delete=False) as out:
        out.write(data)
    os.replace(out.name, dest)
    return dest


def _json(url: str, what: str) -> dict:
    try:
        return json.loads(_get(url, what))
    except json.JSONDecodeError as error:
        raise JarNotFound(f"{what} at {url} is not JSON ({error})") from None


def _get(url: str, what: str) -> bytes:
    try:
        with urllib.request.urlopen(url, timeout=TIMEOUT) as response:
            return response.read()
    except (urllib.error.URLError, OSError, ValueError) as error:
        raise JarNotFound(f"could not download {what} from {url} ({getattr(error, 'reason', error)}); "
                          f"give the jar's path to --game-jar instead") from None
