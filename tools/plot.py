#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Pictures of an identification made with the `hyst` tool (PNG files).

Reads the measured record, the output of `hyst fit` (coefficients on line 1,
lo,hi on line 2) and the output of `hyst sim --tp` over the record's inputs
from row --skip on, and draws:

  loop.png        the measured loop, the fitted f0 and its reflected falling
                  branch f0(lo) + f0(hi) - f0(lo + hi - x)
  prediction.png  prediction vs measurement over time
  error.png       prediction error over time
  tp.png          turning-point count over time

Example (docs/identification.md):
  hyst fit --degree 3 --skip 350 --delay 1 --ycol 5 data.dat > fit.txt
  tail -n +351 data.dat | hyst sim --poly "$(head -1 fit.txt)" \
      --range "$(sed -n 2p fit.txt)" --tp > sim.csv
  tools/plot.py --data data.dat --ycol 5 --skip 350 --delay 1 \
      --fit fit.txt --sim sim.csv --out build/report

numpy and matplotlib come from tools/pyenv.sh (a venv under build/, from
PyPI, made on first use) when this Python lacks them. Neither the C build nor the tests need this script.
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def ensure_packages():
    """Re-runs this script with tools/pyenv.sh's Python (numpy + matplotlib) if needed."""
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
        return
    except ImportError:
        pass
    if os.environ.get("HYST_PLOT_VENV") == "1":
        sys.exit("plot.py: numpy/matplotlib still missing in the Python of tools/pyenv.sh")
    py = subprocess.check_output(["bash", os.path.join(ROOT, "tools", "pyenv.sh")], text=True).strip()
    env = dict(os.environ, HYST_PLOT_VENV="1")
    os.execve(py, [py, os.path.abspath(__file__)] + sys.argv[1:], env)


SPLIT = re.compile(r"\s*[,;]\s*|\s+")


def read_columns(path, cols):
    """Columns (1-based) of the data lines of path, as the `hyst` tool reads them."""
    out = [[] for _ in cols]
    with open(path) as f:
        for lineno, line in enumerate(f, 1):
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            fields = SPLIT.split(s)
            for k, c in enumerate(cols):
                if c > len(fields):
                    sys.exit(f"plot.py: {path}:{lineno}: field {c} is missing")
                try:
                    out[k].append(float(fields[c - 1]))
                except ValueError:
                    sys.exit(f"plot.py: {path}:{lineno}: field {c}: '{fields[c - 1]}' is not a number")
    return out


def read_fit(path):
    with open(path) as f:
        lines = [l.strip() for l in f if l.strip() and not l.startswith("#")]
    coeffs = [float(v) for v in lines[0].split(",")]
    lo, hi = (float(v) for v in lines[1].split(","))
    return coeffs, lo, hi


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--data", required=True, help="measured record")
    p.add_argument("--xcol", type=int, default=1, help="input column (1-based, default 1)")
    p.add_argument("--ycol", type=int, default=2, help="output column (1-based, default 2)")
    p.add_argument("--skip", type=int, default=0, help="rows skipped before --sim's inputs")
    p.add_argument("--delay", type=int, default=0, help="output lag in samples")
    p.add_argument("--fit", required=True, help="output of hyst fit")
    p.add_argument("--sim", required=True, help="output of hyst sim --tp from row --skip on")
    p.add_argument("--mark", type=int, default=None,
                   help="sample (after --skip) where the fitted part ends, drawn as a line")
    p.add_argument("--rate", type=float, default=None, help="sampling rate in Hz (time in s)")
    p.add_argument("--title", default="", help="prefix of the plot titles")
    p.add_argument("--out", required=True, help="output folder for the PNG files")
    a = p.parse_args()

    ensure_packages()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    x_all, y_all = (np.array(c) for c in read_columns(a.data, [a.xcol, a.ycol]))
    sim = np.loadtxt(a.sim, delimiter=",", ndmin=2)
    pred, tp = sim[:, 0], sim[:, 1] if sim.shape[1] > 1 else np.zeros(len(sim))
    coeffs, lo, hi = read_fit(a.fit)

    n = min(len(pred), len(x_all) - a.skip - a.delay)
    x = x_all[a.skip:a.skip + n]
    y = y_all[a.skip + a.delay:a.skip + a.delay + n]
    pred, tp = pred[:n], tp[:n]
    err = pred - y
    t = np.arange(n) / a.rate if a.rate else np.arange(n)
    tlabel = "time (s)" if a.rate else "sample"
    os.makedirs(a.out, exist_ok=True)
    title = (a.title + ": ") if a.title else ""

    def mark(ax):
        if a.mark is not None:
            ax.axvline(t[min(a.mark, n - 1)], color="k", ls=":", lw=1,
                       label="end of the fitted part")

    xs = np.linspace(lo, hi, 400)
    f0 = np.polyval(coeffs, xs)
    f_lo, f_hi = np.polyval(coeffs, [lo, hi])
    fall = f_lo + f_hi - np.polyval(coeffs, lo + hi - xs)
    fig, ax = plt.subplots(figsize=(7, 5))
    ax.plot(x, y, ".", ms=2, color="0.6", label="measured")
    ax.plot(xs, f0, "-", color="C0", lw=2, label="fitted f0 (rising)")
    ax.plot(xs, fall, "-", color="C3", lw=2, label="reflected falling branch")
    ax.set_xlabel("input x")
    ax.set_ylabel("output y")
    ax.set_title(title + "major loop, degree %d fit" % (len(coeffs) - 1))
    ax.legend()
    ax.grid(alpha=0.3)
    files = [os.path.join(a.out, "loop.png")]
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(10, 4))
    ax.plot(t, y, "-", color="0.5", lw=1, label="measured")
    ax.plot(t, pred, "-", color="C0", lw=1, label="model prediction")
    mark(ax)
    ax.set_xlabel(tlabel)
    ax.set_ylabel("output y")
    ax.set_title(title + "prediction vs measurement")
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    files.append(os.path.join(a.out, "prediction.png"))
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(10, 3.5))
    ax.plot(t, err, "-", color="C3", lw=1)
    mark(ax)
    ax.set_xlabel(tlabel)
    ax.set_ylabel("prediction - measured")
    rms = float(np.sqrt(np.mean(err ** 2)))
    ax.set_title(title + "error: RMS %.3g, max |e| %.3g" % (rms, float(np.max(np.abs(err)))))
    ax.grid(alpha=0.3)
    files.append(os.path.join(a.out, "error.png"))
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(10, 3))
    ax.step(t, tp, where="post", color="C2")
    mark(ax)
    ax.set_xlabel(tlabel)
    ax.set_ylabel("turning points")
    ax.set_title(title + "turning points in memory")
    ax.grid(alpha=0.3)
    files.append(os.path.join(a.out, "tp.png"))
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)

    for f in files:
        print(f)


if __name__ == "__main__":
    main()
