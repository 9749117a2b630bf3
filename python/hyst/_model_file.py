# SPDX-License-Identifier: MIT
"""Model files in the format hyst-model-text 1, the one ``hyst fit --save``
writes and ``hyst sim --model`` reads (docs/cli.md, "Model files"), also
read and written by the MATLAB/Octave functions. Two kinds: ``poly`` (f0,
coefficients highest power first) and ``everett`` (the asymmetric kind's
branch function E)."""
import math
import os
import struct
import tempfile

MAGIC = "hyst-model-text 1"
_KEYS = ("kind", "lo", "hi", "coeffs", "delay", "y_lo", "degree", "terms", "creep_tau",
         "creep_weight")
#: Keys each kind needs, and keys only the other kind has.
_NEEDS = {"poly": ("lo", "hi", "coeffs"), "everett": ("lo", "hi", "y_lo", "degree", "terms")}
_REFUSES = {"poly": ("y_lo", "degree", "terms"), "everett": ("coeffs",)}
_MAX_COEFFS = 10  # HYST_MAX_DEGREE + 1 in the default build
_EVERETT_MAX_DEGREE = 4  # HYST_EVERETT_MAX_DEGREE
_CREEP_MAX_TERMS = 4  # HYST_CREEP_MAX_TERMS
_CREEP_KEYS = ("creep_tau", "creep_weight")
#: The comment line before a creep term, as the host tool writes it.
_CREEP_COMMENT = ("# creep: the output plus sum of creep_weight[k] s_k, s_k the input lagged "
                  "with time constant creep_tau[k] samples (from lo at rest)")


def everett_terms(degree):
    """Coefficients of E at total degree ``degree``: w^i t^j, i >= 1, i + j <= degree."""
    return degree * (degree + 1) // 2


class ModelFileError(ValueError):
    """A malformed model file; the message names the file and the line."""


def _numbers(path, no, key, values):
    """The numbers of one line (a whole number for delay and degree)."""
    whole = key in ("delay", "degree")
    numbers = []
    for i, v in enumerate(values, start=2):
        try:
            x = float(v)
        except ValueError:
            x = math.nan
        if not math.isfinite(x) or (whole and (x < 0 or x != int(x))):
            what = {"delay": "a whole number of samples",
                    "degree": "a whole number"}.get(key, "a finite number")
            raise ModelFileError(f"{path}:{no}: field {i}: {v!r} is not {what}")
        numbers.append(x)
    return numbers


def _creep_numbers(path, no, key, values):
    """The numbers of a creep_tau or creep_weight line, checked as the host
    tool checks them (tools/cli/model_file.c), with its messages."""
    needs = f"{key} needs 1 to {_CREEP_MAX_TERMS} numbers (one per creep term)"
    if not values:
        raise ModelFileError(f"{path}:{no}: field 2 is missing: {needs}")
    if len(values) > _CREEP_MAX_TERMS:
        raise ModelFileError(f"{path}:{no}: field {_CREEP_MAX_TERMS + 2}: one too many: {needs}")
    numbers = []
    for i, v in enumerate(values, start=2):
        try:
            x = float(v)
        except ValueError:
            x = math.nan
        if not math.isfinite(x):
            raise ModelFileError(f"{path}:{no}: field {i}: '{v}' is not a finite number")
        if key == "creep_tau" and not x >= 1.0:
            raise ModelFileError(f"{path}:{no}: field {i}: '{v}' is not a time constant of "
                                 "at least 1 sample")
        numbers.append(x)
    return numbers


def _creep_complete(path, seen, where):
    """Both creep keys or neither, as many numbers in each (the host tool's
    checks and messages, after the model's keys)."""
    has = [k for k in _CREEP_KEYS if k in seen]
    if len(has) == 1:
        other = _CREEP_KEYS[1] if has[0] == _CREEP_KEYS[0] else _CREEP_KEYS[0]
        raise ModelFileError(f"{path}:{where[has[0]]}: field 1: {has[0]} needs {other} too "
                             "(creep: both or neither)")
    if has and len(seen["creep_tau"]) != len(seen["creep_weight"]):
        n_w, n_t = len(seen["creep_weight"]), len(seen["creep_tau"])
        what = f"{n_w + 2} is missing" if n_w < n_t else f"{n_t + 2}: one too many"
        raise ModelFileError(f"{path}:{where['creep_weight']}: field {what}: creep_weight needs "
                             f"{n_t} numbers, one per creep_tau")


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


def _creep_text(tau, weight):
    """The creep term's lines after the model's, as the host tool writes them
    (cli_model_text())."""
    if tau is None:
        return ""
    return (_CREEP_COMMENT + "\ncreep_tau" + "".join(f" {v:.17g}" for v in tau) +
            "\ncreep_weight" + "".join(f" {v:.17g}" for v in weight) + "\n")


def load_model(path):
    """Reads a model file. Returns a dict: ``kind`` ("poly" or "everett"),
    ``lo``, ``hi``, ``delay`` (samples, 0 when absent) and, for poly,
    ``coeffs`` (highest power first); for everett ``y_lo``, ``degree`` and
    ``terms`` (e[i-1][j] of w^i t^j, i = 1..degree, then j = 0..degree-i);
    with a creep term also ``creep_tau`` (time constants, samples) and
    ``creep_weight`` (lists of 1 to 4 numbers, one per lag; the keys are
    absent when the file has none)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    if not lines or lines[0].strip() != MAGIC:
        first = lines[0].strip() if lines else ""
        raise ModelFileError(f"{path}:1: {first!r} is not {MAGIC!r} (another format or version)")
    seen, where = {}, {}
    for no, line in enumerate(lines[1:], start=2):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        key, values = fields[0], fields[1:]
        if key not in _KEYS:
            raise ModelFileError(f"{path}:{no}: field 1: {key!r} is not a key {_KEYS}")
        if key in seen:
            raise ModelFileError(f"{path}:{no}: field 1: {key!r} given twice")
        where[key] = no
        if key == "kind":
            if len(values) != 1 or values[0] not in _NEEDS:
                raise ModelFileError(f"{path}:{no}: field 2: kind must be 'poly' or 'everett'")
            seen[key] = values[0]
            continue
        if key in _CREEP_KEYS:
            seen[key] = _creep_numbers(path, no, key, values)
            continue
        if key == "coeffs" and not 2 <= len(values) <= _MAX_COEFFS:
            raise ModelFileError(f"{path}:{no}: coeffs needs 2 to {_MAX_COEFFS} numbers")
        if key == "terms" and not values:
            raise ModelFileError(f"{path}:{no}: terms needs numbers")
        if key not in ("coeffs", "terms") and len(values) != 1:
            raise ModelFileError(f"{path}:{no}: {key} needs one value")
        numbers = _numbers(path, no, key, values)
        if key == "degree" and not 1 <= numbers[0] <= _EVERETT_MAX_DEGREE:
            raise ModelFileError(f"{path}:{no}: field 2: degree must be 1 to "
                                 f"{_EVERETT_MAX_DEGREE}")
        seen[key] = numbers if key in ("coeffs", "terms") else numbers[0]
    if "kind" not in seen:
        raise ModelFileError(f"{path}: the key kind is missing")
    kind = seen["kind"]
    for key in _REFUSES[kind]:
        if key in seen:
            raise ModelFileError(f"{path}:{where[key]}: field 1: {key!r} is not a key of "
                                 f"kind {kind}")
    for key in _NEEDS[kind]:
        if key not in seen:
            raise ModelFileError(f"{path}: the key {key} is missing")
    _creep_complete(path, seen, where)
    model = {"kind": kind, "lo": seen["lo"], "hi": seen["hi"], "delay": int(seen.get("delay", 0))}
    if kind == "poly":
        model["coeffs"] = seen["coeffs"]
    else:
        degree = int(seen["degree"])
        if len(seen["terms"]) != everett_terms(degree):
            raise ModelFileError(f"{path}:{where['terms']}: terms needs {everett_terms(degree)} "
                                 f"numbers for degree {degree}, not {len(seen['terms'])}")
        model.update(y_lo=seen["y_lo"], degree=degree, terms=seen["terms"])
    if "creep_tau" in seen:
        model.update(creep_tau=seen["creep_tau"], creep_weight=seen["creep_weight"])
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


def _poly_args(coeffs, kind, degree, y_lo, terms):
    """Checks a poly description; returns its coefficients as numbers."""
    if kind != "poly":
        raise ValueError(f"kind must be 'poly' or 'everett', not {kind!r}")
    if degree is not None or y_lo is not None or terms is not None:
        raise ValueError("degree, y_lo and terms belong to kind 'everett'")
    coeffs = [float(c) for c in coeffs] if coeffs is not None else []
    if not 2 <= len(coeffs) <= _MAX_COEFFS or not all(math.isfinite(v) for v in coeffs):
        raise ValueError(f"2 to {_MAX_COEFFS} finite coefficients are needed")
    return coeffs


def save_model(path, coeffs=None, lo=None, hi=None, delay=0, *, kind="poly", degree=None,
               y_lo=None, terms=None, creep_tau=None, creep_weight=None):
    """Writes a model file (17 significant digits: the same doubles read
    back), replacing ``path`` whole or not at all. ``kind="everett"`` writes
    the asymmetric kind from ``degree``, ``y_lo`` and ``terms`` (no
    ``coeffs``). ``creep_tau`` and ``creep_weight`` (both or neither, 1 to 4
    numbers each, time constants >= 1 sample) add a creep term, written after
    the model as ``hyst fit --save`` writes it.
    ``save_model(path, **load_model(other))`` copies a file."""
    creep_tau, creep_weight = _creep_args(creep_tau, creep_weight)
    if lo is None or hi is None or not all(math.isfinite(float(v)) for v in (lo, hi)):
        raise ValueError("a finite domain lo, hi is needed")
    if int(delay) != delay or delay < 0:
        raise ValueError("delay must be a whole number of samples")
    if kind == "everett":
        if coeffs is not None:
            raise ValueError("kind 'everett' has terms, not coeffs")
        degree, y_lo, terms = _everett_args(degree, y_lo, terms)
        text = (f"{MAGIC}\n# hyst model: asymmetric, branch function E on [lo, hi] "
                "(output at lo y_lo), terms e[i-1][j] of w^i t^j for i = 1..degree, "
                f"j = 0..degree-i, the output {int(delay)} samples after its input "
                f"(docs/cli.md)\nkind everett\nlo {float(lo):.17g}\nhi {float(hi):.17g}\n"
                f"y_lo {y_lo:.17g}\ndelay {int(delay)}\ndegree {degree}\n"
                "terms " + " ".join(f"{t:.17g}" for t in terms) + "\n")
    else:
        coeffs = _poly_args(coeffs, kind, degree, y_lo, terms)
        text = (f"{MAGIC}\n# hyst model: f0 on [lo, hi], coefficients highest power first, "
                f"the output {int(delay)} samples after its input (docs/cli.md)\n"
                f"kind poly\nlo {float(lo):.17g}\nhi {float(hi):.17g}\ndelay {int(delay)}\n"
                "coeffs " + " ".join(f"{c:.17g}" for c in coeffs) + "\n")
    text += _creep_text(creep_tau, creep_weight)
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


def _c_number(v, digits=17):
    """v as a C floating literal of `digits` significant digits (always a
    '.' or an exponent), as the CLI's cli_c_number() prints it."""
    t = f"{float(v):.{digits}g}"
    return t if any(ch in t for ch in ".eEn") else t + ".0"


def _literal(v):
    """A 17-digit C literal in HYST_REAL_C() (exact in a double build)."""
    return f"HYST_REAL_C({_c_number(v)})"


def _as_float(v):
    """v rounded to float32, as a float build reads its header literal."""
    return struct.unpack("f", struct.pack("f", float(v)))[0]


def _table_literal(v, f32):
    """A table number as a C literal of its type (float: 9 digits, suffix f)."""
    return _c_number(v, 9) + "f" if f32 else _c_number(v)


def _compensator_text(name, kind, coeffs, lo, hi, degree, y_lo, terms, intervals, rows):
    """The compensator's table in float and in double, sealed, as
    ``hyst header --compensator`` writes it (docs/cli.md)."""
    from . import _hyst  # the extension: this module stays importable without it
    everett = kind == "everett"
    if rows is not None and not everett:
        raise ValueError("rows applies to kind everett only: the compensator of kind poly "
                         "tabulates f0^-1 in one row (intervals alone)")
    if intervals is None:
        intervals = _hyst.EVERETT_INV_INTERVALS if everett else _hyst.INV_TABLE
    if everett and rows is None:
        rows = _hyst.EVERETT_INV_ROWS
    built = {}
    for f32, cls in ((True, _hyst.ModelF32), (False, _hyst.ModelF64)):
        r = _as_float if f32 else float
        if everett:
            c = cls(degree, r(lo), r(hi), r(y_lo), [r(t) for t in terms], 2, True, intervals, rows)
        else:
            c = cls([r(v) for v in coeffs], r(lo), r(hi), 2, True, intervals)
        built[f32] = (c.table, c.table_seal)
    size = (f"HYST_EVERETT_INV_TABLE_LEN({name}_ROWS, {name}_INTERVALS)" if everett
            else f"HYST_INV_TABLE_LEN({name}_INTERVALS)")
    use = (f" *   hyst_curve_from_everett(&fwd, &{name});\n"
           f" *   hyst_curve_everett_inverse_table_const(&comp, &fwd, {name}_table, {name}_ROWS,\n"
           f" *                                          {name}_INTERVALS, &{name}_seal);\n"
           if everett else
           f" *   hyst_curve_from_poly(&fwd, &{name});\n"
           f" *   hyst_curve_inverse_table_const(&comp, &fwd, {name}_table, {name}_INTERVALS,\n"
           f" *                                  &{name}_seal);\n")
    text = ("\n/* The compensator's table in float and in double, sealed; worst error measured by "
            f"the build\n * {built[True][1][1]:.3g} (float) / {built[False][1][1]:.3g} (double) "
            "of the drive range. Firmware takes it from flash:\n" + use +
            " *   hyst_init_curve(&S, &comp, ...);  // comp outlives S */\n")
    if everett:
        text += f"#define {name}_ROWS {rows}u\n"
    text += f"#define {name}_INTERVALS {intervals}u\n#ifdef HYST_USE_DOUBLE\n"
    for f32 in (False, True):
        table, (crc, max_err) = built[f32]
        text += f"static const {'float' if f32 else 'double'} {name}_table[{size}] = {{"
        text += ",".join(("\n    " if i % 4 == 0 else " ") + _table_literal(v, f32)
                         for i, v in enumerate(table))
        text += (f"}};\nstatic const hyst_table_seal_t {name}_seal = "
                 f"{{0x{crc:08X}ul, {_table_literal(max_err, False)}}};\n")
        text += "#else\n" if not f32 else "#endif\n"
    return text


def _creep_header(name, tau, weight):
    """The creep term's block of a header, as ``hyst header`` writes it
    (header_creep() in tools/cli/model_file.c): its count, time constants and
    weights for hyst_creep_init() with the domain's lo as the rest drive."""
    if tau is None:
        return ""
    return ("\n/* creep: add hyst_creep_step() of the model's input to its output\n"
            f" * (hyst/creep.h): hyst_creep_init(&creep, {name}_CREEP_TERMS,\n"
            f" * {name}_creep_tau, {name}_creep_weight, lo) */\n"
            f"#define {name}_CREEP_TERMS {len(tau)}u\n"
            f"static const hyst_wide_t {name}_creep_tau[{name}_CREEP_TERMS] = {{"
            + ", ".join(_literal(v) for v in tau) + "};\n"
            f"static const hyst_wide_t {name}_creep_weight[{name}_CREEP_TERMS] = {{"
            + ", ".join(_literal(v) for v in weight) + "};\n")


def header_text(name, coeffs=None, lo=None, hi=None, *, kind="poly", degree=None, y_lo=None,
                terms=None, delay=0, compensator=False, intervals=None, rows=None,
                creep_tau=None, creep_weight=None):
    """C header declaring the firmware's model as ``hyst fit --header``
    writes it: ``static const hyst_poly_t name`` (f0), or for
    ``kind="everett"`` ``static const hyst_everett_t name`` (degree, lo, hi,
    y_lo, e[i-1][j]); 17-digit literals in HYST_REAL_C(), exact in a double
    build (HYST_USE_DOUBLE). ``delay`` is not part of a header; it is
    accepted so that a :func:`load_model` dict can be passed whole.
    ``compensator=True`` adds the compensator's table, built here by the
    library in float and in double and sealed, as ``hyst header
    --compensator`` writes it: ``name_table``, ``name_seal``,
    ``name_INTERVALS`` (and ``name_ROWS``), for firmware's
    ``hyst_curve_inverse_table_const()`` or
    ``hyst_curve_everett_inverse_table_const()`` (``intervals``, ``rows``:
    the table's size, the library's defaults when None). A creep term
    (``creep_tau``, ``creep_weight``, as :func:`save_model` takes them) adds
    ``#include "hyst/creep.h"``, ``name_CREEP_TERMS``, ``name_creep_tau`` and
    ``name_creep_weight`` after the model, as ``hyst header`` writes them,
    for ``hyst_creep_init(&creep, name_CREEP_TERMS, name_creep_tau,
    name_creep_weight, lo)`` (the compensator's table is the hysteresis
    model's alone: firmware subtracts ``hyst_creep_output()`` before it)."""
    creep_tau, creep_weight = _creep_args(creep_tau, creep_weight)
    if not name.isidentifier() or not name.isascii():
        raise ValueError(f"{name!r} is not a C identifier")
    if not compensator and (intervals is not None or rows is not None):
        raise ValueError("intervals and rows size the compensator's table (compensator=True)")
    del delay
    guard = name.upper() + "_H"
    if kind == "everett":
        degree, y_lo, terms = _everett_args(degree, y_lo, terms)
        e_rows, k = [], 0
        for i in range(1, degree + 1):
            n = degree - i + 1  # j = 0..degree - i
            e_rows.append("{" + ", ".join(_literal(t) for t in terms[k:k + n]) + "}")
            k += n
        what = (f"asymmetric model (branch function E),\n * degree {degree}, "
                f"domain [{float(lo):.9g}, {float(hi):.9g}]")
        decl = (f"static const hyst_everett_t {name} = {{\n    {degree}u, {_literal(lo)}, "
                f"{_literal(hi)}, {_literal(y_lo)},\n    {{" + ",\n     ".join(e_rows) + "}};")
    else:
        coeffs = _poly_args(coeffs, kind, degree, y_lo, terms)
        body = ",\n     ".join(_literal(c) for c in coeffs)
        what = (f"major ascending curve f0,\n * degree {len(coeffs) - 1}, "
                f"domain [{float(lo):.9g}, {float(hi):.9g}]")
        decl = (f"static const hyst_poly_t {name} = {{\n    {len(coeffs) - 1}u, "
                f"{_literal(lo)}, {_literal(hi)},\n    {{{body}}}}};")
    table = (_compensator_text(name, kind, coeffs, lo, hi, degree, y_lo, terms, intervals, rows)
             if compensator else "")
    includes = '#include "hyst/curve.h"\n'
    if creep_tau is not None:
        includes += '#include "hyst/creep.h"\n'
    return (f"/* Generated by the Python package hyst: {what}. */\n"
            f"#ifndef {guard}\n#define {guard}\n\n{includes}\n"
            f"{decl}\n{_creep_header(name, creep_tau, creep_weight)}{table}\n"
            f"#endif /* {guard} */\n")
