"""Released frozen dataclasses (frozen_init) build the same objects as the generated ``__init__``:
equal and hashed by value; their fields raise FrozenInstanceError when assigned while guarded, as
the whole suite runs (tests/conftest.py), so no code path of dpemu's that the tests reach assigns
to a node; released (as dpemu runs), ``new`` builds them by plain stores."""
from __future__ import annotations

import dataclasses
import inspect
import pickle

import pytest

from mcfunction_parser import ast, diagnostics
from mcfunction_parser import frozen_init
from mcfunction_parser.frozen_init import guard_nodes, is_guarded, speed_up_inits
from mcfunction_parser.parse import forget_read_lines, parse_function


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


@pytest.fixture
def released():
    """The nodes as dpemu runs them (unguarded) inside the test, guarded again after it."""
    guard_nodes(False)
    forget_read_lines()
    try:
        yield
    finally:
        guard_nodes(True)
        forget_read_lines()


def test_the_suite_runs_guarded():
    assert is_guarded()
    assert "__setattr__" in ast.ScoreSet.__dict__ and "__setattr__" in diagnostics.Diagnostic.__dict__


def test_released_classes_drop_the_guard_and_keep_value_semantics(released):
    for cls in frozen_init._RELEASED:
        assert "__setattr__" not in cls.__dict__ and "__delattr__" not in cls.__dict__, cls.__name__
        assert cls.new is not cls
    loc = diagnostics.Loc("f", 1, 2)
    node = ast.ScoreSet.new(loc, "set", ast.NameTarget.new("#a", loc), "obj", 3)
    assert type(node) is ast.ScoreSet and node == ast.ScoreSet(loc, "set", ast.NameTarget("#a", loc), "obj", 3)
    assert hash(node) == hash(ast.ScoreSet(loc, "set", ast.NameTarget("#a", loc), "obj", 3))
    assert node.targets.is_uuid is False and pickle.loads(pickle.dumps(node)) == node
    assert not hasattr(node, "__dict__")  # still slotted: no field can be added by mistake
    with pytest.raises(AttributeError):
        node.other = 1
    guard_nodes(True)
    with pytest.raises(dataclasses.FrozenInstanceError):
        node.value = 4
    with pytest.raises(dataclasses.FrozenInstanceError):
        del node.value


def test_parses_and_relocations_build_equal_nodes_guarded_or_not():
    """relocate writes ``new`` out for each way of building: a function with repeated lines (relocated)
    parses to the same nodes either way, and each relocated command equals its fresh parse."""
    lines = ["execute as @e[tag=a] at @s if score @s x matches 1.. run tp @s ~ ~1 ~",
             "scoreboard players operation @s a += #b c", "kill @e[type=zombie,distance=..5]"]
    source = "\n".join(lines * 3) + "\n  " + lines[0] + "\n"

    def parse():
        forget_read_lines()
        function, diags = parse_function(source, "f.mcfunction", "t:f", (1, 21, 0))
        assert not diags
        return function.commands

    guarded = parse()
    guard_nodes(False)
    try:
        released = parse()
    finally:
        guard_nodes(True)
        forget_read_lines()
    assert released == guarded and len(guarded) == 10
    for cmd in guarded[3:]:  # relocated: equal to the same text read afresh at that place
        forget_read_lines()
        text = source.split("\n")[cmd.loc.line - 1]
        alone, _ = parse_function("\n" * (cmd.loc.line - 1) + text + "\n", "f.mcfunction", "t:f", (1, 21, 0))
        assert alone.commands[0] == cmd


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


def _twin(cls):
    """The class ``@dataclass(frozen=True, slots=True)`` makes of ``cls``'s fields (flattened)."""
    fields = dataclasses.fields(cls)
    namespace = {"__annotations__": {f.name: f.type for f in fields}, "__qualname__": cls.__qualname__,
                 **{f.name: f.default for f in fields if f.default is not dataclasses.MISSING}}
    return dataclasses.dataclass(frozen=True, slots=True)(type(cls.__name__, (), namespace))


@pytest.mark.parametrize("module", [ast, diagnostics])
def test_nodes_behave_as_the_dataclasses_they_are_declared_as(module):
    """``frozen_init.node`` compiles no method per class; what it gives each node matches what
    ``@dataclass(frozen=True, slots=True)`` makes of the same fields: the parameters (frozen, with
    ``__init__``, ``__repr__`` and ``__eq__``), ``__match_args__``, the signed docstring of a class
    without one (``help()``), ``repr``, ``hash`` and equality (same class only)."""
    nodes = [c for c in _module_dataclasses(module) if c.__dataclass_params__.frozen]
    assert len(nodes) >= (90 if module is ast else 1) and all(frozen_init.is_frozen(c) for c in nodes)
    names = ("init", "repr", "eq", "order", "unsafe_hash", "frozen")
    for cls in nodes:
        twin = _twin(cls)
        assert [getattr(cls.__dataclass_params__, n) for n in names] == \
            [getattr(twin.__dataclass_params__, n) for n in names], cls.__name__
        assert cls.__match_args__ == twin.__match_args__, cls.__name__
        if cls.__doc__.startswith(cls.__name__ + "("):  # no docstring: signed as dataclasses signs it
            assert cls.__doc__ == twin.__doc__
        values = [(i, f"v{i}") for i, _ in enumerate(dataclasses.fields(cls))]
        other = [(i, "w") for i, _ in enumerate(dataclasses.fields(cls))]
        made, twin_made = cls(*values), twin(*values)
        assert repr(made) == repr(twin_made) and hash(made) == hash(twin_made), cls.__name__
        assert made == cls(*values) and (made != cls(*other)) == bool(values)
        assert made.__eq__(twin_made) is NotImplemented and made != twin_made
