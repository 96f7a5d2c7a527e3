"""Building the AST's nodes fast: frozen, slotted dataclasses without the cost of being frozen.

The nodes (and ``Diagnostic``) are frozen, slotted dataclasses: equal and hashed by value, and
never changed once built (:mod:`.relocate` shares a node between commands; the emulator keys caches
by them). Freezing costs on every build: the generated ``__init__`` stores each field with
``object.__setattr__``, and a class with its own ``__setattr__`` makes every attribute store go
through it. The parser builds about ten nodes per command, so :func:`speed_up_inits` releases each
such class of a module:

- its ``__setattr__`` and ``__delattr__`` (which raise ``FrozenInstanceError``) are removed, so
  that a node is immutable by convention: nothing in dpemu assigns to a node's field, and the test
  suite checks it, running with the guard back on (:func:`guard_nodes`);
- ``cls.new(...)``, with the parameters of ``cls(...)``, builds the same object with
  ``object.__new__`` and plain slot stores, the parser's way to build a node (about 30 % faster
  than filling a builder of the same layout and assigning ``__class__``, which a guarded class
  needs, and about twice as fast as calling a frozen class);
- ``__init__`` stores through the slot descriptors (about twice as fast as the generated one,
  guarded or not), and ``__reduce__`` pickles a node as its class and field values
  (``pack.parallel`` sends parsed functions between processes).

``__init__`` and ``new`` are compiled from their source when first used: a run reads a few kinds of
command, and compiling the methods of every node at import was most of the parser's start-up. The
AST declares its nodes with :func:`node` for the same reason: ``@dataclass(frozen=True,
slots=True)`` without the methods dataclasses would compile for each class (about 70 ms for the
hundred classes), their generic equivalents here standing in.

Classes it can't reproduce exactly (``default_factory``, ``init=False`` or keyword-only fields,
``__post_init__``) stay frozen, and their ``new`` is the class itself.
"""
from __future__ import annotations

import dataclasses
import inspect
from operator import attrgetter
from types import MemberDescriptorType

# every class released by speed_up_inits -> its frozen (__setattr__, __delattr__)
_RELEASED: dict[type, tuple] = {}
_GUARDED = [False]
# called with the new state when guard_nodes changes it (relocate forgets the code it generated)
ON_GUARD: list = []


def node(cls: type) -> type:
    """``@dataclass(frozen=True, slots=True)``: the same fields, slots, equality, hash, repr and
    immutability, the methods generic over the class's fields instead of compiled for each; its
    ``__dataclass_params__`` and the docstring of a class without one are those dataclasses gives."""
    documented = bool(cls.__doc__)
    if not documented:  # dataclasses would sign it from an __init__ it does not have yet
        cls.__doc__ = "-"
    # made unfrozen, then frozen by the methods below: dataclasses refuses that on a frozen base
    bases = [b.__dataclass_params__ for b in cls.__mro__[1:] if "__dataclass_params__" in b.__dict__]
    for base in bases:
        base.frozen = False
    try:
        made = dataclasses.dataclass(cls, init=False, repr=False, eq=False, slots=True)
    finally:
        for base in bases:
            base.frozen = True
    params = made.__dataclass_params__
    params.init = params.repr = params.eq = params.frozen = True  # what the methods below give it
    if not documented:
        made.__doc__ = made.__name__ + _text_signature(made)
    names = tuple(f.name for f in dataclasses.fields(made))
    made._values = staticmethod(_values_of(names))
    made.__eq__, made.__hash__, made.__repr__ = _eq, _hash, _repr
    made.__setattr__, made.__delattr__ = _frozen_setattr, _frozen_delattr
    return made


def _text_signature(cls: type) -> str:
    """``str(inspect.signature(cls))`` of the ``__init__`` dataclasses writes (no ``-> None``)."""
    params = [f"{f.name}: {inspect.formatannotation(f.type)}"
              + ("" if f.default is dataclasses.MISSING else f" = {f.default!r}") for f in dataclasses.fields(cls)]
    return f"({', '.join(params)})"


def _values_of(names: tuple):
    """The tuple of a node's field values (what it equals, hashes and pickles as)."""
    if len(names) > 1:
        return attrgetter(*names)
    if names:
        one = attrgetter(names[0])
        return lambda obj: (one(obj),)
    return lambda obj: ()


def _eq(self, other):
    if other.__class__ is self.__class__:
        return self._values(self) == other._values(other)
    return NotImplemented


def _hash(self):
    return hash(self._values(self))


def _repr(self):
    values = ", ".join(f"{f.name}={getattr(self, f.name)!r}" for f in dataclasses.fields(self))
    return f"{type(self).__qualname__}({values})"


def _frozen_setattr(self, name, value):
    raise dataclasses.FrozenInstanceError(f"cannot assign to field {name!r}")


def _frozen_delattr(self, name):
    raise dataclasses.FrozenInstanceError(f"cannot delete field {name!r}")


def is_frozen(cls: type) -> bool:
    """Whether ``cls`` is a frozen dataclass (a :func:`node`, or declared ``frozen=True``)."""
    return dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen


class _Lazy:
    """A method of ``cls`` compiled on first use: the first look-up builds it with ``make(cls)``,
    puts it on the class in this descriptor's place and hands it out."""

    __slots__ = ("cls", "name", "make")

    def __init__(self, cls: type, name: str, make) -> None:
        self.cls, self.name, self.make = cls, name, make

    def __get__(self, obj, owner=None):
        made = self.make(self.cls)
        type.__setattr__(self.cls, self.name, made)
        return self.cls.__dict__[self.name].__get__(obj, owner)


def speed_up_inits(namespace: dict) -> None:
    """Release every eligible dataclass defined in the module ``namespace`` (its globals())."""
    module = namespace["__name__"]
    for obj in list(namespace.values()):
        if isinstance(obj, type) and obj.__module__ == module and dataclasses.is_dataclass(obj):
            if _signature(obj, {}) is None:
                obj.new = obj
                continue
            obj.__init__ = _Lazy(obj, "__init__", _fast_init)
            if "_values" not in obj.__dict__:
                obj._values = staticmethod(_values_of(tuple(f.name for f in dataclasses.fields(obj))))
            obj.__reduce__ = _reduce
            _RELEASED[obj] = (obj.__dict__["__setattr__"], obj.__dict__["__delattr__"])
            _set_guard(obj, _GUARDED[0])


def guard_nodes(on: bool = True) -> None:
    """Put the frozen ``__setattr__``/``__delattr__`` back on every released class (assigning to a
    node's field raises ``FrozenInstanceError`` again), or take them off again with ``on=False``.
    The test suite runs guarded; ``new`` then builds through a builder class (see :func:`_factory`)."""
    if _GUARDED[0] is on:
        return
    _GUARDED[0] = on
    for cls in _RELEASED:
        _set_guard(cls, on)
    for hook in ON_GUARD:
        hook(on)


def is_guarded() -> bool:
    return _GUARDED[0]


def _set_guard(cls: type, on: bool) -> None:
    if on:
        cls.__setattr__, cls.__delattr__ = _RELEASED[cls]
    elif "__setattr__" in cls.__dict__:
        del cls.__setattr__, cls.__delattr__
    cls.new = _Lazy(cls, "new", _factory)  # written for the guard as it is when first used


def _signature(cls: type, namespace: dict) -> list[str] | None:
    """The parameters of ``cls``'s ``__init__`` (defaults put in ``namespace``), None if the
    fields are not all plain slots set from positional-or-keyword parameters."""
    if not is_frozen(cls) or "__slots__" not in cls.__dict__ or hasattr(cls, "__post_init__"):
        return None
    signature = []
    for i, f in enumerate(dataclasses.fields(cls)):
        if (not f.init or f.kw_only or f.default_factory is not dataclasses.MISSING
                or type(getattr(cls, f.name, None)) is not MemberDescriptorType):
            return None
        if f.default is dataclasses.MISSING:
            signature.append(f.name)
        else:
            namespace[f"_default{i}"] = f.default
            signature.append(f"{f.name}=_default{i}")
    return signature


def _fast_init(cls: type):
    namespace: dict = {}
    signature = _signature(cls, namespace)
    body = []
    for i, f in enumerate(dataclasses.fields(cls)):
        namespace[f"_set{i}"] = getattr(cls, f.name).__set__
        body.append(f"    _set{i}(self, {f.name})\n")
    source = f"def __init__(self, {', '.join(signature)}):\n{''.join(body) or '    pass'}\n"
    exec(source, namespace)  # noqa: S102  (the source is built from the field names above)
    init = namespace["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    return init


def builder(cls: type) -> type:
    """The class whose instances are filled by plain attribute stores before becoming ``cls``:
    ``cls`` itself when released, else a class of the same layout (the same base and slots) without
    the frozen ``__setattr__``, whose instance then takes ``cls`` as its ``__class__`` (which Python
    allows between classes of one layout)."""
    if cls.__dict__.get("__setattr__") is None:
        return cls
    made = cls.__dict__.get("_builder")
    if made is None or made.__dict__.get("_of") is not cls:
        made = type(f"{cls.__name__}Builder", (cls.__base__,), {
            "__slots__": cls.__dict__["__slots__"], "__init__": object.__init__, "_of": cls,
            "__setattr__": object.__setattr__, "__delattr__": object.__delattr__})
        type.__setattr__(cls, "_builder", made)
    return made


def build_lines(cls: type, values: list[str], indent: str = "    ") -> list[str]:
    """Source lines building ``cls`` from the expressions ``values`` (one per field) into ``self``,
    with ``_new`` = ``object.__new__`` and ``B`` = :func:`builder` (``cls``) in the namespace."""
    lines = [f"{indent}self = _new(B)"]
    lines += [f"{indent}self.{f.name} = {v}" for f, v in zip(dataclasses.fields(cls), values)]
    if builder(cls) is not cls:
        lines.append(f"{indent}self.__class__ = cls")
    return lines


def _factory(cls: type):
    """``cls.new``: ``cls(...)`` built by plain slot stores (see the module's docs), for the guard
    as it is now."""
    namespace: dict = {"cls": cls, "_new": object.__new__, "B": builder(cls)}
    signature = _signature(cls, namespace)
    body = build_lines(cls, [f.name for f in dataclasses.fields(cls)])
    source = f"def new({', '.join(signature)}):\n" + "\n".join(body) + "\n    return self\n"
    exec(source, namespace)  # noqa: S102  (the source is built from the field names)
    new = namespace["new"]
    new.__qualname__ = f"{cls.__qualname__}.new"
    return staticmethod(new)


def _reduce(self):
    """``__reduce__`` as the class and the field values (the default goes through the generated
    ``__getstate__`` and ``__setstate__``: about three times slower to pickle, and to unpickle)."""
    return type(self), self._values(self)
