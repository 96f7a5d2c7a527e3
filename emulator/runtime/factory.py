"""The backends by name, each imported only when asked for: a run on the reference backend never
loads numba, and neither backend's modules import this one."""
from __future__ import annotations

from emulator.runtime.auto import AutoBackend
from emulator.runtime.backend import Backend


def make_backend(name: str) -> Backend:
    """A new backend by name: ``numba`` (the VM), ``python`` (the reference) or ``auto`` (the
    reference, then the VM once the run proves long: :mod:`emulator.runtime.auto`)."""
    if name == "numba":
        from emulator.vm.backend import NumbaBackend

        return NumbaBackend()
    if name == "python":
        from emulator.reference import ReferenceBackend

        return ReferenceBackend()
    if name == "auto":
        return AutoBackend(make_backend("python"), lambda: make_backend("numba"))
    raise ValueError(f"unknown backend {name!r}: expected 'numba', 'python' or 'auto'")
