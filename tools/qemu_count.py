#!/usr/bin/env python3
"""Exact instruction counts between GPIO edges of a firmware image under QEMU.

Runs an mps2-an386 ELF with one instruction per translation block
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

Usage:
  qemu_count.py ELF [--csv out.csv] [--profile N,M --profile-out f.tsv]
Prints one line per pulse: index raw net label... ; exit status is the
firmware's, or 2 on a tool error. Import: measure(elf, ...) -> Run.
"""
import argparse
import os
import re
import subprocess
import sys
import threading

QEMU_ARGS = ["-M", "mps2-an386", "-cpu", "cortex-m4", "-nographic",
             "-monitor", "none", "-serial", "none",
             "-semihosting-config", "enable=on,target=native",
             "-icount", "shift=0",
             "-d", "exec,nochain", "-singlestep",
             "-trace", "mps2_fpgaio_write"]

# "mps2_fpgaio_write MPS2 FPGAIO write: offset 0x0 data 0x1 size 4", maybe
# prefixed by "pid@time:" depending on the QEMU version.
FPGAIO_RE = re.compile(rb"mps2_fpgaio_write.*offset 0x([0-9a-fA-F]+) data 0x([0-9a-fA-F]+)")
# "Trace 0: 0x7f.. [00000000/000004c8/00000110/ff200000] sym": 2nd field = pc
TRACE_PC_RE = re.compile(rb"\[[0-9a-fA-F]+/([0-9a-fA-F]+)/")
# -d exec lines saying the block logged last did not execute (QEMU 7.2).
UNDONE = (b"cpu_io_recompile: rewound", b"Stopped execution of TB chain")


class ToolError(Exception):
    pass


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


def _parse_log(stream, run, profile):
    led = 0
    count = 0
    total = 0
    last_key = None
    prof = run.profile
    for line in stream:
        if line.startswith(b"Trace"):
            total += 1
            if led:
                count += 1
                last_key = None
                if len(run.pulses) in profile:
                    m = TRACE_PC_RE.search(line)
                    if m:
                        last_key = (len(run.pulses), int(m.group(1), 16))
                        prof[last_key] = prof.get(last_key, 0) + 1
            continue
        if line.startswith(UNDONE):
            # The block just logged did not run: an I/O access rewound it to
            # recompile (it runs again, logged again), or an exit request
            # stopped it before its first instruction. With -singlestep the
            # block is that one instruction.
            total -= 1
            if led:
                count -= 1
                if last_key is not None:
                    prof[last_key] -= 1
                    last_key = None
            continue
        m = FPGAIO_RE.search(line)
        if m is None or int(m.group(1), 16) != 0:
            continue
        bit = int(m.group(2), 16) & 1
        if bit and not led:
            count = 0
        elif led and not bit:
            run.pulses.append(Pulse(len(run.pulses), count))
        led = bit
    run.instructions = total
    if led:
        raise ToolError("the pin was still high when the firmware ended")


def measure(elf, qemu="qemu-system-arm", timeout=900, profile=()):
    """Runs elf under QEMU; returns a Run with labelled pulses.

    profile: pulse indices whose instructions are also counted per address,
    in Run.profile[(index, pc)]."""
    if not os.path.isfile(elf):
        raise ToolError("no such firmware image: %s" % elf)
    cmd = [qemu] + QEMU_ARGS + ["-kernel", elf]
    run = Run()
    try:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                stdin=subprocess.DEVNULL)
    except OSError as e:
        raise ToolError("cannot start %s: %s" % (qemu, e))
    out_chunks = []
    reader = threading.Thread(target=lambda: out_chunks.append(proc.stdout.read()))
    reader.start()
    timer = threading.Timer(timeout, proc.kill)
    timer.start()
    try:
        _parse_log(proc.stderr, run, frozenset(profile))
    finally:
        proc.stderr.close()
        run.exit_code = proc.wait()
        timer.cancel()
        reader.join()
    text = b"".join(out_chunks).decode("utf-8", "replace")
    run.stdout_lines = text.splitlines()
    if run.instructions == 0:
        raise ToolError("QEMU logged no instructions (exit %s): is -d exec supported?"
                        % run.exit_code)
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
    args = ap.parse_args(argv)
    try:
        wanted = [int(i) for i in args.profile.split(",") if i.strip()]
        run = measure(args.elf, args.qemu, args.timeout, wanted)
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
    print("# pulses %d instructions %d exit %d" % (len(rows), run.instructions, run.exit_code),
          file=sys.stderr)
    return run.exit_code


if __name__ == "__main__":
    sys.exit(main())
