from mcfunction_parser import ast
from mcfunction_parser.nbt import Compound, Double, Int, IntArray, List
from tests.parser.parser_helpers import parse_err, parse_ok


def test_get():
    cmd = parse_ok("data get entity @s Pos[1] 100")
    assert isinstance(cmd, ast.DataGet) and cmd.scale == 100.0 and cmd.path.text == "Pos[1]"
    assert parse_ok("data get storage ns:s").path is None
    assert isinstance(parse_ok("data get block 1 2 3 Items").target, ast.BlockData)


def test_merge_and_remove():
    cmd = parse_ok("data merge storage ns:s {a:[I;1,2],b:{c:1.5}}")
    assert type(cmd.nbt["a"]) is IntArray and cmd.nbt["b"]["c"] == 1.5 and type(cmd.nbt["b"]["c"]) is Double
    assert isinstance(parse_ok("data remove entity @s Tags[0]"), ast.DataRemove)
    assert "compound" in parse_err("data merge storage ns:s [1]").message


def test_modify_sources():
    v = parse_ok("data modify storage ns:s a set value [1,2,3]")
    assert v.mode == "set" and isinstance(v.source, ast.SourceValue)
    assert type(v.source.value) is List and type(v.source.value[0]) is Int
    f = parse_ok("data modify storage ns:s a append from entity @s Inventory[{Slot:0b}]")
    assert isinstance(f.source, ast.SourceFrom) and f.source.path.text == "Inventory[{Slot:0b}]"
    i = parse_ok("data modify storage ns:s list insert -1 value {x:1}")
    assert i.index == -1 and type(i.source.value) is Compound
    s = parse_ok("data modify storage ns:s name set string entity @s CustomName 1 -1")
    assert isinstance(s.source, ast.SourceString) and (s.source.start, s.source.end) == (1, -1)
    m = parse_ok("data modify entity @s {} merge from storage ns:s")
    assert m.mode == "merge" and m.source.path is None


def test_modify_string_needs_1_19_4():
    assert "1.19.4" in parse_err("data modify storage a:b x set string storage a:b y", (1, 19, 3)).message


def test_entity_target_must_be_single():
    text = "data get entity @e[type=pig] Health"
    d = parse_err(text)
    assert "only one" in d.message and d.col == text.index("@e") + 1
    parse_ok("data get entity @e[type=pig,limit=1] Health")


def test_bad_mode_and_trailing_value():
    assert "modification mode" in parse_err("data modify storage a:b x put value 1").message
    text = "data modify storage a:b x set value 1 2"
    assert parse_err(text).col == text.rindex("2") + 1
