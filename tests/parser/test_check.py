"""The linter behind ``dpemu check``: parser errors surface, plus the whole-pack rules."""
import gc
import json
import re
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from mcfunction_parser import ast, check
from mcfunction_parser.check import check_packs, check_releases, walk
from mcfunction_parser.pack.loader import load_packs
from mcfunction_parser.pack.versions import parse_mc_version
from tests.datapack.pack_paths import PACK

META = json.dumps({"pack": {"pack_format": 61, "description": "t"}})


def write(root: Path, files: dict[str, str | bytes]) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    if "pack.mcmeta" not in files:
        (root / "pack.mcmeta").write_text(META)
    for rel, content in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(content if isinstance(content, bytes) else content.encode())
    return root


def fn(name: str) -> str:
    return f"data/a/function/{name}.mcfunction"


LOAD = {"data/minecraft/tags/function/load.json": '{"values": ["a:load"]}'}


def messages(result, severity):
    return [d.message for d in result.of(severity)]


def test_syntax_errors_come_from_the_parser_and_the_rest_still_loads(tmp_path):
    root = write(tmp_path / "p", {**LOAD,
        fn("load"): "scoreboard objectives add o dummy\nfunction a:broken\n",
        fn("broken"): 'execute as @e[tag=a run say x\ndata modify storage a:b x set value "abc\nsay fine\n'})
    result = check_packs([root])
    errors = result.of("error")
    # ServerFunctionLibrary: a function with a line that does not parse fails to load, so the
    # call to it names an unknown function
    assert [(e.line, e.col) for e in errors] == [(1, 21), (2, 37), (2, 1)]
    assert "unclosed" in errors[1].message
    assert errors[2].message.startswith("function a:broken fails to load")
    assert errors[0].source_line == "execute as @e[tag=a run say x"
    assert result.functions == 2 and result.commands == 3


def test_literal_integers_out_of_range(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): "scoreboard objectives add o dummy\n"
                                  "scoreboard players set x o 2147483648\nscoreboard players add x o -1\n"
                                  "scoreboard players set x o -2147483648\n"})
    errors = check_packs([root]).of("error")
    # the function fails to load, and #minecraft:load with it (TagLoader: a missing reference)
    assert [(e.line, e.col) for e in errors] == [(2, 28), (3, 28), (1, 13)]
    assert "fails to load (a line of it does not parse)" in errors[2].message


def test_calls_to_missing_functions_and_tags(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): (
        "function a:nope\nschedule function a:gone 5t\nexecute if function a:missing run say x\n"
        "function #a:no_tag\nexecute unless function #a:broken_tag run say x\nfunction a:load\n"),
        "data/a/tags/function/broken_tag.json": '{"values": ["a:absent"]}'})
    result = check_packs([root])
    linter = [(d.line, d.message) for d in result.of("error") if d.path.endswith("load.mcfunction")]
    assert linter == [
        (1, "unknown function a:nope"),
        (2, "unknown function a:gone (schedule function)"),
        (3, "unknown function a:missing (execute if function)"),
        (4, "unknown function tag #a:no_tag"),
        (5, "function tag #a:broken_tag fails to load (function a:absent does not exist) "
            "(execute if function)"),
    ]


def test_macro_function_calls_need_every_key(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): (
        "function a:m\nfunction a:m {x: 1, y: 2}\nfunction a:m {x: 1}\n"
        "function a:m with storage a:s args\nfunction a:plain {x: 1}\n"),
        fn("m"): "$say $(x)\nsay between\n$say $(y) $(x)\n", fn("plain"): "say p\n"})
    errors = check_packs([root]).of("error")
    assert [(e.line, e.message) for e in errors] == [
        (1, "function a:m is a macro function: calling it without arguments fails"),
        (3, "function a:m needs macro argument(s) y: the call fails without them")]


def test_macro_functions_run_without_arguments_by_schedule_and_game_tags(tmp_path):
    root = write(tmp_path / "p", {
        "data/minecraft/tags/function/tick.json": '{"values": ["#a:inner"]}',
        "data/a/tags/function/inner.json": '{"values": ["a:m"]}',
        fn("m"): "$say $(x)\nschedule function a:m 1t\n"})
    errors = [(e.line, e.message) for e in check_packs([root]).of("error")]
    assert errors == [
        (None, "function a:m is a macro function: as a member of #minecraft:tick it runs without "
               "arguments and fails"),
        (2, "function a:m is a macro function: a scheduled call has no arguments and fails")]


def test_execute_if_function_without_return(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): (
        "execute if function a:silent run say 1\nexecute unless function #a:quiet run say 2\n"
        "execute if function a:answers run say 3\nexecute if function #a:mixed run say 4\n"
        "execute if function a:nested run say 5\nexecute if function a:macro run say 6\n"),
        fn("silent"): "say s\n", fn("answers"): "execute if score x o matches 1 run return 1\n",
        fn("nested"): "execute as @s run return run say hi\n", fn("macro"): "$return $(x)\n",
        "data/a/tags/function/quiet.json": '{"values": ["a:silent"]}',
        "data/a/tags/function/mixed.json": '{"values": ["a:silent", "a:answers"]}'})
    warnings = [(d.line, d.message) for d in check_packs([root]).of("warning") if "return" in d.message]
    assert warnings == [
        (1, "a:silent never runs 'return', so 'execute if function' always fails"),
        (2, "#a:quiet never runs 'return', so 'execute unless function' always fails")]


def test_objectives_never_created(tmp_path):
    lib = write(tmp_path / "lib", {fn("lib_init"): "scoreboard objectives add shared dummy\n"
                                   "$scoreboard objectives add $(name) dummy\n"
                                   "$scoreboard objectives add macro_made $(criterion)\n",
                                   "data/minecraft/tags/function/load.json": '{"values": ["a:lib_init"]}'})
    game = write(tmp_path / "game", {**LOAD, fn("load"): (
        "scoreboard players set x shared 1\nscoreboard players set x typo 1\n"
        "execute if score x typo matches 1 run say hi\nexecute as @e[scores={other=1..}] run say x\n"
        "scoreboard players operation x shared += y macro_made\n")})
    result = check_packs([lib, game])
    assert sorted(messages(result, "warning")) == [
        "objective 'other' is used but never created by 'scoreboard objectives add' in the loaded packs",
        "objective 'typo' is used but never created by 'scoreboard objectives add' in the loaded packs (2 uses)",
    ]
    typo = next(d for d in result.of("warning") if "typo" in d.message)
    assert (typo.line, typo.col) == (2, 1)


def test_unreferenced_functions_are_infos(tmp_path):
    root = write(tmp_path / "p", {**LOAD,
        fn("load"): "function a:called\nschedule function a:later 1s\n",
        fn("called"): "say c\n", fn("later"): "say l\n", fn("reward"): "say r\n",
        fn("orphan"): "say o\n", fn("recursive"): "function a:recursive\n",
        "data/a/advancement/adv.json": '{"criteria": {"t": {"trigger": "tick"}}, "rewards": {"function": "a:reward"}}'})
    result = check_packs([root])
    assert sorted(messages(result, "info")) == [
        f"function a:{name} is never referenced (no tag, function, schedule or advancement reward "
        "names it)" for name in ("orphan", "recursive")]
    assert result.of("error") == [] and result.of("warning") == []


def test_functions_named_in_macro_lines_are_referenced(tmp_path):
    root = write(tmp_path / "p", {**LOAD,
        fn("load"): "function a:m {v: 1, name: x}\n",
        fn("m"): "$function a:helper {v: $(v)}\n$function a:$(name)\n$function a:pre_$(name)\n",
        fn("helper"): "say h\n", fn("pre_"): "say never\n"})
    result = check_packs([root])
    assert messages(result, "info") == [
        "function a:pre_ is never referenced (no tag, function, schedule or advancement reward names it)"]


def test_functions_in_a_failed_tag_are_not_unreferenced(tmp_path):
    root = write(tmp_path / "p", {fn("x"): "say x\n", "data/minecraft/tags/function/tick.json":
                                  '{"values": ["a:x", "a:missing"]}'})
    result = check_packs([root])
    assert result.of("info") == [] and len(result.of("error")) == 1


def test_summary_and_json(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): "say a\n\n# comment\nfunction a:nope\n"})
    result = check_packs([root])
    assert result.summary() == "3 files, 1 function, 2 commands: 1 error, 0 warnings"
    data = result.to_json()
    assert set(data) == {"files", "functions", "commands", "lines", "errors", "warnings", "infos", "versions", "seconds"}
    assert data["lines"] == 4 and data["errors"][0] == {
        "path": f"{root}/data/a/function/load.mcfunction", "line": 4, "col": 1,
        "message": "unknown function a:nope"}


def test_diagnostics_are_sorted_by_file_and_position(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): "function a:z\nfunction a:y\n", fn("b"): "function a:q\n"})
    result = check_packs([root])
    keys = [(d.path, d.line or 0) for d in result.diagnostics]
    assert keys == sorted(keys)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(function=st.binary(max_size=200), tag_file=st.binary(max_size=80), meta=st.binary(max_size=60))
def test_arbitrary_bytes_never_crash(tmp_path_factory, function, tag_file, meta):
    root = write(tmp_path_factory.mktemp("fuzz"), {
        "pack.mcmeta": meta, fn("f"): function, "data/a/tags/function/t.json": tag_file})
    result = check_packs([root])
    assert result.summary()  # every problem became a diagnostic
    assert all(d.path for d in result.diagnostics)


def test_generated_corpus_checks_without_errors(tmp_path):
    sys.path.insert(0, str(Path(__file__).parents[2] / "bench"))
    corpus = pytest.importorskip("corpus")
    lines = corpus.write_corpus(tmp_path / "corpus", lines=40000)
    first = check_packs([tmp_path / "corpus"])
    # The generated pack names a few functions, tags and predicates it does not define: provide
    # them in a second pack, so every remaining error would be a parser or linter fault.
    missing = {m.group(2): m.group(1) for d in first.of("error")
               if (m := re.match(r"unknown (function tag #|function |predicate )(\S+)", d.message))}
    library = {"pack.mcmeta": json.dumps({"pack": {"pack_format": corpus.PACK_FORMAT, "description": ""}})}
    stubs = {"function tag #": ("tags/function", ".json", '{"values": []}'),
             "function ": ("function", ".mcfunction", "return 1\n"),
             "predicate ": ("predicate", ".json", '{"condition": "minecraft:random_chance", "chance": 1}')}
    for name, kind in missing.items():
        ns, path = name.split(":")
        folder, suffix, text = stubs[kind]
        library[f"data/{ns}/{folder}/{path}{suffix}"] = text
    write(tmp_path / "library", library)
    result = check_packs([tmp_path / "corpus", tmp_path / "library"])
    assert result.of("error") == []
    functions_added = sum(kind == "function " for kind in missing.values())
    assert result.lines == lines + functions_added and lines >= 40000 and result.commands > 25000


def test_advancement_rewards_must_exist_and_later_packs_replace_advancements(tmp_path):
    first = write(tmp_path / "first", {"data/a/advancement/adv.json": '{"criteria": {"t": {"trigger": "tick"}},'
                                       ' "rewards": {"function": "a:old"}}', fn("old"): "say old\n"})
    second = write(tmp_path / "second", {"data/a/advancement/adv.json": '{"criteria": {"t": {"trigger": "tick"}},\n'
                                         ' "rewards": {"function": "a:gone"}}'})
    result = check_packs([first, second])
    [error] = result.of("error")
    assert (error.message, error.line, error.col) == ("unknown function a:gone (advancement reward)", 2, 26)
    assert error.source_line == ' "rewards": {"function": "a:gone"}}'
    assert [d.message.split(" is ")[0] for d in result.of("info")] == ["function a:old"]


def test_advancement_loot_and_recipe_rewards_must_exist(tmp_path):
    # AdvancementRewards.grant gives nothing for an unknown table and skips an unknown recipe, in
    # silence: graded as other references (an error in a namespace the packs define, a warning in
    # another; the game's own ids are not judged without its jar)
    root = write(tmp_path / "p", {
        "data/a/advancement/adv.json": json.dumps({"criteria": {"t": {"trigger": "minecraft:tick"}}, "rewards": {
            "loot": ["a:chest", "a:gone", "lib:bonus", "minecraft:chests/igloo_chest"],
            "recipes": ["a:wand", "a:nope", "minecraft:stick"]}}, indent=1),
        "data/a/loot_table/chest.json": '{"pools": []}',
        "data/a/recipe/wand.json": '{"type": "minecraft:crafting_shapeless", "ingredients": ["minecraft:stick"],'
                                   ' "result": {"id": "minecraft:stick"}}',
        "data/a/recipe/broken.json": '{"ingredients": []}', **LOAD,
        fn("load"): "recipe give @a a:wand\nrecipe take @a *\nexecute as @a run recipe give @s a:typo\n"
                    "recipe give @a minecraft:stick\n"})
    result = check_packs([root])
    errors = {(d.message, d.line) for d in result.of("error")}
    assert errors == {("unknown loot table a:gone (advancement reward)", 10),
                      ("unknown recipe a:nope (advancement reward)", 16),
                      ("recipe a:broken: missing the string 'type'", 1),
                      ("unknown recipe a:typo", 3)}  # RecipeCommand: the id is looked up when it runs
    assert [d.message.split(":")[0:2] for d in result.of("warning")] == [["unknown loot table lib", "bonus (advancement reward)"]]


def test_predicates_must_exist_unless_inline(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("load"): (
        "execute if predicate a:known run say 1\nexecute if predicate a:unknown run say 2\n"
        "execute as @e[predicate=!a:missing] run say 3\n"
        'execute if predicate {condition: "minecraft:random_chance", chance: 0.5} run say 4\n'),
        "data/a/predicate/known.json": '{"condition": "minecraft:random_chance", "chance": 0.5}',
        "data/a/predicates/old_folder.json": "{}"})
    errors = [(e.line, e.message) for e in check_packs([root]).of("error")]
    assert errors == [(2, "unknown predicate a:unknown"), (3, "unknown predicate a:missing")]


def test_a_predicate_of_a_namespace_no_pack_defines_is_a_warning(tmp_path):
    # EntitySelectorOptions "predicate" looks the id up per entity when the selector runs (an
    # unknown one matches nothing): the function loads, and the predicate may come from a library
    root = write(tmp_path / "p", {**LOAD, fn("load"): "execute as @e[predicate=lib:near] run say 1\n"})
    result = check_packs([root])
    assert result.of("error") == []
    [warning] = [w for w in result.of("warning") if "lib:near" in w.message]
    assert warning.message == ("unknown predicate lib:near: no loaded pack defines the namespace 'lib' (it is "
                               "unknown when it runs unless a pack beside this one defines it; name that pack "
                               "with --with)")
    lib = write(tmp_path / "lib", {"data/lib/predicate/near.json": '{"condition": "minecraft:random_chance", '
                                                                   '"chance": 0.5}'})
    assert not [w for w in check_packs([root], with_packs=[lib]).of("warning") if "lib:near" in w.message]


def _generic_facts(loaded):
    """What the rules read, found the slow way: every node of every function (check.walk)."""
    calls, predicates, uses, created, returning = [], [], {}, set(), set()
    for function in [*loaded.functions.values(), *loaded.refused.values()]:
        nodes = []
        for command in function.commands:
            walk(command, nodes)
        for node in nodes:
            if isinstance(node, (ast.FunctionCall, ast.Schedule, ast.IfFunction, ast.MacroLine)):
                calls.append((function, node))
            if isinstance(node, (ast.Return, ast.MacroLine)):
                returning.add(function.id)
            if isinstance(node, ast.IfPredicate):
                predicates.append((node.predicate, node.loc))
            if isinstance(node, ast.SelectorArg) and node.key == "predicate":
                predicates.append((node.value, node.loc))
            if isinstance(node, ast.ObjectivesAdd):
                created.add(node.objective)
                continue
            if isinstance(node, ast.MacroLine):
                created.update(re.findall(r"(?:^|\s)scoreboard\s+objectives\s+add\s+(\S+)", node.template))
            for name in ("objective", "source_objective"):
                if isinstance(getattr(node, name, None), str):
                    uses.setdefault(getattr(node, name), []).append(node.loc)
            if isinstance(node, ast.SelectorArg) and node.key == "scores":
                for objective, _ in node.value:
                    uses.setdefault(objective, []).append(node.loc)
    return calls, predicates, uses, created, returning


def test_the_rules_walk_finds_what_walking_every_node_finds(tmp_path):
    """The linter looks only inside fields whose declared type can hold a node its rules read;
    on the generated corpus (every command family, each selector given a score and a predicate
    to find) and the pool pack it finds the same nodes, in the same order, as the walk over
    every node."""
    sys.path.insert(0, str(Path(__file__).parents[2] / "bench"))
    corpus = pytest.importorskip("corpus")
    corpus.write_corpus(tmp_path / "corpus", lines=20000)
    for path in (tmp_path / "corpus").rglob("*.mcfunction"):
        path.write_text(re.sub(r"@([aeprsn])(\[)?", lambda m: f"@{m[1]}[scores={{o=1}},predicate=a:p"
                               + ("," if m[2] else "]"), path.read_text()))
    loaded = load_packs([tmp_path / "corpus", PACK])
    facts = check._gather(loaded)
    calls, predicates, uses, created, returning = _generic_facts(loaded)
    assert len(calls) > 1000 and len(predicates) > 100 and len(uses) >= 10 and returning
    assert [(f.id, n) for f, n in facts.calls] == [(f.id, n) for f, n in calls]
    assert facts.predicates == predicates
    assert facts.uses == uses and list(facts.uses) == list(uses)
    assert (facts.created, facts.returning) == (created, returning)


def test_checked_packs_leave_the_youngest_collector_generation(tmp_path):
    """After a check the collector's next young collection does not walk the loaded ASTs."""
    root = write(tmp_path / "p", {**LOAD, fn("load"): "scoreboard objectives add o dummy\n" * 50})
    result = check_packs([root])
    young = {id(o) for o in gc.get_objects(generation=0)}
    commands = result.loaded.functions["a:load"].commands
    assert len(commands) == 50 and not any(id(c) in young for c in commands)


def test_the_progress_callback_hears_every_function_once_per_release(tmp_path):
    root = write(tmp_path / "p", {**LOAD, fn("a"): "say a\n", fn("b"): "say b\n"})
    heard = []
    check_releases([root], [parse_mc_version("1.21"), parse_mc_version("1.21.4")],
                   on_function=lambda done, total: heard.append((done, total)))
    assert heard == [(1, 2), (2, 2)] * 2  # a:a and a:b, for each of the two formats


def test_inline_predicates_are_checked_as_the_game_loads_them(tmp_path):
    # ExecuteCommand's inline predicate (1.20.5+) goes through the condition codec when the function loads
    pack = write(tmp_path / "p", {fn("f"): 'execute if predicate {condition:"minecraft:nope"} run say a\n'
                                           'execute if predicate {condition:"minecraft:random_chance",chance:0.5f} run say b\n'})
    [error] = check_packs([pack]).of("error")
    assert error.line == 1 and "inline predicate: unknown predicate condition type 'minecraft:nope'" in error.message


def test_inline_loot_tables_and_item_modifiers_are_checked_as_the_game_loads_them(tmp_path):
    # ResourceOrIdArgument (1.20.5+) decodes an inline loot table or item modifier with the file's
    # codec when the function loads: an unknown function type or item id refuses it
    pack = write(tmp_path / "p", {fn("f"): "\n".join([
        'item modify entity @s weapon.mainhand {function:"minecraft:nope"}',
        'loot give @s loot {pools:[{rolls:1,entries:[{type:"minecraft:item",name:"minecraft:not_real"}]}]}',
        'item modify entity @s weapon.mainhand {function:"minecraft:set_count",count:2}',
        'loot give @s loot {pools:[{rolls:1,entries:[{type:"minecraft:item",name:"minecraft:stone"}]}]}']) + "\n"})
    errors = check_packs([pack]).of("error")
    assert [(e.line, e.message) for e in errors] == [
        (1, "inline item modifier: unknown item function type 'minecraft:nope'"),
        (2, "inline loot table: unknown item 'minecraft:not_real'")]
