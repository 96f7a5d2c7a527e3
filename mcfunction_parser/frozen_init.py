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


def _fast_init(cls: type):
    params = cls.__dataclass_params__
    if not params.frozen or "__slots__" not in cls.__dict__ or hasattr(cls, "__post_init__"):
        return None
    fields = dataclasses.fields(cls)
    namespace: dict = {}
    signature = []
    body = []
    for i, f in enumerate(fields):
        slot = getattr(cls, f.name, None)
        if (not f.init or f.kw_only or f.default_factory is not dataclasses.MISSING
                or type(slot) is not MemberDescriptorType):
            return None
        namespace[f"_set{i}"] = slot.__set__
        if f.default is dataclasses.MISSING:
            signature.append(f.name)
        else:
            namespace[f"_default{i}"] = f.default
            signature.append(f"{f.name}=_default{i}")
        body.append(f"    _set{i}(self, {f.name})\n")
    source = f"def __init__(self, {', '.join(signature)}):\n{''.join(body) or '    pass'}\n"
    exec(source, namespace)  # noqa: S102  (the source is built from the field names above)
    init = namespace["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    init.__doc__ = cls.__init__.__doc__
    return init


def _reduce(cls: type):
    """``__reduce__`` as the class and the field values (the default goes through the generated
    ``__getstate__`` and ``__setstate__``: about three times slower to pickle, and to unpickle)."""
    values = "".join(f"self.{f.name}, " for f in dataclasses.fields(cls))
    namespace: dict = {}
    exec(f"def __reduce__(self):\n    return (type(self), ({values}))\n", namespace)  # noqa: S102
    reduce = namespace["__reduce__"]
    reduce.__qualname__ = f"{cls.__qualname__}.__reduce__"
    return reduce
