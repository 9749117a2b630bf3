# SPDX-License-Identifier: MIT
"""Constructors that pick the library's variant by numpy dtype, and fit()."""
import math
import warnings

import numpy as np

from . import _hyst
from ._errors import FitWarning, HystError
from ._model_file import NO_TABLE, _creep_args, header_text, save_model

MAX_DEGREE = _hyst.MAX_DEGREE
EVERETT_MAX_DEGREE = _hyst.EVERETT_MAX_DEGREE
#: Most knot intervals of a spline f0 (HYST_SPLINE_MAX_INTERVALS).
SPLINE_MAX_INTERVALS = _hyst.SPLINE_MAX_INTERVALS

#: Turning-point entries per array: never full for inputs taking 4096
#: distinct values (a 12-bit DAC), HYST_CAPACITY(4096).
DEFAULT_CAPACITY = 2048

_METHODS = {"joint": 1, "reflect": 2}


def _count(n, name="count", least=-1):
    """A count (a table's intervals or rows, a capacity) as the extension's C
    integer: a count beyond its range becomes 2^62 or `least`, which the
    library refuses as out of range (HystError: ERR_ARG, ERR_CAPACITY) like
    any other, instead of a TypeError; a fraction is refused, never
    truncated."""
    if isinstance(n, (float, np.floating)) and not float(n).is_integer():
        raise ValueError(f"{name} must be a whole number, not {n!r}")
    return max(min(int(n), 1 << 62), least)


def _samples(name, v):
    """skip or delay: a whole number of samples >= 0 (an int, or a float
    without a fraction), never silently rounded or taken for "choose"."""
    if (isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating))
            or not float(v).is_integer() or v < 0):
        raise ValueError(f"{name} must be a whole number of samples >= 0, not {v!r}")
    return int(v)


def _record(name, v):
    """A record's column as float64: NaN marks a missing sample (an output
    not fitted, an input the model ignores); _check_record() refuses an
    infinite one."""
    v = np.ascontiguousarray(v, dtype=np.float64)
    if v.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, not of shape {v.shape}")
    return v


def _check_record(x, y, skip, delay, names=("x", "y")):
    """Refuses what hyst fit refuses in a record, by its check
    (fit_record_check()): an infinite sample, no sample left, a column whose
    samples used (NaN aside) are all one number (no model could be fitted
    to it), a response that clearly falls as its drive rises (every model of
    hyst rises with its input, so the choice could only pick the least bad;
    a sensor of the opposite sign is the usual cause). Returns the check's
    dict (its minor: the drive's reversals inside its range)."""
    r = _hyst.record_check(x, y, skip, delay)
    fault = r["fault"]
    if fault in ("infinite_input", "infinite_output"):
        name = names[0] if fault == "infinite_input" else names[1]
        raise ValueError(f"{name}[{r['at']}] is {r['value']}: a record's samples are finite "
                         "numbers, or NaN where one is missing")
    if fault == "no_sample":
        raise HystError(_hyst.Status.ERR_ARG, f"fit: skip {skip} and delay {delay} "
                        f"leave no sample of the {len(x)} given")
    if fault in ("constant_input", "constant_output"):
        name, what = (names[0], "drive") if fault == "constant_input" else (names[1], "response")
        v = r["value"]
        raise ValueError(f"{name} is constant ("
                         + (f"{v:.9g} at every sample used" if not math.isnan(v)
                            else "NaN throughout")
                         + f"): a record's {what} must vary")
    if fault == "falling":
        raise ValueError(f"{names[1]} falls as {names[0]} rises (correlation "
                         f"{r['correlation']:.3g}): every model of hyst rises with its input; "
                         f"negate {names[1]}")
    return r


def _variant(dtype, f32, f64):
    dt = np.dtype(dtype)
    if dt == np.float64:
        return f64
    if dt == np.float32:
        return f32
    raise TypeError(f"dtype must be float32 or float64, not {dt}")


def _with_creep(m, creep_tau, creep_weight):
    """m with the creep term (creep_tau, creep_weight), if any: the library's
    lags (hyst_*_creep_*), every one at lo at rest."""
    tau, weight = _creep_args(creep_tau, creep_weight)
    if tau is not None:
        m.set_creep(tau, weight)
    return m


def _with_deadband_creep(m, deadband, creep_tau, creep_weight):
    """m with its deadband (hyst_*_set_deadband(); 0: none) and its creep term."""
    if deadband:
        m.deadband = deadband
    return _with_creep(m, creep_tau, creep_weight)


def Creep(tau, weight, x_rest, *, dtype=np.float64):
    """A creep term alone (hyst/creep.h): lags of a drive of time constants
    ``tau`` (samples, each >= 1) and weights ``weight`` (1 to 4 of each),
    every lag at ``x_rest`` after init and reset. ``step(x)`` returns
    c[n] = sum_k weight[k] s_k[n] (from the drives before x), then takes x in;
    ``output`` is c[n] of the next sample. float64 runs hyst_f64_creep_*,
    float32 hyst_f32_creep_*."""
    return _variant(dtype, _hyst.CreepF32, _hyst.CreepF64)(
        list(map(float, tau)), list(map(float, weight)), float(x_rest))


def Model(coeffs, lo, hi, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, deadband=0.0,
          creep_tau=None, creep_weight=None):
    """A TCM model with polynomial f0 (coefficients highest power first) on [lo, hi].

    float64 runs the library's ``hyst_f64_*`` variant, float32 ``hyst_f32_*``.
    The instance owns ``capacity`` entries per turning-point array.
    ``creep_tau``, ``creep_weight`` (1 to 4 numbers each, as a model file
    holds them) add a creep term: the output is the hysteresis model's plus
    sum_k creep_weight[k] s_k, s_k a first-order lag (time constant
    creep_tau[k] samples, hyst_*_creep_*()) of the input as the model took
    it (clamped to [lo, hi]), every lag at lo at rest; strictly causal, as
    ``hyst sim --model`` runs it.
    """
    m = _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, coeffs)), float(lo), float(hi), _count(capacity, "capacity", 0), False)
    return _with_deadband_creep(m, deadband, creep_tau, creep_weight)


#: Intervals of the firmware's compensator table (HYST_INV_TABLE, the default
#: of HYST_DEFINE_INVERSE / HYST_INIT_INVERSE).
INV_TABLE = _hyst.INV_TABLE

#: The asymmetric compensator's table as firmware declares it by default
#: (HYST_EVERETT_INV_ROWS rows per direction, HYST_EVERETT_INV_INTERVALS
#: intervals per row; hyst_*_curve_everett_inverse_table()).
EVERETT_INV_ROWS = _hyst.EVERETT_INV_ROWS
EVERETT_INV_INTERVALS = _hyst.EVERETT_INV_INTERVALS


def Compensator(coeffs, lo, hi, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, intervals=0,
                creep_tau=None, creep_weight=None):
    """The inverse model of Model(coeffs, lo, hi): desired output in, drive out.

    ``intervals=0`` (the default, as ``hyst inv``) runs the exact inverse, the
    reference. ``intervals=N`` runs the tabulated compensator firmware runs
    (hyst_*_init_inverse_table(); ``INV_TABLE`` is HYST_INIT_INVERSE's), bit
    for bit: its ``inverse_error`` is the worst error against the exact
    inverse that init measured, as a fraction of the drive range. Intervals
    outside 0 .. 2^20 raise ``HystError`` (ERR_ARG) before any table is
    allocated. With a creep term (``creep_tau``, ``creep_weight``: the
    model's, as :func:`Model` takes them) each desired output y gives the
    drive of the hysteresis compensator for y - c, c the creep's
    contribution (``creep_output``, from the drives before), whose lags then
    take that drive in: ``hyst inv --model``'s compensator, bit for bit."""
    return _with_creep(_variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, coeffs)), float(lo), float(hi), _count(capacity, "capacity", 0), True,
        _count(intervals, "intervals")),
        creep_tau, creep_weight)


def ModelFromPoints(xs, ys, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, inverse=False):
    """A TCM model whose f0 is piecewise linear through the points (xs, ys),
    xs strictly increasing, ys increasing (the library's PWL curve kind);
    ``inverse=True`` gives its compensator."""
    return _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, xs)), list(map(float, ys)), _count(capacity, "capacity", 0),
        bool(inverse))


def ModelFromEverett(degree, lo, hi, y_lo, terms, *, dtype=np.float64,
                     capacity=DEFAULT_CAPACITY, deadband=0.0, inverse=False, intervals=0,
                     rows=None, creep_tau=None, creep_weight=None):
    """The asymmetric kind (hyst_everett_t): rising from a turning point
    (b, y_b) the output is y_b + E(x, b), falling from (a, y_a) it is
    y_a - E(a, x), with E(a, b) the sum of e[i-1][j] w^i t^j over i >= 1,
    i + j <= degree (1..EVERETT_MAX_DEGREE), w = (a - b) / (hi - lo),
    t = (b - lo) / (hi - lo). ``terms`` lists e[i-1][j] for i = 1..degree,
    then j = 0..degree-i (degree 2: w, w t, w^2); ``y_lo`` is the output at
    lo after reset. The library refuses an E that does not increase in a and
    decrease in b on the whole triangle (``HystError`` ERR_NOT_MONOTONE).

    ``inverse=True`` gives its compensator: desired output in, on the major
    loop's output range [y_lo, y_lo + E(hi, lo)] (clamped outside), drive
    out. With ``intervals=0`` (the default) it solves each branch
    (hyst_curve_inverse(), kind HYST_CURVE_EVERETT_INV), within about 1e-12
    (float64) / 1e-6 (float32) of the drive span. ``intervals=N`` runs the
    tabulated compensator firmware runs (hyst_*_curve_everett_inverse_table(),
    kind HYST_CURVE_EVERETT_INV_TABLE), bit for bit: ``rows`` + 1 rows per
    direction (``rows=None``: ``EVERETT_INV_ROWS``, the library's default;
    3 .. 4096) of N intervals (1 .. 2^20; ``EVERETT_INV_INTERVALS`` is the
    library's default); ``inverse_error`` is the worst error against the
    solved compensator that init measured, as a fraction of the drive span,
    and ``intervals``, ``rows`` say which table it is (0 for the solved
    one). Bad table arguments (out of range, ``rows`` without intervals,
    either without ``inverse=True``) raise ``HystError`` (ERR_ARG) before
    the table is allocated. ``creep_tau``, ``creep_weight``: a creep term,
    as :func:`Model` (the model) and :func:`Compensator` (its compensator)
    take it."""
    m = _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        int(degree), float(lo), float(hi), float(y_lo), list(map(float, terms)),
        _count(capacity, "capacity", 0), bool(inverse), _count(intervals, "intervals"),
        None if rows is None else _count(rows, "rows"))
    return _with_deadband_creep(m, deadband, creep_tau, creep_weight)


def ModelFromEverettGrid(knots, weights, y_lo, *, dtype=np.float64, capacity=DEFAULT_CAPACITY,
                         deadband=0.0, inverse=False, creep_tau=None, creep_weight=None):
    """The asymmetric kind on a grid (hyst_everett_grid_t): E of a Preisach
    density constant on each cell of the grid of ``knots`` (K + 1 strictly
    increasing, K in 1..12; lo the first, hi the last), the cell (i, j)'s
    mass ``weights[i (i + 1) / 2 + j]`` (K (K + 1) / 2 numbers, >= 0);
    ``y_lo`` the output at lo after reset (hyst_*_curve_from_everett_grid(),
    docs/theory.md). ``inverse=True`` gives its compensator, each branch
    solved in closed form (hyst_*_curve_everett_grid_inverse()). What the
    library refuses raises ``HystError``. ``creep_tau``, ``creep_weight``: a
    creep term, as :func:`Model` and :func:`Compensator` take it."""
    m = _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, knots)), list(map(float, weights)), float(y_lo),
        _count(capacity, "capacity", 0), bool(inverse))
    return _with_deadband_creep(m, deadband, creep_tau, creep_weight)


def ModelFromSpline(lo, hi, values, slopes, *, dtype=np.float64, capacity=DEFAULT_CAPACITY,
                    deadband=0.0, inverse=False, intervals=0, creep_tau=None, creep_weight=None):
    """The symmetric kind whose f0 is a monotone cubic spline on uniform
    knots (hyst_spline_t): ``values`` and ``slopes`` are f0 and its slope
    (output units per input unit, each >= 0) at the K + 1 knots
    lo + k (hi - lo) / K, k = 0..K (K in 1..SPLINE_MAX_INTERVALS), f0 the
    cubic (Hermite) of those between two knots
    (hyst_*_curve_from_spline()). ``inverse=True`` gives its compensator:
    with ``intervals=0`` (the default) each drive solved on f0's cubic piece
    per sample (hyst_curve_spline_inverse(); a flat piece has none:
    ERR_NOT_INVERTIBLE); ``intervals=N`` (1 .. 2^20; ``INV_TABLE`` is the
    library's default) runs the tabulated compensator firmware runs
    (hyst_*_curve_spline_inverse_table(), kind HYST_CURVE_SPLINE_INV_TABLE),
    bit for bit, its ``inverse_error`` the worst error init measured, as a
    fraction of the drive range. ``intervals`` out of range, or without
    ``inverse=True``, raises ``HystError`` (ERR_ARG) before the table is
    allocated. What the library refuses raises ``HystError`` (a piece that
    falls: ERR_NOT_INCREASING). ``creep_tau``, ``creep_weight``: a creep
    term, as :func:`Model` and :func:`Compensator` take it."""
    m = _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        float(lo), float(hi), list(map(float, values)), list(map(float, slopes)),
        _count(capacity, "capacity", 0), bool(inverse), _count(intervals, "intervals"))
    return _with_deadband_creep(m, deadband, creep_tau, creep_weight)


def _creep_of(desc):
    """The creep keys of a description (none when it has no creep term)."""
    return {"creep_tau": desc.get("creep_tau"), "creep_weight": desc.get("creep_weight")}


def _with_rate(m, desc):
    """m with the description's rate term, if it has one (``rate_tau``,
    ``rate_weight``: hyst_*_rate_*, at rest at lo), as ``hyst sim --model``
    and ``hyst inv --model`` apply it."""
    if desc.get("rate_tau") is not None or desc.get("rate_weight") is not None:
        m.set_rate(desc.get("rate_tau"), desc.get("rate_weight"))
    return m


def _curve_kind(desc, **kw):
    """The model, or (inverse=True) the compensator, of a description of
    kind everett_grid or spline (a curve made from a table of its own), with
    its creep and rate terms; ``intervals`` is the spline's alone (its
    tabulated compensator)."""
    if desc["kind"] == "spline":
        m = ModelFromSpline(desc["lo"], desc["hi"], desc["values"], desc["slopes"],
                            **_creep_of(desc), **kw)
    else:
        m = ModelFromEverettGrid(desc["knots"], desc["weights"], desc["y_lo"], **_creep_of(desc),
                                 **kw)
    return _with_rate(m, desc)


def model_from(desc, *, dtype=np.float64, capacity=DEFAULT_CAPACITY):
    """The model a description gives: a :func:`hyst.load_model` dict (its
    delay is not the model's: apply it to the comparison) or
    ``Fit.description()``; kind poly (``coeffs``, ``lo``, ``hi``) when the
    dict has no ``kind``; with its creep term when it has ``creep_tau`` and
    ``creep_weight``, and its rate term (docs/rate.md: the output plus
    ``rate_weight`` times a low-pass, of time constant ``rate_tau`` samples,
    of the input's change) when it has ``rate_tau`` and ``rate_weight``.
    A model with a rate term has no snapshot (``save()`` raises). Kind
    everett_grid (``y_lo``, ``knots``, ``weights``) is E on a grid
    (hyst_*_curve_from_everett_grid()), kind spline (``lo``, ``hi``,
    ``values``, ``slopes``) f0 a monotone cubic spline
    (hyst_*_curve_from_spline()), as ``hyst sim --model`` runs them."""
    if desc.get("kind", "poly") in ("everett_grid", "spline"):
        return _curve_kind(desc, dtype=dtype, capacity=capacity)
    if desc.get("kind", "poly") == "everett":
        return _with_rate(ModelFromEverett(desc["degree"], desc["lo"], desc["hi"], desc["y_lo"],
                                           desc["terms"], dtype=dtype, capacity=capacity,
                                           **_creep_of(desc)), desc)
    return _with_rate(Model(desc["coeffs"], desc["lo"], desc["hi"], dtype=dtype,
                            capacity=capacity, **_creep_of(desc)), desc)


def compensator_from(desc, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, intervals=0,
                     rows=None):
    """The compensator (inverse model) of the model :func:`model_from` gives:
    desired output in, drive out, for either kind. ``intervals=0`` (the
    default) gives the exact one; ``intervals=N`` the tabulated one firmware
    runs: kind poly as in :func:`Compensator`, kind spline as in
    :func:`ModelFromSpline`, kind everett as in :func:`ModelFromEverett`
    (with its ``rows``). ``rows`` is the asymmetric kind's: given for kind
    poly or spline, it raises ``HystError`` (ERR_ARG). With
    the description's creep term, the compensator subtracts the creep's
    contribution from each desired output first (:func:`Compensator`); with
    its rate term, the rate term's too (known before the drive is chosen).
    Kind everett_grid's compensator solves each branch in closed form
    (hyst_*_curve_everett_grid_inverse()), as ``hyst inv --model``: it has
    no table (``intervals`` or ``rows`` given raise ``HystError``,
    ERR_ARG)."""
    kind = desc.get("kind", "poly")
    if kind in NO_TABLE:
        if intervals or rows is not None:
            raise HystError(_hyst.Status.ERR_ARG,
                            f"kind {kind} has no tabulated compensator ({NO_TABLE[kind]})")
        return _curve_kind(desc, dtype=dtype, capacity=capacity, inverse=True)
    if kind != "everett" and rows is not None:
        raise HystError(_hyst.Status.ERR_ARG,
                        f"rows is the asymmetric kind's table (kind everett), not kind {kind}'s")
    if kind == "spline":
        return _curve_kind(desc, dtype=dtype, capacity=capacity, inverse=True,
                           intervals=intervals)
    if kind == "everett":
        return _with_rate(ModelFromEverett(desc["degree"], desc["lo"], desc["hi"], desc["y_lo"],
                                           desc["terms"], dtype=dtype, capacity=capacity,
                                           inverse=True, intervals=intervals, rows=rows,
                                           **_creep_of(desc)), desc)
    return _with_rate(Compensator(desc["coeffs"], desc["lo"], desc["hi"], dtype=dtype,
                                  capacity=capacity, intervals=intervals, **_creep_of(desc)),
                      desc)


def outside_identified(desc, x):
    """How many of the inputs x lie outside the range the model was
    identified on (``identified`` of a :func:`hyst.load_model` dict or of
    ``Fit.description()``; 0 when none is recorded): the samples ``hyst sim
    --model`` counts, predicted by the branches continued beyond it (and
    clamped beyond the domain)."""
    ident = desc.get("identified")
    if ident is None:
        return 0
    x = np.asarray(x, dtype=np.float64)
    return int(np.count_nonzero((x < ident[0]) | (x > ident[1])))


def PI(thresholds, weights, *, dtype=np.float64):
    """A Prandtl-Ishlinskii model; ``.inverse()`` gives its inverse."""
    return _variant(dtype, _hyst.PIF32, _hyst.PIF64)(
        list(map(float, thresholds)), list(map(float, weights)))


class Fit:
    """An identified model and the model it defines.

    ``kind`` is ``"poly"`` (f0 by hyst_ident_fit(): ``coeffs`` highest power
    first, ``method``, ``rms`` and ``max_abs`` residuals of the measured
    samples against the major loop, ``used``, ``rising``, ``falling``,
    ``increasing``, ``y_lo_est``, ``y_hi_est``) or ``"everett"`` (the
    asymmetric kind's E by hyst_everett_fit_*(): ``terms``, ``y_lo``, ``rms``
    of the least-squares residuals, ``used``, ``t_degree``: the highest power
    of t fitted, the terms above it 0). Both have ``degree``, ``lo``,
    ``hi``, ``delay``, ``candidates`` and ``model``, the model at A0 (poly:
    ``t_degree`` None), and ``identified``: None, or (LO, HI), the range of
    the inputs f0 or E was identified on when its domain is wider (a widened
    candidate chosen, or ``domain``), counted by :meth:`outside_identified`. Model
    calls (``process``, ``step``, ``reset``...) go to ``model``, so a Fit is
    used as the model itself.

    ``creep`` is the creep term fitted with the model (:func:`fit`'s
    ``creep``), or None: a dict of ``tau`` (samples), ``weight``, ``offset``
    (the constant fitted with it, already folded into the model: f0's
    constant or E's ``y_lo``), ``rms`` and ``max_abs`` of the model with it
    over the record, and ``holdout_rms`` with it and ``holdout_rms_without``
    it, the hold-out scores that chose it. ``creep_tau`` and
    ``creep_weight`` are the model's (lists; empty without one), and
    ``model``, ``predict``, ``save`` and ``header`` include it. ``rate`` is
    the rate term fitted with it (:func:`fit`'s ``rate``), or None: a dict of
    ``tau``, ``weight``, ``holdout_rms`` and ``holdout_rms_without``;
    ``rate_tau`` and ``rate_weight`` the model's (None without one), which
    the model, its file and its header include. ``rms`` and ``max_abs`` stay
    the hysteresis fit's own. The automatic choice's E of t-degree 0, the
    symmetric model, is kind ``"poly"`` with kind poly compared, as ``hyst
    fit`` writes it: its f0 ``y_lo + sum e[i-1][0] ((x - lo) / (hi - lo))^i``
    in powers of x, ``method`` ``"branches"`` (E's least squares along
    every branch, ``rms`` its residual) and ``everett`` the E (degree,
    t_degree, y_lo, terms). A grid (``"everett_grid"``) has ``knots``,
    ``weights``, ``y_lo`` and ``determined``: False when the record's turning
    points leave some masses open (then :class:`FitWarning`). A spline
    (``"spline"``, the symmetric model whose f0 is a monotone cubic spline
    fitted along every branch) has ``intervals`` (K, also its ``degree``),
    ``values`` and ``slopes`` (f0 and its slope at the knots
    lo + k (hi - lo) / K, k = 0..K), ``rms`` and ``max_abs`` of the model
    run over the record and ``identified`` (as everett's).
    ``validation_rms`` (:func:`fit`'s ``validate``, else None): the model's
    RMS error run from rest over the validation record, what the choice was
    scored on.
    """

    def __init__(self, result, dtype, capacity, delay=0, candidates=None, creep=None,
                 rate=None):
        self.__dict__.update(result)
        self.kind = result.get("kind", "poly")
        self.t_degree = result.get("t_degree")
        if self.kind == "poly" and result["method"] != "branches":
            self.method = {v: k for k, v in _METHODS.items()}[result["method"]]
        # an int, or a float with a sub-sample delay (the model file's 3.5)
        self.delay = delay if isinstance(delay, float) and not delay.is_integer() else int(delay)
        self.identified = result.get("identified")
        self.candidates = candidates or []
        self.creep = creep
        self.creep_tau = [creep["tau"]] if creep else []
        self.creep_weight = [creep["weight"]] if creep else []
        self.rate = rate
        self.rate_tau = rate["tau"] if rate else None
        self.rate_weight = rate["weight"] if rate else None
        self.excitation = None  # the automatic choice's: set by fit()
        self.validation_rms = None  # fit(validate=...): the model's error on that record
        self.model = model_from(self.description(), dtype=dtype, capacity=capacity)

    def description(self):
        """The model's parameters as :func:`hyst.load_model` returns them
        (without the delay), its creep term included when it has one:
        ``save_model(path, **fit.description())``."""
        if self.kind == "everett":
            d = {"kind": "everett", "degree": self.degree, "lo": self.lo, "hi": self.hi,
                 "y_lo": self.y_lo, "terms": list(self.terms)}
        elif self.kind == "everett_grid":
            d = {"kind": "everett_grid", "lo": self.lo, "hi": self.hi, "y_lo": self.y_lo,
                 "knots": list(self.knots), "weights": list(self.weights)}
        elif self.kind == "spline":
            d = {"kind": "spline", "lo": self.lo, "hi": self.hi, "values": list(self.values),
                 "slopes": list(self.slopes)}
        else:
            d = {"kind": "poly", "coeffs": list(self.coeffs), "lo": self.lo, "hi": self.hi}
        if self.creep_tau:
            d.update(creep_tau=list(self.creep_tau), creep_weight=list(self.creep_weight))
        if self.rate:
            d.update(rate_tau=self.rate_tau, rate_weight=self.rate_weight)
        if self.identified is not None:
            d["identified"] = tuple(self.identified)
        return d

    def outside_identified(self, x):
        """How many of the inputs x lie outside ``identified``, the range the
        model was identified on (0 when its domain is that range):
        :func:`outside_identified`."""
        return outside_identified(self.description(), x)

    def save(self, path):
        """Writes the model file (hyst-model-text 1, delay included) that
        ``hyst sim --model`` reads."""
        save_model(path, delay=self.delay, **self.description())

    def header(self, name, compensator=False, intervals=None, rows=None):
        """The firmware header (C source text) declaring ``hyst_poly_t name``
        (kind poly), ``hyst_everett_t name`` (kind everett),
        ``hyst_everett_grid_t name`` or ``hyst_spline_t name``; with
        ``compensator=True`` also its compensator's table, built and sealed
        (:func:`header_text`)."""
        return header_text(name, **self.description(), compensator=compensator,
                           intervals=intervals, rows=rows)

    def __getattr__(self, name):
        # only called for names not found on the Fit itself
        return getattr(self.__dict__["model"], name)

    def make_model(self, *, dtype=None, capacity=None):
        """A new model, at rest, of everything the fit chose: its kind's
        curve and its creep term (``dtype`` and ``capacity`` the Fit's
        unless given). ``hyst.Model(f.coeffs, f.lo, f.hi)`` would drop the
        creep term and the asymmetric kind. The delay is the measurement's,
        not the model's: the model's output k goes with the measured output
        k + ``delay``."""
        return model_from(self.description(),
                          dtype=self.model.dtype if dtype is None else dtype,
                          capacity=self.model.capacity if capacity is None else capacity)

    def make_compensator(self, *, dtype=None, capacity=None, intervals=0, rows=None):
        """The compensator of :meth:`make_model`'s model (creep term
        included): desired output in, drive out (:func:`compensator_from`;
        ``intervals=N`` the tabulated one firmware runs)."""
        return compensator_from(self.description(),
                                dtype=self.model.dtype if dtype is None else dtype,
                                capacity=self.model.capacity if capacity is None else capacity,
                                intervals=intervals, rows=rows)

    def predict(self, x):
        """Outputs of a fresh model (at A0) for the inputs x; ``model`` is untouched."""
        return self.make_model().process(np.ascontiguousarray(x, dtype=self.model.dtype))

    def __repr__(self):
        creep = (f", creep_tau={self.creep_tau[0]:.6g}, creep_weight={self.creep_weight[0]:.9g}"
                 if self.creep_tau else "")
        if self.kind == "everett":
            t = ", ".join(f"{v:.9g}" for v in self.terms)
            return (f"Fit(kind='everett', degree={self.degree}, t_degree={self.t_degree}, "
                    f"terms=[{t}], "
                    f"y_lo={self.y_lo:.9g}, lo={self.lo:.9g}, hi={self.hi:.9g}, "
                    f"rms={self.rms:.6g}{creep})")
        if self.kind == "everett_grid":
            k = ", ".join(f"{v:.9g}" for v in self.knots)
            return (f"Fit(kind='everett_grid', intervals={self.degree}, knots=[{k}], "
                    f"y_lo={self.y_lo:.9g}, rms={self.rms:.6g}{creep})")
        if self.kind == "spline":
            v = ", ".join(f"{v:.9g}" for v in self.values)
            return (f"Fit(kind='spline', intervals={self.intervals}, values=[{v}], "
                    f"lo={self.lo:.9g}, hi={self.hi:.9g}, rms={self.rms:.6g}{creep})")
        c = ", ".join(f"{v:.9g}" for v in self.coeffs)
        max_abs = f", max_abs={self.max_abs:.6g}" if "max_abs" in self.__dict__ else ""
        return (f"Fit(coeffs=[{c}], lo={self.lo:.9g}, hi={self.hi:.9g}, "
                f"rms={self.rms:.6g}{max_abs}, method={self.method!r}{creep})")


#: Delays tried by fit() when none is given, the parsimony margin of the
#: choice, and the resolution below which a hold-out error counts as that
#: fraction of the output's range (a simulated record fitted to its own
#: rounding): the same as ``hyst fit`` without --degree (docs/cli.md).
MAX_DELAY = _hyst.FIT_MAX_DELAY
PARSIMONY = _hyst.FIT_PARSIMONY
RESOLUTION = _hyst.FIT_RESOLUTION
#: Parameters a creep term adds in the choice: its weight and its time
#: constant (hyst fit's FIT_CREEP_PARAMETERS).
CREEP_PARAMS = _hyst.FIT_CREEP_PARAMETERS


#: The kinds fit() knows.
KINDS = ("poly", "everett", "everett_grid", "spline")
#: Those it compares with kind=None (as ``hyst fit`` without --kind: every one).
AUTO_KINDS = ("poly", "everett", "everett_grid", "spline")
# The kinds without t_degree, their degree a polynomial's or their knot intervals.
_NO_T_DEGREE = ("poly", "everett_grid", "spline")


def _fit_one(x, y, kind, degree, method, lo, hi, skip, delay, t_degree=None):
    if kind == "everett_grid":  # degree: the grid's knot intervals
        return _hyst.fit_grid(x, y, degree, lo, hi, skip, delay)
    if kind == "spline":  # degree: the spline's knot intervals
        return _hyst.fit_spline(x, y, degree, lo, hi, skip, delay)
    if kind == "everett":
        return _hyst.fit_everett(x, y, degree, lo, hi, skip, delay,
                                 -1 if t_degree is None else int(t_degree))
    return _hyst.fit(x, y, degree, _METHODS[method], lo, hi, skip, delay)


def _refusal(res):
    """Why the fitted parameters give no model, or None when they do."""
    if res.get("kind") in ("everett", "everett_grid", "spline"):
        st = res["curve_status"]
        return None if st == _hyst.Status.OK else _status_words(st)
    return None if res["increasing"] else "f0 not increasing"


_NO_RECORD = np.empty(0)


def _score(x, y, kind, deg, k, d, method, lo, hi, skip, creep_tau, validate=None):
    """One candidate (kind, degree deg, t_degree k, delay d) scored on the
    hold-out splits, or on the validation record validate = (vx, vy); with
    creep_tau >= 0 also its creep term (hyst fit's fit_score(),
    tools/cli/fit_select.c)."""
    vx, vy = validate if validate is not None else (_NO_RECORD, _NO_RECORD)
    c = _hyst.score(x, y, _FIT_KINDS[kind], int(deg),
                    0 if k is None else int(k), _METHODS[method], lo, hi, skip, int(d),
                    creep_tau, vx, vy)
    c["status"] = _status(c)
    return c


_FIT_KINDS = {"poly": _hyst.FIT_POLY, "everett": _hyst.FIT_EVERETT,
              "everett_grid": _hyst.FIT_GRID, "spline": _hyst.FIT_SPLINE}


def _status_words(st):
    """A fit's or its curve's refusal (a status other than OK) in words."""
    if st == _hyst.Status.ERR_NOT_MONOTONE:
        return "E not monotone"
    if st == _hyst.Status.ERR_NOT_INCREASING:  # a spline's piece that falls
        return "f0 not increasing"
    return _hyst.Status(st).name


def _status(c):
    """Why a candidate of the tool's choice has no score ("OK" when it has
    one): its fit's status, an f0 that does not increase, an E the library
    refuses."""
    st = c.pop("status_code")
    increasing = c.pop("increasing")
    if st != _hyst.Status.OK:
        return _status_words(st)
    return "OK" if increasing else "f0 not increasing"


def _select(x, y, kinds, method, lo, hi, skip, delay, t_degree=None, creep_tau=-1.0,
            rate_tau=-1.0, validate=None):
    """Every candidate (kind, degree, t_degree, delay) and the choice, made
    by the `hyst` tool's own code (fit_select(), tools/cli/fit_select.c):
    fitted on the first two thirds, scored by its prediction of the last
    third, alone and with its creep term (creep_tau >= 0); the fewest
    parameters within PARSIMONY of the lowest error win; between as many,
    the symmetric kind, then the lower error (the widened one at a tie in
    rounding). Returns the candidates, the
    index chosen (None: none), whether with its creep term, the chosen
    one's domain (lo, hi) when it is a widened one (fit_chosen_domain()),
    else None, and the search (fit_search(): with delay None the delays are
    scaled to the drive and a fraction of a sample may be chosen; its "x"
    is then the drive interpolated, which the model is fitted on; with
    rate_tau >= 0 its "with_rate", "rate_tau", "rate_holdout_rms" and
    "rate_without" say whether a rate term is kept, as ``hyst fit --rate``
    scores it: fit_rate_search()). validate = (vx, vy): every score is the
    prediction of that record instead (fitted on the whole of x, y; its
    "vx" the validation drive interpolated by the fraction chosen)."""
    mask = 0
    for k in kinds:
        mask |= _FIT_KINDS[k]
    vx, vy = validate if validate is not None else (_NO_RECORD, _NO_RECORD)
    cands, best, with_creep, domain, search = _hyst.select(
        x, y, mask, _METHODS[method], lo, hi, skip, -1 if delay is None else int(delay),
        -1 if t_degree is None else int(t_degree), creep_tau, rate_tau, vx, vy)
    for c in cands:
        c["status"] = _status(c)
    return cands, best, with_creep, domain, search


def _choose(cands, creep_tau=-1.0):
    """(index, with_creep) of the option hyst fit's rule picks among scored
    candidates ((None, False) if none was scored): fit_choose(), the tool's."""
    return _hyst.choose(cands, creep_tau)


def _creep_option(creep, what="creep"):
    """fit()'s ``creep`` (or ``rate``) as hyst fit's --creep (--rate): -1
    none, 0 auto, or the time constant."""
    if isinstance(creep, str) and creep in ("none", "auto"):
        return -1.0 if creep == "none" else 0.0
    try:
        tau = float(creep)
    except (TypeError, ValueError):
        tau = math.nan
    if isinstance(creep, (str, bool)) or not 1.0 <= tau <= 1e9:
        raise ValueError(f"{what} must be 'none', 'auto' or a time constant of 1 to 1e9 samples, "
                         f"not {creep!r}")
    return tau


def _final_creep(res, x, y, kind, skip, delay, tau, rate_tau=0.0):
    """The creep term of time constant tau (0: none) and the rate term of
    time constant rate_tau (0: none) fitted to the residual of the model
    fitted on the whole record (hyst fit's fit_final_creep()), the offset
    folded into the model (res: f0's constant or E's y_lo)."""
    n = len(x) - delay
    m = model_from(res, capacity=(n - skip) // 2 + 2)
    c = _hyst.holdout(m, x, y, skip, delay, n, tau, rate_tau if rate_tau > 0 else -1.0)["creep"]
    if c is None or not ((c["tau"] > 0 or c["rate_tau"] > 0) and math.isfinite(c["weight"]) and
                         math.isfinite(c["offset"]) and
                         (not c["rate_tau"] > 0 or math.isfinite(c["rate_weight"]))):
        what, t = ("creep", tau) if tau > 0 else ("rate", rate_tau)
        raise ValueError(f"the {what} term of time constant {t:g} samples could not be fitted "
                         "to the model's residual (a drive that never moves?)")
    if kind in ("everett", "everett_grid"):
        res["y_lo"] += c["offset"]
    elif kind == "spline":  # f0 moved as a whole, as hyst fit moves it
        res["values"] = [v + c["offset"] for v in res["values"]]
    else:
        res["coeffs"][-1] += c["offset"]
    return c


def fit(x, y, degree=None, *, kind=None, t_degree=None, method="joint", domain=None, skip=0,
        delay=None, creep="auto", rate="none", validate=None, dtype=np.float64,
        capacity=DEFAULT_CAPACITY):
    """Identifies a model from a recorded drive ``x`` and response ``y``.

    Sample i (skip <= i < n - delay) pairs x[i] with y[i + delay]; the domain
    is ``domain=(lo, hi)`` or the range of those inputs. ``kind="poly"``
    fits f0 (hyst_ident_fit(); ``method`` ``"joint"``, both branches in one
    least-squares problem, or ``"reflect"``, the paper's Eq. 14; or
    ``"branches"``, as ``hyst fit --method branches``: E of t-degree 0 of
    degree 1..EVERETT_MAX_DEGREE fitted along every branch the record
    takes, minor loops included, written as f0, ValueError where its powers
    of x cancel);
    ``kind="everett"`` the asymmetric kind's E (hyst_everett_fit_*(), degree
    1..EVERETT_MAX_DEGREE; the record starts from rest at sample ``skip``, its
    outputs fitted from the first input within 1 % of an end of the range on
    (every output where that input comes after the first third), inputs
    outside the domain are clamped as the model clamps them;
    ``t_degree`` fits only E's terms w^i t^j with j <= t_degree, the others
    0: major loops alone determine E of t_degree 1 at most, at any degree);
    ``kind="everett_grid"`` E on a grid of ``degree`` knot intervals and
    ``kind="spline"`` f0 a monotone cubic spline of ``degree`` uniform knot
    intervals (1..SPLINE_MAX_INTERVALS; without a degree 2..16 compared),
    fitted along every branch, minor loops included, as ``hyst fit --kind
    spline [--degree K]`` fits it. With no option, ``fit(x, y)`` chooses as
    ``hyst fit`` with no option does: ``degree=None`` (the default) chooses the degree, and
    ``delay=None`` (the default) the delay (0..MAX_DELAY, or up to 1/64 of
    the drive's period, then a fraction of a sample: the result's ``delay``
    is then a float, the model fitted on the drive interpolated), by
    hold-out exactly as ``hyst fit`` without --degree does; with a degree
    given, ``delay=None`` chooses the delay of that model as ``hyst fit
    --degree D`` without --delay does. The kind too when ``kind`` is None
    (AUTO_KINDS compared, as ``hyst fit`` without --kind: poly, everett,
    everett_grid and spline; everett of each degree with each t_degree
    0..degree-1, or only the one given; the parameter count is degree + 1
    for poly, E's terms fitted + 1 for everett, K + 3 for a spline of K
    intervals): every candidate is in the result's ``candidates`` (dicts:
    kind, degree, t_degree (None for poly), delay, params, holdout_rms,
    fit_rms, status, chosen; with a creep term scored also creep_tau (0:
    none), creep_weight, creep_holdout_rms, with_creep: chosen with it).
    With a degree given, ``kind=None`` means poly and ``t_degree=None`` all
    of E's terms (degree - 1); f0 of a given degree, or chosen among f0
    alone (``kind="poly"``), on a drive with minor loops is biased (its
    estimator takes every sample for a major branch's): a
    :class:`FitWarning` says so, as ``hyst fit --degree`` and ``--kind tcm``
    warn.

    ``creep`` chooses a creep term as ``hyst fit --creep`` does
    (docs/creep.md): ``"auto"`` (the default) scores each candidate alone
    and with one lag of the input, its time constant the best of 100, 200,
    500, ..., 20000 samples on the hold-out (those up to the record's
    length) and its weight one parameter more, by the same rule (with a
    degree given: the model with it when the model alone errs by more than
    PARSIMONY over it); ``"none"`` fits none; a number TAU (1..1e9) always
    fits one lag of TAU samples. The creep term chosen gets its weight and a
    constant from the residual of the model fitted on the whole record, the
    constant folded into the model (f0's constant, E's y_lo): the result's
    ``creep``, ``creep_tau`` and ``creep_weight`` (:class:`Fit`).

    ``rate`` chooses a rate term (docs/rate.md) as ``hyst fit --rate`` does,
    with ``degree=None`` only: ``"none"`` (the default), ``"auto"`` (the
    choice scored again with one of time constant 1 sample, 1/256 and 1/64
    of the drive's period, kept when it lowers the hold-out error by more
    than PARSIMONY) or a time constant TAU (1..1e9 samples, always). Its
    weight is fitted with the creep lag's and the constant on the whole
    record: the result's ``rate`` (tau, weight, holdout_rms,
    holdout_rms_without), ``rate_tau`` and ``rate_weight`` (None without
    one).

    ``validate=(x2, y2)``, a second record of the same actuator (validation
    data, as ``hyst fit --validate``): every choice above (kind, degree,
    delay, creep, rate) is made on it instead of the hold-out, each
    candidate fitted on the whole of (x, y) from ``skip`` on and scored by
    its RMS error run from rest over (x2, y2) from ``skip`` on (the
    candidates' ``holdout_rms`` is that error; ``excitation`` then says
    what x2 tests the choice on). The model is fitted on (x, y) as without
    it. Returns a :class:`Fit`.
    """
    if method not in _METHODS and method != "branches":
        raise ValueError(f"method must be one of {sorted(_METHODS) + ['branches']}, "
                         f"not {method!r}")
    if kind is not None and kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS} or None, not {kind!r}")
    if t_degree is not None and kind != "everett":
        raise ValueError("t_degree needs kind='everett'")
    if t_degree is not None and not (0 <= int(t_degree) < EVERETT_MAX_DEGREE and (
            degree is None or int(t_degree) < int(degree))):
        raise ValueError(f"t_degree must be 0..degree-1, not {t_degree!r}")
    creep_tau = _creep_option(creep)
    rate_tau = _creep_option(rate, "rate")
    if rate_tau >= 0 and degree is not None:
        raise ValueError("rate applies to the automatic choice (degree=None), as hyst fit --rate")
    lo, hi = (0.0, 0.0) if domain is None else (float(domain[0]), float(domain[1]))
    x = _record("x", x)
    y = _record("y", y)
    skip = _samples("skip", skip)
    if delay is not None:
        delay = _samples("delay", delay)
    record = _check_record(x, y, skip, delay or 0)
    branches = method == "branches"
    if branches:  # f0 fitted along every branch: E of t-degree 0, written as f0
        if kind not in (None, "poly"):
            raise ValueError(f"method='branches' fits kind poly (f0 along every branch), not "
                             f"kind={kind!r}")
        if degree is not None and int(degree) > EVERETT_MAX_DEGREE:
            raise ValueError(f"method='branches' fits f0 of degree 1..{EVERETT_MAX_DEGREE} "
                             f"(E of t-degree 0), not {degree!r}")
        kind, t_degree, method = "everett", 0, "joint"
    # f0 of a given degree, or chosen among f0 alone: warned of below (its degree, or None)
    minor_loops = (kind == "poly" or (kind is None and degree is not None)) and record["minor"] > 0
    degree_given = degree
    if validate is not None:  # refused as the record is (hyst fit --validate)
        if not isinstance(validate, (tuple, list)) or len(validate) != 2:
            raise ValueError("validate must be a record (x2, y2)")
        vx, vy = _record("validate's x", validate[0]), _record("validate's y", validate[1])
        if len(vx) != len(vy):
            raise ValueError(f"validate's x and y differ in length ({len(vx)}, {len(vy)})")
        if len(vx) < skip + 2:
            raise ValueError(f"validate: {max(len(vx) - skip, 0)} samples after skip {skip}: a "
                             "validation record needs two or more")
        _check_record(vx, vy, skip, 0, ("validate's x", "validate's y"))
        validate = (vx, vy)
    cands, chosen, with_creep, fraction, search = None, None, False, 0.0, {}
    as_poly = branches
    if degree is None:
        kinds = AUTO_KINDS if kind is None else (kind,)
        cands, best, with_creep, widened, search = _select(
            x, y, kinds, method, lo, hi, skip, delay,
            None if t_degree is None else int(t_degree), creep_tau, rate_tau, validate)
        if best is None:
            raise ValueError("no candidate gave a model (an increasing f0, a monotone E) "
                             "that could predict "
                             + ("the validation record" if validate is not None
                                else "the last third of the record")
                             + (" with the creep term given" if creep_tau > 0 else ""))
        chosen = cands[best]
        kind, degree, delay = chosen["kind"], chosen["degree"], chosen["delay"]
        if search["x"] is not None:  # a sub-sample delay: the drive interpolated
            x = np.asarray(search["x"], dtype=np.float64)
            fraction = search["delay_fraction"]
            if validate is not None:  # and the validation record's, as the tool's
                validate = (np.asarray(search["vx"], dtype=np.float64), validate[1])
        t_degree = chosen["t_degree"]
        # E of t-degree 0 is the symmetric model: written as f0, as hyst fit writes it
        as_poly = kind == "everett" and t_degree == 0 and ("poly" in kinds or branches)
        if widened is not None:
            # the domain the tool fits it on: the inputs' range widened, f0
            # or E continued beyond the inputs (fit_chosen_domain())
            lo, hi = widened
        for i, c in enumerate(cands):
            c["chosen"] = i == best
            c["with_creep"] = i == best and with_creep
    elif delay is None:  # the delay of the model given, as hyst fit --degree D chooses it
        k = 0 if (kind or "poly") in _NO_T_DEGREE else (
            int(degree) - 1 if t_degree is None else int(t_degree))
        vx, vy = validate if validate is not None else (_NO_RECORD, _NO_RECORD)
        g = _hyst.given_delay(x, y, _FIT_KINDS[kind or "poly"], int(degree), k,
                              _METHODS[method], lo, hi, skip, vx, vy)
        delay = g["delay"]
        if g["x"] is not None:
            x = np.asarray(g["x"], dtype=np.float64)
            fraction = g["delay_fraction"]
            if validate is not None:
                validate = (np.asarray(g["vx"], dtype=np.float64), validate[1])
    if degree is not None and (creep_tau >= 0 or validate is not None) and \
            len(x) > skip + int(delay):
        # the model as given, its creep term scored by the same hold-out (or
        # on the validation record, which scores the model even without one)
        k = None if (kind or "poly") in _NO_T_DEGREE else (
            int(degree) - 1 if t_degree is None else int(t_degree))
        chosen = _score(x, y, kind or "poly", int(degree), k, int(delay), method, lo, hi, skip,
                        creep_tau, validate)
        with_creep = (chosen["creep_tau"] > 0 and math.isfinite(chosen["creep_holdout_rms"]) and
                      (creep_tau > 0 or not chosen["holdout_rms"] <=
                       chosen["creep_holdout_rms"] * (1 + PARSIMONY)))
    res = _fit_one(x, y, kind or "poly", int(degree), method, lo, hi, skip, int(delay),
                   t_degree)
    if res.get("kind") == "everett_grid" and not res["determined"]:
        warnings.warn(_hyst.FIT_GRID_UNDETERMINED, FitWarning, stacklevel=2)
    if res.get("kind", "poly") != "everett_grid" and len(x) > skip + int(delay):
        # a domain wider than the inputs: the range f0 (or E) was identified
        # on is recorded, as hyst fit --save records it
        used = x[skip:len(x) - int(delay)]
        a, b = float(np.nanmin(used)), float(np.nanmax(used))
        if res["lo"] < a or b < res["hi"]:
            res["identified"] = (max(a, res["lo"]), min(b, res["hi"]))
    creep_info = rate_info = None
    with_rate = search.get("with_rate", False)
    if (with_creep or with_rate) and _refusal(res) is None:
        c = _final_creep(res, x, y, kind or "poly", skip, int(delay),
                         chosen["creep_tau"] if with_creep else 0.0,
                         search["rate_tau"] if with_rate else 0.0)
        if with_creep:
            creep_info = {"tau": c["tau"], "weight": c["weight"], "offset": c["offset"],
                          "rms": c["fit_rms"], "max_abs": c["max_abs"],
                          "holdout_rms": chosen["creep_holdout_rms"],
                          "holdout_rms_without": chosen["holdout_rms"]}
        if with_rate:
            rate_info = {"tau": c["rate_tau"], "weight": c["rate_weight"],
                         "holdout_rms": search["rate_holdout_rms"],
                         "holdout_rms_without": search["rate_without"]}
    if as_poly and _refusal(res) is None:
        res = _written_as_poly(res)
        if branches and res["kind"] != "poly":
            raise ValueError(f"method='branches': E of degree {res['degree']} fitted along the "
                             f"branches gives no f0 in powers of x on [{res['lo']:.9g}, "
                             f"{res['hi']:.9g}] (they cancel far from 0, or f0 falls): shift "
                             "the inputs, or fit kind='everett', t_degree=0")
    f = Fit(res, dtype, capacity, delay=int(delay) + fraction if fraction else int(delay),
            candidates=cands, creep=creep_info, rate=rate_info)
    if cands is not None and validate is not None:
        f.excitation = _validation_excitation(x, skip, len(x) - int(delay), validate,
                                              int(delay))
    elif cands is not None:
        f.excitation = _excitation(x, y, skip, len(x) - int(delay), int(delay))
    if minor_loops:
        _warn_minor_loops(record["minor"], None if degree_given is None else int(degree_given))
    if validate is not None and chosen is not None:
        f.validation_rms = (search["rate_holdout_rms"] if with_rate
                            else chosen["creep_holdout_rms"] if with_creep
                            else chosen["holdout_rms"])
    return f


def _written_as_poly(res):
    """The chosen E of t-degree 0 (res, its creep term's offset in y_lo) as
    the model it is, the symmetric one, whose compensator is a table: f0 in
    powers of x (hyst fit's fit_poly_from_everett()), ``method`` "branches"
    and ``everett`` the E it was fitted as; res itself where that refuses it
    (powers of x that cancel)."""
    coeffs = _hyst.poly_from_everett(res["degree"], res["lo"], res["hi"], res["y_lo"],
                                     res["terms"])
    if coeffs is None:
        return res
    out = {"kind": "poly", "degree": res["degree"], "lo": res["lo"], "hi": res["hi"],
           "coeffs": coeffs, "method": "branches", "rms": res["rms"], "used": res["used"],
           "increasing": True,
           "everett": {k: res[k] for k in ("degree", "t_degree", "y_lo", "terms")}}
    if res.get("identified") is not None:
        out["identified"] = res["identified"]
    return out


def _warn_minor_loops(minor, degree):
    """hyst fit's warning of f0 of a given degree (None: of the degree
    chosen among f0 alone, kind="poly") fitted on a drive with minor loops
    (FitWarning): biased, the estimator taking every sample for a major
    branch's."""
    what, leave = ((f"of degree {degree}", "degree=None to let fit choose") if degree is not None
                   else ("of every degree", "kind=None to let fit compare E too"))
    warnings.warn(f"x has {minor} reversal{'' if minor == 1 else 's'} inside its range (minor "
                  f"loops): f0 {what} is biased, its fit taking every rising sample for the "
                  f"major ascending branch and every falling one for the descending; leave "
                  f"{leave}, or fit method='branches' (f0 along every branch)", FitWarning,
                  stacklevel=3)


def _validation_excitation(x, skip, end, validate, delay):
    """What the validation record tested the choice on (fit_validation_excitation(),
    as hyst fit --validate prints it), with its warnings (FitWarning)."""
    e = _hyst.validation_excitation(x, skip, end, validate[0], validate[1], delay)
    if e["span"] < _hyst.FIT_HOLDOUT_MIN_SPAN:
        warnings.warn(f"the validation record's inputs span {100 * e['span']:.3g} % of the "
                      "range of the record's: the choice was not tested over the rest of it",
                      FitWarning, stacklevel=3)
    if e["minor"] == 0:
        warnings.warn("the validation record holds no minor loop (every reversal at an end of "
                      "the record's inputs' range or beyond): the choice was not tested on "
                      "minor loops", FitWarning, stacklevel=3)
    return e


def _excitation(x, y, skip, end, delay):
    """What the hold-out's last third tested the choice on (fit_excitation(),
    as hyst fit prints it), with hyst fit's warnings (FitWarning)."""
    e = _hyst.excitation(x, y, skip, end, delay)
    if e["span"] < _hyst.FIT_HOLDOUT_MIN_SPAN:
        warnings.warn(f"the last third's inputs span {100 * e['span']:.3g} % of the record's "
                      "range: the choice was not tested over the rest of it", FitWarning,
                      stacklevel=3)
    if e["minor"] == 0:
        warnings.warn("the last third holds no minor loop (every reversal at an end of the "
                      "inputs' range): the choice was not tested on minor loops", FitWarning,
                      stacklevel=3)
    return e
