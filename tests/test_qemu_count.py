#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""ctest: tools/qemu_count.py's two ways of counting agree.

Runs one benchmark image with the counting plugin and from QEMU's instruction
log, profiling two pulses and with an instruction hook, and requires the same
pulses with the same counts, the same per-address profiles, the same
instructions with the same disassembly passed to the hook (what
tools/cycle_model.py costs), the same total and the same firmware output.
Exit 77 (skipped) when QEMU cannot load the plugin: the log is then the only
method and there is nothing to compare.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import qemu_count  # noqa: E402


class Recorder:
    """An instruction hook that keeps what it is given."""

    def __init__(self):
        self.events = []

    def begin(self, index):
        self.events.append(("begin", index))

    def insn(self, pc, disasm):
        self.events.append((pc, disasm))

    def end(self, pulse):
        self.events.append(("end", pulse.index, pulse.raw))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--elf", required=True)
    ap.add_argument("--qemu", default="qemu-system-arm")
    ap.add_argument("--profile", default="1,7", help="pulse indices to profile")
    args = ap.parse_args()
    wanted = [int(i) for i in args.profile.split(",")]
    fast_hook, slow_hook = Recorder(), Recorder()
    fast = qemu_count.measure(args.elf, args.qemu, profile=wanted, method="plugin", hook=fast_hook)
    if fast.method != "plugin":
        print("qemu_count: this QEMU cannot load the plugin; nothing to compare")
        return 77
    slow = qemu_count.measure(args.elf, args.qemu, profile=wanted, method="trace", hook=slow_hook)
    fails = []
    if not fast_hook.events or fast_hook.events != slow_hook.events:
        diff = next((i for i, (a, b) in enumerate(zip(fast_hook.events, slow_hook.events)) if a != b),
                    min(len(fast_hook.events), len(slow_hook.events)))
        fails.append("the hook's instructions differ at event %d of %d / %d: %s / %s"
                     % (diff, len(fast_hook.events), len(slow_hook.events),
                        fast_hook.events[diff:diff + 1], slow_hook.events[diff:diff + 1]))
    if not fast.pulses or len(fast.pulses) != len(slow.pulses):
        fails.append("%d pulses with the plugin, %d from the log" % (len(fast.pulses), len(slow.pulses)))
    for a, b in zip(fast.pulses, slow.pulses):
        if (a.raw, a.net, a.label) != (b.raw, b.net, b.label):
            fails.append("pulse %d: plugin %s %s, log %s %s" % (a.index, a.raw, a.label, b.raw, b.label))
            break
    if fast.instructions != slow.instructions:
        fails.append("total: plugin %d, log %d" % (fast.instructions, slow.instructions))
    if not fast.profile or fast.profile != slow.profile:
        fails.append("the profiles of pulses %s differ (or are empty)" % args.profile)
    if fast.stdout_lines != slow.stdout_lines or fast.exit_code != slow.exit_code:
        fails.append("the firmware's output or exit status differ")
    print("qemu_count: %d pulses, %d instructions, profiles of %d addresses, %d hook events: %s"
          % (len(fast.pulses), fast.instructions, len(fast.profile), len(fast_hook.events),
             "differ" if fails else "the same"))
    for f in fails:
        print("FAIL: " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
