"""Dummies with bows and crossbows (emulator.world.projectile_weapons). Sources: BowItem.use (drawn
with ammunition or in creative, else FAIL; shooting waits for a release PackTest cannot send),
CrossbowItem.use/performShooting (a charged crossbow shoots at once: 3.15 blocks per tick,
inaccuracy 1), Player.getProjectile, AbstractArrow (at the eyes less 0.1, Owner, pickup, crit),
Projectile.getMovementToShoot, ItemStack.hurtAndBreak (one durability per arrow)."""
import pytest

from tests.conftest import OPEN_AREA
from tests.testing.test_dummy_hands import run

USING = {"demo/advancement/drawing.json": '{"criteria":{"c":{"trigger":"minecraft:using_item",'
                                          '"conditions":{"item":{"items":"minecraft:bow"}}}},"rewards":{"function":"demo:drawing"}}',
         "demo/function/drawing.mcfunction": "scoreboard players add @s draws 1\nadvancement revoke @s only demo:drawing\n"}


def test_a_bow_is_drawn_only_with_arrows_and_never_shoots(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add draws dummy\n"
        "give @s bow\n"
        "dummy @s use item\n"                       # no arrow: FAIL
        "await delay 2\n"
        "assert not score @s draws matches 1..\n"
        "give @s arrow 3\n"
        "dummy @s use item\n"
        "await delay 40\n"
        "assert score @s draws matches 40\n"
        "assert not entity @e[type=arrow]\n"
        "assert items entity @s container.* arrow[count=3]\n"), pack_format=61, files=USING)
    assert result.status == "passed", result.report()
    assert "\n".join(result.details).count("cannot use that item") == 1


@pytest.mark.parametrize("pack_format, crossbow", [
    (61, 'crossbow[charged_projectiles=[{id:"minecraft:arrow",count:1}]]'),
    (26, 'crossbow{Charged:1b,ChargedProjectiles:[{id:"minecraft:arrow",Count:1b}]}')])
@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_charged_crossbow_shoots_its_arrow_along_the_view(tmp_path, pack_format, crossbow, backend):
    """The dummy looks south (yaw 0): the arrow flies +z at 3.15 +- the spread, from the eyes less 0.1."""
    data = "SelectedItem.components.\"minecraft:charged_projectiles\"" if pack_format > 26 else \
        "SelectedItem.tag.ChargedProjectiles"
    damage = "SelectedItem.components{\"minecraft:damage\":1}" if pack_format > 26 else "SelectedItem.tag{Damage:1}"
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add t dummy\n"
        "scoreboard objectives add shots minecraft.used:minecraft.crossbow\n"
        f"give @s {crossbow}\n"
        "dummy @s use item\n"
        "assert entity @e[type=arrow,x=0.5,y=2.52,z=0.5,distance=..0.001]\n"
        "assert entity @e[type=arrow,nbt={crit:1b,pickup:1b,damage:2.0d}]\n"
        "execute store result score #vz t run data get entity @e[type=arrow,limit=1] Motion[2] 1000\n"
        "assert score #vz t matches 3095..3205\n"
        "execute store result score #vx t run data get entity @e[type=arrow,limit=1] Motion[0] 1000\n"
        "assert score #vx t matches -60..60\n"
        "execute store result score #owner t run data get entity @e[type=arrow,limit=1] Owner[0]\n"
        "execute store result score #uuid t run data get entity @s UUID[0]\n"
        "assert score #owner t = #uuid t\n"
        f"assert not data entity @s {data}[0]\n"
        f"assert data entity @s {damage}\n"
        "assert score @s shots matches 1\n"), pack_format=pack_format, backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_multishot_spreads_the_volley_and_a_rocket_slows_it(tmp_path, backend):
    """ProjectileWeaponItem.shoot: Multishot I spreads three projectiles over 10 degrees each side
    of the view (0, +10, -10 about the up vector); a firework rocket among them makes the whole
    volley 1.6 blocks a tick (CrossbowItem.getShootingPower) and is a FireworkRocketEntity at the
    eyes less 0.15, shot at an angle; the crossbow wears 1 per arrow and 3 per rocket."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add t dummy\n"
        "give @s crossbow[enchantments={levels:{\"minecraft:multishot\":1,\"minecraft:piercing\":2}},"
        "charged_projectiles=[{id:\"minecraft:arrow\",count:1},{id:\"minecraft:arrow\",count:1},"
        "{id:\"minecraft:firework_rocket\",count:1,components:{\"minecraft:fireworks\":{flight_duration:2}}}]]\n"
        "dummy @s use item\n"
        "assert entity @e[type=arrow,nbt={PierceLevel:2b}]\n"
        "execute store result score #n t if entity @e[type=arrow]\n"
        "assert score #n t matches 2\n"
        "assert entity @e[type=firework_rocket,x=0.5,y=2.47,z=0.5,distance=..0.001,nbt={ShotAtAngle:1b}]\n"
        "execute store result score #life t run data get entity @e[type=firework_rocket,limit=1] LifeTime\n"
        "assert score #life t matches 30..41\n"          # 10 x (2 + 1) + nextInt(6) + nextInt(7)
        "execute as @e[type=arrow] store result score @s t run data get entity @s Motion[0] 1000\n"
        # the straight arrow: x within the spread; the second turned -10 degrees about +y (towards -x:
        # 1.6 x sin(10 deg) = 0.278), the rocket +10 degrees
        "assert entity @e[type=arrow,scores={t=-30..30}]\n"
        "assert entity @e[type=arrow,scores={t=-300..-250}]\n"
        "execute store result score #vx t run data get entity @e[type=firework_rocket,limit=1] Motion[0] 1000\n"
        "assert score #vx t matches 250..300\n"
        "assert data entity @s SelectedItem.components{\"minecraft:damage\":5}\n"), pack_format=61, backend=backend)
    assert result.status == "passed", result.report()


HIT = {"demo/advancement/hit.json": '{"criteria":{"c":{"trigger":"minecraft:player_hurt_entity","conditions":'
                                    '{"damage":{"type":{"direct_entity":{"type":"minecraft:snowball"}}},'
                                    '"entity":{"type":"minecraft:pig"}}}},"rewards":{"function":"demo:hit"}}',
       "demo/function/hit.mcfunction": "scoreboard players add @s hits 1\n"}


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("pack_format", [48, 61])
def test_a_thrown_snowball_hurts_the_pig_in_its_way(tmp_path, backend, pack_format):
    """SnowballItem.use: a snowball from the eyes less 0.1 along the view at 1.5 a tick, one used;
    ProjectileUtil.getEntityHitResult finds the pig's box (inflated by 0.3) before the barrier wall;
    Snowball.onHitEntity hurts it by 0 as thrown damage of the dummy (HurtTime 10,
    player_hurt_entity with the snowball as direct entity), then the snowball breaks."""
    result = run(tmp_path, "# @dummy\n# @skyaccess\n" + OPEN_AREA + (
        "scoreboard objectives add hits dummy\n"
        "scoreboard objectives add thrown minecraft.used:minecraft.snowball\n"
        "summon pig ~0.5 ~1 ~1.4 {NoAI:1b,NoGravity:1b,Tags:[\"target\"]}\n"
        "give @s snowball 2\n"
        "dummy @s use item\n"
        "assert entity @e[type=snowball,nbt={Item:{id:\"minecraft:snowball\"}}]\n"
        "assert items entity @s weapon.mainhand snowball[count=1]\n"
        "assert score @s thrown matches 1\n"
        "await score @s hits matches 1\n"
        "assert not entity @e[type=snowball]\n"
        "assert entity @e[tag=target,nbt={HurtTime:10s}]\n"), pack_format=pack_format, files=HIT, backend=backend)
    assert result.status == "passed", result.report()


def test_a_trident_is_drawn_and_never_thrown(tmp_path):
    """TridentItem.use: startUsingItem (72000 ticks); it is thrown on release only, which a dummy never
    does; one point from breaking it fails (isTooDamagedToUse)."""
    result = run(tmp_path, "# @dummy\n" + (
        "give @s trident[damage=249]\n"
        "dummy @s use item\n"
        "item replace entity @s weapon.mainhand with trident\n"
        "dummy @s use item\n"
        "await delay 30\n"
        "assert not entity @e[type=trident]\n"
        "assert items entity @s weapon.mainhand trident\n"), pack_format=61)
    assert result.status == "passed", result.report()
    assert "\n".join(result.details).count("cannot use that item") == 1
