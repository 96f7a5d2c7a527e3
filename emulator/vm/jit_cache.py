"""Loading the VM's compiled functions from numba's on-disk cache without numba's whole set-up.

Before each cache load numba refreshes its target: it imports and installs every lowering and typing
registry it has (arrays, lists, dicts, random, linear algebra ...), about a quarter of a warm start's
CPU time, which loaded machine code never reads. What loaded code needs is numba's runtime (its
memory allocator: the loop's ``np.empty``, the machine's structure), which the refresh starts first;
the compiler refreshes the target itself before it compiles anything (``CompilerBase``), and so does
the target on a lowering it does not know yet (``BaseContext.get_function``). So a dispatcher made
lean here starts the runtime alone before loading, and refreshes the target as numba would when
nothing was cached (it compiles next).
"""
from __future__ import annotations

import types

from numba.core.runtime import nrt


def lean_loads(*dispatchers) -> None:
    """Make each of the ``dispatchers`` (``@njit(cache=True)`` functions) load from the cache leanly."""
    for dispatcher in dispatchers:
        cache = dispatcher._cache
        if hasattr(cache, "_load_overload"):  # a cache on disk (not NullCache: cache=False)
            cache.load_overload = types.MethodType(_load_overload, cache)


def _load_overload(cache, sig, target_context):
    nrt.rtsys.initialize(target_context)  # what the refresh does first, and what loaded code needs
    with cache._guard_against_spurious_io_errors():
        loaded = cache._load_overload(sig, target_context)
        if loaded is not None:
            return loaded
    target_context.refresh()  # not cached: numba compiles next, set up as it expects
    return None
