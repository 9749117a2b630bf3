# SPDX-License-Identifier: MIT
"""Model files (hyst-model-text 1): what `hyst fit --save` writes, Python
reads, and the reverse; the model from the file runs bit for bit as the
CLI's `sim --model` (delay applied)."""
import os
import subprocess

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
