"""The math library (datapack/data/pool/function/math) runs on both backends: one world per module."""
import pytest

from tests.datapack.pool_world import BACKENDS, PoolWorld


@pytest.fixture(scope="module", params=BACKENDS)
def board(request):
    return PoolWorld(request.param)
