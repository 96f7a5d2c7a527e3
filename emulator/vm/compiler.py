"""AST -> bytecode for the numba VM.

What compiles to VM instructions: scoreboard ``players`` commands on named holders (``#x``,
``$y``, player names), ``*`` (set, add, remove, reset, enable, and the operations its order does not
change: :func:`_order_free`), ``@s`` and the selectors the VM evaluates (:mod:`emulator.vm.entity_arrays`:
``@e @a @s @p @n @r`` with type, any number of tags, scores, name, team, gamemode, level, rotations,
positions, volumes, distance, limit and sort), ``tag SEL add|remove``, ``enable``; ``if|unless score`` on named holders and
``@s``, ``if|unless entity SEL``, ``if|unless dimension``, ``as|at|positioned as|rotated as|facing entity SEL``,
``on vehicle|passengers``
and ``positioned|facing X Y Z``, ``rotated``, ``anchored``, ``align`` (the VM makes their contexts), ``tp [SEL] X Y Z`` (``~`` and ``^`` too),
``if|unless predicate`` (the predicates :mod:`emulator.vm.predicate_rows` compiles), ``store result|success score`` on named holders and ``@s``, ``store ... entity @s Pos[i] double S``;
``if|unless function``, function calls and tags, every ``return`` form, and macro calls
(instantiated by Python on first use). Everything else is a host op run by Python: a final command
(``OP_HOST``: ``say``, ``schedule``, selectors ...), an execute stage (``OP_HOSTSTAGE``: ``in``,
``on origin``, ``if data`` ...; it sets the context the rest of the chain runs in, through
:mod:`emulator.vm.host` and :mod:`emulator.commands.stages`) or a store into NBT or a bossbar (``OP_HOSTSTORE``).

Shapes (the cost rule is in :mod:`emulator.runtime.backend`; the opcodes in :mod:`emulator.vm.opcodes`)::

    scoreboard players add #a o 1      ADD h o 1                       (charges 1 itself)
    function f                         CALL f                          (charges 1 itself)
    execute if score #a o matches 1.. store result score #b o run function f
                                       CMD ->end; IFMATCH; CHKOBJ; CALL f; STORE; end: ENDCMD
    return run CMD                     CMD k ->none; ...CMD...; RETRES; none: RETNONE
    execute as @e run return 1         CMD ->end; ASSTAGE sel; STAGESDONE; RETV 1; end: ENDCMD; RETPEND
    execute as @e[tag=x] at @s run tp @s ~ ~1 ~
                                       CMD ->end; ASSTAGE sel; ASSTAGE sel' at; STAGESDONE; TP sel' k 7; end: ENDCMD
                                       (sel' is @s; floats[k:k+3] = 0, 1, 0; 7: all three relative)
    execute as @e[nbt={}] run say hi
                                       CMD ->end; HOSTSTAGE; STAGESDONE; HOST; end: ENDCMD
"""
from __future__ import annotations

from typing import Callable

from emulator.vm import loop as vm
from emulator.vm.entity_arrays import shuffles
from emulator.vm.opcodes import OPERATION_KINDS
from emulator.vm.program import HostOp, MacroCall, Program
from emulator.vm.storage_leaves import STORE_TYPES, key_path, number_code
from emulator.world.state import Scoreboard
from mcfunction_parser.ast import (
    Command, Condition, DataGet, DataModify, EntityData, IfData, PathFilter, SourceValue, StorageData, ExAlign, ExAnchored, ExAs, ExAt, ExFacing, ExFacingEntity, ExRotated, Execute, ExOn, ExPositioned, ExPositionedAs,
    ExRotatedAs, Function, FunctionCall, IfDimension, IfEntity, IfFunction, IfScore, IfScoreMatches, NameTarget,
    IfPredicate, ObjectivesAdd, ObjectivesRemove, PathIndex, PathKey, Return, Selector, SourceFrom, TagCommand, ScoreEnable, ScoreGet, ScoreOperation, ScoreReset, ScoreSet,
    StoreBossbar, StoreData, StoreScore, Subcommand, Teleport, Tellraw, Vec2, Vec3, Coord, Wildcard,
)
from emulator.world.semantics import INT_MAX, INT_MIN
from emulator.world.source import world_coordinate
from emulator.commands.entities import ENTITY_CONTEXT_STAGES
from emulator.world.display import TRANSFORM_PARTS
from emulator.world.entity_table import EF_MX, EF_TRANSFORM, EF_X, EF_YAW

_SET_OPS = {"set": vm.OP_SET, "add": vm.OP_ADD, "remove": vm.OP_REMOVE}


class Compiler:
    """Compiles functions into a :class:`Program`, interning names in ``scoreboard``.

    ``functions``: id -> parsed function; ``resolve_tag``: tag id -> member function ids;
    ``tags``: the ids of known tags (an unknown tag is a runtime failure, like the game).
    """

    def __init__(self, program: Program, scoreboard: Scoreboard, functions: dict[str, Function],
                 resolve_tag: Callable[[str], list[str]], tags: set[str] | dict, selectors=None, leaves=None) -> None:
        self.program = program
        self.selectors = selectors  # emulator.vm.entity_arrays.SelectorTables (None: no entity forms)
        self.leaves = leaves  # emulator.vm.storage_leaves.StorageLeaves (None: storage stays with the host)
        self.sb = scoreboard
        self.functions = functions
        self.resolve_tag = resolve_tag
        self.tags = tags
        self.fn_id = ""  # the function being compiled
        self.fn_index = -1
        self.loc = None

    # ------------------------------------------------------------------ functions
    def compile_all(self) -> None:
        for fid in self.functions:
            self.program.intern_function(fid)
        for fid, fn in self.functions.items():
            if not fn.is_macro:
                self.compile_function(fid, fn.commands)

    def compile_function(self, fid: str, commands: tuple[Command, ...] | list[Command]) -> int:
        """Compile a body under id ``fid`` (a macro instance gets its own id); returns its index."""
        idx = self.program.intern_function(fid)
        self.fn_id, self.fn_index = fid, idx
        start = self.program.next_pc
        for cmd in commands:
            self.loc = cmd.loc
            self.command(cmd)
        self.emit(vm.OP_FEND)
        self.program.set_start(idx, start)
        return idx

    def emit(self, op: int, *args: int) -> int:
        return self.program.emit(op, *args, loc=self.loc, owner=self.fn_index)

    # ------------------------------------------------------------------ commands
    def command(self, cmd: Command) -> None:
        if isinstance(cmd, Execute):
            stages, final = flatten_execute(cmd)
            if (len(stages) == 1 and isinstance(stages[0], IfScoreMatches) and _vm_condition(stages[0])
                    and self.one_instruction(final)):
                self.score_test_run(stages[0], final)
            else:
                self.chain(stages, final, returning=False)
        elif isinstance(cmd, Return):
            self.return_(cmd, [], in_chain=False)
        elif isinstance(cmd, FunctionCall):
            self.call(cmd, returning=False)
        else:
            self.final(cmd)

    def final(self, cmd: Command) -> None:
        """A command run once per context, charging 1 (rule 3)."""
        if isinstance(cmd, ScoreSet) and self.vm_holders(cmd.targets):
            h = self.holders(cmd.targets)
            self.emit(_SET_OPS[cmd.action], h, self.objective(cmd.objective), cmd.value)
        elif isinstance(cmd, ScoreReset) and self.vm_holders(cmd.targets):
            h = self.holders(cmd.targets)
            if cmd.objective is None:
                self.emit(vm.OP_RESETALL, h)
            else:
                self.emit(vm.OP_RESET, h, self.objective(cmd.objective))
        elif isinstance(cmd, ScoreGet) and _named(cmd.target):
            self.emit(vm.OP_GET, self.holder(cmd.target), self.objective(cmd.objective))
        elif (isinstance(cmd, ScoreOperation) and self.vm_holders(cmd.targets) and self.vm_holders(cmd.sources)
              and _order_free(cmd)):
            h, o = self.holders(cmd.targets), self.objective(cmd.objective)
            h2 = self.holders(cmd.sources, sources_of=(h, o))
            self.emit(vm.FIRST_OPERATION + OPERATION_KINDS[cmd.op], h, o, h2, self.objective(cmd.source_objective))
        elif isinstance(cmd, ScoreEnable) and self.vm_holders(cmd.targets):
            h = self.holders(cmd.targets)
            self.emit(vm.OP_ENABLE, h, self.objective(cmd.objective))
        elif isinstance(cmd, TagCommand) and (tag := self.tag_operands(cmd)) is not None:
            self.emit(vm.OP_TAG, tag[0], tag[1], int(cmd.action == "add"))
        elif isinstance(cmd, Teleport) and (tp := self.teleport(cmd)) is not None:
            self.emit(vm.OP_TP, *tp)
            self.host(vm.OP_HOST, cmd)  # a target going to another level
        elif isinstance(cmd, DataGet) and (field := _entity_field(cmd.target, cmd.path)) is not None:
            self.host(vm.OP_GETFIELD, cmd, field[0], self.program.intern_float(1.0 if cmd.scale is None else cmd.scale),
                      operand=3)
        elif isinstance(cmd, DataModify) and (leaf := self.set_leaf(cmd)) is not None:
            self.host(vm.OP_SETLEAF, cmd, *leaf, operand=4)
        elif isinstance(cmd, DataModify) and (leaves := self.copy_leaves(cmd)) is not None:
            self.host(vm.OP_COPYLEAF, cmd, *leaves, operand=3)
        elif isinstance(cmd, DataGet) and (leaf := self.leaf(cmd.target, cmd.path)) is not None:
            self.host(vm.OP_GETLEAF, cmd, leaf, self.program.intern_float(1.0 if cmd.scale is None else cmd.scale),
                      operand=3)
        elif isinstance(cmd, (ObjectivesAdd, ObjectivesRemove)):
            self.host(vm.OP_OBJECTIVE, cmd, self.objective(cmd.objective), int(isinstance(cmd, ObjectivesAdd)),
                      operand=3)
        elif isinstance(cmd, Tellraw) and not shuffles(cmd.targets) and (sel := self.selector(cmd.targets)) is not None:
            self.host(vm.OP_LOG, cmd, sel)  # the host writes the line
        else:
            self.host(vm.OP_HOST, cmd)

    def one_instruction(self, cmd: Command | None) -> bool:
        """``cmd`` compiles to one instruction that leaves the context as it found it: a score
        command or operation on names (or ``@s``), a call of a plain function."""
        if isinstance(cmd, ScoreSet):
            return _named(cmd.targets)
        if isinstance(cmd, ScoreOperation):
            return _named(cmd.targets) and _named(cmd.sources)
        return (isinstance(cmd, FunctionCall) and not cmd.is_tag and cmd.arguments is None and cmd.with_source is None
                and cmd.function in self.functions and not self.functions[cmd.function].is_macro)

    def score_test_run(self, st: IfScoreMatches, final: Command) -> None:
        """``execute if|unless score H O matches R run CMD``, CMD one instruction: IFRUN, then CMD
        (the chain's CMD, IFMATCH and ENDCMD in one: the hot shape of scoreboard code)."""
        lo = INT_MIN if st.range.lo is None else max(INT_MIN, st.range.lo)
        hi = INT_MAX if st.range.hi is None else min(INT_MAX, st.range.hi)
        at = self.emit(vm.OP_IFRUN, self.holder(st.target), self.objective(st.objective), lo, hi, 0, int(st.negated))
        self.command(final)
        if self.program.next_pc != at + 2:
            raise AssertionError(f"IFRUN's command took {self.program.next_pc - at - 1} instructions")
        self.program.patch(at, 5, self.program.next_pc)

    def host(self, op: int, node: Command | Subcommand, *operands: int, operand: int = 1) -> None:
        """Emit ``op`` naming ``node`` as a host op (its index in operand slot ``operand``, among ``operands``)."""
        self.program.host_ops.append(HostOp(node, self.fn_id))
        index = len(self.program.host_ops) - 1
        self.emit(op, *operands[:operand - 1], index, *operands[operand - 1:])

    # ------------------------------------------------------------------ execute chains

    def chain(self, stages: list[Subcommand], final: Command | None, returning: bool,
              outer_stores: tuple[StoreScore, ...] = (), forked: bool = False) -> None:
        """``CMD``, the stages, the final command, the stores, then the chain's end: ``ENDCMD``,
        or for ``return run`` (``returning``) ``RETRES`` with the abort target ``RETNONE``.
        ``forked``: the chain continues one that forked (``return run``'s rest keeps its
        ChainModifiers: a stage's error there fails only its context too)."""
        cmd_pc = self.emit(vm.OP_CMD, 0)
        stores = list(outer_stores)
        barriers = []
        for i, st in enumerate(stages):
            last = final is None and i == len(stages) - 1
            forked = forked or isinstance(st, _FORKS)
            if isinstance(st, (IfScoreMatches, IfScore)) and not _vm_condition(st):
                self.host(vm.OP_HOST if last else vm.OP_HOSTSTAGE, st, int(forked))
            elif isinstance(st, IfEntity) and (sel := self.selector(st.targets)) is not None:
                self.emit(vm.OP_IFENT, sel, 0, 0, 0, 0, int(st.negated), int(last))
            elif isinstance(st, IfPredicate) and (sel := self.this_predicate(st)) is not None:
                self.emit(vm.OP_IFENT, sel, 0, 0, 0, 0, int(st.negated), int(last))  # counts 1 or 0
            elif isinstance(st, IfData) and (test := self.leaf_test(st)) is not None:
                self.emit(vm.OP_IFLEAF, *test, 0, 0, int(st.negated), int(last))
            elif isinstance(st, IfDimension) and st.dimension in self.program.levels.ids:  # else it fails: host
                self.emit(vm.OP_IFDIM, self.program.levels.ids[st.dimension], 0, 0, 0, 0, int(st.negated), int(last))
            elif isinstance(st, ENTITY_CONTEXT_STAGES) and not last and (sel := self.selector(st.targets)) is not None:
                self.emit(vm.OP_ASSTAGE, sel, int(forked), ENTITY_CONTEXT_STAGES.index(type(st)))
            elif isinstance(st, ExOn) and not last and st.relation in _RELATIONS and self.selectors is not None:
                self.emit(vm.OP_ASSTAGE, _RELATIONS[st.relation], int(forked), 0)  # as each related entity
            elif isinstance(st, ExFacingEntity) and not last and (sel := self.selector(st.targets)) is not None:
                self.emit(vm.OP_ASSTAGE, sel, int(forked), vm.FACING_EYES if st.anchor == "eyes" else vm.FACING_FEET)
            elif isinstance(st, (ExPositioned, ExFacing)) and not last:
                first, flags = self.coordinates(st.pos)
                self.emit(vm.OP_CTXSTAGE, vm.CTX_POSITIONED if isinstance(st, ExPositioned) else vm.CTX_FACING, flags,
                          first)
            elif isinstance(st, ExRotated) and not last and "local" not in (st.rot.x.kind, st.rot.y.kind):
                first = self.program.next_float
                self.emit(vm.OP_CTXSTAGE, vm.CTX_ROTATED, self.angles(st.rot), first)
            elif isinstance(st, ExAnchored) and not last:
                self.emit(vm.OP_CTXSTAGE, vm.CTX_ANCHORED, vm.ANCHOR_EYES if st.anchor == "eyes" else vm.ANCHOR_FEET)
            elif isinstance(st, ExAlign) and not last:
                self.emit(vm.OP_CTXSTAGE, vm.CTX_ALIGN, sum(1 << "xyz".index(a) for a in st.axes))
            elif (column := _field_store(st)) is not None and _context_kept(stages[i + 1:], final):
                self.emit(vm.OP_FIELDSTAGE, 1, int(forked))
                stores.append(_FieldStore(st, column))
            elif (isinstance(st, StoreData) and st.type in STORE_TYPES
                  and (leaf := self.leaf(st.target, st.path)) is not None):
                self.emit(vm.OP_FIELDSTAGE, 0, int(forked))
                stores.append(_LeafStore(st, leaf))
            elif isinstance(st, IfScoreMatches):
                lo = INT_MIN if st.range.lo is None else max(INT_MIN, st.range.lo)
                hi = INT_MAX if st.range.hi is None else min(INT_MAX, st.range.hi)
                self.emit(vm.OP_IFMATCH, self.holder(st.target), self.objective(st.objective), lo, hi, 0,
                          int(st.negated), int(last))
            elif isinstance(st, IfScore):
                self.emit(vm.OP_IFSCORE, vm.CMP_BY_SYMBOL[st.op], self.holder(st.target), self.objective(st.objective),
                          self.holder(st.source), self.objective(st.source_objective), int(st.negated), int(last))
            elif isinstance(st, StoreScore) and isinstance(st.targets, NameTarget):
                self.emit(vm.OP_CHKOBJ, self.objective(st.objective), int(forked))
                stores.append(st)
            elif isinstance(st, StoreScore) and _bare_self(st.targets) and _context_kept(stages[i + 1:], final):
                self.emit(vm.OP_CHKOBJ, self.objective(st.objective), int(forked), 1)
                stores.append(_SelfScoreStore(st))
            elif (isinstance(st, StoreScore) and isinstance(st.targets, Wildcard) and not outer_stores
                  and _tracking_kept(stages, final)):
                self.emit(vm.OP_CHKOBJ, self.objective(st.objective), int(forked), 2)
                stores.append(_TrackedScoreStore(st))
            elif isinstance(st, (StoreScore, StoreData, StoreBossbar)):
                self.host(vm.OP_HOSTSTAGE, st, int(forked))  # resolves the store's target now, as the modifier does
                stores.append(st)
            elif isinstance(st, IfFunction):  # the calls, then the rest of the chain as a new entry
                if not returning and any(isinstance(before, _MULTIPLY) for before in stages[:i]):
                    barriers.append(self.emit(vm.OP_STAGESDONE, 0, 1))  # every context before any call
                self.if_function(st)
                self.emit(vm.OP_CONT)
            else:  # a context modifier or a condition the VM does not evaluate
                if not last and (guard := self.guard(st)) is not None:
                    self.emit(vm.OP_HOSTGUARD, guard, int(isinstance(st, IfEntity) and st.negated))
                self.host(vm.OP_HOST if last else vm.OP_HOSTSTAGE, st, int(forked))
        collect = final is not None and not returning and any(isinstance(st, _MULTIPLY) for st in stages)
        collect_pc = self.emit(vm.OP_STAGESDONE, 0) if collect else None
        if isinstance(final, Return):
            self.return_(final, stores, in_chain=True, forked=forked)
            stores = []
        elif isinstance(final, FunctionCall):
            self.call(final, returning)
        elif final is not None:
            self.final(final)
        self.stores(stores)
        if returning:
            self.emit(vm.OP_RETRES)
            end = self.emit(vm.OP_RETNONE)
        else:
            end = self.emit(vm.OP_ENDCMD)
            if isinstance(final, Return) and final.kind != "run":
                self.emit(vm.OP_RETPEND)  # each context returned (or none did): now the function ends
        self.program.patch(cmd_pc, 1, end)
        for pc in barriers + ([collect_pc] if collect_pc is not None else []):
            self.program.patch(pc, 1, end)

    def stores(self, stores: list) -> None:
        """Apply the chain's stores to the result, in the order written (callbacks chain so)."""
        for st in stores:
            if isinstance(st, _SelfScoreStore):
                self.emit(vm.OP_STORE, 0 if st.node.kind == "result" else 1, vm.HOLDER_SELF,
                          self.objective(st.node.objective))
            elif isinstance(st, _LeafStore):
                self.host(vm.OP_STORELEAF, st.node, st.leaf, 0 if st.node.kind == "result" else 1,
                          self.program.intern_float(st.node.scale), STORE_TYPES[st.node.type], operand=5)
            elif isinstance(st, _FieldStore):
                self.host(vm.OP_STOREFIELD, st.node, st.column, 0 if st.node.kind == "result" else 1,
                          self.program.intern_float(st.node.scale), operand=4)
            elif isinstance(st, _TrackedScoreStore):
                self.emit(vm.OP_STORE, 0 if st.node.kind == "result" else 1, vm.HOLDER_TRACKED,
                          self.objective(st.node.objective))
            elif isinstance(st, StoreScore) and isinstance(st.targets, NameTarget):
                self.emit(vm.OP_STORE, 0 if st.kind == "result" else 1, self.holder(st.targets),
                          self.objective(st.objective))
            else:
                self.host(vm.OP_HOSTSTORE, st)

    def if_function(self, st: IfFunction) -> None:
        members = self.members(st.function, st.is_tag, abort=True)
        if members is None:
            return
        if not members:  # an empty tag: the rest of the chain never runs
            self.emit(vm.OP_STOP)
            return
        if any(self.functions[m].is_macro for m in members):
            self.emit(vm.OP_FAIL, vm.ERR_MACRO_ARGS, self.name(st.function), 0, 1)
            return
        self.emit(vm.OP_IFFN_BEGIN)
        steps = []
        for m in members:
            self.emit(vm.OP_CALL, self.program.intern_function(m))
            steps.append(self.emit(vm.OP_IFFN_STEP, 0))
        end = self.emit(vm.OP_IFFN_END, int(st.negated))
        for pc in steps:
            self.program.patch(pc, 1, end)

    # ------------------------------------------------------------------ return
    def return_(self, cmd: Return, stores: list[StoreScore], in_chain: bool, forked: bool = False) -> None:
        if cmd.kind in ("value", "fail"):
            ok, value = (1, cmd.value) if cmd.kind == "value" else (0, 0)
            if stores:  # the return's callback feeds the chain's stores first
                self.emit(vm.OP_RESULT, ok, value)
                self.stores(stores)
            if cmd.kind == "value":
                self.emit(vm.OP_RETV, value, int(not in_chain))
            else:
                self.emit(vm.OP_RETFAIL, 0, int(not in_chain))
            return
        # return run CMD: a continuation entry in return mode; skipped if no context is left
        gate = self.emit(vm.OP_JMPDEAD, 0) if in_chain else None
        inner = cmd.command
        stages, final = flatten_execute(inner) if isinstance(inner, Execute) else ([], inner)
        self.chain(stages, final, returning=True, outer_stores=tuple(stores), forked=forked)
        if gate is not None:
            self.program.patch(gate, 1, self.program.next_pc)

    # ------------------------------------------------------------------ calls
    def call(self, cmd: FunctionCall, returning: bool) -> None:
        members = self.members(cmd.function, cmd.is_tag, abort=False)
        if members is None:
            return
        if not members:
            self.emit(vm.OP_FAIL, vm.ERR_EMPTY_TAG, self.name("#" + cmd.function), 0, 0)
            return
        with_arguments = cmd.arguments is not None or cmd.with_source is not None
        if not cmd.is_tag and (with_arguments or self.functions[members[0]].is_macro):
            self.macro_call(cmd, members[0])
            self.emit(vm.OP_CALLREG)
            return
        # a tag: each macro member is instantiated with the call's arguments (a plain one ignores
        # them); one that cannot be fails the command and the later members are not queued
        ends = []
        if returning:
            skips = []
            for i, member in enumerate(members):
                ends += self.member_call(member, cmd)
                if i < len(members) - 1:
                    skips.append(self.emit(vm.OP_RETIFHAS, 0))
            for pc in skips + ends:
                self.program.patch(pc, 1, self.program.next_pc)
            return
        if len(members) == 1:
            ends += self.member_call(members[0], cmd)
        else:
            self.emit(vm.OP_TAGBEGIN)
            for member in members:
                ends += self.member_call(member, cmd)
                self.emit(vm.OP_TAGACC)
            self.emit(vm.OP_TAGEND)
        for pc in ends:
            self.program.patch(pc, 1, self.program.next_pc)

    def member_call(self, member: str, cmd: FunctionCall) -> list[int]:
        """Call one member of a tag; the pcs to patch with the call's end (after a failed instantiation)."""
        if not self.functions[member].is_macro:
            self.emit(vm.OP_CALL, self.program.intern_function(member))
            return []
        self.macro_call(cmd, member)
        skip = self.emit(vm.OP_IFNOFN, 0)
        self.emit(vm.OP_CALLREG)
        return [skip]

    def macro_call(self, cmd: FunctionCall, function: str) -> None:
        self.program.macro_calls.append(MacroCall(cmd, function, self.fn_id))
        self.emit(vm.OP_MACRO, len(self.program.macro_calls) - 1)

    def members(self, function: str, is_tag: bool, abort: bool) -> list[str] | None:
        """The functions a reference runs, or None after emitting the unknown-function failure."""
        if is_tag:
            if function in self.tags:
                return self.resolve_tag(function)
            self.emit(vm.OP_FAIL, vm.ERR_UNKNOWN_FUNCTION, self.name("#" + function), 0, int(abort))
            return None
        if function in self.functions:
            return [function]
        self.emit(vm.OP_FAIL, vm.ERR_UNKNOWN_FUNCTION, self.name(function), 0, int(abort))
        return None

    # ------------------------------------------------------------------ entities
    def selector(self, target) -> int | None:
        """The selector row of ``target`` when the VM evaluates it, else None."""
        return None if self.selectors is None else self.selectors.selector(target)

    def guard(self, st: Subcommand) -> int | None:
        """OP_HOSTGUARD's selector for a host stage that finds entities (SelectorTables.guard)."""
        if self.selectors is None or not isinstance(st, (IfEntity, ExFacingEntity, *ENTITY_CONTEXT_STAGES)):
            return None
        return self.selectors.guard(st.targets)

    def this_predicate(self, st: IfPredicate) -> int | None:
        """The KIND_THIS selector row of ``if|unless predicate ID|{...}`` when the VM evaluates it
        (an unknown id, an inline predicate the game refuses and what the VM does not read stay
        with the host)."""
        if self.selectors is None:
            return None
        return self.selectors.this_predicate(st.predicate)

    def teleport(self, cmd: Teleport) -> tuple[int, ...] | None:
        """OP_TP's operands (selector, first of x y z in floats, flags, kind, its operand) for ``tp
        [SEL] X Y Z [YAW PITCH | facing X Y Z | facing entity E [ANCHOR]]`` and ``tp [SEL] E``; None
        when the host runs it (a selector the VM does not evaluate, or a random one: the host runs
        the command again for a target going to another level, which must draw once). Flags: the
        relative (``~``) axes' bits, ``TP_LOCAL`` for ``^``, ``TP_SELF`` without targets (the
        executor, turned to the execution rotation), ``TP_ROT`` and the relative angles. Kind:
        TPF_POS (the facing position's flags, its x y z after the angles), TPF_FEET or TPF_EYES (the
        faced entity's selector), TPF_ENTITY (the destination's selector, no floats). Absolute
        integer x/z are centred (+0.5), as Vec3Argument's ``WorldCoordinate.get`` does
        (emulator.world.source)."""
        if any(shuffles(t) for t in (cmd.targets, cmd.facing_entity, cmd.destination)):
            return None
        sel = self.selector(Selector("s", (), cmd.loc) if cmd.targets is None else cmd.targets)
        if sel is None:
            return None
        dest = cmd.destination
        if not isinstance(dest, Vec3):
            entity = self.selector(dest)
            return None if entity is None else (sel, 0, 0, vm.TPF_ENTITY, entity)
        kind, operand = 0, 0
        if cmd.facing_entity is not None:
            operand = self.selector(cmd.facing_entity)
            if operand is None:
                return None
            kind = vm.TPF_EYES if cmd.facing_anchor == "eyes" else vm.TPF_FEET
        first, flags = self.coordinates(dest)
        rotation = self.angles(cmd.rotation or Vec2(Coord("abs", 0.0), Coord("abs", 0.0), dest.loc))
        flags |= (vm.TP_REL_YAW if rotation & 1 else 0) | (vm.TP_REL_PITCH if rotation & 2 else 0)
        if cmd.rotation is not None:
            flags |= vm.TP_ROT
        if cmd.facing is not None:
            kind, operand = vm.TPF_POS, self.coordinates(cmd.facing)[1]
        return sel, first, flags | (vm.TP_SELF if cmd.targets is None else 0), kind, operand

    def angles(self, rot: Vec2) -> int:
        """Intern a rotation's two angles (the next two floats); the bits of its relative ones."""
        self.program.intern_float(rot.x.value)
        self.program.intern_float(rot.y.value)
        return (1 if rot.x.kind == "rel" else 0) | (2 if rot.y.kind == "rel" else 0)

    def coordinates(self, vec: Vec3) -> tuple[int, int]:
        """(first of x y z in floats, flags) of a position argument for OP_TP and OP_CTXSTAGE: the
        relative axes' bits, or TP_LOCAL."""
        coords = (vec.x, vec.y, vec.z)
        first = self.program.next_float
        for axis, coord in enumerate(coords):
            world = coord.kind == "abs"
            self.program.intern_float(world_coordinate(coord, 0.0, axis != 1) if world else coord.value)
        flags = vm.TP_LOCAL if vec.is_local else sum(1 << axis for axis, c in enumerate(coords) if c.kind == "rel")
        return first, flags

    # ------------------------------------------------------------------ storage numbers
    def leaf(self, target, path) -> int | None:
        """The storage leaf of ``storage S a.b.c`` (compound keys and list indices: ``a.l[0]``), else None."""
        keys = key_path(path)
        if self.leaves is None or not isinstance(target, StorageData) or keys is None:
            return None
        return self.leaves.leaf(target.id, keys)

    def set_leaf(self, cmd: DataModify) -> tuple[int, int, int] | None:
        """(leaf, type, number) of ``data modify storage S P set value N`` with N a number the VM mirrors."""
        if cmd.mode != "set" or not isinstance(cmd.source, SourceValue) or not number_code(cmd.source.value):
            return None
        leaf = self.leaf(cmd.target, cmd.path)
        if leaf is None:
            return None
        return leaf, number_code(cmd.source.value), self.program.intern_float(float(cmd.source.value))

    def copy_leaves(self, cmd: DataModify) -> tuple[int, int] | None:
        """(leaf, source leaf) of ``data modify storage S P set from storage S2 P2``, both paths of
        keys and list indices (a copy of one tag: NbtPathArgument.set of the last value found)."""
        source = cmd.source
        if cmd.mode != "set" or not isinstance(source, SourceFrom) or source.path is None:
            return None
        leaf, copied = self.leaf(cmd.target, cmd.path), self.leaf(source.source, source.path)
        return None if leaf is None or copied is None else (leaf, copied)

    def leaf_test(self, st: IfData) -> tuple[int, int, int] | None:
        """(leaf, type, number) of ``if|unless data storage S {K:N}`` (one key, a number the VM mirrors),
        or (leaf, 0, 0) of ``if|unless data storage S a.b.c`` (compound keys: the path leads to a tag,
        counted once as the game counts the tags it finds)."""
        if (leaf := self.leaf(st.source, st.path)) is not None:
            return leaf, 0, 0
        nodes = st.path.nodes
        if not (len(nodes) == 1 and isinstance(nodes[0], PathFilter) and len(nodes[0].pattern) == 1):
            return None
        (key, value), = nodes[0].pattern.items()
        if not number_code(value) or self.leaves is None or not isinstance(st.source, StorageData):
            return None
        return self.leaves.leaf(st.source.id, (key,)), number_code(value), self.program.intern_float(float(value))

    def tag_operands(self, cmd: TagCommand) -> tuple[int, int] | None:
        """(selector, tag number) of ``tag SEL add|remove T`` when the VM can run it, else None."""
        if cmd.action not in ("add", "remove") or (sel := self.selector(cmd.targets)) is None:
            return None
        return sel, self.selectors.tag_id(cmd.name)

    # ------------------------------------------------------------------ names
    def holder(self, target) -> int:
        """A name's holder id, or HOLDER_SELF for a bare ``@s`` (the VM reads the executor's)."""
        if isinstance(target, Selector):
            return vm.HOLDER_SELF
        return self.sb.holder_id(target.name)

    def holders(self, target, sources_of: tuple[int, int] | None = None) -> int | None:
        """The holder operand of a name, ``@s``, ``*`` or a selector the VM evaluates (its SELHOLDERS is
        emitted now, so call this just before the op and only once it will be emitted); None for
        the host. ``sources_of``: the operation's target operand and objective, for its sources."""
        if _named(target):
            return self.holder(target)
        sel = vm.SEL_TRACKED if isinstance(target, Wildcard) else self.selector(target)
        if sel is None:
            return None
        self.emit(vm.OP_SELHOLDERS, sel, int(sources_of is not None), *(sources_of or ()))
        return vm.HOLDER_SELBUF

    def vm_holders(self, target) -> bool:
        return _named(target) or isinstance(target, Wildcard) or self.selector(target) is not None

    def objective(self, name: str) -> int:
        return self.sb.objective_id(name)

    def name(self, text: str) -> int:
        return self.program.intern_name(text)


# Stages registered with ``fork`` in ExecuteCommand (the others are plain redirects)
_FORKS = (Condition, ExAs, ExAt, ExPositionedAs, ExRotatedAs, ExFacingEntity, ExOn)  # `summon` redirects
# `execute on` relations the VM follows itself (the entity table's EI_VEHICLE); the others read NBT
_RELATIONS = {"vehicle": vm.REL_VEHICLE, "passengers": vm.REL_PASSENGERS}
# Stages that can make several contexts: their chains collect the contexts before the final command
_MULTIPLY = (ExAs, ExAt, ExPositionedAs, ExRotatedAs, ExFacingEntity, ExOn)


class _FieldStore:
    """A ``store ... entity @s PATH TYPE S`` into a field the entity table keeps (see :func:`_field_store`)."""

    def __init__(self, node: StoreData, column: int) -> None:
        self.node = node
        self.column = column


class _LeafStore:
    """A ``store ... storage S P TYPE SCALE`` into a storage leaf."""

    def __init__(self, node: StoreData, leaf: int) -> None:
        self.node = node
        self.leaf = leaf


class _SelfScoreStore:
    """A ``store result|success score @s OBJ`` the VM runs (the chain keeps its executor)."""

    def __init__(self, node: StoreScore) -> None:
        self.node = node


class _TrackedScoreStore:
    """A ``store result|success score * OBJ`` the VM runs (the chain keeps the holders tracked: :func:`_tracking_kept`)."""

    def __init__(self, node: StoreScore) -> None:
        self.node = node


# The numeric entity fields the entity table keeps: NBT list -> (first column, size, element type)
_FIELD_LISTS = {"Pos": (EF_X, 3, "double"), "Motion": (EF_MX, 3, "double"), "Rotation": (EF_YAW, 2, "float")}


def _field_store(st) -> int | None:
    """The column of ``store result|success entity @s PATH TYPE S`` when PATH is a field the table
    keeps and TYPE its list's element type (another type does not fit the list: the host's store
    fails as the game's does), else None."""
    if not isinstance(st, StoreData):
        return None
    field = _entity_field(st.target, st.path)
    return field[0] if field is not None and field[1] == st.type else None


def _entity_field(target, path) -> tuple[int, str] | None:
    """(column, element type) when ``target path`` is ``entity @s`` and one number of Pos, Motion,
    Rotation or a display's ``transformation`` part (the VM checks the entity is a display), else None."""
    if not (isinstance(target, EntityData) and _bare_self(target.target) and path is not None):
        return None
    nodes = path.nodes
    if len(nodes) == 2 and isinstance(nodes[0], PathKey) and nodes[0].name in _FIELD_LISTS:
        first, size, element = _FIELD_LISTS[nodes[0].name]
    elif (len(nodes) == 3 and nodes[0] == PathKey("transformation") and isinstance(nodes[1], PathKey)
          and nodes[1].name in TRANSFORM_PARTS):
        start, size = TRANSFORM_PARTS[nodes[1].name]
        first, element = EF_TRANSFORM + start, "float"
    else:
        return None
    index = nodes[-1]
    if not (isinstance(index, PathIndex) and -size <= index.index < size):
        return None
    return first + index.index % size, element


def _context_kept(later: list[Subcommand], final) -> bool:
    """No later stage (nor a ``return run`` chain) changes the executor: a store resolved at its
    stage writes to the entity the chain ends with."""
    return all(isinstance(st, (Condition, StoreScore, StoreData, StoreBossbar)) for st in later) and not (
        isinstance(final, Return) and final.kind == "run")


def _tracking_kept(stages: list[Subcommand], final) -> bool:
    """Nothing in the chain gives a holder its first score or takes its last, so the holders ``*``
    names when its store runs are those its stage read (ExecuteCommand.storeValue resolves them
    there): the chain's only store (nor one of an enclosing ``return run``'s chain), no call (``if
    function``), and no final command but a read (``scoreboard players get``, ``data get``) or none."""
    stores = [st for st in stages if isinstance(st, (StoreScore, StoreData, StoreBossbar))]
    return (len(stores) == 1 and not any(isinstance(st, IfFunction) for st in stages)
            and (final is None or isinstance(final, (ScoreGet, DataGet))))


def _bare_self(target) -> bool:
    return isinstance(target, Selector) and target.variable == "s" and not target.args


def _named(holder) -> bool:
    """A holder the VM resolves itself: a name, or a bare ``@s`` (through the context's holder)."""
    return isinstance(holder, NameTarget) or _bare_self(holder)


def _order_free(cmd: ScoreOperation) -> bool:
    """The operation gives the game's scores whatever order ``*`` names its holders in (the game's
    is its score map's hash order, the VM's the interning order): ``*`` on one side only, the two
    objectives different (no target is a source), and for ``*`` targets an operation that neither
    writes the source (``><``) nor may stop half-way (``/=`` and ``%=`` by zero fail at the first
    target, which alone got its score created); for ``*`` sources only ``<`` and ``>`` (each
    target's steps in another order would wrap, and the sanitizer report, differently)."""
    wild_targets, wild_sources = isinstance(cmd.targets, Wildcard), isinstance(cmd.sources, Wildcard)
    if not (wild_targets or wild_sources):
        return True
    if (wild_targets and wild_sources) or cmd.objective == cmd.source_objective:
        return False
    return cmd.op in ("<", ">") or (wild_targets and cmd.op in ("=", "+=", "-=", "*="))


def _vm_condition(st: IfScore | IfScoreMatches) -> bool:
    if isinstance(st, IfScore):
        return _named(st.target) and _named(st.source)
    return _named(st.target)


def flatten_execute(cmd: Execute) -> tuple[list[Subcommand], Command | None]:
    """``execute A run execute B run C`` -> stages A+B, final C (``run`` costs nothing)."""
    stages: list[Subcommand] = []
    final: Command | None = cmd
    while isinstance(final, Execute):
        stages.extend(final.subcommands)
        final = final.run
    return stages, final
