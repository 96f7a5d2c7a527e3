"""The server side of a run: the backend protocol both backends implement, with the hooks the
profiler reads (:mod:`.backend`), the backends by name (:mod:`.factory`), the whole server tick:
load once, tick tags, schedule, time, the players' per-tick statistics (:mod:`.server`), and macro
instantiation, shared by both backends (:mod:`.macros`)."""
