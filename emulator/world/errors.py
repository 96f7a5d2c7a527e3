"""The message texts of command failures, by key (one source of truth).

``MESSAGES`` holds the game's en_us texts for the translation keys the emulator raises (the game's
``CommandSyntaxException`` messages), as 1.21.4 words them (a key 1.21.4 lacks: as the first release
that has it words it; tested against the shipped language files); ``EMULATOR_MESSAGES`` the emulator's own, keyed ``dpemu.*``,
for what the game has no message for (a limit of the emulator, a command it cannot read).
:class:`CommandFailure`, the one failure of a command on both backends (the game's
``CommandSyntaxException``), is built from a key of either table.
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
    "argument.dimension.invalid": "Unknown dimension '{0}'",
    "commands.teleport.invalidPosition": "Invalid position for teleport",
    "commands.stopwatch.already_exists": "Stopwatch '{0}' already exists",  # 1.21.11+
    "commands.stopwatch.does_not_exist": "Stopwatch '{0}' does not exist",
    "commands.spreadplayers.failed.entities": "Could not spread {0} entity/entities around {1}, {2} (too many entities "
                                              "for space - try using spread of at most {3})",
    "commands.spreadplayers.failed.teams": "Could not spread {0} team(s) around {1}, {2} (too many entities for space "
                                           "- try using spread of at most {3})",
    "commands.spreadplayers.failed.invalid.height": "Invalid maxHeight {0}; expected higher than world minimum {1}",
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
    "commands.place.template.invalid": "There is no template with id \"{0}\"",
    "commands.place.template.failed": "Failed to place template",
    "commands.clone.failed": "No blocks were cloned",
    "commands.clone.overlap": "The source and destination areas cannot overlap",
    "commands.clone.toobig": "Too many blocks in the specified area (maximum {0}, specified {1})",
    "commands.fill.failed": "No blocks were filled",
    "commands.team.add.duplicate": "A team already exists by that name",
    "commands.team.empty.unchanged": "Nothing changed. That team is already empty",
    "commands.team.option.collisionRule.unchanged": "Nothing changed. Collision rule is already that value",
    "commands.team.option.color.unchanged": "Nothing changed. That team already has that color",
    "commands.team.option.deathMessageVisibility.unchanged": "Nothing changed. Death message visibility is already that value",
    "commands.team.option.friendlyfire.alreadyDisabled": "Nothing changed. Friendly fire is already disabled for that team",
    "commands.team.option.friendlyfire.alreadyEnabled": "Nothing changed. Friendly fire is already enabled for that team",
    "commands.team.option.name.unchanged": "Nothing changed. That team already has that name",
    "commands.team.option.nametagVisibility.unchanged": "Nothing changed. Nametag visibility is already that value",
    "commands.team.option.seeFriendlyInvisibles.alreadyDisabled": "Nothing changed. That team already can't see invisible teammates",
    "commands.team.option.seeFriendlyInvisibles.alreadyEnabled": "Nothing changed. That team can already see invisible teammates",
    "team.notFound": "Unknown team '{0}'",
    "commands.fill.toobig": "Too many blocks in the specified area (maximum {0}, specified {1})",
    "commands.fillbiome.toobig": "Too many blocks in the specified volume (maximum {0}, specified {1})",
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
    "commands.help.failed": "Unknown command or insufficient permissions",
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
    "arguments.objective.notFound": "Unknown scoreboard objective '{0}'",
    "arguments.block.tag.unknown": "Unknown block tag '{0}'",
    "predicate.unknown": "Unknown predicate: {0}",
    "advancement.advancementNotFound": "Unknown advancement: {0}",
    "recipe.notFound": "Unknown recipe: {0}",
    "commands.recipe.give.failed": "No new recipes were learned",
    "commands.recipe.take.failed": "No recipes could be forgotten",
    "argument.player.entities": "Only players may be affected by this command, but the provided selector includes entities",
    "commands.advancement.criterionNotFound": "The advancement {0} does not contain the criterion '{1}'",
    "commands.advancement.grant.one.to.one.failure": "Couldn't grant advancement {0} to {1} as they already have it",
    "commands.advancement.grant.one.to.many.failure": "Couldn't grant advancement {0} to {1} players as they already have it",
    "commands.advancement.grant.many.to.one.failure": "Couldn't grant {0} advancements to {1} as they already have them",
    "commands.advancement.grant.many.to.many.failure": "Couldn't grant {0} advancements to {1} players as they already have them",
    "commands.advancement.revoke.one.to.one.failure": "Couldn't revoke advancement {0} from {1} as they don't have it",
    "commands.advancement.revoke.one.to.many.failure": "Couldn't revoke advancement {0} from {1} players as they don't have it",
    "commands.advancement.revoke.many.to.one.failure": "Couldn't revoke {0} advancements from {1} as they don't have them",
    "commands.advancement.revoke.many.to.many.failure": "Couldn't revoke {0} advancements from {1} players as they don't have them",
    "commands.advancement.grant.criterion.to.one.failure": "Couldn't grant criterion '{0}' of advancement {1} to {2} as they already have it",
    "commands.advancement.grant.criterion.to.many.failure": "Couldn't grant criterion '{0}' of advancement {1} to {2} players as they already have it",
    "commands.advancement.revoke.criterion.to.one.failure": "Couldn't revoke criterion '{0}' of advancement {1} from {2} as they don't have it",
    "commands.advancement.revoke.criterion.to.many.failure": "Couldn't revoke criterion '{0}' of advancement {1} from {2} players as they don't have it",
    "argument.resource_or_id.no_such_element": "Can't find element '{0}' in registry '{1}'",
    "argument.resource_or_id.failed_to_parse": "Failed to parse structure: {0}",
    "arguments.objective.readonly": "Scoreboard objective '{0}' is read-only",
    "arguments.operation.div0": "Cannot divide by zero",
    "argument.scoreHolder.empty": "No relevant score holders could be found",
    "arguments.function.unknown": "Unknown function {0}",
    "commands.scoreboard.objectives.add.duplicate": "An objective already exists by that name",
    "commands.scoreboard.players.get.null": "Can't get value of {0} for {1}; none is set",
    "commands.execute.conditional.fail": "Test failed",
    "commands.execute.conditional.fail_count": "Test failed, count: {0}",
    "commands.schedule.same_tick": "Can't schedule for current tick",
    "commands.time.no_default_clock": "There is no default clock in dimension {0}",
    "commands.time.no_time_marker_found": "Time marker {0} does not exist for clock {1}",
    "commands.time.wrong_timeline_for_clock": "Timeline {0} is not valid for clock {1}",
    "argument.resource.not_found": "Can't find element '{0}' of type '{1}'",
    "commands.schedule.cleared.failure": "No schedules with id {0}",
    "command.forkLimit": "Maximum number of contexts ({0}) reached",
    "commands.function.instantiationFailure": "Failed to instantiate function {0}: {1}",
    "commands.function.error.missing_arguments": "Missing arguments to function {0}",
    "commands.function.error.missing_argument": "Missing argument {1} to function {0}",
    "commands.function.error.parse": "While instantiating macro {0}: Command '{1}' caused error: {2}",
    "commands.function.scheduled.no_functions": "Can't find any functions for name {0}",
    "commands.item.target.not_a_container": "Target position {0}, {1}, {2} is not a container",
    "commands.item.source.not_a_container": "Source position {0}, {1}, {2} is not a container",
    "commands.item.target.no_such_slot": "The target does not have slot {0}",
    "commands.item.source.no_such_slot": "The source does not have slot {0}",
    "commands.item.target.no_changes": "No targets accepted item into slot {0}",
    "commands.item.target.no_changed.known_item": "No targets accepted item {0} into slot {1}",
    "commands.give.failed.toomanyitems": "Can't give more than {0} of {1}",
    "clear.failed.single": "No items were found on player {0}",
    "clear.failed.multiple": "No items were found on {0} players",
    "commands.drop.no_held_items": "Entity can't hold any items",
    "commands.drop.no_loot_table": "Entity {0} has no loot table",
    "arguments.item.overstacked": "{0} can only stack up to {1}",
    "arguments.item.tag.unknown": "Unknown item tag '{0}'",
    "commands.experience.set.points.invalid": "Cannot set experience points above the maximum points for the player's current level",
    "commands.enchant.failed": "Nothing changed. Targets either have no item in their hands or the enchantment could not be applied",
    "commands.enchant.failed.entity": "{0} is not a valid entity for this command",
    "commands.enchant.failed.incompatible": "{0} cannot support that enchantment",
    "commands.enchant.failed.itemless": "{0} is not holding any item",
    "commands.enchant.failed.level": "{0} is higher than the maximum level of {1} supported by that enchantment",
    "commands.effect.give.failed": "Unable to apply this effect (target is either immune to effects, or has something stronger)",
    "commands.effect.clear.everything.failed": "Target has no effects to remove",
    "commands.effect.clear.specific.failed": "Target doesn't have the requested effect",
    "commands.attribute.failed.entity": "{0} is not a valid entity for this command",
    "commands.attribute.failed.no_attribute": "Entity {0} has no attribute {1}",
    "commands.attribute.failed.no_modifier": "Attribute {0} for entity {1} has no modifier {2}",
    "commands.attribute.failed.modifier_already_present": "Modifier {0} is already present on attribute {1} for entity {2}",
    "commands.damage.invulnerable": "Target is invulnerable to the given damage type",
    "commands.difficulty.failure": "The difficulty did not change; it is already set to {0}",
    "commands.forceload.added.failure": "No chunks were marked for force loading",
    "commands.forceload.removed.failure": "No chunks were removed from force loading",
    "commands.forceload.query.failure": "Chunk at {0} in {1} is not marked for force loading",
    "commands.forceload.toobig": "Too many chunks in the specified area (maximum {0}, specified {1})",
    "commands.worldborder.set.failed.nochange": "Nothing changed. The world border is already that size",
    "commands.worldborder.set.failed.small": "World border cannot be smaller than 1 block wide",
    "commands.worldborder.set.failed.big": "World border cannot be bigger than {0} blocks wide",
    "commands.worldborder.set.failed.far": "World border cannot be further out than {0} blocks",
    "commands.worldborder.center.failed": "Nothing changed. The world border is already centered there",
    "commands.worldborder.damage.amount.failed": "Nothing changed. The world border damage is already that amount",
    "commands.worldborder.damage.buffer.failed": "Nothing changed. The world border damage buffer is already that distance",
    "commands.worldborder.warning.time.failed": "Nothing changed. The world border warning is already that amount of time",
    "commands.worldborder.warning.distance.failed": "Nothing changed. The world border warning is already that distance",
    "argument.pos.outofbounds": "That position is outside the allowed boundaries.",
    "commands.particle.failed": "The particle was not visible for anybody",
    "argument.waypoint.invalid": "Selected entity is not a waypoint",
    "commands.teammsg.failed.noteam": "You must be on a team to message your team",
    "commands.swing.failed.notliving": "No living entities were found to swing",
    "commands.playsound.failed": "The sound is too far away to be heard",
    "commands.spectate.self": "Cannot spectate yourself",
    "commands.spectate.not_spectator": "{0} is not in spectator mode",
    "commands.spectate.cannot_spectate": "{0} cannot be spectated",
    "commands.datapack.unknown": "Unknown data pack '{0}'",
    "commands.datapack.enable.failed": "Pack '{0}' is already enabled!",
    "commands.datapack.disable.failed": "Pack '{0}' is not enabled!",
}

EMULATOR_MESSAGES = {
    "dpemu.unsupported": "{0} is not supported yet",
    "dpemu.unmodelled": "not modelled: {0}",
    "dpemu.selector.unsupported": "selector argument '{0}' is not supported",
    "dpemu.block.invalid": "invalid block '{0}': {1}",
    "dpemu.command.unreadable": "'{0}': {1}",
    "dpemu.structure.invalid": "the structure template {0} cannot be read: {1}",
    "dpemu.gamerule.unknown": "Unknown game rule '{0}'",
    "dpemu.macro.not_compound": "Expected argument to be a compound, got {0}",
    "dpemu.loot.unknown_table": "Unknown loot table {0}",
    "dpemu.loot.unknown_modifier": "Unknown item modifier {0}",
    "dpemu.loot.invalid": "{0} does not parse: {1}",
    "dpemu.packtest.failed": "{0}",
}


class CommandFailure(Exception):
    """The one failure of a command: the message of ``key`` (a key of :data:`MESSAGES`, or the
    emulator's own ``dpemu.*`` of :data:`EMULATOR_MESSAGES`) filled with ``args``.

    A failing command fails (result 0, ``store success`` 0) and the run goes on. ``report``: also
    record a runtime diagnostic at the command (with the function traceback). Failures that
    datapacks rely on routinely (a test that fails, ``objectives add`` of an existing objective,
    ``get`` of an unset score) are silent, as in the game; failures that point at a pack bug
    (division by zero, an unknown objective or function) or at a limit of the emulator (an
    unsupported stage) are reported."""

    unmodelled = False  # the emulator does not model what failed (see :class:`Unmodelled`)

    def __init__(self, key: str, *args, report: bool = False) -> None:
        self.key = key
        self.message = (MESSAGES.get(key) or EMULATOR_MESSAGES[key]).format(*args)
        self.report = report
        super().__init__(self.message)


class Unmodelled(CommandFailure):
    """The command needs something the emulator does not model (a predicate condition, an
    unknown vanilla tag ...): it fails, reported, and a test that meets it is inconclusive."""

    unmodelled = True

    def __init__(self, reason: str) -> None:
        super().__init__("dpemu.unmodelled", reason, report=True)
        self.reason = reason
