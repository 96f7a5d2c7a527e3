"""Items, inventories, loot tables and item modifiers run identically on both backends, as the
game runs them (each rule's source named); the crafter pack (tests/backends/packs/crafter) is a
library-style use: a barrel read with ``execute if items``, loot tables with conditions, item
modifiers, item tags, ``assert items`` in PackTest files."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from emulator.api import Emulator
from emulator.testing import discover, run_suite
from emulator.world.entities import entity_nbt
from mcfunction_parser.nbt import to_snbt
from tests.backends.programs import write_pack
from tests.backends.test_entities import run_both

CRAFTER = Path(__file__).parent / "packs" / "crafter"
STEVE = [("Steve", (0.0, 64.0, 0.0), (0.0, 0.0))]
SETUP = "scoreboard objectives add v dummy\n"


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_the_crafter_pack_passes_its_own_suite(backend):
    summary = run_suite(discover([CRAFTER]), backend, strict=True)
    assert [(r.id, r.status, r.message) for r in summary.results] == [
        ("craft:crafter", "passed", ""), ("craft:reward", "passed", "")]


def _on_both(pack):
    """Each backend's emulator on ``pack`` after ``t:main`` ran with Steve online."""
    for backend in ("python", "numba"):
        emu = Emulator(backend=backend)
        emu.load(pack)
        emu.add_player("Steve", (0.0, 64.0, 0.0))
        emu.call("t:main")
        yield emu


def _json(pack, rel: str, value) -> None:
    """A JSON resource (a loot table ...) written into the pack."""
    (pack / rel).parent.mkdir(parents=True, exist_ok=True)
    (pack / rel).write_text(json.dumps(value))


def _scores(emu):
    return emu.scores().get("v", {})


def _player(emu):
    return emu.state.entities.players()[0]


def test_give_stacks_and_drops_what_does_not_fit(tmp_path):
    # GiveCommand: stacks of the maximum size; Inventory.add; leftovers dropped with no pickup delay
    emu = run_both(tmp_path, {"t:main": SETUP + "give Steve ender_pearl 600\n"
                              "execute store result score #n v if items entity Steve container.* ender_pearl\n"
                              "execute store result score #drops v if entity @e[type=item]\n"
                              "execute store result score #r v run give Steve stone 6401\n"}, players=STEVE)
    assert _scores(emu) == {"#n": 576, "#drops": 2, "#r": 0}  # 36 x 16 kept, 24 in two items; 64 x 100 max
    assert {int(e["PickupDelay"]) for e in (entity_nbt(x) for x in emu.state.entities.entities
                                            if x.type == "minecraft:item")} == {0}


def test_clear_results_and_query(tmp_path):
    # ClearInventoryCommands: the count removed; maxCount 0 only counts; nothing found fails
    emu = run_both(tmp_path, {"t:main": SETUP + "give Steve stone 10\ngive Steve dirt[custom_data={k:1b}] 3\n"
                              "execute store result score #q v run clear Steve stone 0\n"
                              "execute store result score #c v run clear Steve *[custom_data~{k:1b}] 2\n"
                              "execute store success score #none v run clear Steve diamond\n"
                              "execute store result score #all v run clear Steve\n"}, players=STEVE)
    assert _scores(emu) == {"#q": 10, "#c": 2, "#none": 0, "#all": 11}


def test_item_replace_slots_and_failures(tmp_path):
    # ItemCommands: a slot the entity lacks (SlotAccess.NULL) fails; a block that is no container fails
    emu = run_both(tmp_path, {"t:main": SETUP + 'summon armor_stand 0 64 0 {Tags:["s"]}\nsummon marker 0 64 0 {Tags:["m"]}\n'
                              "execute store result score #a v run item replace entity @e[tag=s] armor.head with diamond_helmet\n"
                              "execute store success score #m v run item replace entity @e[tag=m] weapon with stick\n"
                              "execute store success score #b v run item replace block 5 5 5 container.0 with stick\n"
                              "setblock 5 5 5 hopper\n"
                              "execute store success score #slot v run item replace block 5 5 5 container.5 with stick\n"
                              "item replace entity Steve hotbar.0 with stone 3\n"
                              "item replace entity Steve player.cursor from entity Steve weapon.mainhand\n"
                              "execute store result score #cur v if items entity Steve player.cursor stone\n"
                              "execute store result score #h v if items entity @e[tag=s] armor.* *\n"}, players=STEVE)
    assert _scores(emu) == {"#a": 1, "#m": 0, "#b": 0, "#slot": 0, "#cur": 3, "#h": 1}
    stand = next(e for e in emu.state.entities.entities if "s" in e.tags)
    assert entity_nbt(stand)["ArmorItems"][3]["id"] == "minecraft:diamond_helmet"


def test_data_views_and_writes(tmp_path):
    # EntityDataAccessor reads NbtPredicate.getEntityTagForPredicate (SelectedItem for players);
    # data modify block ... Items changes the container the item commands read
    emu = run_both(tmp_path, {"t:main": SETUP + "setblock 0 0 0 chest\n"
                              'data modify block 0 0 0 Items append value {Slot:4b,id:"minecraft:apple",count:7}\n'
                              "execute store result score #apple v if items block 0 0 0 container.4 apple\n"
                              "item replace entity Steve weapon.mainhand from block 0 0 0 container.4\n"
                              "execute store result score #sel v run data get entity Steve SelectedItem.count\n"
                              'execute store result score #nbt v if entity @a[nbt={SelectedItem:{id:"minecraft:apple"}}]\n'
                              'summon item 0 64 0 {Item:{id:"minecraft:stick",count:2},Tags:["i"]}\n'
                              "execute store result score #ent v if items entity @e[tag=i] contents stick\n"}, players=STEVE)
    assert _scores(emu) == {"#apple": 7, "#sel": 7, "#nbt": 1, "#ent": 2}


def test_loaded_items_drop_components_equal_to_their_defaults(tmp_path):
    # Entity.load / BlockEntity.loadWithComponents read each stack with ItemStack.CODEC, whose
    # PatchedDataComponentMap.fromPatch applies the patch over the item's defaults: a damage of 0 on a
    # sword, or a removal of food it never had, is gone when the NBT is read back
    emu = run_both(tmp_path, {"t:main": SETUP + "setblock 0 0 0 chest\n"
                              'data modify block 0 0 0 Items append value {Slot:0b,id:"minecraft:diamond_sword",count:1,'
                              'components:{"minecraft:damage":0,"!minecraft:food":{}}}\n'
                              "execute store result score #block v if data block 0 0 0 Items[0].components\n"
                              'summon item 0 64 0 {Item:{id:"minecraft:iron_sword",count:1,components:{"minecraft:damage":0,'
                              '"minecraft:custom_data":{k:1b}}},Tags:["i"]}\n'
                              "execute store result score #item v if data entity @e[tag=i,limit=1] Item.components\n"
                              'execute store result score #kept v if data entity @e[tag=i,limit=1] Item.components."minecraft:custom_data"\n'
                              'execute store result score #damage v if data entity @e[tag=i,limit=1] Item.components."minecraft:damage"\n'
                              'setblock 1 0 0 barrel{Items:[{Slot:1b,id:"minecraft:stone",count:2,components:{"minecraft:max_stack_size":64}}]}\n'
                              "execute store result score #barrel v if data block 1 0 0 Items[0].components\n"}, players=STEVE)
    assert _scores(emu) == {"#block": 0, "#item": 1, "#kept": 1, "#damage": 0, "#barrel": 0}


def test_loot_targets(tmp_path):
    # LootCommand: spawn drops item entities, replace fills slot after slot, insert distributes
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "stone", "functions": [
        {"function": "set_count", "count": 70}]}]}]}
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + "loot spawn 0 64 0 loot t:stone\n"
                                          "execute store result score #e v if entity @e[type=item]\n"
                                          "setblock 0 0 0 barrel\n"
                                          "execute store result score #r v run loot replace block 0 0 0 container.3 loot t:stone\n"
                                          "execute store result score #i v if items block 0 0 0 container.4 stone\n"
                                          "execute store result score #n v run loot insert 0 0 0 loot t:stone\n"
                                          "execute store result score #all v if items block 0 0 0 container.* stone\n"
                                          "execute store result score #g v run loot give Steve loot t:stone\n"})
    _json(pack, "data/t/loot_table/stone.json", table)
    results = []
    for emu in _on_both(pack):
        results.append((_scores(emu), emu.entities(), [d.format() for d in emu.diagnostics]))
    assert results[0] == results[1]
    assert results[0][0] == {"#e": 2, "#r": 2, "#i": 6, "#n": 2, "#all": 140, "#g": 2}


def test_bad_loot_input(tmp_path):
    # an unknown loot table or modifier id fails the command with a diagnostic; a function type
    # the emulator does not model is named, never a silent empty drop
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + "loot give Steve loot t:missing\n"
                                          "execute store success score #s v run loot give Steve loot t:smelt\n"
                                          "item modify entity Steve weapon t:nothing\n"})
    _json(pack, "data/t/loot_table/smelt.json", {"pools": [{"rolls": 1, "entries": [
        {"type": "item", "name": "book", "functions": [{"function": "enchant_with_levels", "levels": 30}]}]}]})
    for emu in _on_both(pack):
        messages = [d.message for d in emu.diagnostics]
        assert messages == ["Unknown loot table t:missing", "not modelled: item function 'minecraft:enchant_with_levels'",
                            "Unknown item modifier t:nothing"]
        assert _scores(emu) == {"#s": 0}


def test_equipment_layout_of_1_21_5(tmp_path):
    # from 1.21.5 (pack format 71) equipment is one compound for players and mobs alike
    pack = write_pack(tmp_path / "pack", {"t:main": "summon zombie 0 64 0\n"
                                          "item replace entity @e[type=zombie] armor.head with iron_helmet\n"
                                          "item replace entity Steve weapon.offhand with shield\n"}, pack_format=71)
    emu = Emulator(backend="python")
    emu.load(pack)
    emu.add_player("Steve", (0.0, 64.0, 0.0))
    emu.call("t:main")
    zombie = next(e for e in emu.state.entities.entities if e.type == "minecraft:zombie")
    assert to_snbt(entity_nbt(zombie)["equipment"]) == '{head:{count:1,id:"minecraft:iron_helmet"}}'
    assert entity_nbt(_player(emu))["equipment"]["offhand"]["id"] == "minecraft:shield"


def test_fish_and_mine_loot_take_the_blocks_centre_as_origin(tmp_path):
    # LootCommand.dropFishingLoot / dropBlockLoot: ORIGIN is Vec3.atCenterOf(pos), not the
    # command's position; a location_check on the origin sees the centre
    centred = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "cod"}], "conditions": [
        {"condition": "location_check", "predicate": {"position": {"x": {"min": 2.5, "max": 2.5},
                                                                   "y": {"min": 64.5, "max": 64.5}}}}]}]}
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + "setblock 2 64 0 stone\n"
                                          "execute positioned 7.2 70 1 store result score #fish v run "
                                          "loot give Steve fish t:centred 2 64 0\n"
                                          "execute positioned 7.2 70 1 store result score #mine v run loot give Steve mine 2 64 0"})
    _json(pack, "data/t/loot_table/centred.json", centred)
    _json(pack, "data/minecraft/loot_table/blocks/stone.json", centred)
    for emu in _on_both(pack):
        assert _scores(emu) == {"#fish": 1, "#mine": 1}


def test_kill_loot_uses_the_entity_table_and_its_killer(tmp_path):
    # LootCommand.dropKillLoot: the entity's loot table (DeathLootTable), the executor as the killer;
    # an entity that is not living has none; a vanilla table no pack defines is not shipped
    drops = {"pools": [{"rolls": 1, "conditions": [{"condition": "killed_by_player"}],
                        "entries": [{"type": "item", "name": "rotten_flesh"}]}]}
    pack = write_pack(tmp_path / "pack", {
        "t:main": SETUP + 'summon zombie 0 64 0 {DeathLootTable:"t:zdrops",Tags:["z"]}\nsummon marker 0 64 0\n'
        "execute store result score #server v run loot give Steve kill @e[tag=z,limit=1]\n"
        "execute as Steve store result score #player v run loot give Steve kill @e[tag=z,limit=1]\n"
        "execute store success score #marker v run loot give Steve kill @e[type=marker,limit=1]\n"
        "summon cow 0 64 0\nloot give Steve kill @e[type=cow,limit=1]\n"})
    _json(pack, "data/t/loot_table/zdrops.json", drops)
    for emu in _on_both(pack):
        assert _scores(emu) == {"#server": 0, "#player": 1, "#marker": 0}
        assert [d.message for d in emu.diagnostics] == [
            "not modelled: the game's own loot table minecraft:entities/cow is not known without the game's data "
            "(pass --game-jar)"]


def test_set_name_resolved_as_the_entity(tmp_path):
    # SetNameFunction with "entity": ComponentUtils.updateForEntity as that entity (the command's
    # executor is "this"; run as the server there is none and the name stays as written); the library idiom
    # of an inline table into an item display's contents, read back through its NBT
    emu = run_both(tmp_path, {"t:main": SETUP + "scoreboard players set #x v 42\n"
                              'data modify storage t:s msg set value "hello"\n'
                              "summon item_display -30000000 0 1600 {UUID:[I;181,0,0,3]}\n"
                              'execute as Steve run loot replace entity B5-0-0-0-3 contents loot {pools:[{rolls:1,'
                              'entries:[{type:"item",name:"egg",functions:[{function:"set_name",entity:"this",name:['
                              '{storage:"t:s",nbt:"msg"},'
                              '{score:{name:"#x",objective:"v"}}]}]}]}]}\n'
                              'data modify storage t:s name set from entity B5-0-0-0-3 item.components."minecraft:custom_name"\n'
                              'loot replace entity B5-0-0-0-3 contents loot {pools:[{rolls:1,entries:[{type:"item",'
                              'name:"egg",functions:[{function:"set_name",name:{score:{name:"#x",objective:"v"}}}]}]}]}\n'
                              'data modify storage t:s raw set from entity B5-0-0-0-3 item.components."minecraft:custom_name"\n'},
                   players=STEVE)
    storage = emu.state.storage["t:s"]
    assert json.loads(storage["name"]) == [{"text": "hello"}, {"text": "42"}]
    assert json.loads(storage["raw"]) == {"score": {"name": "#x", "objective": "v"}}  # no entity: as written


def test_item_tags_no_pack_defines_are_said_to_be_missing(tmp_path):
    # the game's own tags are not shipped: a test on one fails with a diagnostic, never a silent miss
    emu = run_both(tmp_path, {"t:main": SETUP + "give Steve oak_log\n"
                              "execute store success score #logs v if items entity Steve container.* #minecraft:logs\n"},
                   players=STEVE)
    assert _scores(emu) == {"#logs": 0}
    assert [d.message for d in emu.diagnostics] == [
        "not modelled: the vanilla item tag #minecraft:logs is not known without the game's data (pass --game-jar)"]


def test_single_item_containers(tmp_path):
    # DecoratedPotBlockEntity is a ContainerSingleItem saved under "item": the library idiom of
    # rolling an inline table into a pot far away and reading its custom data back
    emu = run_both(tmp_path, {"t:main": SETUP + "setblock -30000000 0 1606 decorated_pot\n"
                              'loot replace block -30000000 0 1606 contents loot {pools:[{rolls:1,entries:[{type:"item",'
                              'name:"cod",functions:[{function:"set_custom_data",tag:{v:42}}]}]}]}\n'
                              "execute store result score #v v run data get block -30000000 0 1606 "
                              'item.components."minecraft:custom_data".v\n'
                              "execute store success score #s v run item replace block -30000000 0 1606 container.1 with cod\n"})
    assert _scores(emu) == {"#v": 42, "#s": 0}


def test_mine_reads_the_block_and_its_state(tmp_path):
    # LootCommand.dropBlockLoot: the block's table (here a pack's own blocks/ table), the block state
    # for block_state_property and copy_state, the tool for match_tool
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "oak_slab",
                                                 "conditions": [{"condition": "block_state_property", "block": "oak_slab",
                                                                 "properties": {"type": "double"}}],
                                                 "functions": [{"function": "set_count", "count": 2},
                                                               {"function": "copy_state", "block": "oak_slab",
                                                                "properties": ["type"]}]}]},
                       {"rolls": 1, "conditions": [{"condition": "match_tool", "predicate": {"items": "minecraft:shears"}}],
                        "entries": [{"type": "item", "name": "stick"}]}]}
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + "setblock 0 0 0 oak_slab[type=double]\nsetblock 1 0 0 oak_slab\n"
                                          "execute store result score #d v run loot give Steve mine 0 0 0 shears\n"
                                          "execute store result score #s v run loot give Steve mine 1 0 0\n"
                                          "execute store result score #n v if items entity Steve container.* oak_slab\n"})
    _json(pack, "data/minecraft/loot_table/blocks/oak_slab.json", table)
    for emu in _on_both(pack):
        assert _scores(emu) == {"#d": 2, "#s": 0, "#n": 2}
        slab = entity_nbt(_player(emu))["Inventory"][0]
        assert to_snbt(slab["components"]) == '{"minecraft:block_state":{type:"double"}}'


def test_sub_predicates_as_packs_use_them(tmp_path):
    # a backpack library reads a held shulker box's contents (ItemContainerPredicate), a potion
    # belt clears potions by their potion (ItemPotionsPredicate), a predicate file reads a book's
    # author (ItemWrittenBookPredicate) in the entity predicate's equipment, on both backends
    box = ("shulker_box[container=[{slot:0,item:{id:'minecraft:tripwire_hook',count:1,"
           "components:{'minecraft:custom_data':{key:'vault'}}}},{slot:1,item:{id:'minecraft:bread',count:5}}]]")
    _json(tmp_path / "pack", "data/t/predicate/author.json", {
        "condition": "minecraft:entity_properties", "entity": "this",
        "predicate": {"equipment": {"offhand": {"items": "minecraft:written_book", "predicates": {
            "minecraft:written_book_content": {"author": "Alex", "pages": {"size": {"min": 1}}}}}}}})
    emu = run_both(tmp_path, {"t:main": SETUP + f"item replace entity Steve weapon.mainhand with {box}\n"
                              "item replace entity Steve weapon.offhand with written_book[written_book_content="
                              "{title:'Log',author:'Alex',pages:['\"day 1\"']}]\n"
                              "give Steve potion[potion_contents={potion:'minecraft:healing'}] 1\n"
                              "give Steve potion[potion_contents={potion:'minecraft:poison'}] 1\n"
                              "execute store result score #key v if items entity Steve weapon.mainhand "
                              "*[container~{items:{contains:[{predicates:{'minecraft:custom_data':{key:'vault'}}}]}}]\n"
                              "execute store result score #food v if items entity Steve weapon.* "
                              "*[container~{items:{count:[{test:{items:'minecraft:bread',count:{min:5}},count:1}]}}]\n"
                              "execute store result score #healing v run clear Steve *[potion_contents~'minecraft:healing']\n"
                              "execute store result score #author v as Steve if predicate t:author\n"}, players=STEVE)
    assert _scores(emu) == {"#key": 1, "#food": 1, "#healing": 1, "#author": 1}


def test_death_loot_reads_the_damage_source(tmp_path):
    # a mob's death loot rolls with its damage source (LivingEntity.dropFromLootTable:
    # DAMAGE_SOURCE); DamageSourceCondition reads its type's tags, source entity and directness
    tag = {"values": ["minecraft:player_attack"]}
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "minecraft:emerald"}], "conditions": [
        {"condition": "minecraft:damage_source_properties", "predicate": {
            "tags": [{"id": "t:melee", "expected": True}], "is_direct": True,
            "source_entity": {"type": "minecraft:player", "distance": {"horizontal": {"max": 5}}}}}]},
        {"rolls": 1, "entries": [{"type": "item", "name": "minecraft:bone"}], "conditions": [
            {"condition": "minecraft:damage_source_properties", "predicate": {"source_entity": {}}}]}]}
    _json(tmp_path / "pack", "data/minecraft/loot_table/entities/zombie.json", table)
    _json(tmp_path / "pack", "data/t/tags/damage_type/melee.json", tag)
    emu = run_both(tmp_path, {"t:main": SETUP + "summon zombie 1 64 0 {Tags:['a']}\nsummon zombie 9 64 0 {Tags:['b']}\n"
                              "summon zombie 1 64 2 {Tags:['c']}\n"
                              "damage @e[tag=a,limit=1] 100 minecraft:player_attack by Steve\n"
                              "damage @e[tag=b,limit=1] 100 minecraft:player_attack by Steve\n"
                              "damage @e[tag=c,limit=1] 100 minecraft:magic\n"
                              "execute store result score #emeralds v if entity @e[type=item,nbt={Item:{id:'minecraft:emerald'}}]\n"
                              "execute store result score #bones v if entity @e[type=item,nbt={Item:{id:'minecraft:bone'}}]\n"},
                   players=STEVE)
    # a: near, by the player (emerald and bone); b: too far for the emerald (bone only); c: no entity
    assert _scores(emu) == {"#emeralds": 1, "#bones": 2}
