import pytest

from mcfunction_parser.ast import PathAll, PathFilter, PathIndex, PathKey, PathMatch
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt_path import nbt_path
from mcfunction_parser.reader import ParseError, Reader


def path(text: str):
    r = Reader(text, Loc("t", 1, 1), (1, 21, 0))
    result = nbt_path(r)
    assert r.pos == len(text)
    assert result.text == text
    return result.nodes


def test_nodes():
    nodes = path('a.b[0].c[-1][]."quoted key"{y:2}[{x:1b}].z')
    kinds = [type(n) for n in nodes]
    assert kinds == [PathKey, PathKey, PathIndex, PathKey, PathIndex, PathAll, PathKey, PathFilter, PathMatch, PathKey]
    assert nodes[2].index == 0 and nodes[4].index == -1 and nodes[6].name == "quoted key"
    assert nodes[7].pattern == {"y": 2} and nodes[8].pattern == {"x": 1}


def test_root_compound():
    nodes = path("{a:1}.b")
    assert type(nodes[0]) is PathFilter and nodes[1].name == "b"
    assert type(path("{a:1}")[0]) is PathFilter


def test_unusual_key_characters():
    assert path("a-b:c+d")[0].name == "a-b:c+d"


@pytest.mark.parametrize("text", ["a..b", "a.", "a[x]", "a[0]{b:1}", "a[{x:1}]{y:2}", "{a:1}{b:1}", "a.{b:1}", "[0",
                                  "{a:1}b"])
def test_invalid_paths(text):
    with pytest.raises(ParseError):
        path(text)
