#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Estimated Cortex-M3/M4 cycles of the exact instruction traces QEMU gives.

tools/qemu_count.py counts the instructions between two edges of the timing
pin exactly; QEMU has no timing model, so it cannot say how many *cycles*
they take. This tool replays the same instructions, in execution order
(qemu-system-arm -d exec,nochain,in_asm -singlestep: one "Trace" line per
executed instruction, the disassembly of each translated one), through a
per-instruction cost model of the Cortex-M3/M4 pipeline, and prints the
estimated cycles of each pulse beside its instruction count.

Sources (ARM Technical Reference Manuals; the same figures are reproduced in
the silicon vendors' manuals, e.g. TI SWCU185 for the M3 and SWCU192 for the
M4F):
  - Cortex-M3 TRM (DDI 0337, r2p0/r2p1), section 3.3.1 "Cortex-M3
    instructions", Table 3-1 "Cortex-M3 instruction set summary", and
    section 3.3.2 "Load/store timings".
  - Cortex-M4 TRM (DDI 0439), section 3.3.1 "Cortex-M4 instructions", Table
    3-1 "Cortex-M4 instruction set summary", section 3.3.2 "Load/store
    timings" (the same rules as the M3), and section 7.2.3 "FPU instruction
    set", Table 7-1 (FPU instruction cycle counts).

The model (zero wait states; P = pipeline refill, 1..3 in the TRMs, taken
as --refill, default 2; N = registers transferred):
  data processing, MOV/MOVW/MOVT, shifts, compare, extend, bit field,
  CLZ/RBIT/REV, saturate, IT, NOP, DMB/DSB ........................ 1
  ... with the PC as destination (MOV PC / ADD PC) ................. 1+P
  MUL ............................................................. 1
  MLA, MLS ........................................... M3: 2,  M4: 1
  UMULL/SMULL (M3: 3..5, early termination) ......... M3: 5,  M4: 1
  UMLAL/SMLAL (M3: 4..7, early termination) ......... M3: 7,  M4: 1
  M4 DSP multiplies (SMLA*, SMUL*, SMUAD, ...) ............... M4: 1
  SDIV/UDIV: 2..12 by the operands (early termination); the operands are
    not in the trace, so the documented WORST, 12 (--div-cycles)
  LDR/LDRB/LDRH/LDRSB/LDRSH/LDREX ................................ 2
    pipelined (3.3.2): after a load single whose destination does not
    form this address, 1 (so N consecutive loads take N+1)
  STR/STRB/STRH, immediate or no offset ("always one cycle", 3.3.2) 1
  STR with a register offset ...... 2; 1 right after a load single (3.3.2)
  LDRD/STRD (1+N, not pipelined with their neighbours) ........... 3
  LDM/POP, STM/PUSH ............................................... 1+N
  ... LDM/POP with the PC in the list, LDR into the PC ..... 1+N+P, 2+P
  address interlock (3.3.2: "any load or store that generates an address
    dependent on the result of a preceding data processing operation
    stalls the pipeline for an additional cycle"): +1 when the base or
    index register was written by the instruction just before
  B, BL, BX, BLX .................................................. 1+P
  B<cond>, CBZ/CBNZ: taken 1+P, not taken 1 (taken = the next executed
    instruction is not the one that follows in memory)
  TBB/TBH ......................................................... 2+P
  ISB 1+P;  MRS/MSR/CPS "1 or 2": 2;  WFI/WFE 1 (+ the wait, unknown)
  FPU (M4F only, Table 7-1): VADD/VSUB/VMUL/VNMUL/VABS/VNEG/VCMP(E)/VCVT,
    VMOV (one register), VMRS/VMSR ................................. 1
  VMOV with two core registers .................................... 2
  VFMA/VFMS/VFNMA/VFNMS, VMLA/VMLS/VNMLA/VNMLS ................... 3
  VDIV, VSQRT ..................................................... 14
  VLDR/VSTR: single 2, double 3 (not pipelined: the integer pairing rule
    is not stated for them; conservative)
  VLDM/VSTM/VPUSH/VPOP ............. 1+N, N counted in 32-bit words
  SVC/BKPT/UDF: exception entry, not modelled (1, and reported)
Conditional instructions in an IT block: a branch or a PC load is resolved
from the trace (taken or not); any other is costed as executed (its
condition is not in the trace), an upper bound; the "min" column assumes
all of them failed (1 cycle each).

What it does NOT model (see docs/timing.md): wait states of flash or RAM,
caches (none on M3/M4), bus contention (the DMA, the fetch unit against
literal loads "LDR Rx,[PC,#imm] might add a cycle"), the variation of P
(1..3) with alignment and speculation, IT folding (0 cycles after a 16-bit
instruction on some revisions), the early termination of divides and long
multiplies, FPU register hazards (a result used before its latency),
interrupts and exceptions. The M7 (dual issue, branch prediction, caches)
is out of scope: images for mps2-an500 are refused.

Output: one line per pulse, "index raw cycles net net_cycles min label...",
where raw/net are qemu_count's instruction counts and net_cycles = cycles -
cal_cycles + (1 + P): the calibration pulse's callee is one BX LR, costed
1+P, so net_cycles are the cycles of the measured function from its first
instruction to its return (approximately: pipelining across the call
boundaries is counted in the wrapper).

Usage:
  cycle_model.py ELF [--core m3|m4] [--refill P] [--div-cycles N]
                 [--csv f.csv] [--explain i,j] [--summary] [--machine M]
  cycle_model.py --self-test
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import qemu_count  # noqa: E402

CONDS = frozenset("eq ne cs hs cc lo mi pl vs vc hi ls ge lt gt le al".split())
REG_ALIASES = {"sb": "r9", "sl": "r10", "fp": "r11", "ip": "r12", "sp": "r13",
               "lr": "r14", "pc": "r15"}
CORE_REG_RE = re.compile(r"^(r1[0-5]|r[0-9]|sb|sl|fp|ip|sp|lr|pc)$")

# Mnemonic (without condition, S suffix, .w/.n or data type) -> kind.
_KINDS = {}
for _m in ("mov mvn movw movt add adc adr sub sbc rsb rsc neg cmp cmn and eor orr orn bic "
           "tst teq lsl lsr asr ror rrx ssat usat ssat16 usat16 sxtb sxth uxtb uxth sxtab "
           "sxtah uxtab uxtah sxtb16 uxtb16 sxtab16 uxtab16 ubfx sbfx bfi bfc clz rbit rev "
           "rev16 revsh addw subw sel qadd qsub qdadd qdsub qadd8 qadd16 qsub8 qsub16 qasx "
           "qsax sadd8 sadd16 ssub8 ssub16 sasx ssax uadd8 uadd16 usub8 usub16 uasx usax "
           "shadd8 shadd16 shsub8 shsub16 shasx shsax uhadd8 uhadd16 uhsub8 uhsub16 uhasx "
           "uhsax uqadd8 uqadd16 uqsub8 uqsub16 uqasx uqsax pkhbt pkhtb usad8 usada8").split():
    _KINDS[_m] = "alu"
_KINDS["mul"] = "mul"
for _m in ("mla", "mls"):
    _KINDS[_m] = "mla"
for _m in ("umull", "smull"):
    _KINDS[_m] = "mull"
for _m in ("umlal", "smlal"):
    _KINDS[_m] = "mlal"
for _m in ("smulbb smulbt smultb smultt smulwb smulwt smlabb smlabt smlatb smlatt smlawb "
           "smlawt smlad smladx smlsd smlsdx smlald smlaldx smlsld smlsldx smlalbb smlalbt "
           "smlaltb smlaltt smmul smmulr smmla smmlar smmls smmlsr smuad smuadx smusd smusdx "
           "umaal").split():
    _KINDS[_m] = "dsp_mul"
for _m in ("sdiv", "udiv"):
    _KINDS[_m] = "div"
for _m in "ldr ldrb ldrh ldrsb ldrsh ldrt ldrbt ldrht ldrsbt ldrsht ldrex ldrexb ldrexh".split():
    _KINDS[_m] = "ld"
for _m in "str strb strh strt strbt strht".split():
    _KINDS[_m] = "st"
for _m in "strex strexb strexh".split():
    _KINDS[_m] = "strex"
_KINDS["ldrd"] = "ldrd"
_KINDS["strd"] = "strd"
for _m in "ldm ldmia ldmfd ldmdb ldmea pop".split():
    _KINDS[_m] = "ldm"
for _m in "stm stmia stmea stmdb stmfd push".split():
    _KINDS[_m] = "stm"
_KINDS.update({"b": "b", "bl": "bl", "blx": "bl", "bx": "bl", "cbz": "cb", "cbnz": "cb",
               "tbb": "tb", "tbh": "tb"})
for _m in "nop yield sev dmb dsb clrex pld pli pldw".split():
    _KINDS[_m] = "one"
_KINDS["isb"] = "isb"
for _m in "wfi wfe".split():
    _KINDS[_m] = "wait"
for _m in "mrs msr cpsid cpsie".split():
    _KINDS[_m] = "sys"
for _m in "svc bkpt udf".split():
    _KINDS[_m] = "exc"
for _m in "vadd vsub vmul vnmul vabs vneg vcmp vcmpe vcvt vcvtr vcvtb vcvtt vmrs vmsr".split():
    _KINDS[_m] = "fp1"
_KINDS["vmov"] = "vmov"
for _m in "vfma vfms vfnma vfnms vmla vmls vnmla vnmls".split():
    _KINDS[_m] = "fmac"
for _m in ("vdiv", "vsqrt"):
    _KINDS[_m] = "fdiv"
_KINDS["vldr"] = "vldr"
_KINDS["vstr"] = "vstr"
for _m in "vldm vldmia vldmdb vstm vstmia vstmdb vpush vpop".split():
    _KINDS[_m] = "vldm"

FP_KINDS = frozenset(("fp1", "vmov", "fmac", "fdiv", "vldr", "vstr", "vldm"))
# Kinds whose result an address needs one more cycle to use (3.3.2).
DATA_PROC = frozenset(("alu", "mul", "mla", "mull", "mlal", "dsp_mul", "div", "vmov", "fp1"))
NO_DEST = frozenset(("cmp", "cmn", "tst", "teq"))


def _reg(tok):
    tok = tok.strip().rstrip("!").lower()
    if CORE_REG_RE.match(tok):
        return REG_ALIASES.get(tok, tok)
    return None


def _split_operands(ops):
    """Top-level comma split (not inside [] or {})."""
    out, depth, cur = [], 0, []
    for ch in ops:
        if ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
        if ch == "," and depth == 0:
            out.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    if "".join(cur).strip():
        out.append("".join(cur).strip())
    return out


def _reglist(ops):
    """Registers of the {...} list of ops: (core registers, 32-bit words)."""
    m = re.search(r"\{([^}]*)\}", ops)
    if not m:
        return set(), 0
    core, words = set(), 0
    for item in m.group(1).split(","):
        item = item.strip().lower()
        if not item:
            continue
        lo, _, hi = item.partition("-")
        if lo[0] in "sd" and lo[1:].isdigit():
            n = (int(hi[1:]) - int(lo[1:]) + 1) if hi else 1
            words += n * (2 if lo[0] == "d" else 1)
            continue
        a, b = _reg(lo), _reg(hi) if hi else None
        if a is None:
            continue
        if b is None:
            core.add(a)
        else:
            for i in range(int(a[1:]), int(b[1:]) + 1):
                core.add("r%d" % i)
        words = len(core)
    return core, words


def _addr_regs(ops):
    m = re.search(r"\[([^\]]*)\]", ops)
    if not m:
        return set()
    regs = set()
    for part in m.group(1).split(",")[:2]:
        r = _reg(part.split()[0]) if part.strip() else None
        if r:
            regs.add(r)
    return regs


def split_mnemonic(mnemonic):
    """(base, cond, sets_flags) of a capstone mnemonic, or (None, ...) if unknown."""
    m = mnemonic.lower().split(".")[0]
    if m in _KINDS:
        return m, None, False
    if re.match(r"^it[te]{0,3}$", m):
        return "it", None, False
    if m[-2:] in CONDS and m[:-2] in _KINDS:
        return m[:-2], m[-2:], False
    if m.endswith("s") and m[:-1] in _KINDS:
        return m[:-1], None, True
    if m[-2:] in CONDS and m[-3:-2] == "s" and m[:-3] in _KINDS:
        return m[:-3], m[-2:], True
    return None, None, False


class Insn:
    """One decoded instruction: its fixed cost parts and register use."""
    __slots__ = ("size", "text", "base", "kind", "cond", "cost", "writes", "addr",
                 "ld_dst", "pc_write", "reg_offset", "unknown")

    def __init__(self, size, mnemonic, ops, core):
        self.size = size
        self.text = ("%s %s" % (mnemonic, ops)).strip()
        base, cond, _ = split_mnemonic(mnemonic)
        self.base, self.cond, self.unknown = base, cond, base is None
        if base == "it":
            kind = "it"
        else:
            kind = _KINDS.get(base, "alu")
        self.kind = kind
        self.writes, self.addr, self.ld_dst = set(), set(), set()
        self.pc_write, self.reg_offset = False, False
        operands = _split_operands(ops)
        first = _reg(operands[0]) if operands else None
        if kind in FP_KINDS and core == "m3":
            raise ValueError("FPU instruction on a Cortex-M3 trace: %s" % self.text)
        if kind in ("dsp_mul",) and core == "m3":
            raise ValueError("ARMv7E-M instruction on a Cortex-M3 trace: %s" % self.text)

        if kind in ("alu", "mul", "mla", "dsp_mul", "div"):
            self.cost = {"alu": 1, "mul": 1, "dsp_mul": 1, "div": None,
                         "mla": 2 if core == "m3" else 1}[kind]
            if base not in NO_DEST and first:
                self.writes.add(first)
                self.pc_write = first == "r15"
        elif kind in ("mull", "mlal"):
            self.cost = (5 if kind == "mull" else 7) if core == "m3" else 1
            self.writes.update(r for r in map(_reg, operands[:2]) if r)
        elif kind == "ld":
            self.cost = 2
            self.addr = _addr_regs(ops)
            if first:
                self.ld_dst.add(first)
                self.pc_write = first == "r15"
        elif kind in ("st", "strex"):
            self.addr = _addr_regs(ops)
            inner = re.search(r"\[([^\]]*)\]", ops)
            parts = inner.group(1).split(",") if inner else []
            self.reg_offset = len(parts) > 1 and _reg(parts[1].split()[0]) is not None
            self.cost = 2 if (kind == "strex" or self.reg_offset) else 1
        elif kind in ("ldrd", "strd"):
            self.cost = 3
            self.addr = _addr_regs(ops)
            if kind == "ldrd":
                self.ld_dst.update(r for r in map(_reg, operands[:2]) if r)
        elif kind in ("ldm", "stm"):
            regs, n = _reglist(ops)
            self.cost = 1 + n
            self.addr = {"r13"} if base in ("push", "pop") else ({first} if first else set())
            if kind == "ldm":
                self.ld_dst = regs
                self.pc_write = "r15" in regs
        elif kind in ("b", "bl", "cb"):
            self.cost = 1
            self.pc_write = True
        elif kind == "tb":
            self.cost = 2
            self.addr = _addr_regs(ops)
            self.pc_write = True
        elif kind in ("it", "one", "wait"):
            self.cost = 1
        elif kind == "isb":
            self.cost = 1  # + P below
        elif kind == "sys":
            self.cost = 2
            if base == "mrs" and first:
                self.writes.add(first)
        elif kind == "exc":
            self.cost = 1
        elif kind == "fp1":
            self.cost = 1
            if base == "vmrs" and first:
                self.writes.add(first)
        elif kind == "vmov":
            core_regs = [r for r in map(_reg, operands) if r]
            self.cost = 2 if len(core_regs) >= 2 else 1
            if core_regs and first:
                self.writes.update(r for r in map(_reg, operands[:len(core_regs)]) if r)
        elif kind == "fmac":
            self.cost = 3
        elif kind == "fdiv":
            self.cost = 14
        elif kind in ("vldr", "vstr"):
            self.cost = 3 if operands and operands[0].lower().startswith("d") else 2
            self.addr = _addr_regs(ops)
        elif kind == "vldm":
            _, words = _reglist(ops)
            self.cost = 1 + words
            self.addr = {"r13"} if base in ("vpush", "vpop") else ({first} if first else set())
        else:  # pragma: no cover - every kind is handled above
            self.cost = 1


class CycleModel:
    """Per-pulse cycle estimates; a qemu_count.measure() hook."""

    def __init__(self, core="m4", refill=2, div_cycles=12, explain=()):
        if core not in ("m3", "m4"):
            raise ValueError("core must be m3 or m4")
        self.core, self.P, self.div = core, refill, div_cycles
        self.explain = frozenset(explain)
        self.decoded = {}
        self.results = {}      # pulse index -> (cycles, min_cycles)
        self.details = {}      # pulse index -> [(pc, text, cost, note)]
        self.unknown = {}      # mnemonic -> executions costed 1 by default
        self.unmodelled = 0    # exceptions (SVC/BKPT/UDF) inside pulses
        self._index = None

    # -- qemu_count hook -------------------------------------------------
    def begin(self, index):
        self._index = index
        self._held = None      # (pc, Insn) waiting for its successor
        self._prev = None      # Insn costed last
        self._cycles = 0
        self._saving = 0
        self._detail = [] if index in self.explain else None

    def insn(self, pc, disasm):
        if self._index is None:
            return
        if disasm is None:
            raise ValueError("no disassembly for pc 0x%x (was -d in_asm given?)" % pc)
        ins = self.decoded.get(pc)
        if ins is None:
            ins = Insn(disasm[0], disasm[1], disasm[2], self.core)
            self.decoded[pc] = ins
        if self._held is not None:
            hpc, hins = self._held
            self._account(hpc, hins, pc != hpc + hins.size)
        self._held = (pc, ins)

    def end(self, pulse):
        if self._index is None:
            return
        if self._held is not None:
            hpc, hins = self._held
            self._account(hpc, hins, False)
        self.results[pulse.index] = (self._cycles, self._cycles - self._saving)
        if self._detail is not None:
            self.details[pulse.index] = self._detail
        self._index = None

    # -- the model ----------------------------------------------------------
    def cost(self, ins, prev, taken):
        """(cycles, possible saving if a condition failed, note) of ins after prev."""
        P = self.P
        note = []
        k = ins.kind
        c = ins.cost if k != "div" else self.div
        saving = 0
        if k in ("b", "cb"):
            if taken:
                c, note = 1 + P, ["taken"]
            elif k == "b" and ins.cond is None:
                c = 1 + P  # falls through to its own target
        elif k in ("bl", "tb"):
            if ins.cond is not None and not taken:
                c, note = 1, ["condition failed"]
            else:
                c += P
        elif ins.pc_write:
            if ins.cond is not None and not taken:
                c, note = 1, ["condition failed"]
            else:
                c += P
        elif k == "isb":
            c += P
        elif ins.cond is not None:
            saving = c - 1  # executed or not: the trace does not say
            if saving:
                note.append("cond: %d if it failed" % 1)
        if prev is not None:
            prev_ld = prev.kind == "ld" and not prev.pc_write
            if prev_ld and k in ("ld", "st") and not ins.pc_write and not (prev.ld_dst & ins.addr):
                if k == "ld" or ins.reg_offset:
                    c -= 1
                    saving = max(0, saving - 1)
                    note.append("pipelined")
            if ins.addr and prev.kind in DATA_PROC and (prev.writes & ins.addr):
                c += 1
                note.append("address interlock")
        if k == "exc":
            self.unmodelled += 1
            note.append("exception entry not modelled")
        if ins.unknown:
            self.unknown[ins.text.split()[0]] = self.unknown.get(ins.text.split()[0], 0) + 1
            note.append("unknown mnemonic: 1")
        return c, saving, ", ".join(note)

    def _account(self, pc, ins, taken):
        c, saving, note = self.cost(ins, self._prev, taken)
        self._cycles += c
        self._saving += saving
        self._prev = ins
        if self._detail is not None:
            self._detail.append((pc, ins.text, c, note))


def core_of_machine(machine):
    if machine == "mps2-an385":
        return "m3"
    if machine == "mps2-an386":
        return "m4"
    raise qemu_count.ToolError("no cycle model for %s (Cortex-M7: dual issue, branch prediction "
                               "and caches are out of scope)" % machine)


def rows_of(run, model):
    """[(index, raw, cycles, net, net_cycles, min_cycles, label)]."""
    rows = []
    cal = None
    for p in run.pulses:
        cyc, lo = model.results.get(p.index, (None, None))
        if p.label and p.label[0].startswith("cal"):
            cal = cyc
        net_c = cyc - cal + 1 + model.P if (cal is not None and p.net is not None) else None
        rows.append((p.index, p.raw, cyc, p.net, net_c, lo, p.label))
    return rows


def summary(rows, out=sys.stdout):
    """Per label kind: pulses, min/max instructions and cycles (net when known),
    and, for labels "kind m k p", a fit of the worst net cycles per p."""
    kinds = {}
    for idx, raw, cyc, net, net_c, lo, label in rows:
        kind = label[0] if label else "-"
        n = net if net is not None else raw
        c = net_c if net_c is not None else cyc
        kinds.setdefault(kind, []).append((n, c, label))
    out.write("# %-22s %6s %9s %11s %7s\n" % ("kind", "pulses", "insns", "cycles", "cyc/ins"))
    for kind, items in sorted(kinds.items()):
        ns = [i[0] for i in items]
        cs = [i[1] for i in items]
        rng = lambda v: ("%d" % min(v)) if min(v) == max(v) else "%d-%d" % (min(v), max(v))
        out.write("  %-22s %6d %9s %11s %7.2f\n" % (kind, len(items), rng(ns), rng(cs),
                                                 float(sum(cs)) / max(1, sum(ns))))
    worst = {}
    for idx, raw, cyc, net, net_c, lo, label in rows:
        if net_c is None or len(label) != 4 or not label[0].startswith(("wipe", "exh_wipe")):
            continue
        try:
            p = int(label[3])
        except ValueError:
            continue
        if p > 0:
            worst[p] = max(worst.get(p, 0), net_c)
    if len(worst) >= 2:
        ps = sorted(worst)
        xs, ys = ps, [worst[p] for p in ps]
        n = float(len(xs))
        mx, my = sum(xs) / n, sum(ys) / n
        sxx = sum((x - mx) ** 2 for x in xs)
        a = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx else 0.0
        b = my - a * mx
        out.write("# worst wipe-out net cycles per p: %s\n"
                  % " ".join("p%d=%d" % (p, worst[p]) for p in ps))
        out.write("# fit: %.2f p + %.1f cycles (paper, DSP28335 at 150 MHz: 28.5 p + 85.5)\n"
                  % (a, b))


# -- self-test ----------------------------------------------------------------

def _synthetic_log(program, undo_last=True):
    """QEMU-like log lines (bytes) for one pulse running program
    [(pc, size, mnemonic, operands)] in order."""
    lines = [b"mps2_fpgaio_write MPS2 FPGAIO write: offset 0x0 data 0x1 size 4\n"]
    seen = set()
    for i, (pc, size, mn, ops) in enumerate(program):
        if pc not in seen:
            seen.add(pc)
            hexes = " ".join(["abcd"] * (size // 2))
            lines.append(b"----------------\n")
            lines.append(b"IN: f\n")
            lines.append(("0x%08x:  %s  %s %s\n" % (pc, hexes, mn, ops)).encode())
        lines.append(("Trace 0: 0x7f0000000000 [00000000/%08x/00000110/ff020201] f\n"
                      % pc).encode())
        if undo_last and i == len(program) - 1:
            # the pin store: logged, rewound by -icount, logged again
            lines.append(b"cpu_io_recompile: rewound execution of TB to %08x\n" % pc)
            lines.append(("Trace 0: 0x7f0000000000 [00000000/%08x/00000110/ff038201] f\n"
                          % pc).encode())
    lines.append(b"mps2_fpgaio_write MPS2 FPGAIO write: offset 0x0 data 0x0 size 4\n")
    return lines


def _run_program(program, core, refill=2):
    run = qemu_count.Run()
    model = CycleModel(core, refill, explain=(0,))
    qemu_count._parse_log(iter(_synthetic_log(program)), run, frozenset(), model)
    return run, model


def self_test():
    failures = []

    def check(name, got, want):
        if got != want:
            failures.append("%s: got %r, want %r" % (name, got, want))

    for mn, want in (("bls", ("b", "ls", False)), ("bl", ("bl", None, False)),
                     ("mls", ("mls", None, False)), ("lsls", ("lsl", None, True)),
                     ("bics", ("bic", None, True)), ("bhi.w", ("b", "hi", False)),
                     ("ldrhi", ("ldr", "hi", False)), ("ldrh", ("ldrh", None, False)),
                     ("vcmpe.f32", ("vcmpe", None, False)), ("ite", ("it", None, False)),
                     ("teq", ("teq", None, False)), ("movs", ("mov", None, True)),
                     ("bxne", ("bx", "ne", False)), ("popne", ("pop", "ne", False))):
        check("split_mnemonic(%s)" % mn, split_mnemonic(mn), want)

    # Cortex-M4F, P = 2. Expected cycles by hand, with the rule that applies.
    m4 = [
        (0x100, 4, "ldr.w", "r3, [r0, #4]", 2),        # load
        (0x104, 2, "ldr", "r2, [r0, #8]", 1),          # pipelined after a load
        (0x106, 2, "ldr", "r1, [r2]", 2),              # address from that load: not pipelined
        (0x108, 2, "adds", "r1, r1, r3", 1),
        (0x10a, 2, "str", "r1, [r0, #0xc]", 1),        # STR immediate: 1
        (0x10c, 4, "add.w", "r2, r0, r3, lsl #2", 1),
        (0x110, 2, "str", "r1, [r2, r3]", 3),          # register offset 2 + interlock on r2
        (0x112, 2, "cmp", "r1, #0", 1),
        (0x114, 2, "beq", "#0x120", 3),                # taken: 1 + P
        (0x120, 4, "vldr", "s0, [r0]", 2),
        (0x124, 4, "vfma.f32", "s1, s0, s0", 3),
        (0x128, 4, "vdiv.f32", "s2, s1, s0", 14),
        (0x12c, 4, "vmrs", "apsr_nzcv, fpscr", 1),
        (0x130, 2, "bne", "#0x200", 1),                # not taken
        (0x132, 2, "push", "{r4, r5, lr}", 4),         # 1 + N
        (0x134, 4, "bl", "#0x300", 3),                 # 1 + P
        (0x300, 4, "udiv", "r0, r1, r2", 12),          # documented worst
        (0x304, 4, "pop.w", "{r4, r5, pc}", 6),        # 1 + N + P
        (0x138, 2, "it", "ne", 1),
        (0x13a, 2, "ldrne", "r0, [r4]", 2),            # conditional: costed as executed
        (0x13c, 4, "vmov", "r0, r1, d0", 2),           # two core registers
        (0x140, 2, "str", "r2, [r3]", 1),              # the pin store (rewound once)
    ]
    run, model = _run_program([p[:4] for p in m4], "m4")
    check("m4 pulses", len(run.pulses), 1)
    check("m4 instructions", run.pulses[0].raw, len(m4))
    check("m4 cycles", model.results.get(0), (sum(p[4] for p in m4), sum(p[4] for p in m4) - 1))
    for (pc, text, c, note), p in zip(model.details.get(0, []), m4):
        check("m4 %s" % text, c, p[4])

    # Cortex-M3: no FPU, slower multiply-accumulate and long multiplies.
    m3 = [
        (0x200, 2, "mov", "r2, r0", 1),
        (0x202, 4, "umull", "r0, r1, r2, r3", 5),      # 3..5: worst
        (0x206, 4, "mla", "r0, r1, r2, r0", 2),
        (0x20a, 4, "smlal", "r0, r1, r2, r3", 7),      # 4..7: worst
        (0x20e, 2, "ldr", "r4, [r1]", 3),              # r1 from SMLAL just before: 2 + interlock
        (0x210, 2, "ldr", "r3, [r2]", 1),              # pipelined after a load
        (0x212, 2, "movs", "r0, #0", 1),
        (0x214, 2, "ldr", "r3, [r2]", 2),
        (0x216, 2, "str", "r3, [r0, r2]", 1),          # register offset, pipelined after LDR
        (0x218, 2, "cbz", "r3, #0x220", 1),            # not taken
        (0x21a, 2, "bx", "lr", 3),
        (0x400, 2, "str", "r2, [r3]", 1),
    ]
    run, model = _run_program([p[:4] for p in m3], "m3")
    check("m3 cycles", model.results.get(0), (sum(p[4] for p in m3),) * 2)
    for (pc, text, c, note), p in zip(model.details.get(0, []), m3):
        check("m3 %s" % text, c, p[4])
    try:
        _run_program([(0x100, 4, "vadd.f32", "s0, s0, s1"), (0x104, 2, "str", "r2, [r3]")], "m3")
        failures.append("m3 accepted an FPU instruction")
    except ValueError:
        pass

    # Calibration: net_cycles = cycles - cal_cycles + (1 + P).
    run = qemu_count.Run()
    model = CycleModel("m4", 2)
    log = (_synthetic_log([(0x10, 2, "blx", "r4"), (0x40, 2, "bx", "lr"), (0x12, 2, "str", "r2, [r3]")])
           + _synthetic_log([(0x10, 2, "blx", "r4"), (0x80, 2, "movs", "r0, #1"),
                             (0x82, 2, "bx", "lr"), (0x12, 2, "str", "r2, [r3]")]))
    qemu_count._parse_log(iter(log), run, frozenset(), model)
    run.pulses[0].label, run.pulses[1].label = ["cal_x"], ["body"]
    run.pulses[1].net = run.pulses[1].raw - run.pulses[0].raw + 1
    rows = rows_of(run, model)
    check("cal cycles", rows[0][2], 3 + 3 + 1)
    check("net cycles", rows[1][4], 1 + 3)  # movs + bx lr
    check("net insns", rows[1][3], 2)

    if failures:
        for f in failures:
            print("FAIL " + f)
        return 1
    print("cycle_model self-test: OK (%d synthetic instructions)" % (len(m4) + len(m3) + 7))
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("elf", nargs="?")
    ap.add_argument("--self-test", action="store_true", help="run the model's unit test")
    ap.add_argument("--core", choices=("m3", "m4"), help="default: from the image's machine")
    ap.add_argument("--machine", choices=sorted(qemu_count.BOARDS),
                    help="QEMU machine (default: from the ELF)")
    ap.add_argument("--refill", type=int, default=2, help="P, pipeline refill cycles (1..3)")
    ap.add_argument("--div-cycles", type=int, default=12, help="SDIV/UDIV cost (2..12)")
    ap.add_argument("--qemu", default=os.environ.get("HYST_QEMU", "qemu-system-arm"))
    ap.add_argument("--timeout", type=float, default=1800.0)
    ap.add_argument("--csv", help="write index,raw,cycles,net,net_cycles,min_cycles,label")
    ap.add_argument("--explain", default="", help="pulse indices to print instruction by instruction")
    ap.add_argument("--summary", action="store_true", help="per-kind ranges instead of every pulse")
    args = ap.parse_args(argv)
    if args.self_test:
        return self_test()
    if not args.elf:
        ap.error("an ELF image, or --self-test")
    try:
        machine = args.machine or qemu_count.machine_of(args.elf)
        core = args.core or core_of_machine(machine)
        explain = [int(i) for i in args.explain.split(",") if i.strip()]
        model = CycleModel(core, args.refill, args.div_cycles, explain)
        run = qemu_count.measure(args.elf, args.qemu, args.timeout, machine=machine, hook=model)
    except (qemu_count.ToolError, ValueError) as e:
        print("cycle_model: %s" % e, file=sys.stderr)
        return 2
    rows = rows_of(run, model)
    fmt = lambda v: "" if v is None else str(v)
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("index,raw,cycles,net,net_cycles,min_cycles,label\n")
            for r in rows:
                f.write(",".join(fmt(v) for v in r[:6]) + "," + " ".join(r[6]) + "\n")
    print("# %s on %s, model %s, P=%d, divide %d cycles, zero wait states"
          % (os.path.basename(args.elf), machine, core, args.refill, args.div_cycles))
    if args.summary:
        summary(rows)
    else:
        print("# index raw cycles net net_cycles min_cycles label")
        for r in rows:
            print(" ".join(fmt(v) for v in r[:6]) + " " + " ".join(r[6]))
    for idx in explain:
        print("# pulse %d, instruction by instruction: pc cycles text [rule]" % idx)
        for pc, text, c, note in model.details.get(idx, []):
            print("  %08x %3d  %-40s %s" % (pc, c, text, note))
    if model.unknown:
        print("# costed 1 cycle, mnemonic not in the model: %s"
              % ", ".join("%s x%d" % kv for kv in sorted(model.unknown.items())), file=sys.stderr)
    if model.unmodelled:
        print("# %d exception entries inside pulses not modelled" % model.unmodelled,
              file=sys.stderr)
    print("# pulses %d instructions %d exit %d" % (len(rows), run.instructions, run.exit_code),
          file=sys.stderr)
    return run.exit_code


if __name__ == "__main__":
    sys.exit(main())
