"""A player just joined or respawned takes no damage for 60 ticks (emulator.world.spawn_protection).
Up to 1.21.3 ServerPlayer.hurt refuses damage that does not bypass invulnerability while
spawnInvulnerableTime (60, counted down in ServerPlayer.tick) lasts, for every player; from 1.21.4
ServerPlayer.isInvulnerableTo refuses any damage until the client has loaded (Player.hasClientLoaded:
a dummy, with no client, waits for the 60-tick timeout). Decompiled 1.16.5, 1.20.6, 1.21.3 and 1.21.4
ServerPlayer.java and Player.java; 26.1.2 ServerGamePacketListenerImpl.java."""
import pytest

from emulator.api import Emulator
from tests.conftest import OPEN_AREA, write_pack
from tests.testing.test_dummy_hands import run


@pytest.mark.parametrize("pack_format", [48, 57, 61])
def test_a_new_dummy_takes_no_damage_for_60_ticks(tmp_path, pack_format):
    result = run(tmp_path, "# @dummy\n# @timeout 200\n" + OPEN_AREA + (
        "damage @s 4\n"
        "assert data entity @s {Health:20.0f}\n"
        "await delay 50\n"
        "damage @s 4\n"
        "assert data entity @s {Health:20.0f}\n"
        "await delay 20\n"
        "damage @s 4\n"
        "assert data entity @s {Health:16.0f}\n"), pack_format=pack_format)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, health", [(48, "0.0f"), (57, "0.0f"), (61, "20.0f")])
def test_kill_gets_through_only_before_1_21_4(tmp_path, pack_format, health):
    # generic_kill bypasses invulnerability (ServerPlayer.hurt's spawn check lets it by), not
    # isInvulnerableTo's !hasClientLoaded()
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "kill @s\n"
        f"assert data entity @s {{Health:{health}}}\n"), pack_format=pack_format)
    assert result.status == "passed", result.report()


def test_a_respawned_dummy_waits_again(tmp_path):
    result = run(tmp_path, "# @timeout 200\n" + OPEN_AREA + (
        "dummy Alex spawn\n"
        "await delay 70\n"
        "kill Alex\n"
        "dummy Alex respawn\n"
        "damage Alex 4\n"
        "assert data entity Alex {Health:20.0f}\n"
        "await delay 70\n"
        "damage Alex 4\n"
        "assert data entity Alex {Health:16.0f}\n"), pack_format=61)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("mc, health", [("1.21.1", 20), ("1.21.4", 16)])
def test_a_clients_player_is_protected_only_before_1_21_4(tmp_path, mc, health):
    # its client loads at once here; spawnInvulnerableTime protects every player up to 1.21.3
    root = write_pack(tmp_path / "p", {"t/function/hurt.mcfunction": "damage Alex 4\n"
                                                                     "execute store result score #h h run "
                                                                     "data get entity Alex Health\n",
                                       "t/function/load.mcfunction": "scoreboard objectives add h dummy\n"},
                      load=["t:load"])
    emu = Emulator(backend="python")
    emu.load(root, mc_version=mc)
    emu.start()
    emu.add_player("Alex", (0.5, 64.0, 0.5))
    emu.tick(1)
    emu.call("t:hurt")
    assert emu.score("#h", "h") == health
