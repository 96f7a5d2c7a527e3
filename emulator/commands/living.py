"""The living-entity commands: ``xp``/``experience``, ``effect``, ``attribute``, ``damage``,
``gamemode``, ``spectate`` and ``waypoint``, on the state :mod:`emulator.world.living` keeps in the
entities' NBT.

The parser keeps these commands as text; each is read once per source line (cached) into its
arguments, then run per context. Results are the game's: ``xp add|set`` the players changed,
``xp query`` the value, ``effect`` the entities changed, ``attribute ... get [SCALE]`` the value
times the scale cast to int, ``damage`` 1.

Sources (decompiled 1.21): server/commands/ExperienceCommand.java, EffectCommands.java,
AttributeCommand.java, DamageCommand.java; 26.1.2 WaypointCommand.java, Waypoint.Icon.
"""
from __future__ import annotations


from emulator.world import advancements, combat, living, spectating
from emulator.world.entities import uuid_string
from emulator.world.entity_flags import flying_after
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.semantics import double_to_int
from mcfunction_parser import ast, gamedata
from mcfunction_parser.arguments import vec3
from mcfunction_parser.nbt import Compound, Int, String
from mcfunction_parser.pack.tags import normalise_id
from mcfunction_parser.primitives import is_uuid, uuid_ints
from mcfunction_parser.reader import ParseError, Reader

from .entities import (_executor_required, argument_spans, arguments, executor, found, parse_target, players_found,
                       single, single_player, target_word, world_source)


def _number(cmd, words: list, index: int, kind=float, default=None):
    if index >= len(words):
        if default is not None:
            return default
        raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected a number", report=True)
    try:
        return kind(words[index])
    except ValueError:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, f"expected a number, got '{words[index]}'",
                             report=True) from None


def _resource(word: str) -> str:
    return word if ":" in word else f"minecraft:{word}"


# ---------------------------------------------------------------------- xp
def experience(env, cmd: ast.GenericCommand, ctx) -> int:
    """``xp add|set TARGETS AMOUNT [points|levels]``, ``xp query TARGET points|levels``."""
    words, target = arguments(cmd)
    action = words[0] if words else ""
    who = target_word(cmd, words, 1, target)
    if action == "query":
        player = single_player(env.state, who, ctx)
        unit = words[2] if len(words) > 2 else ""
        return living.query_levels(player) if unit == "levels" else living.query_points(player)
    amount = _number(cmd, words, 2, int)
    unit = words[3] if len(words) > 3 else "points"
    players = players_found(env.state, who, ctx)
    if action == "add":
        for player in players:
            (living.add_levels if unit == "levels" else living.add_points)(player, amount)
        return len(players)
    changed = 0
    for player in players:
        if unit == "levels":
            living.set_levels(player, amount)
            changed += 1
        else:
            changed += living.set_points(player, amount)
    if not changed:
        raise CommandFailure("commands.experience.set.points.invalid")
    return changed


# ---------------------------------------------------------------------- effect
def effect(env, cmd: ast.GenericCommand, ctx) -> int:
    """``effect give TARGETS EFFECT [SECONDS|infinite] [AMPLIFIER] [HIDE_PARTICLES]`` and ``effect clear
    [TARGETS] [EFFECT]`` (no targets: the executor)."""
    words, target = arguments(cmd)
    if words and words[0] == "clear":
        return _clear(env, cmd, words, target, ctx)
    effect_id = _resource(words[2]) if len(words) > 2 else ""
    instant = effect_id in living.INSTANT
    seconds = words[3] if len(words) > 3 else None
    if seconds == "infinite":
        duration = living.INFINITE
    elif seconds is not None:  # an instant effect's seconds are ticks (EffectCommands.giveEffect)
        duration = _number(cmd, words, 3, int, 0) * (1 if instant else 20)
    else:
        duration = 1 if instant else 600
    amplifier = _number(cmd, words, 4, int, 0)
    visible = not (len(words) > 5 and words[5] == "true")
    source = executor(env.state, ctx)
    changed = 0
    for e in found(env.state, target_word(cmd, words, 1, target), ctx):
        if living.is_living(e.type) and living.give_effect(env.state, e, effect_id, duration, amplifier, visible):
            advancements.effects_changed(env.state, e, source)
            changed += 1
    if not changed:
        raise CommandFailure("commands.effect.give.failed")
    return changed


def _clear(env, cmd, words, target, ctx) -> int:
    if len(words) > 1:
        entities = found(env.state, target_word(cmd, words, 1, target), ctx)
    else:
        entities = [_executor_required(env.state, ctx)]
    effect_id = _resource(words[2]) if len(words) > 2 else None
    changed = 0
    for e in entities:
        if living.is_living(e.type) and living.clear_effects(e, effect_id):
            advancements.effects_changed(env.state, e, None)
            changed += 1
    if not changed:
        raise CommandFailure("commands.effect.clear.specific.failed" if effect_id else
                             "commands.effect.clear.everything.failed")
    return changed


# ---------------------------------------------------------------------- attribute
def _attribute_name(name: str, release) -> str:
    """The attribute's name in messages: the en_us text of its description id (Attribute.getDescriptionId:
    ``attribute.name.`` and its registry path in the release: movement_speed reads Speed)."""
    key = "attribute.name." + living.saved_attribute_id(name, release).split(":", 1)[1]
    return gamedata.language(tuple(release)).get(key) or name.replace("_", " ").title()


def attribute(env, cmd: ast.GenericCommand, ctx) -> int:
    """``attribute TARGET ATTRIBUTE get [SCALE] | base get [SCALE] | base set VALUE | base reset |
    modifier add ID VALUE OPERATION | modifier remove ID | modifier value get ID [SCALE]``."""
    words, target, starts = argument_spans(cmd)
    entity = single(env.state, target_word(cmd, words, 0, target), ctx)
    name = living.attribute_id(words[1]) if len(words) > 1 else ""
    if not living.is_living(entity.type):
        raise CommandFailure("commands.attribute.failed.entity", entity.display_name)
    if name not in living.DEFAULTS or not living.has_attribute(entity.type, name):
        raise CommandFailure("commands.attribute.failed.no_attribute", entity.display_name,
                             _attribute_name(name, entity.release))
    action = tuple(words[2:4])
    if action[:1] == ("get",):
        return double_to_int(living.attribute_value(entity, name) * _number(cmd, words, 3, float, 1.0))
    if action == ("base", "get"):
        return double_to_int(living.base_value(entity, name) * _number(cmd, words, 4, float, 1.0))
    if action == ("base", "set"):
        living.set_base(entity, name, _number(cmd, words, 4))
        return 1
    if action == ("base", "reset"):
        living.reset_base(entity, name)
        return 1
    if action[:1] == ("modifier",):
        return _modifier(cmd, entity, name, action[1:], words, starts)
    raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected get, base or modifier", report=True)


# AttributeCommand's operation literals before 1.20.5, by AttributeModifier.Operation's later names
_OLD_OPERATIONS = {"add": "add_value", "multiply_base": "add_multiplied_base", "multiply": "add_multiplied_total"}


def _modifier(cmd, entity, name: str, action: tuple, words: list, starts: list[int]) -> int:
    """``modifier add KEY [NAME] VALUE OPERATION | remove KEY | value get KEY [SCALE]``: KEY an id
    from 1.21; before it a UUID, and ``add`` takes the modifier's name (a string) after it
    (AttributeCommand of 1.16 - 1.20.6); the failures name the key as written back (UUID.toString).
    ``words`` and ``starts``: :func:`argument_spans` of the command."""
    at = 5 if action == ("value",) else 4  # the key's word: after `value get`
    key, shown = _modifier_key(cmd, entity, words[at] if len(words) > at else "")
    if action == ("add",):
        if entity.release >= living.MODIFIER_IDS:
            label, rest = "", words[at + 1:]
        else:
            label, rest = _string_then_words(cmd, starts[at + 1] if len(starts) > at + 1 else len(cmd.text))
        operation = rest[1] if len(rest) > 1 else ""
        if not living.add_modifier(entity, name, key, _number(cmd, rest, 0), _OLD_OPERATIONS.get(operation, operation),
                                   label):
            raise CommandFailure("commands.attribute.failed.modifier_already_present", shown,
                                 _attribute_name(name, entity.release), entity.display_name)
        return 1
    if action == ("remove",):
        if not living.remove_modifier(entity, name, key):
            raise CommandFailure("commands.attribute.failed.no_modifier", _attribute_name(name, entity.release),
                                 entity.display_name, shown)
        return 1
    if action == ("value",) and words[4:5] == ["get"]:
        value = living.modifier_value(entity, name, key)
        if value is None:
            raise CommandFailure("commands.attribute.failed.no_modifier", _attribute_name(name, entity.release),
                                 entity.display_name, shown)
        return double_to_int(value * _number(cmd, words, 6, float, 1.0))
    raise CommandFailure("dpemu.command.unreadable", cmd.name, "expected modifier add, remove or value get", report=True)


def _modifier_key(cmd, entity, word: str) -> tuple:
    """(the modifier's key, as messages show it): an id from 1.21, else a UUID (UuidArgument) as four ints."""
    if entity.release >= living.MODIFIER_IDS:
        return _resource(word), _resource(word)
    if not is_uuid(word):
        raise CommandFailure("dpemu.command.unreadable", cmd.name, f"expected a UUID, got '{word}'", report=True)
    key = uuid_ints(word)
    return key, uuid_string(key)


def _string_then_words(cmd, start: int) -> tuple[str, list[str]]:
    """The string argument at ``start`` (StringArgumentType.string: quoted, or one word) and the
    words after it."""
    reader = Reader(cmd.text, cmd.loc, (26, 2, 0))
    reader.pos = start
    try:
        label = reader.string()
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error.message, report=True) from None
    return label, cmd.text[reader.pos:].split()


# ---------------------------------------------------------------------- damage
BYPASSES_INVULNERABILITY = {"minecraft:out_of_world", "minecraft:generic_kill"}


def damage(env, cmd: ast.GenericCommand, ctx) -> int:
    """``damage TARGET AMOUNT [TYPE] [at POS | by ENTITY [from CAUSE]]``: the target is hurt (no
    AI) by a source of that type whose entity is CAUSE, else ENTITY (DamageCommand: the responsible
    entity earns the kill credit and fires the hurt triggers), from POS or ENTITY's position (where
    its knockback comes from: :func:`emulator.world.combat.hurt`)."""
    words, target = arguments(cmd)
    entity = single(env.state, target_word(cmd, words, 0, target), ctx)
    amount = _number(cmd, words, 1)
    damage_type = _resource(words[2]) if len(words) > 2 and words[2] not in ("at", "by") else "minecraft:generic"
    direct = _source_entity(env, words, target, "by", ctx)
    cause = _source_entity(env, words, target, "from", ctx) or direct
    source = combat.DamageSource(damage_type, cause, direct, _source_position(env, cmd, words, ctx))
    if not living.is_living(entity.type) or not combat.hurt(env.state, entity, amount, source,
                                                            damage_type in BYPASSES_INVULNERABILITY):
        raise CommandFailure("commands.damage.invulnerable")
    return 1


def _source_position(env, cmd, words: list, ctx) -> tuple[float, float, float] | None:
    """The position after ``at`` (Vec3Argument: centred x and z), None without it."""
    if "at" not in words:
        return None
    start = words.index("at") + 1
    reader = Reader(" ".join(w for w in words[start:start + 3] if w is not None), cmd.loc, tuple(env.state.version))
    try:
        vec = vec3(reader)
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, error.message, report=True) from None
    return world_source(env.state, ctx).position_of(vec)


def _source_entity(env, words: list, target, keyword: str, ctx):
    """The one entity after ``by`` / ``from`` (EntityArgument.getEntity), None without the keyword
    (``target``: the command's first selector, where its word is None)."""
    if keyword not in words or words.index(keyword) + 1 >= len(words):
        return None
    word = words[words.index(keyword) + 1]
    try:
        return single(env.state, target if word is None else parse_target(word), ctx)
    except ValueError as error:
        raise CommandFailure("dpemu.command.unreadable", "damage", str(error), report=True) from None


# ---------------------------------------------------------------------- gamemode
GAME_MODES = ("survival", "creative", "adventure", "spectator")


def gamemode(env, cmd: ast.GenericCommand, ctx) -> int:
    """``gamemode MODE [TARGETS]`` (GameModeCommand.setMode): the players whose mode changed; a
    player already in that mode does not count, and the command does not fail for it. Without
    targets, the executor (a player)."""
    words, target = arguments(cmd)
    mode = words[0] if words else ""
    if mode not in GAME_MODES:
        raise CommandFailure("dpemu.command.unreadable", cmd.name, f"unknown game mode '{mode}'", report=True)
    if len(words) > 1:
        players = players_found(env.state, target_word(cmd, words, 1, target), ctx)
    else:
        player = _executor_required(env.state, ctx)
        if not player.is_player:
            raise CommandFailure("permissions.requires.player")
        players = [player]
    changed = [p for p in players if p.gamemode != mode]
    for player in changed:
        player.gamemode = mode
        player.flying = flying_after(mode, player.flying)
        if mode != "spectator":  # ServerPlayer.setGameMode: setCamera(this)
            spectating.stop(env.state, player)
    return len(changed)


def spectate(env, cmd: ast.GenericCommand, ctx) -> int:
    """``spectate [TARGET [PLAYER]]`` (SpectateCommand): PLAYER (the executor by default) watches
    through TARGET's eyes, or stops watching without one."""
    words, target = arguments(cmd)
    state = env.state
    camera = single(state, target_word(cmd, words, 0, target), ctx) if words else None
    if len(words) > 1:
        try:
            player = single_player(state, parse_target(words[1]), ctx)
        except ValueError as error:
            raise CommandFailure("dpemu.command.unreadable", cmd.name, str(error), report=True) from None
    else:
        player = _executor_required(state, ctx)
        if not player.is_player:
            raise CommandFailure("permissions.requires.player")
    return spectating.spectate(state, camera, player)


# ---------------------------------------------------------------------- waypoint
# ChatFormatting's colours (ColorArgument)
TEXT_COLORS = {"black": 0x000000, "dark_blue": 0x0000AA, "dark_green": 0x00AA00, "dark_aqua": 0x00AAAA,
               "dark_red": 0xAA0000, "dark_purple": 0xAA00AA, "gold": 0xFFAA00, "gray": 0xAAAAAA,
               "dark_gray": 0x555555, "blue": 0x5555FF, "green": 0x55FF55, "aqua": 0x55FFFF, "red": 0xFF5555,
               "light_purple": 0xFF55FF, "yellow": 0xFFFF55, "white": 0xFFFFFF}
DEFAULT_STYLE = "minecraft:default"


def waypoint(env, cmd: ast.GenericCommand, ctx) -> int:
    """``waypoint modify ENTITY color COLOR|hex RRGGBB|reset`` and ``style set STYLE|reset``
    (WaypointCommand, 1.21.6+): the living entity's locator bar icon, saved as
    ``locator_bar_icon {style, color}`` while either differs from the default (LivingEntity
    .addAdditionalSaveData); the result is 0. ``waypoint list`` is not modelled."""
    words, target = arguments(cmd)
    if words[:1] != ["modify"]:
        raise Unmodelled("waypoint list (which entities transmit a waypoint)")
    entity = single(env.state, target_word(cmd, words, 1, target), ctx)
    if not living.is_living(entity.type):  # WaypointArgument.getWaypoint
        raise CommandFailure("argument.waypoint.invalid")
    icon = entity.data.get("locator_bar_icon")
    style = str(icon.get("style", DEFAULT_STYLE)) if isinstance(icon, Compound) else DEFAULT_STYLE
    color = icon.get("color") if isinstance(icon, Compound) else None
    kind, value = words[2], words[3:]
    if kind == "color":
        color = None if value == ["reset"] else Int(int(value[1], 16) if value[0] == "hex" else TEXT_COLORS[value[0]])
    else:
        style = DEFAULT_STYLE if value == ["reset"] else normalise_id(value[1])
    entity.data.pop("locator_bar_icon", None)
    if style != DEFAULT_STYLE or color is not None:  # Waypoint.Icon.hasData
        icon = Compound(style=String(style))
        if color is not None:
            icon["color"] = color
        entity.data["locator_bar_icon"] = icon
    return 0


HANDLERS = {"gamemode": gamemode, "spectate": spectate, "xp": experience, "experience": experience, "effect": effect,
            "attribute": attribute, "damage": damage, "waypoint": waypoint}
