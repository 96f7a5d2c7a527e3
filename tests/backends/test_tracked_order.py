"""``*`` (Scoreboard.getTrackedPlayers) walks the game's holder map in its hash order, which follows
the order in which holders got their first score. The reference backend replays the map score by
score; the VM writes scores in place and brings the map up to date when ``*`` is next used, adding
the holders that got a first score since in the order they were interned (see
emulator.world.state.Scoreboard.tracked_holders). The two differ when such holders collide in the
table and got their first scores in another order than they were interned: here entities summoned
in one order (a nether one among them) get their first score in selector order (the overworld's
entities first), and a swap over ``*`` then pairs other scores. A known gap of the VM, kept here."""
import pytest

from tests.backends.programs import run_root, write_pack

SETUP = "\n".join([
    "scoreboard objectives add o dummy", "scoreboard objectives add p dummy", "scoreboard players set #n p 2",
    'summon marker ~ ~ ~ {Tags:["m","a"]}', "summon marker ~2 ~ ~ {Tags:[\"m\"],CustomName:'\"Bob\"'}",
    'summon marker ~ ~1 ~5 {Tags:["n"]}', 'summon armor_stand ~1 ~ ~1 {Tags:["m"]}',
    'execute in minecraft:the_nether run summon marker ~ ~ ~1 {Tags:["m","nether"]}',
    'summon item_display ~-1 ~ ~ {Tags:["d"]}',
    'summon armor_stand ~-2 ~ ~ {Tags:["v"],Passengers:[{id:"marker",Tags:["m","r"]},{id:"marker",Tags:["r"]}]}',
    "scoreboard players set @e[tag=m] o -2147483648", "function t:loop"])
LOOP = ("scoreboard players remove #n p 1\n"
        "scoreboard players operation * o >< @e[tag=m,scores={o=..5}] p\n"
        "execute if score #n p matches 1.. run function t:loop")


@pytest.mark.xfail(strict=True, reason="the VM adds holders first scored between two uses of * in interning order")
def test_star_after_holders_first_scored_out_of_interning_order(tmp_path):
    pack = write_pack(tmp_path / "pack", {"t:f0": SETUP, "t:loop": LOOP})
    reference = run_root("python", pack, "t:f0", roots=2)
    vm = run_root("numba", pack, "t:f0", roots=2)
    assert vm.scores == reference.scores
