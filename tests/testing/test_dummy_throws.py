"""Dummies throwing eggs, ender pearls, potions and experience bottles (emulator.world.
projectile_weapons.throw). Sources (decompiled 1.21): EggItem, EnderpearlItem (cooldown 20),
ThrowablePotionItem (0.5 blocks a tick, 20 degrees up), ExperienceBottleItem (0.7, 20 up),
Projectile.shootFromRotation, ThrownEnderpearl.onHit (the owner moves to the pearl, 5 fall
damage), ThrownPotion.applySplash."""
import pytest

from tests.testing.test_dummy_hands import run

WALL = "fill ~-2 ~ ~3 ~3 ~4 ~3 stone\n"  # a wall 2.5 blocks south of the dummy: what it throws hits it


@pytest.mark.parametrize("pack_format", [48, 61])
def test_a_thrown_ender_pearl_takes_the_dummy_along_and_cools_down(tmp_path, pack_format):
    result = run(tmp_path, "# @dummy\n# @skyaccess\n" + WALL + (
        "scoreboard objectives add pearls minecraft.used:minecraft.ender_pearl\n"
        "await delay 60\n"  # 1.21.4: the landing's fall damage needs the client loaded (ServerPlayer.isInvulnerableTo)
        "give @s ender_pearl 2\n"
        "dummy @s use item\n"
        "dummy @s use item\n"  # the pearl cools down 20 ticks: the second use passes
        "assert score @s pearls matches 1\n"
        "assert items entity @s weapon.mainhand ender_pearl[count=1]\n"
        "await entity @s[nbt={Health:15.0f}]\n"), pack_format=pack_format, backend="python")
    assert result.status == "passed", result.report()
    assert "\n".join(result.details).count("cannot use that item") == 1  # the second use passed


def test_a_thrown_splash_potion_slows_the_pig_near_where_it_breaks(tmp_path):
    result = run(tmp_path, "# @dummy\n# @skyaccess\n" + WALL + (
        "scoreboard objectives add thrown minecraft.used:minecraft.splash_potion\n"
        "summon pig ~0.5 ~1 ~1.5 {NoAI:1b,NoGravity:1b,Tags:[\"target\"]}\n"
        "give @s splash_potion[potion_contents=\"minecraft:slowness\"]\n"
        "dummy @s use item\n"
        "assert entity @e[type=potion]\n"
        "assert score @s thrown matches 1\n"
        "await entity @e[tag=target,nbt={active_effects:[{id:\"minecraft:slowness\"}]}]\n"
        "assert not entity @e[type=potion]\n"), pack_format=48, backend="python")
    assert result.status == "passed", result.report()
