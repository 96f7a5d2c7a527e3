"""The data-driven resources of the loaded packs that commands read: loot tables, item modifiers
and item tags.

``Resources.from_packs(packs)`` takes them from :func:`mcfunction_parser.load_packs`' result
(only files that decoded: the game skips the others); ``Resources()`` is an empty world. ``random`` is the seeded source loot rolls and dropped items draw from (seed 0;
not the game's own random sequence). ``item_tag(tag_id)`` is the one place an item tag is resolved: the packs' own
``tags/item`` files (nested tags flattened, ``replace`` honoured); the game's vanilla item tags
are not shipped, so using one no pack defines fails the command saying so (never a silent miss).
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field

from mcfunction_parser.ast import FunctionTag
from mcfunction_parser.pack.tags import resolve_tag
from emulator.world.errors import CommandFailure


class _AnyItem:
    """Every item id exists (the item registry is not modelled)."""

    def __contains__(self, item_id) -> bool:
        return True


@dataclass
class Resources:
    loot_tables: dict = field(default_factory=dict)  # id -> JSON value
    item_modifiers: dict = field(default_factory=dict)
    item_tags: dict[str, FunctionTag] = field(default_factory=dict)
    paths: dict[str, str] = field(default_factory=dict)  # "loot_table ns:id" -> the file, for messages
    random: random.Random = field(default_factory=lambda: random.Random(0))  # loot rolls, dropped items
    _resolved: dict[str, frozenset[str]] = field(default_factory=dict, repr=False)

    @classmethod
    def from_packs(cls, packs) -> "Resources":
        tables, modifiers = getattr(packs, "loot_tables", {}), getattr(packs, "item_modifiers", {})
        found = cls({k: d.value for k, d in tables.items()},
                    {k: d.value for k, d in modifiers.items()}, dict(getattr(packs, "item_tags", {})))
        for kind, docs in (("loot_table", tables), ("item_modifier", modifiers)):
            found.paths.update((f"{kind} {k}", d.path) for k, d in docs.items())
        return found

    def item_tag(self, tag_id: str) -> frozenset[str]:
        """The tag's items. A tag no pack defines fails the command with a diagnostic: the game's
        own tags are not shipped, and the game refuses a function naming an unknown tag."""
        tag_id = tag_id.removeprefix("#")
        if tag_id not in self.item_tags:
            if tag_id.startswith("minecraft:"):
                raise CommandFailure("dpemu.unsupported", f"the game's item tag #{tag_id}", report=True)
            raise CommandFailure("arguments.item.tag.unknown", tag_id, report=True)
        members = self._resolved.get(tag_id)
        if members is None:
            members = self._resolved[tag_id] = frozenset(resolve_tag(self.item_tags, _AnyItem(), tag_id))
        return members
