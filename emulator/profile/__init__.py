"""Profiles of a run: counters per tick, root, function and line; report formats; call stacks."""
