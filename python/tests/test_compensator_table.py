# SPDX-License-Identifier: MIT
"""The tabulated compensator, as firmware runs it (Compensator(...,
intervals=N)): the C library's outputs bit for bit, within its measured
error of the exact compensator, monotone, and saved and restored like any
instance."""
import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, same_bits, signal

N = 20000
Y_LO, Y_HI = 0.58517, 5.5587636  # Eq. 20 at 0 and 40 V
SPAN = 40.0


@pytest.mark.parametrize("dtype,ctype", [(np.float64, "f64"), (np.float32, "f32")])
@pytest.mark.parametrize("intervals", [32, hyst.INV_TABLE])
def test_tabulated_compensator_matches_c(run_ref, dtype, ctype, intervals):
    y = signal(N, Y_LO, Y_HI, nonfinite=True).astype(dtype)
    c = hyst.Compensator(PAPER_F0, 0, 40, dtype=dtype, intervals=intervals)
    x = c.process(y)
    x_c, status_c, snap_c = run_ref("inv", y, dtype, type=ctype, lo=0.0, hi=40.0,
                                    coeffs=PAPER_F0, cap=2048, intervals=intervals)
    assert same_bits(x, x_c)
    assert c.block_status == status_c
    assert c.save() == snap_c


def sweeps(n=20001):
    """Up the whole output range, then down: at most two turning points, so
    each drive is one table evaluation from an exact or one-evaluation-old
    turning point."""
    up = np.linspace(Y_LO, Y_HI, n)
    return up, up[::-1]


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_default_table_within_its_measured_error_of_the_exact_inverse(dtype):
    """The issue's target: at most 1e-5 of the drive range with the default
    table, on Eq. 20; and the drives along a sweep within it. (A drive is a
    turning point's drive plus one evaluation, and the turning points' drives
    are earlier outputs: a drive under n nested turning points can differ by
    n + 1 evaluations' errors.)"""
    exact = hyst.Compensator(PAPER_F0, 0, 40, dtype=dtype)
    table = hyst.Compensator(PAPER_F0, 0, 40, dtype=dtype, intervals=hyst.INV_TABLE)
    assert exact.intervals == 0 and exact.inverse_error == 0.0
    assert table.intervals == hyst.INV_TABLE
    assert 0.0 < table.inverse_error <= 1e-5
    # the exact inverse's own rounding: a few ulps of the range
    slack = 1e-13 if dtype == np.float64 else 8 * np.finfo(np.float32).eps
    for evaluations, y in enumerate(sweeps(), 1):
        got = table.process(y.astype(dtype)).astype(np.float64)
        want = exact.process(y.astype(dtype)).astype(np.float64)
        assert np.abs(got - want).max() <= evaluations * (table.inverse_error + slack) * SPAN


def test_fewer_intervals_err_more_and_say_so():
    """16 intervals: every one within the tolerance, a larger measured error.
    (Fewer, on Eq. 20, miss it: those intervals are evaluated exactly.)"""
    coarse = hyst.Compensator(PAPER_F0, 0, 40, intervals=16)
    fine = hyst.Compensator(PAPER_F0, 0, 40, intervals=hyst.INV_TABLE)
    assert coarse.inverse_error > 1000 * fine.inverse_error
    exact = hyst.Compensator(PAPER_F0, 0, 40)
    for evaluations, y in enumerate(sweeps(), 1):
        diff = np.abs(coarse.process(y) - exact.process(y))
        # init measures 15 points per interval: at 16 intervals the dense
        # maximum is 0.07 % above it (docs/pi_and_inverse.md)
        assert diff.max() <= evaluations * (1.01 * coarse.inverse_error + 1e-13) * SPAN
        assert diff.max() > fine.inverse_error * SPAN  # the coarse table's error shows


def test_drive_never_moves_against_the_desired_output():
    c = hyst.Compensator(PAPER_F0, 0, 40, intervals=16)
    up = np.linspace(Y_LO, Y_HI, 5001)
    down = up[::-1]
    for y in (up, down, np.concatenate([up[:3000], up[3000:1000:-1]])):
        c.reset()
        x = c.process(y)
        dy, dx = np.diff(y), np.diff(x)
        assert np.all(dx[dy > 0] >= 0) and np.all(dx[dy < 0] <= 0)


def test_tabulated_compensator_round_trips_through_a_snapshot():
    d = signal(4000, 0.6, 5.5, seed=9)
    a = hyst.Compensator(PAPER_F0, 0, 40, intervals=64)
    a.process(d[:2000])
    b = hyst.Compensator(PAPER_F0, 0, 40, intervals=64)
    b.restore(a.save())
    assert same_bits(a.process(d[2000:]), b.process(d[2000:]))


def test_compensator_from_passes_intervals_and_bad_counts_are_refused():
    desc = {"coeffs": PAPER_F0, "lo": 0.0, "hi": 40.0}
    assert hyst.compensator_from(desc, intervals=32).intervals == 32
    with pytest.raises(hyst.HystError) as err:
        hyst.Compensator(PAPER_F0, 0, 40, intervals=(1 << 20) + 1)
    assert err.value.status == hyst.Status.ERR_ARG
