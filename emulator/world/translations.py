"""A translated text component's text, as a server reads it (``Component.getString``): the key's
en_us string of the release (:func:`mcfunction_parser.gamedata.language`), else its ``fallback``
(1.19.4+), else the key itself, with ``%s`` / ``%N$s`` taking the ``with`` arguments and ``%%`` a
percent sign. A template the game cannot decompose (another conversion, a stray ``%``, an argument
that is not there) reads as written. A ``keybind`` reads as the translation of its key (the server's
KeybindResolver: Component.translatable).

Source: decompiled 1.21 network/chat/contents/TranslatableContents (decompose, decomposeTemplate,
getArgument: FORMAT_PATTERN ``%(?:(\\d+)\\$)?([A-Za-z%]|$)``), KeybindContents; the ``fallback``
field came with 23w03a (1.19.4).
"""
from __future__ import annotations

import re
from typing import Callable

from mcfunction_parser import gamedata

FALLBACK = (1, 19, 4)
_FORMAT = re.compile(r"%(?:(\d+)\$)?([A-Za-z%]|$)")


class _Unformattable(Exception):
    """TranslatableFormatException: the template is shown as it is."""


def translated(component: dict, release, plain: Callable[[object], str]) -> str:
    """The text of a ``translate`` component (its own part, without its ``extra``); ``plain`` reads
    an argument's text. ``release`` None: no game strings (only the fallback and the key)."""
    key = str(component["translate"])
    strings = gamedata.language(tuple(release)) if release is not None else {}
    fallback = component.get("fallback")
    if key in strings:
        template = strings[key]
    elif isinstance(fallback, str) and (release is None or tuple(release) >= FALLBACK):
        template = fallback
    else:
        template = key
    arguments = component.get("with")
    try:
        return _decompose(template, arguments if isinstance(arguments, list) else [], plain)
    except _Unformattable:
        return template


def keybind(component: dict, release) -> str:
    """A ``keybind`` component on a server: the translation of its key (``key.jump`` reads Jump)."""
    return translated({"translate": str(component["keybind"])}, release, str)


def _decompose(template: str, arguments: list, plain: Callable[[object], str]) -> str:
    parts, at, counter = [], 0, 0
    for match in _FORMAT.finditer(template):
        if "%" in template[at:match.start()]:
            raise _Unformattable
        parts.append(template[at:match.start()])
        conversion, written = match.group(2), match.group(0)
        if conversion == "%" and written == "%%":
            parts.append("%")
        elif conversion != "s":
            raise _Unformattable
        else:
            index = int(match.group(1)) - 1 if match.group(1) is not None else counter
            if match.group(1) is None:
                counter += 1
            if not 0 <= index < len(arguments):
                raise _Unformattable
            parts.append(plain(arguments[index]))
        at = match.end()
    if "%" in template[at:]:
        raise _Unformattable
    parts.append(template[at:])
    return "".join(parts)
