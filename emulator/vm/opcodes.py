"""The VM's opcode table: one row per opcode, the one place its number, name, operands, cost and
family are written.

Opcodes are numbered in table order. Read by :mod:`emulator.vm.generate`, which writes the ``OP_*``
constants and the family ranges into :mod:`emulator.vm.loop` (numba's on-disk cache does not notice
a constant changed in another module, so the jitted loop reads them as literals of its own module)
and the dispatch tests from the families; the compiler emits those constants (an operation's by
:data:`OPERATION_KINDS`); ``dpemu disasm`` and ``dpemu profile`` print ``name``, and the
disassembler decodes the operands by ``operands``.

- ``name``: what the disassembler and the profiler print.
- ``operands``: the kind of each slot a..g in order: h holder, o objective, i int, p pc, f function,
  c comparison, n name, l dimension, x host op, m macro call, b flag, s selector, d float, _ unused.
- ``cost``: how the instruction charges the quota (the rule in :mod:`emulator.runtime.backend`):
  ``entry`` a command run per context: skipped without one, cut without quota, then charged 1;
  ``stage`` an execute stage: charged once per chain, contexts or not (not again when a fork
  re-enters the chain); ``condition`` a stage, or an entry when it ends the chain; ``check`` an
  entry that costs nothing (cut without quota, never charged); ``operand`` charged when an operand
  says so; ``free`` neither checks nor charges.
- ``family``: the dispatch branch that serves it. A family of several opcodes is served by one
  branch testing its range of numbers, so its opcodes are numbered consecutively and nothing else
  lies in that range.
"""
from __future__ import annotations

from dataclasses import dataclass

ENTRY, STAGE, CONDITION, CHECK, OPERAND, FREE = "entry", "stage", "condition", "check", "operand", "free"
CHARGED = (ENTRY, STAGE, CONDITION, OPERAND)  # the costs that may charge the quota

# `scoreboard players operation`: one opcode each, numbered by kind (OPK_*) from the family's first
OPERATIONS = (("ASSIGN", "="), ("ADD", "+="), ("SUB", "-="), ("MUL", "*="), ("DIV", "/="), ("MOD", "%="),
              ("MIN", "<"), ("MAX", ">"), ("SWAP", "><"))


@dataclass(frozen=True)
class Opcode:
    code: int
    name: str
    operands: str
    cost: str
    family: str
    doc: str

    @property
    def constant(self) -> str:
        """Its constant in :mod:`emulator.vm.loop` (the operations have none: FIRST_OPERATION + OPK_*)."""
        return "OP_" + self.name


def _family(name: str, rows) -> list[tuple]:
    return [(name, *row) for row in rows]


def _single(*row) -> list[tuple]:
    return _family(row[0].lower(), [row])


# (family, name, operands, cost, doc)
_ROWS = [
    *_single("HALT", "", FREE, "root finished: return ST_DONE"),
    *_single("CMD", "p", CHECK, "a: abort pc. A chain's entry check; alive = 1, has = 0. Each stage op charges itself"),
    *_single("ENDCMD", "", FREE, "alive = 1 (after a chain with conditions)"),
    *_single("CONT", "", CHECK, "a continuation entry (after `if function`): the entry check"),
    *_single("STAGESDONE", "pb", FREE, "a: the chain's ENDCMD, b: before an `if function`. After a fork, this context "
                                       "is kept until every context has passed the stages before: for the final "
                                       "command, or for the `if function` (its calls run for each context in turn, "
                                       "as ExecuteCommand.scheduleFunctionConditionsAndTest queues them)"),
    *_family("score", [
        ("SET", "hoi", ENTRY, "a: holders, b: objective, c: value"),
        ("ADD", "hoi", ENTRY, "a holders, b o, c value"),
        ("REMOVE", "hoi", ENTRY, "a holders, b o, c value"),
    ]),
    # the cold commands of a line of their own, served by one branch of the dispatch (one entry
    # rule: skipped without a context, the root cut without quota, then charged)
    *_family("line", [
        ("RESET", "ho", ENTRY, "a holders, b o"),
        ("RESETALL", "h", ENTRY, "a holders"),
        ("GET", "ho", ENTRY, "a h (a name or @s), b o"),
        ("ENABLE", "ho", ENTRY, "a: holders, b: objective. `scoreboard players enable`"),
        ("TAG", "sib", ENTRY, "a: selector, b: tag number (bit b & 63 of word b >> 6), c: 1 add / 0 remove. `tag "
                              "SEL add|remove T` (fails when nothing changes; an entity holds at most MAX_TAGS)"),
        ("LOG", "xs", ENTRY, "a: host op index, b: selector. `tellraw SEL`: fails when SEL finds no player "
                             "(TellRawCommand: EntityArgument.getPlayers), else its result is the count. The line is "
                             "queued in logbuf (op, context) either way: the host's tellraw decides what is written, "
                             "when the VM returns (before Python serves anything else, so the log keeps its order)"),
        ("GETFIELD", "idx", ENTRY, "a: column of the entity floats (entity_table EF_*), b: scale (index into floats), c: "
                                  "host op index. `data get entity @s PATH [S]` on a numeric field the table keeps "
                                  "(Pos, Motion, Rotation, a display's transformation): Mth.floor(value * S); an "
                                  "entity without that field (transformation on another type) goes to the host"),
        ("SETLEAF", "iidx", ENTRY, "a: storage leaf (vm.storage_leaves), b: its number's type (LEAF_*), c: the "
                                   "number (index into floats), d: host op index. `data modify storage S P set value "
                                   "N`: fails when the same number is there (\"Nothing changed\"); no number there "
                                   "goes to the host (which creates the path), and so does a list's element of "
                                   "another type"),
        ("COPYLEAF", "iix", ENTRY, "a: storage leaf, b: the source's leaf, c: host op index. `data modify storage S P "
                                   "set from storage S2 P2`: the source's number with its type (a copy), failing when "
                                   "the same is there; no number at either, or a list's element given another type, "
                                   "goes to the host"),
        ("GETLEAF", "idx", ENTRY, "a: storage leaf, b: scale (index into floats), c: host op index. `data get "
                                  "storage S P [SCALE]`: Mth.floor(number * SCALE); no number there goes to the host"),
        ("TP", "sdiii", ENTRY, "a: selector, b: x (index into floats; y, z and the rotation's yaw, pitch follow), c: "
                               "flags (the relative `~` axes' bits, TP_LOCAL, TP_SELF, TP_ROT and its relative angles "
                               "TP_REL_YAW, TP_REL_PITCH), d: kind (TPF_*), e: its operand. `tp [SEL] X Y Z [YAW "
                               "PITCH | facing X Y Z | facing entity E [ANCHOR]]` and `tp [SEL] E`: every target to "
                               "the same position (the execution position plus the relative parts, ^ from its anchor, "
                               "or E's), each keeping its rotation (TP_SELF: the execution rotation; TP_ROT: the given "
                               "one, `~` from the execution rotation; E's; wrapped, the pitch clamped) or looking "
                               "from its anchor at the position or entity faced, and losing its vertical motion; "
                               "outside the spawnable bounds, or E not exactly one entity, the command fails. Always "
                               "followed by the command's HOST, which runs it instead when a target goes to another "
                               "level (the context's or E's: the host moves it in the order); TP skips it otherwise"),
    ]),
    *_single("HOST", "x", ENTRY, "a: host op index. A final command run by Python (charged here, per context)"),
    *_single("OBJECTIVE", "obx", ENTRY, "a: objective, b: 1 add / 0 remove, c: host op index. `scoreboard objectives "
                                        "add O ...`: fails when O exists (ScoreboardCommand.addObjective: "
                                        "ERROR_OBJECTIVE_ALREADY_EXISTS, not reported); a new one goes to the host (it "
                                        "keeps the criterion and display name). `scoreboard objectives remove O`: O must "
                                        "exist (reported); its scores go (a holder left with none is kept for `*`: "
                                        "Scoreboard.removeObjective keeps it in the map); the result is the count of "
                                        "objectives left. A family of its own: the small loops serve it (a load "
                                        "function adds its objectives)"),
    *_single("SELHOLDERS", "sbii", FREE, "a: selector, b: 0 targets / 1 sources, c, d: the sources' operation's "
                                         "target holder and objective. The holders of the selector's "
                                         "entities for the next op's HOLDER_SELBUF operand: targets in selbuf[0:R_NSEL], "
                                         "sources from the buffer's middle (R_NSEL2 of them; none read when the "
                                         "operation fails on its targets first). A separate op keeps calls "
                                         "out of the scoreboard ops (a call costs them ~20 %)"),
    *_family("condition", [
        ("IFSCORE", "choho" + "bb", CONDITION, "a: comparison (CMP_*), b h1, c o1, d h2, e o2, f negated, g final"),
        ("IFMATCH", "hoii_bb", CONDITION, "a h, b o, c lo, d hi, f negated, g final"),
        ("IFENT", "s____bb", CONDITION, "a: selector, f negated, g final. `if|unless entity SEL`"),
        ("IFLEAF", "iid__bb", CONDITION, "a: storage leaf, b: type (LEAF_*), c: number (index into floats), f "
                                         "negated, g final. `if|unless data storage S {K:N}`: the leaf holds N; "
                                         "b = 0: `if|unless data storage S a.b.c`: the path leads to a tag"),
        ("IFDIM", "l____bb", CONDITION, "a: dimension (Program.dimensions), f negated, g final. `if|unless "
                                        "dimension D`: the context's dimension (ctx_dim) is D"),
    ]),
    *_single("CHKOBJ", "obi", STAGE, "a o, b forked, c: the holder is 1 @s, 2 `*`. The `store ... score` stage: "
                                     "fails if o does not exist, or (c = 1) without an executor (\"No entity was "
                                     "found\": the command, or in a forked chain this context), or (c = 2, first) "
                                     "when `*` names nobody"),
    *_single("STORE", "bho", FREE, "a: 0 result / 1 success, b h (a name, @s or HOLDER_TRACKED: every holder `*` "
                                   "names), c o"),
    *_family("call", [
        ("CALL", "f", ENTRY, "a: function id"),
        ("CALLREG", "", ENTRY, "call regs[R_CALLFN] (the root stub, macro instances); skip if it is -1"),
    ]),
    *_family("return", [
        ("FEND", "", FREE, "end of a function body: return without a result"),
        ("RETV", "ib", CHECK, "a: value, b: 1 when the return is its own command line (an entry). `return N`. In a "
                              "forked chain every context returns (BuildContexts runs the custom command for each "
                              "one): RETV counts the returns in R_NRET and goes on; the chain's RETPEND then ends "
                              "the function"),
        ("RETFAIL", "_b", CHECK, "b: as RETV. `return fail`"),
        ("RETRES", "", CHECK, "end of `return run CMD`: return CMD's result (fail if it had none)"),
        ("RETNONE", "", FREE, "abort target of `return run`: end the function without a result"),
        ("RETPEND", "", FREE, "after a forked chain ending in `return N|fail`: return, if some context did"),
    ]),
    *_family("returned", [
        ("RETIFHAS", "p", FREE, "a: pc after the calls. `return run function #tag`: a member that returned skips "
                                "the later members (the discard drops them); the chain's stores and RETRES follow"),
        ("IFFN_STEP", "p", FREE, "a: pc after the calls. A returned member ends the isolated call"),
    ]),
    *_single("IFNOFN", "p", FREE, "a: target. After OP_MACRO in a tag call: a member that could not be "
                                  "instantiated (or no context) skips the rest of the call (the command fails)"),
    *_single("TAGBEGIN", "", FREE, "acc_any = 0, acc_sum = 0"),
    *_single("TAGACC", "", FREE, "add the last call's result to the accumulator"),
    *_single("TAGEND", "", CHECK, "the tag's result: the sum, if any member returned"),
    *_single("IFFN_BEGIN", "", FREE, "has = 0"),
    *_single("IFFN_END", "b", FREE, "a: negated. alive &= (value != 0) != negated; no return counts as value 0. A "
                                    "function that returned in several contexts passes the context once per return "
                                    "(ST_REPEAT)"),
    *_single("FAIL", "inbb", OPERAND, "a: error (ERR_*), b: operand, c: charge 1, d: abort the chain. The command "
                                      "fails"),
    *_single("RESULT", "bi", FREE, "a: ok, b: value. The result of `return N|fail` ending a chain, for its stores"),
    *_single("JMPDEAD", "p", FREE, "a: target. `run return run ...` with no context left: skip it"),
    *_single("STOP", "", FREE, "abort the chain without an error (`if function` on an empty tag)"),
    *_single("STOREFIELD", "ibdx", FREE, "a: column (EF_*), b: 0 result / 1 success, c: scale (index into floats), "
                                         "d: host op index. `store ... entity @s PATH TYPE S` into a field the table "
                                         "keeps, as Entity.load reads it back (Pos clamped, Motion over 10 dropped, "
                                         "Rotation % 360, a display's transformation as float); another type's "
                                         "transformation goes to the host; a player's data is not modified"),
    *_single("MACRO", "m", FREE, "a: macro call index. Python instantiates, sets regs[R_CALLFN]"),
    *_single("HOSTSTAGE", "xb", STAGE, "a: host op index, b forked. An execute stage run by Python: sets alive, "
                                       "R_CTX"),
    *_single("HOSTGUARD", "sb", STAGE, "a: selector, b: negated. Before the HOSTSTAGE of `as|at|positioned as|"
                                       "rotated as|facing entity|if|unless entity SEL` whose SEL the host evaluates: "
                                       "a selector finding every entity the host would test its own arguments on "
                                       "(SelectorTables.guard); when it finds none, the stage makes no context "
                                       "(`unless`: keeps this one), charged here, and the HOSTSTAGE is skipped"),
    *_single("HOSTSTORE", "x", FREE, "a: host op index. `store ... storage|entity|block|bossbar`, after the result"),
    *_single("ASSTAGE", "sbb", STAGE, "a: selector (REL_VEHICLE, REL_PASSENGERS: `on vehicle|passengers`), b forked, c: kind (commands.entities.ENTITY_CONTEXT_STAGES: "
                                      "as, at, positioned as, rotated as; then FACING_FEET, FACING_EYES: `facing "
                                      "entity SEL feet|eyes`). One context per entity found, made by "
                                      "the VM (or one it made earlier in the root that still holds: as_cache); "
                                      "ST_GROWCTX when the context table or the fork stack is full"),
    *_single("CTXSTAGE", "iid", STAGE, "a: kind (CTX_POSITIONED, CTX_ROTATED, CTX_ANCHORED, CTX_ALIGN, CTX_FACING), b: its "
                                       "operand (flags as OP_TP's: relative axes, TP_LOCAL; the relative angles' bits; "
                                       "ANCHOR_*; the axes' bits), c: x or the yaw (index into floats; the rest "
                                       "follow). `positioned X Y Z` (anchored at the feet), `rotated YAW PITCH`, "
                                       "`anchored eyes|feet`, `align AXES`, `facing X Y Z` (from the anchor): the context changed so (made by the VM, or "
                                       "one it made before from the same context and pc)"),
    *_single("FIELDSTAGE", "bb", STAGE, "a: an executor is needed, b forked. The stage of a STOREFIELD (`store ... "
                                        "entity @s PATH TYPE S`: fails without an executor) or a STORELEAF"),
    *_single("STORELEAF", "ibdix", FREE, "a: storage leaf, b: 0 result / 1 success, c: scale (index into floats), "
                                         "d: type (LEAF_*), e: host op index. `store ... storage S P TYPE SCALE`: "
                                         "(TYPE)(result * SCALE); no number there, or a list's element of another type, goes "
                                         "to the host"),
    *_family("operation", [(f"OPER{symbol}", "hoho", ENTRY, f"a h1, b o1, c h2, d o2. `{symbol}`")
                           for _, symbol in OPERATIONS]),
    *_single("IFRUN", "hoiipb", STAGE, "a h (a name or @s), b o, c lo, d hi, e: the pc after CMD, f negated. "
                                       "`execute if|unless score H O matches LO..HI run CMD` where CMD is one "
                                       "instruction (a score command on names, a function call) and the chain has no "
                                       "other stage: CMD's entry check and the condition stage in one (charged as the "
                                       "stage), then CMD, or the pc after it; no ENDCMD follows"),
    *_single("RESUME", "", FREE, "an advancement reward's call came back (Program.REWARD_PC): return ST_RESUME, "
                                 "Python restores the registers the command that earned it left"),
]
TABLE = tuple(Opcode(code, name, operands, cost, family, doc)
              for code, (family, name, operands, cost, doc) in enumerate(_ROWS))
BY_CODE = {op.code: op for op in TABLE}
OPERATION_KINDS = {symbol: k for k, (_, symbol) in enumerate(OPERATIONS)}


def families() -> dict[str, tuple[int, int]]:
    """Each family's range of numbers (first, last), in numbering order."""
    ranges: dict[str, tuple[int, int]] = {}
    for op in TABLE:
        first, _ = ranges.get(op.family, (op.code, op.code))
        ranges[op.family] = (first, op.code)
    return ranges
