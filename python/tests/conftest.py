# SPDX-License-Identifier: MIT
"""Shared fixtures: the C side (hyst_ref and the `hyst` tool, built from this
repository by CMake) and deterministic input signals."""
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data" / "piezo_major_loop.dat"
# f0 of the paper's Eq. 20 on [0, 40] V, highest power first
PAPER_F0 = [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]


@pytest.fixture(scope="session")
def c_build(tmp_path_factory):
    """Builds python/tests/ref (hyst_ref + the `hyst` tool) once per session,
    in $HYST_PY_REF_BUILD if set (tools/test_python keeps it under build/)."""
    out = Path(os.environ.get("HYST_PY_REF_BUILD") or tmp_path_factory.mktemp("ref"))
    src = REPO / "python" / "tests" / "ref"
    for cmd in (["cmake", "-S", str(src), "-B", str(out), "-DCMAKE_BUILD_TYPE=Release"],
                ["cmake", "--build", str(out), "-j2"]):
        r = subprocess.run(cmd, capture_output=True, text=True)
        assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    return {"ref": out / "hyst_ref", "cli": out / "hyst" / "tools" / "cli" / "hyst"}


@pytest.fixture
def run_ref(c_build, tmp_path):
    """run_ref(kind, x, out_dtype, **opts) -> (outputs, status, snapshot bytes or None);
    kind "bench": (outputs, best nanoseconds per sample, None)."""

    def run(kind, x, out_dtype, **opts):
        fin, fout, fsnap = tmp_path / "in.raw", tmp_path / "out.raw", tmp_path / "snap.raw"
        np.ascontiguousarray(x).tofile(fin)
        args = [str(c_build["ref"]), kind, f"in={fin}", f"out={fout}"]
        if kind != "pi":
            args.append(f"snap={fsnap}")
        for k, v in opts.items():
            if isinstance(v, (list, tuple)):
                v = ",".join(map(repr, map(float, v)))
            elif not isinstance(v, str):
                v = repr(v)
            args.append(f"{k}={v}")
        r = subprocess.run(args, capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        snap = fsnap.read_bytes() if fsnap.exists() else None
        printed = float(r.stdout) if kind == "bench" else int(r.stdout)
        return np.fromfile(fout, dtype=out_dtype), printed, snap

    return run


def signal(n, lo, hi, seed=1, outside=True, nonfinite=False):
    """Deeply nested minor loops (a damped oscillation), then sweeps between
    random ends; repeated samples, a few samples outside [lo, hi] and,
    optionally, NaN and infinities."""
    rng = np.random.default_rng(seed)
    mid, half = (lo + hi) / 2, (hi - lo) / 2
    ends = [lo] + [mid + half * (-0.8) ** k for k in range(1, 40)]
    parts = [np.linspace(a, b, 25) for a, b in zip(ends[:-1], ends[1:])]
    x = ends[-1]
    while sum(p.size for p in parts) < n:
        end = rng.uniform(lo, hi)
        parts.append(np.linspace(x, end, int(rng.integers(2, 60))))
        x = end
    s = np.concatenate(parts)[:n]
    rep = rng.integers(1, n, n // 50)
    s[rep] = s[rep - 1]  # repeated samples
    if outside:
        idx = rng.integers(0, n, n // 100)
        s[idx] = np.where(rng.random(idx.size) < 0.5, lo - 1.0, hi + 1.0)
    if nonfinite:
        s[rng.integers(0, n, 5)] = np.nan
        s[rng.integers(0, n, 2)] = np.inf
    return s


def same_bits(a, b):
    """Exact equality of two float arrays, bit for bit (NaN and -0 included)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype != b.dtype or a.shape != b.shape:
        return False
    u = {4: np.uint32, 8: np.uint64}[a.dtype.itemsize]
    return bool(np.array_equal(a.view(u), b.view(u)))


def run_cli(c_build, *args, ok=True, stdin=None):
    """`hyst ARGS...` (each argument str()'d): its CompletedProcess, the exit
    status asserted 0 (ok=False: non-zero)."""
    r = subprocess.run([str(c_build["cli"]), *map(str, args)], input=stdin, capture_output=True,
                       text=True)
    assert (r.returncode == 0) == ok, r.stderr
    return r


def numbers(text):
    """The numbers of a tool's output, as a float64 array."""
    return np.array([float(v) for v in text.split()])


def sim_matches_cli(c_build, tmp_path, path, x):
    """hyst.model_from() of model file `path`'s description gives for the
    inputs x bit for bit the outputs `hyst sim --model path` gives (the
    file's delay applied), by block and by step: the description and the
    outputs."""
    import hyst

    desc = hyst.load_model(path)
    d = desc["delay"]
    inp = tmp_path / "x.txt"
    np.savetxt(inp, x, fmt="%.17g")
    cli = numbers(run_cli(c_build, "sim", "--model", path, "--digits", 17, inp).stdout)
    y = hyst.model_from(desc).process(x)
    assert len(cli) == len(x) and np.array_equal(cli[d:], y[:len(y) - d])
    m = hyst.model_from(desc)
    assert np.array_equal([m.step(v) for v in x], y)
    return desc, y


def inv_matches_cli(c_build, tmp_path, path, desc, y):
    """hyst.compensator_from(desc), desc model file `path`'s description, gives
    bit for bit the drives `hyst inv --model path` gives for the desired
    outputs y: the compensator and its drives."""
    import hyst

    out = tmp_path / "y.txt"
    np.savetxt(out, y, fmt="%.17g")
    drive_cli = numbers(run_cli(c_build, "inv", "--model", path, "--digits", 17, out).stdout)
    comp = hyst.compensator_from(desc)
    drive = comp.process(y)
    assert np.array_equal(drive_cli, drive)
    return comp, drive
