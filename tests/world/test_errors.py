"""The game's message texts the emulator fails commands with."""
from __future__ import annotations

import re

from emulator.world.errors import MESSAGES
from mcfunction_parser import gamedata

REFERENCE = (1, 21, 4)  # the release whose wording MESSAGES keeps


def _as_format(text: str) -> str:
    """A Java translation template (%s, %2$s, %%) as the str.format template MESSAGES holds."""
    counter = iter(range(99))
    return re.sub(r"%(?:(\d+)\$)?([s%])", lambda m: "%" if m.group(0) == "%%" else
                  "{%d}" % (int(m.group(1)) - 1 if m.group(1) else next(counter)), text)


def test_messages_are_the_games_en_us_texts():
    # each key as 1.21.4's en_us.json words it, or as the first shipped release that has it does
    # (the stopwatch keys came with 1.21.11, the world clock ones with 26.1)
    releases = sorted(r for r in gamedata._index()["languages"] if r >= REFERENCE)
    wrong = {}
    for key, text in MESSAGES.items():
        found = next((gamedata.language(r)[key] for r in releases if key in gamedata.language(r)), None)
        if found is None or _as_format(found) != text:
            wrong[key] = (text, found)
    assert wrong == {}
