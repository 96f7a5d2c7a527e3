"""The rounding the math library promises, in Python."""


def round_half_away(numerator, denominator):
    q = (abs(numerator) * 2 + denominator) // (2 * denominator)
    return q if numerator >= 0 else -q
