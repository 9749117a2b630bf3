# SPDX-License-Identifier: MIT
"""Identification on the measured piezo record (tests/data): fit on the
first half, predict the second half with the model started at A0."""
import numpy as np
import pytest

import hyst
from conftest import DATA

# tests/data/README.md: settling in the first 350 rows, sensor lag 1 sample,
# input at 0 V (the model's A0) on row 4150
SKIP, SPLIT, END, DELAY = 350, 4150, 7950, 1


@pytest.fixture(scope="module")
def record():
    x, y = np.loadtxt(DATA, usecols=(0, 4)).T
    assert x[SPLIT] == x.min()
    return x, y


def prediction_rms(f, x, y):
    e = f.predict(x[SPLIT:END]) - y[SPLIT + DELAY:END + DELAY]
    return float(np.sqrt(np.mean(e ** 2)))


@pytest.mark.parametrize("method", ["joint", "reflect"])
def test_fit_predicts_the_other_half(record, method):
    x, y = record
    f = hyst.fit(x[:SPLIT + DELAY], y[:SPLIT + DELAY], 3, method=method, skip=SKIP, delay=DELAY)
    assert f.method == method and f.degree == 3 and len(f.coeffs) == 4
    assert f.increasing and f.used == f.rising + f.falling
    assert 0.99 * (SPLIT - SKIP) < f.used <= SPLIT - SKIP  # a sample before the first move has no direction
    assert f.rising > 0 and f.falling > 0
    assert (f.lo, f.hi) == (x[SKIP:SPLIT].min(), x[SKIP:SPLIT].max())
    assert 0 < f.rms <= f.max_abs
    span = y.max() - y.min()
    rms = prediction_rms(f, x, y)
    # within a few per cent of the output range, and far better than a line
    assert rms < 0.03 * span
    line = hyst.fit(x[:SPLIT + DELAY], y[:SPLIT + DELAY], 1, method=method, skip=SKIP,
                    delay=DELAY)
    assert prediction_rms(line, x, y) > 2 * rms
    print(f"\n{method}: {f!r}; prediction RMS {rms:.4g} on an output range of {span:.4g}")


@pytest.mark.parametrize("creep", ["auto", "none"])
def test_fit_is_a_model(record, creep):
    x, y = record
    f = hyst.fit(x, y, 3, skip=SKIP, delay=DELAY, dtype=np.float32, creep=creep)
    assert f.model.dtype == "float32" and f.dtype == "float32"
    # the record drifts: hyst fit's hold-out chooses a creep term for it
    assert (f.creep is not None) == (creep == "auto") and len(f.creep_tau) == (creep == "auto")
    m = hyst.Model(f.coeffs, f.lo, f.hi, dtype=np.float32, creep_tau=f.creep_tau,
                   creep_weight=f.creep_weight)
    xs = x[SPLIT:END].astype(np.float32)
    assert np.array_equal(f.process(xs), m.process(xs))
    assert f.tp_count == m.tp_count
    f.reset()
    assert f.tp_count == 0 and np.array_equal(f.predict(xs), m.process(xs) * 0 + f.process(xs))


def test_fit_domain_and_reflect(record):
    x, y = record
    f = hyst.fit(x, y, 2, domain=(0.0, 4.0), skip=SKIP, delay=DELAY)
    assert (f.lo, f.hi) == (0.0, 4.0)
    assert np.isfinite(f.y_lo_est) and np.isfinite(f.y_hi_est)
