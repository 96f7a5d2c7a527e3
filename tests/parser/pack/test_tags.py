"""Function tags: entry forms, merging across packs, required entries, nesting, cycles, bad JSON.

Rules from minecraft.wiki "Tag" (JSON format): ``required`` defaults to true and a missing
required entry makes the tag fail to load; a circular reference causes a loading failure;
``replace`` drops lower-priority packs' entries.
"""
import pytest

from mcfunction_parser.ast import FunctionTag, TagEntry
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.pack.loader import load_packs
from mcfunction_parser.pack.tags import resolve_tag
from tests.parser.pack.packbuild import tag

FN = "data/a/function/{}.mcfunction"
TAG = "data/{}/tags/function/{}.json"
LOC = Loc("t.json", 1, 1)


def _functions(*names):
    return {FN.format(n): "say " + n + "\n" for n in names}


def test_entry_forms_and_default_namespace(make_pack):
    root = make_pack(files={**_functions("x"), "data/minecraft/function/y.mcfunction": "say y\n",
                            TAG.format("a", "t"): tag("a:x", {"id": "y"}, {"id": "a:x", "required": True})})
    loaded = load_packs([root])
    entries = loaded.tags["a:t"].entries
    assert [(e.id, e.is_tag, e.required) for e in entries] == [
        ("a:x", False, True), ("minecraft:y", False, True), ("a:x", False, True)]
    assert loaded.resolve_tag("#a:t") == ["a:x", "minecraft:y"]
    assert loaded.resolve_tag("a:t") == loaded.resolve_tag("#a:t")


def test_nested_tags_flatten_in_order_without_duplicates(make_pack):
    root = make_pack(files={**_functions("p", "q", "r"),
                            TAG.format("a", "outer"): tag("a:r", "#a:inner", "a:p"),
                            TAG.format("a", "inner"): tag("a:q", "a:r", "#a:leaf"),
                            TAG.format("a", "leaf"): tag("a:p")})
    loaded = load_packs([root])
    assert loaded.errors == []
    assert loaded.resolve_tag("a:outer") == ["a:r", "a:q", "a:p"]
    assert [e.id for e in loaded.tags["a:outer"].entries] == ["a:r", "a:inner", "a:p"]  # not flattened


def test_optional_missing_entries_are_skipped(make_pack):
    root = make_pack(files={**_functions("x"), TAG.format("a", "t"): tag(
        {"id": "a:gone", "required": False}, "a:x", {"id": "#a:no_tag", "required": False})})
    loaded = load_packs([root])
    assert loaded.errors == [] and loaded.resolve_tag("a:t") == ["a:x"]


def test_missing_required_function_fails_the_tag(make_pack):
    root = make_pack(files={**_functions("x"), TAG.format("a", "t"): '{"values": [\n  "a:x",\n  "a:gone"\n]}'})
    loaded = load_packs([root])
    [error] = loaded.errors
    assert "#a:t fails to load: function a:gone does not exist" in error.message
    assert (error.line, error.col) == (3, 3)
    assert error.source_line == '  "a:gone"'
    assert "a:t" not in loaded.tags and "a:t" in loaded.failed_tags
    assert loaded.resolve_tag("a:t") == []


def test_failure_propagates_to_including_tags(make_pack):
    root = make_pack(files={TAG.format("a", "bad"): tag("a:gone"), TAG.format("a", "outer"): tag("#a:bad"),
                            TAG.format("a", "soft"): tag({"id": "#a:bad", "required": False})})
    loaded = load_packs([root])
    assert set(loaded.failed_tags) == {"a:bad", "a:outer"}
    assert "includes #a:bad, which fails to load" in loaded.errors[-1].message
    assert "a:soft" in loaded.tags


def test_cycle_is_diagnosed_once_and_its_tags_fail(make_pack):
    root = make_pack(files={**_functions("x"), TAG.format("a", "one"): tag("a:x", "#a:two"),
                            TAG.format("a", "two"): tag("#a:one")})
    loaded = load_packs([root])
    [error] = loaded.errors
    assert "circular reference #a:one -> #a:two -> #a:one" in error.message
    assert error.path.endswith("two.json")
    assert set(loaded.failed_tags) == {"a:one", "a:two"}


def test_self_reference_is_a_cycle(make_pack):
    loaded = load_packs([make_pack(files={TAG.format("a", "me"): tag("#a:me")})])
    assert "circular reference #a:me -> #a:me" in loaded.errors[0].message


def test_bad_json_has_line_and_column_and_other_tags_load(make_pack):
    root = make_pack(files={**_functions("x"), TAG.format("a", "bad"): '{"values": [\n  "a:x"\n  "a:y"]}',
                            TAG.format("a", "good"): tag("a:x")})
    loaded = load_packs([root])
    [error] = loaded.errors
    assert error.message.startswith("invalid JSON: Expecting ','")
    assert (error.line, error.col) == (3, 3)
    assert loaded.resolve_tag("a:good") == ["a:x"]


def test_empty_parts_of_an_id_are_valid_and_resolve_like_the_game(make_pack):
    # ResourceLocation.read: an empty path is valid (isValidPath finds nothing to refuse), an empty
    # namespace is minecraft's; the entries then name what they name (here: nothing that exists)
    root = make_pack(files={**_functions("x"), TAG.format("a", "t"): tag("a:x", "#a:", ":x")})
    messages = [d.message for d in load_packs([root]).errors]
    assert not any("invalid resource location" in m for m in messages)
    assert any("function tag #a: does not exist" in m for m in messages)
    assert any("function minecraft:x does not exist" in m for m in messages)


def test_malformed_tag_files(make_pack):
    root = make_pack(files={TAG.format("a", "novalues"): '{"replace": false}',
                            TAG.format("a", "badentry"): '{"values": [3]}',
                            TAG.format("a", "badid"): '{"values": ["A:Upper"]}',
                            TAG.format("a", "badreplace"): '{"replace": "yes", "values": []}'})
    messages = sorted(d.message for d in load_packs([root]).errors)
    assert len(messages) == 4
    assert any('"values" list' in m for m in messages)
    assert any("must be a string or an object" in m for m in messages)
    assert any("invalid resource location 'A:Upper'" in m for m in messages)
    assert any('"replace" must be true or false' in m for m in messages)


@pytest.mark.parametrize("folder,kind", [("function", "function tag"), ("item", "item tag"), ("block", "block tag"),
                                         ("entity_type", "entity_type tag"), ("fluid", "fluid tag"),
                                         ("worldgen/biome", "worldgen/biome tag")])
def test_every_message_names_the_registry_of_the_tag(make_pack, folder, kind):
    # each registry's tag file (TagLoader reads them all alike) is reported as what it is
    path = "data/a/tags/" + folder + "/{}.json"
    root = make_pack(files={path.format("novalues"): '{"replace": false}', path.format("badentry"): '{"values": [3]}',
                            path.format("badid"): '{"values": ["A:Upper"]}',
                            path.format("badreplace"): '{"replace": "yes", "values": []}'})
    messages = [d.message for d in load_packs([root]).errors]
    assert len(messages) == 4 and all(m.startswith(f"invalid {kind}: ") for m in messages), messages


def test_tags_merge_across_packs_and_replace_drops_earlier(tmp_path, make_pack):
    first = make_pack("first", files={**_functions("x", "y"), TAG.format("minecraft", "tick"): tag("a:x"),
                                      TAG.format("minecraft", "load"): tag("a:x")})
    second = make_pack("second", files={"data/b/function/z.mcfunction": "say z\n",
                                        TAG.format("minecraft", "tick"): tag("b:z", "a:y"),
                                        TAG.format("minecraft", "load"): tag("b:z", replace=True)})
    loaded = load_packs([first, second])
    assert loaded.resolve_tag("minecraft:tick") == ["a:x", "b:z", "a:y"]
    assert loaded.resolve_tag("minecraft:load") == ["b:z"]


def test_old_format_reads_tags_functions(make_pack):
    root = make_pack(fmt=26, files={"data/a/functions/x.mcfunction": "say x\n",
                                    "data/a/tags/functions/t.json": tag("a:x"),
                                    "data/a/tags/function/new.json": tag("a:x")})
    loaded = load_packs([root])
    assert loaded.resolve_tag("a:t") == ["a:x"] and "a:new" not in loaded.tags
    [warning] = loaded.warnings
    assert "'data/a/tags/function/' ignored" in warning.message


def test_large_tag_file_reports_each_entry_at_its_own_position(make_pack):
    values = ",\n".join(f'  "a:f{i}"' for i in range(20000))
    root = make_pack(files={TAG.format("a", "big"): '{"values": [\n' + values + "\n]}"})
    loaded = load_packs([root])
    last = loaded.errors[-1]  # every entry is missing: one error per entry, at its own line
    assert len(loaded.errors) == 20000 and (last.line, last.col) == (20001, 3)


def test_nested_tags_that_share_members_are_each_walked_once():
    # a chain of diamonds: #d0 includes #d1 twice over (through #a1 and #b1), and so on; walked
    # path by path this is 2**40 visits, the game's own resolution builds each tag once
    # (TagLoader.build with its memo of resolved tags)
    tags = {}
    for level in range(40):
        nxt = f"t:d{level + 1}"
        tags[f"t:d{level}"] = FunctionTag(f"t:d{level}", [TagEntry(f"t:a{level + 1}", True, True, LOC),
                                                           TagEntry(f"t:b{level + 1}", True, True, LOC)])
        for side in "ab":
            tags[f"t:{side}{level + 1}"] = FunctionTag(f"t:{side}{level + 1}", [TagEntry(nxt, True, True, LOC),
                                                                                TagEntry(f"t:f{level}", False, True, LOC)])
    tags["t:d40"] = FunctionTag("t:d40", [TagEntry("t:end", False, True, LOC)])

    class Counting(dict):
        lookups = 0

        def get(self, key, default=None):
            Counting.lookups += 1
            return super().get(key, default)

    functions = {f"t:f{level}" for level in range(40)} | {"t:end"}
    members = resolve_tag(Counting(tags), functions, "t:d0")
    assert members == ["t:end"] + [f"t:f{level}" for level in reversed(range(40))]
    assert Counting.lookups <= 2 * len(tags)
