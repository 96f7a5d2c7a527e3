"""``--game-jar auto``: the jar of the packs' release from the launcher's folder, else dpemu's cache,
else downloaded from Mojang the way the launcher does it (version manifest -> version document ->
``downloads.client`` with its SHA-1), checked and cached; one that cannot be had is an error and the
packs load without it. Mojang is stood in for by a local server (``DPEMU_VERSION_MANIFEST``)."""
from __future__ import annotations

import hashlib
import http.server
import json
import threading
import zipfile

import pytest
from click.testing import CliRunner

from emulator.cli import main
from tests.backends.programs import write_pack
from tests.parser.pack.packbuild import tag

RELEASE = "1.21.1"


def jar_bytes(tmp_path) -> bytes:
    path = tmp_path / "made.jar"
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("data/minecraft/tags/block/logs.json", tag("minecraft:oak_log"))
    return path.read_bytes()


@pytest.fixture
def home(tmp_path, monkeypatch):
    """A user with no launcher and an empty dpemu cache."""
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "home/.local/share"))
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path / "dpemu/gamedata"))
    monkeypatch.delenv("DPEMU_GAME_JAR", raising=False)
    return tmp_path / "home"


class Mojang:
    """A local stand-in for piston-meta/piston-data: serves the manifest, the version document, the jar."""

    def __init__(self, jar: bytes, sha1: str | None = None):
        self.jar, self.requests = jar, []
        self.sha1 = sha1 or hashlib.sha1(jar).hexdigest()
        handler = self._handler()
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.base = f"http://127.0.0.1:{self.server.server_address[1]}"
        threading.Thread(target=self.server.serve_forever, daemon=True).start()

    def _handler(self):
        mojang = self

        class Handler(http.server.BaseHTTPRequestHandler):
            def do_GET(self):
                mojang.requests.append(self.path)
                body = mojang.files().get(self.path)
                self.send_response(200 if body is not None else 404)
                self.end_headers()
                self.wfile.write(body or b"")

            def log_message(self, *args):
                pass

        return Handler

    def files(self) -> dict[str, bytes]:
        manifest = {"versions": [{"id": RELEASE, "url": f"{self.base}/v1/{RELEASE}.json"}]}
        document = {"downloads": {"client": {"url": f"{self.base}/client.jar", "sha1": self.sha1}}}
        return {"/manifest.json": json.dumps(manifest).encode(), f"/v1/{RELEASE}.json": json.dumps(document).encode(),
                "/client.jar": self.jar}

    def close(self):
        self.server.shutdown()
        self.server.server_close()


@pytest.fixture
def pack(tmp_path):
    load = ("scoreboard objectives add o dummy\nsetblock 0 64 0 oak_log\n"
            "execute store result score #log o if block 0 64 0 #minecraft:logs")
    return str(write_pack(tmp_path / "pack", {"t:load": load}, {"minecraft:load": ["t:load"]}))


def run(pack, tmp_path, *extra):
    out = tmp_path / "r.json"
    result = CliRunner().invoke(main, ["run", pack, "--backend", "python", "--mc", RELEASE, "--json", str(out), *extra])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    report = json.loads(out.read_text())
    messages = [d["message"] for d in report["load_diagnostics"] + report["diagnostics"]]
    return report["scores"].get("o", {}).get("#log"), messages


def test_the_launchers_jar_of_the_release_is_read(home, pack, tmp_path):
    launcher = home / ".minecraft/versions" / RELEASE / f"{RELEASE}.jar"
    launcher.parent.mkdir(parents=True)
    launcher.write_bytes(jar_bytes(tmp_path))
    assert run(pack, tmp_path, "--game-jar", "auto") == (1, [])


def test_a_download_is_checked_cached_and_reused(home, pack, tmp_path, monkeypatch):
    mojang = Mojang(jar_bytes(tmp_path))
    monkeypatch.setenv("DPEMU_VERSION_MANIFEST", f"{mojang.base}/manifest.json")
    monkeypatch.setenv("DPEMU_GAME_JAR", "auto")  # the option's environment variable
    log, messages = run(pack, tmp_path)
    assert log == 1 and len(messages) == 1 and "downloading the Minecraft 1.21.1 client jar" in messages[0]
    assert mojang.requests == ["/manifest.json", f"/v1/{RELEASE}.json", "/client.jar"]
    cached = tmp_path / "dpemu/jars" / f"{RELEASE}.jar"
    assert cached.read_bytes() == mojang.jar
    mojang.close()
    assert run(pack, tmp_path) == (1, [])  # from the cache, with Mojang gone


def test_a_jar_that_fails_its_sha1_is_not_kept(home, pack, tmp_path, monkeypatch):
    mojang = Mojang(jar_bytes(tmp_path), sha1="0" * 40)
    monkeypatch.setenv("DPEMU_VERSION_MANIFEST", f"{mojang.base}/manifest.json")
    log, messages = run(pack, tmp_path, "--game-jar", "auto")
    mojang.close()
    assert log == 0  # the tag is not known: the command fails saying so, and the pack goes on
    assert any("does not match its SHA-1" in m and "the packs load without the game's data" in m for m in messages)
    assert any("(pass --game-jar)" in m for m in messages)
    assert not (tmp_path / "dpemu/jars" / f"{RELEASE}.jar").exists()


def test_no_network_and_an_unknown_release_are_errors_not_tracebacks(home, pack, tmp_path, monkeypatch):
    monkeypatch.setenv("DPEMU_VERSION_MANIFEST", "http://127.0.0.1:9/manifest.json")  # nothing listens
    messages = run(pack, tmp_path, "--game-jar", "auto")[1]
    assert any("could not download the version manifest" in m and "give the jar's path to --game-jar" in m
               for m in messages)
    mojang = Mojang(jar_bytes(tmp_path))
    monkeypatch.setenv("DPEMU_VERSION_MANIFEST", f"{mojang.base}/manifest.json")
    out = tmp_path / "r.json"
    CliRunner().invoke(main, ["run", pack, "--backend", "python", "--mc", "1.21.4", "--game-jar", "auto",
                              "--json", str(out)])
    mojang.close()
    messages = [d["message"] for d in json.loads(out.read_text())["load_diagnostics"]]
    assert any("Minecraft 1.21.4 is not in the version manifest" in m for m in messages)
