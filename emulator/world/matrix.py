"""A display entity's ``transformation`` given as 16 numbers: the row-major 4x4 matrix the game
decomposes into translation, left rotation, scale and right rotation, in its float steps.

- ``decompose(values)``: ``Transformation(Matrix4f).ensureDecomposed``: the matrix is divided by
  its m33, the translation is its last column, the upper 3x3 goes through
  ``MatrixUtil.svdDecompose`` (five Jacobi sweeps on AᵀA for the right rotation, then Givens QR
  steps for the left rotation and the scale). Returns ``(translation, left_rotation, scale,
  right_rotation)``, quaternions as ``(x, y, z, w)``.
- ``axis_angle(angle, axis)``: ``new Quaternionf(new AxisAngle4f(angle, axis))`` (the other form a
  rotation may be written in).

The JOML operations are written out in float32 as JOML (FASTMATH off, fma off) performs them:
``Matrix3f.mul``, ``Matrix3f.rotate(Quaternionf)``, ``Quaternionf.mul``/``normalize``,
``Math.invsqrt``/``sin``/``cosFromSin``. A matrix is ``m[column][row]`` as JOML's ``mCR`` fields.

Sources (decompiled 1.21): com/mojang/math/Transformation.java, MatrixUtil.java (svdDecompose,
stepJacobi, approxGivensQuat, qrGivensQuat), GivensParameters.java; util/ExtraCodecs.java
(MATRIX4F: ``setRowColumn(i >> 2, i & 3, value)``, AXISANGLE4F); org.joml 1.10 Matrix3f, Quaternionf,
AxisAngle4f, Math.
"""
from __future__ import annotations

import math

import numpy as np

F = np.float32
_PI2 = math.pi + math.pi
_PI_F, _PI2_F, _PI_HALF_F = F(math.pi), F(_PI2), F(math.pi * 0.5)


# ---------------------------------------------------------------------- JOML's float math
def _sqrt(x) -> np.float32:
    return F(math.sqrt(float(x)))


def _invsqrt(x) -> np.float32:
    return F(1.0) / _sqrt(x)


def _sin(x) -> np.float32:
    return F(math.sin(float(x)))


def _cos_from_sin(sin, angle) -> np.float32:
    """org.joml.Math.cosFromSin(float, float): the cosine's magnitude from the sine, its sign from
    the angle's quadrant."""
    cos = _sqrt(F(1.0) - sin * sin)
    a = F(angle + _PI_HALF_F)
    b = F(a - F(int(a / _PI2_F)) * _PI2_F)
    if b < 0.0:
        b = F(_PI2_F + b)
    return -cos if b >= _PI_F else cos


def _mul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Matrix3f.mul: a x b (nmCR = aC0... as fma(a0R, bC0, fma(a1R, bC1, a2R * bC2)), no fused ops)."""
    out = np.zeros((3, 3), dtype=F)
    for c in range(3):
        for r in range(3):
            out[c][r] = a[0][r] * b[c][0] + (a[1][r] * b[c][1] + a[2][r] * b[c][2])
    return out


def _rotation(q) -> np.ndarray:
    """The rotation matrix Matrix3f.rotate(Quaternionf) multiplies by (rmCR)."""
    x, y, z, w = q
    w2, x2, y2, z2 = w * w, x * x, y * y, z * z
    zw, xy, xz, yw, yz, xw = z * w, x * y, x * z, y * w, y * z, x * w
    dzw, dxy, dxz, dyw, dyz, dxw = zw + zw, xy + xy, xz + xz, yw + yw, yz + yz, xw + xw
    return np.array([[w2 + x2 - z2 - y2, dxy + dzw, dxz - dyw],
                     [dxy - dzw, y2 - z2 + w2 - x2, dyz + dxw],
                     [dyw + dxz, dyz - dxw, z2 - y2 - x2 + w2]], dtype=F)


def _rotate(m: np.ndarray, q) -> np.ndarray:
    rm = _rotation(q)
    out = np.zeros((3, 3), dtype=F)
    for c in range(3):
        for r in range(3):
            out[c][r] = m[0][r] * rm[c][0] + m[1][r] * rm[c][1] + m[2][r] * rm[c][2]
    return out


def _qmul(a, b):
    """Quaternionf.mul: a x b, each component as JOML's nested fma (not fused)."""
    x, y, z, w = a
    qx, qy, qz, qw = b
    return (w * qx + (x * qw + (y * qz + -z * qy)),
            w * qy + (-x * qz + (y * qw + z * qx)),
            w * qz + (x * qy + (-y * qx + z * qw)),
            w * qw + (-x * qx + (-y * qy + -z * qz)))


def _normalize(q):
    x, y, z, w = q
    inv = _invsqrt(x * x + (y * y + (z * z + w * w)))
    return (x * inv, y * inv, z * inv, w * inv)


# ---------------------------------------------------------------------- GivensParameters
def _givens(sin_half, cos_half):
    """GivensParameters.fromUnnormalized."""
    w = _invsqrt(sin_half * sin_half + cos_half * cos_half)
    return (w * sin_half, w * cos_half)


def _givens_angle(angle):
    """GivensParameters.fromPositiveAngle."""
    half = F(angle / F(2.0))
    sin = _sin(half)
    return (sin, _cos_from_sin(sin, half))


def _around(axis: int, g):
    """GivensParameters.aroundX/Y/Z(Quaternionf) and (Matrix3f)."""
    s_half, c_half = g
    q = [F(0.0), F(0.0), F(0.0), c_half]
    q[axis] = s_half
    cos, sin = c_half * c_half - s_half * s_half, F(2.0) * s_half * c_half
    m = np.eye(3, dtype=F)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]  # the plane the rotation turns
    m[i][i] = m[j][j] = cos
    m[i][j], m[j][i] = sin, -sin
    return tuple(q), m


_G = F(3.0) + F(2.0) * _sqrt(F(2.0))  # MatrixUtil.G: cot(pi/8)^2 ... 3 + 2 sqrt 2
_PI_4 = _givens_angle(F(math.pi / 4))


def _approx_givens(a11, a12, a22):
    a = F(2.0) * (a11 - a22)
    return _givens(a12, a) if _G * a12 * a12 < a * a else _PI_4


def _qr_givens(a1, a2):
    p = F(math.hypot(float(a1), float(a2)))
    sh = a2 if p > F(1.0e-6) else F(0.0)
    ch = abs(a1) + max(p, F(1.0e-6))
    if a1 < 0.0:
        sh, ch = ch, sh
    return _givens(sh, ch)


def _similarity(m: np.ndarray, rot: np.ndarray) -> np.ndarray:
    """MatrixUtil.similarityTransform: rotᵀ (m rot)."""
    return _mul(rot.T.copy(), _mul(m, rot))


def _step_jacobi(m: np.ndarray, q):
    """MatrixUtil.stepJacobi: zero the off-diagonal pairs (0,1), (0,2), (1,2) in turn."""
    for axis, (i, j), negate in ((2, (0, 1), False), (1, (0, 2), True), (0, (1, 2), False)):
        if m[i][j] * m[i][j] + m[j][i] * m[j][i] > F(1.0e-6):
            g = _approx_givens(m[i][i], F(0.5) * (m[i][j] + m[j][i]), m[j][j])
            if negate:
                g = (-g[0], g[1])
            rq, rm = _around(axis, g)
            q = _qmul(q, rq)
            m = _similarity(m, rm)
    return m, q


def _eigenvalue_jacobi(m: np.ndarray, iterations: int):
    q = (F(0.0), F(0.0), F(0.0), F(1.0))
    for _ in range(iterations):
        m, q = _step_jacobi(m, q)
    return m, _normalize(q)


def svd_decompose(a: np.ndarray):
    """MatrixUtil.svdDecompose(A): (left rotation, scale, right rotation)."""
    ata, right = _eigenvalue_jacobi(_mul(a.T.copy(), a), 5)
    first_small, second_small = float(ata[0][0]) < 1.0e-6, float(ata[1][1]) < 1.0e-6
    b = _rotate(a, right)
    left = (F(0.0), F(0.0), F(0.0), F(1.0))
    g = _qr_givens(b[1][1], -b[1][0]) if first_small else _qr_givens(b[0][0], b[0][1])
    rq, rm = _around(2, g)
    left = _qmul(left, rq)
    r1 = _mul(rm.T.copy(), b)
    g = _qr_givens(r1[2][2], -r1[2][0]) if first_small else _qr_givens(r1[0][0], r1[0][2])
    g = (-g[0], g[1])
    rq, rm = _around(1, g)
    left = _qmul(left, rq)
    r2 = _mul(rm.T.copy(), r1)
    g = _qr_givens(r2[2][2], -r2[2][1]) if second_small else _qr_givens(r2[1][1], r2[1][2])
    rq, rm = _around(0, g)
    left = _qmul(left, rq)
    r3 = _mul(rm.T.copy(), r2)
    scale = (r3[0][0], r3[1][1], r3[2][2])
    x, y, z, w = right
    return left, scale, (-x, -y, -z, w)


def decompose(values) -> tuple[tuple, tuple, tuple, tuple]:
    """The 16 numbers (row-major) of a transformation matrix as translation, left rotation, scale and
    right rotation (Transformation.ensureDecomposed)."""
    m = np.zeros((4, 4), dtype=F)  # m[column][row]
    for i, v in enumerate(values):
        m[i & 3][i >> 2] = F(v)
    f = F(1.0) / m[3][3]
    upper = np.array([[m[c][r] * f for r in range(3)] for c in range(3)], dtype=F)
    left, scale, right = svd_decompose(upper)
    translation = (m[3][0] * f, m[3][1] * f, m[3][2] * f)
    return translation, left, scale, right


def axis_angle(angle: float, axis) -> tuple:
    """``new Quaternionf(new AxisAngle4f(angle, axis))``: the angle wrapped into [0, 2pi) in double,
    then sin/cos of its half."""
    a = float(F(angle))
    wrapped = F(((_PI2 + a % _PI2) if a < 0.0 else a) % _PI2)
    half = F(wrapped * F(0.5))
    sin = _sin(half)
    return (F(axis[0]) * sin, F(axis[1]) * sin, F(axis[2]) * sin, _cos_from_sin(sin, half))
