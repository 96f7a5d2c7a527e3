"""``recipe give|take TARGETS RECIPE|*``: the players' recipe books (:mod:`emulator.world.recipes`).

The parser keeps the command as text; it is read here. Source (decompiled 1.21):
server/commands/RecipeCommand.java (giveRecipes / takeRecipes: the result is the number of recipes
added or removed over every player; none fails, "No new recipes were learned" / "No recipes could
be forgotten"), ResourceLocationArgument.getRecipe (an unknown id fails, "Unknown recipe"),
EntityArgument.getPlayers.
"""
from __future__ import annotations

from emulator.world import advancements, recipes
from emulator.world.errors import CommandFailure
from mcfunction_parser import ast

from .entities import arguments, players_found, target_word


def recipe(env, cmd: ast.GenericCommand, ctx) -> int:
    words, target = arguments(cmd)
    if len(words) != 3 or words[0] not in ("give", "take"):
        raise CommandFailure("dpemu.command.unreadable", "recipe", "expected 'recipe give|take TARGETS RECIPE|*'",
                             report=True)
    action, which, state = words[0], words[2], env.state
    players = players_found(state, target_word(cmd, words, 1, target), ctx)
    if which == "*":
        chosen = recipes.every(state.resources)
    else:
        recipe_id = which if ":" in which else "minecraft:" + which
        if not recipes.find(state.resources, recipe_id):
            raise recipes.unknown_recipe(recipe_id)
        chosen = [recipe_id]
    if action == "give":
        changed = sum(advancements.award_recipes(state, p, chosen) for p in players)
    else:
        changed = sum(recipes.revoke(p, chosen) for p in players)
    if changed == 0:
        raise CommandFailure(f"commands.recipe.{action}.failed")
    return changed


HANDLERS = {"recipe": recipe}
