# SPDX-License-Identifier: MIT
"""Model files in the format hyst-model-text 1, the one ``hyst fit --save``
writes and ``hyst sim --model`` reads (docs/cli.md, "Model files"), also
read and written by the MATLAB/Octave functions."""
import math
import os
import tempfile

MAGIC = "hyst-model-text 1"
_KEYS = ("kind", "lo", "hi", "coeffs", "delay")


class ModelFileError(ValueError):
    """A malformed model file; the message names the file and the line."""


def load_model(path):
    """Reads a model file; returns a dict with ``coeffs`` (highest power
    first), ``lo``, ``hi`` and ``delay`` (samples, 0 when absent)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    if not lines or lines[0].strip() != MAGIC:
        first = lines[0].strip() if lines else ""
        raise ModelFileError(f"{path}:1: {first!r} is not {MAGIC!r} (another format or version)")
    seen = {}
    for no, line in enumerate(lines[1:], start=2):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        key, values = fields[0], fields[1:]
        if key not in _KEYS:
            raise ModelFileError(f"{path}:{no}: field 1: {key!r} is not a key {_KEYS}")
        if key in seen:
            raise ModelFileError(f"{path}:{no}: field 1: {key!r} given twice")
        if key == "kind":
            if values != ["poly"]:
                raise ModelFileError(f"{path}:{no}: field 2: kind must be 'poly'")
            seen[key] = "poly"
            continue
        if (key == "coeffs" and not 2 <= len(values) <= 10) or (key != "coeffs" and len(values) != 1):
            raise ModelFileError(f"{path}:{no}: {key} needs "
                                 f"{'2 to 10 numbers' if key == 'coeffs' else 'one value'}")
        numbers = []
        for i, v in enumerate(values, start=2):
            try:
                x = float(v)
            except ValueError:
                x = math.nan
            if not math.isfinite(x) or (key == "delay" and (x < 0 or x != int(x))):
                what = "a whole number of samples" if key == "delay" else "a finite number"
                raise ModelFileError(f"{path}:{no}: field {i}: {v!r} is not {what}")
            numbers.append(x)
        seen[key] = numbers if key == "coeffs" else numbers[0]
    for key in _KEYS[:4]:
        if key not in seen:
            raise ModelFileError(f"{path}: the key {key} is missing")
    return {"coeffs": seen["coeffs"], "lo": seen["lo"], "hi": seen["hi"],
            "delay": int(seen.get("delay", 0))}


def save_model(path, coeffs, lo, hi, delay=0):
    """Writes a model file (17 significant digits: the same doubles read
    back), replacing ``path`` whole or not at all."""
    coeffs = [float(c) for c in coeffs]
    if not 2 <= len(coeffs) <= 10 or not all(math.isfinite(v) for v in coeffs + [lo, hi]):
        raise ValueError("2 to 10 finite coefficients and a finite domain are needed")
    if int(delay) != delay or delay < 0:
        raise ValueError("delay must be a whole number of samples")
    text = (f"{MAGIC}\n# hyst model: f0 on [lo, hi], coefficients highest power first, "
            f"the output {int(delay)} samples after its input (docs/cli.md)\n"
            f"kind poly\nlo {float(lo):.17g}\nhi {float(hi):.17g}\ndelay {int(delay)}\n"
            "coeffs " + " ".join(f"{c:.17g}" for c in coeffs) + "\n")
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
