# SPDX-License-Identifier: MIT
"""The package computes what the C library computes, bit for bit: against
hyst_ref (the library's block calls in a C program) on raw arrays, and
against the `hyst` tool's text output."""
import subprocess

import numpy as np
import pytest

import hyst
from conftest import DATA, PAPER_F0, same_bits, signal

N = 20000


@pytest.mark.parametrize("dtype,ctype", [(np.float64, "f64"), (np.float32, "f32")])
@pytest.mark.parametrize("kind", ["sim", "inv"])
@pytest.mark.parametrize("capacity,deadband", [(2048, 0.0), (3, 0.0), (2048, 0.3), (3, 0.3)])
def test_model_and_compensator_match_c(run_ref, dtype, ctype, kind, capacity, deadband):
    lo, hi = (0.0, 40.0) if kind == "sim" else (0.58517, 5.5587636)
    x = signal(N, lo, hi, nonfinite=True).astype(dtype)
    make = hyst.Model if kind == "sim" else hyst.Compensator
    m = make(PAPER_F0, 0, 40, dtype=dtype, capacity=capacity)
    m.deadband = deadband
    y = m.process(x)
    y_c, status_c, snap_c = run_ref(kind, x, dtype, type=ctype, lo=0.0, hi=40.0,
                                    coeffs=PAPER_F0, cap=capacity, deadband=deadband)
    assert y.dtype == dtype
    assert same_bits(y, y_c)
    assert m.block_status == status_c
    assert m.save() == snap_c
    # the per-sample call gives the same outputs as the block call
    m.reset()
    assert same_bits(np.array([m.step(v) for v in x], dtype=dtype), y_c)


def test_small_capacity_merges_and_bounds(run_ref):
    """With 3 entries the memory overflows: the C and Python runs agree on
    the merged state and the status, and the error bound is reported."""
    x = signal(N, 0.0, 40.0)
    m = hyst.Model(PAPER_F0, 0, 40, capacity=3)
    bounds = [(m.step(v), m.error_bound)[1] for v in x]
    assert m.events & hyst.EVENT_FULL
    assert max(bounds) > 0.0
    y_c, status_c, snap_c = run_ref("sim", x, np.float64, lo=0.0, hi=40.0, coeffs=PAPER_F0,
                                    cap=3)
    assert m.save() == snap_c
    m.reset()
    assert same_bits(m.process(x), y_c) and status_c == m.block_status


@pytest.mark.parametrize("deadband", [0, 40])
def test_code_model_matches_c(run_ref, deadband):
    x = np.clip(signal(N, 0, 4095, outside=False), 0, 4095).astype(np.uint16)
    m = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 64)
    m.deadband = deadband
    y = m.process(x)
    y_c, status_c, snap_c = run_ref("code", x, np.float32, lo=0.0, hi=40.0, coeffs=PAPER_F0,
                                    cap=64, code_lo=0, code_hi=4095, deadband=deadband)
    assert y.dtype == np.float32
    assert same_bits(y, y_c) and m.block_status == status_c and m.save() == snap_c


@pytest.mark.parametrize("dtype,ctype", [(np.float64, "f64"), (np.float32, "f32")])
def test_pi_matches_c(run_ref, dtype, ctype):
    r = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]
    w = [0.0789, 0.2268, 0.1928, 0.2019, 0.1995, 0.2001, 0.2000, 0.2000, 0.1999, 0.2005]
    x = signal(N, -0.2, 1.2, nonfinite=True).astype(dtype)
    p = hyst.PI(r, w, dtype=dtype)
    y = p.process(x)
    y_c, status_c, _ = run_ref("pi", x, dtype, type=ctype, r=r, w=w, cap=16)
    assert same_bits(y, y_c) and p.block_status == status_c
    # the inverse model takes the outputs back to the inputs (finite ones)
    back = p.inverse().process(np.nan_to_num(y, nan=0.0))
    fin = np.isfinite(x)
    tol = 1e-9 if dtype == np.float64 else 1e-4
    assert np.max(np.abs(back[fin][:100] - x[fin][:100])) < tol


def cli(c_build, *args, stdin=""):
    r = subprocess.run([str(c_build["cli"]), *args], input=stdin, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout.split()


@pytest.mark.parametrize("command", ["sim", "inv"])
def test_cli_prints_the_same_numbers(c_build, command):
    """`hyst sim|inv` prints %.9g of the f64 model's outputs: the package's
    float64 results, printed the same way, are the same text."""
    lo, hi = (0.0, 40.0) if command == "sim" else (0.58517, 5.5587636)
    x = signal(N, lo, hi, seed=3)
    lines = cli(c_build, command, "--poly", ",".join(map(repr, PAPER_F0)), "--range", "0,40",
                stdin="\n".join(map(repr, x.tolist())) + "\n")
    make = hyst.Model if command == "sim" else hyst.Compensator
    y = make(PAPER_F0, 0, 40).process(x)
    assert lines == ["%.9g" % v for v in y]


def test_cli_pi_prints_the_same_numbers(c_build):
    r, w = [0.0, 0.25, 0.5], [0.5, 0.3, 0.2]
    x = signal(N, -0.5, 1.5, seed=4)
    lines = cli(c_build, "pi", "--thresholds", ",".join(map(repr, r)),
                "--weights", ",".join(map(repr, w)), stdin="\n".join(map(repr, x.tolist())) + "\n")
    assert lines == ["%.9g" % v for v in hyst.PI(r, w).process(x)]


def test_cli_fit_gives_the_same_coefficients(c_build):
    out = cli(c_build, "fit", "--degree", "3", "--skip", "350", "--delay", "1",
              "--xcol", "1", "--ycol", "5", str(DATA))
    coeffs_c = out[0].split(",")
    lo_c, hi_c = out[1].split(",")
    x, y = np.loadtxt(DATA, usecols=(0, 4)).T
    f = hyst.fit(x, y, 3, skip=350, delay=1)
    assert coeffs_c == ["%.15g" % c for c in f.coeffs]
    assert [lo_c, hi_c] == ["%.15g" % f.lo, "%.15g" % f.hi]
