# SPDX-License-Identifier: MIT
"""python -m hyst plot: look at a model against a measured record without
writing code: the loop, prediction vs measurement, the error, and the
compensator's drive for the measured output.

  python -m hyst plot DATA --model M.hyst [--xcol I] [--ycol J] [--skip S]
                     [--out FIG.png]

DATA: columns separated by blanks, ',' or ';' ('#' lines skipped), as the
hyst tool reads them; M.hyst: a model file (hyst fit --save, hyst.save_model).
The model runs in double from rest (A0) over the inputs after --skip, with
the file's delay applied to the comparison; the compensator (the inverse
model, of either kind) is driven by the measured outputs, and its drive is
drawn against the drive that was applied. Prints the RMS and max error, and
the RMS of the compensator's drive minus the applied drive."""
import argparse
import sys

import numpy as np

from ._api import compensator_from, model_from
from ._model_file import load_model
from ._plot import _pyplot


def _plot(argv):
    ap = argparse.ArgumentParser(prog="python -m hyst plot", description=__doc__.split("\n")[0])
    ap.add_argument("data")
    ap.add_argument("--model", required=True)
    ap.add_argument("--xcol", type=int, default=1)
    ap.add_argument("--ycol", type=int, default=2)
    ap.add_argument("--skip", type=int, default=0)
    ap.add_argument("--out", default="hyst_plot.png")
    a = ap.parse_args(argv)
    m = load_model(a.model)
    rows = np.loadtxt(a.data, comments="#", delimiter=None, ndmin=2,
                      converters=None, usecols=(a.xcol - 1, a.ycol - 1))
    x, y = rows[a.skip:, 0], rows[a.skip:, 1]
    d = int(m["delay"])
    f = m["delay"] - d  # a sub-sample delay: the model's input interpolated
    if f > 0:
        x = np.concatenate([x[:1], (1 - f) * x[1:] + f * x[:-1]])
    n = len(x) - d
    if n < 2:
        sys.exit(f"python -m hyst plot: {a.data}: fewer than 2 samples after --skip and the delay")
    pred = model_from(m, capacity=n // 2 + 2).process(np.ascontiguousarray(x[:n]))
    meas = y[d:d + n]
    err = pred - meas
    drive = compensator_from(m, capacity=n // 2 + 2).process(np.ascontiguousarray(meas))
    drive_rms = float(np.sqrt(np.mean((drive - x[:n]) ** 2)))
    plt = _pyplot()
    fig, ax = plt.subplots(2, 2, figsize=(11, 7))
    ax[0, 0].plot(x[:n], meas, ".", ms=2, color="0.6", label="measured")
    ax[0, 0].plot(x[:n], pred, lw=1, label="model")
    ax[0, 0].set(xlabel="input", ylabel="output", title="hysteresis loop")
    ax[0, 0].legend(loc="best")
    k = np.arange(n)
    ax[0, 1].plot(k, meas, color="0.6", lw=1, label="measured")
    ax[0, 1].plot(k, pred, lw=1, label="model")
    ax[0, 1].set(xlabel="sample", ylabel="output", title=f"prediction (delay {d} samples)")
    ax[0, 1].legend(loc="best")
    rms, peak = float(np.sqrt(np.mean(err ** 2))), float(np.max(np.abs(err)))
    ax[1, 0].plot(k, err, lw=1, color="C3")
    ax[1, 0].set(xlabel="sample", ylabel="model - measured",
                 title=f"error: RMS {rms:.4g}, max {peak:.4g}")
    ax[1, 1].plot(k, x[:n], color="0.6", lw=1, label="drive applied")
    ax[1, 1].plot(k, drive, lw=1, label="compensator's drive for the measured output")
    ax[1, 1].set(xlabel="sample", ylabel="input",
                 title=f"compensator ({m['kind']}): drive - applied RMS {drive_rms:.4g}")
    ax[1, 1].legend(loc="best")
    fig.tight_layout()
    fig.savefig(a.out)
    print(f"{a.out}: {n} samples, error RMS {rms:.6g}, max {peak:.6g}, "
          f"compensator's drive - applied RMS {drive_rms:.6g}")
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "plot":
        sys.exit("usage: python -m hyst plot DATA --model M.hyst [--xcol I] [--ycol J] "
                 "[--skip S] [--out FIG.png]")
    return _plot(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
