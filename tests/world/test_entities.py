"""Entities, selectors, execution positions and teleport.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): world/entity/EntityType.java, Entity.java,
commands/arguments/selector/EntitySelector.java, EntitySelectorParser.java,
options/EntitySelectorOptions.java, server/commands/TeleportCommand.java,
commands/arguments/coordinates/WorldCoordinate.java, CommandSourceStack.java.
"""
from __future__ import annotations

import numpy as np
import pytest

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, List, String
from emulator.world import java_random, nbt_ops, rotation, teleport
from emulator.world.entities import EntityStore, entity_nbt, load_nbt, uuid_string
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.selectors import SelectorWorld, select, select_one
from emulator.world.source import Source
from tests.world.world_paths import path

F32 = np.float32
LOC = Loc("t.mcfunction", 1, 1)


def sel(variable: str, **args) -> ast.Selector:
    """``sel("e", tag="a", type="!minecraft:marker")``: a leading ``!`` negates a string value."""
    built = []
    for key, value in args.items():
        values = value if isinstance(value, list) else [value]
        for v in values:
            negated = isinstance(v, str) and v.startswith("!")
            built.append(ast.SelectorArg(key, v[1:] if negated else v, negated, LOC))
    return ast.Selector(variable, tuple(built), LOC)


def coord(kind, value, is_int=False):
    return ast.Coord(kind, float(value), is_int)


def vec(*coords) -> ast.Vec3:
    return ast.Vec3(*coords, LOC)


# ----------------------------------------------------------------------------- entities


def test_uuid_string_is_javas():
    # UUID.toString of int[4] {1, 2, 3, 4}: zero-padded hex groups 8-4-4-4-12.
    assert uuid_string((1, 2, 3, 4)) == "00000001-0000-0002-0000-000300000004"
    assert uuid_string((-1, 0, 0, -2)) == "ffffffff-0000-0000-0000-0000fffffffe"


def test_summoned_uuids_are_version_4_and_seeded():
    a, b = EntityStore(7).summon("minecraft:marker", (0, 0, 0)), EntityStore(7).summon("minecraft:marker", (0, 0, 0))
    assert a.uuid == b.uuid
    text = a.uuid_string
    assert text[14] == "4" and text[19] in "89ab"  # Mth.createInsecureUUID sets version and variant


def test_hitboxes_and_eye_heights():
    store = EntityStore()
    player = store.add_player("Steve", (0.0, 64.0, 0.0))
    stand = store.summon("minecraft:armor_stand", (1.0, 0.0, 1.0))
    small = store.summon("minecraft:armor_stand", (1.0, 0.0, 1.0), Compound(Small=Byte(1)))
    marker = store.summon("minecraft:marker", (2.0, 3.0, 4.0))
    # EntityType: player 0.6 x 1.8 eyes 1.62; armor stand 0.5 x 1.975 eyes 1.7775; a small one is
    # half size with its own eye height (ArmorStand.BABY_DIMENSIONS: withEyeHeight(0.9875F))
    assert player.eye_height == F32(1.62) and player.anchor("eyes")[1] == 64.0 + float(F32(1.62))
    assert stand.bounding_box == (0.75, 0.0, 0.75, 1.25, float(F32(1.975)), 1.25)
    assert small.eye_height == F32(0.9875) and small.bounding_box[4] == float(F32(1.975) * F32(0.5))
    assert marker.bounding_box == (2.0, 3.0, 4.0, 2.0, 3.0, 4.0) and marker.eye_height == 0.0
    display = store.summon("minecraft:item_display", (0.0, 0.0, 0.0))
    assert display.eye_height == 0.0 and display.anchor("eyes") == display.pos


def test_living_mobs_follow_entities_coming_and_dying():
    # the list the entity steps walk is kept between calls: an entity summoned, or one whose alive
    # flag is written (killed, or brought back by a test), is seen by the next call
    store = EntityStore()
    pig = store.summon("minecraft:pig", (0.0, 0.0, 0.0))
    store.summon("minecraft:marker", (0.0, 0.0, 0.0))
    assert store.living_mobs() == [pig]
    cow = store.summon("minecraft:cow", (0.0, 0.0, 0.0))
    assert store.living_mobs() == [pig, cow]
    pig.alive = False
    assert store.living_mobs() == [cow]
    pig.alive = True
    assert store.living_mobs() == [pig, cow]


def test_entity_nbt_view_and_load_back():
    store = EntityStore()
    e = store.summon("minecraft:marker", (1.5, 2.0, 3.0), Compound(Tags=List([String("a")]), data=Compound(k=Int(1))))
    nbt = entity_nbt(e)
    assert nbt["Pos"] == [1.5, 2.0, 3.0] and type(nbt["Pos"][0]) is Double
    assert type(nbt["Rotation"][0]) is Float and nbt["Tags"] == ["a"] and nbt["data"] == {"k": 1}
    assert list(nbt["UUID"]) == list(e.uuid)
    # Entity.load: Rotation % 360, Motion over 10 dropped, Pos clamped, a Pos of ints ignored (0).
    nbt["Rotation"] = List([Float(370.0), Float(-400.0)])
    nbt["Motion"] = List([Double(11.0), Double(-2.0), Double(0.5)])
    nbt["Pos"] = List([Double(4e7), Double(-3e7), Double(1.0)])
    load_nbt(e, nbt)
    assert (e.yaw, e.pitch) == (F32(10.0), F32(-40.0))
    assert e.motion == (0.0, -2.0, 0.5)
    assert e.pos == (3.0000512e7, -2.0e7, 1.0)
    nbt["Pos"] = List([Int(1), Int(2), Int(3)])
    load_nbt(e, nbt)
    assert e.pos == (0.0, 0.0, 0.0)


def test_modifying_an_entity_keeps_its_uuid_and_refuses_players():
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0))
    uuid = e.uuid
    store.modify(e, lambda nbt: nbt_ops.modify(nbt, path("UUID", "UUID"), "set", [nbt_ops.copy_tag(
        nbt["UUID"].__class__([Int(1), Int(2), Int(3), Int(4)]))]))
    assert e.uuid == uuid  # EntityDataAccessor.setData restores the UUID
    store.modify(e, lambda nbt: nbt_ops.set_path(nbt, path("data.x", "data", "x"), Int(3)))
    assert e.data["data"] == {"x": 3}
    with pytest.raises(CommandFailure, match="Nothing changed"):
        store.modify(e, lambda nbt: nbt_ops.modify(nbt, path("data.x", "data", "x"), "set", [Int(3)]))
    store.modify(e, lambda nbt: nbt_ops.data_merge(nbt, Compound(Rotation=List([Float(90.0), Float(0.0)]))))
    assert e.yaw == F32(90.0)
    steve = store.add_player("Steve", (0, 0, 0))
    with pytest.raises(CommandFailure, match="Unable to modify player data"):
        store.modify(steve, lambda nbt: nbt_ops.set_path(nbt, path("x", "x"), Int(1)))


# ----------------------------------------------------------------------------- selectors


@pytest.fixture
def world():
    store = EntityStore(3)
    far = store.summon("minecraft:marker", (10.0, 0.0, 0.0), Compound(Tags=List([String("ball")])))
    near = store.summon("minecraft:marker", (2.0, 0.0, 0.0), Compound(Tags=List([String("ball"), String("cue")])))
    stand = store.summon("minecraft:armor_stand", (5.0, 0.0, 0.0))
    alex = store.add_player("Alex", (3.0, 0.0, 0.0))
    steve = store.add_player("Steve", (-1.0, 0.0, 0.0))
    return store, dict(far=far, near=near, stand=stand, alex=alex, steve=steve)


def names(found, ents):
    return [k for e in found for k, v in ents.items() if v is e]


def test_unsorted_e_is_creation_order_and_a_is_players(world):
    store, ents = world
    src = Source()
    assert names(select(store, sel("e"), src), ents) == ["far", "near", "stand", "alex", "steve"]
    assert names(select(store, sel("a"), src), ents) == ["alex", "steve"]
    assert names(select(store, sel("e", limit=2), src), ents) == ["far", "near"]


def test_nearest_selectors(world):
    store, ents = world
    src = Source(pos=(0.0, 0.0, 0.0))
    assert names(select(store, sel("p"), src), ents) == ["steve"]
    assert names(select(store, sel("n"), src), ents) == ["steve"]
    assert names(select(store, sel("n", type="minecraft:marker"), src), ents) == ["near"]
    assert names(select(store, sel("e", sort="furthest", limit=2), src), ents) == ["far", "stand"]


def test_type_tag_name_and_negations(world):
    store, ents = world
    src = Source()
    assert names(select(store, sel("e", type="!minecraft:marker"), src), ents) == ["stand", "alex", "steve"]
    assert names(select(store, sel("e", tag=["ball", "!cue"]), src), ents) == ["far"]
    assert names(select(store, sel("e", tag=""), src), ents) == ["stand", "alex", "steve"]
    assert names(select(store, sel("e", tag="!"), src), ents) == ["far", "near"]
    assert names(select(store, sel("e", name="Alex"), src), ents) == ["alex"]
    assert names(select(store, sel("e", name="Armor Stand"), src), ents) == ["stand"]
    skeleton = store.summon("minecraft:skeleton", (0, 0, 0))
    assert select(store, sel("e", type="#minecraft:skeletons"), src) == [skeleton]
    bones = SelectorWorld(lambda tag, type_id: tag == "my:bones" and type_id == "minecraft:skeleton")
    assert select(store, sel("e", type="#my:bones"), src, world=bones) == [skeleton]
    with pytest.raises(Unmodelled, match="#minecraft:logs is not known"):  # a vanilla tag not built in
        select(store, sel("e", type="#minecraft:logs"), src)


def test_distance_is_inclusive_and_measured_to_the_feet(world):
    store, ents = world
    src = Source(pos=(0.0, 0.0, 0.0))
    d = lambda lo, hi: ast.FloatRange(lo, hi)  # noqa: E731
    assert names(select(store, sel("e", distance=d(None, 2.0)), src), ents) == ["near", "steve"]
    assert names(select(store, sel("e", distance=d(2.0, 5.0)), src), ents) == ["near", "stand", "alex"]


def test_distance_prefilter_box_is_strict_on_the_negative_side():
    # distance=..R also tests the box [-R, R+1] with AABB.intersects (strict), so a zero-size marker
    # exactly R below the origin on an axis is outside although its distance equals R.
    store = EntityStore()
    below = store.summon("minecraft:marker", (-2.0, 0.0, 0.0))
    above = store.summon("minecraft:marker", (2.0, 0.0, 0.0))
    found = select(store, sel("e", distance=ast.FloatRange(None, 2.0)), Source())
    assert found == [above] and below not in found


def test_volume_uses_hitbox_intersection():
    store = EntityStore()
    stand = store.summon("minecraft:armor_stand", (0.9, 0.0, 0.0))  # hitbox x from 0.65 to 1.15
    marker = store.summon("minecraft:marker", (1.0, 0.5, 0.5))
    inside = store.summon("minecraft:marker", (0.5, 0.5, 0.5))
    src = Source()
    # x=0,y=0,z=0,dx=0 is the box [0,1]^3: the stand's hitbox overlaps; a marker exactly on x=1 is not.
    found = select(store, sel("e", x=0.0, y=0.0, z=0.0, dx=0.0), src)
    assert found == [stand, inside] and marker not in found
    # A negative extent grows the box the other way: [-2, 1] on x.
    assert select(store, sel("e", x=0.0, y=0.0, z=0.0, dx=-2.0, type="minecraft:marker"), src) == [inside]


def test_rotation_bounds_wrap_like_the_game():
    store = EntityStore()
    up = store.summon("minecraft:marker", (0, 0, 0), pitch=-45.0)
    level = store.summon("minecraft:marker", (0, 0, 0), pitch=0.0)
    down = store.summon("minecraft:marker", (0, 0, 0), pitch=30.0)
    r = lambda lo, hi: ast.FloatRange(lo, hi)  # noqa: E731
    # x_rotation=10.. has max 359 -> wrapped -1, so it matches pitch >= 10 OR pitch <= -1.
    assert select(store, sel("e", x_rotation=r(10.0, None)), Source()) == [up, down]
    # x_rotation=..20 has min 0: negative pitches do not match.
    assert select(store, sel("e", x_rotation=r(None, 20.0)), Source()) == [level]


def test_scores_nbt_gamemode_level(world):
    store, ents = world
    table = {(ents["alex"].score_holder, "hp"): 5, (ents["near"].score_holder, "hp"): 20}
    scores = lambda holder, obj: table.get((holder, obj))  # noqa: E731
    src = Source()
    found = select(store, sel("e", scores=(("hp", ast.IntRange(1, 10)),)), src, scores=scores)
    assert names(found, ents) == ["alex"]
    assert names(select(store, sel("e", nbt=Compound(Tags=List([String("cue")]))), src), ents) == ["near"]
    ents["steve"].gamemode, ents["alex"].level = "creative", 30
    assert names(select(store, sel("a", gamemode="!survival"), src), ents) == ["steve"]
    assert names(select(store, sel("e", level=ast.IntRange(10, None)), src), ents) == ["alex"]


def test_self_selector_and_single_entity(world):
    store, ents = world
    src = Source(entity=ents["near"])
    assert select(store, sel("s", tag="cue"), src) == [ents["near"]]
    assert select(store, sel("s", tag="nope"), src) == []
    assert select(store, sel("s"), Source()) == []
    with pytest.raises(CommandFailure, match="No entity was found"):
        select_one(store, sel("e", tag="nope"), src)
    with pytest.raises(Unmodelled, match="selector argument 'predicate'") as unsupported:
        select(store, sel("e", predicate="my:p"), src)  # no world given to evaluate predicates
    assert unsupported.value.report


def test_random_is_seeded(world):
    # ORDER_RANDOM shuffles (Collections.shuffle); here with the table's seeded java.util.Random.
    store, _ = world
    picks = []
    for seed in range(20):  # seeds far apart (java.util.Random's first draws of nearby seeds agree)
        java_random.set_seed(store.table.random, seed * 0x9E3779B9)
        first = select(store, sel("r"), Source())
        java_random.set_seed(store.table.random, seed * 0x9E3779B9)
        assert select(store, sel("r"), Source()) == first  # same seed, same pick
        picks.append(first[0].player_name)
    assert set(picks) == {"Alex", "Steve"}  # and both players get picked across seeds


# ----------------------------------------------------------------------------- source positions


def test_world_coordinates_centre_integer_x_z():
    # WorldCoordinate.parseDouble(centerCorrect): "1" -> 1.5 for x/z, y unchanged, "1.0" unchanged.
    src = Source(pos=(10.0, 20.0, 30.0))
    pos = src.position_of(vec(coord("abs", 1, True), coord("abs", 2, True), coord("abs", 3.0)))
    assert pos == (1.5, 2.0, 3.0)
    assert src.position_of(vec(coord("rel", 1), coord("rel", -1), coord("rel", 0))) == (11.0, 19.0, 30.0)


def test_local_coordinates_use_the_anchor():
    store = EntityStore()
    steve = store.add_player("Steve", (0.0, 64.0, 0.0))
    src = Source(pos=(0.0, 64.0, 0.0), entity=steve, anchor="eyes")
    x, y, z = src.position_of(vec(coord("local", 0), coord("local", 0), coord("local", 1)))
    assert y == 64.0 + float(F32(1.62)) and z == 1.0


def test_execute_facing_from_eyes():
    store = EntityStore()
    steve = store.add_player("Steve", (0.0, 0.0, 0.0))
    faced = Source(entity=steve, anchor="eyes").facing_position((0.0, float(F32(1.62)), 5.0))
    assert (faced.yaw, faced.pitch) == rotation.facing_rotation((0.0, float(F32(1.62)), 0.0), (0.0, float(F32(1.62)), 5.0))
    assert faced.pitch == 0.0  # level with the eyes, not with the feet
    assert Source(entity=steve).facing_position((0.0, float(F32(1.62)), 5.0)).pitch < 0.0


# ----------------------------------------------------------------------------- teleport


def test_tp_keeps_the_entity_rotation_wrapped():
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0), yaw=350.0, pitch=10.0)
    e.motion = (1.0, 2.0, 3.0)
    src = Source(pos=(5.0, 5.0, 5.0), yaw=F32(90.0))
    teleport.teleport(src, [e], vec(coord("rel", 1), coord("abs", 70, True), coord("abs", 0, True)))
    assert e.pos == (6.0, 70.0, 0.5)
    assert (e.yaw, e.pitch) == (F32(-10.0), F32(10.0))  # Mth.wrapDegrees(350) = -10
    assert e.motion == (1.0, 0.0, 3.0)


def test_tp_relative_rotation_is_relative_to_the_execution_rotation():
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0), yaw=0.0)
    src = Source(yaw=F32(170.0), pitch=F32(80.0))
    rot = ast.Vec2(coord("rel", 20), coord("rel", 20), LOC)
    teleport.teleport(src, [e], vec(coord("rel", 0), coord("rel", 0), coord("rel", 0)), rotation_arg=rot)
    assert (e.yaw, e.pitch) == (F32(-170.0), F32(90.0))  # 190 wraps; 100 is clamped to 90


def test_tp_self_uses_the_execution_rotation():
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0), yaw=45.0)
    dest = teleport.to_position_self(Source(entity=e, yaw=F32(-30.0)), vec(coord("abs", 1.0), coord("abs", 2.0), coord("abs", 3.0)))
    assert dest == teleport.Destination((1.0, 2.0, 3.0), F32(-30.0), F32(0.0))


def test_tp_facing_turns_from_the_new_position():
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0))
    target = store.summon("minecraft:marker", (10.0, 0.0, 5.0))
    teleport.teleport(Source(), [e], vec(coord("abs", 10.0), coord("abs", 0.0), coord("abs", 0.0)),
                      facing_entity=target)
    assert (e.yaw, e.pitch) == rotation.facing_rotation((10.0, 0.0, 0.0), (10.0, 0.0, 5.0))
    assert abs(e.yaw) < 1e-5 and e.pitch == 0.0  # looks south (yaw one float step off 0, see facing)
    teleport.teleport(Source(), [e], vec(coord("abs", 0.0), coord("abs", 0.0), coord("abs", 0.0)),
                      facing=vec(coord("abs", -3.0), coord("abs", 0.0), coord("abs", 0.0)))
    assert abs(e.yaw - F32(90.0)) < 1e-4


def test_tp_to_entity_and_invalid_position():
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0))
    dest = store.summon("minecraft:marker", (1.0, 2.0, 3.0), yaw=200.0, pitch=-100.0)
    teleport.teleport(Source(), [e], destination_entity=dest)
    assert e.pos == (1.0, 2.0, 3.0) and (e.yaw, e.pitch) == (F32(-160.0), F32(-90.0))
    with pytest.raises(CommandFailure, match="Invalid position for teleport"):
        teleport.teleport(Source(), [e], vec(coord("abs", 3e7), coord("abs", 0.0), coord("abs", 0.0)))


def test_tags_are_capped_at_1024():
    from emulator.world.entities import add_tag, remove_tag

    e = EntityStore().summon("minecraft:marker", (0, 0, 0))
    assert all(add_tag(e, f"t{i}") for i in range(1024))
    assert not add_tag(e, "one_more") and not add_tag(e, "t0")
    assert remove_tag(e, "t0") and not remove_tag(e, "t0")


def test_align_floors_the_named_axes():
    src = Source(pos=(1.7, -0.5, -2.2)).aligned("xz")
    assert src.pos == (1.0, -0.5, -3.0)


def _parsed_selector(text: str) -> ast.Selector:
    from mcfunction_parser.reader import Reader
    from mcfunction_parser.selectors import selector

    return selector(Reader(text, LOC, (1, 21, 0)))


def test_selectors_from_the_parser(world):
    store, ents = world
    src = Source(pos=(0.0, 0.0, 0.0))
    cases = {
        "@e[type=!minecraft:marker,distance=..3.5]": ["alex", "steve"],
        "@e[tag=ball,sort=furthest,limit=1]": ["far"],
        "@e[x=4,y=0,z=0,distance=..1.5]": ["stand", "alex"],
        "@a[x=2.5,y=-1,z=-1,dx=1,dy=1,dz=1]": ["alex"],
        "@e[type=#minecraft:skeletons]": [],
        "@p[name=!Steve]": ["alex"],
    }
    for text, expected in cases.items():
        assert names(select(store, _parsed_selector(text), src), ents) == expected, text


def test_load_keeps_tags_and_name_when_missing_and_types_base_fields():
    # Entity.load: Tags / CustomName only change when present; Fire is read with getShort,
    # OnGround with getBoolean, a missing Air is kept, a missing Fire reads 0.
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0), Compound(Tags=List([String("a")]), CustomName=String('"Bob"')))
    nbt = entity_nbt(e)
    del nbt["Tags"], nbt["CustomName"], nbt["Air"], nbt["Fire"]
    nbt["OnGround"] = Int(7)
    nbt["FallDistance"] = Double(0.1)
    nbt["NoGravity"], nbt["Silent"] = Byte(1), Byte(0)
    load_nbt(e, nbt)
    assert e.tags == {"a"} and e.display_name == "Bob"
    view = entity_nbt(e)
    assert view["Air"] == 300 and view["Fire"] == 0 and type(view["Fire"]).__name__ == "Short"
    assert view["OnGround"] == 1 and type(view["OnGround"]).__name__ == "Byte"
    assert view["FallDistance"] == float(F32(0.1)) and type(view["FallDistance"]) is Float
    assert view["NoGravity"] == 1 and "Silent" not in view  # flags are saved only when true
    nbt = entity_nbt(e)
    nbt["Tags"] = List()
    nbt["data"] = Int(3)  # Marker reads "data" with getCompound: a wrong type reads {}
    load_nbt(e, nbt)
    assert e.tags == set() and entity_nbt(e)["data"] == {}
    assert entity_nbt(store.summon("minecraft:marker", (0, 0, 0)))["data"] == {}


def test_compiled_query_runs_against_any_source(world):
    from emulator.world.selectors import SelectorQuery

    store, ents = world
    nearest = SelectorQuery(_parsed_selector("@e[type=minecraft:marker,sort=nearest,limit=1]"))
    assert names(nearest.run(store, Source(pos=(0.0, 0.0, 0.0))), ents) == ["near"]
    assert names(nearest.run(store, Source(pos=(9.0, 0.0, 0.0))), ents) == ["far"]


def test_summon_failures():
    store = EntityStore()
    with pytest.raises(CommandFailure, match="Can't summon entity of type minecraft:player"):
        store.summon("minecraft:player", (0, 0, 0))
    with pytest.raises(CommandFailure, match="Invalid position for summon"):
        store.summon("minecraft:marker", (0.0, 2.0e7, 0.0))
    first = store.summon("minecraft:marker", (0, 0, 0))
    with pytest.raises(CommandFailure, match="duplicate UUIDs"):
        store.summon("minecraft:marker", (0, 0, 0), Compound(UUID=nbt_ops.copy_tag(entity_nbt(first)["UUID"])))
    assert len(store.entities) == 1


def test_display_entities_save_their_render_fields():
    # Display.addAdditionalSaveData always writes transformation, billboard, durations, view
    # range, shadow and size fields; readAdditionalSaveData ignores values of the wrong kind.
    store = EntityStore()
    d = store.summon("minecraft:item_display", (0, 0, 0), Compound(teleport_duration=Int(80), billboard=String("center")))
    nbt = entity_nbt(d)
    assert nbt["transformation"]["scale"] == [1.0, 1.0, 1.0] and type(nbt["transformation"]["scale"][0]) is Float
    assert nbt["teleport_duration"] == 59 and nbt["billboard"] == "center" and nbt["item_display"] == "none"
    store.modify(d, lambda n: nbt_ops.set_path(n, path("transformation.translation", "transformation", "translation"),
                                               List([Double(0.5), Double(1.0), Double(0.1)])))
    t = entity_nbt(d)["transformation"]
    assert t["translation"] == [0.5, 1.0, float(F32(0.1))] and type(t["translation"][0]) is Float
    assert t["left_rotation"] == [0.0, 0.0, 0.0, 1.0]
    # A partial transformation does not decode: the previous one stays.
    store.modify(d, lambda n: nbt_ops.set_path(n, path("transformation", "transformation"),
                                               Compound(scale=List([Float(2.0)] * 3))))
    assert entity_nbt(d)["transformation"] == t
    store.modify(d, lambda n: nbt_ops.set_path(n, path("start_interpolation", "start_interpolation"), Int(0)))
    assert "start_interpolation" not in entity_nbt(d)  # read, never saved


def test_positioned_resets_the_anchor_to_feet():
    # ExecuteCommand: positioned POS is withPosition(...).withAnchor(FEET); positioned as keeps it.
    store = EntityStore()
    steve = store.add_player("Steve", (0.0, 0.0, 0.0))
    src = Source(entity=steve, anchor="eyes")
    moved = src.positioned(vec(coord("local", 0), coord("local", 0), coord("local", 0)))
    assert moved.pos == (0.0, float(F32(1.62)), 0.0) and moved.anchor == "feet"
    assert src.with_position((1.0, 2.0, 3.0)).anchor == "eyes"


def test_tp_discards_a_non_finite_rotation():
    # A rotation argument of 1e39 is infinite as a float; wrapDegrees gives NaN and setYRot refuses it.
    store = EntityStore()
    e = store.summon("minecraft:marker", (0, 0, 0), yaw=30.0)
    rot = ast.Vec2(coord("abs", 1e39), coord("abs", 10), LOC)
    teleport.teleport(Source(), [e], vec(coord("abs", 1.0), coord("abs", 2.0), coord("abs", 3.0)), rotation_arg=rot)
    assert e.yaw == F32(30.0) and e.pitch == F32(10.0) and e.pos == (1.0, 2.0, 3.0)


def test_living_mobs_follow_summons_kills_level_changes_and_deaths():
    """Only LivingEntities tick effects (LivingEntity.tickEffects): the store's living_mobs are the
    living ones among its entities, in its order, as entities come, go and die."""
    store = EntityStore()
    store.summon("minecraft:marker", (0, 0, 0))
    zombie = store.summon("minecraft:zombie", (0, 0, 0))
    player = store.add_player("p", (0, 0, 0))
    assert store.living_mobs() == [zombie, player]
    stand = store.summon("minecraft:armor_stand", (0, 0, 0))
    store.summon("minecraft:item_display", (0, 0, 0))
    assert store.living_mobs() == [zombie, player, stand]
    store.kill(zombie)
    assert store.living_mobs() == [player, stand]
    store.move_to_level(player, "minecraft:the_nether")
    assert store.living_mobs() == [stand, player]
    player.alive = False  # a dead player stays in the store
    assert store.living_mobs() == [stand]
