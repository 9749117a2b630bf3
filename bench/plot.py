#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""cost_vs_p.png from tcm_cost.csv (the analogue of the paper's Fig. 8).

  plot.py tcm_cost.csv out.png FIT_SLOPE FIT_CONST PI10_INSNS TYPICAL_INSNS

Left: instructions per sample vs comparisons p of the binary search, every
wipe-out sample measured, with the fitted line. Right: the deepest wipe-out
(worst of the two deepest targets) vs m, binary and linear search, with PI-10 and the typical sample.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    src, dst = sys.argv[1], sys.argv[2]
    a, c, pi10, typ = (float(v) for v in sys.argv[3:7])
    rows = list(csv.DictReader(open(src)))
    for r in rows:
        for k in ("m", "k", "p", "insns"):
            r[k] = int(r[k])
    wipe = ("wipe_fall", "wipe_rise", "wipe_revfall", "wipe_revrise")

    def base(kind):
        return kind.split("_", 1)[1] if kind.startswith(("exh_", "show_")) else kind

    # Interior targets only (k >= 1): at lo or hi an engine may skip the search.
    b = [r for r in rows if r["variant"] == "binary" and base(r["kind"]) in wipe and r["k"] >= 1]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.8))
    ax1.scatter([r["p"] for r in b], [r["insns"] for r in b], s=10, alpha=0.4,
                label="wipe-out samples, k >= 1 (%d)" % len(b))
    ps = sorted({r["p"] for r in b})
    ax1.plot([0] + ps, [c] + [a * p + c for p in ps], "r-",
             label="fit: %.1f p + %.1f" % (a, c))
    ax1.axhline(150, color="k", ls="--", lw=1, label="budget 150")
    ax1.axhline(typ, color="g", ls=":", lw=1, label="typical sample (%d)" % typ)
    ax1.set_xlabel("p (comparisons in the binary search)")
    ax1.set_ylabel("instructions per sample (Cortex-M4F)")
    ax1.set_title("TCM per-sample cost vs p, Nu = 4096")
    ax1.legend(fontsize=8)
    ax1.grid(alpha=0.3)

    for variant, style in (("binary", "b."), ("linear", "m.")):
        worst = {}
        for r in rows:
            if r["variant"] == variant and r["kind"] in wipe:
                worst[r["m"]] = max(worst.get(r["m"], 0), r["insns"])
        d = sorted(worst.items())
        ax2.plot([m for m, _ in d], [i for _, i in d], style, ms=3,
                 label="worst wipe-out, %s search" % variant)
    ax2.axhline(pi10, color="orange", lw=1, label="PI-10 (%d)" % pi10)
    ax2.axhline(typ, color="g", ls=":", lw=1, label="TCM typical (%d)" % typ)
    ax2.axhline(150, color="k", ls="--", lw=1, label="budget 150")
    ax2.set_xscale("log", base=2)
    ax2.set_yscale("log")
    ax2.set_xlabel("m (turning points in the searched array)")
    ax2.set_ylabel("instructions per sample")
    ax2.set_title("What the binary search buys")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(dst, dpi=110)


if __name__ == "__main__":
    main()
