"""The game's vanilla registry tags: the ``data/minecraft/tags/<registry>/`` files of its built-in
data pack, which every world loads first, under the packs.

Source: the game jar the user already has (``--game-jar PATH``). Both jars carry the files: the
client jar at its root, the server jar (a bundler since 1.18) inside the nested
``META-INF/versions/<v>/server-<v>.jar``; either is read as a zip, without Java. Tags change with
every release and no maintained Python package ships them (PrismarineJS's minecraft-data has
registries and block states but no tags), so the user's own jar of the targeted release is the
faithful source; nothing is bundled beyond :data:`BUILTIN_TAGS`.

Without a jar, :data:`BUILTIN_TAGS` holds a few vanilla entity type tags (copied from the 1.21
jar's ``data/minecraft/tags/entity_type``), the damage type tags the hurt rules read (1.21's
DamageTypeTagsProvider) and the block tags a campfire's smoke and a hopper's reach through a
block read (VanillaBlockTagsProvider); any other ``#minecraft:`` tag is unknown to the
emulator, and a command reading one says it is not modelled instead of matching nothing.
"""
from __future__ import annotations

import io
import zipfile
from pathlib import Path

BUILTIN_TAGS: dict[str, dict[str, frozenset[str]]] = {
    "entity_type": {
        "minecraft:skeletons": frozenset({
            "minecraft:skeleton", "minecraft:stray", "minecraft:wither_skeleton", "minecraft:skeleton_horse",
            "minecraft:bogged"}),
        "minecraft:zombies": frozenset({
            "minecraft:zombie_horse", "minecraft:zombie", "minecraft:zombie_villager",
            "minecraft:zombified_piglin", "minecraft:zoglin", "minecraft:drowned", "minecraft:husk"}),
        "minecraft:arrows": frozenset({"minecraft:arrow", "minecraft:spectral_arrow"}),
        "minecraft:raiders": frozenset({
            "minecraft:evoker", "minecraft:pillager", "minecraft:ravager", "minecraft:vindicator",
            "minecraft:illusioner", "minecraft:witch"}),
        "minecraft:impact_projectiles": frozenset({
            "minecraft:arrow", "minecraft:spectral_arrow", "minecraft:firework_rocket", "minecraft:snowball",
            "minecraft:fireball", "minecraft:small_fireball", "minecraft:egg", "minecraft:trident",
            "minecraft:dragon_fireball", "minecraft:wither_skull", "minecraft:wind_charge",
            "minecraft:breeze_wind_charge"}),
    },
    "block": {
        "minecraft:campfires": frozenset({"minecraft:campfire", "minecraft:soul_campfire"}),
        # VanillaBlockTagsProvider: #beehives (a hopper takes items in through them)
        "minecraft:does_not_block_hoppers": frozenset({"minecraft:bee_nest", "minecraft:beehive"}),
    },
    "damage_type": {
        "minecraft:bypasses_armor": frozenset("minecraft:" + t for t in (
            "on_fire in_wall cramming drown fly_into_wall generic wither dragon_breath starve fall freeze "
            "stalagmite magic indirect_magic out_of_world generic_kill sonic_boom outside_border").split()),
        "minecraft:is_fire": frozenset("minecraft:" + t for t in (
            "in_fire campfire on_fire lava hot_floor unattributed_fireball fireball").split()),
        "minecraft:no_knockback": frozenset("minecraft:" + t for t in (
            "explosion player_explosion bad_respawn_point in_fire lightning_bolt on_fire lava hot_floor in_wall "
            "cramming drown starve cactus fall fly_into_wall out_of_world generic magic wither dragon_breath "
            "dry_out sweet_berry_bush freeze stalagmite outside_border generic_kill campfire").split()),
        # the falls CombatTracker.getMostSignificantFall weighs
        "minecraft:is_fall": frozenset({"minecraft:fall", "minecraft:ender_pearl", "minecraft:stalagmite"}),
        # what the resistance effect does not reduce (LivingEntity.getDamageAfterMagicAbsorb)
        "minecraft:bypasses_effects": frozenset({"minecraft:starve"}),
        "minecraft:bypasses_resistance": frozenset({"minecraft:out_of_world", "minecraft:generic_kill"}),
        # what a totem of undying does not save from (LivingEntity.checkTotemDeathProtection)
        "minecraft:bypasses_invulnerability": frozenset({"minecraft:out_of_world", "minecraft:generic_kill"}),
        # the players' damage game rules (Player.isInvulnerableTo)
        "minecraft:is_drowning": frozenset({"minecraft:drown"}),
        "minecraft:is_freezing": frozenset({"minecraft:freeze"}),
        "minecraft:always_most_significant_fall": frozenset({"minecraft:out_of_world"}),
    },
}


class GameJarError(Exception):
    """The file is not a readable game jar."""


def open_game_jar(path: str | Path) -> zipfile.Path:
    """The root of the jar's data (a zip path holding ``data/minecraft/tags/...``): the jar itself,
    or the server jar nested in a bundler jar. Raises :class:`GameJarError` when it is neither."""
    try:
        archive = zipfile.ZipFile(path)
        names = archive.namelist()
    except (OSError, zipfile.BadZipFile) as error:
        raise GameJarError(f"{path}: not a readable game jar ({error})") from None
    if any(n.startswith("data/minecraft/tags/") for n in names):
        return zipfile.Path(archive)
    nested = [n for n in names if n.startswith("META-INF/versions/") and n.endswith(".jar")]
    if nested:
        inner = zipfile.ZipFile(io.BytesIO(archive.read(nested[0])))
        if any(n.startswith("data/minecraft/tags/") for n in inner.namelist()):
            return zipfile.Path(inner)
    raise GameJarError(f"{path}: no data/minecraft/tags in this jar (give the game's client or server jar)")
