"""The numba VM: opcodes and the single @njit dispatch loop, alone in this module.

The opcodes live here because numba's on-disk cache does not notice a changed constant imported
from another module. The compiler (:mod:`emulator.vm.compiler`) imports them from here.

Code layout: ``code`` is ``int32[n, WIDTH]``, one instruction per row: ``[op, a, b, c, d, e, f, g]``.
A command line compiles to a short sequence (see the compiler); the cost rule implemented here is
the one documented in :mod:`emulator.runtime.backend`.

Machine state lives in arrays owned by Python so the loop can return (for a host command, a macro
instantiation, contexts to make, a full frame stack, a runtime error, a full buffer) and resume:
``regs`` (int64, indexes ``R_*``), the frame stack ``frames`` (int64 ``[depth, F_WIDTH]``), the
scoreboard ``values``/``present``/``locked``/``alive``, the per-instruction ``counts``, the
sanitizer's ``ovf`` buffer, the queued log lines ``logbuf``, per context its executor's holder,
slot and position (``ctx_holder``, ``ctx_entity``, ``ctx_pos``), and the entities
(:mod:`emulator.vm.entity_arrays`: ``ent``, ``epos``, ``edirty``, ``eorder``, with the selector
tables ``sels``/``tests`` and the scratch ``selbuf`` for what a selector finds). Registers that
matter across a call (``alive``, the tag accumulator, the command's abort target, the context,
the fork loop flag) are saved in the frame and restored on return.

A call with array arguments costs more than a whole scoreboard command here, and even an untaken
call in a branch slows it: the scoreboard ops resolve names and ``@s`` themselves and read a
selector's holders from OP_SELHOLDERS, emitted just before them.
The same holds for an ``inline="always"`` helper taking an array when the inlined body branches
(numba then keeps a reference count increment and decrement per use: the charge preamble
``quota -= 1; counts[pc] += 1`` as such a helper halved the loop's speed), so the charge is
written out in each op; the shared helpers take scalars or run straight-line code. The scoreboard
ops take a lean path for one target and one source (a name or ``@s``), and the dispatch chain
tests the hottest opcodes first (operations, set/add/remove, a chain's CMD/IF*/ENDCMD, calls).
``run`` uses numba's ``numpy`` error model: the divisions check their divisor themselves, and
without the Python model's ZeroDivisionError paths the loop is smaller and a few % faster.
The generated code is sensitive to the loop's shape (measured with ``bench_vm.py --baseline``): one
entry-rule test before the dispatch for every line command cost 7 %, one branch for the four
execute stages 30 % (register allocation), so only the cold line commands share a branch.

Forks: the VM runs a chain for one context (``R_CTX``, an index into the backend's context
table). When a stage makes several (Python makes the contexts: a host stage, ``as SEL``, ``if
function`` returning several times), Python sets ``R_LOOP`` and pushes the others on the fork
stack ``fstack`` (rows ``[depth, resume pc, context]``, the next one on top). The chain's
``STAGESDONE`` (after the last stage) keeps the context in ``coll`` (rows ``[depth, context,
final pc]``; the frame's ``F_CHEAD`` is the first not yet run) and jumps to the chain's ``ENDCMD``,
which re-enters the chain after the forking stage with the next context of its depth; once every
context went through the stages, it runs the final command for each kept context in turn (each
stage sees all contexts before any final command runs, as the game's BuildContexts does), then
ends the command. Rows of deeper depths left by a function that returned early are stale: they
are dropped when met. Stage ops charge themselves (once, even with no context left, and not on a
re-entered pass), so a stage that fails the command leaves the later stages uncharged, as in the game.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from emulator.world import semantics

WIDTH = 8

# ---------------------------------------------------------------- opcodes
# Holder operands: >= 0 a holder id; HOLDER_SELF the executor (`@s`): ctx_holder[ctx] is its holder
# id, -1 for the server (the command fails, or a condition stage drops the context: "No entity was
# found"); HOLDER_SELBUF the holders the SELHOLDERS just before found (see entity_arrays)
HOLDER_SELF = -2
HOLDER_SELBUF = -3

OP_HALT = 0  # root finished: return ST_DONE
OP_CMD = 1  # a: abort pc. A chain's entry check; alive = 1, has = 0. Each stage op charges itself
OP_ENDCMD = 2  # alive = 1 (after a chain with conditions)
OP_CONT = 3  # a continuation entry (after `if function`): the entry check
OP_STAGESDONE = 4  # a: the chain's ENDCMD. After a fork, Python keeps this context for the final command
OP_SET = 10  # a: holders, b: objective, c: value
OP_ADD = 11  # a holders, b o, c value
OP_REMOVE = 12  # a holders, b o, c value
OP_RESET = 13  # a holders, b o
OP_RESETALL = 14  # a holders
OP_GET = 15  # a h (a name or @s), b o
OP_TAG = 16  # a: selector, b: tag bit, c: 1 add / 0 remove. `tag SEL add|remove T` (fails when nothing changes)
OP_IFENT = 17  # a: selector, f negated, g final. `if|unless entity SEL`
OP_ENABLE = 18  # a: holders, b: objective. `scoreboard players enable`
OP_SELHOLDERS = 19  # a: selector, b: 0 targets / 1 sources. Free. The holders of the selector's entities
# for the next op's HOLDER_SELBUF operand: targets in selbuf[0:R_NSEL], sources from the buffer's middle
# (R_NSEL2 of them). A separate op keeps calls out of the scoreboard ops (a call costs them ~20 %)
OP_IFSCORE = 20  # a: comparison (CMP_*), b h1, c o1, d h2, e o2, f negated, g final
OP_IFMATCH = 21  # a h, b o, c lo, d hi, f negated, g final
OP_CHKOBJ = 22  # a o, b forked, c: the holder is @s. The `store ... score` stage: fails if o does not
# exist, or (c) without an executor ("No entity was found": the command, or in a forked chain this context)
OP_STORE = 23  # a: 0 result / 1 success, b h (a name or @s), c o
OP_CALL = 30  # a: function id
OP_CALLREG = 31  # call regs[R_CALLFN] (the root stub, macro instances); skip if it is -1
OP_FEND = 32  # end of a function body: return without a result
OP_RETV = 33  # a: value, b: 1 when the return is its own command line (an entry). `return N`.
# In a forked chain every context returns (BuildContexts runs the custom command for each one):
# RETV counts the returns in R_NRET and goes on; the chain's RETPEND then ends the function
OP_RETFAIL = 34  # b: as RETV. `return fail`
OP_RETRES = 35  # end of `return run CMD`: return CMD's result (fail if it had none)
OP_RETNONE = 36  # abort target of `return run`: end the function without a result
OP_RETPEND = 37  # after a forked chain ending in `return N|fail`: return, if some context did
OP_RETIFHAS = 38  # a: pc after the calls. `return run function #tag`: a member that returned skips the
# later members (the discard drops them); the chain's stores and RETRES follow
OP_IFNOFN = 39  # a: target. After OP_MACRO in a tag call: a member that could not be instantiated
# (or no context) skips the rest of the call (the command fails)
OP_TAGBEGIN = 40  # acc_any = 0, acc_sum = 0
OP_TAGACC = 41  # add the last call's result to the accumulator
OP_TAGEND = 42  # the tag's result: the sum, if any member returned
OP_IFFN_BEGIN = 43  # has = 0
OP_IFFN_STEP = 44  # a: pc after the calls. A returned member ends the isolated call
OP_IFFN_END = 45  # a: negated. alive &= (value != 0) != negated; no return counts as value 0. A function
# that returned in several contexts passes the context once per return (ST_REPEAT)
OP_FAIL = 46  # a: error (ERR_*), b: operand, c: charge 1, d: abort the chain. The command fails
OP_RESULT = 47  # a: ok, b: value. The result of `return N|fail` ending a chain, for its stores
OP_JMPDEAD = 48  # a: target. `run return run ...` with no context left: skip it
OP_STOP = 49  # abort the chain without an error (`if function` on an empty tag)
OP_STOREPOS = 50  # a: axis, b: 0 result / 1 success, c: scale (index into floats). Pos[a] = (double)(v * S)
OP_MACRO = 51  # a: macro call index. Python instantiates, sets regs[R_CALLFN]
OP_HOSTSTAGE = 52  # a: host op index, b forked. An execute stage run by Python: sets alive, R_CTX
OP_HOSTSTORE = 53  # a: host op index. `store ... storage|entity|block|bossbar`, after the result
OP_ASSTAGE = 54  # a: selector, b forked, c: kind (world_entities.ENTITY_CONTEXT_STAGES: as, at, positioned
# as, rotated as). One context per entity found: `as` contexts made earlier in the root come from
# as_cache, the others from Python (ST_FORK)
OP_POSSTAGE = 55  # b forked. The `store ... entity @s Pos[i] double S` stage: fails without an executor
OP_HOST = 56  # a: host op index. A final command run by Python (charged here, per context)
OP_TP = 59  # a: selector, b: x (index into floats; y, z follow), c: bits of the relative (`~`) axes.
# `tp SEL X Y Z`: every target to the same position (the execution position plus the relative
# parts), each keeping its rotation; outside the spawnable bounds the command fails
OP_GETPOS = 58  # a: axis, b: scale (index into floats, -1 none). `data get entity @s Pos[a] [S]`: Mth.floor
OP_LOG = 57  # a: host op index, b: selector. `tellraw SEL`: fails when SEL finds no player (TellRawCommand:
# EntityArgument.getPlayers), else its result is the count. The line is queued in logbuf (op, context)
# either way: the host's tellraw decides what is written, when the VM returns (before Python serves
# anything else, so the log keeps its order)
OP_OPER_BASE = 60  # + OPK_*: a h1, b o1, c h2, d o2. One opcode per operation (no inner dispatch)
# OP_RESET..OP_ENABLE and OP_HOST..OP_TP are commands of a line of their own served by one branch of the
# dispatch (one entry rule: skipped without a context, the root cut without quota, then charged)

# operations: opcode OP_OPER_BASE + OPK_*
OPK_ASSIGN, OPK_ADD, OPK_SUB, OPK_MUL, OPK_DIV, OPK_MOD, OPK_MIN, OPK_MAX, OPK_SWAP = range(9)
OPK_BY_SYMBOL = {"=": 0, "+=": 1, "-=": 2, "*=": 3, "/=": 4, "%=": 5, "<": 6, ">": 7, "><": 8}

OP_NAMES = {v: k[3:] for k, v in dict(globals()).items() if k.startswith("OP_") and isinstance(v, int)}
OP_NAMES.update({OP_OPER_BASE + k: f"OPER{symbol}" for symbol, k in OPK_BY_SYMBOL.items()})
# comparisons of OP_IFSCORE
CMP_LT, CMP_LE, CMP_EQ, CMP_GE, CMP_GT = range(5)
CMP_BY_SYMBOL = {"<": 0, "<=": 1, "=": 2, ">=": 3, ">": 4}
# sanitizer op kinds (for the report): OPK_* for operations, then these
SAN_ADD_CMD, SAN_REMOVE_CMD = 100, 101

# ---------------------------------------------------------------- registers, frames, status
R_PC, R_QUOTA, R_DEPTH, R_ALIVE, R_HAS, R_OK, R_VAL = range(7)
R_ACC_ANY, R_ACC_SUM, R_ABORT, R_CALLFN, R_ERR, R_ERRARG, R_NOVF, R_CTX = range(7, 15)
R_SANITIZE, R_ERRPC, R_COUNTING, R_FORKLIMIT, R_LOOP, R_NRET, R_NSEL, R_NLOG, R_EDIRTY = range(15, 24)
R_NFORK, R_NCOLL, R_NSEL2 = range(24, 27)  # rows used in fstack and coll; SELHOLDERS' source count
N_REGS = 27  # R_EDIRTY: 1 once the VM marked an entity dirty (Python writes them back, clears it)

F_RETPC, F_FN, F_ALIVE, F_ACC_ANY, F_ACC_SUM, F_ABORT, F_CTX, F_CALLPC, F_QUOTA, F_LOOP, F_CHEAD = range(11)
F_WIDTH = 11

ST_DONE, ST_HOST, ST_CUT, ST_GROW, ST_ERROR, ST_FLUSH, ST_MACRO, ST_GROWCOLL, ST_REPEAT, ST_FORK = range(10)

# R_LOOP: no fork in this command; forked, first pass; re-entered for a later context (its stages
# were charged on the first pass); a kept context running the final command (a `return run`
# chain there is new: its stages charge)
LOOP_NONE, LOOP_FORKED, LOOP_REENTERED, LOOP_FINAL = range(4)

ERR_DIV_ZERO, ERR_UNKNOWN_OBJECTIVE, ERR_UNKNOWN_FUNCTION, ERR_EMPTY_TAG, ERR_MACRO_ARGS, ERR_FORK_LIMIT = range(1, 7)

OVF_WIDTH = 5  # pc, op kind, a, b, exact

# ---------------------------------------------------------------- entities (emulator.vm.entity_arrays)
# ent[slot]: type id, tag bits, score holder id; slot = Entity.order. dirty[slot]: what the VM changed
ENT_WIDTH = 3
E_TYPE, E_TAGS, E_HOLDER = range(ENT_WIDTH)
DIRTY_TAGS, DIRTY_POS, DIRTY_TP = 1, 2, 4  # DIRTY_TP: Python applies the rest of a teleport
PLAYER_TYPE = 0
# selector rows: kind (@e/@a/@s), required and forbidden tag bits, limit, its tests (first, count);
# a test row: [TEST_SCORE, objective, lo, hi] or [TEST_TYPE, type id, negated, 0]
SEL_WIDTH = 6
S_KIND, S_REQUIRED, S_FORBIDDEN, S_LIMIT, S_TESTS, S_NTESTS = range(SEL_WIDTH)
KIND_E, KIND_A, KIND_S = range(3)
TEST_SCORE, TEST_TYPE = range(2)
POS_LIMIT_XZ, POS_LIMIT_Y = 3.0000512e7, 2.0e7  # Entity.load clamps positions to these


@njit(cache=True, inline="always")
def _wrap(x):
    return ((x + 2147483648) & 0xFFFFFFFF) - 2147483648


@njit(cache=True, inline="always")
def _overflowed(x):
    return x < -2147483648 or x > 2147483647


@njit(cache=True, inline="always")
def _operate(k, a, b):
    """``a OP b`` for OPK_* ``k`` (exact, in int64; the caller wraps). Division by zero is the
    caller's check; for a swap this is the target's new value (the caller writes the source)."""
    if k == OPK_ADD:
        return a + b
    if k == OPK_SUB:
        return a - b
    if k == OPK_MUL:
        return a * b
    if k == OPK_DIV:
        return a // b
    if k == OPK_MOD:
        return a % b
    if k == OPK_MIN:
        return a if a < b else b
    if k == OPK_MAX:
        return a if a > b else b
    return b  # assign, swap


@njit(cache=True, inline="always")
def _set_score(op, values, present, h, o, d):
    """`scoreboard players set|add|remove` of ``d`` on one score (an unset score counts as 0):
    (the old value, the exact new one); the wrapped one is stored."""
    old = np.int64(0)
    if op == OP_SET:
        exact = d
    else:
        old = np.int64(values[h, o]) if present[h, o] else np.int64(0)
        exact = old + d if op == OP_ADD else old - d
    values[h, o] = _wrap(exact)
    present[h, o] = 1
    return old, exact


@njit(cache=True, inline="always")
def _report(ovf, novf, pc, kind, a, b, exact):
    """The sanitizer's row for an operation at ``pc`` whose exact result left int32; the new row count."""
    ovf[novf, 0] = pc
    ovf[novf, 1] = kind
    ovf[novf, 2] = a
    ovf[novf, 3] = b
    ovf[novf, 4] = exact
    return novf + 1


@njit(cache=True)
def _matches(sel, slot, sels, tests, ent, values, present, alive_obj):
    """EntitySelector's predicate for one entity (tags, @a's player test, type and score tests)."""
    tags = ent[slot, E_TAGS]
    if (tags & sels[sel, S_REQUIRED]) != sels[sel, S_REQUIRED] or (tags & sels[sel, S_FORBIDDEN]) != 0:
        return False
    if sels[sel, S_KIND] == KIND_A and ent[slot, E_TYPE] != PLAYER_TYPE:
        return False
    first = sels[sel, S_TESTS]
    for t in range(first, first + sels[sel, S_NTESTS]):
        if tests[t, 0] == TEST_TYPE:
            if (ent[slot, E_TYPE] == tests[t, 1]) == (tests[t, 2] != 0):
                return False
        else:
            o = tests[t, 1]
            h = ent[slot, E_HOLDER]
            if alive_obj[o] == 0 or present[h, o] == 0 or values[h, o] < tests[t, 2] or values[h, o] > tests[t, 3]:
                return False
    return True


@njit(cache=True)
def _select(sel, self_slot, sels, tests, ent, order, values, present, alive_obj, out, off):
    """The slots selector ``sel`` finds (``self_slot``: the executor's, -1 for the server), written to
    ``out[off:]`` in the game's order (unsorted: the store's order, cut at the limit); their count."""
    if sels[sel, S_KIND] == KIND_S:
        if self_slot >= 0 and _matches(sel, self_slot, sels, tests, ent, values, present, alive_obj):
            out[off] = self_slot
            return 1
        return 0
    n = 0
    limit = sels[sel, S_LIMIT]
    for i in range(order.shape[0]):
        slot = order[i]
        if _matches(sel, slot, sels, tests, ent, values, present, alive_obj):
            out[off + n] = slot
            n += 1
            if n >= limit:
                break
    return n


@njit(cache=True)
def fork_contexts(regs, fstack, coll, contexts, n, depth, resume):
    """A stage made ``contexts[:n]`` (n >= 2) at frame ``depth``: run the rest of the chain (from
    ``resume``) for the first now and push the others on the fork stack for the chain's ENDCMD.
    A fork inside a forked chain stacks on top (the game's order: each outer context's inner
    contexts in turn); in a new command, rows an earlier function left at this depth are stale.
    The VM and Python (host stages) both fork through here. False when ``fstack`` is too small
    (nothing changed)."""
    fresh = regs[R_LOOP] == LOOP_NONE
    nf = regs[R_NFORK]
    while nf > 0 and fstack[nf - 1, 0] >= (depth if fresh else depth + 1):
        nf -= 1
    if nf + n - 1 > fstack.shape[0]:
        return False
    if fresh:
        nc = regs[R_NCOLL]
        while nc > 0 and coll[nc - 1, 0] >= depth:
            nc -= 1
        regs[R_NCOLL] = nc
        regs[R_LOOP] = LOOP_FORKED
    for i in range(1, n):  # the next one on top
        row = nf + n - 1 - i
        fstack[row, 0] = depth
        fstack[row, 1] = resume
        fstack[row, 2] = contexts[i]
    regs[R_NFORK] = nf + n - 1
    regs[R_CTX] = contexts[0]
    return True


AS_CACHE_SIZE = 4096  # (context, entity slot) -> the `as` context: a direct-mapped cache, per root


@njit(cache=True, inline="always")
def as_cache_row(ctx, slot):
    return (ctx * 7919 + slot) & (AS_CACHE_SIZE - 1)


_double_to_int = njit(cache=True)(semantics.double_to_int)  # Java's (int) of a double


@njit(cache=True)
def _mth_floor(x):
    """``semantics.mth_floor`` (Mth.floor) on the jitted cast."""
    i = _double_to_int(x)
    return _wrap(i - 1) if x < i else i


@njit(cache=True)
def _in_spawnable_bounds(x, y, z):
    """``world.entities.in_spawnable_bounds``: finite, floor of x/z in [-3e7, 3e7), of y in [-2e7, 2e7)."""
    if not (np.isfinite(x) and np.isfinite(y) and np.isfinite(z)):
        return False
    fx, fy, fz = np.floor(x), np.floor(y), np.floor(z)
    return -3.0e7 <= fx < 3.0e7 and -3.0e7 <= fz < 3.0e7 and -2.0e7 <= fy < 2.0e7


@njit(cache=True, inline="always")
def _clamp_pos(v, limit):
    """``max(-limit, min(v, limit))`` as Python evaluates it (the host's clamp; NaN gives -limit)."""
    t = limit if limit < v else v
    return t if t > -limit else -limit


@njit(cache=True, error_model="numpy")
def run(code, func_start, floats, regs, frames, values, present, locked, alive_obj, trig, counts, totals, active, ovf,
        ctx_holder, ctx_entity, ctx_pos, sels, tests, ent, epos, edirty, eorder, selbuf, logbuf, fstack, coll,
        as_cache):
    """Run from ``regs[R_PC]`` until done or until Python is needed; returns an ``ST_*`` status.

    ``totals[f]`` gets the cost spent inside function ``f`` and its callees, counted for the
    outermost activation only (``active[f]`` counts f's frames on the stack).
    On return ``regs[R_PC]`` is where to resume; for ST_HOST/ST_MACRO it is the asking instruction
    and Python moves it past once it has set ``R_HAS/R_OK/R_VAL`` (or ``R_CALLFN``), for ST_CUT the
    entry that was not run, for ST_GROW the call to retry.
    """
    pc = regs[R_PC]
    quota = regs[R_QUOTA]
    depth = regs[R_DEPTH]
    alive = regs[R_ALIVE]
    has = regs[R_HAS]
    ok = regs[R_OK]
    val = regs[R_VAL]
    acc_any = regs[R_ACC_ANY]
    acc_sum = regs[R_ACC_SUM]
    abort = regs[R_ABORT]
    ctx = regs[R_CTX]
    loop = regs[R_LOOP]
    nret = regs[R_NRET]
    sanitize = regs[R_SANITIZE] != 0
    counting = regs[R_COUNTING] != 0  # off only to measure the counters' cost
    forklimit = regs[R_FORKLIMIT]
    novf = regs[R_NOVF]
    nlog = regs[R_NLOG]
    status = ST_DONE
    err = 0
    errarg = 0
    ipc = pc
    while True:
        ipc = pc
        op = code[pc, 0]
        if op >= OP_OPER_BASE:  # scoreboard players operation, one opcode per operation
            if alive == 0:
                pc += 1
                continue
            if quota <= 0:
                status = ST_CUT
                break
            o = code[pc, 2]
            o2 = code[pc, 4]
            h = code[pc, 1]
            if h == HOLDER_SELF:
                h = ctx_holder[ctx]
            h2 = code[pc, 3]
            if h2 == HOLDER_SELF:
                h2 = ctx_holder[ctx]
            if h >= 0 and h2 >= 0:  # one target, one source (names or @s): the common case, kept lean
                if sanitize and novf >= ovf.shape[0]:
                    status = ST_FLUSH
                    break
                quota -= 1
                if counting:
                    counts[pc] += 1
                has = 1
                ok = 0
                val = 0
                pc += 1
                if alive_obj[o] == 0 or alive_obj[o2] == 0:
                    err = ERR_UNKNOWN_OBJECTIVE
                    errarg = o if alive_obj[o] == 0 else o2
                    status = ST_ERROR
                    break
                if present[h, o] == 0:  # get-or-create: the target first, then the source
                    values[h, o] = 0
                    present[h, o] = 1
                if present[h2, o2] == 0:
                    values[h2, o2] = 0
                    present[h2, o2] = 1
                a = np.int64(values[h, o])
                b = np.int64(values[h2, o2])
                k = op - OP_OPER_BASE
                if b == 0 and (k == OPK_DIV or k == OPK_MOD):
                    err = ERR_DIV_ZERO
                    errarg = 0
                    status = ST_ERROR
                    break
                r = _operate(k, a, b)
                if k == OPK_SWAP:
                    values[h2, o2] = a
                nv = _wrap(r)
                values[h, o] = nv
                ok = 1
                val = nv
                if sanitize and _overflowed(r):
                    novf = _report(ovf, novf, ipc, k, a, b, r)
                    if novf >= ovf.shape[0]:
                        status = ST_FLUSH
                        break
                continue
            if h >= 0:
                selbuf[0] = h
                nt = 1
            else:
                nt = regs[R_NSEL] if h == HOLDER_SELBUF else 0
            half = selbuf.shape[0] >> 1
            if h2 >= 0:
                selbuf[half] = h2
                ns = 1
            else:
                ns = regs[R_NSEL2] if h2 == HOLDER_SELBUF else 0
            if sanitize and novf + nt * ns > ovf.shape[0]:  # room for every report first: runs again after
                status = ST_FLUSH
                break
            quota -= 1
            if counting:
                counts[pc] += 1
            has = 1
            ok = 0
            val = 0
            pc += 1
            # the game's argument order: targets, target objective, sources, source objective
            if nt == 0 or (alive_obj[o] != 0 and ns == 0):
                continue
            if alive_obj[o] == 0 or alive_obj[o2] == 0:
                err = ERR_UNKNOWN_OBJECTIVE
                errarg = o if alive_obj[o] == 0 else o2
                status = ST_ERROR
                break
            k = op - OP_OPER_BASE
            total = np.int64(0)
            failed = False
            for i in range(nt):
                h = selbuf[i]
                if present[h, o] == 0:  # get-or-create: the target first, then each source
                    values[h, o] = 0
                    present[h, o] = 1
                for j in range(half, half + ns):
                    h2 = selbuf[j]
                    if present[h2, o2] == 0:
                        values[h2, o2] = 0
                        present[h2, o2] = 1
                    a = np.int64(values[h, o])
                    b = np.int64(values[h2, o2])
                    if b == 0 and (k == OPK_DIV or k == OPK_MOD):
                        failed = True
                        break
                    r = _operate(k, a, b)
                    if k == OPK_SWAP:
                        values[h2, o2] = a
                    values[h, o] = _wrap(r)
                    if sanitize and _overflowed(r):
                        novf = _report(ovf, novf, ipc, k, a, b, r)
                if failed:
                    break
                total += values[h, o]
            if failed:
                err = ERR_DIV_ZERO
                errarg = 0
                status = ST_ERROR
                break
            ok = 1
            val = _wrap(total)
            if sanitize and novf >= ovf.shape[0]:
                status = ST_FLUSH
                break
        elif op == OP_ADD or op == OP_REMOVE or op == OP_SET:
            if alive == 0:
                pc += 1
                continue
            if quota <= 0:
                status = ST_CUT
                break
            h = code[pc, 1]
            if h == HOLDER_SELF:
                h = ctx_holder[ctx]
            if h >= 0:  # a name, or @s run by an entity
                n = 1
            else:
                n = regs[R_NSEL] if h == HOLDER_SELBUF else 0
            if sanitize and novf + n > ovf.shape[0]:
                status = ST_FLUSH
                break
            quota -= 1
            if counting:
                counts[pc] += 1
            o = code[pc, 2]
            has = 1
            ok = 0
            val = 0
            pc += 1
            if n == 0:  # "No entity was found"
                continue
            if alive_obj[o] == 0:
                err = ERR_UNKNOWN_OBJECTIVE
                errarg = o
                status = ST_ERROR
                break
            d = np.int64(code[ipc, 3])
            kind = SAN_ADD_CMD if op == OP_ADD else SAN_REMOVE_CMD
            if h >= 0:  # one holder: the common case, kept lean
                old, exact = _set_score(op, values, present, h, o, d)
                ok = 1
                val = _wrap(exact)
                if sanitize and _overflowed(exact):
                    novf = _report(ovf, novf, ipc, kind, old, d, exact)
                    if novf >= ovf.shape[0]:
                        status = ST_FLUSH
                        break
                continue
            total = np.int64(0)
            for i in range(n):
                old, exact = _set_score(op, values, present, selbuf[i], o, d)
                total += _wrap(exact)
                if sanitize and _overflowed(exact):
                    novf = _report(ovf, novf, ipc, kind, old, d, exact)
            ok = 1
            val = _wrap(d * n) if op == OP_SET else _wrap(total)
            if sanitize and novf >= ovf.shape[0]:
                status = ST_FLUSH
                break
        elif op == OP_CMD:
            if quota <= 0:
                status = ST_CUT
                break
            alive = 1
            has = 0
            abort = code[pc, 1]
            pc += 1
        elif op == OP_IFSCORE or op == OP_IFMATCH or op == OP_IFENT:  # a condition: a stage, or final
            final = code[pc, 7]
            if not final and loop != LOOP_REENTERED:  # a stage: charged once, contexts or not
                quota -= 1
                if counting:
                    counts[pc] += 1
            if alive == 0:
                pc += 1
                continue
            if final:
                if quota <= 0:
                    status = ST_CUT
                    break
                quota -= 1
                if counting:
                    counts[pc] += 1
            if op == OP_IFENT:  # `if|unless entity SEL`
                n = _select(code[pc, 1], ctx_entity[ctx], sels, tests, ent, eorder, values, present, alive_obj,
                            selbuf, 0)
                passed = (n > 0) != (code[pc, 6] != 0)
                fval = 0 if not passed else (1 if code[pc, 6] else n)  # `if` counts the entities, `unless` gives 1
            else:
                h = code[pc, 1] if op == OP_IFMATCH else code[pc, 2]
                o = code[pc, 2] if op == OP_IFMATCH else code[pc, 3]
                bad = alive_obj[o] == 0
                if op == OP_IFSCORE and alive_obj[code[pc, 5]] == 0:
                    bad = True
                    o = code[pc, 5]
                if bad:
                    err = ERR_UNKNOWN_OBJECTIVE
                    errarg = o
                    has = 1
                    ok = 0
                    val = 0
                    # a condition is a fork: its error drops the context, later stages still run
                    pc += 1
                    alive = 0 if not final else alive
                    status = ST_ERROR
                    break
                if h == HOLDER_SELF:
                    h = ctx_holder[ctx]
                if op == OP_IFSCORE and code[pc, 4] == HOLDER_SELF and ctx_holder[ctx] < 0:
                    h = -1
                if h < 0:  # @s run by the server: a final test fails, a stage (a fork) drops the context
                    if final:
                        has = 1
                        ok = 0
                        val = 0
                    else:
                        alive = 0
                    pc += 1
                    continue
                passed = False
                if present[h, o]:
                    a = values[h, o]
                    if op == OP_IFMATCH:
                        passed = code[pc, 3] <= a <= code[pc, 4]
                    else:
                        h2 = code[pc, 4]
                        if h2 == HOLDER_SELF:
                            h2 = ctx_holder[ctx]
                        o2 = code[pc, 5]
                        if present[h2, o2]:
                            b = values[h2, o2]
                            c = code[pc, 1]
                            if c == CMP_LT:
                                passed = a < b
                            elif c == CMP_LE:
                                passed = a <= b
                            elif c == CMP_EQ:
                                passed = a == b
                            elif c == CMP_GE:
                                passed = a >= b
                            else:
                                passed = a > b
                if code[pc, 6]:
                    passed = not passed
                fval = 1 if passed else 0
            if final:
                has = 1
                ok = 1 if passed else 0
                val = fval
            elif not passed:
                alive = 0
            elif forklimit <= 1:  # BuildContexts: the one context made reaches the fork limit
                err = ERR_FORK_LIMIT
                errarg = forklimit
                alive = 0
                pc = abort
                status = ST_ERROR
                break
            pc += 1
        elif op == OP_ENDCMD:
            if loop:  # a stage forked: the next context through the rest of the chain
                nf = regs[R_NFORK]
                while nf > 0 and fstack[nf - 1, 0] > depth:
                    nf -= 1
                regs[R_NFORK] = nf
                alive = 1
                if nf > 0 and fstack[nf - 1, 0] == depth:
                    regs[R_NFORK] = nf - 1
                    pc = fstack[nf - 1, 1]
                    ctx = fstack[nf - 1, 2]
                    loop = LOOP_REENTERED
                    continue
                nc = regs[R_NCOLL]
                while nc > 0 and coll[nc - 1, 0] > depth:
                    nc -= 1
                head = frames[depth - 1, F_CHEAD]
                if head < nc and coll[head, 0] == depth:  # the next kept context through the final command
                    frames[depth - 1, F_CHEAD] = head + 1
                    regs[R_NCOLL] = nc
                    ctx = coll[head, 1]
                    pc = coll[head, 2]
                    loop = LOOP_FINAL
                    continue
                while nc > 0 and coll[nc - 1, 0] >= depth:  # every context done: the command ends
                    nc -= 1
                regs[R_NCOLL] = nc
                loop = LOOP_NONE
            alive = 1
            ctx = frames[depth - 1, F_CTX]  # the next command runs in the function's own context again
            pc += 1
        elif op == OP_CALL or op == OP_CALLREG:
            fn = code[pc, 1] if op == OP_CALL else regs[R_CALLFN]
            if alive == 0 or fn < 0:
                pc += 1
                continue
            if quota <= 0:
                status = ST_CUT
                break
            if depth >= frames.shape[0]:
                status = ST_GROW
                break
            quota -= 1
            if counting:
                counts[pc] += 1
            frames[depth, F_RETPC] = pc + 1
            frames[depth, F_FN] = fn
            frames[depth, F_ALIVE] = alive
            frames[depth, F_ACC_ANY] = acc_any
            frames[depth, F_ACC_SUM] = acc_sum
            frames[depth, F_ABORT] = abort
            frames[depth, F_CTX] = ctx
            frames[depth, F_CALLPC] = pc
            frames[depth, F_QUOTA] = quota
            frames[depth, F_LOOP] = loop
            active[fn] += 1
            depth += 1
            has = 0
            loop = 0
            pc = func_start[fn]
        elif op >= OP_FEND and op <= OP_RETPEND:
            if op == OP_FEND or op == OP_RETNONE:
                has = 0
            elif op == OP_RETV or op == OP_RETFAIL:
                if alive == 0:
                    pc += 1
                    continue
                if code[pc, 2] and quota <= 0:  # a `return` line is an entry of its own
                    status = ST_CUT
                    break
                has = 1
                ok = 1 if op == OP_RETV else 0
                val = code[pc, 1] if op == OP_RETV else 0
                if loop:  # one context of a forked chain: the others return too
                    nret += 1
                    pc += 1
                    continue
            elif op == OP_RETRES:
                if not (alive and has):  # FallthroughTask, an entry: returns failure
                    if quota <= 0:
                        status = ST_CUT
                        break
                    has = 1
                    ok = 0
                    val = 0
                elif not ok:
                    val = 0
                # else `has` keeps the callee's count of returns: each reaches the caller
            elif nret == 0:  # OP_RETPEND: no context returned
                pc += 1
                continue
            if nret:  # the caller's callback hears every context's return
                has = nret
                nret = 0
            depth -= 1
            fn = frames[depth, F_FN]
            active[fn] -= 1
            if active[fn] == 0:
                totals[fn] += frames[depth, F_QUOTA] - quota
            pc = frames[depth, F_RETPC]
            alive = frames[depth, F_ALIVE]
            acc_any = frames[depth, F_ACC_ANY]
            acc_sum = frames[depth, F_ACC_SUM]
            abort = frames[depth, F_ABORT]
            ctx = frames[depth, F_CTX]
            loop = frames[depth, F_LOOP]
        elif OP_RESET <= op <= OP_ENABLE or OP_HOST <= op <= OP_TP:  # the other commands of a line of their own
            if alive == 0:
                pc += 1
                continue
            if quota <= 0:
                status = ST_CUT
                break
            if op == OP_LOG and nlog >= logbuf.shape[0]:  # runs again once Python wrote the queued lines
                status = ST_FLUSH
                break
            quota -= 1
            if counting:
                counts[pc] += 1
            if op == OP_GET or op == OP_RESET or op == OP_RESETALL or op == OP_ENABLE:
                h = code[pc, 1]
                if h == HOLDER_SELF:
                    h = ctx_holder[ctx]
                if h >= 0:
                    selbuf[0] = h
                    n = 1
                else:
                    n = regs[R_NSEL] if h == HOLDER_SELBUF else 0
                o = code[pc, 2]
                has = 1
                ok = 0
                val = 0
                pc += 1
                if n == 0:  # @s run by the server, a selector finding nothing
                    continue
                if op != OP_RESETALL and alive_obj[o] == 0:
                    err = ERR_UNKNOWN_OBJECTIVE
                    errarg = o
                    status = ST_ERROR
                    break
                if op == OP_GET:
                    h = selbuf[0]
                    if present[h, o]:
                        ok = 1
                        val = values[h, o]
                    continue
                if op == OP_ENABLE:
                    if trig[o] == 0:  # "You can only enable trigger-objectives"
                        continue
                    unlocked = 0
                    for i in range(n):  # get-or-create (0), then unlock: the count of scores unlocked
                        h = selbuf[i]
                        if present[h, o] == 0:
                            values[h, o] = 0
                            present[h, o] = 1
                        if locked[h, o]:
                            locked[h, o] = 0
                            unlocked += 1
                    ok = 1 if unlocked else 0
                    val = unlocked
                    continue
                for i in range(n):  # reset: an unset score is locked again
                    h = selbuf[i]
                    if op == OP_RESETALL:
                        present[h, :] = 0
                        locked[h, :] = 1
                    else:
                        present[h, o] = 0
                        locked[h, o] = 1
                ok = 1
                val = n
            elif op == OP_TAG:
                n = _select(code[pc, 1], ctx_entity[ctx], sels, tests, ent, eorder, values, present, alive_obj, selbuf, 0)
                m = np.int64(1) << code[pc, 2]
                changed = 0
                for i in range(n):
                    e = selbuf[i]
                    had = (ent[e, E_TAGS] & m) != 0
                    if code[pc, 3] != 0 and not had:
                        ent[e, E_TAGS] |= m
                    elif code[pc, 3] == 0 and had:
                        ent[e, E_TAGS] &= ~m
                    else:
                        continue
                    changed += 1
                    edirty[e] |= DIRTY_TAGS
                    regs[R_EDIRTY] = 1
                has = 1
                ok = 1 if changed else 0
                val = changed
                pc += 1
            elif op == OP_HOST:
                status = ST_HOST
                break
            elif op == OP_TP:
                n = _select(code[pc, 1], ctx_entity[ctx], sels, tests, ent, eorder, values, present, alive_obj, selbuf, 0)
                k = code[pc, 2]
                x = floats[k] + ctx_pos[ctx, 0] if code[pc, 3] & 1 else floats[k]  # WorldCoordinate.get: value + base
                y = floats[k + 1] + ctx_pos[ctx, 1] if code[pc, 3] & 2 else floats[k + 1]
                z = floats[k + 2] + ctx_pos[ctx, 2] if code[pc, 3] & 4 else floats[k + 2]
                has = 1
                ok = 0
                val = 0
                pc += 1
                if n == 0 or not _in_spawnable_bounds(x, y, z):  # "No entity was found", "Invalid position"
                    continue
                for i in range(n):
                    e = selbuf[i]
                    epos[e, 0] = x
                    epos[e, 1] = y
                    epos[e, 2] = z
                    edirty[e] |= DIRTY_TP
                regs[R_EDIRTY] = 1
                ok = 1
                val = n
            elif op == OP_GETPOS:
                e = ctx_entity[ctx]
                has = 1
                ok = 0
                val = 0
                if e >= 0:  # else "No entity was found"
                    x = epos[e, code[pc, 1]]
                    if code[pc, 2] >= 0:
                        x = x * floats[code[pc, 2]]
                    ok = 1
                    val = _mth_floor(x)
                pc += 1
            else:  # OP_LOG
                n = _select(code[pc, 2], ctx_entity[ctx], sels, tests, ent, eorder, values, present, alive_obj, selbuf, 0)
                has = 1
                ok = 1 if n else 0
                val = n
                logbuf[nlog, 0] = code[pc, 1]
                logbuf[nlog, 1] = ctx
                nlog += 1
                pc += 1
        elif op == OP_SELHOLDERS:
            if alive:
                off = (selbuf.shape[0] >> 1) if code[pc, 2] else 0
                n = _select(code[pc, 1], ctx_entity[ctx], sels, tests, ent, eorder, values, present, alive_obj,
                            selbuf, off)
                for i in range(off, off + n):
                    selbuf[i] = ent[selbuf[i], E_HOLDER]
                regs[R_NSEL2 if code[pc, 2] else R_NSEL] = n
            pc += 1
        elif op == OP_ASSTAGE:
            if loop != LOOP_REENTERED:
                quota -= 1
                if counting:
                    counts[pc] += 1
            if alive == 0:
                pc += 1
                continue
            n = _select(code[pc, 1], ctx_entity[ctx], sels, tests, ent, eorder, values, present, alive_obj, selbuf, 0)
            pc += 1
            if n == 0:
                alive = 0
            elif n >= forklimit:  # BuildContexts' fork limit
                err = ERR_FORK_LIMIT
                errarg = forklimit
                alive = 0
                pc = abort
                status = ST_ERROR
                break
            else:
                cached = code[pc - 1, 3] == 0 and regs[R_NFORK] + n <= fstack.shape[0]
                for i in range(n if cached else 0):  # `as`: contexts made before for these entities?
                    row = as_cache_row(ctx, selbuf[i])
                    if as_cache[row, 0] != ctx or as_cache[row, 1] != selbuf[i]:
                        cached = False
                        break
                if not cached:  # Python makes the contexts of selbuf[:n] (and forks if several)
                    regs[R_NSEL] = n
                    status = ST_FORK
                    break
                for i in range(n):
                    selbuf[i] = as_cache[as_cache_row(ctx, selbuf[i]), 2]
                if n == 1:
                    ctx = selbuf[0]
                    continue
                regs[R_LOOP] = loop
                fork_contexts(regs, fstack, coll, selbuf, n, depth, pc)  # room checked above
                loop = regs[R_LOOP]
                ctx = regs[R_CTX]
        elif op == OP_POSSTAGE:
            if loop != LOOP_REENTERED:
                quota -= 1
                if counting:
                    counts[pc] += 1
            if alive and ctx_entity[ctx] < 0:  # "No entity was found": the command, or this context, fails
                alive = 0
                pc = pc + 1 if code[pc, 2] else abort
                continue
            if alive and forklimit <= 1:
                err = ERR_FORK_LIMIT
                errarg = forklimit
                alive = 0
                pc = abort
                status = ST_ERROR
                break
            pc += 1
        elif op == OP_STOREPOS:
            e = ctx_entity[ctx]
            if alive and has and e >= 0 and ent[e, E_TYPE] != PLAYER_TYPE:  # a player's data cannot be modified
                stored = (val if ok else 0) if code[pc, 2] == 0 else ok
                axis = code[pc, 1]
                epos[e, axis] = _clamp_pos(np.float64(stored) * floats[code[pc, 3]],
                                           POS_LIMIT_Y if axis == 1 else POS_LIMIT_XZ)
                edirty[e] |= DIRTY_POS
                regs[R_EDIRTY] = 1
            pc += 1
        elif op == OP_STORE:
            if alive and has:
                h = code[pc, 2]
                if h == HOLDER_SELF:  # the chain's stage checked there is an executor
                    h = ctx_holder[ctx]
                o = code[pc, 3]
                v = (val if ok else 0) if code[pc, 1] == 0 else ok
                values[h, o] = v
                present[h, o] = 1
            pc += 1
        elif op == OP_CHKOBJ:  # the `store ... score` stage
            if loop != LOOP_REENTERED:
                quota -= 1
                if counting:
                    counts[pc] += 1
            if alive and (alive_obj[code[pc, 1]] == 0 or forklimit <= 1):
                err = ERR_UNKNOWN_OBJECTIVE if alive_obj[code[pc, 1]] == 0 else ERR_FORK_LIMIT
                errarg = code[pc, 1] if err == ERR_UNKNOWN_OBJECTIVE else forklimit
                alive = 0
                pc = pc + 1 if code[pc, 2] else abort  # in a forked chain only this context fails
                status = ST_ERROR
                break
            if alive and code[pc, 3] and ctx_holder[ctx] < 0:
                alive = 0
                pc = pc + 1 if code[pc, 2] else abort
                continue
            pc += 1
        elif op == OP_STAGESDONE:
            if loop and alive:  # forked: every context goes through the stages before any runs
                nc = regs[R_NCOLL]
                while nc > 0 and coll[nc - 1, 0] > depth:  # stale rows of a function that returned early
                    nc -= 1
                regs[R_NCOLL] = nc
                if nc >= coll.shape[0]:
                    status = ST_GROWCOLL
                    break
                if nc == 0 or coll[nc - 1, 0] != depth:  # the command's first kept context
                    frames[depth - 1, F_CHEAD] = nc
                coll[nc, 0] = depth
                coll[nc, 1] = ctx
                coll[nc, 2] = pc + 1
                regs[R_NCOLL] = nc + 1
                pc = code[pc, 1]  # the chain's ENDCMD: the next context
                continue
            pc += 1
        elif op == OP_TAGBEGIN:
            acc_any = 0
            acc_sum = 0
            pc += 1
        elif op == OP_TAGACC:
            if alive and has:
                acc_any = 1
                acc_sum = _wrap(acc_sum + (val if ok else 0) * has)  # has: the member's count of returns
            pc += 1
        elif op == OP_TAGEND:  # the accumulator's report is an entry queued after the members
            if alive and quota <= 0:
                status = ST_CUT
                break
            if alive:
                has = acc_any
                ok = 1
                val = acc_sum
            pc += 1
        elif op == OP_IFFN_BEGIN:
            has = 0
            pc += 1
        elif op == OP_IFNOFN:
            pc = code[pc, 1] if regs[R_CALLFN] < 0 else pc + 1
        elif op == OP_IFFN_STEP or op == OP_RETIFHAS:
            pc = code[pc, 1] if has else pc + 1
        elif op == OP_IFFN_END:
            if alive:
                # no member returned: the isolated call's FallthroughTask reports (false, 0)
                v = val if (has and ok) else 0
                passed = (v == 0) if code[pc, 1] else (v != 0)
                alive = 1 if passed else 0
                if passed and has > 1:  # each return passed the context on: Python forks it (R_HAS copies)
                    pc += 1
                    status = ST_REPEAT
                    break
            has = 0
            pc += 1
        elif op == OP_CONT:
            if quota <= 0:
                status = ST_CUT
                break
            pc += 1
        elif op == OP_FAIL:
            if alive == 0 and code[pc, 4] == 0:  # an aborting failure happens even with no context
                pc += 1
                continue
            if quota <= 0:
                status = ST_CUT
                break
            if code[pc, 3]:
                quota -= 1
                if counting:
                    counts[pc] += 1
            has = 1
            ok = 0
            val = 0
            err = code[pc, 1]
            errarg = code[pc, 2]
            if code[pc, 4]:
                alive = 0
                pc = abort
            else:
                pc += 1
            status = ST_ERROR
            break
        elif op == OP_RESULT:
            if alive:
                has = 1
                ok = code[pc, 1]
                val = code[pc, 2]
            pc += 1
        elif op == OP_JMPDEAD:
            pc = pc + 1 if alive else code[pc, 1]
        elif op == OP_STOP:  # even with no context left: nothing of the chain follows
            alive = 0
            pc = abort
        elif op == OP_HOSTSTAGE:
            if loop != LOOP_REENTERED:
                quota -= 1
                if counting:
                    counts[pc] += 1
            if alive == 0:
                pc += 1
                continue
            status = ST_HOST
            break
        elif op == OP_HOSTSTORE:
            if alive == 0 or has == 0:
                pc += 1
                continue
            status = ST_HOST
            break
        elif op == OP_MACRO:
            if alive == 0:
                regs[R_CALLFN] = -1
                pc += 1
                continue
            status = ST_MACRO
            break
        else:  # OP_HALT
            status = ST_DONE
            break
    regs[R_PC] = pc
    regs[R_QUOTA] = quota
    regs[R_DEPTH] = depth
    regs[R_ALIVE] = alive
    regs[R_HAS] = has
    regs[R_OK] = ok
    regs[R_VAL] = val
    regs[R_ACC_ANY] = acc_any
    regs[R_ACC_SUM] = acc_sum
    regs[R_ABORT] = abort
    regs[R_CTX] = ctx
    regs[R_LOOP] = loop
    regs[R_NRET] = nret
    regs[R_NOVF] = novf
    regs[R_NLOG] = nlog
    if status == ST_ERROR:
        regs[R_ERR] = err
        regs[R_ERRARG] = errarg
        regs[R_ERRPC] = ipc
    return status


def new_registers() -> np.ndarray:
    return np.zeros(N_REGS, dtype=np.int64)


def new_frames(depth: int) -> np.ndarray:
    return np.zeros((depth, F_WIDTH), dtype=np.int64)


def new_fork_stack(size: int = 64) -> np.ndarray:
    return np.zeros((size, 3), dtype=np.int64)


def new_overflow_buffer(size: int = 1024) -> np.ndarray:
    return np.zeros((size, OVF_WIDTH), dtype=np.int64)
