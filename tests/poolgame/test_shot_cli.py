"""`dpemu shot`: a table set up, a shot struck through the pack's API, emulated to rest."""
import json

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


def test_shot_out_of_range_prints_the_packs_refusal():
    result = run("--speed", "7")
    assert result.exit_code == 1
    assert "shot refused: speed must be 1..6500" in result.output


def test_break_takes_no_aim():
    result = run("--break", "--angle", "10")
    assert result.exit_code == 2
    assert "--break" in result.output and "--angle" in result.output


def test_a_pack_without_the_pool_api_is_named(tmp_path):
    (tmp_path / "pack.mcmeta").write_text('{"pack": {"pack_format": 48, "description": "x"}}')
    result = run(str(tmp_path), "--speed", "1")
    assert result.exit_code == 1
    assert "not a pool datapack" in result.output
