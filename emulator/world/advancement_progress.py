"""Advancement progress: what each player obtained, when an advancement is done, and reading it
(``@a[advancements={...}]``, the player predicate's ``advancements``). Granting, triggers and
rewards are :mod:`emulator.world.advancements`.

- ``Progress`` (``state.advancement_progress``): per player UUID, per advancement, the criteria
  obtained; ``of(player, advancement_id)``.
- ``is_done(state, player, advancement_id)``: AdvancementProgress.isDone (every requirement group
  has an obtained criterion; no requirements: never done; AdvancementRequirements.test).
- ``matches(state, player, wanted)``: ``id=bool`` (done or not) or ``id={criterion=bool}``; an
  unknown advancement or a non-player never matches (EntitySelectorOptions ``advancements``).
  Progress waiting on a trigger the emulator does not observe (:data:`OBSERVED`) raises Unmodelled.
- ``parse_selector_value(text)``: the selector's ``{id=true,id2={crit=false}}``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from emulator.world.entities import Entity
from emulator.world.errors import Unmodelled
from mcfunction_parser.pack.advancements import criteria, requirements

# the triggers that fire in the emulator (the player actions fire using_item .. placed_block:
# emulator.world.player_actions, block_use, block_placing, combat; a teleport between levels
# changed_dimension; a tool's wear item_durability_changed: emulator.world.tools; recipe_unlocked;
# a totem used_totem: emulator.world.death_protection; levitation and enter_block:
# advancements.tick_players)
OBSERVED = frozenset({"impossible", "tick", "location", "inventory_changed", "using_item", "consume_item",
                      "default_block_use", "item_used_on_block", "player_hurt_entity", "entity_hurt_player",
                      "player_killed_entity", "entity_killed_player", "placed_block", "changed_dimension",
                      "effects_changed", "recipe_unlocked", "item_durability_changed", "crafter_recipe_crafted",
                      "started_riding", "thrown_item_picked_up_by_player", "thrown_item_picked_up_by_entity",
                      "used_totem", "levitation", "enter_block"})


def full_id(text) -> str | None:
    if not isinstance(text, str):
        return None
    return text if ":" in text else "minecraft:" + text


@dataclass
class Progress:
    obtained: dict[str, dict[str, set[str]]] = field(default_factory=dict)  # player UUID -> advancement -> criteria
    first_tick: dict[str, int] = field(default_factory=dict)  # player UUID -> the tick it first ticked
    # player UUID -> inventory menu slot -> the stack last broadcast (AbstractContainerMenu.lastSlots)
    menu_slots: dict[str, dict] = field(default_factory=dict)

    def of(self, player: Entity, advancement_id: str) -> set[str]:
        return self.obtained.setdefault(player.uuid_string, {}).setdefault(advancement_id, set())


def short_trigger(trigger: str) -> str:
    return trigger.removeprefix("minecraft:")


def is_done(state, player: Entity, advancement_id: str) -> bool:
    """AdvancementProgress.isDone: every requirement group has an obtained criterion."""
    advancement = state.resources.advancements[advancement_id]
    groups = requirements(advancement)
    got = state.advancement_progress.of(player, advancement_id)
    return bool(groups) and all(any(name in got for name in group) for group in groups)


def known(state, advancement_id: str) -> bool:
    """Whether the packs have the advancement. The game's own (``minecraft:``, when no pack has it)
    are not loaded, even with the game's jar: not modelled, so a test reading one is inconclusive
    rather than failed by a missing advancement the game has."""
    if advancement_id in state.resources.advancements:
        return True
    if advancement_id.startswith("minecraft:"):
        raise Unmodelled(f"the game's own advancement {advancement_id} (the emulator loads the packs' advancements only)")
    return False


def matches(state, player: Entity, wanted: dict) -> bool:
    """``advancements={id=bool, id={criterion=bool}}`` for one entity (non-players never match)."""
    if not player.is_player:
        return False
    for advancement_id, expected in wanted.items():
        advancement_id = full_id(advancement_id)
        if not known(state, advancement_id):
            return False  # EntitySelectorOptions: an unknown advancement matches nothing
        _readable(state, player, advancement_id)
        got = state.advancement_progress.of(player, advancement_id)
        if isinstance(expected, dict):
            if any((name in got) != bool(done) for name, done in expected.items()):
                return False
        elif is_done(state, player, advancement_id) != bool(expected):
            return False
    return True


def _readable(state, player: Entity, advancement_id: str) -> None:
    """Progress waiting on a trigger the emulator does not observe is unknown here."""
    got = state.advancement_progress.of(player, advancement_id)
    for name, criterion in criteria(state.resources.advancements[advancement_id]).items():
        if name not in got and short_trigger(criterion["trigger"]) not in OBSERVED:
            raise Unmodelled(f"advancement {advancement_id}: criterion '{name}' waits for the trigger "
                             f"{criterion['trigger']}, which the emulator does not observe")


def parse_selector_value(text: str) -> dict:
    """The ``advancements={...}`` selector value: ``{id=true,id2={crit=false}}``."""
    body = text.strip()[1:-1]
    out: dict = {}
    depth, start, parts = 0, 0, []
    for i, char in enumerate(body):
        depth += char == "{"
        depth -= char == "}"
        if char == "," and depth == 0:
            parts.append(body[start:i])
            start = i + 1
    parts.append(body[start:])
    for part in filter(str.strip, parts):
        key, _, value = part.partition("=")
        value = value.strip()
        out[key.strip()] = parse_selector_value(value) if value.startswith("{") else value == "true"
    return out
