"""The fast __init__ of frozen dataclasses builds the same objects as the generated one."""
from __future__ import annotations

import dataclasses
import inspect
import pickle

import pytest

from mcfunction_parser import ast, diagnostics
from mcfunction_parser.frozen_init import speed_up_inits


def _module_dataclasses(module):
    return [c for c in vars(module).values()
            if isinstance(c, type) and c.__module__ == module.__name__ and dataclasses.is_dataclass(c)]


@dataclasses.dataclass(frozen=True, slots=True)
class _Base:
    a: int
    b: str = "b"


@dataclasses.dataclass(frozen=True, slots=True)
class _Child(_Base):
    c: tuple = ()


@dataclasses.dataclass(frozen=True, slots=True)
class _WithFactory:
    items: list = dataclasses.field(default_factory=list)


@dataclasses.dataclass(slots=True)
class _Mutable:
    a: int


def test_patched_classes_build_equal_frozen_objects():
    generated = {cls: cls.__init__ for cls in (_Base, _Child, _WithFactory, _Mutable)}
    speed_up_inits(globals())
    assert _Base.__init__ is not generated[_Base] and _Child.__init__ is not generated[_Child]
    # what the fast init can't reproduce keeps the generated one
    assert _WithFactory.__init__ is generated[_WithFactory] and _Mutable.__init__ is generated[_Mutable]
    child = _Child(1, c=(2,))
    assert (child.a, child.b, child.c) == (1, "b", (2,))
    assert child == _Child(a=1, b="b", c=(2,)) and hash(child) == hash(_Child(1, "b", (2,)))
    with pytest.raises(dataclasses.FrozenInstanceError):
        child.a = 2
    with pytest.raises(TypeError):
        _Child()  # a is required
    with pytest.raises(TypeError):
        _Base(1, "x", "extra")


@pytest.mark.parametrize("module", [ast, diagnostics])
def test_every_node_keeps_its_parameters(module):
    for cls in _module_dataclasses(module):
        if any(f.default_factory is not dataclasses.MISSING for f in dataclasses.fields(cls)):
            continue  # keeps the generated __init__ (checked above)
        expected = [(f.name, f.default) for f in dataclasses.fields(cls) if f.init and not f.kw_only]
        parameters = list(inspect.signature(cls.__init__).parameters.values())[1:]
        actual = [(p.name, dataclasses.MISSING if p.default is p.empty else p.default) for p in parameters]
        assert actual == expected, cls.__name__


def test_ast_nodes_are_still_frozen_and_equal_by_value():
    loc = diagnostics.Loc("f", 1, 2)
    assert loc == diagnostics.Loc(path="f", line=1, col=2) and str(loc) == "f:1:2"
    node = ast.ScoreSet(loc, "set", ast.NameTarget("#a", loc), "obj", 3)
    assert node.value == 3 and node.targets.is_uuid is False  # a default filled in
    with pytest.raises(dataclasses.FrozenInstanceError):
        node.value = 4
    with pytest.raises(AttributeError):  # a named tuple's fields are read-only
        loc.col = 1


def test_new_builds_the_object_the_class_builds():
    speed_up_inits(globals())
    child = _Child.new(1, c=(2,))
    assert type(child) is _Child and child == _Child(1, "b", (2,)) and hash(child) == hash(_Child(1, c=(2,)))
    with pytest.raises(dataclasses.FrozenInstanceError):
        child.a = 2
    with pytest.raises(TypeError):
        _Child.new()  # a is required
    assert _WithFactory.new is _WithFactory  # no fast __init__: new is the class itself
    loc = diagnostics.Loc.new("f", 1, 2)
    assert type(loc) is diagnostics.Loc and loc == diagnostics.Loc("f", 1, 2) and str(loc) == "f:1:2"
    assert type(diagnostics.new_loc(("f", 1, 2))) is diagnostics.Loc and diagnostics.new_loc(("f", 1, 2)) == loc
    assert (loc.path, loc.line, loc.col) == ("f", 1, 2) and pickle.loads(pickle.dumps(loc)) == loc
    with pytest.raises(AttributeError):
        loc.col = 3
    node = ast.ScoreSet.new(loc, "set", ast.NameTarget.new("#a", loc), "obj", 3)
    assert type(node) is ast.ScoreSet and node == ast.ScoreSet(loc, "set", ast.NameTarget("#a", loc), "obj", 3)
    assert node.targets.is_uuid is False and pickle.loads(pickle.dumps(node)) == node


@pytest.mark.parametrize("module", [ast, diagnostics])
def test_every_node_has_new_with_its_parameters(module):
    for cls in _module_dataclasses(module):
        assert "new" in cls.__dict__, cls.__name__  # its own: a subclass must not build its base
        if cls.new is cls:
            continue
        parameters = [(p.name, p.default) for p in inspect.signature(cls.new).parameters.values()]
        assert parameters == [(p.name, p.default) for p in inspect.signature(cls.__init__).parameters.values()][1:]
        values = [object() for _ in dataclasses.fields(cls)]
        built, made = cls.new(*values), cls(*values)
        assert type(built) is cls and all(getattr(built, f.name) is getattr(made, f.name)
                                          for f in dataclasses.fields(cls)), cls.__name__


def test_patched_classes_pickle_as_their_fields():
    loc = diagnostics.Loc("f", 1, 2)
    selector = ast.Selector("e", (ast.SelectorArg("tag", "a", False, loc),), loc)
    node = ast.Execute(loc, (ast.ExAs(loc, selector),), ast.Say(loc, "hi"))
    assert node.__reduce__() == (ast.Execute, (loc, node.subcommands, node.run))
    copy = pickle.loads(pickle.dumps(node))
    assert copy == node and copy.run.loc is copy.loc  # one object pickled once stays one
    speed_up_inits(globals())
    assert pickle.loads(pickle.dumps(_Child(1, c=(2,)))) == _Child(1, "b", (2,))
    assert _WithFactory.__reduce__ is object.__reduce__  # no fast __init__: pickled as before
