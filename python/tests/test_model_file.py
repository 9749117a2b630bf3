# SPDX-License-Identifier: MIT
"""Model files (hyst-model-text 1): what `hyst fit --save` writes, Python
reads, and the reverse; the model from the file runs bit for bit as the
CLI's `sim --model` (delay applied)."""
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import hyst

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "piezo_major_loop.dat")


def test_cli_model_file_round_trip(c_build, tmp_path):
    path = tmp_path / "m.hyst"
    subprocess.run([str(c_build["cli"]), "fit", "--degree", "4", "--skip", "350", "--delay", "2",
                    "--xcol", "1", "--ycol", "5", "--save", str(path), DATA],
                   check=True, capture_output=True)
    m = hyst.load_model(path)
    assert m["delay"] == 2 and len(m["coeffs"]) == 5
    assert len(m["creep_tau"]) == 1  # hyst fit --creep auto chose a creep term
    x = np.loadtxt(DATA, usecols=0)[350:1350]
    y = hyst.model_from(m).process(x)
    inp = tmp_path / "x.txt"
    np.savetxt(inp, x, fmt="%.17g")
    out = subprocess.run([str(c_build["cli"]), "sim", "--model", str(path), str(inp)],
                         check=True, capture_output=True, text=True).stdout.split()
    cli = np.array([float(v) for v in out])
    # line k of sim --model is the model's output for input k - 2 (9 digits printed)
    assert np.allclose(cli[2:], y[:-2], rtol=1e-8, atol=0)
    assert np.all(cli[:2] == cli[0])
    # written back by Python, read by Python and by the CLI: the same doubles
    again = tmp_path / "again.hyst"
    hyst.save_model(again, m["coeffs"], m["lo"], m["hi"], delay=m["delay"],
                    creep_tau=m["creep_tau"], creep_weight=m["creep_weight"])
    assert hyst.load_model(again) == m
    assert again.read_text() == path.read_text()  # the CLI's text, creep lines included
    out2 = subprocess.run([str(c_build["cli"]), "sim", "--model", str(again), str(inp)],
                          check=True, capture_output=True, text=True).stdout
    assert out2.split() == out


@pytest.mark.parametrize("lines, message", [
    (["hyst-model-text 2", "kind poly", "lo 0", "hi 1", "coeffs 1 0"], ":1:"),
    (["hyst-model-text 1", "kind poly", "lo 0", "hi 1", "gain 2", "coeffs 1 0"], ":5: field 1"),
    (["hyst-model-text 1", "kind poly", "lo 0", "coeffs 1 0"], "the key hi is missing"),
    (["hyst-model-text 1", "kind poly", "lo 0", "hi 1", "delay -1", "coeffs 1 0"], ":5: field 2"),
    (["hyst-model-text 1", "kind poly", "lo 0", "hi nan", "coeffs 1 0"], ":4: field 2"),
])
def test_malformed_model_files(tmp_path, lines, message):
    path = tmp_path / "bad.hyst"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(hyst.ModelFileError, match=message):
        hyst.load_model(path)


def test_fit_chooses_as_the_cli_and_the_header_reproduces_it(c_build, tmp_path):
    """Python fits the measured record with degree and delay chosen (the
    CLI's rule, the same candidates), saves the model and the header: the
    CLI (17 digits) and a C program built on the header give the package's
    outputs to the last bit, in double."""
    d = np.loadtxt(DATA)
    x, y = d[:, 0], d[:, 4]
    f = hyst.fit(x, y, degree=None, delay=None, skip=350, kind="poly")  # the CLI's kinds
    assert f.degree <= 5 and len(f.candidates) == 81
    cli = subprocess.run([str(c_build["cli"]), "fit", "--kind", "tcm", "--skip", "350",
                          "--xcol", "1", "--ycol", "5", DATA], check=True, capture_output=True,
                         text=True).stdout
    assert f"# chosen by hold-out: degree {f.degree}, delay {f.delay} " in cli
    scored = [c for c in f.candidates if np.isfinite(c["holdout_rms"])]
    for c in scored:  # the same scores, printed by the CLI with 6 digits
        assert f"# candidate degree {c['degree']} delay {c['delay']}: hold-out rms " \
               f"{c['holdout_rms']:.6g}," in cli

    # with both kinds, both choose the same model
    a = hyst.fit(x, y, degree=None, delay=None, skip=350)
    cli = subprocess.run([str(c_build["cli"]), "fit", "--skip", "350", "--xcol", "1",
                          "--ycol", "5", DATA], check=True, capture_output=True,
                         text=True).stdout
    chosen = [c for c in a.candidates if c["chosen"]][0]
    t_deg = f"t-degree {a.t_degree}, " if a.kind == "everett" else ""
    # the record drifts: both choose a creep term too, two parameters more
    assert chosen["with_creep"] and a.creep is not None
    assert f"# chosen by hold-out: degree {a.degree}, delay {a.delay} (kind {a.kind}, " \
           f"{t_deg}creep, {chosen['params'] + 2} parameters:" in cli
    assert f"\n# parameters {chosen['params'] + 2}\n" in cli
    assert f"\n# creep: tau {a.creep_tau[0]:.6g} samples, weight {a.creep_weight[0]:.9g} " \
           f"(hold-out rms {a.creep['holdout_rms']:.6g}; without it " \
           f"{a.creep['holdout_rms_without']:.6g})\n" in cli
    assert (a.kind, a.degree, a.t_degree) == ("everett", 4, 1)  # E linear in t
    everett = [c for c in a.candidates if c["kind"] == "everett"]
    assert len(everett) == 90 and cli.count("# candidate everett degree") == 90
    for c in everett:  # the same candidates, scored alike (6 digits) or refused alike
        line = f"# candidate everett degree {c['degree']} t-degree {c['t_degree']} " \
               f"delay {c['delay']}: "
        assert line + (f"hold-out rms {c['holdout_rms']:.6g}," if np.isfinite(c["holdout_rms"])
                       else "not scored") in cli, line
        if c["creep_tau"] > 0:  # and its creep term, scored alike
            assert f"; with creep tau {c['creep_tau']:.6g}: {c['creep_holdout_rms']:.6g}" in \
                cli.split(line)[1].split("\n")[0], line

    model = tmp_path / "m.hyst"
    f.save(model)
    assert f.creep is not None and hyst.load_model(model)["creep_tau"] == f.creep_tau
    xs = x[350:2350]
    want = hyst.model_from(f.description()).process(xs)
    inp = tmp_path / "x.txt"
    np.savetxt(inp, xs, fmt="%.17g")
    out = subprocess.run([str(c_build["cli"]), "sim", "--model", str(model), "--digits", "17",
                          str(inp)], check=True, capture_output=True, text=True).stdout.split()
    got = np.array([float(v) for v in out])
    assert np.array_equal(got[f.delay:], want[:len(want) - f.delay])  # bit for bit

    out = run_on_header(tmp_path, "f0_fit", f.header("f0_fit"),
                        "hyst_init(&S, &f0_fit, xl, yl, xr, yr, 4096) != HYST_OK" + CREEP_INIT,
                        inp, CREEP_DECLARATION, step=CREEP_STEP)
    assert np.array_equal(out, want)  # bit for bit, the creep term included


RUN_C = r"""
#include <stdio.h>
#include "hyst/hyst.h"
#include "NAME.h"
static double xl[4096], yl[4096], xr[4096], yr[4096];
int main(int argc, char **argv)
{
    DECLARATIONS
    hyst_t S;
    double x;
    FILE *in = argc > 1 ? fopen(argv[1], "r") : NULL;
    if (in == NULL || INIT_FAILS) {
        return 1;
    }
    while (fscanf(in, "%lf", &x) == 1) {
        printf("%.17g\n", STEP);
    }
    return fclose(in) != 0;
}
"""

# A model with a creep term in firmware: the creep of the input as the model
# took it added to its output (hyst/creep.h), every lag at lo at rest
CREEP_DECLARATION = "hyst_creep_t creep;"
CREEP_INIT = (" ||\n        hyst_creep_init(&creep, NAME_CREEP_TERMS, NAME_creep_tau, "
              "NAME_creep_weight, NAME.lo) != HYST_OK")
CREEP_STEP = "hyst_step(&S, x) + hyst_creep_step(&creep, hyst_input(&S))"


def run_on_header(tmp_path, name, header, init_fails, inputs, declarations="",
                  step="hyst_step(&S, x)"):
    """Builds a C program on `header` (NAME.h) and the library's sources, in
    double, with the project's warnings as errors: `init_fails` is the
    condition that prepares the instance S, true on failure; `step` the
    output of an input x. Runs it on the file `inputs`; returns its outputs
    (17 digits)."""
    (tmp_path / f"{name}.h").write_text(header)
    program = RUN_C.replace("DECLARATIONS", declarations).replace("STEP", step)
    program = program.replace("INIT_FAILS", init_fails).replace("NAME", name)
    (tmp_path / "run.c").write_text(program)
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    srcs = sorted(os.path.join(root, "src", s) for s in os.listdir(os.path.join(root, "src"))
                  if s.endswith(".c"))
    exe = tmp_path / "run"
    subprocess.run(["cc", "-std=c99", "-O2", "-DHYST_USE_DOUBLE", "-Wall", "-Wextra", "-Wpedantic",
                    "-Wconversion", "-Wshadow", "-Werror", "-I", str(tmp_path),
                    "-I", os.path.join(root, "include"), str(tmp_path / "run.c"), *srcs,
                    "-lm", "-o", str(exe)], check=True)
    out = subprocess.run([str(exe), str(inputs)], check=True, capture_output=True,
                         text=True).stdout.split()
    return np.array([float(v) for v in out])


@pytest.mark.parametrize("kind, degree, delay, most, drive_most", [
    # um, on the measured record (the fit's own residual is ~0.34); drive 0.027 V
    ("poly", 3, 3, 1.0, 0.04),
    ("everett", 2, 4, 0.3, 0.03),  # its least-squares residual is 0.23; drive 0.018 V
])
def test_plot_command_without_code(tmp_path, kind, degree, delay, most, drive_most):
    """python -m hyst plot: a figure from a data file and a model file; the
    compensator of either kind, driven by the measured output, gives about
    the drive that was applied (0 .. 3.6 V)."""
    pytest.importorskip("matplotlib")
    d = np.loadtxt(DATA)
    f = hyst.fit(d[:, 0], d[:, 4], degree, kind=kind, skip=350, delay=delay)
    model = tmp_path / "m.hyst"
    f.save(model)
    fig = tmp_path / "fig.png"
    out = subprocess.run([sys.executable, "-m", "hyst", "plot", DATA, "--model", str(model),
                          "--xcol", "1", "--ycol", "5", "--skip", "350", "--out", str(fig)],
                         check=True, capture_output=True, text=True,
                         env={**os.environ, "MPLBACKEND": "Agg"}).stdout
    assert fig.stat().st_size > 10000 and fig.read_bytes()[:4] == b"\x89PNG"
    rms = float(out.split("error RMS ")[1].split(",")[0])
    assert 0 < rms < most
    drive_rms = float(out.split("applied RMS ")[1])
    assert 0 < drive_rms < drive_most


# ---- the asymmetric kind (kind everett) ----

EVERETT_TEXT = """hyst-model-text 1
# comment lines as now
kind everett
lo 0
hi 3.6000000000000001
y_lo -0.035382239014971697
delay 3
degree 2
terms 0.61 0.02 -0.1
"""


def test_everett_file_reads_as_written(tmp_path):
    path = tmp_path / "e.hyst"
    path.write_text(EVERETT_TEXT)
    m = hyst.load_model(path)
    assert m == {"kind": "everett", "lo": 0.0, "hi": 3.6, "y_lo": -0.035382239014971697,
                 "delay": 3, "degree": 2, "terms": [0.61, 0.02, -0.1]}
    model = hyst.model_from(m)
    assert model.kind == "everett" and model.terms == [0.61, 0.02, -0.1]
    # written back: the same keys in the same order, read back: the same dict
    again = tmp_path / "again.hyst"
    hyst.save_model(again, **m)
    lines = again.read_text().splitlines()
    assert lines[0] == "hyst-model-text 1" and lines[1].startswith("# ")
    assert [ln.split()[0] for ln in lines[2:]] == ["kind", "lo", "hi", "y_lo", "delay", "degree",
                                                    "terms"]
    assert lines[2] == "kind everett"
    assert lines[-1] == "terms 0.60999999999999999 0.02 -0.10000000000000001"  # 17 digits
    assert hyst.load_model(again) == m


@pytest.mark.parametrize("degree", [1, 2, 3, 4])
def test_everett_round_trip_bit_for_bit(tmp_path, degree):
    rng = np.random.default_rng(degree)
    n = degree * (degree + 1) // 2
    # awkward doubles: random mantissas over many exponents, a negative zero,
    # the smallest subnormal
    terms = list(rng.standard_normal(n) * 10.0 ** rng.integers(-300, 300, n))
    terms[0] = -0.0
    if n > 1:
        terms[1] = 5e-324
    lo, hi, y_lo = float(rng.uniform(-1, 0)), float(rng.uniform(1, 2)), 1 / 3
    path = tmp_path / "e.hyst"
    hyst.save_model(path, lo=lo, hi=hi, kind="everett", degree=degree, y_lo=y_lo, terms=terms,
                    delay=degree)
    m = hyst.load_model(path)
    got = np.array([m["lo"], m["hi"], m["y_lo"]] + m["terms"])
    want = np.array([lo, hi, y_lo] + terms)
    assert got.view(np.uint64).tolist() == want.view(np.uint64).tolist()
    assert (m["kind"], m["degree"], m["delay"]) == ("everett", degree, degree)


GOOD_E = ["hyst-model-text 1", "kind everett", "lo 0", "hi 3.6", "y_lo -0.03", "degree 2",
          "terms 0.61 0.02 -0.1"]


@pytest.mark.parametrize("lines, message", [
    (GOOD_E + ["coeffs 1 0"], ":8: field 1: coeffs is not a key of kind everett"),
    (["hyst-model-text 1", "kind poly", "lo 0", "hi 1", "coeffs 1 0", "terms 1"],
     ":6: field 1: terms is not a key of kind poly"),
    (["hyst-model-text 1", "y_lo 2", "kind poly", "lo 0", "hi 1", "coeffs 1 0"],
     ":2: field 1: y_lo is not a key of kind poly"),
    (["hyst-model-text 1", "kind poly", "lo 0", "hi 1", "degree 1", "coeffs 1 0"],
     ":5: field 1: degree is not a key of kind poly"),
    ([ln for ln in GOOD_E if not ln.startswith("y_lo")], "the key y_lo is missing"),
    ([ln for ln in GOOD_E if not ln.startswith("degree")], "the key degree is missing"),
    ([ln for ln in GOOD_E if not ln.startswith("terms")], "the key terms is missing"),
    ([ln for ln in GOOD_E if not ln.startswith("lo")], "the key lo is missing"),
    ([ln for ln in GOOD_E if not ln.startswith("kind")], "the key kind is missing"),
    (GOOD_E[:5] + ["degree 0", GOOD_E[6]], ":6: field 2: '0' is not a degree in 1..4"),
    (GOOD_E[:5] + ["degree 5", GOOD_E[6]], ":6: field 2: '5' is not a degree in 1..4"),
    (GOOD_E[:5] + ["degree 2.5", GOOD_E[6]], ":6: field 2: '2.5' is not a degree in 1..4"),
    (GOOD_E[:5] + ["degree 2 3", GOOD_E[6]], ":6: field 3: one too many: degree needs one value"),
    (GOOD_E[:6] + ["terms 0.61 0.02"], ":7: field 4 is missing: terms needs 3 numbers for degree 2"),
    (GOOD_E[:6] + ["terms 0.61 0.02 -0.1 0"], ":7: field 5: one too many: terms needs 3 numbers for degree 2"),
    (GOOD_E[:6] + ["terms 0.61 inf -0.1"], ":7: field 3: 'inf' is not a finite number"),
    (GOOD_E[:6] + ["terms 0.61 0.02 x"], ":7: field 4: 'x' is not a finite number"),
    (GOOD_E[:6] + ["terms"], ":7: field 2 is missing: terms needs 1 to 10 numbers (E's coefficients)"),
    (GOOD_E[:4] + ["y_lo nan"] + GOOD_E[5:], ":5: field 2: 'nan' is not a finite number"),
    (GOOD_E + ["terms 1 2 3"], ":8: field 1: 'terms' given twice"),
    (["hyst-model-text 1", "kind preisach"] + GOOD_E[2:], ":2: field 2: kind must be"),
    (["hyst-model-text 1", "kind everett poly"] + GOOD_E[2:], ":2: field 2: kind must be"),
])
def test_malformed_everett_files(tmp_path, lines, message):
    path = tmp_path / "bad.hyst"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(hyst.ModelFileError) as err:
        hyst.load_model(path)
    assert str(err.value).startswith(str(path)) and message in str(err.value)


def test_everett_writer_refuses_what_the_reader_would(tmp_path):
    path = tmp_path / "e.hyst"
    good = {"lo": 0.0, "hi": 1.0, "kind": "everett", "degree": 2, "y_lo": 0.0,
            "terms": [1.0, 0.0, 0.0]}
    for change in ({"terms": [1.0, 0.0]}, {"degree": 5, "terms": [1.0] * 15},
                   {"terms": [1.0, math.nan, 0.0]}, {"y_lo": math.inf}, {"coeffs": [1.0, 0.0]},
                   {"y_lo": None}, {"kind": "pwl"}, {"hi": math.nan}):
        with pytest.raises(ValueError):
            hyst.save_model(path, **dict(good, **change))
    with pytest.raises(ValueError):
        hyst.save_model(path, [1.0, 0.0], 0.0, 1.0, terms=[1.0])  # poly with an everett key
    assert not path.exists()


def test_everett_header_compiles_and_reproduces_the_model(tmp_path):
    """header_text of kind everett: a hyst_everett_t initializer that the C
    compiler takes with the project's warnings as errors; a C program built
    on it gives the package's outputs to the last bit, in double."""
    x, y = np.loadtxt(DATA, usecols=(0, 4)).T
    f = hyst.fit(x, y, 2, kind="everett", skip=350, delay=1)
    text = f.header("e_fit")
    assert "static const hyst_everett_t e_fit = {\n    2u, " in text
    assert f.creep is not None and "#define e_fit_CREEP_TERMS 1u\n" in text
    xs = x[350:2350]
    inp = tmp_path / "x.txt"
    np.savetxt(inp, xs, fmt="%.17g")
    out = run_on_header(tmp_path, "e_fit", text,
                        "hyst_curve_from_everett(&curve, &e_fit) != HYST_OK ||\n"
                        "        hyst_init_curve(&S, &curve, xl, yl, xr, yr, 4096) != HYST_OK" +
                        CREEP_INIT, inp,
                        declarations="hyst_curve_t curve;\n    " + CREEP_DECLARATION,
                        step=CREEP_STEP)
    assert np.array_equal(out, hyst.model_from(f.description()).process(xs))  # bit for bit
    # the same header from the model file, passed whole
    f.save(tmp_path / "e.hyst")
    assert hyst.header_text("e_fit", **hyst.load_model(tmp_path / "e.hyst")) == text


def test_save_writes_regular_files_only(tmp_path):
    # as hyst fit --save: a link is written through, kept; a directory, a pipe
    # or a link to nothing is refused, left as it was, with no file beside it
    f0 = dict(coeffs=[1.0, 0.0], lo=0.0, hi=1.0)
    real = tmp_path / "real.hyst"
    real.write_text("old")
    link = tmp_path / "link.hyst"
    link.symlink_to(real)
    hyst.save_model(link, **f0)
    assert link.is_symlink() and hyst.load_model(real)["coeffs"] == [1.0, 0.0]
    pipe = tmp_path / "pipe"
    os.mkfifo(pipe)
    dangling = tmp_path / "dangling.hyst"
    dangling.symlink_to(tmp_path / "nowhere" / "m.hyst")
    for target, error, said in ((tmp_path, IsADirectoryError, "is a directory"),
                                (pipe, OSError, "not a regular file"),
                                (dangling, FileNotFoundError, "link to nothing")):
        before = sorted(p.name for p in tmp_path.iterdir())
        with pytest.raises(error, match=said):
            hyst.save_model(target, **f0)
        assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert pipe.is_fifo() and dangling.is_symlink()


def test_header_of_a_curve_firmware_refuses_is_refused():
    # as hyst header: no header of a model whose init would fail
    with pytest.raises(hyst.HystError) as err:
        hyst.header_text("falls", [-1.0, 0.0], 0.0, 1.0)
    assert err.value.status == hyst.Status.ERR_NOT_INCREASING
    with pytest.raises(hyst.HystError) as err:
        hyst.header_text("e", kind="everett", degree=1, lo=0.0, hi=1.0, y_lo=0.0, terms=[-1.0])
    assert err.value.status == hyst.Status.ERR_NOT_MONOTONE
    assert "hyst_poly_t rises" in hyst.header_text("rises", [1.0, 0.0], 0.0, 1.0)
