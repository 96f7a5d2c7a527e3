"""A PackTest dummy has no client: from 1.21.4 it takes no damage until its client would have
loaded, 60 of its ticks after it spawned (Player.hasClientLoaded / clientLoadedTimeoutTimer,
ServerPlayer.tick -> tickClientLoadTimeout, ServerPlayer.isInvulnerableTo; decompiled 1.21.4,
1.21.7, 26.1.2). 1.21.3 has no such wait."""
import pytest

from tests.conftest import OPEN_AREA
from tests.testing.test_dummy_hands import run


def test_from_1_21_4_a_new_dummy_takes_no_damage_for_60_ticks(tmp_path):
    result = run(tmp_path, "# @dummy\n# @timeout 200\n" + OPEN_AREA + (
        "damage @s 4\n"
        "kill @s\n"                                   # LivingEntity.kill hurts too: refused as well
        "assert data entity @s {Health:20.0f}\n"
        "await delay 50\n"
        "damage @s 4\n"
        "assert data entity @s {Health:20.0f}\n"
        "await delay 20\n"
        "damage @s 4\n"
        "assert data entity @s {Health:16.0f}\n"), pack_format=61)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, health", [(48, "16.0f"), (57, "16.0f"), (61, "20.0f")])
def test_a_dummy_is_hurt_at_once_before_1_21_4(tmp_path, pack_format, health):
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "damage @s 4\n"
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
