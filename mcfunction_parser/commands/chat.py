"""``say`` and ``tellraw``."""
from __future__ import annotations

import re

from .. import ast
from ..arguments import text_component
from ..reader import Reader
from ..selectors import AT_N, selector, target

# MessageArgument parses a selector wherever '@' is followed by a selector letter.
_MESSAGE_SELECTOR = re.compile(r"@[spaern]")
_MESSAGE_SELECTOR_OLD = re.compile(r"@[spaer]")  # before @n existed


def say(r: Reader, loc) -> ast.Command:
    r.space("message")
    start = r.pos
    message(r)
    return ast.Say.new(loc, r.text[start:])


def message(r: Reader) -> None:
    """A MessageArgument: the rest of the command, its selectors parsed."""
    start = r.pos
    text = r.text
    pattern = _MESSAGE_SELECTOR if r.version >= AT_N else _MESSAGE_SELECTOR_OLD
    for m in pattern.finditer(text, start):
        if m.start() < r.pos:
            continue
        r.pos = m.start()
        selector(r)
    r.pos = r.end


def tellraw(r: Reader, loc) -> ast.Command:
    r.space("players")
    who = target(r, players=True)
    r.space("text component")
    component = text_component(r)
    r.finish()
    return ast.Tellraw.new(loc, who, component)


PARSERS = {"say": say, "tellraw": tellraw}
