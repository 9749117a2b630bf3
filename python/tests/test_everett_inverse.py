# SPDX-License-Identifier: MIT
"""The asymmetric kind's compensator (hyst.ModelFromEverett(..., inverse=True),
hyst.compensator_from): the model driven by it reproduces the desired output;
its drive agrees with the exact inverse of the plain reference of
test_everett.py (the reference's response to the next input, bisected); the
drive never moves against the desired output; block call = steps; snapshots
continue bit for bit."""
import numpy as np
import pytest

import hyst
from conftest import same_bits
from test_everett import E3, EXAMPLES, Reference, output_range

DEGREES = [e["degree"] for e in EXAMPLES]


def desired(e, n, seed, dtype=np.float64):
    """A random walk with jumps (one in ten) over the major loop's output
    range [y_lo, y_lo + E(hi, lo)], ends included."""
    rng = np.random.default_rng(seed)
    lo, hi = e["y_lo"], e["y_lo"] + output_range(e)
    v, out = 0.5 * (lo + hi), np.empty(n)
    for k in range(n):
        v = rng.uniform(lo, hi) if rng.random() < 0.1 else v + (hi - lo) * rng.uniform(-0.05, 0.05)
        v = min(max(v, lo), hi)
        out[k] = v
    return out.astype(dtype)


def exact_drive(ref, y):
    """The input whose response is y: the response increases with the next
    input, from y_lo at lo to the top of the major loop at hi, whatever the
    state."""
    a, b = ref.e["lo"], ref.e["hi"]
    while True:
        m = 0.5 * (a + b)
        if m <= a or m >= b:
            return m
        if ref.response(m) < y:
            a = m
        else:
            b = m


@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("dtype, tol", [(np.float64, 1e-9), (np.float32, 2e-5)])
def test_model_driven_by_the_compensator_gives_the_desired_output(e, dtype, tol):
    yd = desired(e, 5000, seed=41 + e["degree"], dtype=dtype)
    c = hyst.ModelFromEverett(**e, dtype=dtype, inverse=True)
    drive = c.process(yd)
    assert c.inverse and c.kind == "everett" and drive.dtype == dtype
    assert np.all((drive >= e["lo"]) & (drive <= e["hi"]))
    y = hyst.ModelFromEverett(**e, dtype=dtype).process(drive)
    err = np.max(np.abs(y.astype(np.float64) - yd)) / output_range(e)
    assert err <= tol, err


@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("dtype, tol", [(np.float64, 1e-9), (np.float32, 1e-5)])
def test_drive_agrees_with_the_exact_inverse(e, dtype, tol):
    """Measured: 2e-13 .. 1.4e-12 of the drive span in float64, 4e-7 ..
    1.5e-6 in float32 (the exact inverse of the rounded desired output)."""
    yd = desired(e, 2000, seed=51 + e["degree"], dtype=dtype)
    drive = hyst.ModelFromEverett(**e, dtype=dtype, inverse=True).process(yd)
    ref, worst = Reference(e), 0.0
    for k, y in enumerate(yd):
        x = exact_drive(ref, float(y))
        worst = max(worst, abs(float(drive[k]) - x))
        ref.step(x)  # the reference follows its own exact drive
    worst /= e["hi"] - e["lo"]
    assert worst <= tol, worst


def slow_sweep(e, dtype, seed, jump):
    """Adjacent desired outputs up and down through many turning points (a
    reversal every 50 samples on average), and a move of ``jump`` of the
    output range every 100: (desired outputs, whether each one goes up)."""
    rng = np.random.default_rng(seed)
    lo, width = e["y_lo"], output_range(e)
    y = dtype(lo + width * rng.uniform(0.2, 0.8))
    top, bottom = dtype(lo + width), dtype(lo)
    yd, up = np.empty(20000, dtype=dtype), np.empty(20000, dtype=bool)
    going_up = True
    for k in range(yd.size):
        if rng.random() < 0.02:
            going_up = not going_up
        y = np.nextafter(y, top if going_up else bottom)
        if rng.random() < 0.01:
            y = dtype(min(max(y + (1 if going_up else -1) * jump * width, bottom), top))
        yd[k], up[k] = y, going_up
    return yd, up


def assert_monotone(drive, up):
    """The drive never moves against the desired output, and moves both ways."""
    step = np.diff(drive)
    assert np.all(np.where(up[1:], step >= 0, step <= 0))
    assert np.count_nonzero(step > 0) > 1000 and np.count_nonzero(step < 0) > 1000


@pytest.mark.parametrize("e", EXAMPLES, ids=DEGREES)
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_drive_is_monotone_on_a_slow_sweep(e, dtype):
    """Adjacent desired outputs up and down through many turning points, and
    a few wider moves: the drive never moves against the desired output."""
    yd, up = slow_sweep(e, dtype, 61 + e["degree"], 1e-3)
    assert_monotone(hyst.ModelFromEverett(**e, dtype=dtype, inverse=True).process(yd), up)


def assert_snapshots_refused(c, others):
    """c's snapshot is refused by each of others, and theirs by c (ERR_CURVE)."""
    for other in others:
        for into, taken in ((c, other), (other, c)):
            with pytest.raises(hyst.HystError) as err:
                into.restore(taken.save())
            assert err.value.name == "ERR_CURVE"


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_block_equals_steps_and_snapshots_continue(dtype):
    yd = desired(E3, 4000, seed=71, dtype=dtype)
    block = hyst.ModelFromEverett(**E3, dtype=dtype, inverse=True).process(yd)
    c = hyst.ModelFromEverett(**E3, dtype=dtype, inverse=True, capacity=64)
    steps = np.array([c.step(v) for v in yd], dtype=dtype)
    assert same_bits(block, steps)
    for k in (100, 1234, 3001):
        a = hyst.ModelFromEverett(**E3, dtype=dtype, inverse=True, capacity=64)
        a.process(yd[:k])
        b = hyst.ModelFromEverett(**E3, dtype=dtype, inverse=True, capacity=64)
        b.restore(a.save())
        assert b.tp_count == a.tp_count
        assert same_bits(b.process(yd[k:]), block[k:])
    # the model's snapshot is not the compensator's, nor the other way round
    assert_snapshots_refused(c, [hyst.ModelFromEverett(**E3, dtype=dtype, capacity=64)])


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_clamped_desired_outputs_and_compensator_from(dtype):
    c = hyst.compensator_from(dict(E3, kind="everett"), dtype=dtype)
    top = E3["y_lo"] + output_range(E3)
    assert c.inverse and c.dtype == np.dtype(dtype).name
    assert c.step(top + 1.0) == E3["hi"] and c.status == hyst.Status.WARN_CLAMPED
    assert c.step(E3["y_lo"] - 1.0) == E3["lo"] and c.status == hyst.Status.WARN_CLAMPED
    assert c.step(E3["y_lo"] + 0.5 * output_range(E3)) > E3["lo"]
    assert c.status == hyst.Status.OK
    # the polynomial kind's compensator through the same door
    poly = {"kind": "poly", "coeffs": [0.02, 0.3, 1.0, 0.0], "lo": 0.0, "hi": 10.0}
    yd = np.linspace(0.0, 5.0, 50, dtype=dtype)
    assert same_bits(hyst.compensator_from(poly, dtype=dtype).process(yd),
                     hyst.Compensator(poly["coeffs"], 0.0, 10.0, dtype=dtype).process(yd))


def test_refusals_raise_the_status():
    with pytest.raises(hyst.HystError) as err:
        hyst.ModelFromEverett(**dict(E3, terms=[8.0, 3.0, -20.0, 2.0, 1.0, -0.5]), inverse=True)
    assert err.value.name == "ERR_NOT_MONOTONE"
