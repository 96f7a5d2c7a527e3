"""Each command's Python implementation, written once and run by both backends: the numba VM's host
side (:mod:`emulator.vm.host`, for what the VM does not jit) and the reference interpreter
(:mod:`emulator.reference.adapter`). Control flow (the queue, costs, forks, ``function`` and
``return``) is not here: each backend has its own, and they are each other's oracle.

A command takes ``(env, node, ctx)``: the backend (:mod:`.env`), the AST node and the execution
:class:`~emulator.world.state.Context`; it returns its int result or raises
:class:`~.failure.CommandFailure`. The world's state and rules are :mod:`emulator.world`.

Modules
- :mod:`.env`         what a command needs from its backend (:class:`~.env.Env`)
- :mod:`.failure`     the one failure type, keyed to the game's messages (:mod:`emulator.world.errors`)
- :mod:`.dispatch`    the final command of a chain: which module runs it
- :mod:`.scoreboard`  ``scoreboard objectives|players ...``
- :mod:`.holders`     score holders and objectives as arguments
- :mod:`.data`        ``data`` on storage, entities and blocks; ``if data``; ``function ... with``
- :mod:`.conditions`  ``if|unless`` tests, as a stage or as the final command
- :mod:`.stages`      the context-changing execute stages (as, at, positioned, rotated, in, on ...)
- :mod:`.stores`      ``execute store`` into scores, data and bossbars
- :mod:`.entities`    entity arguments and contexts; ``summon kill tag tp ride rotate``
- :mod:`.blocks`      ``setblock``, ``fill``, ``if block(s)``
- :mod:`.living`      ``xp``, ``effect``, ``attribute``, ``damage``
- :mod:`.server`      ``say tellraw gamerule schedule time random trigger``
- :mod:`.bossbar`     ``bossbar``
- :mod:`.level`       the level's data: ``list weather difficulty seed defaultgamemode worldborder setworldspawn spawnpoint``
"""
