"""The packs' data-driven resources a running world reads (the game's ReloadableServerResources):
loot tables, item modifiers, predicates, advancements, recipes and registry tags, from :class:`LoadedPacks`.

- ``Resources.from_packs(packs)`` (only files that load: the game skips the others);
  ``Resources()`` is an empty world's (only the built-in vanilla tags,
  :data:`mcfunction_parser.gamedata.vanilla_tags.BUILTIN_TAGS`).
- ``random``: the seeded source loot rolls and dropped items draw from (seed 0; not the game's own
  random sequence).
- ``tag(registry, tag_id)``: the flattened :class:`RegistryTag`, or None when no such tag loaded.
- ``in_tag(registry, tag_id, value)``: membership; ``item_tag(tag_id)``: an item tag's members.
  ``tag_members(registry, tag_id)``: a tag's members, none for an unknown tag.
  A ``#minecraft:`` tag the emulator does not know (no game jar given) raises
  :class:`~emulator.world.errors.Unmodelled` unless ``value`` is among its known members, never a
  silent "no".
- ``recipes``: recipe id -> type (the packs', and the game's from its jar); see
  :mod:`emulator.world.recipes`; ``recipe_bodies``: id -> JSON of those that decode
  (:mod:`emulator.world.crafting` matches them).
- ``enchantments``: enchantment id -> JSON, the packs' definitions that load (see
  :mod:`emulator.world.enchanting`).
- ``loot_table(table_id)``: a loaded table; None for one that does not exist. A ``minecraft:``
  table without the game's data raises Unmodelled naming ``--game-jar``.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Any, Callable

from emulator.world import structures
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.gamedata.vanilla_tags import BUILTIN_TAGS
from mcfunction_parser.pack.registry_tags import RegistryTag


_READ_ENCHANTMENTS = ("unbreaking",)  # the enchantments whose effects the emulator carries out


# the game's block loot tables that drop nothing, known without its data: VanillaBlockLoot's noDrop()
# (spawners, fire, portals ...) and the blocks whose properties say noLootTable() (decompiled 1.21,
# data/loot/packs/VanillaBlockLoot.generate, world/level/block/Blocks)
EMPTY_BLOCK_TABLES = frozenset("minecraft:blocks/" + name for name in (
    "cake frosted_ice spawner trial_spawner vault fire soul_fire nether_portal budding_amethyst powder_snow frogspawn "
    "reinforced_deepslate suspicious_sand suspicious_gravel "
    "air cave_air void_air water lava bubble_column barrier bedrock light structure_void structure_block jigsaw "
    "command_block chain_command_block repeating_command_block end_gateway end_portal end_portal_frame moving_piston "
    "piston_head").split())

@dataclass
class Resources:
    loot_tables: dict = field(default_factory=dict)  # id -> JSON value
    item_modifiers: dict = field(default_factory=dict)
    paths: dict[str, str] = field(default_factory=dict)  # "loot_table ns:id" -> the file, for messages
    predicates: dict[str, Any] = field(default_factory=dict)  # id -> JSON value
    advancements: dict[str, Any] = field(default_factory=dict)
    recipes: dict[str, str] = field(default_factory=dict)  # id -> its type
    recipe_bodies: dict[str, Any] = field(default_factory=dict)  # id -> its JSON (the recipes that decode)
    tags: dict[str, dict[str, RegistryTag]] = field(default_factory=dict)  # registry -> tag id -> tag
    vanilla_data: bool = False  # the game's own tags and loot tables were loaded (from its jar)
    random: random.Random = field(default_factory=lambda: random.Random(0))  # loot rolls, dropped items
    redefined_enchantments: frozenset = frozenset()  # vanilla enchantments a pack's file redefines
    enchantments: dict[str, Any] = field(default_factory=dict)  # id -> JSON (the packs' files that load)
    # a structure template's file from the packs (``place template``), None when no pack has it
    template_file: Callable[[str], bytes | None] = lambda template_id: None

    @classmethod
    def from_packs(cls, packs) -> "Resources":
        tables, modifiers = packs.loot_tables, packs.item_modifiers
        found = cls({k: d.value for k, d in tables.items()}, {k: d.value for k, d in modifiers.items()},
                    predicates=dict(packs.predicates), advancements=dict(packs.advancements),
                    recipes=dict(packs.recipes), recipe_bodies=dict(packs.recipe_bodies),
                    tags={registry: dict(tags) for registry, tags in packs.registry_tags.items()},
                    vanilla_data=packs.vanilla_data, enchantments=dict(packs.enchantments))
        found.redefined_enchantments = frozenset(
            f"minecraft:{e}" for e in _READ_ENCHANTMENTS if packs.read_file(f"data/minecraft/enchantment/{e}.json"))
        found.template_file = lambda template_id: structures.find_template(packs, template_id)
        for kind, docs in (("loot_table", tables), ("item_modifier", modifiers)):
            found.paths.update((f"{kind} {k}", d.path) for k, d in docs.items())
        return found

    def tag(self, registry: str, tag_id: str) -> RegistryTag | None:
        found = self.tags.get(registry, {}).get(tag_id)
        if found is None and not self.vanilla_data and tag_id in BUILTIN_TAGS.get(registry, {}):
            return RegistryTag(BUILTIN_TAGS[registry][tag_id])
        return found

    def in_tag(self, registry: str, tag_id: str, value: str) -> bool:
        tag = self.tag(registry, tag_id)
        if tag is not None and value in tag.members:
            return True
        self._known(registry, tag_id, tag)
        return False

    def loot_table(self, table_id: str) -> dict | None:
        """A loot table by id; a vanilla one unknown without the game's data is not modelled, but for
        the blocks known to drop nothing (:data:`EMPTY_BLOCK_TABLES`)."""
        table = self.loot_tables.get(table_id)
        if table is None and not self.vanilla_data and table_id in EMPTY_BLOCK_TABLES:
            return {}
        if table is None and table_id.startswith("minecraft:") and not self.vanilla_data:
            raise Unmodelled(f"the game's own loot table {table_id} is not known without the game's data "
                             "(pass --game-jar)")
        return table

    def item_tag(self, tag_id: str) -> frozenset[str]:
        """The members of item tag ``tag_id`` (``#`` optional). A tag no pack defines fails the
        command, as the game refuses a function naming an unknown tag (a vanilla one the emulator
        does not know is not modelled)."""
        tag_id = tag_id.removeprefix("#")
        tag = self.tag("item", tag_id)
        self._known("item", tag_id, tag)
        if tag is None:
            raise CommandFailure("arguments.item.tag.unknown", tag_id, report=True)
        return tag.members

    def tag_members(self, registry: str, tag_id: str) -> frozenset[str]:
        """The members of a tag of ``registry`` (none for a tag no pack defines); a vanilla tag
        the emulator does not know is not modelled."""
        tag = self.tag(registry, tag_id)
        self._known(registry, tag_id, tag)
        return tag.members if tag is not None else frozenset()

    def _known(self, registry: str, tag_id: str, tag: RegistryTag | None) -> None:
        unknown = tag.unknown if tag is not None else (
            (tag_id,) if tag_id.startswith("minecraft:") and not self.vanilla_data else ())
        if unknown:
            raise Unmodelled(f"the vanilla {registry} tag #{unknown[0]} is not known without the game's data "
                             "(pass --game-jar)")
