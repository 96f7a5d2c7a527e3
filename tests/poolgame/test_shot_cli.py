"""`dpemu shot`: a table set up, a shot struck through the pack's API, emulated to rest."""
import json

import pytest

from click.testing import CliRunner

from emulator.cli import main


def run(*args):
    return CliRunner().invoke(main, ["shot", *args], catch_exceptions=False)


def test_gentle_shot_moves_only_the_cue_ball_and_reports_it_as_json():
    # 0.8 m/s across the table (+z) from the head spot: no other ball is in the way
    result = run("--angle", "90", "--speed", "0.8", "--sanitize", "--json", "-")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["at_rest"] and report["overflows"] == [] and report["diagnostics"] == []
    balls = {b["id"]: b for b in report["balls"]}
    assert sorted(balls) == list(range(16))
    assert balls[0]["z_mm"] > 635 + 100 and abs(balls[0]["x_mm"] - 635) < 1
    assert balls[0]["tick"] is not None and balls[0]["tick"] <= report["ticks"]
    assert all(balls[i]["tick"] is None for i in range(1, 16))
    assert report["ticks"] == len(report["commands_per_tick"]["each"])
    assert report["commands_per_tick"]["max"] == max(report["commands_per_tick"]["each"])


def test_shot_out_of_range_prints_the_packs_refusal_in_the_units_typed():
    # the pack says "speed must be 1..6500 (mm/s)"; the option takes m/s
    result = run("--speed", "7")
    assert result.exit_code == 1
    assert "shot refused: --speed must be 0.001..6.5 m/s" in result.output
    result = run("--speed", "1", "--elevation", "95")
    assert "shot refused: --elevation must be 0..89 degrees" in result.output
    result = run("--speed", "1", "--tip", "0,-0.7")
    assert "shot refused: --tip Y must be -0.5..0.5 ball radii" in result.output


def test_the_json_keeps_the_packs_own_refusal():
    result = run("--speed", "7", "--json", "-")
    assert json.loads(result.stdout)["refused"] == ["Pool: shot refused: speed must be 1..6500 (mm/s)"]


@pytest.mark.parametrize("args, option", [
    (("--speed", "nan"), "--speed"), (("--speed", "inf"), "--speed"), (("--speed", "1e400"), "--speed"),
    (("--speed", "1", "--angle", "-inf"), "--angle"), (("--speed", "1", "--elevation", "nan"), "--elevation"),
    (("--speed", "1", "--tip", "0.1,nan"), "--tip"), (("--speed", "1", "--tip", "0.1"), "--tip"),
])
def test_numbers_that_are_not_finite_are_usage_errors_naming_the_option(args, option):
    result = run(*args)
    assert result.exit_code == 2 and option in result.output and "Traceback" not in result.output


def test_an_unwritable_json_path_is_refused_before_the_shot(tmp_path):
    result = run("--break", "--json", str(tmp_path / "missing" / "out.json"))
    assert result.exit_code == 2 and "does not exist" in result.output
    assert "table at rest" not in result.output


def test_a_json_write_that_fails_keeps_the_summary(tmp_path, monkeypatch):
    out = tmp_path / "out.json"

    def refuse(self, *args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(type(out), "write_text", refuse)
    result = run("--speed", "0.5", "--json", str(out))
    assert result.exit_code == 1
    assert "table at rest" in result.stdout and "could not write" in result.stderr


def test_balls_still_rolling_at_max_ticks_are_not_called_stopped():
    result = run("--break", "--max-ticks", "20")
    assert result.exit_code == 1
    assert "still moving" in result.output and "stopped at tick 20" not in result.output


def test_break_takes_no_aim():
    result = run("--break", "--angle", "10")
    assert result.exit_code == 2
    assert "--break" in result.output and "--angle" in result.output


def test_a_pack_without_the_pool_api_is_named(tmp_path):
    (tmp_path / "pack.mcmeta").write_text('{"pack": {"pack_format": 48, "description": "x"}}')
    result = run(str(tmp_path), "--speed", "1")
    assert result.exit_code == 1
    assert "not a pool datapack" in result.output


def test_trajectory_adds_positions_and_events_to_the_json():
    result = run("--angle", "90", "--speed", "0.8", "--json", "-", "--trajectory")
    trajectory = json.loads(result.stdout)["trajectory"]
    assert trajectory["ids"] == list(range(16))
    assert len(trajectory["positions_mm"]) > 10 and trajectory["positions_mm"][0][0] == [635.0, 635.0]
    assert all(e["kind"] in ("ball", "cushion", "pocket") for e in trajectory["events"])


def test_trajectory_without_json_is_a_usage_error():
    assert run("--break", "--trajectory").exit_code == 2


def test_plot_draws_the_table(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "shot.png"
    result = run("--angle", "20", "--speed", "2", "--plot", str(out))
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20_000


def test_plot_into_a_missing_folder_is_refused_before_the_shot(tmp_path):
    result = run("--break", "--plot", str(tmp_path / "missing" / "b.png"))
    assert result.exit_code == 2 and "table at rest" not in result.output
