"""The game's float math, rotations and store casts.

Expected values come from the game's formulas (decompiled 1.21 util/Mth.java, world/phys/Vec3.java,
commands/arguments/coordinates/LocalCoordinates.java, commands/CommandSourceStack.java,
server/commands/ExecuteCommand.java) evaluated on a real JVM by tests/world/java/MthRef.java when
``javac`` is available, so float32 rounding and Java's Math.sin/asin/cos are the JVM's own.
"""
from __future__ import annotations

import math
import shutil
import struct
import subprocess
from pathlib import Path

import numpy as np
import pytest

from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte, Double, Float, Int, Long, Short
from emulator.world import mth, rotation, stores

F32 = np.float32
JAVA_SOURCE = Path(__file__).parent / "java" / "MthRef.java"


# ----------------------------------------------------------------------------- pinned values


def test_sine_table_is_indexed_by_truncated_float_product():
    # Mth.sin(x) = SIN[(int)(x * 10430.378F) & 65535]: sin(pi/2 as float) lands on index 16384.
    assert mth.sin(F32(math.pi / 2)) == F32(1.0)
    assert mth.cos(F32(0.0)) == F32(1.0)
    # The table is float32 and stepped: sin(1e-5) is entry 0 (the product 0.104 truncates to 0).
    assert mth.sin(F32(1e-5)) == F32(0.0)
    # cos(pi) is SIN[(int)(32768.0F + 16384.0F) & 0xFFFF] = SIN[49152], exactly -1.
    assert mth.cos(F32(math.pi)) == F32(-1.0)
    assert mth.SIN_TABLE.dtype == np.float32 and len(mth.SIN_TABLE) == 65536


def test_sine_table_is_the_games_entry_by_entry():
    # Mth's static initialiser: SIN[i] = (float)Math.sin((double)i * Math.PI * 2.0 / 65536.0), the
    # product and quotient in double left to right (the table is built from numpy's doubles)
    expected = [F32(math.sin(i * math.pi * 2.0 / 65536.0)) for i in range(65536)]
    assert mth.SIN_TABLE.tobytes() == np.array(expected, dtype=np.float32).tobytes()


def test_wrap_degrees_float():
    # Mth.wrapDegrees(float): f % 360 (sign of dividend), then >= 180 -> -360, < -180 -> +360.
    assert mth.wrap_degrees_f(180.0) == F32(-180.0)
    assert mth.wrap_degrees_f(-180.0) == F32(-180.0)
    assert mth.wrap_degrees_f(540.5) == F32(-179.5)
    assert mth.wrap_degrees_f(-190.0) == F32(170.0)
    assert mth.wrap_degrees_d(359.0) == -1.0


def test_atan2_is_close_to_but_not_math_atan2():
    # Mth.atan2 is a table with a cubic correction: about 1e-6 off the true angle (fastInvSqrt does
    # one Newton step), never equal to it.
    samples = [(1.0, 2.0), (-3.0, 0.5), (0.3, -0.7), (-1e-3, -5.0), (7.0, 7.0)]
    assert all(abs(mth.atan2(y, x) - math.atan2(y, x)) < 2e-6 for y, x in samples)
    assert any(mth.atan2(y, x) != math.atan2(y, x) for y, x in samples)
    assert mth.atan2(0.0, 0.0) == 0.0
    assert math.isnan(mth.atan2(math.nan, 1.0))


def test_facing_due_axes():
    # CommandSourceStack.facing: (float)(Mth.atan2(...) * 57.2957763671875) with the table atan2.
    # Mth.atan2 is a hair off pi/2 and the widened float constant is not exactly 180/pi, so due
    # south is not exactly 0 but one float step below, due west two steps under 90, straight
    # down one step under 90.
    origin = (0.0, 0.0, 0.0)
    assert rotation.facing_rotation(origin, (1.0, 0.0, 0.0)) == (F32(-90.0), F32(0.0))
    assert rotation.facing_rotation(origin, (0.0, 0.0, 1.0)) == (F32(-7.6293945e-06), F32(0.0))
    assert rotation.facing_rotation(origin, (-1.0, 0.0, 0.0)) == (F32(89.999985), F32(0.0))
    assert rotation.facing_rotation(origin, (0.0, 0.0, -1.0)) == (F32(-180.0), F32(0.0))
    yaw, pitch = rotation.facing_rotation(origin, (0.0, -1.0, 0.0))
    assert yaw == F32(-90.0) and pitch == F32(89.99999)  # atan2(0, 0) = 0, minus 90
    # The same constant, written as a double division (how Vineflower prints it), would give 0.
    assert mth.f32(mth.atan2(1.0, 0.0) * 180.0 / float(mth.PI_F)) - F32(90.0) == F32(0.0)


def test_local_coordinates_forward_is_the_view_direction():
    # ^ ^ ^1 facing yaw 0 pitch 0 moves +z by cos(0)*... = 1 exactly (table entries are exact there).
    assert rotation.local_to_world((0.0, 0.0, 0.0), 0.0, 0.0, 0.0, 0.0, 1.0) == (
        float(mth.cos(F32(90.0) * mth.DEG_TO_RAD)), 0.0, 1.0)
    x, y, z = rotation.local_to_world((10.0, 64.0, 10.0), -90.0, 0.0, 0.0, 0.0, 2.0)
    assert abs(x - 12.0) < 1e-6 and abs(z - 10.0) < 1e-6 and y == 64.0
    # ^1 (left) facing south (+z) points east (+x).
    x, _, z = rotation.local_to_world((0.0, 0.0, 0.0), 0.0, 0.0, 1.0, 0.0, 0.0)
    assert abs(x - 1.0) < 1e-6 and abs(z) < 1e-6


def test_rotation_argument_and_teleport_wrapping():
    # RotationArgument: (float)(value + (double) base) for "~"; tp wraps then clamps pitch to ±90.
    rel, absolute = ast.Coord("rel", 10.0), ast.Coord("abs", 200.0)
    assert rotation.relative_rotation(F32(175.0), F32(0.0), rel, absolute) == (F32(185.0), F32(200.0))
    assert rotation.teleport_rotation(F32(185.0), F32(200.0)) == (F32(-175.0), F32(-90.0))
    assert rotation.teleport_rotation(F32(0.0), F32(100.0)) == (F32(0.0), F32(90.0))
    # Loading Rotation NBT keeps % 360 and discards non-finite values.
    assert rotation.load_rotation((F32(5.0), F32(6.0)), (F32(-725.0), F32(math.inf))) == (F32(-5.0), F32(6.0))


def test_store_casts_follow_java_narrowing():
    # ExecuteCommand.wrapStores: (int)((double)v*scale), (short)(int)..., (byte)(int)..., (long), (float).
    assert stores.stored_tag("int", 7, 0.5) == 3 and type(stores.stored_tag("int", 7, 0.5)) is Int
    assert stores.stored_tag("int", -7, 0.5) == -3  # truncation toward zero
    assert stores.stored_tag("int", 2**31 - 1, 10.0) == 2**31 - 1  # saturates
    assert stores.stored_tag("short", 40000, 1.0) == 40000 - 65536
    assert stores.stored_tag("byte", 2**31 - 1, 4.0) == -1  # saturate to int MAX, low 8 bits
    assert stores.stored_tag("long", 3, 1e30) == 2**63 - 1
    assert type(stores.stored_tag("short", 1, 1)) is Short and type(stores.stored_tag("byte", 1, 1)) is Byte
    assert stores.stored_tag("float", 1, 0.1) == float(F32(0.1)) and type(stores.stored_tag("float", 1, 0.1)) is Float
    assert stores.stored_tag("double", 1, 0.1) == 0.1 and type(stores.stored_tag("double", 1, 0.1)) is Double
    assert type(stores.stored_tag("long", 1, 1.0)) is Long


# ----------------------------------------------------------------------------- JVM cross-check


def _hf(x) -> str:
    return format(struct.unpack("<I", struct.pack("<f", float(x)))[0], "x")


def _hd(x: float) -> str:
    return format(struct.unpack("<Q", struct.pack("<d", x))[0], "x")


def _pf(h: str) -> np.float32:
    return F32(struct.unpack("<f", struct.pack("<I", int(h, 16)))[0])


def _pd(h: str) -> float:
    return struct.unpack("<d", struct.pack("<Q", int(h, 16)))[0]


def _jdk_bins() -> list[Path]:
    """Directories holding both ``java`` and ``javac``: the one on PATH first, then /usr/lib/jvm."""
    found = []
    if shutil.which("javac") and shutil.which("java"):
        found.append(Path(shutil.which("java")).resolve().parent)
    found += sorted(Path(p).parent for p in Path("/usr/lib/jvm").glob("*/bin/javac"))
    return [b for b in found if (b / "java").exists()]


def _major(bin_dir: Path) -> int:
    out = subprocess.run([str(bin_dir / "java"), "-version"], capture_output=True, text=True).stderr
    version = out.split('"')[1] if '"' in out else "0"
    return int(version.split(".")[0])


def _jvm(tmp_path_factory, min_major: int):
    bins = [b for b in _jdk_bins() if _major(b) >= min_major]
    if not bins:
        pytest.skip(f"no JDK {min_major}+: the JVM cross-check needs javac and java")
    bin_dir, out = bins[0], tmp_path_factory.mktemp("mthref")
    subprocess.run([str(bin_dir / "javac"), "-d", str(out), str(JAVA_SOURCE)], check=True, capture_output=True)

    def ask(lines: list[str]) -> list[str]:
        done = subprocess.run([str(bin_dir / "java"), "-cp", str(out), "MthRef"], input="\n".join(lines) + "\n",
                              check=True, capture_output=True, text=True)
        return done.stdout.splitlines()

    return ask


@pytest.fixture(scope="module")
def java(tmp_path_factory):
    return _jvm(tmp_path_factory, 8)


@pytest.fixture(scope="module")
def java19(tmp_path_factory):
    # Double/Float.toString print the shortest digits from Java 19 on (1.20.5+ runs on Java 21).
    return _jvm(tmp_path_factory, 19)


def _random_floats(rng, n, scale):
    return [F32(v) for v in rng.uniform(-scale, scale, n)]


def test_trig_and_wrap_match_the_jvm(java):
    rng = np.random.default_rng(1)
    values = _random_floats(rng, 1500, 1000.0) + _random_floats(rng, 500, 4.0) + [F32(0.0), F32(-0.0), F32(1e9)]
    queries = [f"{op} {_hf(v)}" for v in values for op in ("sin", "cos", "wrap")]
    answers = java(queries)
    ours = [_hf(f(v)) for v in values for f in (mth.sin, mth.cos, mth.wrap_degrees_f)]
    assert ours == answers


def test_atan2_tables_match_the_jvm(java):
    ours = [f"{_hd(a)} {_hd(c)}" for a, c in zip(mth.ASIN_TAB, mth.COS_TAB)]
    assert ours == java(["tables"])


def test_atan2_matches_the_jvm(java):
    rng = np.random.default_rng(2)
    pairs = [(float(y), float(x)) for y, x in rng.uniform(-50, 50, (2000, 2))]
    pairs += [(0.0, 1.0), (1.0, 0.0), (-1.0, -1.0), (1e-300, 1.0), (3.0, -1e-12)]
    answers = java([f"atan2 {_hd(y)} {_hd(x)}" for y, x in pairs])
    assert [_hd(mth.atan2(y, x)) for y, x in pairs] == answers


def test_facing_and_local_coordinates_match_the_jvm(java):
    rng = np.random.default_rng(3)
    queries, ours = [], []
    for _ in range(800):
        o = tuple(float(v) for v in rng.uniform(-100, 100, 3))
        t = tuple(float(v) for v in rng.uniform(-100, 100, 3))
        for kind, legacy in (("facing", False), ("facing117", True)):
            queries.append(f"{kind} " + " ".join(_hd(v) for v in o + t))
            yaw, pitch = rotation.facing_rotation(o, t, float_horizontal=legacy)
            ours.append(f"{_hf(yaw)} {_hf(pitch)}")
        yaw, pitch = F32(rng.uniform(-400, 400)), F32(rng.uniform(-90, 90))
        offsets = tuple(float(v) for v in rng.uniform(-10, 10, 3))
        queries.append("local " + " ".join([_hd(v) for v in o] + [_hf(yaw), _hf(pitch)] + [_hd(v) for v in offsets]))
        ours.append(" ".join(_hd(v) for v in rotation.local_to_world(o, yaw, pitch, *offsets)))
        queries.append(f"dir {_hf(yaw)} {_hf(pitch)}")
        ours.append(" ".join(_hd(v) for v in rotation.direction_from_rotation(yaw, pitch)))
        queries.append(f"view {_hf(yaw)} {_hf(pitch)}")
        ours.append(" ".join(_hd(v) for v in rotation.view_vector(yaw, pitch)))
    assert ours == java(queries)


def test_store_casts_match_the_jvm(java):
    rng = np.random.default_rng(4)
    cases = [(int(v), float(s)) for v, s in zip(rng.integers(-2**31, 2**31, 400), rng.uniform(-1e4, 1e4, 400))]
    cases += [(5, math.nan), (1, math.inf), (-1, math.inf), (2**31 - 1, 1.5), (-(2**31), 1.0), (300, 1.0)]
    answers = java([f"store {v} {_hd(s)}" for v, s in cases])
    ours = []
    for v, s in cases:
        tags = [stores.stored_tag(t, v, s) for t in ("int", "long", "short", "byte")]
        ours.append(" ".join(str(int(t)) for t in tags) + " " + _hf(stores.stored_tag("float", v, s)))
    assert ours == answers


def test_numeric_tag_narrowing_matches_the_jvm(java):
    # NumericTag.getAsByte/Short/Int/Long for doubles and floats (what arrays store and paths read).
    from emulator.world.nbt_ops import narrow
    from mcfunction_parser.nbt import Byte, Int, Long, Short

    rng = np.random.default_rng(5)
    values = [float(v) for v in rng.uniform(-1e6, 1e6, 300)] + [float(v) for v in rng.uniform(-3e9, 3e9, 200)]
    values += [math.nan, math.inf, -math.inf, -0.5, 2.0**31, -(2.0**31) - 300.0, 1e20, -1e20, 255.9, -128.5]
    answers = java([f"narrow {_hd(v)}" for v in values])
    ours = []
    for v in values:
        as_double = [narrow(Double(v), t) for t in (Byte, Short, Int, Long)]
        as_float = [narrow(Float(float(mth.f32(v))), t) for t in (Byte, Short, Int, Long)]
        ours.append(" ".join(str(x) for x in as_double + as_float))
    assert ours == answers


def test_number_text_matches_java_19(java19):
    from emulator.world.text import java_double_string, java_float_string

    rng = np.random.default_rng(6)
    doubles = [float(v) for v in rng.uniform(-1e4, 1e4, 300)] + [float(10.0 ** e) * 1.2345 for e in range(-330, 300, 7)]
    doubles += [5e-324, 1e-3, 9.999999999999999e-4, 1e7, 9999999.999999998, 0.1, 1e23, -0.0, 0.0, math.inf, math.nan, 100.0]
    floats = [F32(v) for v in rng.uniform(-1e4, 1e4, 300)] + [F32(1.4e-45), F32(3.4028235e38), F32(1e7), F32(0.001), F32(-0.0)]
    answers = java19([f"dtext {_hd(v)}" for v in doubles] + [f"ftext {_hf(v)}" for v in floats])
    ours = [java_double_string(v) for v in doubles] + [java_float_string(v) for v in floats]
    assert ours == answers
