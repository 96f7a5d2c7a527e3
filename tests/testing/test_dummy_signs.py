"""Signs: the block entity a ``setblock`` leaves and a dummy's click on one (emulator.world.signs).
Sources: SignBlockEntity.loadAdditional/saveAdditional and executeClickCommandsIfPresent (the
run_command click events of the side the player faces, run as the player at the sign's centre),
isFacingFrontText, SignText.DIRECT_CODEC, SignBlock.useWithoutItem (waxed, ran commands or
editable text: the use is consumed), ComponentSerialization (a plain text collapses to a string)."""
import pytest

from tests.testing.test_dummy_hands import run

CLICK_JSON = ("'{\"text\":\"Go\",\"clickEvent\":{\"action\":\"run_command\",\"value\":\"/scoreboard players add @s %s 1\"}}'")
CLICK_SNBT = "{text:\"Go\",click_event:{action:\"run_command\",command:\"/scoreboard players add @s %s 1\"}}"


def _sign(rotation: int, front: str, back: str, snbt: bool = False) -> str:
    empty = '""' if snbt else "'\"\"'"
    line = CLICK_SNBT if snbt else CLICK_JSON
    return (f"setblock ~2 ~ ~ oak_sign[rotation={rotation}]{{front_text:{{messages:[{line % front},{empty},{empty},"
            f"{empty}]}},back_text:{{messages:[{line % back},{empty},{empty},{empty}]}}}}\n")


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("rotation, side", [(4, "front"), (12, "back")])
def test_a_click_runs_the_commands_of_the_side_the_dummy_faces(tmp_path, backend, rotation, side):
    """rotation 4 faces west (90 degrees), towards the dummy two blocks west of it; 12 faces away."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add front dummy\nscoreboard objectives add back dummy\n"
        + _sign(rotation, "front", "back") +
        "dummy @s use block ~2 ~ ~\n"
        f"assert score @s {side} matches 1\n"
        f"assert not score @s {'back' if side == 'front' else 'front'} matches 1\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_click_events_are_components_from_1_21_5(tmp_path):
    result = run(tmp_path, "# @dummy\nscoreboard objectives add front dummy\nscoreboard objectives add back dummy\n"
                 + _sign(4, "front", "back", snbt=True) +
                 "dummy @s use block ~2 ~ ~\nassert score @s front matches 1\n", pack_format=71)
    assert result.status == "passed", result.report()


def test_the_commands_run_at_the_signs_centre_as_the_player(tmp_path):
    line = ("'{\"text\":\"\",\"clickEvent\":{\"action\":\"run_command\",\"value\":\"summon marker ~ ~ ~ "
            "{Tags:[\\\\\"here\\\\\"]}\"}}'")
    result = run(tmp_path, "# @dummy\n" + (
        f"setblock ~2 ~ ~ oak_sign[rotation=4]{{front_text:{{messages:[{line},'\"\"','\"\"','\"\"']}}}}\n"
        "dummy @s use block ~2 ~ ~\n"
        "execute positioned ~2.5 ~0.5 ~0.5 run assert entity @e[type=marker,tag=here,distance=..0.0001]\n"))
    assert result.status == "passed", result.report()


def test_setblock_gives_a_sign_its_block_entity_read_as_the_game_loads_it(tmp_path):
    """loadAdditional: a side that does not decode (three lines) stays empty; a plain text line is
    saved as its string; color and has_glowing_text default; is_waxed read."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ oak_sign\n"
        "assert block ~2 ~ ~ oak_sign{front_text:{messages:['\"\"','\"\"','\"\"','\"\"'],color:\"black\"},is_waxed:0b}\n"
        "setblock ~2 ~1 ~ oak_sign{front_text:{messages:['{\"text\":\"Hi\"}','\"\"','\"\"','\"\"']},"
        "back_text:{messages:['\"x\"']},is_waxed:1b}\n"
        "assert block ~2 ~1 ~ oak_sign{front_text:{messages:['\"Hi\"','\"\"','\"\"','\"\"'],has_glowing_text:0b},"
        "back_text:{messages:['\"\"','\"\"','\"\"','\"\"']},is_waxed:1b}\n"))
    assert result.status == "passed", result.report()


def test_a_sign_without_commands_consumes_the_use_only_where_its_text_may_be_edited(tmp_path):
    files = {"demo/advancement/used.json": (
        '{"criteria":{"c":{"trigger":"minecraft:default_block_use","conditions":{"location":[{"condition":'
        '"minecraft:block_state_property","block":"minecraft:oak_sign"}]}}}}')}
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ oak_sign[rotation=4]\n"
        "gamemode adventure @s\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert entity @s[advancements={demo:used=false}]\n"
        "gamemode survival @s\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert entity @s[advancements={demo:used=true}]\n"), files=files)
    assert result.status == "passed", result.report()


def test_a_dye_on_a_sign_is_inconclusive(tmp_path):
    result = run(tmp_path, "# @dummy\nsetblock ~2 ~ ~ oak_sign[rotation=4]\ngive @s red_dye\n"
                           "dummy @s use block ~2 ~ ~\n")
    assert result.status == "inconclusive", result.report()
