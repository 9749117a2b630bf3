#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Turns the target's printout (examples/paper_report.c) into a report.

usage: report.py FIRMWARE_OUTPUT OUT_DIR [--timing CSV] [--bench SUMMARY]
                 [--measured-fit HYST_FIT_OUTPUT --measured-data FILE
                  [--measured-model-output HYST_SIM_OUTPUT]]

Writes OUT_DIR/README.md and PNG figures, and prints the headline figures
by section, with their units. Every number comes from the files given (the
measured record's bound on rate-independent models is computed here, from
the record); the paper's own numbers are quoted beside them. Without
--timing and --bench the per-sample cost is left out (./tools/demo writes
the report first, then again with them). Needs numpy and matplotlib
(tools/pyenv.sh provides them); the C build never does.
"""
import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def parse(path):
    """Sections of '@section', '@value', '@table' lines."""
    sections, cur, table, meta = {}, None, None, {}
    with open(path, encoding="utf-8") as fh:
        for ln, line in enumerate(fh, 1):
            line = line.rstrip("\n")
            if not line:
                continue
            if line.startswith("@section "):
                cur = {"values": {}, "tables": {}}
                sections[line.split()[1]] = cur
                table = None
            elif line.startswith("@value "):
                _, key, val = line.split()
                (cur["values"] if cur is not None else meta)[key] = float(val)
            elif line.startswith("@table "):
                _, name, cols = line.split()
                table = {"cols": cols.split(","), "rows": []}
                cur["tables"][name] = table
            elif line.startswith("@end"):
                cur, table = None, None
            elif line.startswith("@"):
                parts = line[1:].split(maxsplit=1)
                meta[parts[0]] = parts[1] if len(parts) > 1 else ""
            elif table is not None:
                try:
                    table["rows"].append([float(v) for v in line.split(",")])
                except ValueError:
                    sys.exit(f"report: {path}:{ln}: malformed table row: {line!r}")
    for sec in sections.values():
        for t in sec["tables"].values():
            t["data"] = np.array(t["rows"]) if t["rows"] else np.zeros((0, len(t["cols"])))
    return meta, sections


CONSOLE = []  # (section title, [lines]) printed by main()


def say(title, line):
    """A headline figure for the console, under its section's title."""
    if not CONSOLE or CONSOLE[-1][0] != title:
        CONSOLE.append((title, []))
    CONSOLE[-1][1].append(line)


def col(table, name):
    return table["data"][:, table["cols"].index(name)]


def fmt(v, digits=4):
    return f"{v:.{digits}g}"


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)
    return name


def poly(prefix, vals, degree):
    return [vals[f"{prefix}_c{k}"] for k in range(degree, -1, -1)]


def example1(sec, md):
    v = sec["values"]
    md.append("## Simulation Example 1: identification of f0 = x²\n")
    md.append("TCM with f0 = x² on [0, 1] driven by a full-range sine (10 periods, 2000 samples), "
              f"Gaussian output noise σ = {fmt(v['noise_sigma'])} (0.5 % of the range); degree-2 fit.\n")
    md.append("| | c2 | c1 | c0 | residual RMS |\n|---|---|---|---|---|")
    md.append("| paper | 1.0005 | -0.0008 | 0.0002 | |")
    for m, label in (("reflect", "hyst, paper's estimator (Eq. 14)"), ("joint", "hyst, joint estimator (default)")):
        c = poly(m, v, 2)
        md.append(f"| {label} | {c[0]:.4f} | {c[1]:.4f} | {c[2]:.4f} | {fmt(v[m + '_rms'])} |")
    md.append("")
    c = poly("joint", v, 2)
    say("Example 1: f0 = x^2 identified (unitless)",
        f"c2 {c[0]:.4f}, c1 {c[1]:.4f}, c0 {c[2]:.4f} (paper 1.0005, -0.0008, 0.0002)")


def example2(sec, md, out):
    v = sec["values"]
    md.append("## Simulation Example 2: TCM reproduces the PI model (Table 1)\n")
    md.append("PI model with the 10 operators of Table 1 against TCM with f0 = the PI loading curve "
              "(piecewise linear), both in float on the target.\n")
    md.append("| signal | samples | max \\|TCM − PI\\| | of the output range |\n|---|---|---|---|")
    for key in sorted(k[:-len("_samples")] for k in v if k.endswith("_samples")):
        md.append(f"| {key} | {int(v[key + '_samples'])} | {fmt(v[key + '_max_diff'])} | "
                  f"{fmt(v[key + '_max_diff'] / v['range'])} |")
    worst = max(v[k] for k in v if k.endswith("_max_diff"))
    say("Example 2: TCM reproduces PI-10 (unitless)",
        f"largest |TCM - PI| {fmt(worst / v['range'], 3)} of the output range over "
        f"{sum(1 for k in v if k.endswith('_samples'))} signals")
    t = sec["tables"].get("trace")
    if t is not None and len(t["data"]):
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot(col(t, "x"), col(t, "y_pi"), lw=2.5, label="PI (10 operators)")
        ax.plot(col(t, "x"), col(t, "y_tcm"), "--", lw=1, label="TCM, f0 = PI loading curve")
        ax.set_xlabel("input x (normalised, 0-1)")
        ax.set_ylabel("output y (normalised)")
        ax.legend()
        md.append(f"\n![TCM and PI]({save(fig, out, 'example2_pi.png')})\n")
    md.append("")


def experiment(sec, md, out):
    v = sec["values"]
    t = sec["tables"]["prediction"]
    md.append("## The experiment: f0 identified from a piezo plant, then the paper's test signal\n")
    md.append("The plant is a rate-independent Bouc–Wen model (`examples/common/plant_bw.c`) tuned to the "
              "paper's stage (0–40 V → 0.59–5.56 µm, loop width 16 % of the range). It is *not* a TCM: its "
              "minor loops do not close exactly and it has no wiping-out property, so the identified TCM can "
              "only approximate it, as with a real stage. f0 (degree 3) is identified on the target from five "
              "0–40–0 V triangles (0.1 V steps, first cycle dropped); then the paper's test signal (a triangle "
              "whose amplitude shrinks around 20 V for 7 peaks and 7 valleys, then grows back) drives plant "
              "and model.\n")
    md.append("| | c3 | c2 | c1 | c0 |\n|---|---|---|---|---|")
    md.append("| paper, Eq. 20 (real stage) | -6.1876e-6 | 1.1949e-3 | 8.6444e-2 | 5.8517e-1 |")
    for m, label in (("reflect", "identified, paper's estimator"), ("joint", "identified, joint (used)")):
        c = poly(m, v, 3)
        md.append(f"| {label} | {c[0]:.4e} | {c[1]:.4e} | {c[2]:.4e} | {c[3]:.4e} |")
    md.append("")
    md.append("| | paper | hyst on Cortex-M4F |\n|---|---|---|")
    md.append(f"| max prediction error | 0.12 µm | {v['max_error_um']:.3f} µm ({v['max_error_pct']:.2f} % of range) |")
    md.append(f"| RMS prediction error | — | {v['rms_error_um']:.3f} µm |")
    md.append(f"| max turning points | 14 (7 LTP + 7 RTP) | {int(v['max_tp'])} |")
    md.append("")
    title = "The experiment: f0 from a Bouc-Wen piezo, then the paper's test signal"
    say(title, f"max prediction error {v['max_error_um']:.3f} um ({v['max_error_pct']:.2f} % of the "
               f"range; paper 0.12 um), RMS {v['rms_error_um']:.3f} um")
    say(title, f"turning points held at most {int(v['max_tp'])} (paper 14)")
    i, x = col(t, "i"), col(t, "x_V")
    yp, ym, tp = col(t, "y_plant_um"), col(t, "y_model_um"), col(t, "tp")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(x, yp, lw=2.5, label="plant (Bouc–Wen)")
    ax.plot(x, ym, "--", lw=1, label="TCM prediction")
    ax.set_xlabel("drive voltage (V)")
    ax.set_ylabel("displacement (µm)")
    ax.legend()
    md.append(f"![loops]({save(fig, out, 'experiment_loops.png')})\n")
    fig, axs = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    axs[0].plot(i, x)
    axs[0].set_ylabel("input (V)")
    axs[1].plot(i, ym - yp)
    axs[1].set_ylabel("model − plant (µm)")
    axs[2].step(i, tp, where="post")
    axs[2].set_ylabel("turning points (count)")
    axs[2].set_xlabel("sample (0.1 V steps)")
    md.append(f"![error and turning points (Fig. 14 analogue)]({save(fig, out, 'experiment_error_tp.png')})\n")


def measured(sec, md, out):
    v = sec["values"]
    md.append("## Measured data: a real piezo micromanipulator\n")
    md.append("`tests/data/piezo_major_loop.dat` (yan9a/DiscreteBacklashOperator, MIT): 200 Hz, 1 Hz waves "
              "of 0–3.6 V; output in sensor units (range about 45). Degree 3, sensor lag 1 sample; fit on rows "
              "350–4149 (after the settling), predict rows 4150–7949 through the model.\n")
    md.append("| estimator | c3 | c2 | c1 | c0 | fit RMS | prediction RMS | prediction max |\n|---|---|---|---|---|---|---|---|")
    for m in ("reflect", "joint"):
        c = poly(m, v, 3)
        md.append(f"| {m} | {c[0]:.5g} | {c[1]:.5g} | {c[2]:.5g} | {c[3]:.5g} | {fmt(v[m + '_rms'])} | "
                  f"{fmt(v[m + '_predict_rms'])} | {fmt(v[m + '_predict_max'])} |")
    md.append("")
    md.append("The model `hyst fit` chooses on this record, and its prediction, follow.\n")


CANDIDATE = re.compile(r"^# candidate (?:everett degree (\d+) t-degree (\d+)|degree (\d+)) delay (\d+): "
                       r"hold-out rms ([0-9.eE+-]+)(?:, fit rms [0-9.eE+-]+; with creep tau ([0-9.eE+]+): "
                       r"([0-9.eE+-]+))?")
CHOSEN = re.compile(r"^# chosen by hold-out: degree (\d+), delay (\d+) \(kind (\w+)(?:, t-degree (\d+))?, "
                    r"(creep, )?(\d+) parameters")
PI_COMPARE = re.compile(r"PI (\d+) operators \((\d+) parameters\) ([0-9.eE+-]+)")
# the chosen model's RMS on the last third alone, as the comparison with PI prints it
CHOSEN_LAST_THIRD = re.compile(r"\) ([0-9.eE+-]+), PI \d+ operators")


def everett_params(d, k):
    """Identified reals of E of degree d, t-degree k: its terms and y_lo."""
    return 1 + sum(min(d - i, k) + 1 for i in range(1, d + 1))


def periodic_bound(x, y, skip, delay):
    """What any rate-independent model can do on a record whose drive
    repeats exactly: its output is then periodic too. Returns the period,
    the hold-out RMS of the best periodic prediction learnable from the
    training part (each phase's mean there), that of the hold-out's own
    phase means (the cycle-to-cycle scatter) and the drift of the output's
    cycle mean over the record; None if the drive does not repeat."""
    n = len(x)
    period = next((p for p in range(2, (n - skip) // 3)
                   if np.array_equal(x[skip + p:], x[skip:n - p])), None)
    if period is None:
        return None
    train = 2 * (n - skip - delay) // 3
    ks = np.arange(skip, n - delay)
    target, phase = y[ks + delay], ks % period
    fit, hold = ks < skip + train, ks >= skip + train

    def phase_means(mask):
        sums = np.bincount(phase[mask], weights=target[mask], minlength=period)
        return sums / np.maximum(np.bincount(phase[mask], minlength=period), 1)

    learnable = np.sqrt(np.mean((target[hold] - phase_means(fit)[phase[hold]]) ** 2))
    scatter = np.sqrt(np.mean((target[hold] - phase_means(hold)[phase[hold]]) ** 2))
    cycles = (n - skip) // period
    means = y[skip:skip + cycles * period].reshape(cycles, period).mean(axis=1)
    return period, learnable, scatter, means[-1] - means[0], cycles


def measured_choice(fit_path, data_path, md, out, model_output=None):
    """The measured record's automatic choice by the host tool (hyst fit's
    printout: every candidate without and with its creep term), the chosen
    model's prediction (hyst sim --model over the record, model_output) and
    what bounds any rate-independent model on that record."""
    # options: (kind, degree, t-degree, delay, parameters, hold-out, creep tau or None)
    cands, chosen, pi, chosen_last = [], None, None, None
    with open(fit_path, encoding="utf-8") as fh:
        for line in fh:
            m = CANDIDATE.match(line)
            if m:
                if m.group(1):
                    d, k = int(m.group(1)), int(m.group(2))
                    base = ("everett", d, k, int(m.group(4)), everett_params(d, k))
                else:
                    d = int(m.group(3))
                    base = ("poly", d, None, int(m.group(4)), d + 1)
                cands.append(base + (float(m.group(5)), None))
                if m.group(6):  # the creep option: its weight and time constant, two more
                    cands.append(base[:4] + (base[4] + 2, float(m.group(7)), float(m.group(6))))
            m = CHOSEN.match(line)
            if m:
                chosen = m
            m = PI_COMPARE.search(line) if line.startswith("# compare") else None
            if m:
                pi = (int(m.group(1)), int(m.group(2)), float(m.group(3)))
                last = CHOSEN_LAST_THIRD.search(line)
                chosen_last = float(last.group(1)) if last else None
    if chosen is None or pi is None or chosen_last is None or not cands:
        sys.exit(f"report: {fit_path}: no chosen model, candidates or PI comparison in hyst fit's output")
    delay, with_creep = int(chosen.group(2)), chosen.group(5) is not None
    picked = next(c for c in cands if c[0] == chosen.group(3) and c[1] == int(chosen.group(1)) and
                  c[3] == delay and (c[2] is None or c[2] == int(chosen.group(4))) and
                  (c[6] is not None) == with_creep)

    def name(c):
        base = f"E of degree {c[1]}, t-degree {c[2]}" if c[0] == "everett" else f"TCM degree {c[1]}"
        return base + (f" + creep (tau {c[6]:g} samples)" if c[6] is not None else "")

    md.append("## Measured data: the model `hyst fit` chooses\n")
    md.append("The host tool on the same record, as a user runs it: `hyst fit --skip 350 --xcol 1 --ycol 5 "
              "--compare-pi 10 tests/data/piezo_major_loop.dat` (its printout in `measured_fit.txt`). Every "
              "candidate (symmetric TCM of degree 1-9, E of degree 1-4 with each t-degree, delays 0-8), alone "
              "and with a creep term (one lag of the input, its time constant chosen from 100-20000 samples, "
              "docs/creep.md: two parameters more, its weight and time constant), is scored by its RMS "
              "prediction error on the last third (fitted on the first two) and on the middle third (fitted "
              "on the others); its score is the root mean square of the two, and the fewest parameters within "
              "1 % of the best score win. Best candidate per parameter count:\n")
    md.append("| parameters | model | delay | hold-out score (two thirds) |\n|---|---|---|---|")
    for p in sorted({c[4] for c in cands}):
        best = min((c for c in cands if c[4] == p), key=lambda c: c[5])
        mark = " (chosen)" if best is picked else ""
        md.append(f"| {p} | {name(best)}{mark} | {best[3]} | {fmt(best[5])} |")
    small = min((c for c in cands if c[4] <= 6), key=lambda c: c[5])
    plain = min((c for c in cands if c[6] is None), key=lambda c: (c[5], c[4]))
    md.append("")
    md.append(f"Chosen: {name(picked)}, delay {delay}, {picked[4]} parameters, hold-out score "
              f"{fmt(picked[5])}. The best of at most 6 parameters, {name(small)} at delay {small[3]}, scores "
              f"{fmt(small[5])} ({small[5] / picked[5]:.2f} times the chosen's); without a creep term the best "
              f"is {name(plain)} at delay {plain[3]}, {fmt(plain[5])} ({plain[5] / picked[5]:.2f} times). "
              f"On the last third alone (PI-{pi[0]}, non-negative least squares with {pi[1]} parameters, is "
              f"fitted on the first two thirds only): the chosen model {fmt(chosen_last)}, PI-{pi[0]} "
              f"{fmt(pi[2])}: PI-{pi[0]} / it = **{pi[2] / chosen_last:.2f}**.\n")
    title = "Measured record (real piezo): the model `hyst fit` chooses"
    say(title, f"{name(picked)}, delay {delay} samples, {picked[4]} parameters")
    say(title, f"RMS on the last third {fmt(chosen_last)} sensor units; PI-{pi[0]} {fmt(pi[2])}: "
               f"{pi[2] / chosen_last:.2f} times better")
    data = np.loadtxt(data_path)
    if model_output:
        chosen_prediction(data, np.loadtxt(model_output), 350, delay, name(picked), md, out)
    bound = periodic_bound(data[:, 0], data[:, 4], 350, delay)
    if bound is None:
        md.append("The record's drive does not repeat exactly: no bound computed.\n")
        return
    period, learnable, scatter, drift, cycles = bound
    md.append(f"Why the creep term: the record's drive repeats exactly every {period} samples, so the output of "
              "any rate-independent model (any kind, degree or delay: hysteresis alone, PI-10 included) is "
              "periodic on the last third. The best such prediction in least squares on the first two thirds "
              f"is each phase's mean output there ({period} free values). It scores {fmt(learnable)} on the "
              f"last third: PI-{pi[0]} / it = {pi[2] / learnable:.2f}. The rest is creep: the output's mean "
              f"over a cycle moves by {drift:+.3f} over the {cycles} cycles (the cycle-to-cycle scatter is "
              f"{fmt(scatter)}), a drift that the lag of the drive in the creep term predicts: "
              f"{fmt(chosen_last)} on the last third, {100 * (1 - chosen_last / learnable):.0f} % below what any "
              "rate-independent model can reach there. Minor loops, which the goal names, are not in the "
              "record.\n")


def chosen_prediction(data, y_model, skip, delay, label, md, out):
    """measured_prediction.png: the chosen model (as `hyst fit --save` wrote
    it, fitted on the whole record) run by `hyst sim --model` over the
    record, against the measured output on the hold-out's rows (the last
    third). The record is sampled at 200 Hz."""
    n = len(data)
    if len(y_model) != n:
        sys.exit(f"report: hyst sim gave {len(y_model)} outputs for {n} rows")
    start = skip + 2 * (n - skip - delay) // 3
    rows = np.arange(start, n)
    t, ymeas, ymod = rows / 200.0, data[start:, 4], y_model[start:]
    rms = float(np.sqrt(np.mean((ymod - ymeas) ** 2)))
    fig, axs = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    axs[0].plot(t, ymeas, lw=2, label="measured")
    axs[0].plot(t, ymod, "--", lw=1, label=label)
    axs[0].set_ylabel("output (sensor units)")
    axs[0].legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)
    axs[1].plot(t, ymod - ymeas, lw=0.8)
    axs[1].set_ylabel("model − measured (sensor units)")
    axs[1].set_xlabel("time (s, 200 Hz rows)")
    axs[1].set_title(f"RMS {rms:.4g} on these rows", fontsize=9)
    md.append(f"The chosen model as `hyst fit --save` writes it (refitted on the whole record) and run by "
              f"`hyst sim --model` over the record, on the last third (rows {start}-{n - 1}): RMS "
              f"{fmt(rms)} sensor units.\n")
    md.append(f"![measured]({save(fig, out, 'measured_prediction.png')})\n")


def timing(path, md, out):
    """Fig. 8 analogue from bench/run's tcm_cost.csv (variant,kind,m,k,p,insns)."""
    rows = []
    with open(path, encoding="utf-8") as fh:
        header = fh.readline().strip().split(",")
        for line in fh:
            rec = dict(zip(header, line.strip().split(",")))
            rows.append(rec)
    worst, linear, typical = {}, {}, []
    for r in rows:
        p, n = int(r["p"]), int(r["insns"])
        if r["kind"].endswith(("typ_fall", "typ_rise")):
            if r["variant"] == "binary":  # the shipped engine, not the linear scan
                typical.append(n)
        elif "wipe" in r["kind"] and p > 0:
            table = worst if r["variant"] == "binary" else linear
            table[p] = max(table.get(p, 0), n)
    md.append("## Computation time per sample (Fig. 8 analogue)\n")
    md.append("Instructions executed on the Cortex-M4F between the rising and the falling edge of the timing "
              "pin (the FPGAIO LED register of mps2-an386) around one `hyst_step` call, counted exactly under "
              "QEMU by `tools/qemu_count.py` (a TCG plugin counts every instruction; same count on every run). p is the number of "
              "comparisons of the binary search; each point is the worst sample (a wipe-out) with that p. The "
              "paper's line, 0.19 p + 0.57 µs on a 150 MHz DSP28335, is drawn in cycles (28.5 p + 85.5); M4 "
              "instructions and C28x cycles are not the same unit: compare shape and order of magnitude.\n")
    ps = np.array(sorted(worst))
    ws = np.array([worst[p] for p in ps])
    a, b = np.polyfit(ps, ws, 1)
    md.append(f"| | paper (DSP28335, cycles) | hyst (Cortex-M4F, instructions) |\n|---|---|---|")
    md.append(f"| sample that passes no turning point | — | {max(typical) if typical else '?'} |")
    md.append(f"| worst sample, Nu = 4096 (p = {ps.max()}) | 28.5 × 12 + 85.5 = 427.5 (2.80 µs) | {ws.max()} |")
    md.append(f"| cost per comparison (fitted slope) | 28.5 | {a:.2f} |")
    md.append(f"| fixed cost (fitted intercept) | 85.5 | {b:.1f} |")
    if linear:
        md.append(f"| worst sample with a linear scan instead of the binary search | — | {max(linear.values())} |")
    md.append("")
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.plot(ps, ws, "o", label="hyst worst sample (binary search)")
    ax.plot(ps, a * ps + b, "k-", lw=1, label=f"fit: {a:.2f} p + {b:.1f}")
    pp = np.linspace(0, 12, 50)
    ax.plot(pp, 28.5 * pp + 85.5, "r:", label="paper: 150 MHz × (0.19 p + 0.57 µs)")
    ax.set_ylim(0, None)
    ax.set_xlabel("p (comparisons of the binary search)")
    ax.set_ylabel("M4 instructions / DSP cycles")
    ax.legend(fontsize=8)
    md.append(f"![timing]({save(fig, out, 'timing_vs_p.png')})\n")


def read_summary(path):
    vals = {}
    if path:
        with open(path, encoding="utf-8") as fh:
            for line in fh:
                parts = line.split()
                if len(parts) == 2 and not parts[0].startswith("#"):
                    vals[parts[0]] = parts[1]
    return vals


def per_core(b, md):
    """The per-core table (docs/timing.md's, from bench/run's keys)."""
    def g(key):
        return b.get(key, "")

    def pair(a, c):
        return f"{g(a)} / {g(c) or 'not modelled'}" if g(a) else ""
    ram = g("ram_12bit_bytes")
    rows = [
        ("Cortex-M0 (size only: no QEMU board)", "", "", "", "", g("m0_core_flash_Os"), "", ""),
        ("Cortex-M3, soft float", pair("m3_f32_typical_insns", "m3_f32_typical_cycles"),
         pair("m3_f32_worst_insns_nu4096", "m3_f32_worst_cycles_nu4096"), g("m3_f32_pi10_insns"),
         g("m3_f32_engine_flash_O2"), g("m3_f32_core_flash_Os"), ram, "libgcc helpers: not static"),
        ("Cortex-M3, q31 model", g("m3_q31_typical_insns"), g("m3_q31_worst_insns_nu4096"), "", "", "",
         "", ""),
        ("Cortex-M3, q31 compensator", g("m3_q31_inv_typical_insns"), g("m3_q31_inv_worst_insns_nu4096"),
         "", "", "", "", ""),
        ("Cortex-M4F", pair("tcm_typical_insns", "m4_typical_cycles"),
         pair("tcm_worst_clamped_insns_nu4096", "m4_worst_cycles_nu4096"), g("pi10_insns"),
         g("core_flash_bytes_O2_tcm"), g("core_flash_bytes_Os"), ram, g("step_stack_bytes")),
        ("Cortex-M7 (double FPU)", pair("m7_f32_typical_insns", "m7_f32_typical_cycles"),
         pair("m7_f32_worst_insns_nu4096", "m7_f32_worst_cycles_nu4096"), g("m7_f32_pi10_insns"),
         g("m7_f32_engine_flash_O2"), g("m7_f32_core_flash_Os"), "", g("m7_f32_step_stack_bytes")),
    ]
    md.append("Per core (float model unless stated, Nu = 4096 codes, cubic f0; instructions exact under QEMU, "
              "cycles from `tools/cycle_model.py` where it models the core; flash in bytes: the engine at -O2, "
              "the whole library at -Os; RAM: instance and the four TP arrays, float; stack: the deepest "
              "static path of the step; docs/timing.md):\n")
    md.append("| core | typical insns / cycles | worst insns / cycles | PI-10 insns | engine flash -O2 | "
              "library flash -Os | RAM | step stack |\n|---|---|---|---|---|---|---|---|")
    md.extend("| " + " | ".join(r) + " |" for r in rows)
    md.append("")


def bench_summary(path, md):
    rows = []
    with open(path, encoding="utf-8") as fh:
        for line in fh:
            parts = line.split()
            if len(parts) == 2:
                rows.append(parts)
    if rows:
        b = dict(rows)
        title = "Per-sample cost on the Cortex-M4F (exact instruction counts under QEMU)"
        say(title, f"hyst_step: typical {b.get('tcm_typical_insns', '?')} instructions, worst at "
                   f"Nu = 4096 {b.get('tcm_worst_clamped_insns_nu4096', '?')}; PI-10 "
                   f"{b.get('pi10_insns', '?')}")
        say(title, f"library flash {b.get('core_flash_bytes_Os', '?')} bytes at -Os, engine "
                   f"{b.get('core_flash_bytes_O2_tcm', '?')} bytes at -O2; step stack "
                   f"{b.get('step_stack_bytes', '?')} bytes")
        cores = "Per-sample cost on the other cores (instructions, typical / worst at Nu = 4096)"
        for label, prefix in (("Cortex-M3, soft float", "m3_f32"), ("Cortex-M3, q31 model", "m3_q31"),
                              ("Cortex-M3, q31 compensator", "m3_q31_inv"),
                              ("Cortex-M7, double FPU", "m7_f32")):
            if f"{prefix}_typical_insns" in b:
                say(cores, f"{label}: {b[prefix + '_typical_insns']} / "
                           f"{b.get(prefix + '_worst_insns_nu4096', '?')}")
        per_core(b, md)
        md.append("Benchmark summary (`bench/run`):\n")
        md.append("| key | value |\n|---|---|")
        md.extend(f"| `{k}` | {v} |" for k, v in rows)
        md.append("")


def memory(sec, md, bench):
    t = sec["tables"]["ram"]
    paper = {12: "16 KB", 16: "256 KB", 18: "1.5 MB", 24: "96 MB"}
    # The instance as a firmware build lays it out (bench/run: default options, no f64 variant on
    # the M4F); the report's own build carries the test suite's f64 variant, a larger instance.
    inst = int(bench.get("sizeof_hyst_t", sec["values"]["instance_bytes"]))
    md.append("## Memory (Table 2 analogue)\n")
    say("Memory (Table 2 analogue)",
        f"instance {int(sec['values']['instance_bytes'])} bytes + 4 arrays of Nu/2 entries x "
        f"{int(sec['values']['real_bytes'])} bytes; at 12 bits {int(t['data'][0][3]):,} bytes")
    md.append(f"One instance with arrays for Nu = 2^bits codes: 4 arrays × Nu/2 entries × "
              f"{int(sec['values']['real_bytes'])} bytes + {inst} bytes of "
              "instance. (The paper's table corresponds to 8 bytes per entry position at 12 and 16 bits and "
              "12 bytes at 18 and 24 bits; hyst keeps x and y of an LTP and of an RTP at each position: 16 "
              "bytes in float, less with the integer-code variant.)\n")
    md.append("| resolution | Nu | entries per array | hyst (bytes) | paper |\n|---|---|---|---|---|")
    for row in t["data"]:
        bits, nu, entries, nbytes = (int(v) for v in row)
        nbytes = int(bench.get(f"ram_{bits}bit_bytes", nbytes))
        md.append(f"| {bits}-bit | {nu} | {entries} | {nbytes:,} | {paper.get(bits, '')} |")
    md.append("")
    if "mem16_ram_bytes" in bench:
        md.append("Beyond the paper (its stated future work): with bounded memory (`docs/memory.md`: 32 entries "
                  "per array, 16-bit integer codes, forgotten loops merged continuously with a stated error "
                  f"bound) one instance takes **{bench['mem16_ram_bytes']} bytes** on the Cortex-M4, and its "
                  "largest deviation from the unbounded model is "
                  f"{bench['mem16_max_err_pct_paper']} % of the output range on the paper's test signal and "
                  f"{bench['mem16_max_err_pct_measured']} % on the measured data's input.\n")


def compensation(sec, md, out):
    v = sec["values"]
    md.append("## Feedforward compensation\n")
    md.append("The Bouc–Wen plant of the experiment (not a TCM) follows a desired displacement shaped like the "
              "paper's test signal, 5–95 % of the stroke, driven (a) open loop by a linear scaling of the major "
              "loop's end points and (b) through the inverse TCM of the f0 identified above (same engine, "
              "curve f0⁻¹ tabulated as monotone cubic pieces, `HYST_INIT_INVERSE`), computed on the target. "
              "Errors in µm.\n")
    md.append("| | RMS error | max error |\n|---|---|---|")
    md.append(f"| open loop (linear scaling) | {fmt(v['open_rms'])} | {fmt(v['open_max'])} |")
    md.append(f"| inverse TCM | {fmt(v['comp_rms'])} | {fmt(v['comp_max'])} |")
    md.append(f"\nThe inverse reduces the RMS tracking error {v['open_rms'] / v['comp_rms']:.1f}-fold "
              f"(Bouc–Wen plant; `comp_rms_ratio` is the asymmetric plant's, below). Along full major loops only, the same compensator reduces it "
              f"{v['major_open_rms'] / v['major_comp_rms']:.1f}-fold (RMS {fmt(v['major_comp_rms'])} vs "
              f"{fmt(v['major_open_rms'])}): f0 fits the plant's major loop; what limits the test signal "
              "is its minor loops, which the Bouc–Wen plant does not close (no wiping-out property), so "
              "no TCM, whatever its f0, follows them.\n")
    t = sec["tables"].get("tracking")
    if t is not None and len(t["data"]):
        fig, ax = plt.subplots(figsize=(7, 4))
        i = col(t, "i")
        ax.plot(i, col(t, "y_open") - col(t, "y_ref"), label="open loop")
        ax.plot(i, col(t, "y_comp") - col(t, "y_ref"), label="inverse TCM")
        ax.set_xlabel("sample")
        ax.set_ylabel("tracking error (µm)")
        ax.legend()
        md.append(f"![compensation]({save(fig, out, 'compensation.png')})\n")
    say("Compensation of the Bouc-Wen plant",
        f"RMS tracking error {fmt(v['comp_rms'])} um with the inverse TCM, {fmt(v['open_rms'])} um "
        f"open loop: {v['open_rms'] / v['comp_rms']:.1f}-fold lower")


def asymmetric(sec, md, out):
    v = sec["values"]
    md.append("## Asymmetric plant with a lagging sensor\n")
    md.append("A plant that is not a TCM (`examples/common/plant_everett.c`): Madelung's rules with a "
              "non-polynomial, non-separable branch function whose loops grow with their centre (rising and "
              "falling branches are not point reflections), read through a first-order sensor lag of 3 "
              "samples, noise 0.1 % of the range. Identified on the target from 6 major loops (the first "
              "dropped): the symmetric TCM's degree and delay chosen by hold-out (fit on two thirds, score "
              "the prediction of the last third, the fewest parameters within 1 % of the best), PI-10's "
              "weights by non-negative least squares at the same delay. Then both predict the sensor's "
              "reading of the paper's test signal (delay applied). Errors in µm.\n")
    md.append("| model | parameters | hold-out RMS | test signal RMS | test signal max |\n|---|---|---|---|---|")
    md.append(f"| symmetric TCM, degree {int(v['tcm_degree'])}, delay {int(v['tcm_delay'])} | "
              f"{int(v['tcm_params'])} | {fmt(v['tcm_holdout_rms'])} | {fmt(v['tcm_predict_rms'])} | "
              f"{fmt(v['tcm_predict_max'])} |")
    md.append(f"| PI-10 (NNLS) | {int(v['pi_params'])} | {fmt(v['pi_holdout_rms'])} | "
              f"{fmt(v['pi_predict_rms'])} | {fmt(v['pi_predict_max'])} |")
    if "everett_degree" in v:
        md.append(f"| asymmetric TCM, degree {int(v['everett_degree'])} in the width, "
                  f"{int(v.get('everett_t_degree', v['everett_degree'] - 1))} in the lower end (E fitted by "
                  f"`hyst_everett_fit_*`) | {int(v['everett_params'])} | {fmt(v['everett_holdout_rms'])} | "
                  f"{fmt(v['everett_predict_rms'])} | {fmt(v['everett_predict_max'])} |")
    md.append("")
    if "everett_degree" in v:
        md.append("The asymmetric kind (docs/theory.md), chosen by the same hold-out rule among E of degree "
                  "1-4 in the loop's width and 0 to that minus one in its lower end t (a record of major loops "
                  "sees E on two edges of its triangle only: E of full total degree 3 or 4 is singular there, "
                  "E linear in t is not), predicts the test signal "
                  f"{v['pi_predict_rms'] / v['everett_predict_rms']:.1f} times better than PI-10 (RMS) with "
                  f"{int(v['everett_params'])} parameters against {int(v['pi_params'])}." +
                  (f" The best candidate of at most 6 parameters (degree {int(v['everett6_degree'])}, "
                   f"{int(v['everett6_t_degree'])} in t) scores {fmt(v['everett6_holdout_rms'])} on the "
                   f"hold-out, {v['pi_holdout_rms'] / v['everett6_holdout_rms']:.1f} times better than PI-10's "
                   f"{fmt(v['pi_holdout_rms'])}." if "everett6_holdout_rms" in v else "") + "\n")
    md.append("The symmetric TCM and PI-10 are both point-symmetric (rule 4), so neither can follow the plant's "
              "asymmetry: that, not their parameter count, bounds their error here.\n")
    title = "Asymmetric plant with a lagging sensor"
    t = sec["tables"].get("prediction")
    if "everett_degree" in v:
        say(title, f"prediction RMS: asymmetric TCM {fmt(v['everett_predict_rms'])} um, PI-10 "
                   f"{fmt(v['pi_predict_rms'])} um: {v['pi_predict_rms'] / v['everett_predict_rms']:.1f} "
                   f"times better ({int(v['everett_params'])} parameters against {int(v['pi_params'])})")
        if t is not None and len(t["data"]) and "y_everett" in t["cols"]:
            i, ys = col(t, "i"), col(t, "y_sensor")
            fig, ax = plt.subplots(figsize=(7, 4))
            for key, label, style in (("y_pi", "PI-10", "-"), ("y_tcm", "symmetric TCM", "-"),
                                      ("y_everett", "asymmetric TCM", "-")):
                err = col(t, key) - ys
                ax.plot(i, err, style, lw=0.9,
                        label=f"{label}: RMS {np.sqrt(np.mean(err ** 2)):.3g} µm")
            ax.set_xlabel("sample (test signal)")
            ax.set_ylabel("prediction − sensor (µm)")
            ax.set_title(f"asymmetric TCM {v['pi_predict_rms'] / v['everett_predict_rms']:.1f} times "
                         "lower RMS than PI-10", fontsize=9)
            ax.legend(fontsize=8, loc="lower center")
            md.append(f"![prediction errors on the asymmetric plant]"
                      f"({save(fig, out, 'asymmetric_error.png')})\n")
    if "symmetric_comp_rms_ratio" in v:
        md.append("Compensation of the actuator along the test signal's shape (5-95 % of the stroke), RMS "
                  "tracking error in µm, open loop = linear scaling of the desired output onto the drive:\n")
        md.append("| compensator | RMS | max | open-loop RMS | RMS reduction | along major loops |\n"
                  "|---|---|---|---|---|---|")
        md.append(f"| inverse of the symmetric TCM | {fmt(v['symmetric_comp_rms'])} | "
                  f"{fmt(v['symmetric_comp_max'])} | {fmt(v['symmetric_open_rms'])} | "
                  f"{v['symmetric_comp_rms_ratio']:.2f} | "
                  f"{v['symmetric_major_open_rms'] / v['symmetric_major_comp_rms']:.1f} |")
        md.append(f"| inverse of the asymmetric TCM (`hyst_curve_inverse()`) | {fmt(v['comp_rms'])} | "
                  f"{fmt(v['comp_max'])} | {fmt(v['open_rms'])} | **comp_rms_ratio "
                  f"{v['comp_rms_ratio']:.2f}** | {v['major_open_rms'] / v['major_comp_rms']:.1f} |" +
                  (f"\n| the same, tabulated as firmware runs it (`hyst_curve_everett_inverse_table()`, "
                   f"default table; init measured {v['table_inverse_error']:.2g} of the drive range) | "
                   f"{fmt(v['table_comp_rms'])} | {fmt(v['table_comp_max'])} | {fmt(v['table_open_rms'])} | "
                   f"comp_table_rms_ratio {v['comp_table_rms_ratio']:.2f} | |" if "comp_table_rms_ratio" in v
                   else "") +
                  (f"\n| identified directly, axes swapped: a forward asymmetric TCM from the reading to the "
                   f"drive (E of degree {int(v['direct_degree'])}, {int(v['direct_t_degree'])} in t, "
                   f"{int(v['direct_params'])} parameters; hold-out {fmt(v['direct_holdout_rms'])} V), at the "
                   f"forward kind's cost per sample | {fmt(v['direct_comp_rms'])} | "
                   f"{fmt(v['direct_comp_max'])} | {fmt(v['direct_open_rms'])} | "
                   f"comp_direct_rms_ratio {v['comp_direct_rms_ratio']:.2f} | |" if "comp_direct_rms_ratio" in v
                   else "") + "\n")
        md.append("The symmetric compensator is limited by its model's symmetry (its major loop is "
                  "point-symmetric, the plant's is not). The asymmetric one inverts a model whose hold-out "
                  "error is at the noise level, faithfully (`tests/test_everett_inverse.c`): what remains is "
                  "the plant's non-polynomial E between the record's loops." +
                  (" The directly identified compensator costs what the forward model costs per sample "
                   "(docs/timing.md) but fits its E to noisy readings as inputs: half the reduction of the "
                   "model's exact or tabulated inverse." if "comp_direct_rms_ratio" in v else "") + "\n")
        say(title, f"compensation: RMS tracking error {fmt(v['comp_rms'])} um through the asymmetric TCM's "
                   f"inverse, {fmt(v['open_rms'])} um open loop: {v['comp_rms_ratio']:.1f}-fold lower "
                   f"(symmetric TCM's inverse: {v['symmetric_comp_rms_ratio']:.2f}-fold)")
        tr = sec["tables"].get("tracking")
        if tr is not None and len(tr["data"]):
            i, ref = col(tr, "i"), col(tr, "y_ref")
            fig, ax = plt.subplots(figsize=(7, 4))
            ax.plot(i, col(tr, "y_open") - ref, lw=0.9,
                    label=f"open loop (linear scaling): RMS {v['open_rms']:.3g} µm")
            ax.plot(i, col(tr, "y_comp") - ref, lw=0.9,
                    label=f"inverse of the asymmetric TCM: RMS {v['comp_rms']:.3g} µm")
            ax.set_xlabel("sample (test signal)")
            ax.set_ylabel("tracking error (µm)")
            ax.set_title(f"RMS tracking error {v['comp_rms_ratio']:.1f}-fold lower (comp_rms_ratio)",
                         fontsize=9)
            ax.legend(fontsize=8, loc="lower right")
            md.append(f"![compensation of the asymmetric plant]"
                      f"({save(fig, out, 'asymmetric_compensation.png')})\n")
    if t is not None and len(t["data"]):
        fig, ax = plt.subplots(figsize=(7, 4))
        x = col(t, "x_V")
        ax.plot(x, col(t, "y_sensor"), lw=2.5, label="plant (sensor)")
        ax.plot(x, col(t, "y_tcm"), lw=1, label="symmetric TCM")
        ax.plot(x, col(t, "y_pi"), lw=1, ls="--", label="PI-10")
        if "y_everett" in t["cols"]:
            ax.plot(x, col(t, "y_everett"), lw=1, ls=":", label="asymmetric TCM")
        ax.set_xlabel("input (V)")
        ax.set_ylabel("output (µm)")
        ax.legend()
        md.append(f"![asymmetric plant]({save(fig, out, 'asymmetric.png')})\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("firmware_output")
    ap.add_argument("out_dir")
    ap.add_argument("--timing", help="CSV of instruction counts vs p")
    ap.add_argument("--bench", help="bench/run summary (key value lines)")
    ap.add_argument("--measured-fit", help="hyst fit's printout on the measured record (host tool)")
    ap.add_argument("--measured-data", help="the measured record (tests/data/piezo_major_loop.dat)")
    ap.add_argument("--console", choices=("all", "bench", "none"), default="all",
                    help="headline figures printed: all, the per-sample cost's only, none")
    ap.add_argument("--measured-model-output",
                    help="hyst sim --model's outputs of the chosen model over the measured record")
    ap.add_argument("--fidelity", help="bench/fidelity's section (other people's actuators)")
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    meta, secs = parse(args.firmware_output)
    md = ["# hyst: the paper's results reproduced on an emulated Cortex-M4F\n",
          "K. Chen, R. Li et al., *Sensors* 2019, 19, 352. Every number below was computed by the firmware "
          f"`examples/paper_report.c` ({meta.get('report', '')}) running in `qemu-system-arm -M mps2-an386`; "
          "the host only drew the figures (`tools/report.py`), but for the section on `hyst fit`, the host "
          "tool itself. Regenerate with `./tools/demo`.\n"]
    renderers = [("example1", lambda s: example1(s, md)), ("example2", lambda s: example2(s, md, args.out_dir)),
                 ("experiment", lambda s: experiment(s, md, args.out_dir)),
                 ("measured", lambda s: measured(s, md, args.out_dir))]
    for name, fn in renderers:
        if name in secs:
            fn(secs[name])
    if args.measured_fit and args.measured_data:
        measured_choice(args.measured_fit, args.measured_data, md, args.out_dir,
                        args.measured_model_output)
    if args.fidelity and os.path.exists(args.fidelity):
        with open(args.fidelity, encoding="utf-8") as fh:
            md.append(fh.read())
    if args.timing:
        timing(args.timing, md, args.out_dir)
    else:
        md.append("## Computation time per sample\n")
        md.append("Not measured in this run: `./tools/demo` writes the report first, then measures the "
                  "per-sample cost (`bench/run`) and writes it again with it.\n")
    if args.bench:
        bench_summary(args.bench, md)
    if "memory" in secs:
        memory(secs["memory"], md, read_summary(args.bench))
    if "compensation" in secs:
        compensation(secs["compensation"], md, args.out_dir)
    if "asymmetric" in secs:
        asymmetric(secs["asymmetric"], md, args.out_dir)
    failures = meta.get("failures", "?")
    md.append(f"---\nChecks that failed on the target: {failures}.\n")
    with open(os.path.join(args.out_dir, "README.md"), "w", encoding="utf-8") as fh:
        fh.write("\n".join(md) + "\n")
    for title, lines in CONSOLE:
        if args.console == "none" or (args.console == "bench" and not title.startswith("Per-sample")):
            continue
        print(f"  {title}")
        for line in lines:
            print(f"    {line}")
    print(f"  checks that failed on the target: {failures}")
    print(f"report: {os.path.join(args.out_dir, 'README.md')}")
    return 0 if failures == "0" else 1


if __name__ == "__main__":
    sys.exit(main())
