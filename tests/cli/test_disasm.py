"""``dpemu disasm``: instructions beside their source lines."""
from __future__ import annotations

from click.testing import CliRunner

from emulator.cli import main
from tests.backends.programs import write_pack


def test_disasm_shows_source_and_decoded_operands(tmp_path):
    pack = write_pack(tmp_path / "pack", {
        "t:f": "# comment\nexecute if score #a o matches 1.. run scoreboard players operation #a o *= #b o\nfunction t:g",
        "t:g": "say hi",
    })
    result = CliRunner().invoke(main, ["disasm", str(pack), "t:f"])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0].split("|")[0].strip() == "2"
    assert "execute if score #a o matches 1.." in lines[0]
    ops = [line.split()[2] for line in lines if line.startswith("      |")]
    assert ops == ["IFRUN", "OPER*=", "CALL", "FEND"]  # a condition and one instruction: fused
    assert any("IFRUN #a o 1 2147483647 ->6 0" in line for line in lines)
    assert any("OPER*= #a o #b o" in line for line in lines)
    assert any("CALL t:g" in line for line in lines)


def test_disasm_host_ops(tmp_path):
    pack = write_pack(tmp_path / "pack", {"t:f": "execute as @e[nbt={}] store result storage t:s v long 1 run say hi"})
    result = CliRunner().invoke(main, ["disasm", str(pack), "t:f"])
    assert result.exit_code == 0, result.output
    ops = [line.split(None, 3)[2:] for line in result.output.splitlines() if line.startswith("      |")]
    # host stages carry the forked flag: after `as`, a failing stage drops only its context
    # after a stage that can fork, STAGESDONE collects each context before any runs the command;
    # HOSTGUARD's selector (@e: the arguments before nbt) skips the host's `as` when it finds nobody
    assert ops == [["CMD", "->11"], ["HOSTGUARD", "sel#0 0"], ["HOSTSTAGE", "[ExAs] 1"], ["HOSTSTAGE", "[StoreData] 1"],
                   ["STAGESDONE", "->11 0"], ["HOST", "[Say]"], ["HOSTSTORE", "[StoreData]"], ["ENDCMD"], ["FEND"]]


def test_disasm_names_the_wildcard(tmp_path):
    pack = write_pack(tmp_path / "pack", {"t:f": "scoreboard players reset * o\n"
                                                 "execute store result score * o run scoreboard players get #a o"})
    result = CliRunner().invoke(main, ["disasm", str(pack), "t:f"])
    assert result.exit_code == 0, result.output
    assert "SELHOLDERS * 0" in result.output and "STORE 0 * o" in result.output


def test_disasm_unknown_function(tmp_path):
    pack = write_pack(tmp_path / "pack", {"t:f": "say hi"})
    result = CliRunner().invoke(main, ["disasm", str(pack), "t:nope"])
    assert result.exit_code == 2 and "no function t:nope" in result.output
