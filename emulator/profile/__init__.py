"""Profiles of a run: the counts per tick, root, function, line, instruction and host op, read
through the runtime's and the backends' declared hooks (:mod:`.data`); the call-stack recorder
(:mod:`.stacks`); report formats and baselines (:mod:`.formats`)."""
