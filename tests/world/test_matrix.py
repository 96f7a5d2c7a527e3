"""A display's transformation given as a matrix, decomposed as the game decomposes it.

Sources (decompiled 1.21): com/mojang/math/Transformation.java (ensureDecomposed: the matrix over
m33, the translation column), MatrixUtil.svdDecompose (Jacobi sweeps, then Givens QR),
GivensParameters; util/ExtraCodecs.java (MATRIX4F is row-major; AXISANGLE4F); world/entity/Display.java.
"""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from emulator.commands.entities import new_state
from emulator.world.entities import entity_nbt
from emulator.world.matrix import axis_angle, decompose
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.reader import Reader
from mcfunction_parser.snbt import compound


def _rotation(q):
    x, y, z, w = map(float, q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _compose(translation, left, scale, right):
    """Transformation.compose: translate, rotate left, scale, rotate right (row-major 4x4)."""
    m = np.eye(4)
    m[:3, :3] = _rotation(left) @ np.diag([float(s) for s in scale]) @ _rotation(right)
    m[:3, 3] = [float(t) for t in translation]
    return m


def test_identity_and_pure_scale_with_translation():
    assert [list(map(float, p)) for p in decompose([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])] == \
        [[0, 0, 0], [0, 0, 0, 1], [1, 1, 1], [0, 0, 0, 1]]
    translation, left, scale, _ = decompose([2, 0, 0, 1, 0, 3, 0, 2, 0, 0, 4, 3, 0, 0, 0, 1])  # row-major
    assert list(map(float, translation)) == [1, 2, 3] and list(map(float, scale)) == [2, 3, 4]


def test_a_rotation_about_y_is_the_left_rotation_and_m33_divides():
    # 90 degrees about y, everything times 2 (m33 = 2 divides it back)
    _, left, scale, right = decompose([0, 0, 2, 0, 0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 0, 2])
    assert np.allclose([float(v) for v in left], [0, math.sqrt(0.5), 0, math.sqrt(0.5)], atol=1e-6)
    assert np.allclose([float(v) for v in scale], [1, 1, 1], atol=1e-6)
    assert np.allclose([float(v) for v in right], [0, 0, 0, 1])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-4, 4, allow_nan=False), min_size=12, max_size=12))
def test_the_parts_compose_back_to_the_matrix(values):
    m = np.array(values + [0, 0, 0, 1], dtype=np.float64).reshape(4, 4)
    if not _converges(m[:3, :3]):
        return
    parts = decompose(m.flatten().tolist())
    assert np.allclose(_compose(*parts), m, atol=2e-3 * max(1.0, np.abs(m).max()))


def _converges(a) -> bool:
    """Where the game's decomposition composes back: not ill-conditioned (five Jacobi sweeps need
    not converge there), and the two smaller singular values not both small. MatrixUtil.stepJacobi
    leaves an off-diagonal pair of AᵀA once its squares sum below 1e-6 (an absolute threshold), and
    such a pair turns the right rotation by about |off-diagonal| / (σi² - σj²), which puts about
    1e-3 / (σi + σj) into the composed matrix."""
    s = np.linalg.svd(a, compute_uv=False)
    return s[2] > 0 and s[0] / s[2] <= 20 and s[1] + s[2] >= 0.5


def test_small_singular_values_stay_off_as_in_the_game():
    # singular values 1.12, 0.223, 0.062 (condition 18): the pair of AᵀA whose eigenvalues are
    # 0.05 and 0.004 keeps an off-diagonal under stepJacobi's 1e-6 threshold, so the game's parts
    # compose back about 7e-3 off (more sweeps change nothing)
    m = np.array([0, 0, 0.25, 0, 0.03125, 0.0625, 0, 0, 1, 0, 0.5, 0, 0, 0, 0, 1], dtype=np.float64).reshape(4, 4)
    assert not _converges(m[:3, :3])
    error = np.abs(_compose(*decompose(m.flatten().tolist())) - m).max()
    assert 5e-3 < error < 1e-2


def test_axis_angle_rotation():
    q = axis_angle(-math.pi / 2, [0, 0, 1])  # a negative angle wraps into [0, 2pi)
    assert np.allclose([float(v) for v in q], [0, 0, math.sqrt(0.5), -math.sqrt(0.5)], atol=1e-6)


def _snbt(text):
    return compound(Reader(text, Loc("t", 1, 1), (1, 21, 4)))


def test_a_display_summoned_with_a_matrix_saves_it_decomposed():
    state = new_state()
    display = state.entities.summon("minecraft:block_display", (0, 0, 0),
                                    _snbt("{transformation:[2f,0f,0f,0.5f,0f,2f,0f,0f,0f,0f,2f,0f,0f,0f,0f,1f]}"))
    t = entity_nbt(display)["transformation"]
    assert [float(v) for v in t["translation"]] == [0.5, 0.0, 0.0]
    assert [float(v) for v in t["scale"]] == [2.0, 2.0, 2.0]
    turned = state.entities.summon("minecraft:item_display", (0, 0, 0), _snbt(
        "{transformation:{translation:[0f,0f,0f],scale:[1f,1f,1f],right_rotation:[0f,0f,0f,1f],"
        "left_rotation:{angle:1.5707964f,axis:[0f,1f,0f]}}}"))
    left = [float(v) for v in entity_nbt(turned)["transformation"]["left_rotation"]]
    assert np.allclose(left, [0, math.sqrt(0.5), 0, math.sqrt(0.5)], atol=1e-6)
