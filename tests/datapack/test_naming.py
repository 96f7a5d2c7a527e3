"""The pack's naming convention (datapack/README.md, "Naming"): `$` public and `#` private fake
players, constants named by value, and every private scratch holder prefixed by the feature that
owns it, as the README's table lists them. A rename that missed a file shows up here as a holder
read but never written, or written but never read."""
import re
from collections import defaultdict

import pytest

from mcfunction_parser import ast
from mcfunction_parser.check import walk
from mcfunction_parser.pack.loader import load_packs
from mcfunction_parser.parse import parse_function
from tests.datapack.pack_paths import PACK

FUNCTIONS = PACK / "data" / "pool" / "function"
TESTS = PACK / "data" / "pool" / "test"
SCRATCH = ("pool.tmp", "pool.math", "pool.test")
MENTION = re.compile(r"(?<![\w#$.])([#$][\w.-]+) (pool\.\w+)\b")
MACRO_ARGUMENT = re.compile(r"\$\(\w+\)")


def _code_lines(path):
    return [line for line in path.read_text().splitlines() if line and not line.startswith("#")]


def mentions():
    """(holder, objective, file) for every fake player named in a command of the pack or its tests."""
    for path in sorted(PACK.glob("data/pool/**/*.mcfunction")):
        for line in _code_lines(path):
            for holder, objective in MENTION.findall(line.lstrip("$")):
                yield holder, objective, path


def prefix_table():
    """The README's prefix table: prefix -> owner (`physics/events/`, `math/<name>`, ...)."""
    readme = (PACK / "README.md").read_text()
    section = readme.split("## Naming", 1)[1]
    table = {}
    for row in re.findall(r"^\| (`#.*?) \| `(.*?)`", section, re.M):
        cells, owner = row
        for prefix in re.findall(r"`(#[^`]*)`", cells):
            table[prefix] = owner
    return table


def _holders(target):
    return [target.name] if isinstance(target, ast.NameTarget) else []


def accesses():
    """(holder, objective, "r" | "w", function id) for every fake-player score the pack's functions
    read or write, from the parsed commands (macro lines parsed with a sample argument)."""
    packs = load_packs([PACK])
    for fid, function in packs.functions.items():
        commands = list(function.commands)
        for command in function.commands:
            if isinstance(command, ast.MacroLine):
                parsed, _ = parse_function(MACRO_ARGUMENT.sub("0", command.template), "macro", fid)
                commands += parsed.commands
        nodes = []
        for command in commands:
            walk(command, nodes)
        for node in nodes:
            yield from ((h, o, k, fid) for h, o, k in _node_accesses(node))


def _node_accesses(node):
    if isinstance(node, ast.ScoreSet):
        kinds = "w" if node.action == "set" else "rw"
        yield from ((h, node.objective, k) for h in _holders(node.targets) for k in kinds)
    elif isinstance(node, ast.ScoreReset) and node.objective:
        yield from ((h, node.objective, "w") for h in _holders(node.targets))
    elif isinstance(node, ast.ScoreGet):
        yield from ((h, node.objective, "r") for h in _holders(node.target))
    elif isinstance(node, ast.ScoreOperation):
        kinds = "w" if node.op == "=" else "rw"
        yield from ((h, node.objective, k) for h in _holders(node.targets) for k in kinds)
        kinds = "rw" if node.op == "><" else "r"
        yield from ((h, node.source_objective, k) for h in _holders(node.sources) for k in kinds)
    elif isinstance(node, ast.IfScore):
        yield from ((h, node.objective, "r") for h in _holders(node.target))
        yield from ((h, node.source_objective, "r") for h in _holders(node.source))
    elif isinstance(node, ast.IfScoreMatches):
        yield from ((h, node.objective, "r") for h in _holders(node.target))
    elif isinstance(node, ast.StoreScore):
        yield from ((h, node.objective, "w") for h in _holders(node.targets))


def test_fake_players_are_public_or_private():
    bad = {(h, o) for h, o, _ in mentions() if h[0] not in "#$"}
    assert not bad


def test_private_constants_are_named_by_their_value():
    load = (FUNCTIONS / "load.mcfunction").read_text()
    for name, value in re.findall(r"^scoreboard players set (#\S+) pool\.const (\S+)$", load, re.M):
        assert name == f"#{value}"
    used = {h for h, o, _ in mentions() if o == "pool.const" and h.startswith("#")}
    assert used and all(re.fullmatch(r"#-?\d+", h) for h in used)


def test_every_scratch_holder_has_a_feature_prefix_from_the_readme():
    table = prefix_table()
    assert "#events." in table and "#ball_ball." in table and "#normalize." in table
    unprefixed, unknown = set(), set()
    for holder, objective, path in mentions():
        if objective not in SCRATCH or not holder.startswith("#"):
            continue
        prefix = holder.split(".", 1)[0] + "."
        if "." not in holder:
            unprefixed.add((holder, objective, path.name))
        elif objective == "pool.test":
            if prefix != f"#{path.stem}.":                   # a test's own holders: #<test>.<name>
                unknown.add((holder, objective, path.name))
        elif prefix not in table:
            unknown.add((holder, objective, path.name))
    assert not unprefixed
    assert not unknown


def test_every_prefix_of_the_table_names_an_owner_and_is_used():
    table = prefix_table()
    used = {h.split(".", 1)[0] + "." for h, o, _ in mentions() if o in ("pool.tmp", "pool.math") and h[0] == "#"}
    for prefix, owner in table.items():
        if prefix == "#<test>.":
            continue
        if owner == "math/<name>":
            assert (FUNCTIONS / "math" / f"{prefix[1:-1]}.mcfunction").is_file(), prefix
        else:
            assert (FUNCTIONS / owner).is_dir(), (prefix, owner)
        assert prefix in used, prefix


def test_math_temporaries_belong_to_the_math_library():
    for holder, objective, path in mentions():
        if objective == "pool.math" and holder.startswith("#"):
            assert path.is_relative_to(FUNCTIONS / "math"), (holder, path)


@pytest.fixture(scope="module")
def reads_and_writes():
    found = defaultdict(lambda: {"r": set(), "w": set()})
    for holder, objective, kind, fid in accesses():
        if holder.startswith("#") and objective in ("pool.tmp", "pool.math"):
            found[(holder, objective)][kind].add(fid)
    return found


def test_every_private_holder_read_is_written(reads_and_writes):
    assert len(reads_and_writes) > 100
    never_written = {key: sorted(uses["r"]) for key, uses in reads_and_writes.items() if not uses["w"]}
    assert not never_written


def test_every_private_holder_written_is_read(reads_and_writes):
    never_read = {key for key, uses in reads_and_writes.items() if not uses["r"]}
    assert not never_read
