# SPDX-License-Identifier: MIT
"""Model files in the format hyst-model-text 1, the one ``hyst fit --save``
writes and ``hyst sim --model`` reads (docs/cli.md, "Model files"), also
read and written by the MATLAB/Octave functions. Four kinds: ``poly`` (f0,
coefficients highest power first), ``everett`` (the asymmetric kind's
branch function E), ``everett_grid`` (E of a Preisach density constant
on each cell of a grid: ``knots``, ``weights``) and ``spline`` (f0 a
monotone cubic spline on uniform knots: ``values``, ``slopes``)."""
import math
import os
import tempfile

MAGIC = "hyst-model-text 1"
_MAX_COEFFS = 10  # HYST_MAX_DEGREE + 1 in the default build
_MAX_BYTES = 1 << 20  # MODEL_TEXT_MAX_BYTES: a larger file is refused unread
_EVERETT_MAX_DEGREE = 4  # HYST_EVERETT_MAX_DEGREE
_CREEP_MAX_TERMS = 4  # HYST_CREEP_MAX_TERMS
_GRID_MAX_INTERVALS = 12  # HYST_EVERETT_GRID_MAX_INTERVALS
#: The kinds whose compensator has no table (it solves each drive): why, as
#: ``hyst inv`` and ``hyst header`` say it.
NO_TABLE = {"everett_grid": "its compensator solves each branch in closed form"}


def everett_terms(degree):
    """Coefficients of E at total degree ``degree``: w^i t^j, i >= 1, i + j <= degree."""
    return degree * (degree + 1) // 2


class ModelFileError(ValueError):
    """A malformed model file; the message names the file and the line."""


def _creep_args(creep_tau, creep_weight):
    """Checks a creep term as the model file holds it: both or neither, 1 to
    4 of each, as many, time constants >= 1 (samples), finite numbers.
    Returns (tau, weight) as lists of floats, or (None, None)."""
    if creep_tau is None and creep_weight is None:
        return None, None
    if creep_tau is None or creep_weight is None:
        raise ValueError("a creep term needs creep_tau and creep_weight (both or neither)")
    tau = [float(v) for v in creep_tau]
    weight = [float(v) for v in creep_weight]
    if not tau and not weight:
        return None, None
    if len(tau) != len(weight) or not 1 <= len(tau) <= _CREEP_MAX_TERMS:
        raise ValueError(f"creep_tau and creep_weight: 1 to {_CREEP_MAX_TERMS} numbers each, "
                         "as many of each (one per creep term)")
    if not all(math.isfinite(v) for v in tau + weight) or not all(v >= 1.0 for v in tau):
        raise ValueError("creep_tau: time constants of at least 1 sample; creep_weight: finite "
                         "numbers")
    return tau, weight


def _rate_args(rate_tau, rate_weight):
    """Checks a rate term as the model file holds it: both or neither, one
    number each; returns [tau, weight] or [] (the reader checks the values)."""
    if rate_tau is None and rate_weight is None:
        return []
    if rate_tau is None or rate_weight is None:
        raise ValueError("a rate term needs rate_tau and rate_weight (both or neither)")
    return [float(rate_tau), float(rate_weight)]


def _model_call(what, kind, lo, hi, delay, coeffs, degree, y_lo, terms, creep_tau,
                creep_weight, *before, identified=None, rate=(), knots=(), weights=(), values=(),
                slopes=()):
    """The extension's model_write or model_header (tools/model_text), the
    model given by its parts (checked there as the reader checks a file)."""
    from . import _hyst
    args = [kind, float(lo), float(hi)]
    if what == "model_write":
        args.append(float(delay))
    args += [list(coeffs or []), float(degree or 0), float(y_lo or 0.0), list(terms or []),
             list(creep_tau or []), list(creep_weight or [])]
    if what == "model_write":
        args.append([float(v) for v in identified] if identified is not None else [])
    return getattr(_hyst, what)(*before, *args, rate=list(rate), knots=list(knots or []),
                                weights=list(weights or []), values=list(values or []),
                                slopes=list(slopes or []))


def load_model(path):
    """Reads a model file. Returns a dict: ``kind`` ("poly", "everett",
    "everett_grid" or "spline"),
    ``lo``, ``hi``, ``delay`` (samples, 0 when absent; an int, or a float
    with a sub-sample delay such as 3.5: the model's input is then
    (1 - f) x[k] + f x[k - 1]), ``identified`` (only when the file records
    it: (LO, HI), the range of the inputs the model was identified on, its
    branches continued beyond it up to [lo, hi]) and, for poly,
    ``coeffs`` (highest power first); for everett ``y_lo``, ``degree`` and
    ``terms`` (e[i-1][j] of w^i t^j, i = 1..degree, then j = 0..degree-i);
    for everett_grid ``y_lo``, ``knots`` (lo first, hi last) and ``weights``
    (the cells' masses, weight[i (i + 1) / 2 + j]); for spline ``values``
    and ``slopes`` (f0 and its slope at the K + 1 knots lo + k (hi - lo) / K);
    with a creep term also ``creep_tau`` (time constants, samples) and
    ``creep_weight`` (lists of 1 to 4 numbers, one per lag; the keys are
    absent when the file has none); with a rate term also ``rate_tau``
    (samples) and ``rate_weight`` (numbers; absent when the file has none:
    :func:`model_from` applies it, :func:`save_model` and
    :func:`header_text` write it). The file is read by the format's one
    reader in C (tools/model_text), the one ``hyst sim --model`` and the
    MATLAB/Octave functions call: a malformed file raises
    :class:`ModelFileError` with its words, naming the file, the line and
    the field."""
    from . import _hyst  # the extension: this module stays importable without it
    with open(path, "rb") as f:
        data = f.read(_MAX_BYTES + 1)
    model = _hyst.model_parse(data, os.fsdecode(path))
    if isinstance(model, str):
        raise ModelFileError(model)
    return model


def _everett_args(degree, y_lo, terms):
    """Checks an everett description; returns (degree, y_lo, terms) as numbers."""
    if degree is None or y_lo is None or terms is None:
        raise ValueError("kind 'everett' needs degree, y_lo and terms")
    if int(degree) != degree or not 1 <= degree <= _EVERETT_MAX_DEGREE:
        raise ValueError(f"degree must be a whole number 1 to {_EVERETT_MAX_DEGREE}")
    terms = [float(t) for t in terms]
    if len(terms) != everett_terms(int(degree)):
        raise ValueError(f"degree {int(degree)} needs {everett_terms(int(degree))} terms")
    if not all(math.isfinite(v) for v in terms + [float(y_lo)]):
        raise ValueError("terms and y_lo must be finite")
    return int(degree), float(y_lo), terms


def _grid_args(y_lo, knots, weights):
    """Checks an everett_grid description; returns (y_lo, knots, weights) as
    numbers (their values are checked by the reader's checks in C)."""
    if y_lo is None or knots is None or weights is None:
        raise ValueError("kind 'everett_grid' needs y_lo, knots and weights")
    knots = [float(v) for v in knots]
    weights = [float(v) for v in weights]
    if not 2 <= len(knots) <= _GRID_MAX_INTERVALS + 1:
        raise ValueError(f"knots: 2 to {_GRID_MAX_INTERVALS + 1} numbers")
    return float(y_lo), knots, weights


def _spline_args(kind, values, slopes, **others):
    """Checks a spline description (``others``: the other kinds' keys, None
    here); returns (values, slopes) as numbers (their counts and values are
    checked by the reader's checks in C). Another kind: refuses values and
    slopes, returns them as given (None)."""
    if kind != "spline":
        if values is not None or slopes is not None:
            raise ValueError("values and slopes belong to kind 'spline'")
        return values, slopes
    given = [k for k, v in others.items() if v is not None]
    if given:
        raise ValueError(f"kind 'spline' has values and slopes, not {', '.join(given)}")
    if values is None or slopes is None:
        raise ValueError("kind 'spline' needs values and slopes")
    return [float(v) for v in values], [float(v) for v in slopes]


def _poly_args(coeffs, kind, degree, y_lo, terms):
    """Checks a poly description; returns its coefficients as numbers."""
    if kind != "poly":
        raise ValueError("kind must be 'poly', 'everett', 'everett_grid' or 'spline', "
                         f"not {kind!r}")
    if degree is not None or y_lo is not None or terms is not None:
        raise ValueError("degree, y_lo and terms belong to kind 'everett'")
    coeffs = [float(c) for c in coeffs] if coeffs is not None else []
    if not 2 <= len(coeffs) <= _MAX_COEFFS or not all(math.isfinite(v) for v in coeffs):
        raise ValueError(f"2 to {_MAX_COEFFS} finite coefficients are needed")
    return coeffs


def save_model(path, coeffs=None, lo=None, hi=None, delay=0, *, kind="poly", degree=None,
               y_lo=None, terms=None, creep_tau=None, creep_weight=None, identified=None,
               rate_tau=None, rate_weight=None, knots=None, weights=None, values=None,
               slopes=None):
    """Writes a model file (17 significant digits: the same doubles read
    back), replacing ``path`` whole or not at all. ``kind="everett"`` writes
    the asymmetric kind from ``degree``, ``y_lo`` and ``terms`` (no
    ``coeffs``); ``kind="everett_grid"`` the kind on a grid from ``y_lo``,
    ``knots`` and ``weights``, ``kind="spline"`` f0 a monotone cubic spline
    from ``values`` and ``slopes`` (2 to 33 of each, slopes >= 0), as ``hyst
    fit --save`` writes them. ``creep_tau`` and ``creep_weight`` (both or neither, 1 to 4
    numbers each, time constants >= 1 sample) add a creep term, written after
    the model as ``hyst fit --save`` writes it; ``rate_tau`` and
    ``rate_weight`` (both or neither, one number each, the time constant >= 1
    sample) a rate term after it (docs/rate.md). ``delay`` may hold a
    fraction of a sample (3.5); ``identified=(LO, HI)`` records the range
    the model was identified on (within [lo, hi]).
    ``save_model(path, **load_model(other))`` copies a file."""
    creep_tau, creep_weight = _creep_args(creep_tau, creep_weight)
    rate = _rate_args(rate_tau, rate_weight)
    if lo is None or hi is None:
        raise ValueError("a domain lo, hi is needed")
    values, slopes = _spline_args(kind, values, slopes, coeffs=coeffs, degree=degree, y_lo=y_lo,
                                  terms=terms, knots=knots, weights=weights)
    if kind == "everett":
        if coeffs is not None:
            raise ValueError("kind 'everett' has terms, not coeffs")
        degree, y_lo, terms = _everett_args(degree, y_lo, terms)
    elif kind == "everett_grid":
        if coeffs is not None or degree is not None or terms is not None:
            raise ValueError("kind 'everett_grid' has y_lo, knots and weights, not coeffs, "
                             "degree or terms")
        y_lo, knots, weights = _grid_args(y_lo, knots, weights)
    elif kind != "spline":
        if knots is not None or weights is not None:
            raise ValueError("knots and weights belong to kind 'everett_grid'")
        coeffs = _poly_args(coeffs, kind, degree, y_lo, terms)
    text = _model_call("model_write", kind, lo, hi, delay, coeffs, degree, y_lo, terms,
                       creep_tau, creep_weight, identified=identified, rate=rate, knots=knots,
                       weights=weights, values=values, slopes=slopes)
    path = _regular_target(path)
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=os.path.basename(path) + ".")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


def _regular_target(path):
    """The file a model is written to, as hyst fit --save writes it: a
    symbolic link is written through (the file it names replaced, the link
    kept); a link to nothing, a directory, a device, a pipe or a socket is
    refused (OSError), nothing written: a rename would put a file in its
    place."""
    path = os.fspath(path)
    if os.path.islink(path):
        target = os.path.realpath(path)
        if not os.path.exists(target):
            raise FileNotFoundError(f"{path}: a symbolic link to nothing: cannot write the model")
        path = target
    if os.path.isdir(path):
        raise IsADirectoryError(f"{path}: is a directory: cannot write the model")
    if os.path.exists(path) and not os.path.isfile(path):
        raise OSError(f"{path}: not a regular file (a device, pipe or socket): cannot write "
                      "the model")
    return path


def _check_curve(kind, coeffs, lo, hi, degree, y_lo, terms, knots, weights, values, slopes):
    """Raises the library's HystError (ERR_NOT_INCREASING, ERR_NOT_MONOTONE...)
    for a curve firmware's init would refuse, as hyst header refuses it: no
    header of a model that cannot run."""
    from . import _api  # the constructors; imported here, _api imports this module
    if kind == "everett":
        _api.ModelFromEverett(degree, lo, hi, y_lo, terms, capacity=2)
    elif kind == "everett_grid":
        _api.ModelFromEverettGrid(knots, weights, y_lo, capacity=2)
    elif kind == "spline":
        _api.ModelFromSpline(lo, hi, values, slopes, capacity=2)
    else:
        _api.Model(coeffs, lo, hi, capacity=2)


def _compensator_text(name, kind, coeffs, lo, hi, degree, y_lo, terms, intervals, rows,
                      values=None, slopes=None):
    """The compensator's table in float and in double, sealed: the text
    ``hyst header --compensator`` writes, from the same C (tools/model_text);
    kind spline's says how firmware builds it, and its size."""
    from . import _hyst  # the extension: this module stays importable without it
    everett = kind == "everett"
    if rows is not None and not everett:
        raise ValueError("rows applies to kind everett only: the compensators of kinds poly "
                         "and spline tabulate f0^-1 in one row (intervals alone)")
    if intervals is None:
        intervals = _hyst.EVERETT_INV_INTERVALS if everett else _hyst.INV_TABLE
    if rows is None:
        rows = _hyst.EVERETT_INV_ROWS if everett else 0
    if isinstance(intervals, bool) or isinstance(rows, bool) or int(intervals) != intervals \
            or int(rows) != rows or intervals < 0 or rows < 0:
        raise ValueError("intervals and rows are whole numbers")
    return _hyst.model_header_table(name, kind, float(lo), float(hi), list(coeffs or []),
                                    float(degree or 0), float(y_lo or 0.0), list(terms or []),
                                    int(intervals), int(rows), list(values or []),
                                    list(slopes or []))


def header_text(name, coeffs=None, lo=None, hi=None, *, kind="poly", degree=None, y_lo=None,
                terms=None, delay=0, compensator=False, intervals=None, rows=None,
                creep_tau=None, creep_weight=None, identified=None, rate_tau=None,
                rate_weight=None, knots=None, weights=None, values=None, slopes=None):
    """C header declaring the firmware's model as ``hyst fit --header``
    writes it: ``static const hyst_poly_t name`` (f0), or for
    ``kind="everett"`` ``static const hyst_everett_t name`` (degree, lo, hi,
    y_lo, e[i-1][j]), for ``kind="everett_grid"`` ``static const
    hyst_everett_grid_t name`` (knots, y_lo, weights), for ``kind="spline"``
    ``static const hyst_spline_t name`` (K, lo, hi, values, slopes; for
    hyst_curve_from_spline() with a table of HYST_SPLINE_TABLE_LEN(K)); no
    compensator's table for these two: their compensators need none;
    17-digit literals in HYST_REAL_C(), exact in a double build
    (HYST_USE_DOUBLE). ``delay`` and ``identified`` are not part of a
    header; they are accepted so that a :func:`load_model` dict can be
    passed whole.
    ``compensator=True`` adds the compensator's table, built here by the
    library in float and in double and sealed, as ``hyst header
    --compensator`` writes it: ``name_table``, ``name_seal``,
    ``name_INTERVALS`` (and ``name_ROWS``), for firmware's
    ``hyst_curve_inverse_table_const()`` or
    ``hyst_curve_everett_inverse_table_const()`` (``intervals``, ``rows``:
    the table's size, the library's defaults when None); kind
    ``everett_grid`` has no table (``hyst_curve_everett_grid_inverse()``
    solves each branch in closed form), nor kind ``spline`` without
    ``intervals`` (``hyst_curve_spline_inverse()`` solves each drive per
    sample): the header says so; with ``intervals`` the spline's is the
    table firmware builds at init (``hyst_curve_spline_inverse_table()``),
    measured here: ``name_INTERVALS`` and the calls. A creep term
    (``creep_tau``, ``creep_weight``, as :func:`save_model` takes them) adds
    ``#include "hyst/creep.h"``, ``name_CREEP_TERMS``, ``name_creep_tau`` and
    ``name_creep_weight`` after the model, as ``hyst header`` writes them,
    for ``hyst_creep_init(&creep, name_CREEP_TERMS, name_creep_tau,
    name_creep_weight, lo)`` (the compensator's table is the hysteresis
    model's alone: firmware subtracts ``hyst_creep_output()`` before it). A
    rate term (``rate_tau``, ``rate_weight``) adds ``#include "hyst/rate.h"``,
    ``name_rate_tau`` and ``name_rate_weight``, as ``hyst header`` writes
    them, for ``hyst_rate_init(&rate, name_rate_tau, name_rate_weight, lo)``."""
    creep_tau, creep_weight = _creep_args(creep_tau, creep_weight)
    rate = _rate_args(rate_tau, rate_weight)
    if not name.isidentifier() or not name.isascii():
        raise ValueError(f"{name!r} is not a C identifier")
    if not compensator and (intervals is not None or rows is not None):
        raise ValueError("intervals and rows size the compensator's table (compensator=True)")
    del delay, identified
    values, slopes = _spline_args(kind, values, slopes, coeffs=coeffs, degree=degree, y_lo=y_lo,
                                  terms=terms, knots=knots, weights=weights)
    if compensator and kind in NO_TABLE and (intervals is not None or rows is not None):
        raise ValueError(f"kind {kind} has no compensator table ({NO_TABLE[kind]})")
    # a spline's compensator is solved per sample unless intervals tabulates it
    solved = compensator and (kind in NO_TABLE or
                              (kind == "spline" and intervals is None and rows is None))
    if kind == "everett":
        degree, y_lo, terms = _everett_args(degree, y_lo, terms)
        what = (f"asymmetric model (branch function E),\n * degree {degree}, "
                f"domain [{float(lo):.9g}, {float(hi):.9g}]")
    elif kind == "everett_grid":
        y_lo, knots, weights = _grid_args(y_lo, knots, weights)
        what = (f"asymmetric model on a grid of {len(knots) - 1} knot intervals,\n * "
                f"domain [{float(lo):.9g}, {float(hi):.9g}]" +
                (";\n * the compensator: hyst_curve_everett_grid_inverse() of that curve,\n"
                 " * then hyst_init_kind() with hyst_kind_everett_grid_inverse; each\n"
                 " * branch solved in closed form, no table of its own" if compensator else ""))
    elif kind == "spline":
        what = (f"symmetric model, f0 a monotone cubic spline\n * of {len(values) - 1} knot "
                f"intervals, domain [{float(lo):.9g}, {float(hi):.9g}]" +
                (";\n * the compensator: hyst_curve_spline_inverse() of that curve,\n"
                 " * then hyst_init_kind() with hyst_kind_spline; each drive solved on\n"
                 " * its cubic piece per sample, no table of its own" if solved else ""))
    else:
        coeffs = _poly_args(coeffs, kind, degree, y_lo, terms)
        what = (f"major ascending curve f0,\n * degree {len(coeffs) - 1}, "
                f"domain [{float(lo):.9g}, {float(hi):.9g}]")
    _check_curve(kind, coeffs, lo, hi, degree, y_lo, terms, knots, weights, values, slopes)
    head = _model_call("model_header", kind, lo, hi, 0, coeffs, degree, y_lo, terms, creep_tau,
                       creep_weight, name, True, rate=rate, knots=knots, weights=weights,
                       values=values, slopes=slopes)
    table = (_compensator_text(name, kind, coeffs, lo, hi, degree, y_lo, terms, intervals, rows,
                               values, slopes)
             if compensator and not solved else "")
    from . import _hyst
    return (f"/* Generated by the Python package hyst: {what}. */\n" + head + table +
            _hyst.model_header(name, False, kind, 0.0, 1.0, [], 0.0, 0.0, [], [], []))

