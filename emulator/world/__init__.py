"""The world library: what datapack commands act on (the world's state) and the game's rules for
it, in pure Python over plain values. The commands that run on it are :mod:`emulator.commands`.
Modules:
- ``state``: the ``WorldState`` a run changes (scoreboard, schedule, gamerules, log ...);
  ``context``: who runs a command and where; ``records``: log lines, runtime diagnostics and
  overflow reports.
- ``errors``: the message texts of command failures (the game's, by translation key).
- ``nbt_ops``: NBT paths, ``data get/merge/modify/remove``, partial NBT matching.
- ``storage``: command storage (``data ... storage``) with the game's accessor semantics.
- ``stores``: ``execute store ... TYPE SCALE`` casts and ``data get [SCALE]`` results.
- ``mth``: the game's float math (sine table, atan2, wrapDegrees) in float32; ``atan_tables``
  holds the JVM's own tables behind ``Mth.atan2``.
- ``rotation``: directions, local coordinates ``^``, ``facing``, rotation wrapping.
- ``source``: the execution context (position, rotation, executor, anchor) and coordinate arguments.
- ``entities``: entity types, the entity store, entity NBT view and loading; ``display`` holds the
  render fields display entities save and how loading reads them.
- ``selectors``: ``@s @e @a @p @r @n`` with their arguments.
- ``text``: numbers and tags as Java prints them (``Double.toString``, ``Tag.getAsString``).
- ``teleport``: ``tp`` destinations for every form.
- ``blocks``: a block map for ``setblock``/``fill``/``execute if block(s)``.
"""
