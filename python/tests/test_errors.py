# SPDX-License-Identifier: MIT
"""Errors of the library raise hyst.HystError with its status; warnings
and ignored samples are reported as the library reports them."""
import numpy as np
import pytest

import hyst
from conftest import PAPER_F0


def raises(status, fn, *args, **kwargs):
    with pytest.raises(hyst.HystError) as e:
        fn(*args, **kwargs)
    err = e.value
    assert err.status == status and int(err.status) == int(status)
    assert err.name == hyst.Status(status).name
    assert err.message == hyst.status_str(int(status)) != "unknown status"
    assert err.message in str(err)
    return err


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_init_errors(dtype):
    raises(hyst.Status.ERR_NOT_INCREASING, hyst.Model, [-1.0, 0.0], 0, 1, dtype=dtype)
    raises(hyst.Status.ERR_DOMAIN, hyst.Model, PAPER_F0, 40, 0, dtype=dtype)
    raises(hyst.Status.ERR_DEGREE, hyst.Model, [1.0], 0, 1, dtype=dtype)
    raises(hyst.Status.ERR_DEGREE, hyst.Model, [1.0] * (hyst.MAX_DEGREE + 2), 0, 1, dtype=dtype)
    raises(hyst.Status.ERR_CAPACITY, hyst.Model, PAPER_F0, 0, 40, dtype=dtype, capacity=1)
    raises(hyst.Status.ERR_COEFF, hyst.Model, [np.nan, 1.0], 0, 1, dtype=dtype)
    raises(hyst.Status.ERR_NOT_INCREASING, hyst.Compensator, [-1.0, 0.0], 0, 1, dtype=dtype)
    m = hyst.Model(PAPER_F0, 0, 40, dtype=dtype)
    raises(hyst.Status.ERR_ARG, setattr, m, "deadband", -1.0)
    raises(hyst.Status.ERR_BREAKPOINTS, hyst.PI, [0.1, 0.2], [1.0, 1.0], dtype=dtype)
    raises(hyst.Status.ERR_WEIGHTS, hyst.PI, [0.0, 0.2], [-1.0, 1.0], dtype=dtype)
    raises(hyst.Status.ERR_ARG, hyst.PI, [0.0, 0.2], [1.0], dtype=dtype)
    with pytest.raises(TypeError):
        hyst.Model(PAPER_F0, 0, 40, dtype=np.int32)


def test_ill_conditioned_curve_refused_in_float32_only():
    x9 = [1.0] + [0.0] * 9  # x^9 on [-1, 1]: about 1e-2 of the range lost in float
    raises(hyst.Status.ERR_ILL_CONDITIONED, hyst.Model, x9, -1, 1, dtype=np.float32)
    m = hyst.Model(x9, -1, 1, dtype=np.float64)
    assert 0 < m.rounding_bound < 1e-9 * 2
    p = hyst.Model(PAPER_F0, 0, 40, dtype=np.float32)
    assert 0 < p.rounding_bound < 1e-5 * 5


def test_code_model_errors():
    raises(hyst.Status.ERR_DOMAIN, hyst.CodeModel, PAPER_F0, 0, 40, 100, 100, 16)
    raises(hyst.Status.ERR_DOMAIN, hyst.CodeModel, PAPER_F0, 0, 40, 0, hyst.CODE_MAX + 1, 16)
    m = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16)
    raises(hyst.Status.ERR_ARG, setattr, m, "deadband", 5000)


def test_fit_errors():
    x = np.array([0.0, 1.0, 0.0, 1.0, 0.0])
    raises(hyst.Status.ERR_SINGULAR, hyst.fit, x, x, 3)
    raises(hyst.Status.ERR_DEGREE, hyst.fit, x, x, 0)
    raises(hyst.Status.ERR_ARG, hyst.fit, x, x[:3], 1)
    with pytest.raises(ValueError):
        hyst.fit(x, x, 1, method="least")


def test_snapshot_errors():
    m = hyst.Model(PAPER_F0, 0, 40, capacity=8)
    m.process(np.array([0.0, 30.0, 10.0, 20.0]))
    snap = bytearray(m.save())
    bad = bytearray(snap)
    bad[len(bad) - 12] ^= 1  # a value, not a length: the CRC catches it
    raises(hyst.Status.ERR_CRC, m.restore, bytes(bad))
    raises(hyst.Status.ERR_FORMAT, m.restore, bytes(snap[:-5]))
    raises(hyst.Status.ERR_FORMAT, m.restore, b"not a snapshot at all, not at all" * 3)
    other = hyst.Model([1.0, 0.0], 0, 40, capacity=8)
    raises(hyst.Status.ERR_CURVE, other.restore, bytes(snap))
    raises(hyst.Status.ERR_VERSION, hyst.Model(PAPER_F0, 0, 40, dtype=np.float32).restore,
           bytes(snap))
    small = hyst.Model(PAPER_F0, 0, 40, capacity=2)
    small.process(np.array([0.0, 30.0, 10.0, 20.0, 15.0]))
    tiny = small.save()
    assert hyst.Model(PAPER_F0, 0, 40, capacity=2).restore(tiny) is None
    # a failed restore leaves the instance as it was
    before = m.save()
    raises(hyst.Status.ERR_CRC, m.restore, bytes(bad))
    assert m.save() == before


def test_warnings_and_ignored_samples_do_not_raise():
    m = hyst.Model(PAPER_F0, 0, 40)
    y = m.process(np.array([10.0, 50.0, 20.0]))
    assert m.block_status == hyst.Status.WARN_CLAMPED
    assert y[1] == m.process(np.array([40.0]))[0]
    m.clear_events()
    y = m.process(np.array([np.nan, 5.0, np.inf]))
    assert m.block_status == hyst.Status.ERR_NONFINITE
    assert m.status == hyst.Status.ERR_NONFINITE
    assert m.events == hyst.EVENT_NONFINITE
    assert y[2] == y[1] != y[0]


def test_unknown_status_has_a_name():
    err = hyst.HystError(12345, "ctx")
    assert err.name == "UNKNOWN" and err.status == 12345
    assert err.message == hyst.status_str(12345)


def _loops():
    """A record with a minor loop whose response the asymmetric kind of
    degree 2 fits exactly (y = x + x^2 / 10 on both branches)."""
    x = np.concatenate([np.linspace(0, 10, 200), np.linspace(10, 2, 150),
                        np.linspace(2, 8, 100), np.linspace(8, 0, 150)])
    return x, x + 0.1 * x * x


def test_fit_takes_a_missing_first_input():
    # a NaN input is a missing sample, also the first: the fit is that of the
    # record without it (the inputs' range, the everett candidates' domain,
    # is the others', not NaN)
    x, y = _loops()
    x[0] = np.nan
    f, rest = hyst.fit(x, y), hyst.fit(x[1:], y[1:])
    assert (f.kind, f.degree, f.lo, f.hi, f.delay) == (rest.kind, rest.degree, rest.lo, rest.hi,
                                                       rest.delay) == ("everett", 2, 0.0, 20.0, 0)
    assert np.allclose(f.terms, rest.terms, rtol=1e-12)
    assert np.allclose(hyst.fit(x, y, 2, kind="everett").terms, [10, 20, 10], rtol=1e-9)


def test_fit_refuses_what_it_cannot_use():
    x, y = _loops()
    bad = x.copy()
    bad[5] = np.inf
    with pytest.raises(ValueError, match=r"x\[5\] is inf"):
        hyst.fit(bad, y)
    with pytest.raises(ValueError, match=r"y\[7\] is -inf"):
        hyst.fit(x, np.where(np.arange(len(y)) == 7, -np.inf, y))
    for opts in ({"delay": -1}, {"delay": 1.5}, {"skip": -2}, {"skip": 2.5},
                 {"delay": -1, "degree": 3}):
        with pytest.raises(ValueError, match="whole number of samples"):
            hyst.fit(x, y, **opts)
    with pytest.raises(hyst.HystError, match="leave no sample") as err:
        hyst.fit(x, y, skip=len(x))
    assert err.value.status == hyst.Status.ERR_ARG
    with pytest.raises(ValueError, match="x is constant"):
        hyst.fit(np.ones(50), np.arange(50.0))
    with pytest.raises(ValueError, match="y falls as x rises"):
        hyst.fit(x, -y)
    with pytest.raises(ValueError, match="y is constant"):
        hyst.fit(x, np.full_like(y, np.nan))
    assert hyst.fit(x, y, delay=2.0, skip=np.int64(1)).delay == 2


def test_counts_are_whole_numbers():
    # a capacity or a table's size is a count: a fraction is refused, never
    # truncated; a negative capacity is the library's "too small"
    raises(hyst.Status.ERR_CAPACITY, hyst.Model, PAPER_F0, 0, 40, capacity=-1)
    for make in (lambda: hyst.Model(PAPER_F0, 0, 40, capacity=8.5),
                 lambda: hyst.Compensator(PAPER_F0, 0, 40, intervals=16.5),
                 lambda: hyst.ModelFromEverett(1, 0, 10, 0, [1.0], inverse=True, intervals=4,
                                               rows=2.5)):
        with pytest.raises(ValueError, match="must be a whole number"):
            make()
    assert hyst.Model(PAPER_F0, 0, 40, capacity=8.0).capacity == 8
