"""When an advancement's reward function runs, on both backends, as the game runs it (decompiled
1.21): AdvancementRewards.grant calls ServerFunctionManager.execute, which inside a running command
goes through Commands.executeCommandInContext to ExecutionContext.queueInitialFunctionCall: the
reward is queued next (``queueNext``, pushed in front once the command's entry returns), in a top
frame one deeper than the command's (``createTopFrame``), as the player, its result going nowhere
(CommandResultCallback.EMPTY); its CallFunction costs 1 of the same root's quota. With no command
running (a trigger fired by the world's tick) it is a root of its own."""
from __future__ import annotations

import json

import pytest

from emulator import Emulator
from emulator.world.entities import entity_nbt
from tests.world.world_emulator import make_pack

BACKENDS = ["python", "numba"]


def _emulator(tmp_path, backend, functions, advancements, players=("Alex", "Steve")):
    root = make_pack(tmp_path / "p", {"t:setup": "scoreboard objectives add o dummy\n"
                                                 "scoreboard objectives add seen dummy", **functions})
    for name, body in advancements.items():
        file = root / "data" / "t" / "advancement" / f"{name}.json"
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(json.dumps(body))
    emu = Emulator(backend=backend)
    emu.load(root)
    emu.call("t:setup")
    for name in players:
        emu.add_player(name, (0, 0, 0))
    return emu


def _impossible(reward: str) -> dict:
    return {"criteria": {"x": {"trigger": "minecraft:impossible"}}, "rewards": {"function": reward}}


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_reward_runs_right_after_the_command_before_the_next_line(tmp_path, backend):
    # ExecutionContext.queueNext: the reward entry goes in front of the caller's next command;
    # its `return` ends only its own frame (createTopFrame: one deeper), and the command's own
    # result still reaches its store (the reward's result goes to CommandResultCallback.EMPTY)
    emu = _emulator(tmp_path, backend, {
        "t:main": "scoreboard players set #order o 1\n"
                  "execute store result score #result o run advancement grant Alex only t:a\n"
                  "scoreboard players operation #seen o = #order o\n"
                  "scoreboard players add #order o 100",
        "t:reward": "scoreboard players add #order o 10\nreturn 7\nscoreboard players add #order o 1000",
    }, {"a": _impossible("t:reward")})
    result = emu.runtime.call("t:main")
    assert (emu.score("#seen", "o"), emu.score("#order", "o"), emu.score("#result", "o")) == (11, 111, 1)
    # the root's cost: its call, 4 lines (the store stage and the grant are 2 units), then the
    # reward's call and its one charged command (a `return N` costs nothing)
    assert result.cost == 1 + 5 + 1 + 1
    assert not [d for d in emu.diagnostics if d.severity in ("error", "warning")]


@pytest.mark.parametrize("backend", BACKENDS)
def test_each_context_of_a_fork_runs_its_reward_before_the_next_context_runs_the_command(tmp_path, backend):
    # ContinuationTask: the command runs once per context, each an entry of its own; the reward an
    # entry earned runs before the continuation queues the next context's
    emu = _emulator(tmp_path, backend, {
        "t:main": "execute as @a run advancement grant @s only t:a",
        "t:reward": "execute store result score @s seen if entity @a[advancements={t:a=true}]",
    }, {"a": _impossible("t:reward")})
    emu.call("t:main")
    assert (emu.score("Alex", "seen"), emu.score("Steve", "seen")) == (1, 2)


@pytest.mark.parametrize("backend", BACKENDS)
def test_rewards_of_one_command_run_in_order_each_with_the_rewards_it_earns_nested(tmp_path, backend):
    # one command granting two advancements queues both rewards; a reward granting another runs
    # that one right after its own command, before the first command's second reward
    emu = _emulator(tmp_path, backend, {
        "t:main": "advancement grant Alex through t:b\nscoreboard players set #after o 1",
        "t:ra": "scoreboard players add #log o 1\nadvancement grant @s only t:c\nscoreboard players add #log o 10",
        "t:rb": "scoreboard players operation #b o = #log o",
        "t:rc": "scoreboard players operation #c o = #log o\nscoreboard players set #after o 0",
    }, {"a": _impossible("t:ra"), "b": {**_impossible("t:rb"), "parent": "t:a"}, "c": _impossible("t:rc")})
    emu.call("t:main")
    assert (emu.score("#c", "o"), emu.score("#b", "o"), emu.score("#log", "o"), emu.score("#after", "o")) == (
        1, 11, 11, 1)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_trigger_fired_inside_a_command_rewards_before_the_next_line(tmp_path, backend):
    # ServerPlayer.onEffectAdded fires effects_changed inside `effect give`: its reward is queued
    # in the running command's execution context like a grant's
    emu = _emulator(tmp_path, backend, {
        "t:main": "effect give Alex minecraft:speed 10 0 true\nscoreboard players operation #seen o = #got o",
        "t:reward": "scoreboard players set #got o 5",
    }, {"e": {"criteria": {"x": {"trigger": "minecraft:effects_changed"}}, "rewards": {"function": "t:reward"}}},
        players=("Alex",))
    emu.call("t:main")
    assert emu.score("#seen", "o") == 5


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_missing_or_macro_reward_is_an_error_and_the_command_goes_on(tmp_path, backend):
    emu = _emulator(tmp_path, backend, {
        "t:main": "advancement grant Alex only t:a\nadvancement grant Alex only t:b\nscoreboard players set #after o 1",
        "t:macro": "$scoreboard players set #m o $(v)",
    }, {"a": _impossible("t:gone"), "b": _impossible("t:macro")})
    emu.call("t:main")
    assert emu.score("#after", "o") == 1
    errors = [d.message for d in emu.diagnostics if d.severity == "error"]
    assert errors[0] == "advancement reward function t:gone does not exist"
    assert "t:macro" in errors[1] and len(errors) == 2


@pytest.mark.parametrize("backend", BACKENDS)
def test_experience_and_loot_come_before_the_function(tmp_path, backend):
    # AdvancementRewards.grant: giveExperiencePoints, then each loot table's items (ADVANCEMENT_REWARD:
    # the player as this at its position) into the inventory, then the function
    root = tmp_path / "p"
    table = root / "data" / "t" / "loot_table" / "gift.json"
    table.parent.mkdir(parents=True, exist_ok=True)
    table.write_text(json.dumps({"pools": [{"rolls": 1, "entries": [
        {"type": "item", "name": "minecraft:diamond", "functions": [{"function": "set_count", "count": 2}]}]}]}))
    emu = _emulator(tmp_path, backend, {
        "t:main": "advancement grant Alex only t:a",
        "t:after": "execute store result score #xp o run xp query @s points\n"
                   "execute store result score #diamonds o run clear @s minecraft:diamond 0",
    }, {"a": {"criteria": {"x": {"trigger": "minecraft:impossible"}},
              "rewards": {"experience": 5, "loot": ["t:gift"], "function": "t:after"}}}, players=("Alex",))
    emu.call("t:main")
    assert (emu.score("#xp", "o"), emu.score("#diamonds", "o")) == (5, 2)


@pytest.mark.parametrize("backend", BACKENDS)
def test_loot_that_does_not_fit_is_thrown_to_the_player(tmp_path, backend):
    # Player.addItem failing: ServerPlayer.drop(stack, false) at the eyes minus 0.3, then
    # setNoPickUpDelay and setTarget(the player): PickupDelay 0 and Owner
    root = tmp_path / "p"
    table = root / "data" / "t" / "loot_table" / "gift.json"
    table.parent.mkdir(parents=True, exist_ok=True)
    table.write_text(json.dumps({"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "minecraft:diamond"}]}]}))
    emu = _emulator(tmp_path, backend, {
        "t:main": "give Alex minecraft:stone 2304\nadvancement grant Alex only t:a",
    }, {"a": {"criteria": {"x": {"trigger": "minecraft:impossible"}}, "rewards": {"loot": ["t:gift"],
                                                                                  "recipes": ["minecraft:stick"]}}},
        players=("Alex",))
    emu.call("t:main")
    [item] = [entity_nbt(e) for e in emu.state.entities.entities if e.type == "minecraft:item"]
    [alex] = emu.state.entities.players()
    assert item["Item"]["id"] == "minecraft:diamond" and item["PickupDelay"] == 0
    assert [int(v) for v in item["Owner"]] == list(alex.uuid)
    assert float(item["Pos"][1]) == pytest.approx(1.62 - 0.3, abs=1e-6)
    warnings = [d for d in emu.diagnostics if d.unmodelled]
    assert ["recipes reward" in d.message and "--game-jar" in d.message for d in warnings] == [True]


def _recipe(root, name: str, kind: str = "minecraft:crafting_shapeless") -> None:
    file = root / "data" / "t" / "recipe" / f"{name}.json"
    file.parent.mkdir(parents=True, exist_ok=True)
    body = {"type": kind}  # a special recipe has no other field; crafting ones as 1.21 writes them
    if kind == "minecraft:crafting_shapeless":
        body.update(ingredients=[{"item": "minecraft:stick"}], result={"id": "minecraft:stick"})
    elif kind == "minecraft:crafting_shaped":
        body.update(pattern=["#"], key={"#": {"item": "minecraft:stick"}}, result={"id": "minecraft:stick"})
    file.write_text(json.dumps(body))


@pytest.mark.parametrize("backend", BACKENDS)
def test_recipe_rewards_commands_and_the_unlocked_trigger(tmp_path, backend):
    # a tutorial chain as packs write it: picking the first advancement's reward teaches the recipe
    # (AdvancementRewards.grant: awardRecipesByKey, an unknown id skipped), recipe_unlocked
    # (RecipeUnlockedTrigger: its recipe) completes the next one, whose function counts; RecipeCommand:
    # the result is the number of recipes added or removed, none fails; a special recipe
    # (CustomRecipe.isSpecial) is never added (ServerRecipeBook.addRecipes)
    root = tmp_path / "p"
    for name, kind in (("wand", "minecraft:crafting_shapeless"), ("staff", "minecraft:crafting_shaped"),
                       ("dye", "minecraft:crafting_special_armordye")):
        _recipe(root, name, kind)
    emu = _emulator(tmp_path, backend, {
        "t:main": "advancement grant Alex only t:start\n"
                  "execute store result score #again o run recipe give Alex t:wand\n"
                  "execute store result score #all o run recipe give @a t:staff\n"
                  "execute store result score #special o run recipe give Alex t:dye\n"
                  "execute store result score #take o run recipe take @a t:staff\n"
                  "execute store result score #taken o run recipe take Alex t:staff\n"
                  "execute store result score #known o if entity @a[name=Alex,nbt={recipeBook:{recipes:['t:wand']}}]\n",
        "t:learned": "scoreboard players add @s seen 1",
    }, {"start": {"criteria": {"x": {"trigger": "minecraft:impossible"}},
                  "rewards": {"recipes": ["t:wand", "t:missing"]}},
        "learn": {"criteria": {"r": {"trigger": "minecraft:recipe_unlocked", "conditions": {"recipe": "t:wand"}}},
                  "rewards": {"function": "t:learned"}}})
    emu.call("t:main")
    scores = {k: emu.score(k, "o") for k in ("#again", "#all", "#special", "#take", "#taken", "#known")}
    assert scores == {"#again": 0, "#all": 2, "#special": 0, "#take": 2, "#taken": 0, "#known": 1}
    assert (emu.score("Alex", "seen"), emu.score("Steve", "seen")) == (1, None)
    book = entity_nbt(emu.state.entities.players()[0])["recipeBook"]
    assert [str(r) for r in book["recipes"]] == ["t:wand"] and [str(r) for r in book["toBeDisplayed"]] == ["t:wand"]
    assert book["isGuiOpen"] == 0 and book["isSmokerFilteringCraftable"] == 0
