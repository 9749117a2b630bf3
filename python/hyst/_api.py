# SPDX-License-Identifier: MIT
"""Constructors that pick the library's variant by numpy dtype, and fit()."""
import math

import numpy as np

from . import _hyst
from ._errors import HystError
from ._model_file import header_text, save_model

MAX_DEGREE = _hyst.MAX_DEGREE

#: Turning-point entries per array: never full for inputs taking 4096
#: distinct values (a 12-bit DAC), HYST_CAPACITY(4096).
DEFAULT_CAPACITY = 2048

_METHODS = {"joint": 1, "reflect": 2}


def _variant(dtype, f32, f64):
    dt = np.dtype(dtype)
    if dt == np.float64:
        return f64
    if dt == np.float32:
        return f32
    raise TypeError(f"dtype must be float32 or float64, not {dt}")


def Model(coeffs, lo, hi, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, deadband=0.0):
    """A TCM model with polynomial f0 (coefficients highest power first) on [lo, hi].

    float64 runs the library's ``hyst_f64_*`` variant, float32 ``hyst_f32_*``.
    The instance owns ``capacity`` entries per turning-point array.
    """
    m = _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, coeffs)), float(lo), float(hi), int(capacity), False)
    if deadband:
        m.deadband = deadband
    return m


def Compensator(coeffs, lo, hi, *, dtype=np.float64, capacity=DEFAULT_CAPACITY):
    """The inverse model of Model(coeffs, lo, hi): desired output in, drive out."""
    return _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, coeffs)), float(lo), float(hi), int(capacity), True)


def ModelFromPoints(xs, ys, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, inverse=False):
    """A TCM model whose f0 is piecewise linear through the points (xs, ys),
    xs strictly increasing, ys increasing (the library's PWL curve kind);
    ``inverse=True`` gives its compensator."""
    return _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, xs)), list(map(float, ys)), int(capacity), bool(inverse))


def PI(thresholds, weights, *, dtype=np.float64):
    """A Prandtl-Ishlinskii model; ``.inverse()`` gives its inverse."""
    return _variant(dtype, _hyst.PIF32, _hyst.PIF64)(
        list(map(float, thresholds)), list(map(float, weights)))


class Fit:
    """An identified f0 (hyst_ident_fit()) and the model it defines.

    Attributes: ``coeffs`` (highest power first), ``lo``, ``hi``, ``degree``,
    ``method``, ``rms`` and ``max_abs`` (residuals of the measured samples
    against the major loop), ``used``, ``rising``, ``falling``,
    ``increasing``, ``y_lo_est``, ``y_hi_est``, and ``model``, a Model with
    this f0 at A0. Model calls (``process``, ``step``, ``reset``...) go to
    ``model``, so a Fit is used as the model itself.
    """

    def __init__(self, result, dtype, capacity, delay=0, candidates=None):
        self.__dict__.update(result)
        self.method = {v: k for k, v in _METHODS.items()}[result["method"]]
        self.delay = int(delay)
        self.candidates = candidates or []
        self.model = Model(self.coeffs, self.lo, self.hi, dtype=dtype, capacity=capacity)

    def save(self, path):
        """Writes the model file (hyst-model-text 1, delay included) that
        ``hyst sim --model`` reads."""
        save_model(path, self.coeffs, self.lo, self.hi, delay=self.delay)

    def header(self, name):
        """The firmware header (C source text) declaring ``hyst_poly_t name``."""
        return header_text(name, self.coeffs, self.lo, self.hi)

    def __getattr__(self, name):
        # only called for names not found on the Fit itself
        return getattr(self.__dict__["model"], name)

    def predict(self, x):
        """Outputs of a fresh model (at A0) for the inputs x; ``model`` is untouched."""
        m = Model(self.coeffs, self.lo, self.hi, dtype=self.model.dtype,
                  capacity=self.model.capacity)
        return m.process(np.ascontiguousarray(x, dtype=self.model.dtype))

    def __repr__(self):
        c = ", ".join(f"{v:.9g}" for v in self.coeffs)
        return (f"Fit(coeffs=[{c}], lo={self.lo:.9g}, hi={self.hi:.9g}, "
                f"rms={self.rms:.6g}, max_abs={self.max_abs:.6g}, method={self.method!r})")


#: Delays tried by fit() when none is given, and the parsimony margin of the
#: choice: the same as ``hyst fit`` without --degree (docs/cli.md).
MAX_DELAY = 8
PARSIMONY = 0.01


def _holdout(res, x, y, skip, delay, first):
    """RMS error of the model (f0 of res, double) over x[skip:n-delay],
    scored from sample ``first`` on against y[k + delay]."""
    n = len(x) - delay
    m = Model(res["coeffs"], res["lo"], res["hi"], capacity=(n - skip) // 2 + 2)
    pred = m.process(np.ascontiguousarray(x[skip:n]))
    meas = y[skip + delay:n + delay]
    k = slice(first - skip, None)
    err = pred[k] - meas[k]
    ok = np.isfinite(x[skip:n][k]) & np.isfinite(meas[k])
    return math.sqrt(float(np.mean(err[ok] ** 2))) if ok.any() else math.nan


def _select(x, y, method, lo, hi, skip, delays):
    """Every candidate (degree, delay): fitted on the first two thirds, scored
    by its prediction of the last third; the fewest parameters within
    PARSIMONY of the lowest error win (hyst fit's rule)."""
    cands, best = [], None
    for d in delays:
        if len(x) <= skip + d:
            break
        train = (2 * (len(x) - skip - d)) // 3
        for deg in range(1, MAX_DEGREE + 1):
            c = {"degree": deg, "delay": d, "holdout_rms": math.nan, "fit_rms": math.nan,
                 "status": "OK"}
            try:
                n = skip + train + d  # the training part, as hyst fit passes it
                res = _hyst.fit(np.ascontiguousarray(x[:n]), np.ascontiguousarray(y[:n]),
                                deg, _METHODS[method], lo, hi, skip, d)
                c["fit_rms"] = res["rms"]
                if res["increasing"]:
                    c["holdout_rms"] = _holdout(res, x, y, skip, d, skip + train)
                else:
                    c["status"] = "f0 not increasing"
            except HystError as e:
                c["status"] = e.name
            if math.isfinite(c["holdout_rms"]) and (
                    best is None or c["holdout_rms"] < cands[best]["holdout_rms"]):
                best = len(cands)
            cands.append(c)
    if best is not None:
        limit = cands[best]["holdout_rms"] * (1 + PARSIMONY)
        for i, c in enumerate(cands):
            b = cands[best]
            if math.isfinite(c["holdout_rms"]) and c["holdout_rms"] <= limit and (
                    c["degree"] < b["degree"] or
                    (c["degree"] == b["degree"] and c["holdout_rms"] < b["holdout_rms"])):
                best = i
    return cands, best


def fit(x, y, degree=3, *, method="joint", domain=None, skip=0, delay=0,
        dtype=np.float64, capacity=DEFAULT_CAPACITY):
    """Identifies f0 from a recorded drive ``x`` and response ``y`` (hyst_ident_fit()).

    Sample i (skip <= i < n - delay) pairs x[i] with y[i + delay]; the domain
    is ``domain=(lo, hi)`` or the range of those inputs. ``method`` is
    ``"joint"`` (both branches in one least-squares problem) or
    ``"reflect"`` (the paper's Eq. 14). ``degree=None`` chooses the degree,
    and ``delay=None`` the delay (0..MAX_DELAY), by hold-out exactly as
    ``hyst fit`` without --degree does: every candidate is in the result's
    ``candidates`` (dicts: degree, delay, holdout_rms, fit_rms, status).
    Returns a :class:`Fit`.
    """
    if method not in _METHODS:
        raise ValueError(f"method must be one of {sorted(_METHODS)}, not {method!r}")
    lo, hi = (0.0, 0.0) if domain is None else (float(domain[0]), float(domain[1]))
    x = np.ascontiguousarray(x, dtype=np.float64)
    y = np.ascontiguousarray(y, dtype=np.float64)
    cands = None
    if degree is None:
        delays = range(0, MAX_DELAY + 1) if delay is None else [int(delay)]
        cands, best = _select(x, y, method, lo, hi, int(skip), delays)
        if best is None:
            raise ValueError("no candidate degree gave an increasing f0 that could predict "
                             "the last third of the record")
        degree, delay = cands[best]["degree"], cands[best]["delay"]
        for i, c in enumerate(cands):
            c["chosen"] = i == best
    elif delay is None:
        raise ValueError("delay=None (chosen) needs degree=None")
    res = _hyst.fit(x, y, int(degree), _METHODS[method], lo, hi, int(skip), int(delay))
    return Fit(res, dtype, capacity, delay=delay, candidates=cands)
