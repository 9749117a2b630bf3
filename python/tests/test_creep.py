# SPDX-License-Identifier: MIT
"""The creep term (hyst/creep.h, docs/creep.md) in the package: model files
with creep_tau and creep_weight read, refused and written as the `hyst` tool
does (the same messages, the same text); models and compensators with a creep
term run bit for bit as `hyst sim --model` and `hyst inv --model`; the
header's creep block is the tool's; fit() chooses a creep term as `hyst fit
--creep` does; Creep is the library's lag."""
import math

import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, inv_matches_cli, numbers, run_cli, signal

# tests/cli/creep.sh's plant: Eq. 20 on 0..40 V, delay 3, one lag of 2000
# samples weighing 0.05 um/V
PLANT = """hyst-model-text 1
kind poly
lo 0
hi 40
delay 3
coeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1
creep_tau 2000
creep_weight 0.05
"""
# an asymmetric model with two lags, one of negative weight, and a poly on
# a domain that does not start at 0 (the lags rest at lo)
EV_CREEP = {"kind": "everett", "lo": 0.0, "hi": 40.0, "y_lo": 0.5, "degree": 3,
            "terms": [3.0, 1.0, 0.0, 2.0, -0.5, 0.4], "delay": 2,
            "creep_tau": [300.0, 5000.0], "creep_weight": [0.02, -0.01]}
POLY_CREEP = {"kind": "poly", "lo": 5.0, "hi": 40.0, "coeffs": PAPER_F0, "delay": 0,
              "creep_tau": [1.0, 50.0, 700.5, 1e6], "creep_weight": [0.01, -0.02, 0.03, 0.5]}


def lags(u, x_rest, tau, weight):
    """The creep term by its definition, in double: c[n] = sum_k w_k s_k[n],
    s_k[n+1] = s_k[n] + (u[n] - s_k[n]) / tau_k, every s_k x_rest at first."""
    s = np.full(len(tau), float(x_rest))
    out = []
    for v in u:
        out.append(float(np.dot(weight, s)))
        s = s + (v - s) / np.asarray(tau)
    return np.array(out)


def taken(x, lo, hi):
    """The inputs as the model takes them: clamped to [lo, hi], a NaN the
    last one (lo at first)."""
    last, out = float(lo), []
    for v in x:
        last = min(max(v, lo), hi) if np.isfinite(v) else last
        out.append(last)
    return np.array(out)


# ---- model files ----

def test_plant_file_reads_and_runs_as_the_cli(c_build, tmp_path):
    path = tmp_path / "plant.hyst"
    path.write_text(PLANT)
    m = hyst.load_model(path)
    assert m == {"kind": "poly", "lo": 0.0, "hi": 40.0, "delay": 3,
                 "coeffs": [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1],
                 "creep_tau": [2000.0], "creep_weight": [0.05]}
    x = signal(6000, 0.0, 40.0, seed=7)  # clamped samples included
    inp = tmp_path / "x.txt"
    np.savetxt(inp, x, fmt="%.17g")
    cli = numbers(run_cli(c_build, "sim", "--model", path, "--digits", 17, inp).stdout)
    y = hyst.model_from(m).process(x)
    # line k of sim --model is the model's output for input k - 3, bit for bit
    assert np.array_equal(cli[3:], y[:-3])
    # the creep term is there: the hysteresis model alone differs, by the
    # weighted lag of the clamped input
    bare = hyst.Model(m["coeffs"], 0, 40).process(x)
    creep = lags(taken(x, 0.0, 40.0), 0.0, [2000.0], [0.05])
    assert np.max(np.abs(y - bare)) > 0.5
    assert np.allclose(y - bare, creep, rtol=0, atol=1e-12)


@pytest.mark.parametrize("desc", [EV_CREEP, POLY_CREEP], ids=["everett", "poly"])
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_round_trip_bit_for_bit(tmp_path, desc, dtype):
    path = tmp_path / "m.hyst"
    hyst.save_model(path, **desc)
    m = hyst.load_model(path)
    assert m == {k: (list(map(float, v)) if isinstance(v, list) else v)
                 for k, v in desc.items()}
    lines = path.read_text().splitlines()
    assert lines[-3] == ("# creep: the output plus sum of creep_weight[k] s_k, s_k the input "
                         "lagged with time constant creep_tau[k] samples (from lo at rest)")
    assert lines[-2].split()[0] == "creep_tau" and lines[-1].split()[0] == "creep_weight"
    again = tmp_path / "again.hyst"
    hyst.save_model(again, **m)
    assert again.read_text() == path.read_text()
    x = signal(3000, desc["lo"], desc["hi"], seed=8).astype(dtype)
    assert np.array_equal(hyst.model_from(m, dtype=dtype).process(x),
                          hyst.model_from(desc, dtype=dtype).process(x))


def test_writer_writes_the_cli_text(c_build, tmp_path):
    """A model file with creep written by `hyst fit --save`, read and written
    back by the package: the same text, byte for byte (kind poly, whose
    comment lines are the tool's)."""
    rec = tmp_path / "rec.txt"
    x, y = plant_record()
    np.savetxt(rec, np.column_stack([x, y]), fmt="%.17g")
    path = tmp_path / "m.hyst"
    run_cli(c_build, "fit", "--degree", 3, "--delay", 3, "--save", path, rec)
    m = hyst.load_model(path)
    assert m["creep_tau"] == [2000.0]  # the automatic choice
    again = tmp_path / "again.hyst"
    hyst.save_model(again, **m)
    assert again.read_text() == path.read_text()


BAD = [  # the lines after the model, the message (as the tool's, after its "hyst sim: ")
    (["creep_tau 100"], ":6: field 1: creep_tau needs creep_weight too (creep: both or neither)"),
    (["creep_weight 0.1"],
     ":6: field 1: creep_weight needs creep_tau too (creep: both or neither)"),
    (["creep_tau 100 1000", "creep_weight 0.5"],
     ":7: field 3 is missing: creep_weight needs 2 numbers, one per creep_tau"),
    (["creep_weight 0.5 0.1", "creep_tau 100"],
     ":6: field 3: one too many: creep_weight needs 1 numbers, one per creep_tau"),
    (["creep_tau 0.5", "creep_weight 0.5"],
     ":6: field 2: '0.5' is not a time constant of at least 1 sample"),
    (["creep_tau 100 -3", "creep_weight 0.5 1"],
     ":6: field 3: '-3' is not a time constant of at least 1 sample"),
    (["creep_tau 1 2 3 4 5", "creep_weight 1 1 1 1 1"],
     ":6: field 6: one too many: creep_tau needs 1 to 4 numbers (one per creep term)"),
    (["creep_tau 1", "creep_weight 1 1 1 1 1"],
     ":7: field 6: one too many: creep_weight needs 1 to 4 numbers (one per creep term)"),
    (["creep_tau", "creep_weight 1"],
     ":6: field 2 is missing: creep_tau needs 1 to 4 numbers (one per creep term)"),
    (["creep_tau 10", "creep_weight nan"], ":7: field 2: 'nan' is not a finite number"),
    (["creep_tau inf", "creep_weight 1"], ":6: field 2: 'inf' is not a finite number"),
    (["creep_tau 10", "creep_weight 0.1 x"], ":7: field 3: 'x' is not a finite number"),
    (["creep_tau 10", "creep_weight 0.1", "creep_tau 20"], ":8: field 1: 'creep_tau' given twice"),
]


@pytest.mark.parametrize("after, message", BAD)
def test_refusals_name_file_line_and_field_as_the_cli(c_build, tmp_path, after, message):
    path = tmp_path / "bad.hyst"
    path.write_text("\n".join(["hyst-model-text 1", "kind poly", "lo 0", "hi 1", "coeffs 1 0"]
                              + after) + "\n")
    with pytest.raises(hyst.ModelFileError) as err:
        hyst.load_model(path)
    assert str(err.value) == f"{path}{message}"
    # the tool refuses it with the same words (one reader: tools/model_text)
    r = run_cli(c_build, "sim", "--model", path, ok=False, stdin="0.5\n")
    assert r.stderr.strip() == f"hyst sim: {path}{message}"


def test_creep_keys_of_either_kind_after_the_model_keys(tmp_path):
    """The creep keys may come anywhere, for either kind; a model key missing
    is reported before a creep key alone (the tool's order)."""
    path = tmp_path / "m.hyst"
    path.write_text("hyst-model-text 1\ncreep_weight 0.25\nkind everett\nlo 0\nhi 2\n"
                    "creep_tau 7\ny_lo 1\ndegree 1\nterms 2\n")
    m = hyst.load_model(path)
    assert m["kind"] == "everett" and (m["creep_tau"], m["creep_weight"]) == ([7.0], [0.25])
    path.write_text("hyst-model-text 1\nkind poly\nlo 0\ncreep_tau 7\ncoeffs 1 0\n")
    with pytest.raises(hyst.ModelFileError, match="the key hi is missing"):
        hyst.load_model(path)


def test_writer_refuses_what_the_reader_would(tmp_path):
    path = tmp_path / "m.hyst"
    good = {"coeffs": [1.0, 0.0], "lo": 0.0, "hi": 1.0}
    for creep in ({"creep_tau": [10.0]}, {"creep_weight": [1.0]},
                  {"creep_tau": [10.0, 20.0], "creep_weight": [1.0]},
                  {"creep_tau": [0.5], "creep_weight": [1.0]},
                  {"creep_tau": [math.nan], "creep_weight": [1.0]},
                  {"creep_tau": [10.0], "creep_weight": [math.inf]},
                  {"creep_tau": [10.0] * 5, "creep_weight": [1.0] * 5}):
        with pytest.raises(ValueError):
            hyst.save_model(path, **good, **creep)
        with pytest.raises(ValueError):
            hyst.header_text("m", **good, **creep)
        with pytest.raises(ValueError):
            hyst.Model(good["coeffs"], 0, 1, **creep)
    assert not path.exists()
    # empty lists: no creep term
    hyst.save_model(path, **good, creep_tau=[], creep_weight=[])
    assert "creep" not in path.read_text() and "creep_tau" not in hyst.load_model(path)


# ---- simulation and compensation ----

@pytest.mark.parametrize("desc", [EV_CREEP, POLY_CREEP], ids=["everett", "poly"])
def test_sim_and_inv_match_the_cli_bit_for_bit(c_build, tmp_path, desc):
    path = tmp_path / "m.hyst"
    hyst.save_model(path, **desc)
    d = desc["delay"]
    x = signal(5000, desc["lo"], desc["hi"], seed=9)
    inp = tmp_path / "x.txt"
    np.savetxt(inp, x, fmt="%.17g")
    cli = numbers(run_cli(c_build, "sim", "--model", path, "--digits", 17, inp).stdout)
    y = hyst.model_from(desc).process(x)
    assert len(cli) == len(x) and np.array_equal(cli[d:], y[:len(y) - d])
    # the compensator: the drive of each desired output, as inv --model
    # (which does not compensate the delay); sim's own outputs give back the
    # inputs (clamped)
    comp, drive = inv_matches_cli(c_build, tmp_path, path, desc, y)
    span = desc["hi"] - desc["lo"]
    assert np.max(np.abs(drive - np.clip(x, desc["lo"], desc["hi"]))) < 1e-9 * span
    # sample by sample, the same numbers; reset: the lags back at lo too
    comp.reset()
    assert np.array_equal([comp.step(v) for v in y], drive)
    m = hyst.model_from(desc)
    assert np.array_equal([m.step(v) for v in x], y)
    m.reset()
    assert np.array_equal(m.process(x), y)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_model_with_creep_is_the_sum(dtype):
    """In either variant: the hysteresis model's output plus the library's
    creep (Creep) of the inputs as the model took them; a NaN sample is
    ignored by both (the block status says so); the compensator's creep
    contribution is creep_output before each sample."""
    desc = dict(POLY_CREEP)
    x = signal(4000, desc["lo"], desc["hi"], seed=10, nonfinite=True).astype(dtype)
    m = hyst.model_from(desc, dtype=dtype)
    y = m.process(x)
    assert y.dtype == dtype and m.block_status == hyst.Status.ERR_NONFINITE
    bare = hyst.Model(desc["coeffs"], desc["lo"], desc["hi"], dtype=dtype)
    taken = []
    for v in x:
        bare.step(v)
        taken.append(bare.input)
    bare.reset()
    c = hyst.Creep(desc["creep_tau"], desc["creep_weight"], desc["lo"], dtype=dtype)
    want = bare.process(x) + c.process(np.array(taken, dtype=dtype))
    assert np.array_equal(y, want)
    assert m.creep_tau == desc["creep_tau"] and m.creep_weight == desc["creep_weight"]
    # the block status as without the creep term when every sample is finite
    fin = x[np.isfinite(x)]
    m.reset()
    m.process(fin)
    bare.reset()
    bare.process(fin)
    assert m.block_status == bare.block_status == hyst.Status.WARN_CLAMPED
    # the compensator: the hysteresis model's compensator of the desired
    # output less creep_output, the creep's share known before the sample
    comp = hyst.compensator_from(desc, dtype=dtype)
    alone = hyst.compensator_from({k: desc[k] for k in ("coeffs", "lo", "hi")}, dtype=dtype)
    for v in y[np.isfinite(y)][:500]:
        c = dtype(comp.creep_output)
        assert comp.step(v) == alone.step(dtype(v) - c)


def test_creep_is_the_librarys_lag():
    """Creep: c[n] = sum_k w_k s_k[n], s_k lags of the drive from x_rest,
    strictly causal (the first contribution is the rest's); float32 within
    the header's bound of the double one; NaN ignored with its status;
    reset and the accessors."""
    tau, w = [5.0, 300.0], [0.7, -0.2]
    x = signal(3000, -1.0, 3.0, seed=11, outside=False)
    c = hyst.Creep(tau, w, 0.5)
    assert c.size == 2 and c.tau == tau and c.weight == w and c.dtype == "float64"
    assert c.output == pytest.approx(0.5 * sum(w), rel=1e-15)
    out = c.process(x)
    assert np.allclose(out, lags(x, 0.5, tau, w), rtol=0, atol=1e-12)
    assert out[0] == pytest.approx(0.5 * sum(w), rel=1e-15)  # causal: x[0] not in c[0]
    c32 = hyst.Creep(tau, w, 0.5, dtype=np.float32)
    out32 = c32.process(x.astype(np.float32))
    m, n = 3.0, len(tau)
    # creep.h's bound, and the inputs' own rounding to float
    bound = (sum(abs(wk) * (tk + 4 * n + 12) for wk, tk in zip(w, tau)) / 2 +
             sum(map(abs, w))) * 2.0 ** -23 * m
    assert out32.dtype == np.float32 and np.max(np.abs(out32 - out)) <= bound
    c.reset()
    assert np.array_equal(c.process(x), out)
    c.reset(2.0)
    assert c.output == pytest.approx(2.0 * sum(w), rel=1e-15)
    before = c.output
    assert c.step(float("nan")) == before and c.output == before
    assert c.status == hyst.Status.ERR_NONFINITE and c.events & hyst.EVENT_NONFINITE
    c.clear_events()
    assert c.events == 0
    for bad in (([0.5], [1.0]), ([10.0], [1.0, 2.0]), ([], []), ([1.0] * 5, [1.0] * 5)):
        with pytest.raises(hyst.HystError) as err:
            hyst.Creep(*bad, 0.0)
        assert err.value.name == "ERR_ARG"
    with pytest.raises(hyst.HystError) as err:
        hyst.Creep([10.0], [math.nan], 0.0)
    assert err.value.name == "ERR_WEIGHTS"


def test_set_creep_and_the_library_refusals():
    m = hyst.Model(PAPER_F0, 0, 40)
    x = signal(2000, 0, 40, seed=12)
    y0 = m.process(x)
    m.set_creep([100.0], [0.1])
    assert not np.array_equal(m.process(x), y0)
    m.set_creep([], [])  # removed: the model alone again, from rest
    assert m.creep_tau == [] and m.creep_output == 0.0
    assert np.array_equal(m.process(x), y0)
    with pytest.raises(hyst.HystError) as err:
        m.set_creep([0.5], [0.1])
    assert err.value.name == "ERR_ARG"
    e = hyst.ModelFromEverett(**{k: EV_CREEP[k] for k in ("degree", "lo", "hi", "y_lo", "terms")})
    with pytest.raises(hyst.HystError) as err:
        e.set_creep([3.0], [math.inf])  # the library's check (the package checks first)
    assert err.value.name == "ERR_WEIGHTS"
    with pytest.raises(ValueError):
        hyst.ModelFromEverett(**{k: EV_CREEP[k] for k in ("degree", "lo", "hi", "y_lo", "terms")},
                              creep_tau=[3.0], creep_weight=[math.inf])


# ---- firmware headers ----

def from_guard(text):
    return text[text.index("#ifndef"):]


def creep_block(text):
    """The includes, and the creep block from its comment to its weights."""
    start = text.index("\n/* creep: ")
    end = text.index("};\n", text.index("_creep_weight[")) + 3
    return text[text.index("#include"):text.index("\n\n", text.index("#include"))], \
        text[start:end]


@pytest.mark.parametrize("desc", [EV_CREEP, POLY_CREEP], ids=["everett", "poly"])
@pytest.mark.parametrize("compensator", [False, True])
def test_header_is_the_clis(c_build, tmp_path, desc, compensator):
    """The creep block of header_text is hyst header's; kind poly's whole
    text from the include guard on is (kind everett's declaration writes
    fewer rows of zeros); with the compensator's table, the block precedes
    the table, whose lines are the tool's."""
    path = tmp_path / "m.hyst"
    hyst.save_model(path, **desc)
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path,
            *(["--compensator"] if compensator else []), "comp")
    cli_text = (tmp_path / "comp.h").read_text()
    text = hyst.header_text("comp", **desc, compensator=compensator)
    assert creep_block(text) == creep_block(cli_text)
    assert creep_block(text)[0] == '#include "hyst/curve.h"\n#include "hyst/creep.h"'
    n = len(desc["creep_tau"])
    assert f"#define comp_CREEP_TERMS {n}u\n" in text
    if desc["kind"] == "poly" and not compensator:
        assert from_guard(text) == from_guard(cli_text)
    if compensator:
        start = "#define comp_INTERVALS" if desc["kind"] == "poly" else "#define comp_ROWS"
        assert text.index("_creep_weight[") < text.index(start)
        assert text[text.index(start):] == cli_text[cli_text.index(start):]


def test_header_compiles_and_runs_with_the_creep_term(tmp_path):
    """The header's creep block in a C program (float and double builds):
    hyst_creep_init() takes it; in double the program gives the package's
    outputs bit for bit."""
    from test_model_file import CREEP_DECLARATION, CREEP_INIT, CREEP_STEP, run_on_header
    desc = {k: v for k, v in POLY_CREEP.items() if k != "delay"}
    x = signal(3000, desc["lo"], desc["hi"], seed=13)
    inp = tmp_path / "x.txt"
    np.savetxt(inp, x, fmt="%.17g")
    out = run_on_header(tmp_path, "plant", hyst.header_text("plant", **desc),
                        "hyst_init(&S, &plant, xl, yl, xr, yr, 4096) != HYST_OK" + CREEP_INIT,
                        inp, CREEP_DECLARATION, step=CREEP_STEP)
    assert np.array_equal(out, hyst.model_from(desc).process(x))


# ---- fit ----

def plant_record():
    """tests/cli/creep.sh's record: the plant (PLANT) driven by 30 triangles
    of 320 samples, its output 3 samples late (at rest before), plus
    +-0.01 um of deterministic noise (the same LCG)."""
    up = np.arange(0.0, 40.0, 0.25)
    x = np.concatenate([np.concatenate([up, 40.0 - up]) for _ in range(30)] + [[0.0]])
    m = {"coeffs": PAPER_F0, "lo": 0.0, "hi": 40.0, "creep_tau": [2000.0],
         "creep_weight": [0.05]}
    h = hyst.model_from(m).process(x)
    y = np.concatenate([np.full(3, h[0]), h[:-3]])
    s, noise = 12345, []
    for _ in range(len(x)):
        s = (s * 1103515245 + 12345) % 2147483648
        noise.append((s / 2147483648 - 0.5) * 0.02)
    return x, y + np.array(noise)


@pytest.fixture(scope="module")
def record():
    return plant_record()


def test_fit_chooses_the_creep_term_as_the_cli(c_build, tmp_path, record):
    x, y = record
    rec = tmp_path / "rec.txt"
    np.savetxt(rec, np.column_stack([x, y]), fmt="%.17g")
    f = hyst.fit(x, y, degree=None, delay=None)
    assert (f.kind, f.degree, f.delay, f.creep_tau) == ("poly", 3, 3, [2000.0])
    assert 0.049 < f.creep_weight[0] < 0.051
    cli = run_cli(c_build, "fit", rec).stdout
    assert "# chosen by hold-out: degree 3, delay 3 (kind poly, creep, 6 parameters" in cli
    assert f"# creep: tau 2000 samples, weight {f.creep_weight[0]:.9g} (hold-out rms " \
           f"{f.creep['holdout_rms']:.6g}; without it {f.creep['holdout_rms_without']:.6g})" in cli
    assert cli.splitlines()[0] == ",".join(f"{c:.15g}" for c in f.coeffs)
    chosen = [c for c in f.candidates if c["chosen"]]
    assert len(chosen) == 1 and chosen[0]["with_creep"] and chosen[0]["creep_tau"] == 2000.0
    # saved: the tool's model file, which sim --model runs as the package does
    path = tmp_path / "m.hyst"
    f.save(path)
    run_cli(c_build, "fit", "--save", tmp_path / "cli.hyst", rec)
    assert path.read_text() == (tmp_path / "cli.hyst").read_text()


def test_fit_creep_none_and_tau(c_build, tmp_path, record):
    x, y = record
    rec = tmp_path / "rec.txt"
    np.savetxt(rec, np.column_stack([x, y]), fmt="%.17g")
    none = hyst.fit(x, y, degree=None, delay=None, creep="none")
    assert none.creep is None and none.creep_tau == [] and "creep_tau" not in none.description()
    assert not any(c["with_creep"] for c in none.candidates)
    cli = run_cli(c_build, "fit", "--creep", "none", rec).stdout
    assert f"# chosen by hold-out: degree {none.degree}, delay {none.delay} (kind {none.kind}, " \
           in cli and "# creep" not in cli
    forced = hyst.fit(x, y, 3, delay=3, creep=500)
    assert forced.creep_tau == [500.0]
    cli = run_cli(c_build, "fit", "--creep", 500, "--degree", 3, "--delay", 3, rec).stdout
    assert cli.splitlines()[0] == ",".join(f"{c:.15g}" for c in forced.coeffs)
    assert f"# creep: tau 500 samples, weight {forced.creep_weight[0]:.9g} " in cli
    # a degree given: creep auto scores the model with and without it
    auto = hyst.fit(x, y, 3, delay=3)
    cli = run_cli(c_build, "fit", "--degree", 3, "--delay", 3, rec).stdout
    assert auto.creep_tau == [2000.0]
    assert cli.splitlines()[0] == ",".join(f"{c:.15g}" for c in auto.coeffs)
    for bad in ("sometimes", 0.5, 2e9, True, None, math.nan):
        with pytest.raises(ValueError, match="creep must be"):
            hyst.fit(x, y, 3, delay=3, creep=bad)


def test_fit_with_creep_predicts_and_compensates(record):
    """The fitted model with its creep term predicts the record (from rest,
    the delay applied) within the noise, far better than without; its
    compensator drives the plant to the desired outputs."""
    x, y = record
    f = hyst.fit(x, y, degree=None, delay=None)
    none = hyst.fit(x, y, degree=None, delay=None, creep="none")
    err = f.predict(x)[:-3] - y[3:]
    err_none = none.predict(x)[:-none.delay or None] - y[none.delay:]
    # (the record's noise is 0.006 RMS; without the term the drift is left)
    assert np.sqrt(np.mean(err ** 2)) < 0.03 < 0.2 < np.sqrt(np.mean(err_none ** 2))
    plant = {"coeffs": PAPER_F0, "lo": 0.0, "hi": 40.0, "creep_tau": [2000.0],
             "creep_weight": [0.05]}
    want = hyst.model_from(plant).process(signal(4000, 2.0, 38.0, seed=14, outside=False))
    drive = hyst.compensator_from(f.description()).process(want)
    got = hyst.model_from(plant).process(drive)
    assert np.max(np.abs(got - want)) < 0.05
