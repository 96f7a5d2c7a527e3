"""What keeps the VM's empty-cache compile short (README, "Where start-up goes"): each jitted helper
compiles once, for one signature, whatever call site reaches it."""
from __future__ import annotations

import re
from pathlib import Path

from emulator.vm import loop


def test_every_select_call_passes_its_offset_typed_alike():
    # a literal offset (0) is typed Literal[int](0) and made numba compile _select, its sorts and its
    # shuffle a second time beside the int64 one (about 5 s of the whole loop's compile)
    text = Path(loop.__file__).read_text()
    calls = re.findall(r"= _select\((.*?)\)\n", text, re.S)
    assert calls
    assert all(re.search(r", np\.int64\([^()]*\)$", call) for call in calls), calls
