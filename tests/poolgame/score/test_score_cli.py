"""dpemu score on the command line: the table, its JSON, the pictures, and bad input (exit 2)."""
import json
import shutil

import pytest
from click.testing import CliRunner

from emulator.cli import main
from poolgame.shot import DEFAULT_PACK


def run(*args):
    return CliRunner().invoke(main, ["score", *args], catch_exceptions=False)


def test_one_model_prints_its_rows_and_the_json_holds_them(tmp_path):
    out = tmp_path / "score.json"
    result = run("--model", "cushion", "--shots", "1", "--mode", "seeded", "--workers", "1", "--json", str(out))
    assert result.exit_code == 0, result.output
    assert "rebound angle" in result.output and "rows pass" in result.output
    report = json.loads(out.read_text())
    rows = {r["metric"]: r for r in report["rows"]}
    assert rows["rebound_angle"]["pass"] and rows["rebound_angle"]["cases"] > 0
    assert all(r["mode"] == "seeded" for r in report["rows"])


def test_a_failing_row_exits_1(tmp_path):
    # a copy of the pool pack whose cushions apply only half of the normal speed's change
    # (v_n' = -e v_n / 2): the normal-speed ratio is 0.425 where the model says 0.85
    pack = tmp_path / "pool"
    shutil.copytree(DEFAULT_PACK, pack)
    rebound = pack / "data/pool/function/physics/resolve/cushion/rebound.mcfunction"
    text = rebound.read_text()
    flip = "scoreboard players operation #cushion.vn pool.tmp *= #-1 pool.const\n"
    assert text.count(flip) == 1
    rebound.write_text(text.replace(flip, flip + "scoreboard players operation #cushion.vn pool.tmp /= #2 pool.const\n"))
    result = run(str(pack), "--model", "cushion", "--shots", "1", "--mode", "seeded", "--workers", "1")
    assert "FAIL" in result.output and result.exit_code == 1


@pytest.mark.parametrize("args, words", [
    (("--model", "nonsense"), "nonsense"),
    (("--shots", "0"), "--shots"),
    (("--shots", "-3"), "--shots"),
    (("--workers", "0"), "--workers"),
])
def test_bad_options_are_usage_errors(args, words):
    result = run(*args)
    assert result.exit_code == 2 and words in result.output and "Traceback" not in result.output


def test_an_unwritable_plot_folder_is_refused_before_any_work(tmp_path):
    result = run("--plot", str(tmp_path / "missing" / "deeper"))
    assert result.exit_code == 2 and "--plot" in result.output and "rows pass" not in result.output


def test_a_pack_that_is_not_the_pool_pack_is_a_usage_error(tmp_path):
    pack = tmp_path / "other"
    (pack / "data" / "x" / "function").mkdir(parents=True)
    (pack / "pack.mcmeta").write_text('{"pack": {"pack_format": 48, "description": ""}}')
    (pack / "data" / "x" / "function" / "f.mcfunction").write_text("say hi\n")
    result = run(str(pack), "--model", "cue")
    assert result.exit_code == 2 and "not the pool datapack" in result.output


def test_plots_are_written(tmp_path):
    pytest.importorskip("matplotlib")
    result = run("--model", "shots", "--shots", "1", "--workers", "1", "--mode", "both", "--plot", str(tmp_path))
    assert result.exit_code in (0, 1), result.output
    for name in ("paths.png", "histograms.png", "growth.png"):
        assert (tmp_path / name).stat().st_size > 10_000
