"""A totem of undying saving its holder (decompiled 26.1.2 and 1.20.6
LivingEntity.checkTotemDeathProtection; 26.1.2 DeathProtection.TOTEM_OF_UNDYING)."""
from __future__ import annotations

import json

import pytest

from emulator.api import Emulator
from tests.conftest import write_pack

BACKENDS = ["numba", "python"]
USED = {"t/advancement/used.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:used_totem", "conditions": {"item": {"items": "minecraft:totem_of_undying"}}}}})}


def world(tmp_path, backend, body: str, mc: str = "1.21.4", files=None) -> Emulator:
    plural = "s" if mc == "1.20.6" else ""  # the folders' names before 1.21
    files = {name.replace("/advancement/", f"/advancement{plural}/"): text for name, text in (files or {}).items()}
    pack = write_pack(tmp_path / "pack", {
        f"t/function{plural}/load.mcfunction": "scoreboard objectives add used minecraft.used:minecraft.totem_of_undying",
        f"t/function{plural}/go.mcfunction": body, **files})
    (pack / f"data/minecraft/tags/function{plural}").mkdir(parents=True)
    (pack / f"data/minecraft/tags/function{plural}/load.json").write_text(json.dumps({"values": ["t:load"]}))
    emu = Emulator(backend=backend)
    emu.load(pack, mc_version=mc)
    emu.start()
    emu.add_player("Alex", pos=(0.0, 64.0, 0.0))
    emu.tick(60)  # past its spawn protection (ServerPlayer.spawnInvulnerableTime, up to 1.21.3)
    emu.call("t:go")
    return emu


def alex(emu) -> dict:
    return emu._one_entity("Alex").data


def effects(data) -> dict:
    return {str(e["id"]): (int(e["amplifier"]), int(e["duration"])) for e in data.get("active_effects", [])}


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("mc", ["1.20.6", "1.21.4"])
def test_a_totem_saves_its_holder(tmp_path, backend, mc):
    emu = world(tmp_path, backend, "effect give Alex minecraft:speed 60\n"
                "item replace entity Alex weapon.offhand with totem_of_undying\n"
                "item replace entity Alex weapon.mainhand with totem_of_undying\ndamage Alex 100", mc, USED)
    data = alex(emu)
    assert float(data["Health"]) == 1.0 and emu.entities("@a")  # alive, at 1 health
    # the speed cleared; regeneration II 900, absorption II 100, fire resistance 800
    assert effects(data) == {"minecraft:regeneration": (1, 900), "minecraft:absorption": (1, 100),
                             "minecraft:fire_resistance": (0, 800)}
    assert emu.score("Alex", "used") == 1  # Stats.ITEM_USED
    assert emu.entities("@a[advancements={t:used=true}]")  # USED_TOTEM
    # the main hand's is used first (InteractionHand.values()); one item, the holder in survival
    assert emu.entities("@a[nbt={Inventory:[{Slot:-106b,id:\"minecraft:totem_of_undying\"}]}]")
    assert not emu.entities("@a[nbt={SelectedItem:{}}]")


@pytest.mark.parametrize("backend", BACKENDS)
def test_kill_and_the_void_pass_it_by(tmp_path, backend):
    """#bypasses_invulnerability (generic_kill, out_of_world): no totem is used."""
    emu = world(tmp_path, backend, "item replace entity Alex weapon.mainhand with totem_of_undying\nkill Alex")
    assert emu.score("Alex", "used") is None
    assert float(alex(emu)["Health"]) == 0.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_any_death_protection_item_saves_with_its_effects(tmp_path, backend):
    """From 1.21.2 the death_protection component: its death_effects in order; a totem without it
    (``!death_protection``) does not save."""
    emu = world(tmp_path, backend,
                "item replace entity Alex weapon.mainhand with totem_of_undying[!death_protection]\n"
                "item replace entity Alex weapon.offhand with stick[death_protection={death_effects:["
                '{type:"apply_effects",effects:[{id:"minecraft:glowing",duration:40}]},{type:"clear_all_effects"},'
                '{type:"apply_effects",effects:[{id:"minecraft:speed",duration:20}]}]}]\n'
                "damage Alex 100")
    assert effects(alex(emu)) == {"minecraft:speed": (0, 20)}
    assert float(alex(emu)["Health"]) == 1.0
