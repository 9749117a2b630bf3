#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Per-core figures of the budget image (bench_target.c, every survivor
count at Nu = 4096) on another core than the Cortex-M4F of analyse.py.

  cores.py --core m3 --build BUILD [--cycles]
  cores.py --core m3_q31 --build BUILD --q31
  cores.py --core m3_q31_inv --build BUILD --q31 --image bench_q31_inv

With --q31 the image is bench_q31 (the q31 variant, hyst/q31.h, on the same
trajectory; --image: another, such as its compensator's) and only
<core>_typical_insns and <core>_worst_insns_nu4096 are printed.

Prints "key value" lines: <core>_typical_insns, <core>_worst_insns_nu4096,
<core>_pi10_insns, <core>_engine_flash_O2 (the f32 engine's bytes, as
analyse.py counts them for the M4F), <core>_core_flash_Os (every object of
the core at -Os), <core>_step_stack_bytes (when the call graph stays inside
the core: not with soft float, whose libgcc helpers it calls) and, with
--cycles (the cores tools/cycle_model.py models: Cortex-M3, M4),
<core>_typical_cycles and <core>_worst_cycles_nu4096. Exact instruction
counts under QEMU, on the image's own MPS2 board.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
import analyse  # noqa: E402
import qemu_count  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--core", required=True, help="key prefix: m3, m7...")
    ap.add_argument("--build", required=True, help="a bench build directory of that core")
    ap.add_argument("--cycles", action="store_true")
    ap.add_argument("--q31", action="store_true", help="the q31 variant's image")
    ap.add_argument("--image", help="the image's name under BUILD/bench (with --q31)")
    ap.add_argument("--qemu", default=os.environ.get("HYST_QEMU", "qemu-system-arm"))
    args = ap.parse_args()
    image = (args.image or "bench_q31") if args.q31 else "bench_budget"
    args.elf = os.path.join(args.build, "bench", image)
    run = qemu_count.measure(args.elf, args.qemu)
    if run.exit_code != 0 or run.meta.get("failures") != "0":
        print("cores: %s: exit %s, failures %s" % (args.elf, run.exit_code, run.meta.get("failures")),
              file=sys.stderr)
        return 1
    samples = [p for p in run.pulses if p.net is not None and not p.label[0].startswith("cal")]
    typical = [p.net for p in samples if p.label[0] in analyse.TYPICAL]
    worst = [p.net for p in samples
             if analyse.wipe_kind(p.label[0]) or p.label[0].startswith("clamp")]
    pi = [p.net for p in samples if p.label[0] == "pi10"]
    if args.q31 and typical and worst:
        print("%s_typical_insns %d" % (args.core, max(typical)))
        print("%s_worst_insns_nu4096 %d" % (args.core, max(worst)))
        return 0
    if not typical or not worst or not pi:
        print("cores: %s: typical, wipe-out or PI samples missing" % args.elf, file=sys.stderr)
        return 1
    print("%s_typical_insns %d" % (args.core, max(typical)))
    print("%s_worst_insns_nu4096 %d" % (args.core, max(worst)))
    print("%s_pi10_insns %d" % (args.core, max(pi)))
    print("%s_engine_flash_O2 %d" % (args.core, analyse.engine_flash(
        args.build, "O2", os.environ.get("HYST_NM", "arm-none-eabi-nm"))))
    print("%s_core_flash_Os %d" % (args.core, analyse.flash_of(
        args.build, "Os", os.environ.get("HYST_SIZE", "arm-none-eabi-size"))[0]))
    try:
        print("%s_step_stack_bytes %d" % (args.core, analyse.stack_of(args.build, "O2",
                                                                       "hyst_f32_step")))
    except RuntimeError as e:
        print("# %s step stack: %s" % (args.core, e))
    if args.cycles:
        typ_c, worst_c = analyse.budget_cycles(args.elf, args.qemu)
        print("%s_typical_cycles %d" % (args.core, typ_c))
        print("%s_worst_cycles_nu4096 %d" % (args.core, worst_c))
    return 0


if __name__ == "__main__":
    sys.exit(main())
