"""The game's own float math (``net.minecraft.util.Mth``), bit for bit.

Java evaluates ``float`` expressions in IEEE single precision; here every float value is a
``numpy.float32`` and every float operation is done on float32 operands, so results match the
game exactly. Doubles are Python floats (IEEE double, like Java's strict arithmetic).

Public functions (plain scalars in, plain scalars out):
- ``f32(x)``: Java's ``(float)`` cast of a double (round to nearest float32).
- ``sin(x)`` / ``cos(x)``: the 65536-entry float sine table, indexed by
  ``(int)(x * 10430.378F) & 0xFFFF`` (cos adds ``16384.0F`` before the cast); ``sin_of``/``cos_of``
  the same of a float32, in the form numba compiles (the VM's jitted rotations use them).
- ``atan2(y, x)``: the game's table-based ``Mth.atan2`` (double in, double out); it differs from
  ``math.atan2`` by about 1e-6 and is what ``facing`` and ``lookAt`` use (its two tables are the
  JVM's own values, see ``atan_tables``).
- ``wrap_degrees_f(x)`` (float) / ``wrap_degrees_d(x)`` (double): ``Mth.wrapDegrees`` into [-180, 180).
- ``floor_f(x)``: ``Mth.floor(float)``; ``clamp_f(x, lo, hi)``: ``Mth.clamp(float, ...)``.
- ``java_float_rem(a, b)``: Java's float ``%`` (sign of the dividend).
- ``fast_inv_sqrt(x)``: ``Mth.fastInvSqrt(double)`` (used by ``atan2``).

Source: decompiled 1.21 ``net/minecraft/util/Mth.java`` (Yeet-Masta/MCP-1.21).
"""
from __future__ import annotations

import math
import struct

import numpy as np

from emulator.world.semantics import double_to_int
from emulator.world.atan_tables import ASIN_TAB, COS_TAB

F32 = np.float32
SIN_SCALE = F32(10430.378)
QUARTER_TURN = F32(16384.0)
DEG_TO_RAD = F32(math.pi / 180.0)  # (float)(Math.PI / 180.0) = 0.017453292F
RAD_TO_DEG = F32(180.0) / F32(math.pi)  # 180.0F / (float)Math.PI = 57.295776F
PI_F = F32(math.pi)  # (float)Math.PI


def f32(x) -> np.float32:
    """Java's ``(float)`` of a double: round to nearest, overflow to infinity."""
    if type(x) is np.float32:
        return x
    if -3.0e38 < x < 3.0e38:
        return F32(x)
    with np.errstate(over="ignore"):
        return F32(x)


def _build_sin_table() -> np.ndarray:
    # (float)Math.sin((double)i * Math.PI * 2.0 / 65536.0), evaluated left to right in double (numpy's
    # products and quotient of doubles are IEEE's, as Python's: the same arguments), each sine the C
    # library's, as math.sin: a third of the time a list of the sines took, at every import
    angles = (np.arange(65536, dtype=np.float64) * math.pi * 2.0 / 65536.0).tolist()
    return np.fromiter(map(math.sin, angles), dtype=np.float64, count=65536).astype(np.float32)


SIN_TABLE = _build_sin_table()


def _table_index(x: np.float32) -> int:
    return double_to_int(float(x)) & 0xFFFF


# Below this magnitude the table products cannot overflow float32, so numpy needs no error guard.
_SAFE = F32(1e30)


def sin_of(x: np.float32) -> np.float32:
    """``Mth.sin(float)`` of a float32 (the table lookup; numba compiles it as is)."""
    return SIN_TABLE[_table_index(x * SIN_SCALE)]


def cos_of(x: np.float32) -> np.float32:
    """``Mth.cos(float)`` of a float32: the table shifted by a quarter turn, the shift added in float."""
    return SIN_TABLE[_table_index(x * SIN_SCALE + QUARTER_TURN)]


def sin(x) -> np.float32:
    """``Mth.sin(float)``."""
    x = f32(x)
    if -_SAFE < x < _SAFE:
        return sin_of(x)
    with np.errstate(over="ignore", invalid="ignore"):
        return sin_of(x)


def cos(x) -> np.float32:
    """``Mth.cos(float)``."""
    x = f32(x)
    if -_SAFE < x < _SAFE:
        return cos_of(x)
    with np.errstate(over="ignore", invalid="ignore"):
        return cos_of(x)


def java_float_rem(a, b) -> np.float32:
    """Java's float ``%``: truncated remainder, exact, sign of the dividend (NaN for inf or b=0)."""
    a, b = float(F32(a)), float(F32(b))
    if math.isinf(a) or b == 0.0 or math.isnan(a) or math.isnan(b):
        return F32(math.nan)
    return F32(math.fmod(a, b))


def wrap_degrees_f(x) -> np.float32:
    """``Mth.wrapDegrees(float)``: ``x % 360`` then one shift into [-180, 180)."""
    f = java_float_rem(x, 360.0)
    if f >= F32(180.0):
        f = f - F32(360.0)
    if f < F32(-180.0):
        f = f + F32(360.0)
    return F32(f)


def wrap_degrees_d(x: float) -> float:
    """``Mth.wrapDegrees(double)``."""
    if math.isinf(x) or math.isnan(x):
        return math.nan
    d = math.fmod(x, 360.0)
    if d >= 180.0:
        d -= 360.0
    if d < -180.0:
        d += 360.0
    return d


def floor_f(x) -> int:
    """``Mth.floor(float)``: ``i = (int) x; return x < i ? i - 1 : i`` (comparison in float)."""
    x = F32(x)
    i = double_to_int(float(x))
    return i - 1 if x < F32(i) else i


def clamp_f(x, lo, hi) -> np.float32:
    """``Mth.clamp(float, float, float)``: ``x < lo ? lo : Math.min(x, hi)`` (NaN stays NaN)."""
    x, lo, hi = F32(x), F32(lo), F32(hi)
    if x < lo:
        return lo
    if math.isnan(float(x)):
        return x
    return x if x <= hi else hi


def _bits(x: float) -> int:
    return struct.unpack("<q", struct.pack("<d", x))[0]


def _from_bits(bits: int) -> float:
    return struct.unpack("<d", struct.pack("<q", ((bits + 2**63) % 2**64) - 2**63))[0]


def fast_inv_sqrt(x: float) -> float:
    """``Mth.fastInvSqrt(double)``: one Newton step from the magic-constant estimate."""
    half = 0.5 * x
    y = _from_bits(6910469410427058090 - (_bits(x) >> 1))
    return y * (1.5 - half * y * y)


_FRAC_BIAS = _from_bits(4805340802404319232)
# the tables as arrays: numba freezes a global array into the VM's code (a tuple would be indexed through a switch)
_ASIN = np.array(ASIN_TAB)
_COS = np.array(COS_TAB)
_ONE_SIXTH = 0.16666666666666666


def atan2(y: float, x: float) -> float:
    """``Mth.atan2(double y, double x)``: table lookup plus a cubic correction, in double (the numba
    VM compiles it as is, with ``_bits``/``_from_bits`` as raw bit casts)."""
    d0 = x * x + y * y
    if math.isnan(d0):
        return math.nan
    negative_y = y < 0.0
    if negative_y:
        y = -y
    negative_x = x < 0.0
    if negative_x:
        x = -x
    steep = y > x
    if steep:
        x, y = y, x
    inv = fast_inv_sqrt(d0)
    x *= inv
    y *= inv
    biased = _FRAC_BIAS + y
    index = ((_bits(biased) & 0xFFFFFFFF) + 2**31) % 2**32 - 2**31  # (int) of the raw long bits
    if not 0 <= index <= 256:
        return math.nan  # only reachable with infinite input, where the game itself throws
    correction = y * float(_COS[index]) - x * (biased - _FRAC_BIAS)
    angle = float(_ASIN[index]) + (6.0 + correction * correction) * correction * _ONE_SIXTH
    if steep:
        angle = math.pi / 2 - angle
    if negative_x:
        angle = math.pi - angle
    if negative_y:
        angle = -angle
    return angle
