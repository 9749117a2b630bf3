# SPDX-License-Identifier: MIT
"""The asymmetric kind (hyst.ModelFromEverett, fit(kind="everett")):
against a plain double reference written here (a list of turning points
and the direct formula), block call, float32, snapshots, refusals, and the
identification of a known E from a noisy record."""
import math

import numpy as np
import pytest

import hyst
from conftest import same_bits, signal
from hyst._api import MAX_DELAY

# an asymmetric E of degree 3 on [0, 10]: loops grow with their lower end
# (w t) and their width enters to the third power
E3 = {"degree": 3, "lo": 0.0, "hi": 10.0, "y_lo": -1.0,
      "terms": [8.0, 3.0, -1.0, 2.0, 1.0, -0.5]}


def e_value(e, a, b):
    """E(a, b) summed term by term: w^i t^j, i = 1..degree, j = 0..degree - i."""
    span = e["hi"] - e["lo"]
    w, t = (a - b) / span, (b - e["lo"]) / span
    k, total = 0, 0.0
    for i in range(1, e["degree"] + 1):
        for j in range(0, e["degree"] - i + 1):
            total += e["terms"][k] * w ** i * t ** j
            k += 1
    return total


class Reference:
    """Madelung's rules on a list of turning points (LTPs at even places, A0
    first): rising from (b, y_b) y = y_b + E(x, b), falling from (a, y_a)
    y = y_a - E(a, x); passing the TP before the current one wipes out both;
    at lo every loop is closed. Inputs clamped to the domain, NaN and
    infinities ignored."""

    def __init__(self, e):
        self.e = e
        self.tx, self.ty = [e["lo"]], [e["y_lo"]]
        self.x_prev, self.y = e["lo"], e["y_lo"]

    def step(self, x):
        e, tx, ty = self.e, self.tx, self.ty
        if not math.isfinite(x):
            return self.y
        x = min(max(float(x), e["lo"]), e["hi"])
        rising = (len(tx) - 1) % 2 == 0
        if x > self.x_prev:
            if not rising:
                tx.append(self.x_prev)
                ty.append(self.y)
            while len(tx) >= 3 and x >= tx[-2]:
                del tx[-2:], ty[-2:]
            self.y = ty[-1] + e_value(e, x, tx[-1])
        elif x < self.x_prev:
            if rising:
                tx.append(self.x_prev)
                ty.append(self.y)
            while len(tx) >= 3 and x <= tx[-2]:
                del tx[-2:], ty[-2:]
            self.y = ty[-1] - e_value(e, tx[-1], x)
            if x <= e["lo"]:
                self.tx, self.ty, self.y = [e["lo"]], [e["y_lo"]], e["y_lo"]
        self.x_prev = x
        return self.y

    def response(self, x):
        """The output if the next input were x; this reference unchanged."""
        probe = Reference(self.e)
        probe.tx, probe.ty = list(self.tx), list(self.ty)
        probe.x_prev, probe.y = self.x_prev, self.y
        return probe.step(x)


def reference(e, xs):
    r = Reference(e)
    return np.array([r.step(x) for x in xs])


def output_range(e):
    return e_value(e, e["hi"], e["lo"])


# E of degrees 3, 2 and 4 that init accepts
EXAMPLES = [
    E3,
    {"degree": 2, "lo": 0.0, "hi": 3.6000000000000001, "y_lo": -0.035382239014971697,
     "terms": [0.61, 0.02, -0.1]},
    {"degree": 4, "lo": -5.0, "hi": 15.0, "y_lo": 2.0,
     "terms": [4.0, 1.0, 0.5, -0.2, 1.0, 0.3, -0.1, 0.5, 0.1, -0.3]},
]


@pytest.mark.parametrize("e", EXAMPLES)
def test_float64_equals_the_reference(e):
    x = signal(8000, e["lo"], e["hi"], seed=21, nonfinite=True)
    want = reference(e, x)
    m = hyst.ModelFromEverett(**e)
    got = m.process(x)
    err = np.max(np.abs(got - want))  # NaN would fail the comparison below
    assert err <= 1e-9 * output_range(e), err
    assert m.kind == "everett" and m.terms == e["terms"] and m.y_lo == e["y_lo"]
    assert (m.lo, m.hi, m.coeffs) == (e["lo"], e["hi"], [])
    assert m.block_status == hyst.Status.ERR_NONFINITE  # NaN samples ignored, as in firmware
    # E's t terms matter on this signal: without them (a symmetric TCM) the
    # output differs, so the agreement above checks them too
    k, width_only = 0, []
    for i in range(1, e["degree"] + 1):
        for j in range(0, e["degree"] - i + 1):
            width_only.append(e["terms"][k] if j == 0 else 0.0)
            k += 1
    symmetric = reference(dict(e, terms=width_only), x)
    assert np.max(np.abs(symmetric - want)) > 1e-3 * output_range(e)


@pytest.mark.parametrize("dtype, tol", [(np.float64, 1e-9), (np.float32, 2e-5)])
def test_step_equals_block_and_float32_follows(dtype, tol):
    x = signal(5000, 0.0, 10.0, seed=22).astype(dtype)
    a = hyst.ModelFromEverett(**E3, dtype=dtype)
    b = hyst.ModelFromEverett(**E3, dtype=dtype)
    ya = a.process(x)
    yb = np.array([b.step(v) for v in x], dtype=dtype)
    assert a.dtype == np.dtype(dtype).name and ya.dtype == dtype
    assert same_bits(ya, yb)
    assert np.max(np.abs(ya - reference(E3, x.astype(np.float64)))) <= tol * output_range(E3)
    assert a.block_status == hyst.Status.WARN_CLAMPED  # signal() has samples outside


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_snapshot_continues_bit_for_bit(dtype):
    x = signal(6000, 0.0, 10.0, seed=23).astype(dtype)
    a = hyst.ModelFromEverett(**E3, dtype=dtype, capacity=64)
    a.process(x[:3000])
    b = hyst.ModelFromEverett(**E3, dtype=dtype, capacity=64)
    b.restore(a.save())
    assert b.tp_count == a.tp_count > 0
    assert same_bits(a.process(x[3000:]), b.process(x[3000:]))
    # taken with another E: refused
    other = dict(E3, terms=[7.0] + E3["terms"][1:])
    with pytest.raises(hyst.HystError) as err:
        hyst.ModelFromEverett(**other, dtype=dtype, capacity=64).restore(a.save())
    assert err.value.name == "ERR_CURVE"


@pytest.mark.parametrize("change, name", [
    ({"terms": [0.61, 0.02, -1.0], "degree": 2}, "ERR_NOT_MONOTONE"),
    ({"degree": 5, "terms": [1.0] * 15}, "ERR_DEGREE"),
    ({"degree": 0, "terms": []}, "ERR_DEGREE"),
    ({"terms": [1.0, 0.0]}, "ERR_ARG"),
    ({"lo": 10.0, "hi": 0.0}, "ERR_DOMAIN"),
    ({"terms": [math.nan] + E3["terms"][1:]}, "ERR_COEFF"),
])
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_refusals_raise_the_status(change, name, dtype):
    with pytest.raises(hyst.HystError) as err:
        hyst.ModelFromEverett(**dict(E3, **change), dtype=dtype)
    assert err.value.name == name and err.value.status == getattr(hyst.Status, name)


def noisy_record(e, n, seed, delay=0, noise=1e-3):
    """The plant (a model of the asymmetric kind) driven by nested minor loops
    and random sweeps, its output with Gaussian noise (noise x the range),
    read `delay` samples late."""
    x = np.clip(signal(n, e["lo"], e["hi"], seed=seed, outside=False), e["lo"], e["hi"])
    y = hyst.ModelFromEverett(**e).process(x)
    y = y + noise * output_range(e) * np.random.default_rng(seed).standard_normal(n)
    return x, np.concatenate([np.full(delay, y[0]), y[:n - delay]])


def test_fit_recovers_a_known_e():
    x, y = noisy_record(E3, 6000, seed=31)
    f = hyst.fit(x, y, 3, kind="everett", domain=(E3["lo"], E3["hi"]))
    assert f.kind == "everett" and f.degree == 3 and len(f.terms) == 6
    assert np.max(np.abs(np.array(f.terms) - E3["terms"])) < 0.1  # terms up to 8
    assert abs(f.y_lo - E3["y_lo"]) < 0.02
    sigma = 1e-3 * output_range(E3)
    assert 0.9 * sigma < f.rms < 1.1 * sigma  # the noise, nothing more
    assert f.used == len(x)
    # the fitted model predicts a record it has not seen, within the noise
    xt = np.clip(signal(4000, 0.0, 10.0, seed=32, outside=False), 0.0, 10.0)
    err = f.predict(xt) - hyst.ModelFromEverett(**E3).process(xt)
    assert np.sqrt(np.mean(err ** 2)) < sigma
    # a Fit is the model; its description builds the same model
    assert np.array_equal(f.process(xt), hyst.model_from(f.description()).process(xt))


def test_fit_from_inside_a_loop():
    """A record that starts inside a loop: the model, from rest, follows
    another branch than the plant's until the input first comes near an end
    of its range; the outputs are fitted from there on, E recovered."""
    x = np.clip(signal(6000, E3["lo"], E3["hi"], seed=33, outside=False), E3["lo"], E3["hi"])
    y = hyst.ModelFromEverett(**E3).process(x)
    near_end = (x <= E3["lo"] + 0.1) | (x >= E3["hi"] - 0.1)
    start = int(np.argmax(near_end)) + 40  # past the first extreme, inside a loop
    start += int(np.argmax(~near_end[start:]))
    xm, ym = x[start:], y[start:]
    settle = int(np.argmax((xm <= xm.min() + 0.01 * np.ptp(xm)) | (xm >= xm.max() - 0.01 * np.ptp(xm))))
    assert settle > 100  # the record's own head, not fitted
    f = hyst.fit(xm, ym, 3, kind="everett", domain=(E3["lo"], E3["hi"]))
    assert f.used == len(xm) - settle
    assert np.max(np.abs(np.array(f.terms) - E3["terms"])) < 1e-3 * np.max(np.abs(E3["terms"]))


def test_fit_of_excursions_growing_from_a_rest_inside():
    """A record whose first extreme comes late (excursions growing from a
    rest in the middle): every output is fitted, not only the tail after
    that extreme; the plant, run from rest as the model is, recovered."""
    steps = [np.full(50, 5.0)]
    for c in range(1, 11):
        a = 0.5 * c
        steps += [np.arange(5.0, 5.0 + a, 0.05), np.arange(5.0 + a, 5.0 - a, -0.05),
                  np.arange(5.0 - a, 5.0, 0.05)]
    x = np.concatenate(steps)
    y = hyst.ModelFromEverett(**E3).process(x)
    near_end = (x <= x.min() + 0.01 * np.ptp(x)) | (x >= x.max() - 0.01 * np.ptp(x))
    assert np.argmax(near_end) > 2 * len(x) // 3  # the first extreme in the last third
    f = hyst.fit(x, y, 3, kind="everett", domain=(E3["lo"], E3["hi"]))
    assert f.used == len(x)
    assert np.max(np.abs(np.array(f.terms) - E3["terms"])) < 1e-3 * np.max(np.abs(E3["terms"]))


def test_auto_choice_prefers_the_asymmetric_kind_on_an_asymmetric_plant():
    x, y = noisy_record(E3, 6000, seed=33, delay=2)
    f = hyst.fit(x, y, None, delay=None, domain=(E3["lo"], E3["hi"]))
    assert (f.kind, f.degree, f.delay) == ("everett", 3, 2)
    # everett: each degree d with each t-degree 0..d - 1
    shapes = hyst.EVERETT_MAX_DEGREE * (hyst.EVERETT_MAX_DEGREE + 1) // 2
    # the grids of 4 and 6 intervals (fit_select.h's FIT_GRID_CANDIDATES) and the
    # splines of 2..16 intervals (FIT_SPLINE_CANDIDATES), as hyst fit
    grids = [c for c in f.candidates if c["kind"] == "everett_grid"]
    assert sorted({c["degree"] for c in grids}) == [4, 6]
    splines = [c for c in f.candidates if c["kind"] == "spline"]
    assert sorted({c["degree"] for c in splines}) == list(range(2, 17))
    assert len(f.candidates) == (MAX_DELAY + 1) * (hyst.MAX_DEGREE + shapes + 2 + 15)
    chosen = [c for c in f.candidates if c["chosen"]]
    assert len(chosen) == 1 and chosen[0]["params"] == 6 + 1 and chosen[0]["t_degree"] == 2
    assert f.t_degree == 2
    poly = [c for c in f.candidates if c["kind"] == "poly" and np.isfinite(c["holdout_rms"])]
    assert min(c["holdout_rms"] for c in poly) > 5 * chosen[0]["holdout_rms"]
    params = {(c["degree"], c["t_degree"]): c["params"] for c in f.candidates
              if c["kind"] == "everett"}
    assert params == {(1, 0): 2, (2, 0): 3, (2, 1): 4, (3, 0): 4, (3, 1): 6, (3, 2): 7,
                      (4, 0): 5, (4, 1): 8, (4, 2): 10, (4, 3): 11}
    # forced to poly, the choice stays within the symmetric kind
    g = hyst.fit(x, y, None, delay=2, kind="poly", domain=(E3["lo"], E3["hi"]))
    assert g.kind == "poly" and {c["kind"] for c in g.candidates} == {"poly"}


def test_auto_choice_on_major_loops_of_a_symmetric_plant():
    """Major loops alone determine E linear in t, not E of t-degree 2 or 3:
    those candidates are reported singular. The plant's cubic f0 and E of
    degree 3 in w alone (t-degree 0) are the same major loop with as many
    parameters (4), their hold-outs differing by rounding only: the
    symmetric kind is chosen (its compensator is a table)."""
    coeffs = [0.02, 0.3, 1.0, 0.0]  # f0 on [0, 10], increasing
    x = 5.0 - 5.0 * np.cos(2 * np.pi * np.arange(6000) / 300)
    y = hyst.Model(coeffs, 0.0, 10.0).process(x)
    y = y + 1e-3 * (y.max() - y.min()) * np.random.default_rng(34).standard_normal(len(y))
    f = hyst.fit(x, y, None, domain=(0.0, 10.0))
    chosen = [c for c in f.candidates if c["chosen"]][0]
    assert (f.degree, f.delay, chosen["params"]) == (3, 0, 4)
    assert f.kind == "poly"
    rms = {(c["kind"], c["degree"], c["t_degree"]): c["holdout_rms"] for c in f.candidates
           if c["delay"] == 0}
    assert rms[("poly", 3, None)] == pytest.approx(rms[("everett", 3, 0)], rel=1e-6)
    for c in f.candidates:
        if c["kind"] == "everett":
            assert (c["status"] == "ERR_SINGULAR") == (c["t_degree"] >= 2), c


def test_choice_rule_fewest_parameters_then_symmetric_then_lower_error():
    from hyst._api import PARSIMONY, _choose

    # the rule is the tool's (fit_choose()), which counts a candidate's
    # parameters from its shape: poly degree + 1, everett E's terms + 1
    shape = {("everett", 4): (2, 1), ("everett", 6): (3, 1)}

    def cand(kind, params, rms):
        degree, t_degree = shape[kind, params] if kind == "everett" else (params - 1, None)
        return {"kind": kind, "degree": degree, "t_degree": t_degree, "holdout_rms": rms}
    best = 1.0
    within = best * (1 + PARSIMONY / 2)
    # the fewest parameters within the margin, whatever its kind
    assert _choose([cand("poly", 5, best), cand("everett", 4, within)]) == (1, False)
    # as many parameters: the symmetric kind, even with the higher error
    assert _choose([cand("everett", 4, best), cand("poly", 4, within)]) == (1, False)
    # outside the margin, fewer parameters do not win
    assert _choose([cand("poly", 5, best),
                    cand("poly", 4, best * (1 + 2 * PARSIMONY))]) == (0, False)
    # between equals of one kind, the lower error; unscored ones never
    assert _choose([cand("everett", 6, within), cand("everett", 6, best),
                    cand("poly", 2, float("nan"))]) == (1, False)
    assert _choose([cand("poly", 2, float("nan"))]) == (None, False)
    # errors equal up to rounding (FIT_TIE, 1e-9): the widened one, not the
    # last digits; a difference the record resolves still goes to the lower
    plain, wide = cand("everett", 4, best), dict(cand("everett", 4, best * (1 + 1e-12)),
                                                 widened=True)
    assert _choose([plain, wide]) == (1, False)
    assert _choose([wide, plain]) == (0, False)
    assert _choose([plain, dict(wide, holdout_rms=best * (1 + 1e-6))]) == (0, False)

    # with creep terms (hyst fit --creep auto): each candidate alone and with
    # its creep term, two parameters more (weight and time constant), by the same rule
    def crept(kind, params, rms, creep_rms):
        return dict(cand(kind, params, rms), creep_tau=1000.0, creep_holdout_rms=creep_rms)
    two = [crept("poly", 4, 2.0, best), crept("poly", 5, 1.5, within)]
    assert _choose(two, 0.0) == (0, True)       # 4 + 2 parameters within the margin
    assert _choose(two, -1.0) == (1, False)     # --creep none: the candidates alone
    assert _choose(two, 1000.0) == (0, True)    # --creep TAU: with it, always
    # the creep term only where it is worth its parameter
    assert _choose([crept("poly", 4, best, within)], 0.0) == (0, False)
    assert _choose([crept("poly", 4, 1.5, best)], 0.0) == (0, True)
    # a candidate whose creep term could not be fitted (tau 0) has no creep option
    assert _choose([dict(crept("poly", 4, 1.5, best), creep_tau=0.0)], 1000.0) == (None, False)


def test_major_loops_determine_e_linear_in_t():
    """A plant whose E is of degree 3, linear in t, driven by major loops
    alone: E of degree 3 in full is singular, t_degree 1 recovers E (the
    w t^2 term 0) and is the automatic choice, as in hyst fit."""
    e = {"degree": 3, "lo": 0.0, "hi": 40.0, "y_lo": 0.5, "terms": [3.0, 1.0, 0.0, 2.0, -0.5, 0.4]}
    x = np.tile(np.concatenate([np.arange(0.0, 40.0, 0.25), np.arange(40.0, 0.0, -0.25)]), 4)
    y = hyst.ModelFromEverett(**e).process(x)
    with pytest.raises(hyst.HystError) as err:
        hyst.fit(x, y, 3, kind="everett")
    assert err.value.name == "ERR_SINGULAR"
    f = hyst.fit(x, y, 3, kind="everett", t_degree=1)
    assert f.t_degree == 1 and f.terms[2] == 0.0
    assert np.max(np.abs(np.array(f.terms) - e["terms"])) < 1e-9
    noisy = y + 2e-3 * np.random.default_rng(35).standard_normal(len(y))
    g = hyst.fit(x, noisy, None)
    assert (g.kind, g.degree, g.t_degree, g.delay) == ("everett", 3, 1, 0)
    assert np.max(np.abs(np.array(g.terms) - e["terms"])) < 0.03
    assert [c["params"] for c in g.candidates if c["chosen"]] == [6]
    with pytest.raises(ValueError):
        hyst.fit(x, y, 3, t_degree=1)  # kind poly
    with pytest.raises(ValueError):
        hyst.fit(x, y, 2, kind="everett", t_degree=2)


def test_fit_errors():
    x = np.array([0.0, 1.0, 0.0, 1.0, 0.0])
    with pytest.raises(hyst.HystError) as err:
        hyst.fit(x, x, 3, kind="everett")
    assert err.value.name == "ERR_SINGULAR"
    with pytest.raises(hyst.HystError) as err:
        hyst.fit(np.linspace(0, 1, 50), np.linspace(0, 1, 50), 5, kind="everett")
    assert err.value.name == "ERR_DEGREE"
    with pytest.raises(hyst.HystError) as err:
        hyst.fit(x, x[:3], 1, kind="everett")
    assert err.value.name == "ERR_ARG"
    with pytest.raises(ValueError, match="kind"):
        hyst.fit(x, x, 1, kind="preisach")
    # an E that is not monotone is refused when the Fit builds its model: a
    # plant that rises then falls (one that clearly falls is refused before
    # the fit: test_errors.py)
    t = np.linspace(0, 1, 400)
    up_down = np.abs(np.sin(6 * np.pi * t))
    with pytest.raises(hyst.HystError) as err:
        hyst.fit(up_down, 4 * up_down * (1 - up_down), 2, kind="everett")
    assert err.value.name == "ERR_NOT_MONOTONE"
