# SPDX-License-Identifier: MIT
"""The asymmetric kind's tabulated compensator, as firmware runs it
(hyst.ModelFromEverett(..., inverse=True, intervals=N, rows=R),
hyst.compensator_from(desc, intervals=N, rows=R)): the C library's outputs,
statuses, snapshots and measured error bit for bit (hyst_ref), its drive
within the error init measured of the solved compensator's and within 1e-5
of the drive span of the exact inverse with the default table, monotone
along a branch, saved and restored like any instance; bad table arguments
refused before anything is allocated."""
import re

import numpy as np
import pytest

import hyst
from conftest import REPO, same_bits
from test_everett import E3, EXAMPLES, Reference, output_range
from test_everett_inverse import (assert_monotone, assert_snapshots_refused, desired, exact_drive,
                                  slow_sweep)

DEGREES = [e["degree"] for e in EXAMPLES]
TARGET = 1e-5  # of the drive span: the default table's promise


def test_defaults_are_the_c_configs():
    """EVERETT_INV_ROWS and EVERETT_INV_INTERVALS are include/hyst/config.h's
    defaults (the build sets no other), the table a compensator with only
    intervals given takes."""
    text = (REPO / "include" / "hyst" / "config.h").read_text()
    for name in ("EVERETT_INV_ROWS", "EVERETT_INV_INTERVALS"):
        value = int(re.search(rf"#define HYST_{name} (\d+)", text).group(1))
        assert getattr(hyst, name) == value, name
    c = hyst.ModelFromEverett(**E3, inverse=True, intervals=hyst.EVERETT_INV_INTERVALS)
    assert (c.rows, c.intervals) == (hyst.EVERETT_INV_ROWS, hyst.EVERETT_INV_INTERVALS)


def table(e, dtype=np.float64, intervals=hyst.EVERETT_INV_INTERVALS, rows=None, **kw):
    return hyst.ModelFromEverett(**e, dtype=dtype, inverse=True, intervals=intervals, rows=rows,
                                 **kw)


def solved(e, dtype=np.float64, **kw):
    return hyst.ModelFromEverett(**e, dtype=dtype, inverse=True, **kw)


def with_bad_samples(e, n, seed, dtype):
    """desired() with a few outputs outside the major loop's range and a few
    NaN and infinities (clamped and ignored as in firmware)."""
    y = desired(e, n, seed).astype(np.float64)
    rng = np.random.default_rng(seed)
    idx = rng.integers(0, n, n // 100)
    y[idx] = np.where(rng.random(idx.size) < 0.5, e["y_lo"] - 1.0,
                      e["y_lo"] + output_range(e) + 1.0)
    y[rng.integers(0, n, 4)] = np.nan
    y[rng.integers(0, n, 2)] = np.inf
    return y.astype(dtype)


def everett_opts(e):
    return {"degree": e["degree"], "lo": e["lo"], "hi": e["hi"], "y_lo": e["y_lo"],
            "terms": e["terms"]}


@pytest.mark.parametrize("dtype,ctype", [(np.float64, "f64"), (np.float32, "f32")])
@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("intervals,rows,capacity,deadband", [
    (hyst.EVERETT_INV_INTERVALS, None, 2048, 0.0),  # the firmware's default table
    (8, 5, 2048, 0.0),  # degree 4: every interval solved instead
    (1, 3, 3, 0.0),  # the smallest table (solved), loops merging
    (48, 24, 2048, 0.002),
])
def test_tabulated_compensator_matches_c(run_ref, tmp_path, dtype, ctype, e, intervals, rows,
                                         capacity, deadband):
    """Outputs, block status, snapshot bytes and measured error equal the C
    library's (rows not given on either side: both take the library's
    HYST_EVERETT_INV_ROWS, which the snapshot's curve identity includes);
    step() equals the block call; the table is the one in use (its drive is
    not the solved compensator's)."""
    y = with_bad_samples(e, 6000, seed=81 + e["degree"], dtype=dtype)
    c = table(e, dtype, intervals, rows, capacity=capacity)
    c.deadband = deadband * output_range(e)
    assert (c.intervals, c.rows) == (intervals, hyst.EVERETT_INV_ROWS if rows is None else rows)
    x = c.process(y)
    err_file = tmp_path / "err.txt"
    opts = dict(everett_opts(e), type=ctype, cap=capacity, intervals=intervals,
                deadband=c.deadband, err=str(err_file))
    if rows is not None:
        opts["rows"] = rows
    x_c, status_c, snap_c = run_ref("inv", y, dtype, **opts)
    assert x.dtype == dtype
    assert same_bits(x, x_c)
    assert c.block_status == status_c
    assert c.save() == snap_c
    assert c.inverse_error == float(err_file.read_text())
    c.reset()
    assert same_bits(np.array([c.step(v) for v in y], dtype=dtype), x_c)
    if c.inverse_error > 0.0:  # 0: every interval missed the tolerance and is solved
        exact = solved(e, dtype, capacity=capacity)
        exact.deadband = c.deadband
        assert not same_bits(exact.process(y), x)


@pytest.mark.parametrize("dtype,ctype", [(np.float64, "f64"), (np.float32, "f32")])
def test_model_of_the_asymmetric_kind_matches_c(run_ref, dtype, ctype):
    """The forward model the compensator inverts: the C library's, bit for bit."""
    rng = np.random.default_rng(5)
    x = rng.uniform(E3["lo"] - 0.5, E3["hi"] + 0.5, 5000).astype(dtype)
    m = hyst.ModelFromEverett(**E3, dtype=dtype)
    y = m.process(x)
    y_c, status_c, snap_c = run_ref("sim", x, dtype, type=ctype, cap=2048, **everett_opts(E3))
    assert same_bits(y, y_c) and m.block_status == status_c and m.save() == snap_c


def sweeps(e, n=2001):
    """Up the major loop's output range from reset, then down: each drive is
    one table evaluation from a turning point whose drive is exact or one
    such evaluation old."""
    up = e["y_lo"] + output_range(e) * np.linspace(0.0, 1.0, n)
    return up, up[::-1]


@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("intervals,rows", [(hyst.EVERETT_INV_INTERVALS, None), (16, 8)])
def test_sweeps_within_the_measured_error_of_the_solved_compensator(e, dtype, intervals, rows):
    """Against the solved compensator (intervals=0): within the error init
    measured (1 % for the points it did not probe), once going up and twice
    going down, plus the solved one's own error (its rounding bound). A
    coarse table errs more than the default one, and says so (in float64:
    in float32 the rounding of the evaluation is most of both)."""
    t, x = table(e, dtype, intervals, rows), solved(e, dtype)
    assert x.intervals == 0 and x.rows == 0 and x.inverse_error == 0.0
    span = e["hi"] - e["lo"]
    allowed = 1.01 * t.inverse_error * span + 2.0 * x.rounding_bound
    worst = 0.0
    for evaluations, y in enumerate(sweeps(e), 1):
        y = y.astype(dtype)
        d = np.abs(t.process(y).astype(np.float64) - x.process(y).astype(np.float64))
        assert d.max() <= evaluations * allowed, (d.max(), allowed)
        worst = max(worst, float(d.max()))
    assert worst > 0.0  # a table, not the solved compensator
    if rows is not None:  # the coarse table
        fine = table(e, dtype)
        assert t.inverse_error > fine.inverse_error
        if dtype == np.float64:
            assert t.inverse_error > 2 * fine.inverse_error


@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_default_table_within_1e5_of_the_exact_inverse(e, dtype):
    """On random walks with jumps, against the exact inverse of the plain
    reference (test_everett_inverse.py), which follows its own exact drive:
    within 1e-5 of the drive span with the default table, which init
    measured within that too."""
    t = table(e, dtype)
    assert 0.0 < t.inverse_error <= TARGET
    yd = desired(e, 1500, seed=91 + e["degree"], dtype=dtype)
    drive = t.process(yd)
    assert t.block_status == hyst.Status.OK
    ref, worst = Reference(e), 0.0
    for k, y in enumerate(yd):
        xk = exact_drive(ref, float(y))
        worst = max(worst, abs(float(drive[k]) - xk))
        ref.step(xk)
    worst /= e["hi"] - e["lo"]
    assert worst <= TARGET, worst


@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("intervals,rows", [(hyst.EVERETT_INV_INTERVALS, None), (24, 4), (4, 3)])
def test_drive_is_monotone_along_a_branch(e, dtype, intervals, rows):
    """Adjacent desired outputs up and down through many turning points, and
    wider moves across intervals: the drive never moves against the desired
    output (default table, a coarse one, one whose intervals are solved
    for degrees 3 and 4)."""
    yd, up = slow_sweep(e, dtype, 101 + e["degree"], 1e-2)
    assert_monotone(table(e, dtype, intervals, rows).process(yd), up)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_block_equals_steps_and_snapshots_continue(dtype):
    yd = desired(E3, 4000, seed=111, dtype=dtype)
    block = table(E3, dtype, capacity=64).process(yd)
    c = table(E3, dtype, capacity=64)
    assert same_bits(np.array([c.step(v) for v in yd], dtype=dtype), block)
    for k in (100, 1234, 3001):
        a = table(E3, dtype, capacity=64)
        a.process(yd[:k])
        b = table(E3, dtype, capacity=64)
        b.restore(a.save())
        assert (b.tp_count, b.output, b.input) == (a.tp_count, a.output, a.input)
        assert same_bits(b.process(yd[k:]), block[k:])
    # a fresh table compensator does not continue the same way
    assert not same_bits(table(E3, dtype, capacity=64).process(yd[3001:]), block[3001:])
    # the solved compensator's snapshot, another table's and the model's are
    # not this one's, nor the other way round
    others = [solved(E3, dtype, capacity=64), table(E3, dtype, rows=8, capacity=64),
              table(E3, dtype, intervals=16, capacity=64),
              hyst.ModelFromEverett(**E3, dtype=dtype, capacity=64)]
    assert_snapshots_refused(c, others)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_compensator_from_builds_either_table(dtype):
    desc = dict(E3, kind="everett")
    yd = desired(E3, 2000, seed=121, dtype=dtype)
    c = hyst.compensator_from(desc, dtype=dtype, intervals=24, rows=6)
    assert (c.kind, c.inverse, c.intervals, c.rows) == ("everett", True, 24, 6)
    assert c.inverse_error == table(E3, dtype, 24, 6).inverse_error > 0.0
    assert same_bits(c.process(yd), table(E3, dtype, 24, 6).process(yd))
    d = hyst.compensator_from(desc, dtype=dtype, intervals=hyst.EVERETT_INV_INTERVALS)
    assert d.rows == hyst.EVERETT_INV_ROWS
    assert same_bits(d.process(yd), table(E3, dtype).process(yd))
    exact = hyst.compensator_from(desc, dtype=dtype)
    assert (exact.intervals, exact.rows, exact.inverse_error) == (0, 0, 0.0)
    assert same_bits(exact.process(yd), solved(E3, dtype).process(yd))
    model = hyst.ModelFromEverett(**E3, dtype=dtype)
    assert (model.inverse, model.intervals, model.rows, model.inverse_error) == (False, 0, 0, 0.0)
    # kind poly takes intervals as before
    poly = {"kind": "poly", "coeffs": [0.02, 0.3, 1.0, 0.0], "lo": 0.0, "hi": 10.0}
    p = hyst.compensator_from(poly, dtype=dtype, intervals=64)
    assert (p.intervals, p.rows) == (64, 0) and p.inverse_error > 0.0


def refused(fn, *args, what, **kwargs):
    with pytest.raises(hyst.HystError) as err:
        fn(*args, **kwargs)
    assert err.value.status == hyst.Status.ERR_ARG
    assert what in err.value.context, err.value.context


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_bad_table_arguments_are_refused_before_allocating(dtype):
    """Out of range, or given where there is no table: HystError ERR_ARG,
    saying which. 2^20 intervals with more than 4096 rows would be hundreds
    of gigabytes: the refusal comes first (not a MemoryError)."""
    big = 1 << 20
    for rows in (-1, 0, 1, 2, 4097, 5000, 1 << 40):
        refused(table, E3, dtype, big, rows, what="rows outside 3 .. 4096")
    for intervals in (-1, big + 1, 10 ** 30):
        refused(table, E3, dtype, intervals, what="intervals outside 1 .. 2^20")
        refused(hyst.Compensator, [0.02, 0.3, 1.0, 0.0], 0, 10, dtype=dtype,
                intervals=intervals, what="intervals outside 1 .. 2^20")
    refused(table, E3, dtype, 0, 16, what="rows needs intervals > 0")
    refused(hyst.ModelFromEverett, **E3, dtype=dtype, intervals=32, what="inverse=True")
    refused(hyst.ModelFromEverett, **E3, dtype=dtype, rows=16, what="inverse=True")
    desc = dict(E3, kind="everett")
    refused(hyst.compensator_from, desc, dtype=dtype, rows=16, what="rows needs intervals > 0")
    refused(hyst.compensator_from, desc, dtype=dtype, intervals=-5, what="intervals outside")
    poly = {"kind": "poly", "coeffs": [0.02, 0.3, 1.0, 0.0], "lo": 0.0, "hi": 10.0}
    refused(hyst.compensator_from, poly, dtype=dtype, intervals=32, rows=16,
            what="kind everett")
    # the smallest table is accepted; a non-monotone E is refused as before
    small = table(E3, dtype, 1, 3)
    assert (small.intervals, small.rows) == (1, 3)
    with pytest.raises(hyst.HystError) as err:
        table(dict(E3, terms=[8.0, 3.0, -20.0, 2.0, 1.0, -0.5]), dtype)
    assert err.value.name == "ERR_NOT_MONOTONE"
