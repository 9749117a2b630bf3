# SPDX-License-Identifier: MIT
"""Model files (hyst-model-text 1): what `hyst fit --save` writes, Python
reads, and the reverse; the model from the file runs bit for bit as the
CLI's `sim --model` (delay applied)."""
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
    x = np.loadtxt(DATA, usecols=0)[350:1350]
    y = hyst.Model(m["coeffs"], m["lo"], m["hi"]).process(x)
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
    hyst.save_model(again, m["coeffs"], m["lo"], m["hi"], delay=m["delay"])
    assert hyst.load_model(again) == m
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
    f = hyst.fit(x, y, degree=None, delay=None, skip=350)
    assert f.degree <= 5 and len(f.candidates) == 81
    cli = subprocess.run([str(c_build["cli"]), "fit", "--skip", "350", "--xcol", "1",
                          "--ycol", "5", DATA], check=True, capture_output=True,
                         text=True).stdout
    assert f"# chosen by hold-out: degree {f.degree}, delay {f.delay} " in cli
    scored = [c for c in f.candidates if np.isfinite(c["holdout_rms"])]
    for c in scored:  # the same scores, printed by the CLI with 6 digits
        assert f"# candidate degree {c['degree']} delay {c['delay']}: hold-out rms " \
               f"{c['holdout_rms']:.6g}," in cli

    model = tmp_path / "m.hyst"
    f.save(model)
    xs = x[350:2350]
    want = hyst.Model(f.coeffs, f.lo, f.hi).process(xs)
    inp = tmp_path / "x.txt"
    np.savetxt(inp, xs, fmt="%.17g")
    out = subprocess.run([str(c_build["cli"]), "sim", "--model", str(model), "--digits", "17",
                          str(inp)], check=True, capture_output=True, text=True).stdout.split()
    got = np.array([float(v) for v in out])
    assert np.array_equal(got[f.delay:], want[:len(want) - f.delay])  # bit for bit

    (tmp_path / "f0_fit.h").write_text(f.header("f0_fit"))
    (tmp_path / "run.c").write_text(RUN_C)
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    srcs = sorted(os.path.join(root, "src", s) for s in os.listdir(os.path.join(root, "src"))
                  if s.endswith(".c"))
    exe = tmp_path / "run"
    subprocess.run(["cc", "-std=c99", "-O2", "-DHYST_USE_DOUBLE", "-I", str(tmp_path),
                    "-I", os.path.join(root, "include"), str(tmp_path / "run.c"), *srcs,
                    "-lm", "-o", str(exe)], check=True)
    out = subprocess.run([str(exe), str(inp)], check=True, capture_output=True,
                         text=True).stdout.split()
    assert np.array_equal(np.array([float(v) for v in out]), want)  # bit for bit


RUN_C = r"""
#include <stdio.h>
#include "hyst/hyst.h"
#include "f0_fit.h"
static double xl[4096], yl[4096], xr[4096], yr[4096];
int main(int argc, char **argv)
{
    hyst_t S;
    double x;
    FILE *in = argc > 1 ? fopen(argv[1], "r") : NULL;
    if (in == NULL || hyst_init(&S, &f0_fit, xl, yl, xr, yr, 4096) != HYST_OK) {
        return 1;
    }
    while (fscanf(in, "%lf", &x) == 1) {
        printf("%.17g\n", hyst_step(&S, x));
    }
    return fclose(in) != 0;
}
"""


def test_plot_command_without_code(tmp_path):
    """python -m hyst plot: a figure from a data file and a model file."""
    pytest.importorskip("matplotlib")
    d = np.loadtxt(DATA)
    f = hyst.fit(d[:, 0], d[:, 4], degree=3, skip=350, delay=3)
    model = tmp_path / "m.hyst"
    f.save(model)
    fig = tmp_path / "fig.png"
    out = subprocess.run([sys.executable, "-m", "hyst", "plot", DATA, "--model", str(model),
                          "--xcol", "1", "--ycol", "5", "--skip", "350", "--out", str(fig)],
                         check=True, capture_output=True, text=True,
                         env={**os.environ, "MPLBACKEND": "Agg"}).stdout
    assert fig.stat().st_size > 10000 and fig.read_bytes()[:4] == b"\x89PNG"
    rms = float(out.split("error RMS ")[1].split(",")[0])
    assert 0 < rms < 1.0  # um, on the measured record (the fit's own residual is ~0.34)
