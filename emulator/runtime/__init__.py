"""The server side of a run: the backend protocol both backends implement (with the hooks the
profiler reads, and :func:`~emulator.runtime.backend.make_backend`), the whole server tick (load
once, tick tags, schedule, time, the players' per-tick statistics) and macro instantiation, shared
by both backends."""
