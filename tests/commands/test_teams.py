"""``team`` (TeamCommand): results, failures and who is in which team, on both backends.
Sources (decompiled 1.21): server/commands/TeamCommand.java (createTeam, deleteTeam, emptyTeam,
joinTeam, leaveTeam, setColor ... return values and errors), world/scores/Scoreboard.java
(addPlayerToTeam leaves the old team first), world/scores/PlayerTeam.java (the defaults)."""
import pytest

from tests.world.world_emulator import emulator


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_team_results_failures_and_membership(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:go": "\n".join([
        "execute store result score #add o run team add a",
        "execute store result score #add2 o run team add b {\"text\":\"Bee\"}",
        "execute store success score #dup o run team add a",
        "summon marker 0 0 0 {Tags:[\"m\"]}",
        "summon pig 0 0 0 {Tags:[\"p\"]}",
        "execute store result score #join o run team join a @e[tag=p]",
        "execute as @e[tag=m] run team join b",
        "execute store result score #fake o run team join a #fake",
        "execute store result score #pigs o if entity @e[team=a]",
        "execute store result score #markers o if entity @e[team=b]",
        "execute store result score #none o if entity @e[team=]",
        "execute store result score #list o run team list a",
        "execute store result score #color o run team modify a color red",
        "execute store success score #again o run team modify a color red",
        "execute store success score #ff o run team modify a friendlyFire true",
        "execute store result score #pre o run team modify a prefix {\"text\":\"A \"}",
        "execute store result score #leave o run team leave @e[tag=p]",
        "execute store result score #after o if entity @e[team=a]",
        "execute store result score #empty o run team empty a",
        "execute store success score #empty2 o run team empty a",
        "execute store success score #unknown o run team join c @e[tag=p]",
        "execute store result score #remove o run team remove b",
    ])})
    emu.call("t:go")
    got = {h: emu.score(h, "o") for h in ("#add", "#add2", "#dup", "#join", "#fake", "#pigs", "#markers", "#none",
                                          "#list", "#color", "#again", "#ff", "#pre", "#leave", "#after",
                                          "#empty", "#empty2", "#unknown", "#remove")}
    # team= tests living entities only (the marker in b is not counted); a name with no entity joins too
    assert got == {"#add": 1, "#add2": 2, "#dup": 0, "#join": 1, "#fake": 1, "#pigs": 1, "#markers": 0, "#none": 0,
                   "#list": 2, "#color": 0, "#again": 0, "#ff": 0, "#pre": 1, "#leave": 1, "#after": 0,
                   "#empty": 1, "#empty2": 0, "#unknown": 0, "#remove": 1}
    assert emu.state.teams.teams["a"].color == "red" and emu.state.teams.teams["a"].prefix == {"text": "A "}


def test_a_mob_summoned_with_team_joins_it(tmp_path):
    """LivingEntity.readAdditionalSaveData: ``Team`` names a team the mob joins (an unknown one is
    skipped with a log line); addAdditionalSaveData never writes it back. A marker keeps it as data."""
    emu = emulator(tmp_path, "python", {"t:go": "\n".join([
        "team add a",
        "summon pig 0 0 0 {Team:\"a\",Tags:[\"in\"]}",
        "summon pig 0 0 0 {Team:\"nope\",Tags:[\"out\"]}",
        "execute store result score #in o if entity @e[tag=in,team=a]",
        "execute store result score #out o if entity @e[tag=out,team=]",
        "execute store success score #saved o run data get entity @e[tag=in,limit=1] Team",
    ])})
    emu.call("t:go")
    assert [emu.score(h, "o") for h in ("#in", "#out", "#saved")] == [1, 1, 0]
    assert len(emu.state.teams.teams["a"].members) == 1


def test_data_merge_with_team_joins_it_as_loading_does(tmp_path):
    """``data merge entity`` loads the merged NBT (EntityDataAccessor.setData: Entity.load), so a
    living entity's ``Team`` joins the team as a summon's does; a marker keeps it as plain data."""
    emu = emulator(tmp_path, "python", {"t:go": "\n".join([
        "team add a",
        "summon pig 0 0 0 {Tags:[\"p\"]}",
        "summon marker 0 0 0 {Tags:[\"m\"]}",
        "data merge entity @e[tag=p,limit=1] {Team:\"a\"}",
        "data merge entity @e[tag=m,limit=1] {Team:\"a\"}",
        "execute store result score #in o if entity @e[team=a]",
        "execute store success score #saved o run data get entity @e[tag=p,limit=1] Team",
        "execute store success score #kept o run data get entity @e[tag=m,limit=1] Team",
    ])})
    emu.call("t:go")
    assert [emu.score(h, "o") for h in ("#in", "#saved", "#kept")] == [1, 0, 1]
    assert emu.state.teams.teams["a"].members == [emu.state.entities.entities[0].score_holder]
