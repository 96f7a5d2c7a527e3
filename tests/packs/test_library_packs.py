"""The packs under tests/packs, written the way datapack libraries use the data-driven world, with
their PackTest suites run on both backends:
- gated: predicates and registry tags (a predicate-gated tick, location/time/score predicates, decimal range bounds,
  a campfire's smoke, no structures in the test world, the sky seen or not, moonlight, references, block and entity type tags);
- rewards: advancements (a player-tick hook that revokes itself, the location trigger, a reward
  chain, grant/revoke modes and criteria, the advancements selector);
- healing: health set through instant effects, the effects_changed trigger and its conditions;
- sight: 26.2 entity sub-predicates, a player's looking_at, an entity's UUID read from the
  insertion of its display name (a selector text resolved by set_name);
- clicks: clicks on interaction entities heard as a library hears them (player_hurt_entity with
  entity and damage conditions, ``execute on attacker|target``);
- crafting: custom recipes tested with a crafter (shaped with a mirrored pattern and an item tag,
  shapeless with a remainder, into a chest in front, crafter_recipe_crafted);
- machines: block entities set up and read as machine and spawner packs do (a spawner placed then
  merged, a bee nest's bees, a furnace's times, the block entity type's id), a smelting line of
  hoppers around a blast furnace cooking the pack's recipe, an item collector filling a double chest;
- lists, typed: a collection library flattening lists that mix types (1.21.5+), and the one-type
  rule of the lists before it;
- ticker: a library ticking its modules' function tag from a repeating command block, as forceload
  libraries do (the block's LastOutput is ``Running functions ...``: FunctionCommand);
- stack: a call-stack library keeping its frames in the storage ``stack:`` (a resource location
  with an empty path, valid: ResourceLocation.isValidPath), as in-game unit test libraries do;
- projectiles: arrows and snowballs flying across the test, an arrow sticking in the barrier wall
  and another falling out of the air onto the structure block, a snowball breaking on the wall, an
  arrow hurting a pig;
- toolstand: an inventory library setting a hidden armor stand's ``HandItems[0]`` (saved empty
  before 1.21.5) and mining a probe block with it to read a loot table's answer;
- squads: a team game's teams (membership by selector and by a name before its player joins,
  friendly fire, a prefix in chat names, empty and remove);
- uninstall, with uninstall_lib beneath it: a module that uninstalls itself with ``datapack disable``
  and is enabled again (its tick stops and starts, every load function runs again)."""
from pathlib import Path

import pytest

from emulator.testing import discover
from emulator.testing.results import PASSED
from emulator.testing.runner import load_suite, run_case

HERE = Path(__file__).resolve().parent
SUITES = {name: list(load_suite(discover([HERE / name])))[0] for name in ("gated", "rewards", "healing", "lists", "sight", "typed",
                                                                         "clicks", "crafting", "ticker", "machines", "stack",
                                                                         "projectiles", "toolstand", "squads")}
CASES = [(name, case) for name, (_, cases) in SUITES.items() for case in cases]


def test_the_packs_load_clean():
    gated, rewards = SUITES["gated"][0], SUITES["rewards"][0]
    assert gated.errors == [] and rewards.errors == []
    assert set(gated.predicates) == {"gated:marked_undead", "gated:in_water", "gated:night", "gated:healthy",
                                     "gated:on_soft_ground", "gated:seasoned", "gated:in_smoke",
                                     "gated:in_village", "gated:outdoors", "gated:moonlit", "gated:lamplit"}
    undead = gated.registry_tags["entity_type"]["gated:undead"]
    # the built-in #minecraft:zombies nested, the optional missing tag skipped (TagLoader)
    assert {"minecraft:husk", "minecraft:zombie", "minecraft:skeleton"} <= undead.members
    assert undead.unknown == ()
    assert len(rewards.advancements) == 12 and "rewards:on_tick" in rewards.advancement_rewards


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("name,case", CASES, ids=[case.id for _, case in CASES])
def test_pack_test_passes(name, case, backend):
    result = run_case(case, SUITES[name][0], backend)
    assert result.status == PASSED, result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_module_uninstalls_and_reinstalls(backend):
    (packs, cases), = load_suite(discover([HERE / "uninstall"]), with_packs=[HERE / "uninstall_lib"])
    assert [case.id for case in cases] == ["uninstall:reinstall"]
    result = run_case(cases[0], packs, backend)
    assert result.status == PASSED, result.report()
