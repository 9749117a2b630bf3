# SPDX-License-Identifier: MIT
"""The spline kind (hyst_spline_t: the symmetric model whose f0 is a monotone
cubic spline on uniform knots, model files of kind spline) in the package:
ModelFromSpline and its compensator are the library's block calls bit for
bit; a file is read by the one reader in C and runs as `hyst sim --model`
and `hyst inv --model [--intervals N]` run it (the tabulated compensator,
hyst_curve_spline_inverse_table(), too); save_model and header_text write what the
tool writes; fit(kind="spline") is `hyst fit --kind spline`'s fit and
choice, its model file the tool's byte for byte (tests/cli/spline.sh's
cases)."""

import re

import numpy as np
import pytest

import hyst
from conftest import (inv_matches_cli, numbers, run_cli, same_bits, signal,
                      sim_matches_cli)

# f0 = x^3 + x on [0, 1] in two pieces: a cubic is its own Hermite spline
CUBIC = {"kind": "spline", "lo": 0.0, "hi": 1.0, "values": [0.0, 0.625, 2.0],
         "slopes": [1.0, 1.75, 4.0]}
CUBIC_TEXT = "hyst-model-text 1\nkind spline\nlo 0\nhi 1\nvalues 0 0.625 2\nslopes 1 1.75 4\n"

# tests/cli/spline.sh's plant, of the fit's own class: f0' = (K / (hi - lo))
# sum w_j B_j (quadratic B-splines on the uniform knots), K = 5 on [0, 3]: a
# C2 spline with a near step, f0(lo) = 0.5
WEIGHTS = [0.3, 0.2, 0.2, 2.5, 2.5, 0.2, 0.1]
K, LO, HI = 5, 0.0, 3.0


def plant(delay=0):
    """The plant's description: f0(x_k) = 0.5 + the sum over intervals i < k
    of (w_i + 4 w_(i+1) + w_(i+2)) / 6, f0'(x_k) = (w_k + w_(k+1)) / 2 K / (hi - lo)."""
    values = [0.5]
    for i in range(K):
        values.append(values[-1] + (WEIGHTS[i] + 4 * WEIGHTS[i + 1] + WEIGHTS[i + 2]) / 6)
    slopes = [(WEIGHTS[k] + WEIGHTS[k + 1]) / 2 * K / (HI - LO) for k in range(K + 1)]
    return {"kind": "spline", "lo": LO, "hi": HI, "values": values, "slopes": slopes,
            "delay": delay}


def loops():
    """tests/cli/spline.sh's drive: minor loops of decreasing size, then a major loop."""
    out = []
    for c in range(12):
        a, b = 3 - c * 0.2, c * 0.2
        out += list(np.arange(b, a, 0.01)) + list(np.arange(a, b, -0.01))
    out += list(np.arange(0, 3, 0.01)) + list(np.arange(3, -0.005, -0.01))
    return np.round(np.array(out), 2)


def record(tmp_path, delay=0, noise=0.0, name="rec.txt"):
    """The plant driven by loops(), its output `delay` samples late, plus
    uniform noise of +-noise: (x, y, the record's file, 17 digits)."""
    x = loops()
    y = hyst.model_from(plant()).process(x)
    y = np.concatenate([np.full(delay, y[0]), y[:len(y) - delay]])
    y = y + np.random.default_rng(4242).uniform(-noise, noise, len(y))
    path = tmp_path / name
    np.savetxt(path, np.column_stack([x, y]), fmt="%.17g")
    return x, y, path


# ---- the model and its compensator ----

@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_a_cubic_runs_as_the_polynomial(dtype):
    """f0 = x^3 + x written as a spline is that cubic: the outputs
    tests/cli/spline.sh prints (exact), and the polynomial model's within 4
    roundings over nested minor loops; the compensator gives the inputs back."""
    x = np.array([0, 0.25, 0.5, 1, 0.5, 0.75, 0], dtype=dtype)
    m = hyst.ModelFromSpline(0, 1, CUBIC["values"], CUBIC["slopes"], dtype=dtype)
    assert m.kind == "spline" and m.values == CUBIC["values"] and m.slopes == CUBIC["slopes"]
    assert m.lo == 0.0 and m.hi == 1.0 and not m.inverse
    y = m.process(x)
    assert y.dtype == dtype
    assert y.tolist() == [0, 0.265625, 0.625, 2, 1.375, 1.640625, 0]
    s = signal(20000, 0.0, 1.0, seed=3).astype(dtype)
    a = hyst.ModelFromSpline(0, 1, CUBIC["values"], CUBIC["slopes"], dtype=dtype).process(s)
    b = hyst.Model([1, 0, 1, 0], 0, 1, dtype=dtype).process(s)
    eps = np.finfo(dtype).eps
    assert np.max(np.abs(a - b)) <= 4 * eps * 2
    c = hyst.ModelFromSpline(0, 1, CUBIC["values"], CUBIC["slopes"], dtype=dtype, inverse=True)
    assert c.inverse and c.kind == "spline"
    drive = c.process(a)
    assert np.max(np.abs(drive - np.clip(s, 0, 1))) < (16 if dtype == np.float64 else 1e4) * eps
    if dtype == np.float64:  # exact at the knots and the ends, within a rounding between
        c.reset()
        d = c.process(y)
        assert d[[0, 2, 3, 4, 6]].tolist() == [0, 0.5, 1, 0.5, 0]
        assert np.max(np.abs(d - x)) <= eps


@pytest.mark.parametrize("dtype,ref_type", [(np.float64, "f64"), (np.float32, "f32")])
@pytest.mark.parametrize("what", ["sim", "inv"])
def test_block_calls_are_the_librarys(run_ref, dtype, ref_type, what):
    """The model (hyst_*_curve_from_spline(), hyst_*_init_curve()) and its
    compensator (hyst_curve_spline_inverse()) give the library's block call's
    outputs, status and snapshot bit for bit, with a deadband and a
    capacity that fills; step() gives the same."""
    p = plant()
    x = signal(6000, LO, HI, seed=8, nonfinite=True)
    opts = dict(type=ref_type, lo=LO, hi=HI, values=p["values"], slopes=p["slopes"], cap=16,
                deadband=0.002)
    inverse = what == "inv"
    if inverse:  # the desired outputs: the model's, beyond its range at times
        x = hyst.model_from(p).process(x) * 1.02 - 0.05
    x = x.astype(dtype)
    m = hyst.ModelFromSpline(LO, HI, p["values"], p["slopes"], dtype=dtype, capacity=16,
                             deadband=0.002, inverse=inverse)
    y = m.process(x)
    ref, status, snap = run_ref(what, x, dtype, **opts)
    assert same_bits(y, ref)
    assert m.block_status == status
    assert m.save() == snap
    m.reset()
    assert same_bits(np.array([m.step(v) for v in x], dtype=dtype), ref)
    # a snapshot restores the model's memory: it continues as the original
    other = hyst.ModelFromSpline(LO, HI, p["values"], p["slopes"], dtype=dtype, capacity=16,
                                 deadband=0.002, inverse=inverse)
    other.restore(snap)
    tail = x[:500]
    assert same_bits(other.process(tail), m.process(tail))


def test_the_compensator_undoes_the_model():
    """Minor loops included: the compensator of the plant driven by the
    plant's outputs gives the drives back (clamped), and the plant driven by
    the compensator's drives gives the desired outputs back."""
    p = plant()
    x = np.concatenate([signal(4000, LO, HI, seed=5), loops()])
    y = hyst.model_from(p).process(x)
    drive = hyst.compensator_from(p).process(y)
    assert np.max(np.abs(drive - np.clip(x, LO, HI))) < 1e-9 * (HI - LO)
    assert np.max(np.abs(hyst.model_from(p).process(drive) - y)) < 1e-9 * np.ptp(y)


# ---- model files ----

PLANT_CREEP_EXTRA = "identified 0.5 2.5\ncreep_tau 300\ncreep_weight 0.05\n"


def plant_file(tmp_path, delay=0, extra=""):
    """The plant as a model file written by the package, `extra` lines after it."""
    path = tmp_path / f"plant{delay}.hyst"
    hyst.save_model(path, **plant(delay))
    path.write_text(path.read_text() + extra)
    return path


def test_load_model_gives_the_spline(tmp_path):
    path = tmp_path / "c.hyst"
    path.write_text(CUBIC_TEXT + "delay 2\n" + PLANT_CREEP_EXTRA.replace("0.5 2.5", "0.25 1"))
    m = hyst.load_model(path)
    assert m["kind"] == "spline" and m["lo"] == 0.0 and m["hi"] == 1.0
    assert m["values"] == CUBIC["values"] and m["slopes"] == CUBIC["slopes"]
    assert m["delay"] == 2 and m["identified"] == (0.25, 1.0)
    assert m["creep_tau"] == [300.0] and m["creep_weight"] == [0.05]
    assert not {"coeffs", "terms", "y_lo", "knots", "weights"} & set(m)


@pytest.mark.parametrize("extra", ["", PLANT_CREEP_EXTRA, "rate_tau 20\nrate_weight 0.1\n"],
                         ids=["plain", "creep", "rate"])
def test_sim_and_inv_match_the_cli_bit_for_bit(c_build, tmp_path, extra):
    path = plant_file(tmp_path, delay=2, extra=extra)
    x = np.concatenate([signal(3000, LO, HI, seed=4), loops()])
    desc, y = sim_matches_cli(c_build, tmp_path, path, x)
    assert desc["kind"] == "spline" and desc["delay"] == 2
    comp, drive = inv_matches_cli(c_build, tmp_path, path, desc, y)
    assert comp.kind == "spline" and comp.inverse
    assert np.max(np.abs(hyst.model_from(desc).process(drive) - y)) < 1e-8 * np.ptp(y)
    if not extra:
        assert np.max(np.abs(drive - np.clip(x, LO, HI))) < 1e-9 * (HI - LO)


@pytest.mark.parametrize("intervals", [8, 64, hyst.INV_TABLE])
@pytest.mark.parametrize("extra", ["", PLANT_CREEP_EXTRA], ids=["plain", "creep"])
def test_the_tabulated_compensator_is_the_clis(c_build, tmp_path, intervals, extra):
    """intervals=N: hyst_curve_spline_inverse_table()'s compensator, as
    `hyst inv --model --intervals N` runs it, bit for bit (ModelFromSpline
    and compensator_from alike); its inverse_error the error the tool
    prints; not the solved compensator's drives, within that error of them
    times the turning points each branch stands on."""
    path = plant_file(tmp_path, extra=extra)
    desc = hyst.load_model(path)
    x = np.concatenate([signal(3000, LO, HI, seed=4), loops()])
    y = hyst.model_from(desc).process(x)
    out = tmp_path / "y.txt"
    np.savetxt(out, y, fmt="%.17g")
    cli = run_cli(c_build, "inv", "--model", path, "--digits", 17, "--intervals", intervals, out)
    comp = hyst.compensator_from(desc, intervals=intervals)
    assert comp.kind == "spline" and comp.inverse and comp.intervals == intervals
    drive = comp.process(y)
    assert np.array_equal(numbers(cli.stdout), drive)
    err = float(re.search(r"init's worst measured error (\S+) of", cli.stderr).group(1))
    assert comp.inverse_error == pytest.approx(err, rel=1e-8)
    if not extra:
        direct = hyst.ModelFromSpline(LO, HI, desc["values"], desc["slopes"], inverse=True,
                                      intervals=intervals)
        assert np.array_equal(direct.process(y), drive)
        exact = hyst.compensator_from(desc).process(y)
        tp = numbers(run_cli(c_build, "inv", "--model", path, "--digits", 17, "--tp",
                             "--intervals", intervals, out).stdout.replace(",", " "))
        assert 0 < np.max(np.abs(drive - exact))
        assert np.all(np.abs(drive - exact) <= (tp[1::2] + 1) * 1.01 * err * (HI - LO) + 1e-12)


def test_files_are_written_as_the_tool_writes_them(c_build, tmp_path):
    """A spline fitted and saved by `hyst fit --kind spline --save`, read and
    written back by the package: the same text, byte for byte; the
    hand-written cubic, with a creep term, a rate term, a fractional delay
    and an identified range, read back as written."""
    _, _, rec = record(tmp_path)
    path = tmp_path / "fitted.hyst"
    run_cli(c_build, "fit", "--kind", "spline", "--degree", 5, "--delay", 0, "--creep", "none",
            "--save", path, rec)
    m = hyst.load_model(path)
    assert m["kind"] == "spline" and len(m["values"]) == 6 == len(m["slopes"])
    again = tmp_path / "again.hyst"
    hyst.save_model(again, **m)
    assert again.read_text() == path.read_text()
    full = dict(CUBIC, delay=2.5, identified=(0.25, 0.75), creep_tau=[300.0, 40.0],
                creep_weight=[0.05, -0.01], rate_tau=20.0, rate_weight=0.1)
    hyst.save_model(again, **full)
    assert hyst.load_model(again) == full
    run_cli(c_build, "sim", "--model", again, "--digits", 17, rec)


def test_header_is_the_clis(c_build, tmp_path):
    path = plant_file(tmp_path, extra=PLANT_CREEP_EXTRA)
    guard = "#ifndef"
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path, "s")
    cli_text = (tmp_path / "s.h").read_text()
    text = hyst.header_text("s", **hyst.load_model(path))
    assert "static const hyst_spline_t s = {" in text
    assert "HYST_SPLINE_TABLE_LEN(5u)" in text
    assert text[text.index(guard):] == cli_text[cli_text.index(guard):]
    # the compensator: the same header, saying how firmware builds it; no table to size
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path, "--compensator", "s")
    cli_text = (tmp_path / "s.h").read_text()
    text = hyst.header_text("s", **hyst.load_model(path), compensator=True)
    assert "hyst_curve_spline_inverse()" in text and "hyst_curve_spline_inverse()" in cli_text
    assert text[text.index(guard):] == cli_text[cli_text.index(guard):]
    # with intervals: the table firmware builds at init, measured here, its size
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path, "--compensator",
            "--intervals", 32, "s")
    cli_text = (tmp_path / "s.h").read_text()
    text = hyst.header_text("s", **hyst.load_model(path), compensator=True, intervals=32)
    assert "hyst_curve_spline_inverse_table(&comp, &fwd, comp_table, s_INTERVALS)" in text
    assert text[text.index(guard):] == cli_text[cli_text.index(guard):]
    with pytest.raises(ValueError, match="rows applies to kind everett only"):
        hyst.header_text("s", **hyst.load_model(path), compensator=True, rows=8)


# the edits of tests/cli/spline.sh's one.hyst the reader refuses, in the tool's words
MALFORMED = [
    ("slopes 1 1.75 4", "slopes 1 1.75"),
    ("slopes 1 1.75 4", "slopes 1 1.75 4 5"),
    ("slopes 1 1.75 4", "slopes 1 -1.75 4"),
    ("values 0 0.625 2", "values 0"),
    ("values 0 0.625 2", "values " + " ".join(map(str, range(34)))),
    ("lo 0", "y_lo 0\nlo 0"),
    ("slopes 1 1.75 4\n", ""),
    ("kind spline", "kind poly\ncoeffs 1 0"),
    ("kind spline", "kind splines"),
]


@pytest.mark.parametrize("old,new", MALFORMED)
def test_malformed_files_are_refused_as_the_tool_refuses_them(c_build, tmp_path, old, new):
    path = tmp_path / "bad.hyst"
    path.write_text(CUBIC_TEXT.replace(old, new))
    with pytest.raises(hyst.ModelFileError) as err:
        hyst.load_model(path)
    x = tmp_path / "x.txt"
    x.write_text("0\n0.5\n")
    cli = run_cli(c_build, "sim", "--model", path, x, ok=False).stderr
    assert f"hyst sim: {err.value}\n" == cli


def test_kind_names_are_the_readers():
    """The kinds the writers name when refusing one are the reader's four."""
    words = "kind must be 'poly', 'everett', 'everett_grid' or 'spline'"
    with pytest.raises(ValueError, match=words):
        hyst.save_model("unused.hyst", kind="splines", lo=0, hi=1, coeffs=[1, 0])
    with pytest.raises(ValueError, match=words):
        hyst.header_text("h", kind="preisach", lo=0, hi=1, coeffs=[1, 0])
    with pytest.raises(ValueError, match=words):  # the extension's own check
        hyst._hyst.model_write("splines", 0.0, 1.0, 0.0, [1.0, 0.0], 0.0, 0.0, [], [], [])
    assert hyst._api.KINDS == ("poly", "everett", "everett_grid", "spline")


def test_refusals(tmp_path):
    # the library's: a piece that falls (the reader takes it: slopes >= 0)
    falls = dict(CUBIC, values=[0.0, 1.9, 2.0])
    with pytest.raises(hyst.HystError) as err:
        hyst.model_from(falls)
    assert err.value.status == hyst.Status.ERR_NOT_INCREASING
    with pytest.raises(hyst.HystError) as err:
        hyst.ModelFromSpline(0, 1, [0.0, 0.625, 2.0], [1.0, -1.75, 4.0])
    assert err.value.status == hyst.Status.ERR_NOT_INCREASING
    with pytest.raises(hyst.HystError) as err:
        hyst.header_text("h", **falls)
    assert err.value.status == hyst.Status.ERR_NOT_INCREASING
    # a flat piece: a model, no compensator
    flat = dict(CUBIC, hi=3.0, values=[0.0, 1.0, 1.0, 2.0], slopes=[1.0, 0.0, 0.0, 1.0])
    y = hyst.model_from(flat).process(np.linspace(0, 3, 31))
    assert np.all(np.diff(y) >= 0) and y[-1] == 2.0
    with pytest.raises(hyst.HystError) as err:
        hyst.compensator_from(flat)
    assert err.value.status == hyst.Status.ERR_NOT_INVERTIBLE
    # counts, before the library: 1 or 34 values, slopes not one per value
    for values, slopes, status in (([0.0], [1.0], hyst.Status.ERR_DEGREE),
                                   (list(range(34)), [1.0] * 34, hyst.Status.ERR_DEGREE),
                                   ([0.0, 1.0, 2.0], [1.0, 1.0], hyst.Status.ERR_ARG)):
        with pytest.raises(hyst.HystError) as err:
            hyst.ModelFromSpline(0, 1, values, slopes)
        assert err.value.status == status
    # the tabulated compensator's arguments: rows (kind everett's), intervals out of range or
    # without inverse=True; a flat piece
    for opts in ({"rows": 8}, {"intervals": 32, "rows": 8}, {"intervals": 2 ** 20 + 1},
                 {"intervals": -1}):
        with pytest.raises(hyst.HystError) as err:
            hyst.compensator_from(CUBIC, **opts)
        assert err.value.status == hyst.Status.ERR_ARG
    with pytest.raises(hyst.HystError) as err:
        hyst.ModelFromSpline(0, 1, CUBIC["values"], CUBIC["slopes"], intervals=32)
    assert err.value.status == hyst.Status.ERR_ARG
    with pytest.raises(hyst.HystError) as err:
        hyst.compensator_from(flat, intervals=32)
    assert err.value.status == hyst.Status.ERR_NOT_INVERTIBLE
    # the writer refuses what the reader would, writing nothing
    bad = tmp_path / "bad.hyst"
    for desc, words in ((dict(CUBIC, slopes=[1.0, -1.75, 4.0]), "slopes: a slope is not >= 0"),
                        (dict(CUBIC, slopes=[1.0, 1.75]), "values and slopes need as many"),
                        (dict(CUBIC, values=[0.0], slopes=[1.0]), "values and slopes need"),
                        (dict(CUBIC, y_lo=0.0), "kind 'spline' has values and slopes, not y_lo"),
                        ({k: v for k, v in CUBIC.items() if k != "slopes"},
                         "kind 'spline' needs values and slopes"),
                        (dict(CUBIC, kind="poly", coeffs=[1.0, 0.0]),
                         "values and slopes belong to kind 'spline'")):
        with pytest.raises(ValueError, match=words):
            hyst.save_model(bad, **desc)
    assert not bad.exists()


# ---- fit: `hyst fit --kind spline` ----

def test_fit_recovers_a_known_spline_as_the_cli(c_build, tmp_path):
    """fit(kind="spline", degree=5) on the plant's own record (minor loops,
    no noise) recovers its f0 along every branch, to 1e-10 of the range,
    and is `hyst fit --kind spline --degree 5`'s fit: the same model file,
    byte for byte."""
    x, y, rec = record(tmp_path)
    f = hyst.fit(x, y, 5, kind="spline", delay=0, creep="none")
    assert f.kind == "spline" and f.degree == 5 and f.intervals == 5 and f.delay == 0
    assert (f.lo, f.hi) == (LO, HI) and f.identified is None and f.creep is None
    p = plant()
    span = p["values"][-1] - p["values"][0]
    assert np.max(np.abs(np.array(f.values) - p["values"])) < 1e-10 * span
    assert np.max(np.abs(np.array(f.slopes) - p["slopes"])) < 1e-9 * span
    assert f.rms < 1e-10 * span and f.used == len(x)
    assert np.max(np.abs(f.predict(x) - y)) < 1e-10 * span
    assert f.description() == {"kind": "spline", "lo": LO, "hi": HI, "values": f.values,
                               "slopes": f.slopes}
    assert repr(f).startswith("Fit(kind='spline', intervals=5, values=[0.5, 0.716666667, ")
    run_cli(c_build, "fit", "--kind", "spline", "--degree", 5, "--delay", 0, "--creep", "none",
            "--save", tmp_path / "cli.hyst", rec)
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    # its compensator undoes it
    drive = f.make_compensator().process(f.predict(x))
    assert np.max(np.abs(drive - x)) < 1e-9 * (HI - LO)


def test_fit_chooses_as_the_cli(c_build, tmp_path):
    """Without a degree, kind="spline" compares 2..16 intervals at each
    delay as `hyst fit --kind spline` does: on the noisy, late plant both
    choose 5 intervals and delay 2, its hold-out error the noise's, and
    save the same file byte for byte."""
    x, y, rec = record(tmp_path, delay=2, noise=0.005)
    f = hyst.fit(x, y, kind="spline", creep="none")
    assert f.kind == "spline" and f.intervals == 5 and f.delay == 2
    assert {c["kind"] for c in f.candidates} == {"spline"}
    assert {c["degree"] for c in f.candidates} == set(range(2, 17))
    chosen = [c for c in f.candidates if c["chosen"]]
    assert len(chosen) == 1 and chosen[0]["params"] == 8 and chosen[0]["t_degree"] is None
    assert 0.0025 < chosen[0]["holdout_rms"] < 0.0033
    cli = run_cli(c_build, "fit", "--kind", "spline", "--creep", "none", "--save",
                  tmp_path / "cli.hyst", rec).stdout
    assert "# chosen by hold-out: degree 5, delay 2 (kind spline, 8 parameters" in cli
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()


def test_the_automatic_choice_compares_the_spline_as_the_cli(c_build, tmp_path):
    """fit() without a kind compares the kinds `hyst fit` without --kind
    compares, the spline among them: on a spline plant's record it chooses
    a spline; the same choice, the same file."""
    x, y, rec = record(tmp_path)
    f = hyst.fit(x, y, creep="none")
    assert {c["kind"] for c in f.candidates} == {"poly", "everett", "everett_grid", "spline"}
    assert f.kind == "spline"
    run_cli(c_build, "fit", "--creep", "none", "--save", tmp_path / "cli.hyst", rec)
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()


@pytest.mark.parametrize("opts,py", [
    (["--degree", 7], {"degree": 7}),
    (["--degree", 5, "--delay", 2, "--creep", 500, "--domain", "-1,3"],
     {"degree": 5, "delay": 2, "creep": 500, "domain": (-1, 3)}),
    ([], {}),
], ids=["delay-chosen", "creep-domain", "creep-chosen"])
def test_fit_options_save_the_clis_file(c_build, tmp_path, opts, py):
    """With a degree, the delay chosen; a creep term (its offset moves f0 as
    a whole) and a domain wider than the inputs (the identified range
    recorded); the creep term chosen: the tool's model file, byte for byte."""
    x, y, rec = record(tmp_path, delay=2, noise=0.005)
    run_cli(c_build, "fit", "--kind", "spline", *opts, "--save", tmp_path / "cli.hyst", rec)
    f = hyst.fit(x, y, kind="spline", **py)
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    assert f.delay == 2
    if "domain" in py:
        assert f.identified == (0.0, 3.0) and f.creep_tau == [500.0] and f.lo == -1.0
        assert f.outside_identified([-0.5, 0.0, 1.0]) == 1


def test_fit_refuses_what_the_cli_refuses():
    x, y = loops(), hyst.model_from(plant()).process(loops())
    for degree in (0, hyst.SPLINE_MAX_INTERVALS + 1):
        with pytest.raises(hyst.HystError) as err:
            hyst.fit(x, y, degree, kind="spline", delay=0, creep="none")
        assert err.value.status == hyst.Status.ERR_ARG
    with pytest.raises(ValueError, match="method='branches' fits kind poly"):
        hyst.fit(x, y, kind="spline", method="branches")
    with pytest.raises(ValueError, match="t_degree needs kind='everett'"):
        hyst.fit(x, y, 5, kind="spline", t_degree=0)
