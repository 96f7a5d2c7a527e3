"""The server: which root sequences run when, what each tick cost, and who is told of each root.

The world loads (:meth:`Runtime.start`): every ``#minecraft:load`` member runs once, each its own
root, before any tick. Each server tick (ServerFunctionManager.tick, then ServerLevel.tickTime):
1. on the first tick after loading, every ``#minecraft:load`` member (unless :meth:`Runtime.start`
   ran them), each its own root;
2. every ``#minecraft:tick`` member in order, each its own root;
3. from 26.1, the world clocks advance (MinecraftServer.tickChildren: after the functions, before
   the levels; :meth:`emulator.world.clocks.WorldClocks.tick`);
4. the game time advances by one, then every scheduled event due at the new time runs, by due
   time then insertion; a scheduled tag runs each member as its own root. Scheduled functions
   run as the server at world spawn; then the blocks' scheduled ticks due
   (:class:`emulator.world.block_ticks.BlockTicks`); before 26.1 the day time then advances by
   one when ``doDaylightCycle`` is on (ServerLevel.tickTime); the weather advances before all of
   step 4 (ServerLevel.advanceWeatherCycle: :mod:`emulator.world.weather`);
5. every burning entity's ``Fire`` counts down, hurting it each 20 ticks, water putting it out
   (Entity.baseTick: :func:`emulator.world.burning.tick_burning`), a living entity with its eyes in a
   block takes ``in_wall`` damage (:func:`emulator.world.suffocation.tick_in_wall`), a player's
   ``Air`` falls with its eyes in water and rises out of it, drowning it at -20 (:func:`emulator.world.breathing.tick_air`),
   a PackTest dummy moves (gravity, landing, fall damage: :func:`emulator.world.falling.tick_falling`),
   items, experience orbs, primed TNT, mobs and armor stands move (:func:`emulator.world.motion.tick_moving`),
   an item frame checks every 101 ticks that it can stay, else breaks and drops
   (:func:`emulator.world.hanging_checks.tick_hanging`),
   every living entity's effects count down (:func:`emulator.world.living.tick_living`; a player
   that lost one fires ``effects_changed``), a dead player's ``DeathTime`` runs
   (:func:`emulator.world.combat.tick_dead`), a player using an item goes on using it
   (:func:`emulator.world.player_actions.tick_using`), an open container out of reach closes
   (:func:`emulator.world.block_use.tick_menus`), a crafter that crafted counts its 6 ticks of
   ``crafting`` down (:func:`emulator.world.crafters.tick_crafting`) and every
   player earns the per-tick statistics (:func:`emulator.world.statistics.tick_players`); arrows,
   tridents, snowballs and thrown items fly, and another projectile made in flight since the last tick is
   reported as not modelled (it would have moved: :func:`emulator.world.projectiles.tick_flying`),
   after area effect clouds age, shrink and affect who is in them (:func:`emulator.world.effect_clouds.
   tick_clouds`: one a potion makes this tick first ticks on the next, as the game's entity list);
6. a spectator behind a camera snaps to it (:func:`emulator.world.spectating.tick_cameras`), then
   every player fires the advancement triggers of its tick (:func:`emulator.world.advancements.
   tick_players`); the block entities tick (:mod:`emulator.world.block_entity_ticks`); a mob in or
   on a block that would act on it is reported as not modelled (:mod:`emulator.world.block_contact`).
An advancement reward function earned by a command (``advancement grant``, ``effect give`` ...)
runs right after that command, inside its root (the backends queue it: AdvancementRewards.grant,
ServerFunctionManager.execute); one earned outside any command (a step of the tick, a PackTest
dummy's action) runs at once as a root of its own, as the player (:meth:`Runtime.run_rewards`,
after each step).

A reload ``datapack`` or ``reload`` asks for (:mod:`emulator.world.pack_repository`) is carried out
when the root that asked ends, or, asked by a load or tick function, once the functions that list
began have run (:meth:`Runtime.apply_reload`; a call after it in that root that the reload changes
is reported: :mod:`emulator.runtime.reloads`); the next tick runs ``#minecraft:load`` first.

Root listeners (:attr:`Runtime.root_listeners`) hear every root the runtime runs, with its result.

:meth:`Runtime.run_ticks` hands a run of quiet ticks to a backend that batches them
(:class:`emulator.runtime.backend.TickBatches`): ticks whose steps 3-6 change nothing but the
clocks (no scheduled event or block tick due, every step of :data:`ENTITY_STEPS` idle, no reward
pending). The backend comes back early when a root needed Python (a host op may change any of
that); the runtime then finishes that tick itself and looks again.
"""
from __future__ import annotations

from collections.abc import Callable

from emulator.runtime import reloads
from emulator.runtime.backend import Backend, RootResult, TickBatches
from emulator.commands import command_contexts
from emulator.commands.advancements import earned_rewards
from emulator.world import (advancements, block_contact, block_entity_ticks, block_use, breathing, burning,
                           combat, crafters, effect_clouds, equipment, falling, hanging_checks, living,
                           motion, nbt_ops, player_actions, projectiles, spawn_protection, spectating, statistics,
                           suffocation)
from emulator.world.context import Context
from emulator.world.pack_repository import PackRepository
from emulator.world.resources import Resources
from emulator.world.dimensions import Levels
from emulator.world.state import WorldState
from mcfunction_parser.nbt import Compound, String
from mcfunction_parser.pack.loader import load_packs
from mcfunction_parser.pack.versions import version_label
from mcfunction_parser.parse import parse_function

COMMAND_BLOCK_FUNCTION = "dpemu:command_block"  # the macro function a command block's command runs in
COMMAND_RUNNER_VERSION = (1, 20, 3)
LOAD_TAG = "minecraft:load"
TICK_TAG = "minecraft:tick"

# steps 5 and 6 in order, each with its test that it would change nothing now
# (a batch of ticks needs every one idle: a step added here comes with its test)
def _living_step(state) -> None:
    """The living entities' tick as far as it is modelled here: their effects
    (:func:`emulator.world.living.tick_living`, an instant effect's damage as combat's magic: it can
    kill; a player that lost one fires ``effects_changed``: ServerPlayer.onEffectsRemoved), then
    their combat trackers' recheck (LivingEntity.tick, every 20 ticks)."""
    for entity in living.tick_living(state, combat.effect_harm):
        advancements.effects_changed(state, entity, None)
    if state.combat_trackers:
        combat.tick_trackers(state)


def _living_idle(state) -> bool:
    return living.tick_is_idle(state) and combat.trackers_idle(state)


def _burning_step(state) -> None:
    """Burning entities' fire ticks (:func:`emulator.world.burning.tick_burning`), its hurt combat's."""
    burning.tick_burning(state, combat.hurt)


def _eyes_step(state) -> None:
    """LivingEntity.baseTick's blocks at the eyes: a wall (:func:`emulator.world.suffocation.
    tick_in_wall`), then the air under water (:func:`emulator.world.breathing.tick_air`); their
    hurt is combat's."""
    for entity in list(state.entities.living_mobs()):
        if not entity.alive or (not state.blocks_in(entity.dimension).states and breathing.settled(entity)):
            continue  # a level with no block: no wall, no water
        suffocation.tick_entity(state, entity, combat.hurt)  # one pass: each entity's wall, then its air
        breathing.tick_entity(state, entity, combat.hurt)


def _eyes_idle(state) -> bool:
    return suffocation.tick_is_idle(state) and breathing.tick_is_idle(state)


ENTITY_STEPS = ((spawn_protection.tick, spawn_protection.tick_is_idle),  # ServerPlayer.tick: first thing
                (_burning_step, burning.tick_is_idle),
                (_eyes_step, _eyes_idle),  # LivingEntity.baseTick: after Entity.baseTick's fire
                (falling.tick_falling, falling.tick_is_idle),
                (motion.tick_moving, motion.tick_is_idle),
                (hanging_checks.tick_hanging, hanging_checks.tick_is_idle),
                (_living_step, _living_idle),
                (equipment.tick, equipment.tick_is_idle),
                (combat.tick_dead, combat.tick_is_idle),
                (player_actions.tick_using, player_actions.tick_is_idle),
                (block_use.tick_menus, block_use.tick_is_idle),
                (crafters.tick_crafting, crafters.tick_is_idle),
                (statistics.tick_players, statistics.tick_is_idle),
                (effect_clouds.tick_clouds, effect_clouds.tick_is_idle),  # before a potion makes one (not ticked then)
                (projectiles.tick_flying, projectiles.tick_is_idle),
                (spectating.tick_cameras, spectating.tick_is_idle),  # ServerPlayer.tick: before its tick trigger
                (advancements.tick_players, advancements.tick_is_idle),
                (block_entity_ticks.tick_block_entities, block_entity_ticks.tick_is_idle),
                (block_contact.tick_report, block_contact.tick_is_idle))

_STEPS = tuple(step for step, _ in ENTITY_STEPS)

# told of each root sequence run: (function id, its result); a listener with a ``roots_ran(function id,
# costs)`` method is told of a batch's roots of one function at once (not cut, no result read)
RootListener = Callable[[str, RootResult], None]


class Runtime:
    """``packs`` running on ``backend`` against ``state``: the backend loads them here, or with
    ``compiled`` keeps what it made of them and only moves to ``state`` (a new world whose
    scoreboard and entity table intern the names of the backend's last one)."""

    def __init__(self, backend: Backend, packs, state: WorldState, sanitize: bool = False,
                 compiled: bool = False) -> None:
        state.resources = Resources.from_packs(packs)
        state.entities.version = tuple(packs.version)
        state.entities.table.levels = Levels.from_packs(packs.dimensions, packs.dimension_types)
        state.pack_repository = PackRepository.from_roots(pack.root for pack in packs.packs)
        advancements.warn_unobserved(state)
        if compiled:
            backend.new_world(state)
        else:
            backend.load(packs, state, sanitize)
        self.backend = backend
        self.packs = packs
        self.state = state
        self.sanitize = sanitize
        self.loaded = False
        self.reloaded = False  # the packs were reloaded: the backend runs other packs than it was given
        self._sweeping = False  # running the functions a tick started (a reload waits for their end)
        self._waiting_roots: list[str] = []  # the roots run while a reload asked for waits (the asker first)
        self.commands_per_tick: list[int] = []
        self.commands_outside_ticks = 0  # API calls made between ticks
        self.max_root_cost = 0  # the costliest root so far (quota headroom = limit - this)
        self.root_listeners: list[RootListener] = []
        self.reload_listeners: list[Callable[[], None]] = []  # told before a reload gives the backend new packs
        self.rewards_cost = 0  # commands advancement rewards ran (counted in their tick)
        self._members: dict[tuple[str, int], tuple[str, ...]] = {}
        self._mixed_lists = nbt_ops.list_rules(packs.version).mixed
        state.command_runner = self.run_command
        state.functions_named = self.functions_named

    def run_command(self, text: str, context: Context) -> int | None:
        """A command block's command as its own root (BaseCommandBlock.performCommand:
        performPrefixedCommand): how many times it succeeded, one per context its ``run`` ran in
        (the source's result callback counts each). It runs as ``return run COMMAND`` in a macro
        function, so both backends parse it when it runs (from 1.20.3, where ``return run`` exists).
        An ``execute`` whose stages only pick contexts (``as``, ``at``, ``positioned`` ... and the
        conditions but ``if function``) and make other than one runs its ``run`` command in each,
        each as a root of its own (the game: one root for the whole command)."""
        if tuple(self.packs.version) < COMMAND_RUNNER_VERSION:
            self.state.error("running a command block's command before 1.20.3", severity="warning", unmodelled=True)
            return None
        if COMMAND_BLOCK_FUNCTION not in self.packs.functions:
            function, _ = parse_function("$return run $(command)", "<command block>", COMMAND_BLOCK_FUNCTION,
                                         tuple(self.packs.version))
            self.packs.functions[COMMAND_BLOCK_FUNCTION] = function
        forked = command_contexts.forked(self.state, self.packs, text, context)
        runs = [(text, context)] if forked is None else [(forked[0], ctx) for ctx in forked[1]]
        return sum(bool(self.run_root(COMMAND_BLOCK_FUNCTION, ctx, Compound(command=String(command))).succeeded)
                   for command, ctx in runs)

    def functions_named(self, name: str, is_tag: bool) -> list:
        """The functions ``function NAME`` (``#NAME`` when ``is_tag``) runs, in order."""
        ids = self.members(name) if is_tag else (name,)
        return [self.packs.functions[f] for f in ids if f in self.packs.functions]

    def members(self, tag: str) -> tuple[str, ...]:
        """The functions ``#tag`` runs, resolved once: the tags do not change while the packs run, and
        functions are only ever added (a command block's), so their count keys what the tag finds."""
        key = (tag, len(self.packs.functions))
        found = self._members.get(key)
        if found is None:
            found = self._members[key] = tuple(self.packs.resolve_tag(tag)) if tag in self.packs.tags else ()
        return found

    def run_root(self, function_id: str, context: Context | None = None, arguments=None) -> RootResult:
        """One root sequence, its NBT lists under the rule of the packs' release (mixed types from 1.21.5)."""
        if nbt_ops.lists_mixed() is self._mixed_lists:  # the rule holds already (a tick's roots, an older release)
            return self._root_ran(function_id, self.backend.run_root(function_id, context, arguments))
        with nbt_ops.list_rules(self.packs.version):
            return self._root_ran(function_id, self.backend.run_root(function_id, context, arguments))

    def _root_ran(self, function_id: str, result: RootResult) -> RootResult:
        """After each root: its listeners, then any reward earned in it outside a command."""
        if result.cost > self.max_root_cost:
            self.max_root_cost = result.cost
        for listener in self.root_listeners:
            listener(function_id, result)
        if self.state.pack_repository.pending is not None:
            self._waiting_roots.append(function_id)
            if not self._sweeping:
                self.apply_reload()
        if self.state.pending_rewards:
            self.run_rewards()
        return result

    def apply_reload(self) -> None:
        """The reload ``datapack``/``reload`` asked for (MinecraftServer.reloadResources): the packs
        of the new selection are read again from their files, as the release the world runs, with
        the game jar they were read with; the world stays. What the packs define is replaced
        (functions, tags, loot, predicates, advancements, recipes); the dimensions stay (the game
        reads them once, when the server starts). The next tick runs ``#minecraft:load`` first."""
        repository = self.state.pack_repository
        selection, repository.pending = repository.pending, None
        packs = load_packs(repository.roots(selection), version_label(self.packs.version),
                           game_jar=self.packs.game_jar)
        packs.add_functions(self.packs.added_functions)
        resources = Resources.from_packs(packs)
        later, self._waiting_roots = self._waiting_roots[1:], []
        self._report_stale(packs, resources, repository.asked_by, later)
        repository.selected = selection
        self.state.resources = resources
        advancements.warn_unobserved(self.state)
        for listener in self.reload_listeners:
            listener()
        self.backend.load(packs, self.state, self.sanitize)
        self.packs, self._members = packs, {}
        self.loaded = False  # ServerFunctionManager.replaceLibrary: postReload
        self.reloaded = True

    def _report_stale(self, packs, resources, asked_by: tuple, later_roots: list[str]) -> None:
        """What the commands after the reload (in the root that asked, at ``asked_by``, and in the
        roots run after it) call or read of what it changed."""
        frames = asked_by + tuple(map(reloads.whole, later_roots))
        stale = reloads.stale_calls(self.packs, packs, frames)
        stale += [r for r in reloads.stale_reads(self.packs, self.state.resources, resources, frames) if r not in stale]
        if stale:
            named = ", ".join("a macro line's" if ref == "$" else ref for ref in stale)
            self.state.error(f"not modelled: {named} called or read after this reload came from the packs before "
                             "it (the game reloads inside the command; here the packs change when the functions "
                             "running then have ended)", asked_by, "warning", unmodelled=True)

    def run_rewards(self) -> int:
        """The advancement rewards earned outside any command, each run now as a root of its own
        (ServerFunctionManager.execute with no execution context running: Commands.
        executeCommandInContext makes one); returns their cost, also added to ``rewards_cost``."""
        cost = 0
        while self.state.pending_rewards:
            for function, context in earned_rewards(self.state, self.packs.functions):
                cost += self.run_root(function, context).cost
        self.rewards_cost += cost
        return cost

    def call(self, function_id: str, context: Context | None = None, arguments=None) -> RootResult:
        """An API call between ticks: one root."""
        before = self.rewards_cost
        result = self.run_root(function_id, context, arguments)
        self.commands_outside_ticks += result.cost + self.rewards_cost - before
        return result

    def start(self) -> int:
        """The world loads: run the ``#minecraft:load`` members now, outside the ticks (the first
        tick then runs only ``#minecraft:tick`` and the schedule). Returns their cost (0 when the
        load functions already ran)."""
        if self.loaded:
            return 0
        self.loaded = True
        self._sweeping = True
        try:
            cost = sum(self.call(f).cost for f in self.members(LOAD_TAG))
        finally:
            self._sweeping = False
        self._reload_if_asked()
        return cost

    def _reload_if_asked(self) -> None:
        if self.state.pack_repository.pending is not None:
            self.apply_reload()

    def tick(self) -> int:
        """Run one server tick; returns its cost (commands executed)."""
        self.rewards_cost = 0
        if nbt_ops.lists_mixed() is self._mixed_lists:
            return self._end_tick(self._tick_roots())
        with nbt_ops.list_rules(self.packs.version):  # entered once for the tick's roots
            cost = self._tick_roots()
        return self._end_tick(cost)

    def _tick_roots(self) -> int:
        """Steps 1 and 2 of a tick: the load functions on the first, then the tick functions (the
        caller entered the list rule: :meth:`run_root` without its check)."""
        cost = 0
        self._sweeping = True  # ServerFunctionManager.tick runs each list it began, whatever reloads
        try:
            if not self.loaded:
                self.loaded = True
                cost += self._run_all(self.members(LOAD_TAG))
                self._reload_if_asked()  # the tick functions are then the new packs'
            run_root, ran = self.backend.run_root, self._root_ran
            for function_id in self.members(TICK_TAG):
                cost += ran(function_id, run_root(function_id)).cost
        finally:
            self._sweeping = False
        return cost

    def run_ticks(self, n: int) -> int:
        """Run ``n`` server ticks, as many :meth:`tick` calls would; returns their cost. Quiet ticks
        run in batches where the backend can."""
        if n == 1:  # one tick() call per tick: nothing to batch
            return self.tick()
        cost = 0
        while n > 0:
            quiet = self._quiet_ticks(n)
            ran, spent = self._batch(quiet) if quiet > 1 else (1, self.tick())
            n -= ran
            cost += spent
        return cost

    def _quiet_ticks(self, n: int) -> int:
        """How many of the next ``n`` ticks may run as a batch: every one but the last must end
        changing only the clocks (see the module's docs)."""
        state = self.state
        if (n <= 1 or not self.loaded or state.pending_rewards or not isinstance(self.backend, TickBatches)
                or not all(idle(state) for _, idle in ENTITY_STEPS)
                or (state.clocks is not None and not state.clocks.steady())):
            return 1
        due = [t for t in (state.schedule.next_due(), state.block_ticks.next_due()) if t is not None]
        return max(1, min(n, min(due) - state.gametime)) if due else n

    def _batch(self, ticks: int) -> tuple[int, int]:
        """Up to ``ticks`` quiet ticks through the backend; returns (ticks run, their cost). The last
        tick it touched ends here: the rest of its functions, then its end (:meth:`_end_tick`)."""
        state = self.state
        members = self.members(TICK_TAG)
        start = (state.gametime, state.tick, state.daytime)
        daylight = state.gamerules.daylight_cycle
        clocks = None if state.clocks is None else state.clocks.snapshot()
        cycle, weather_at = state.gamerules.weather_cycle, [0]

        def at_tick(t: int) -> None:  # ticks 0 .. t-1 of the batch ended moving only the clocks (and the weather)
            state.gametime, state.tick = start[0] + t, start[1] + t
            state.weather.advance_ticks(t - weather_at[0], cycle)  # t only grows in a batch
            weather_at[0] = t
            if clocks is not None:
                state.clocks.after(clocks, t)
            elif daylight:
                state.daytime = start[2] + t
                if t > 0:  # the last tick's updateSkyBrightness saw the day time before it advanced
                    state.sky_time = state.daytime - 1

        self.rewards_cost = 0
        with nbt_ops.list_rules(self.packs.version):
            batch = self.backend.run_ticks(members, ticks, at_tick)
        if batch is None or not len(batch.costs):
            return 1, self.tick()
        costs, m = batch.costs, len(members)
        last = (len(costs) - 1) // m  # the tick the batch ended in
        at_tick(last)
        self.max_root_cost = max(self.max_root_cost, int(costs.max()))
        for j, function_id in enumerate(members):  # every root but the last: not cut, no reward earned
            self._roots_ran(function_id, costs[j:len(costs) - 1:m])
        self.commands_per_tick += costs[:last * m].reshape(last, m).sum(axis=1).tolist()
        self._sweeping = True  # the tick's functions go on (a reload waits for their end)
        try:
            self._root_ran(members[(len(costs) - 1) % m], RootResult(int(costs[-1]), None, batch.cut))
            rest = self._run_all(members[len(costs) - last * m:])
        finally:
            self._sweeping = False
        cost = self._end_tick(int(costs[last * m:].sum()) + rest)
        return last + 1, int(costs[:last * m].sum()) + cost

    def _roots_ran(self, function_id: str, costs) -> None:
        """Roots of ``function_id`` a batch ran (not cut, no reward earned): their listeners."""
        if not len(costs):
            return
        for listener in self.root_listeners:
            many = getattr(listener, "roots_ran", None)
            if many is not None:
                many(function_id, costs)
            else:
                for cost in costs.tolist():
                    listener(function_id, RootResult(cost, None))

    def _end_tick(self, cost: int) -> int:
        """Steps 3-6 of a tick whose functions cost ``cost``; returns the tick's whole cost."""
        state = self.state
        if state.pack_repository.pending is not None:  # asked for by a function the tick ran
            self.apply_reload()
        if state.clocks is not None:
            state.clocks.tick()
        # ServerLevel.tick: advanceWeatherCycle, updateSkyBrightness, then tickTime
        state.weather.advance(state.gamerules.weather_cycle)
        if state.clocks is None:
            state.sky_time = state.daytime
        state.gametime += 1
        while (entry := state.schedule.pop_due(state.gametime)) is not None:
            if entry.is_tag:
                cost += self._run_all(self.members(entry.function))
            elif entry.function in self.packs.functions:  # FunctionCallback: none after a reload took it
                cost += self.run_root(entry.function).cost
        state.block_ticks.run_due(state)
        # ServerLevel.tickTime after the scheduled functions (1.21.11: the rule is advance_time)
        if state.clocks is None and state.gamerules.daylight_cycle:
            state.daytime += 1
        for step in _STEPS:
            step(state)
            if state.pending_rewards:
                self.run_rewards()
        cost += self.rewards_cost
        self.commands_per_tick.append(cost)
        state.tick += 1
        return cost

    def _run_all(self, functions) -> int:
        cost = 0
        for function_id in functions:
            cost += self.run_root(function_id).cost
        return cost
