"""PackTest's ``dummy use entity`` (emulator.world.entity_use). Sources: misode/packtest
DummyCommand.useEntity (each hand through Player.interactOn until one consumes the action), the
game's Interaction.interact, ItemFrame.interact (1.21.2+ results), Entity.interact."""
import pytest

from tests.testing.test_dummy_hands import run


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_item_frame_takes_the_held_item_then_turns_it(tmp_path, backend):
    result = run(tmp_path, "# @dummy\n" + (
        "summon item_frame ~1 ~1 ~ {Tags:[\"f\"]}\n"
        "give @s stone 3\n"
        "dummy @s use entity @e[tag=f,limit=1]\n"
        "assert data entity @e[tag=f,limit=1] {Item:{id:\"minecraft:stone\",count:1}}\n"
        "assert items entity @s weapon.mainhand stone[count=2]\n"
        "dummy @s use entity @e[tag=f,limit=1]\n"
        "dummy @s use entity @e[tag=f,limit=1]\n"
        "assert data entity @e[tag=f,limit=1] {ItemRotation:2b}\n"
        "assert items entity @s weapon.mainhand stone[count=2]\n"), pack_format=61, backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, refused", [(61, True), (48, False)])
def test_an_empty_frame_with_empty_hands_passes_from_1_21_2(tmp_path, pack_format, refused):
    result = run(tmp_path, "# @dummy\nsummon item_frame ~1 ~1 ~ {Tags:[\"f\"]}\n"
                           "dummy @s use entity @e[tag=f,limit=1]\nfail \"end\"\n", pack_format=pack_format)
    assert (result.status, result.message) == ("failed", "end")
    assert ("cannot interact with that entity" in "\n".join(result.details)) == refused


def test_using_an_entity_without_an_interaction_is_refused(tmp_path):
    result = run(tmp_path, "# @dummy\nsummon marker ~1 ~ ~\ndummy @s use entity @e[type=marker,limit=1]\n"
                           "fail \"end\"\n")
    assert "cannot interact with that entity" in "\n".join(result.details)
