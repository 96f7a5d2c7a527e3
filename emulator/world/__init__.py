"""The world library: what datapack commands act on, with the game's exact semantics.

Pure Python over plain values, callable from both backends (the numba VM's host side and the
reference interpreter). Modules:
- ``errors``: ``CommandFailure`` and the game's messages.
- ``nbt_ops``: NBT paths, ``data get/merge/modify/remove``, partial NBT matching.
- ``storage``: command storage (``data ... storage``) with the game's accessor semantics.
- ``data_commands``: ``data``/``execute store``/``if data`` on storage, entities and blocks
  through the game's accessors, and the ``World`` bundle they need.
- ``stores``: ``execute store ... TYPE SCALE`` casts and ``data get [SCALE]`` results.
- ``mth``: the game's float math (sine table, atan2, wrapDegrees) in float32; ``atan_tables``
  holds the JVM's own tables behind ``Mth.atan2``.
- ``rotation``: directions, local coordinates ``^``, ``facing``, rotation wrapping.
- ``source``: the execution context (position, rotation, executor, anchor) and coordinate arguments.
- ``modifiers``: the ``execute`` stages that only move, turn, anchor or re-dimension a context.
- ``entities``: entity types, the entity store, entity NBT view and loading; ``display`` holds the
  render fields display entities save and how loading reads them.
- ``selectors``: ``@s @e @a @p @r @n`` with their arguments.
- ``text``: numbers and tags as Java prints them (``Double.toString``, ``Tag.getAsString``).
- ``teleport``: ``tp`` destinations for every form.
- ``commands``: ``tp``, ``summon``, ``kill`` and ``tag`` from their AST nodes, and entity
  argument resolution.
- ``blocks``: a block map for ``setblock``/``fill``/``execute if block(s)``.
"""
