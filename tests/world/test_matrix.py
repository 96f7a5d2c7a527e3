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
    if np.linalg.cond(m[:3, :3]) > 20:
        return  # ill-conditioned: five Jacobi sweeps (the game's count) need not converge there
    parts = decompose(m.flatten().tolist())
    assert np.allclose(_compose(*parts), m, atol=2e-3 * max(1.0, np.abs(m).max()))


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
