"""The failure every world operation raises, carrying the game's own message.

A command that fails in the game throws a ``CommandSyntaxException`` whose text the player sees; the
world library raises ``CommandFailure(message)`` at the same points, and the backends turn it into
a failed command (result 0, ``store success`` 0) and a log line.

``MESSAGES`` holds the game's en_us texts for the translation keys used here (one source of truth).
"""
from __future__ import annotations

MESSAGES = {
    "arguments.nbtpath.node.invalid": "Invalid NBT path element",
    "arguments.nbtpath.nothing_found": "Found no elements matching {0}",
    "arguments.nbtpath.too_deep": "Resulting NBT too deeply nested",
    "commands.data.merge.failed": "Nothing changed. The specified properties already have these values",
    "commands.data.get.invalid": "Can't get {0}; only numeric tags are allowed",
    "commands.data.get.unknown": "Can't get {0}; tag doesn't exist",
    "commands.data.get.multiple": "This argument accepts a single NBT value",
    "commands.data.modify.expected_list": "Expected list, got: {0}",
    "commands.data.modify.expected_object": "Expected object, got: {0}",
    "commands.data.modify.expected_value": "Expected value, got: {0}",
    "commands.data.modify.invalid_index": "Invalid list index: {0}",
    "commands.data.modify.invalid_substring": "Invalid substring indices: {0} to {1}",
    "commands.data.entity.invalid": "Unable to modify player data",
    "commands.teleport.invalidPosition": "Invalid position for teleport",
    "commands.summon.invalidPosition": "Invalid position for summon",
    "commands.tag.add.failed": "Target either already has the tag or has too many tags",
    "commands.tag.remove.failed": "Target does not have this tag",
    "commands.summon.failed.uuid": "Unable to summon entity due to duplicate UUIDs",
    "entity.not_summonable": "Can't summon entity of type {0}",
    "argument.entity.notfound.entity": "No entity was found",
    "command.unknown.argument": "Incorrect argument for command",
    "permissions.requires.entity": "An entity is required to run this command here",
    "argument.entity.notfound.player": "No player was found",
    "argument.entity.toomany": "Only one entity is allowed, but the provided selector allows more than one",
    "argument.pos.outofworld": "That position is out of this world!",
    "commands.setblock.failed": "Could not set the block",
    "commands.fill.failed": "No blocks were filled",
    "commands.fill.toobig": "Too many blocks in the specified area (maximum {0}, specified {1})",
    "commands.execute.blocks.toobig": "Too many blocks in the specified area (maximum {0}, specified {1})",
    "commands.data.block.invalid": "The target block is not a block entity",
    "permissions.requires.player": "A player is required to run this command here",
    "commands.trigger.failed.unprimed": "You cannot trigger this objective yet",
    "commands.trigger.failed.invalid": "You can only trigger objectives that are 'trigger' type",
    "commands.scoreboard.players.enable.failed": "Nothing changed. That trigger is already enabled",
    "commands.scoreboard.players.enable.invalid": "Enable only works on trigger-objectives",
    "commands.random.error.range_too_large": "The range of the random value must be at most 2147483646",
    "commands.random.error.range_too_small": "The range of the random value must be at least 2",
    "commands.random.roll": "{0} rolled {1} (from {2} to {3})",
    "commands.ride.already_riding": "{0} is already riding {1}",
    "commands.ride.mount.failure.cant_ride_players": "Players can't be ridden",
    "commands.ride.mount.failure.loop": "Can't mount entity on itself or any of its passengers",
    "commands.ride.mount.failure.generic": "{0} couldn't start riding {1}",
    "commands.ride.not_riding": "{0} is not riding any vehicle",
    "commands.bossbar.create.failed": "A bossbar already exists with the ID '{0}'",
    "commands.bossbar.unknown": "No bossbar exists with the ID '{0}'",
    "commands.bossbar.set.players.unchanged": "Nothing changed. Those players are already on the bossbar with nobody to add or remove",
    "commands.bossbar.set.name.unchanged": "Nothing changed. That's already the name of this bossbar",
    "commands.bossbar.set.color.unchanged": "Nothing changed. That's already the color of this bossbar",
    "commands.bossbar.set.style.unchanged": "Nothing changed. That's already the style of this bossbar",
    "commands.bossbar.set.value.unchanged": "Nothing changed. That's already the value of this bossbar",
    "commands.bossbar.set.max.unchanged": "Nothing changed. That's already the max of this bossbar",
    "commands.bossbar.set.visibility.unchanged.hidden": "Nothing changed. The bossbar is already hidden",
    "commands.bossbar.set.visibility.unchanged.visible": "Nothing changed. The bossbar is already visible",
}


class CommandFailure(Exception):
    """A command failed the way the game's command would; ``key`` is the translation key."""

    def __init__(self, key: str, *args) -> None:
        self.key = key
        self.args_ = args
        self.message = MESSAGES[key].format(*args)
        super().__init__(self.message)
