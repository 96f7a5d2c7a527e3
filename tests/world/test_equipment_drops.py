"""A dying mob's equipment, on both backends, as Mob.dropCustomDeathLoot drops it (decompiled 1.21,
world/entity/Mob.java; the chances saved as HandDropChances/ArmorDropChances before 1.21.5 and as
``drop_chances`` from it, 0.085 when not saved): a chance over 1 (2: an item the mob picked up)
always drops, unworn; any other only when a player hurt the mob lately and a draw falls under it,
worn to a random damage; a chance of 0 and an item cursed with vanishing never drop."""
import pytest

from tests.world.world_emulator import emulator

AXE = '{id:"minecraft:iron_axe",count:1}'
VANISHING = '{id:"minecraft:iron_axe",count:1,components:{"minecraft:enchantments":{levels:{"minecraft:vanishing_curse":1}}}}'


def dropped(emu) -> list:
    return [e.data["Item"] for e in emu.state.entities.entities if e.type == "minecraft:item" and e.alive]


def run(tmp_path, backend, mob_nbt: str, kill: str = "kill @e[type=vindicator]", pack_format: int = 48):
    emu = emulator(tmp_path, backend, {"t:go": f"summon vindicator 0 64 0 {mob_nbt}\n{kill}"}, pack_format=pack_format)
    emu.add_player("Alex", (3.0, 64.0, 0.0))
    emu.call("t:go")
    return emu


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_picked_up_item_always_drops_unworn(tmp_path, backend):
    emu = run(tmp_path, backend, f'{{HandItems:[{AXE},{{}}],HandDropChances:[2.0f,0.085f]}}')
    items = dropped(emu)
    assert [i["id"] for i in items] == ["minecraft:iron_axe"]
    assert "minecraft:damage" not in items[0].get("components", {})


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_chance_drop_needs_a_player_and_is_worn(tmp_path, backend):
    nbt = f'{{HandItems:[{AXE},{{}}],HandDropChances:[1.0f,0.085f]}}'
    assert dropped(run(tmp_path / "no_player", backend, nbt)) == []  # killed, no player hurt it
    emu = run(tmp_path / "player", backend, nbt, "damage @e[type=vindicator,limit=1] 100 minecraft:player_attack by Alex")
    items = dropped(emu)
    assert [i["id"] for i in items] == ["minecraft:iron_axe"]
    damage = int(items[0]["components"]["minecraft:damage"])  # 250 - nextInt(1 + nextInt(247))
    assert 4 <= damage <= 250


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_no_chance_and_vanishing_never_drop(tmp_path, backend):
    assert dropped(run(tmp_path / "zero", backend, f'{{HandItems:[{AXE},{{}}],HandDropChances:[0.0f,0.0f]}}',
                       "damage @e[type=vindicator,limit=1] 100 minecraft:player_attack by Alex")) == []
    assert dropped(run(tmp_path / "cursed", backend, f'{{HandItems:[{VANISHING},{{}}],HandDropChances:[2.0f,0.0f]}}')) == []


def test_from_1_21_5_the_chances_are_one_map(tmp_path):
    emu = run(tmp_path, "python", f'{{equipment:{{mainhand:{AXE},head:{{id:"minecraft:iron_helmet",count:1}}}},'
                                  'drop_chances:{mainhand:2.0f}}', pack_format=71)
    assert [i["id"] for i in dropped(emu)] == ["minecraft:iron_axe"]  # the helmet's 0.085 needs a player


def test_mobs_that_drop_more_say_it_is_not_modelled(tmp_path):
    emu = emulator(tmp_path, "python", {"t:go": f"summon zombie 0 64 0 {{HandItems:[{AXE},{{}}]}}\nkill @e[type=zombie]"})
    emu.call("t:go")
    assert any("the equipment a dying minecraft:zombie may drop" in d.message for d in emu.diagnostics)
