"""A faster ``__init__`` for frozen, slotted dataclasses (the AST nodes and ``Loc``).

The ``__init__`` that ``@dataclass(frozen=True)`` generates stores each field with
``object.__setattr__(self, "name", value)``, a generic call that looks the attribute up by name.
The parser builds about ten such objects per command, so it spends a good part of its time there.
:func:`speed_up_inits` gives each frozen, slotted dataclass of a module an ``__init__`` with the
same parameters and defaults that stores through the slot descriptors instead: about twice as fast,
the same objects (assigning to a field afterwards still raises ``FrozenInstanceError``).
Classes it can't reproduce exactly (``default_factory``, ``init=False`` or keyword-only fields,
``__post_init__``) keep the generated one. The classes it speeds up also pickle as their class and
field values, so unpickling builds them with that ``__init__`` too (pack.parallel sends parsed
functions between processes).

Calling a class still costs its call machinery and one slot-descriptor call per field (each packs
its arguments in a tuple). The parser's hot paths build nodes with ``cls.new(...)`` instead, with the
same parameters: it fills a *builder*, a class of the same layout (the same base and slots) whose
attributes are set the plain way, then turns it into ``cls`` by assigning ``__class__`` (which
Python allows between classes of one layout): about twice as fast again, and the same object
``cls(...)`` would give. ``new`` is the class itself where the fast ``__init__`` does not apply.
"""
from __future__ import annotations

import dataclasses
from types import MemberDescriptorType


def speed_up_inits(namespace: dict) -> None:
    """Replace ``__init__`` of every eligible dataclass defined in the module ``namespace`` (its globals())."""
    module = namespace["__name__"]
    for obj in list(namespace.values()):
        if isinstance(obj, type) and obj.__module__ == module and dataclasses.is_dataclass(obj):
            init = _fast_init(obj)
            if init is not None:
                obj.__init__ = init
                obj.__reduce__ = _reduce(obj)
            obj.new = obj if init is None else _factory(obj)


def _signature(cls: type, namespace: dict) -> list[str] | None:
    """The parameters of ``cls``'s ``__init__`` (defaults put in ``namespace``), None if the
    fields are not all plain slots set from positional-or-keyword parameters."""
    params = cls.__dataclass_params__
    if not params.frozen or "__slots__" not in cls.__dict__ or hasattr(cls, "__post_init__"):
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
    if signature is None:
        return None
    body = []
    for i, f in enumerate(dataclasses.fields(cls)):
        namespace[f"_set{i}"] = getattr(cls, f.name).__set__
        body.append(f"    _set{i}(self, {f.name})\n")
    source = f"def __init__(self, {', '.join(signature)}):\n{''.join(body) or '    pass'}\n"
    exec(source, namespace)  # noqa: S102  (the source is built from the field names above)
    init = namespace["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    init.__doc__ = cls.__init__.__doc__
    return init


def _factory(cls: type):
    """``cls.new``: ``cls(...)`` built through a builder of the same layout (see the module's docs)."""
    namespace: dict = {"cls": cls}
    signature = _signature(cls, namespace)
    namespace["_Builder"] = type(f"{cls.__name__}Builder", (cls.__base__,), {
        "__slots__": cls.__dict__["__slots__"], "__init__": object.__init__,
        # both plain: Python then sets attributes through the slots directly
        "__setattr__": object.__setattr__, "__delattr__": object.__delattr__})
    body = "".join(f"    self.{f.name} = {f.name}\n" for f in dataclasses.fields(cls))
    source = f"def new({', '.join(signature)}):\n    self = _Builder()\n{body}    self.__class__ = cls\n    return self\n"
    exec(source, namespace)  # noqa: S102  (the source is built from the field names)
    new = namespace["new"]
    new.__qualname__ = f"{cls.__qualname__}.new"
    new.builder = namespace["_Builder"]  # for code that writes ``new`` out (relocate)
    return staticmethod(new)


def _reduce(cls: type):
    """``__reduce__`` as the class and the field values (the default goes through the generated
    ``__getstate__`` and ``__setstate__``: about three times slower to pickle, and to unpickle)."""
    values = "".join(f"self.{f.name}, " for f in dataclasses.fields(cls))
    namespace: dict = {}
    exec(f"def __reduce__(self):\n    return (type(self), ({values}))\n", namespace)  # noqa: S102
    reduce = namespace["__reduce__"]
    reduce.__qualname__ = f"{cls.__qualname__}.__reduce__"
    return reduce
