"""Java's integer and cast semantics: the one source of truth for both backends.

Every helper is a plain function that numba can compile (the VM calls them through ``njit``
wrappers) and that pure Python can call with ints of any size (the reference backend).
The mask form of wrapping is used because ``np.int32(x)`` raises OverflowError in plain Python.
"""
from __future__ import annotations

import math

INT_MIN = -2147483648
INT_MAX = 2147483647
LONG_MIN = -(2**63)
LONG_MAX = 2**63 - 1


def wrap32(x: int) -> int:
    """Two's-complement wrap to a Java int."""
    return ((x + 2147483648) & 0xFFFFFFFF) - 2147483648


def wraps32(x: int) -> bool:
    """True when storing ``x`` into an int would wrap (what the overflow sanitizer reports)."""
    return x < INT_MIN or x > INT_MAX


def floor_div(a: int, b: int) -> int:
    """Math.floorDiv on ints, with Java's overflow: MIN / -1 is MIN. ``b`` must not be 0."""
    return wrap32(a // b)


def floor_mod(a: int, b: int) -> int:
    """Math.floorMod: the result has the sign of the divisor. ``b`` must not be 0."""
    return a % b


def double_to_int(x: float) -> int:
    """Java's (int) cast of a double: truncation toward zero, saturation, NaN -> 0."""
    if x != x:
        return 0
    if x >= 2147483647.0:
        return INT_MAX
    if x <= -2147483648.0:
        return INT_MIN
    return int(x)


def double_to_long(x: float) -> int:
    """Java's (long) cast of a double."""
    if x != x:
        return 0
    if x >= 9.223372036854775807e18:
        return LONG_MAX
    if x <= -9.223372036854775808e18:
        return LONG_MIN
    return int(x)


def double_to_short(x: float) -> int:
    """(short) of a double: saturate to int first, then keep the low 16 bits."""
    return ((double_to_int(x) + 32768) & 0xFFFF) - 32768


def double_to_byte(x: float) -> int:
    """(byte) of a double: saturate to int first, then keep the low 8 bits."""
    return ((double_to_int(x) + 128) & 0xFF) - 128


def double_to_float(x: float) -> float:
    """(float) of a double: round to the nearest float32."""
    import struct

    try:
        return struct.unpack("f", struct.pack("f", x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def mth_floor(x: float) -> int:
    """The game's Mth.floor(double): ``i = (int) x; return x < i ? i - 1 : i`` in int arithmetic.

    So NaN gives 0, large values saturate, and below INT_MIN the ``- 1`` wraps to INT_MAX.
    ``data get ... SCALE`` returns ``Mth.floor(value * scale)``.
    """
    i = double_to_int(x)
    return wrap32(i - 1) if x < i else i
