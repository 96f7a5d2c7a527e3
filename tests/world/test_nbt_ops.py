"""NBT paths and ``data`` operations, pinned to the game's NbtPathArgument / DataCommands / NbtUtils
(decompiled 1.21, Yeet-Masta/MCP-1.21: commands/arguments/NbtPathArgument.java,
server/commands/data/DataCommands.java, nbt/NbtUtils.java)."""
from __future__ import annotations

import pytest
from hypothesis import given, settings, strategies as st

from mcfunction_parser.nbt import (
    Byte, ByteArray, Compound, Double, Float, Int, IntArray, List, Long, String,
)
from emulator.world import nbt_ops
from emulator.world.errors import CommandFailure
from tests.world.world_paths import path


def C(**kw) -> Compound:
    return Compound(kw)


# ----------------------------------------------------------------------------- equality and matching


def test_tags_equal_is_type_strict():
    # Tag.equals: ByteTag(1) is not IntTag(1); FloatTag compares with == so NaN != NaN.
    assert nbt_ops.tags_equal(Int(1), Int(1))
    assert not nbt_ops.tags_equal(Byte(1), Int(1))
    assert not nbt_ops.tags_equal(Float(float("nan")), Float(float("nan")))
    assert not nbt_ops.tags_equal(List([Int(1)]), List([Long(1)]))
    assert nbt_ops.tags_equal(C(a=List([Int(1)])), C(a=List([Int(1)])))


def test_compare_nbt_compound_is_partial_and_type_strict():
    actual = C(a=Int(1), b=C(c=String("x"), d=Byte(0)))
    assert nbt_ops.compare_nbt(C(b=C(c=String("x"))), actual)
    assert not nbt_ops.compare_nbt(C(a=Byte(1)), actual)  # 1b does not match 1
    assert not nbt_ops.compare_nbt(C(z=Int(0)), actual)


def test_compare_nbt_list_rules():
    # NbtUtils.compareNbt with partialLists: [] matches only [], every pattern element must match
    # some element, and the actual list must be at least as long as the pattern.
    actual = List([Int(1), Int(2), Int(3)])
    assert nbt_ops.compare_nbt(List([Int(3), Int(1)]), actual)
    assert not nbt_ops.compare_nbt(List([Int(4)]), actual)
    assert nbt_ops.compare_nbt(List(), List())
    assert not nbt_ops.compare_nbt(List(), actual)
    assert not nbt_ops.compare_nbt(List([Int(1), Int(1)]), List([Int(1)]))
    assert nbt_ops.compare_nbt(List([Int(1), Int(1)]), List([Int(1), Int(5)]))
    # Without partial lists the comparison is exact equality.
    assert not nbt_ops.compare_nbt(List([Int(3), Int(1)]), actual, partial_lists=False)


# ----------------------------------------------------------------------------- get


def test_get_every_kind_of_node():
    root = C(items=List([C(id=String("a"), n=Int(1)), C(id=String("b"), n=Int(2))]), arr=IntArray([4, 5]))
    assert nbt_ops.get(root, path("items[1].n", "items", 1, "n")) == [Int(2)]
    assert nbt_ops.get(root, path("items[-1].id", "items", -1, "id")) == ["b"]
    assert nbt_ops.get(root, path("items[].n", "items", "[]", "n")) == [1, 2]
    assert nbt_ops.get(root, path('items[{id:"b"}].n', "items", [C(id=String("b"))], "n")) == [2]
    assert nbt_ops.get(root, path("{arr:[I;4,5]}.arr[0]", {"arr": IntArray([4, 5])}, "arr", 0)) == [4]
    got = nbt_ops.get(root, path("arr[]", "arr", "[]"))
    assert got == [4, 5] and all(type(t) is Int for t in got)  # array elements come out as IntTags


def test_get_nothing_found_quotes_the_path_up_to_the_failing_node():
    root = C(a=C(b=Int(1)))
    with pytest.raises(CommandFailure) as err:
        nbt_ops.get(root, path("a.c.d", "a", "c", "d"))
    assert err.value.message == "Found no elements matching a.c"
    with pytest.raises(CommandFailure) as err:
        nbt_ops.get(root, path('a{b:2}.b', "a", {"b": Int(2)}, "b"))
    assert err.value.message == "Found no elements matching a{b:2}"


def test_count_matching_for_execute_if_data():
    root = C(l=List([Int(1), Int(2), Int(3)]))
    assert nbt_ops.count_matching(root, path("l[]", "l", "[]")) == 3
    assert nbt_ops.count_matching(root, path("l[5]", "l", 5)) == 0
    assert nbt_ops.count_matching(root, path("x.y", "x", "y")) == 0


# ----------------------------------------------------------------------------- set


def test_set_creates_missing_compounds_and_counts_changes():
    root = C()
    assert nbt_ops.set_path(root, path("a.b.c", "a", "b", "c"), Int(5)) == 1
    assert root == {"a": {"b": {"c": 5}}} and type(root["a"]["b"]) is Compound
    # Setting the same value again changes nothing.
    assert nbt_ops.set_path(root, path("a.b.c", "a", "b", "c"), Int(5)) == 0
    # A different type of the same number is a change (1b differs from 1).
    assert nbt_ops.set_path(root, path("a.b.c", "a", "b", "c"), Byte(5)) == 1


def test_set_creates_a_list_parent_for_an_all_node():
    # AllElementsNode.createPreferredParentTag is a ListTag; getOrCreate on an empty list adds
    # the next node's preferred parent (a compound), so `l[].x` on nothing gives [{x:1}].
    root = C()
    assert nbt_ops.set_path(root, path("l[].x", "l", "[]", "x"), Int(1)) == 1
    assert root == {"l": [{"x": 1}]} and type(root["l"]) is List


def test_set_index_out_of_range_and_wrong_list_type():
    root = C(l=List([Int(1), Int(2)]))
    assert nbt_ops.set_path(root, path("l[5]", "l", 5), Int(9)) == 0
    assert nbt_ops.set_path(root, path("l[0]", "l", 0), String("x")) == 0  # a list holds one type
    assert nbt_ops.set_path(root, path("l[-1]", "l", -1), Int(7)) == 1
    assert root["l"] == [1, 7]


def test_set_all_elements_returns_number_changed():
    root = C(l=List([Int(1), Int(5), Int(1)]))
    assert nbt_ops.set_path(root, path("l[]", "l", "[]"), Int(1)) == 1
    assert root["l"] == [1, 1, 1]


def test_set_match_element_and_match_child():
    root = C(l=List([C(k=Int(1), v=Int(0)), C(k=Int(2), v=Int(0))]), o=C(t=Int(1)))
    assert nbt_ops.set_path(root, path("l[{k:2}].v", "l", [C(k=Int(2))], "v"), Int(9)) == 1
    assert root["l"][1]["v"] == 9 and root["l"][0]["v"] == 0
    # key{pattern}: replaced only while the current value matches the pattern.
    assert nbt_ops.set_path(root, path("o{t:2}", "o", {"t": Int(2)}), Int(0)) == 0
    assert nbt_ops.set_path(root, path("o{t:1}", "o", {"t": Int(1)}), Int(0)) == 1
    assert root["o"] == 0


def test_set_into_array_narrows_like_getAsByte():
    # ByteArrayTag.setTag stores NumericTag.getAsByte(): an int keeps its low 8 bits,
    # a double goes through Mth.floor first (-1.5d -> -2).
    root = C(b=ByteArray([0, 0]))
    assert nbt_ops.set_path(root, path("b[0]", "b", 0), Int(300)) == 1
    assert nbt_ops.set_path(root, path("b[1]", "b", 1), Double(-1.5)) == 1
    assert root["b"] == [44, -2]


def test_set_too_deep_fails():
    deep = Int(0)
    for _ in range(511):
        deep = C(x=deep)
    with pytest.raises(CommandFailure, match="too deeply nested"):
        nbt_ops.set_path(C(), path("a", "a"), deep)


# ----------------------------------------------------------------------------- insert / merge / remove


def test_append_prepend_insert():
    root = C()
    assert nbt_ops.modify(root, path("l", "l"), "append", [Int(2)]) == 1
    assert nbt_ops.modify(root, path("l", "l"), "prepend", [Int(1)]) == 1
    assert nbt_ops.modify(root, path("l", "l"), "insert", [Int(9), Int(8)], index=-2) == 1
    assert root["l"] == [1, 9, 8, 2]


def test_insert_failures_use_the_game_messages():
    root = C(l=List([Int(1)]), s=String("x"))
    with pytest.raises(CommandFailure) as err:
        nbt_ops.modify(root, path("l", "l"), "insert", [Int(2)], index=5)
    assert err.value.message == "Invalid list index: 5"
    with pytest.raises(CommandFailure) as err:
        nbt_ops.modify(root, path("s", "s"), "append", [Int(2)])
    assert err.value.message == 'Expected list, got: "x"'
    # A value of the wrong type is refused without an error, so nothing changed.
    with pytest.raises(CommandFailure, match="Nothing changed"):
        nbt_ops.modify(root, path("l", "l"), "append", [String("y")])


def test_merge_mode_and_data_merge():
    root = C(o=C(a=Int(1), sub=C(x=Int(1))))
    assert nbt_ops.modify(root, path("o", "o"), "merge", [C(sub=C(y=Int(2)))]) == 1
    assert root["o"] == {"a": 1, "sub": {"x": 1, "y": 2}}
    with pytest.raises(CommandFailure, match="Nothing changed"):
        nbt_ops.modify(root, path("o", "o"), "merge", [C(a=Int(1))])
    with pytest.raises(CommandFailure) as err:
        nbt_ops.modify(root, path("o", "o"), "merge", [Int(3)])
    assert err.value.message == "Expected object, got: 3"
    assert nbt_ops.data_merge(root, C(b=Int(2))) == 1
    assert root["b"] == 2 and root["o"]["a"] == 1
    with pytest.raises(CommandFailure, match="Nothing changed"):
        nbt_ops.data_merge(root, C(o=C(a=Int(1))))


def test_remove_counts_and_nothing_changed():
    root = C(l=List([C(k=Int(1)), C(k=Int(2)), C(k=Int(1))]), a=Int(1))
    assert nbt_ops.data_remove(root, path("l[{k:1}]", "l", [C(k=Int(1))])) == 2
    assert root["l"] == [{"k": 2}]
    assert nbt_ops.data_remove(root, path("a", "a")) == 1
    with pytest.raises(CommandFailure, match="Nothing changed"):
        nbt_ops.data_remove(root, path("missing.x", "missing", "x"))


def test_string_source_substrings():
    # DataCommands.substring: negative bounds count from the end; bad bounds fail.
    assert nbt_ops.string_source([String("hello")], 1, -1) == ["ell"]
    assert nbt_ops.string_source([Int(42)]) == ["42"]
    # Tag.getAsString: numbers as Java prints them with their suffix (StringTagVisitor).
    assert nbt_ops.string_source([Float(0.1), Double(1e7), Byte(-3), Long(5)]) == ["0.1f", "1.0E7d", "-3b", "5L"]
    with pytest.raises(CommandFailure) as err:
        nbt_ops.string_source([String("hi")], 3)
    assert err.value.message == "Invalid substring indices: 3 to 2"
    with pytest.raises(CommandFailure, match="Expected value"):
        nbt_ops.string_source([C()])


# ----------------------------------------------------------------------------- properties

leaf = st.one_of(st.integers(-5, 5).map(Int), st.integers(-5, 5).map(Byte), st.sampled_from(["a", "b"]).map(String))
tags = st.recursive(
    leaf,
    lambda children: st.one_of(
        st.lists(children, max_size=3).map(List),
        st.dictionaries(st.sampled_from(["x", "y", "z"]), children, max_size=3).map(Compound),
    ),
    max_leaves=8,
)


@settings(max_examples=200, deadline=None)
@given(tags)
def test_every_tag_matches_itself_and_its_copy(tag):
    copy = nbt_ops.copy_tag(tag)
    assert nbt_ops.tags_equal(tag, copy)
    assert nbt_ops.compare_nbt(tag, copy)


@settings(max_examples=200, deadline=None)
@given(st.dictionaries(st.sampled_from(["x", "y", "z"]), tags, max_size=3).map(Compound), tags)
def test_set_then_get_round_trips(root, value):
    p = path("k.v", "k", "v")
    nbt_ops.set_path(root, p, value)
    assert nbt_ops.tags_equal(nbt_ops.get(root, p)[0], value)
    assert nbt_ops.set_path(root, p, value) == 0


def _parsed(text: str):
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.nbt_path import nbt_path
    from mcfunction_parser.reader import Reader

    return nbt_path(Reader(text, Loc("t", 1, 1), (1, 21, 0)))


@pytest.mark.parametrize("text, prefix", [
    # NbtPath.createNotFoundException quotes the original text up to the end of the failing node.
    ('a{b:1}.c[{d:"]"}].e', 'a{b:1}.c[{d:"]"}]'),
    ('"q.k".y[-1]', '"q.k".y'),
    ("{r:1}.zz[]", "{r:1}.zz"),
    ("{r:2}.a", "{r:2}"),
    ("k.missing.z", "k.missing"),
])
def test_nothing_found_prefix_with_parsed_paths(text, prefix):
    root = C(a=C(b=Int(1), c=List([C(d=String("x"))])), k=C(), r=Int(1))
    root["q.k"] = C(x=String("not a list"))
    with pytest.raises(CommandFailure) as err:
        nbt_ops.get(root, _parsed(text))
    assert err.value.message == f"Found no elements matching {prefix}"


def test_nesting_up_to_the_limit_is_handled():
    # A value nested 510 deep under a 1-node path is allowed (isTooDeep counts from the path depth).
    deep = Int(0)
    for _ in range(510):
        deep = C(x=deep)
    root = C()
    assert nbt_ops.set_path(root, path("a", "a"), deep) == 1
    assert nbt_ops.tags_equal(root["a"], deep) and nbt_ops.compare_nbt(deep, root["a"])


keys = st.lists(st.sampled_from(["x", "y", "z"]), min_size=1, max_size=3)


@settings(max_examples=200, deadline=None)
@given(st.dictionaries(st.sampled_from(["x", "y", "z"]), tags, max_size=3).map(Compound), keys)
def test_remove_then_nothing_matches(root, names):
    p = path(".".join(names), *names)
    before = nbt_ops.count_matching(root, p)
    assert nbt_ops.remove(root, p) == before
    assert nbt_ops.count_matching(root, p) == 0


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(-5, 5).map(Int), max_size=4), st.lists(st.integers(-5, 5).map(Int), min_size=1, max_size=3),
       st.integers(-6, 6))
def test_insert_matches_python_list_insert(initial, values, index):
    # NbtPath.insert: index < 0 counts from the end (+1), elements go in one after another.
    root = C(l=List(initial))
    position = len(initial) + index + 1 if index < 0 else index
    if not 0 <= position <= len(initial):
        with pytest.raises(CommandFailure, match="Invalid list index"):
            nbt_ops.insert(root, path("l", "l"), index, values)
        return
    assert nbt_ops.insert(root, path("l", "l"), index, values) == 1
    assert root["l"] == initial[:position] + values + initial[position:]


def test_list_rules_by_version():
    # ListTag up to 1.21.4 refuses a second tag type; 1.21.5 lists may mix types.
    root = C(l=List([Int(1)]))
    with nbt_ops.list_rules((1, 21, 4)):
        with pytest.raises(CommandFailure, match="Nothing changed"):
            nbt_ops.modify(root, path("l", "l"), "append", [String("a")])
    with nbt_ops.list_rules((1, 21, 5)):
        assert nbt_ops.modify(root, path("l", "l"), "append", [String("a")]) == 1
        assert nbt_ops.set_path(root, path("l[0]", "l", 0), Byte(2)) == 1
    assert root["l"] == [2, "a"] and type(root["l"][0]) is Byte
