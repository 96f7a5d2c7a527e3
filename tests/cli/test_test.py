"""``dpemu test``: output, exit code, -k, JUnit XML (the pool datapack's own test files run in
test_pool_pack_suite.py)."""
import xml.etree.ElementTree as ET

from click.testing import CliRunner

from emulator.cli import main

SETUP = "scoreboard objectives add o dummy\nscoreboard players set $x o 4\n"
FILES = {
    "demo/test/good.mcfunction": SETUP + "assert score $x o matches 4\n",
    "demo/test/bad.mcfunction": SETUP + "assert score $x o matches 5\n",
    "demo/test/skip.mcfunction": "# @optional\nfail \"allowed to fail\"\n",
}


def test_output_summary_and_exit_code(pack):
    root = pack(FILES)
    result = CliRunner().invoke(main, ["test", str(root)])
    lines = result.output.splitlines()
    assert result.exit_code == 1
    assert lines[-1] == "1 passed, 1 failed, 1 skipped"
    assert "FAIL demo:bad" in lines
    assert any(line.endswith("bad.mcfunction:3: Expected score $x o to match 5, found 4") for line in lines)


def test_filter_passes_with_exit_zero(pack):
    result = CliRunner().invoke(main, ["test", str(pack(FILES)), "-k", "good", "--backend", "python"])
    assert result.exit_code == 0
    assert result.output.splitlines() == ["PASS demo:good", "1 passed, 0 failed"]


def test_junit_xml_structure(pack, tmp_path):
    out = tmp_path / "junit.xml"
    CliRunner().invoke(main, ["test", str(pack(FILES)), "--junit", str(out)])
    suite = ET.parse(out).getroot().find("testsuite")
    assert (suite.get("tests"), suite.get("failures"), suite.get("skipped")) == ("3", "1", "1")
    cases = {c.get("name"): c for c in suite.findall("testcase")}
    assert set(cases) == {"good", "bad", "skip"} and cases["bad"].get("classname") == "demo"
    failure = cases["bad"].find("failure")
    assert failure.get("message") == "Expected score $x o to match 5, found 4"
    assert "bad.mcfunction:3: " in failure.text and cases["bad"].get("line") == "3"
    assert cases["skip"].find("skipped") is not None and cases["good"].find("failure") is None


def test_log_shows_what_each_test_printed(pack, tmp_path):
    # the output lines while each test ran (what its `assert chat` could see), under its verdict
    # with --log, and as its JUnit system-out
    root = pack({"demo/test/chatty.mcfunction": "# @dummy\n" + SETUP + "say hi\n"
                                                "tellraw @a {\"score\":{\"name\":\"$x\",\"objective\":\"o\"}}\n"
                                                "await delay 1\nsay later\n"})
    out = tmp_path / "junit.xml"
    lines = CliRunner().invoke(main, ["test", str(root), "--log", "--junit", str(out)]).output.splitlines()
    assert lines[0] == "PASS demo:chatty" and lines[-1] == "1 passed, 0 failed"
    shown = [line.split("  (")[0] for line in lines[1:-1]]
    assert [line.split(": ", 1)[1].split("] ")[-1] for line in shown] == ["hi", "4", "later"], lines  # say: [name] text
    assert all(line.startswith("  | tick ") for line in shown)
    system_out = ET.parse(out).getroot().find("testsuite/testcase/system-out").text.splitlines()
    assert [line.split("  (")[0] for line in system_out] == [line[4:] for line in shown]
    plain = CliRunner().invoke(main, ["test", str(root)]).output.splitlines()
    assert plain == ["PASS demo:chatty", "1 passed, 0 failed"]


def test_a_missing_path_is_a_usage_error(tmp_path):
    result = CliRunner().invoke(main, ["test", str(tmp_path / "nope")])
    assert result.exit_code == 2 and "does not exist" in result.output


def test_no_tests_found_is_said(pack):
    result = CliRunner().invoke(main, ["test", str(pack({"demo/function/f.mcfunction": "say hi\n"}))])
    assert result.exit_code == 0 and "no test files (data/<ns>/test/**.mcfunction) under" in result.output
    assert result.output.splitlines()[-1] == "0 passed, 0 failed"


def test_runtime_errors_show_with_the_test_and_fail_it_under_strict(pack):
    root = pack({"demo/test/div.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set #z o 0\n"
                                             "scoreboard players operation #a o /= #z o\nassert score #z o matches 0\n"})
    relaxed = CliRunner().invoke(main, ["test", str(root)])
    assert relaxed.exit_code == 0 and "PASS demo:div" in relaxed.output and "Cannot divide by zero" in relaxed.output
    strict = CliRunner().invoke(main, ["test", str(root), "--strict"])
    assert strict.exit_code == 1 and "1 runtime error(s) during the test (--strict)" in strict.output


def test_with_loads_a_library_beneath_each_pack_under_test(tmp_path):
    from tests.conftest import write_pack
    lib = write_pack(tmp_path / "lib", {"lib/function/double.mcfunction": "scoreboard players operation $x o += $x o\n"},
                     load=["lib:init"])
    (lib / "data/lib/function/init.mcfunction").write_text("scoreboard objectives add o dummy\n")
    app = write_pack(tmp_path / "app", {"app/test/uses_lib.mcfunction":
                                        "scoreboard players set $x o 21\nfunction lib:double\nassert score $x o matches 42\n"})
    alone = CliRunner().invoke(main, ["test", str(app)])
    assert alone.exit_code == 1  # without the library the call finds nothing
    both = CliRunner().invoke(main, ["test", str(app), "--with", str(lib)])
    assert both.exit_code == 0, both.output
    assert both.output.splitlines()[-1] == "1 passed, 0 failed"


def test_together_runs_every_modules_tests_in_one_world(tmp_path):
    from tests.conftest import write_pack
    a = write_pack(tmp_path / "a", {"a/function/init.mcfunction": "scoreboard objectives add shared dummy\n",
                                    "a/test/sees_b.mcfunction": "assert score $b shared matches 2\n"}, load=["a:init"])
    b = write_pack(tmp_path / "b", {"b/function/init.mcfunction": "scoreboard players set $b shared 2\n",
                                    "b/test/sees_a.mcfunction": "assert score $b shared matches 2\n"}, load=["b:init"])
    apart = CliRunner().invoke(main, ["test", str(a), str(b)])
    assert apart.output.splitlines()[-1] == "0 passed, 2 failed"  # each pack alone lacks the other's half
    together = CliRunner().invoke(main, ["test", str(a), str(b), "--together"])
    assert together.exit_code == 0, together.output
    assert together.output.splitlines()[-1] == "2 passed, 0 failed"


def test_a_librarys_load_error_is_printed_once(tmp_path):
    from tests.conftest import write_pack
    lib = write_pack(tmp_path / "lib", {"lib/function/bad.mcfunction": "scoreboard players frobnicate\n"})
    apps = [write_pack(tmp_path / name, {f"{name}/test/t.mcfunction": "succeed\n"}) for name in ("one", "two")]
    result = CliRunner().invoke(main, ["test", *map(str, apps), "--with", str(lib)])
    errors = [line for line in result.output.splitlines() if "bad.mcfunction" in line and "error" in line]
    assert len(errors) == 1, result.output
