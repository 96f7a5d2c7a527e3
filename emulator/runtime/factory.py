"""The backends by name, each imported only when asked for: a run on the reference backend never
loads numba, and neither backend's modules import this one."""
from __future__ import annotations

from emulator.runtime.backend import Backend


def make_backend(name: str) -> Backend:
    """A new backend by name: ``numba`` (the VM) or ``python`` (the reference)."""
    if name == "numba":
        from emulator.vm.backend import NumbaBackend

        return NumbaBackend()
    if name == "python":
        from emulator.reference import ReferenceBackend

        return ReferenceBackend()
    raise ValueError(f"unknown backend {name!r}: expected 'numba' or 'python'")
