#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Exact instruction counts between GPIO edges of a firmware image under QEMU.

Two ways to count, the same counts (tests/test_qemu_count.py compares them):

Plugin (the default): QEMU runs at its usual speed with a TCG plugin,
tools/qemu_count_plugin.c, built here with the host's C compiler on first use
(into build/qemu-plugin/ of this tree; HYST_QEMU_PLUGIN names another .so).
It adds one to a counter before every executed instruction and prints the
counter at each store to the pin's register; QEMU's mps2_fpgaio_write trace
event gives the stored value. A pulse's count is the difference of the
counters of the stores that raised and lowered the pin. Profiles (per-address
counts of chosen pulses) and the instruction hook take a second run that
logs the addresses inside those pulses only (with the hook, every pulse's,
and the disassembly of every instruction translated). A QEMU without plugin
support (or HYST_QEMU_COUNT=trace) falls back to the instruction log below.

Instruction log: runs an mps2-an386 ELF with one instruction per translation block
(-singlestep -d exec,nochain: one "Trace" line per executed instruction) and
with the FPGAIO register writes traced (-trace mps2_fpgaio_write). A pulse is
LED0 (bit 0 of FPGAIO offset 0) going 0 -> 1 -> 0; its count is the number of
instructions executed after the write that raised the pin, up to and
including the write that lowers it. A "Trace" line means a block was
entered, not executed: the lines QEMU prints when a block is rewound (the
pin store itself, under -icount) or stopped before its first instruction
(exit requests, icount budget) take one instruction back off. The counts are
then exact and independent of when QEMU's timers fire: the same code gives
the same counts on every run, in every image and on every machine.

Both streams are read from QEMU's stderr, where qemu_log() sends them when no
-D file is given (with -D, QEMU 7.2 writes both into that file); one FILE
keeps the trace events in order with the executed instructions. The log is
parsed as it streams and never stored. A QEMU whose trace backend is not
"log" shows no edges: labelled firmware then fails with a label/pulse
mismatch instead of giving counts. Firmware must not write to stderr inside
a pulse (its text would share the log stream).

Labels: every firmware stdout line "@pulse <fields...>" labels the pulse of
the same rank. Calibration: a pulse whose first label field starts with
"cal" times the same timing wrapper around a callee whose body is a single
instruction; later pulses get net = raw - cal_raw + 1, the instructions of
the measured callee from its first instruction to its return.

Machines: the image runs on the QEMU MPS2 machine of its core (BOARDS), read
from the ELF's build attributes (arm-none-eabi-readelf -A; machine_of()):
mps2-an385 for a Cortex-M3, mps2-an386 for a Cortex-M4 (also the default
when the attributes cannot be read), mps2-an500 for a Cortex-M7; --machine
overrides it.

Instruction hook (used by tools/cycle_model.py): measure(..., hook=h) also
logs QEMU's disassembly of each translated instruction (-d in_asm; with
-singlestep one per block) into Run.disasm {pc: (bytes, mnemonic,
operands)} and calls h.begin(index) at each rising edge, h.insn(pc, disasm)
for each instruction of the pulse in execution order (an instruction QEMU
rewound or stopped is withdrawn before it is passed on), and h.end(pulse)
at the falling edge, with the same instructions the counts include.

Usage:
  qemu_count.py ELF [--csv out.csv] [--profile N,M --profile-out f.tsv]
                [--machine mps2-an385|mps2-an386|mps2-an500] [--method plugin|trace]
Prints one line per pulse: index raw net label... ; exit status is the
firmware's, or 2 on a tool error. Import: measure(elf, ...) -> Run.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import threading

HERE = os.path.dirname(os.path.abspath(__file__))
PLUGIN_SOURCE = os.path.join(HERE, "qemu_count_plugin.c")


class ToolError(Exception):
    pass


# QEMU MPS2 machine -> the only CPU it accepts.
BOARDS = {"mps2-an385": "cortex-m3", "mps2-an386": "cortex-m4", "mps2-an500": "cortex-m7"}
DEFAULT_MACHINE = "mps2-an386"
# ELF Tag_CPU_name (lower case) -> machine.
_CPU_TO_MACHINE = {"cortex-m3": "mps2-an385", "cortex-m4": "mps2-an386",
                   "cortex-m7": "mps2-an500"}


def qemu_args(machine=DEFAULT_MACHINE, in_asm=False):
    """QEMU options (without the program and -kernel) for machine."""
    if machine not in BOARDS:
        raise ToolError("unknown machine %s (expected one of %s)"
                        % (machine, ", ".join(sorted(BOARDS))))
    return ["-M", machine, "-cpu", BOARDS[machine], "-nographic",
            "-monitor", "none", "-serial", "none",
            "-semihosting-config", "enable=on,target=native",
            "-icount", "shift=0",
            "-d", "exec,nochain,in_asm" if in_asm else "exec,nochain", "-singlestep",
            "-trace", "mps2_fpgaio_write"]


QEMU_ARGS = qemu_args()  # the default machine's options (kept for importers)


def machine_of(elf, readelf="arm-none-eabi-readelf"):
    """The MPS2 machine for elf's core, from its build attributes
    (readelf -A); DEFAULT_MACHINE when they cannot be read.

    A linked image often carries the architecture as Tag_CPU_name ("7E-M",
    merged from newlib's objects), so the architecture and the FPU decide:
    ARMv7-M -> Cortex-M3, ARMv7E-M with FPv5 -> Cortex-M7, other ARMv7E-M ->
    Cortex-M4."""
    try:
        out = subprocess.run([readelf, "-A", elf], capture_output=True, text=True,
                             check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return DEFAULT_MACHINE
    m = re.search(r'Tag_CPU_name:\s*"?([A-Za-z0-9-]+)', out)
    if m and m.group(1).lower() in _CPU_TO_MACHINE:
        return _CPU_TO_MACHINE[m.group(1).lower()]
    arch = re.search(r"Tag_CPU_arch:\s*(\S+)", out)
    fp = re.search(r"Tag_FP_arch:\s*(.*)", out)
    if arch and arch.group(1) == "v7":
        return "mps2-an385"
    if arch and arch.group(1) == "v7E-M":
        return "mps2-an500" if fp and "FPv5" in fp.group(1) else "mps2-an386"
    return DEFAULT_MACHINE

# "mps2_fpgaio_write MPS2 FPGAIO write: offset 0x0 data 0x1 size 4", maybe
# prefixed by "pid@time:" depending on the QEMU version.
FPGAIO_RE = re.compile(rb"mps2_fpgaio_write.*offset 0x([0-9a-fA-F]+) data 0x([0-9a-fA-F]+)")
# "Trace 0: 0x7f.. [00000000/000004c8/00000110/ff200000] sym": 2nd field = pc
TRACE_PC_RE = re.compile(rb"\[[0-9a-fA-F]+/([0-9a-fA-F]+)/")
# -d exec lines saying the block logged last did not execute (QEMU 7.2).
UNDONE = (b"cpu_io_recompile: rewound", b"Stopped execution of TB chain")
# -d in_asm (capstone): "0x00001a84:  f8d2 3d88  ldr.w    r3, [r2, #0xd88]"
IN_ASM_RE = re.compile(rb"^0x([0-9a-fA-F]+):\s+((?:[0-9a-fA-F]{4} )*[0-9a-fA-F]{4})\s+(\S+)[ \t]*(.*?)\s*$")


class Pulse:
    __slots__ = ("index", "raw", "net", "label")

    def __init__(self, index, raw):
        self.index, self.raw, self.net, self.label = index, raw, None, []


class Run:
    def __init__(self):
        self.pulses = []
        self.stdout_lines = []
        self.meta = {}
        self.exit_code = None
        self.instructions = 0
        self.profile = {}
        self.machine = DEFAULT_MACHINE
        self.disasm = {}
        self.method = None


def _parse_log(stream, run, profile, hook=None):
    led = 0
    count = 0
    total = 0
    last_key = None
    prof = run.profile
    disasm = run.disasm
    pending = None  # hook: the pc logged last inside the pulse, not yet passed on
    for line in stream:
        if line.startswith(b"Trace"):
            total += 1
            if led:
                count += 1
                last_key = None
                if hook is not None or len(run.pulses) in profile:
                    m = TRACE_PC_RE.search(line)
                    if m:
                        pc = int(m.group(1), 16)
                        if len(run.pulses) in profile:
                            last_key = (len(run.pulses), pc)
                            prof[last_key] = prof.get(last_key, 0) + 1
                        if hook is not None:
                            if pending is not None:
                                hook.insn(pending, disasm.get(pending))
                            pending = pc
            continue
        if line.startswith(UNDONE):
            # The block just logged did not run: an I/O access rewound it to
            # recompile (it runs again, logged again), or an exit request
            # stopped it before its first instruction. With -singlestep the
            # block is that one instruction.
            total -= 1
            if led:
                count -= 1
                pending = None
                if last_key is not None:
                    prof[last_key] -= 1
                    last_key = None
            continue
        if hook is not None and line.startswith(b"0x"):
            m = IN_ASM_RE.match(line)
            if m:
                disasm[int(m.group(1), 16)] = (
                    len(m.group(2).replace(b" ", b"")) // 2,
                    m.group(3).decode("ascii", "replace"),
                    m.group(4).decode("ascii", "replace"))
                continue
        m = FPGAIO_RE.search(line)
        if m is None or int(m.group(1), 16) != 0:
            continue
        bit = int(m.group(2), 16) & 1
        if bit and not led:
            count = 0
            pending = None
            if hook is not None:
                hook.begin(len(run.pulses))
        elif led and not bit:
            pulse = Pulse(len(run.pulses), count)
            run.pulses.append(pulse)
            if hook is not None:
                if pending is not None:
                    hook.insn(pending, disasm.get(pending))
                    pending = None
                hook.end(pulse)
        led = bit
    run.instructions = total
    if led:
        raise ToolError("the pin was still high when the firmware ended")


def plugin_path(cc=None):
    """The counting plugin's shared object, built from PLUGIN_SOURCE when
    missing or older than it; None if it cannot be built (no C compiler)."""
    given = os.environ.get("HYST_QEMU_PLUGIN")
    if given:
        return given
    out_dir = os.path.join(HERE, "..", "build", "qemu-plugin")
    so = os.path.join(out_dir, "qemu_count_plugin.so")
    try:
        if os.path.getmtime(so) >= os.path.getmtime(PLUGIN_SOURCE):
            return so
    except OSError:
        pass
    cc = cc or os.environ.get("CC") or "cc"
    try:
        os.makedirs(out_dir, exist_ok=True)
        # built under a temporary name, then renamed: parallel ctests share it
        fd, tmp = tempfile.mkstemp(suffix=".so", dir=out_dir)
        os.close(fd)
        r = subprocess.run([cc, "-shared", "-fPIC", "-O2", "-o", tmp, PLUGIN_SOURCE],
                           capture_output=True, text=True)
        if r.returncode != 0:
            os.unlink(tmp)
            return None
        os.replace(tmp, so)
    except OSError:
        return None
    return so


class _NoPlugin(Exception):
    """QEMU could not load the plugin: count from the instruction log."""


def _start(cmd):
    try:
        return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                stdin=subprocess.DEVNULL)
    except OSError as e:
        raise ToolError("cannot start %s: %s" % (cmd[0], e))


def _communicate(proc, timeout, parse):
    """Runs parse(stderr) while stdout is collected; returns stdout's text."""
    out_chunks = []
    reader = threading.Thread(target=lambda: out_chunks.append(proc.stdout.read()))
    reader.start()
    timer = threading.Timer(timeout, proc.kill)
    timer.start()
    try:
        parse(proc.stderr)
    finally:
        proc.stderr.close()
        proc.wait()
        timer.cancel()
        reader.join()
    return b"".join(out_chunks).decode("utf-8", "replace")


def _plugin_pass(elf, qemu, timeout, machine, so, windows=(), disas=False):
    """One run with the plugin: (exit code, stdout, pin values, counters at
    the pin stores, total, {window rank: [pc...]}, {pc: (bytes, mnemonic,
    operands)} when disas)."""
    windows = frozenset(windows)
    arg = so
    listed = None
    if windows:
        fd, listed = tempfile.mkstemp(suffix=".txt", prefix="qemu_count_windows_")
        with os.fdopen(fd, "w") as f:
            f.write("\n".join(str(w) for w in sorted(windows)) + "\n")
        arg += ",windows=" + listed
    if disas:
        arg += ",disas=on"
    args = qemu_args(machine)
    args[args.index("exec,nochain")] = "plugin"  # the plugin's lines, not every instruction
    args.remove("-singlestep")
    cmd = [qemu] + args + ["-plugin", arg, "-kernel", elf]
    values, counts, pcs, other, code = [], [], {}, [], {}
    total = [None]

    def parse(stream):
        current = None
        for line in stream:
            if line.startswith(b"@pc "):
                if current is not None:
                    current.append(int(line[4:], 16))
                continue
            if line.startswith(b"@pin "):
                counts.append(int(line[5:]))
                rank = len(counts) - 1
                current = pcs.setdefault(rank, []) if rank in windows else None
                continue
            if line.startswith(b"@insn "):
                parts = line[6:].decode("ascii", "replace").rstrip().split(None, 3)
                if len(parts) >= 3:
                    code[int(parts[0], 16)] = (int(parts[1]), parts[2],
                                               parts[3] if len(parts) > 3 else "")
                continue
            if line.startswith(b"@total "):
                total[0] = int(line[7:])
                continue
            m = FPGAIO_RE.search(line)
            if m is not None:
                if int(m.group(1), 16) == 0:
                    values.append(int(m.group(2), 16))
                continue
            if len(other) < 20:
                other.append(line.decode("utf-8", "replace").rstrip())

    try:
        proc = _start(cmd)
        text = _communicate(proc, timeout, parse)
    finally:
        if listed:
            os.unlink(listed)
    if total[0] is None and not counts and any("plugin" in l.lower() for l in other):
        raise _NoPlugin("; ".join(other))
    if len(values) != len(counts):
        raise ToolError("%d pin writes traced, %d seen by the plugin" % (len(values), len(counts)))
    return proc.returncode, text, values, counts, total[0], pcs, code


def _measure_plugin(elf, qemu, timeout, profile, machine, so, run, hook=None):
    code, text, values, counts, total, _, _ = _plugin_pass(elf, qemu, timeout, machine, so)
    led, start, rises = 0, 0, []
    for rank, (value, count) in enumerate(zip(values, counts)):
        bit = value & 1
        if bit and not led:
            start = count
            rises.append(rank)
        elif led and not bit:
            run.pulses.append(Pulse(len(run.pulses), count - start))
        led = bit
    if led:
        raise ToolError("the pin was still high when the firmware ended")
    run.exit_code, run.stdout_lines = code, text.splitlines()
    run.instructions = total or 0
    wanted = [i for i in sorted(profile) if i < len(run.pulses)]
    traced = range(len(run.pulses)) if hook is not None else wanted
    if not traced:
        return
    # a second run logs the addresses inside the pulses wanted, in order
    _, _, _, again, _, pcs, run.disasm = _plugin_pass(
        elf, qemu, timeout, machine, so, [rises[i] for i in traced], disas=hook is not None)
    if again != counts:
        raise ToolError("the second run counted differently")
    for i in traced:
        seen = pcs.get(rises[i], ())
        if len(seen) != run.pulses[i].raw:
            raise ToolError("pulse %d: %d addresses for %d instructions" % (i, len(seen), run.pulses[i].raw))
    for i in wanted:
        for pc in pcs.get(rises[i], ()):
            run.profile[(i, pc)] = run.profile.get((i, pc), 0) + 1
    if hook is not None:
        for i in traced:
            hook.begin(i)
            for pc in pcs[rises[i]]:
                hook.insn(pc, run.disasm.get(pc))
            hook.end(run.pulses[i])


def _measure_trace(elf, qemu, timeout, profile, machine, hook, run):
    cmd = [qemu] + qemu_args(machine, in_asm=hook is not None) + ["-kernel", elf]
    proc = _start(cmd)
    text = _communicate(proc, timeout, lambda s: _parse_log(s, run, frozenset(profile), hook))
    run.exit_code, run.stdout_lines = proc.returncode, text.splitlines()
    if run.instructions == 0:
        raise ToolError("QEMU logged no instructions (exit %s): is -d exec supported?"
                        % run.exit_code)


def measure(elf, qemu="qemu-system-arm", timeout=900, profile=(), machine=None, hook=None,
            method=None):
    """Runs elf under QEMU; returns a Run with labelled pulses.

    profile: pulse indices whose instructions are also counted per address,
    in Run.profile[(index, pc)]. machine: the QEMU MPS2 machine (BOARDS);
    None reads it from the ELF (machine_of). hook: see the module text.
    method: "plugin" or "trace" (the module text); None: the plugin unless
    HYST_QEMU_COUNT says otherwise, the instruction log when the plugin
    cannot be built or loaded."""
    if not os.path.isfile(elf):
        raise ToolError("no such firmware image: %s" % elf)
    if machine is None:
        machine = machine_of(elf)
    if method is None:
        method = os.environ.get("HYST_QEMU_COUNT", "plugin")
    if method not in ("plugin", "trace"):
        raise ToolError("unknown counting method %s" % method)
    run = Run()
    run.machine = machine
    so = plugin_path() if method == "plugin" else None
    try:
        if so is None:
            raise _NoPlugin("no plugin")
        _measure_plugin(elf, qemu, timeout, profile, machine, so, run, hook)
        run.method = "plugin"
    except _NoPlugin:
        run = Run()
        run.machine = machine
        _measure_trace(elf, qemu, timeout, profile, machine, hook, run)
        run.method = "trace"
    labels = []
    for line in run.stdout_lines:
        if line.startswith("@pulse "):
            labels.append(line.split()[1:])
        elif line.startswith("# "):
            parts = line[2:].split()
            if len(parts) == 2:
                run.meta[parts[0]] = parts[1]
    if labels and len(labels) != len(run.pulses):
        raise ToolError("%d labels for %d pulses: the firmware and the log disagree"
                        % (len(labels), len(run.pulses)))
    cal = None
    for pulse, label in zip(run.pulses, labels or [[]] * len(run.pulses)):
        pulse.label = label
        if label and label[0].startswith("cal"):
            cal = pulse.raw
        elif cal is not None:
            pulse.net = pulse.raw - cal + 1
    return run


def symbol_size(elf, name, nm="arm-none-eabi-nm"):
    """Size in bytes of a symbol of elf (nm -S), or None if absent."""
    out = subprocess.run([nm, "-S", elf], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[3] == name:
            return int(parts[1], 16)
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("elf")
    ap.add_argument("--qemu", default=os.environ.get("HYST_QEMU", "qemu-system-arm"))
    ap.add_argument("--csv", help="write index,raw,net,label... here")
    ap.add_argument("--timeout", type=float, default=900.0)
    ap.add_argument("--profile", default="",
                    help="comma-separated pulse indices to count per address")
    ap.add_argument("--profile-out", help="index<TAB>address<TAB>count for --profile")
    ap.add_argument("--quiet", action="store_true", help="no per-pulse lines")
    ap.add_argument("--machine", choices=sorted(BOARDS),
                    help="QEMU machine (default: from the ELF's build attributes)")
    ap.add_argument("--method", choices=("plugin", "trace"),
                    help="count with the plugin (default) or from the instruction log")
    args = ap.parse_args(argv)
    try:
        wanted = [int(i) for i in args.profile.split(",") if i.strip()]
        run = measure(args.elf, args.qemu, args.timeout, wanted, machine=args.machine,
                      method=args.method)
    except ToolError as e:
        print("qemu_count: %s" % e, file=sys.stderr)
        return 2
    rows = [(p.index, p.raw, "" if p.net is None else p.net, " ".join(p.label))
            for p in run.pulses]
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("index,raw,net,label\n")
            for r in rows:
                f.write("%d,%d,%s,%s\n" % r)
    if args.profile_out:
        with open(args.profile_out, "w") as f:
            for (idx, pc) in sorted(run.profile):
                f.write("%d\t%x\t%d\n" % (idx, pc, run.profile[(idx, pc)]))
    if not args.quiet:
        for r in rows:
            print("%d %d %s %s" % r)
    print("# pulses %d instructions %d exit %d method %s"
          % (len(rows), run.instructions, run.exit_code, run.method), file=sys.stderr)
    return run.exit_code


if __name__ == "__main__":
    sys.exit(main())
