"""The server side of a run: the backend protocol both backends implement, the whole server tick
(load, tick tags, schedule, time) and macro instantiation, shared by both backends."""
