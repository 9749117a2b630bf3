# SPDX-License-Identifier: MIT
"""The piecewise-linear curve kind from Python (ModelFromPoints): bit for bit
the C library's hyst_f64_curve_from_pwl + hyst_f64_init_curve, its
compensator undoes it, and bad points raise with the library's status."""
import os
import subprocess

import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, signal

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")

RUN_PWL_C = r"""
#include <stdio.h>
#include "hyst/hyst.h"
static double px[256], py[256], xl[2048], yl[2048], xr[2048], yr[2048];
int main(int argc, char **argv)
{
    hyst_curve_t c;
    hyst_t S;
    size_t n = 0;
    double x;
    FILE *pts = fopen(argv[1], "r"), *in = fopen(argv[2], "r");
    (void)argc;
    while (n < 256 && fscanf(pts, "%lf %lf", &px[n], &py[n]) == 2) {
        ++n;
    }
    if (hyst_f64_curve_from_pwl(&c, px, py, n) != HYST_OK ||
        hyst_f64_init_curve(&S, &c, xl, yl, xr, yr, 2048) != HYST_OK) {
        return 1;
    }
    while (fscanf(in, "%lf", &x) == 1) {
        printf("%.17g\n", hyst_f64_step(&S, x));
    }
    return 0;
}
"""


def test_pwl_model_is_the_c_library(tmp_path):
    xs = np.linspace(0.0, 40.0, 81)
    ys = np.polyval(PAPER_F0, xs)
    x = signal(3000, 0.0, 40.0, seed=5, outside=False)
    m = hyst.ModelFromPoints(xs, ys)
    y = m.process(x)
    np.savetxt(tmp_path / "pts.txt", np.column_stack([xs, ys]), fmt="%.17g")
    np.savetxt(tmp_path / "x.txt", x, fmt="%.17g")
    (tmp_path / "run.c").write_text(RUN_PWL_C)
    srcs = sorted(os.path.join(ROOT, "src", s) for s in os.listdir(os.path.join(ROOT, "src"))
                  if s.endswith(".c"))
    exe = tmp_path / "run"
    subprocess.run(["cc", "-std=c99", "-O2", "-I", os.path.join(ROOT, "include"),
                    str(tmp_path / "run.c"), *srcs, "-lm", "-o", str(exe)], check=True)
    out = subprocess.run([str(exe), str(tmp_path / "pts.txt"), str(tmp_path / "x.txt")],
                         check=True, capture_output=True, text=True).stdout.split()
    assert np.array_equal(np.array([float(v) for v in out]), y)  # bit for bit
    # close to the polynomial model it samples (interpolation error only)
    p = hyst.Model(PAPER_F0, 0.0, 40.0).process(x)
    assert np.max(np.abs(p - y)) < 2e-3 * (ys[-1] - ys[0])


def test_pwl_compensator_undoes_the_model():
    xs = np.linspace(0.0, 40.0, 41)
    ys = np.polyval(PAPER_F0, xs)
    x = signal(2000, 0.0, 40.0, seed=9, outside=False)
    y = hyst.ModelFromPoints(xs, ys).process(x)
    back = hyst.ModelFromPoints(xs, ys, inverse=True).process(y)
    assert np.max(np.abs(back - x)) < 1e-9 * 40.0


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_pwl_errors(dtype):
    with pytest.raises(hyst.HystError) as e:
        hyst.ModelFromPoints([0.0, 1.0, 1.0], [0.0, 1.0, 2.0], dtype=dtype)
    assert e.value.status == hyst.Status.ERR_BREAKPOINTS
    with pytest.raises(hyst.HystError) as e:
        hyst.ModelFromPoints([0.0, 1.0], [0.0], dtype=dtype)
    assert e.value.status == hyst.Status.ERR_ARG
