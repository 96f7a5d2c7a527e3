"""Command blocks (emulator.world.command_blocks) on both backends. Sources: CommandBlock.tick,
execute, executeChain, neighborChanged/setPoweredAndUpdate; CommandBlockEntity.loadAdditional ->
setAutomatic (auto schedules the tick 1 game tick later), markConditionMet (a conditional block
needs SuccessCount > 0 behind it); BaseCommandBlock.performCommand (SuccessCount, LastExecution,
LastOutput as ``[HH:mm:ss] `` and the message)."""
import pytest

from emulator.api import Emulator
from tests.backends.programs import write_pack

SETUP = "scoreboard objectives add v dummy\n"


def world(tmp_path, main: str, backend: str, pack_format: int = 61) -> Emulator:
    emu = Emulator(backend=backend)
    emu.load(write_pack(tmp_path / "pack", {"t:main": SETUP + main}, pack_format=pack_format))
    emu.start()
    emu.runtime.call("t:main")
    return emu


def block(emu, pos, key):
    return emu.state.blocks.entity(pos).get(key)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_auto_impulse_block_runs_once_the_next_tick(tmp_path, backend):
    emu = world(tmp_path, 'setblock 0 0 0 command_block{auto:1b,Command:"scoreboard players add #n v 1"}\n', backend)
    assert emu.score("#n", "v") is None
    emu.tick()
    assert emu.score("#n", "v") == 1
    assert block(emu, (0, 0, 0), "SuccessCount") == 1
    assert block(emu, (0, 0, 0), "LastExecution") == emu.state.gametime
    emu.tick(5)
    assert emu.score("#n", "v") == 1


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_repeating_block_runs_every_tick_and_its_chain_follows(tmp_path, backend):
    """The chain block it faces runs right after it when auto; a conditional chain block runs only
    while the block behind it succeeded (here a failing test clears it)."""
    main = ('setblock 0 0 0 repeating_command_block[facing=east]{auto:1b,Command:"scoreboard players add #r v 1"}\n'
            'setblock 1 0 0 chain_command_block[facing=east]{auto:1b,Command:"execute if score #r v matches 3.. '
            'run scoreboard players add #c v 0"}\n'
            'setblock 2 0 0 chain_command_block[facing=east,conditional=true]{auto:1b,'
            'Command:"scoreboard players add #k v 1"}\n')
    emu = world(tmp_path, main, backend)
    emu.tick(4)
    assert emu.score("#r", "v") == 4
    assert emu.score("#k", "v") == 2  # the chain's test held in the 3rd and 4th runs only
    assert block(emu, (1, 0, 0), "SuccessCount") == 1 and block(emu, (2, 0, 0), "conditionMet") == 1


def test_a_redstone_block_powers_an_impulse_block_once(tmp_path):
    """neighborChanged: powered rising schedules the tick; staying powered does not run it again."""
    main = ('setblock 0 0 0 command_block{Command:"scoreboard players add #p v 1"}\n'
            "setblock 1 0 0 redstone_block\n")
    emu = world(tmp_path, main, "python")
    emu.tick(3)
    assert emu.score("#p", "v") == 1 and block(emu, (0, 0, 0), "powered") == 1
    emu.runtime.call("t:main")  # the block is set again (unpowered), then the redstone block anew: no change
    emu.tick(2)
    assert emu.score("#p", "v") == 1


def test_last_output_holds_the_time_and_is_not_modelled_beyond(tmp_path):
    """BaseCommandBlock's source: ``[HH:mm:ss] `` and the message (a text component from 1.21.5;
    Bookshelf's bs.time reads the time from LastOutput.text)."""
    emu = world(tmp_path, 'setblock 0 0 0 command_block{auto:1b,Command:"scoreboard players add #n v 1"}\n'
                          "data modify storage t:t time set string block 0 0 0 LastOutput.text 1 9\n",
                "python", pack_format=71)
    emu.tick()
    text = str(block(emu, (0, 0, 0), "LastOutput")["text"])
    assert text[0] == "[" and text[3] == ":" and text[6] == ":" and text.endswith("] ")
    assert any(d.unmodelled and "LastOutput" in d.message for d in emu.diagnostics)


def test_data_merge_auto_starts_a_block(tmp_path):
    """CommandBlockEntity.loadAdditional -> setAutomatic: auto rising schedules the tick."""
    emu = world(tmp_path, 'setblock 0 0 0 command_block{Command:"scoreboard players add #n v 1"}\n'
                          "data merge block 0 0 0 {auto:1b}\n", "python")
    emu.tick()
    assert emu.score("#n", "v") == 1


def last_output(emu, pos=(0, 0, 0)):
    return block(emu, pos, "LastOutput")


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_help_sends_its_usage_and_the_block_keeps_the_last_message(tmp_path, backend):
    """HelpCommand sends ``/TEXT `` + CommandDispatcher.getSmartUsage of each child of the node it
    reached; BaseCommandBlock.sendSystemMessage keeps ``[HH:mm:ss] `` + the message (1.21.5+: the
    component's tag; Bookshelf's bs.time runs ``help me``). Its result is the number of messages."""
    main = ('setblock 0 0 0 command_block{auto:1b,Command:"help me"}\n'
            'setblock 2 0 0 command_block{auto:1b,Command:"execute store result score #k v run help kill"}\n')
    emu = world(tmp_path, main, backend, pack_format=71)
    emu.tick()
    out = last_output(emu)
    assert list(out["extra"]) == ["/me <action>"] and str(out["text"]).endswith("] ")
    assert list(last_output(emu, (2, 0, 0))["extra"]) == ["/kill [<targets>]"]  # kill runs without targets
    assert emu.score("#k", "v") == 1 and block(emu, (0, 0, 0), "SuccessCount") == 1
    assert not any(d.unmodelled for d in emu.diagnostics)


def test_help_of_a_command_the_block_may_not_use_fails_in_red(tmp_path):
    """``stop`` needs level 4, a command block has 2: commands.help.failed, sent with
    CommandSourceStack.sendFailure (the message in red); before 1.21.5 LastOutput is a JSON string."""
    emu = world(tmp_path, 'setblock 0 0 0 command_block{auto:1b,Command:"help stop"}\n', "python", pack_format=61)
    emu.tick()
    import json
    out = json.loads(str(last_output(emu)))
    assert out["extra"] == [{"text": "", "extra": [{"translate": "commands.help.failed"}], "color": "red"}]
    assert block(emu, (0, 0, 0), "SuccessCount") == 0


def test_a_command_that_sends_nothing_leaves_no_output_and_feedback_rules_apply(tmp_path):
    """performCommand clears lastOutput before running; tellraw sends its source nothing. A success
    is kept only while sendCommandFeedback is on (BaseCommandBlock.acceptsSuccess), nothing at all
    without TrackOutput; ``Searge`` is the game's easter egg."""
    main = ('setblock 0 0 0 command_block{auto:1b,Command:"tellraw @a \\"hi\\"",LastOutput:\'{"text":"old"}\'}\n'
            "gamerule sendCommandFeedback false\n"
            'setblock 1 0 0 command_block{auto:1b,Command:"help me"}\n'
            'setblock 2 0 0 command_block{auto:1b,Command:"help me",TrackOutput:0b}\n'
            'setblock 3 0 0 command_block{auto:1b,Command:"searge"}\n')
    emu = world(tmp_path, main, "python", pack_format=61)
    emu.add_player("Alex")  # tellraw to nobody fails ("No player was found": a message not modelled)
    emu.tick()
    assert last_output(emu) is None and last_output(emu, (1, 0, 0)) is None and last_output(emu, (2, 0, 0)) is None
    assert str(last_output(emu, (3, 0, 0))) == '"#itzlipofutzli"' and block(emu, (3, 0, 0), "SuccessCount") == 1
    assert not any(d.unmodelled for d in emu.diagnostics)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_command_block_in_another_level_runs_there(tmp_path, backend):
    """The block's level schedules its tick (CommandBlockEntity.scheduleTick on its own level) and
    BaseCommandBlock.createCommandSourceStack sources the command in that level: ``~`` places the
    stone in the nether beside it; a redstone block there powers an impulse block."""
    main = ('execute in minecraft:the_nether run setblock 0 64 0 command_block{auto:1b,TrackOutput:0b,'
            'Command:"setblock ~ ~1 ~ stone"}\n'
            'execute in minecraft:the_nether run setblock 3 64 0 command_block{TrackOutput:0b,'
            'Command:"scoreboard players add #p v 1"}\n'
            'execute in minecraft:the_nether run setblock 4 64 0 redstone_block\n')
    emu = world(tmp_path, main, backend)
    emu.tick()
    nether = emu.state.blocks_in("minecraft:the_nether")
    assert nether.get((0, 65, 0)).id == "minecraft:stone" and emu.state.blocks.get((0, 65, 0)).is_air
    assert emu.score("#p", "v") == 1
    assert not any(d.unmodelled for d in emu.diagnostics)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_success_count_counts_each_context_the_command_ran_in(tmp_path, backend):
    """BaseCommandBlock.performCommand: the source's callback adds one per successful result, so an
    execute forking over three entities counts 3, over none 0."""
    main = ('summon marker 0 5 0 {Tags:["t"]}\nsummon marker 0 5 0 {Tags:["t"]}\nsummon marker 0 5 0 {Tags:["t"]}\n'
            'setblock 0 0 0 command_block{auto:1b,Command:"execute as @e[tag=t] run scoreboard players add @s v 1"}\n'
            'setblock 2 0 0 command_block{auto:1b,Command:"execute as @e[tag=none] run scoreboard players add @s v 1"}\n'
            'setblock 4 0 0 command_block{auto:1b,Command:"execute as @e[tag=t] if score @s v matches 1 at @s '
            'positioned ~ ~1 ~ run scoreboard players add #n v 1"}\n')
    emu = world(tmp_path, main, backend)
    emu.tick()
    assert block(emu, (0, 0, 0), "SuccessCount") == 3 and block(emu, (2, 0, 0), "SuccessCount") == 0
    assert [e["scores"].get("v") for e in emu.entities("@e[tag=t]")] == [1, 1, 1]
    assert block(emu, (4, 0, 0), "SuccessCount") == 3 and emu.score("#n", "v") == 3



def _function_world(tmp_path, blocks: str) -> Emulator:
    files = {"t:main": SETUP + blocks, "t:one": "scoreboard players add #one v 1",
             "t:two": "scoreboard players add #two v 1", "t:returns": "execute if score #one v matches 1.. run return 1"}
    pack = write_pack(tmp_path / "pack", files, pack_format=71)
    (pack / "data/t/tags/function").mkdir(parents=True)
    (pack / "data/t/tags/function/each.json").write_text('{"values": ["t:one", "t:two"]}')
    emu = Emulator(backend="python")
    emu.load(pack)
    emu.start()
    emu.runtime.call("t:main")
    return emu


def test_function_sends_running_function(tmp_path):
    """FunctionCommand.FunctionCustomExecutor.runGuarded sends ``commands.function.scheduled.single``
    with the function's id (Component.translationArg: a literal), or ``...multiple`` with the ids
    joined by a grey ", " (ComponentUtils.formatList) for a tag of several, before they run (a
    library's repeating block ticking a function tag every tick, as a forceload module does)."""
    emu = _function_world(tmp_path, 'setblock 0 0 0 repeating_command_block{auto:1b,Command:"function #t:each"}\n'
                                    'setblock 2 0 0 command_block{auto:1b,Command:"function t:one"}\n')
    emu.tick(2)
    assert emu.score("#one", "v") == 3 and emu.score("#two", "v") == 2  # the repeating block ran twice
    many = last_output(emu)["extra"][0]
    assert str(many["translate"]) == "commands.function.scheduled.multiple"
    assert list(many["with"][0]["extra"]) == ["t:one", {"text": ", ", "color": "gray"}, "t:two"]
    one = last_output(emu, (2, 0, 0))["extra"][0]
    assert str(one["translate"]) == "commands.function.scheduled.single" and list(one["with"]) == ["t:one"]
    assert not any(d.unmodelled for d in emu.diagnostics)


def test_a_function_that_can_return_leaves_its_output_not_modelled(tmp_path):
    """A function that returns a value then sends ``commands.function.result``
    (FunctionCommand.decorateOutputIfNeeded: the block's source is not silent), which is not
    produced here: the block's output is not modelled; ``execute ... run function`` neither (the
    message goes once per context it ran in)."""
    for command in ("function t:returns", "execute if score #one v matches 0.. run function t:one"):
        emu = _function_world(tmp_path / command.replace(" ", "_").replace(":", "_").replace(".", "_"),
                              f'setblock 0 0 0 command_block{{auto:1b,Command:"{command}"}}\n')
        emu.tick()
        assert any(d.unmodelled and "LastOutput" in d.message for d in emu.diagnostics)
