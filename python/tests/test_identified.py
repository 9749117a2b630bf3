# SPDX-License-Identifier: MIT
"""A model file's sub-sample delay (`delay 3.5`) and identified range
(`identified LO HI`) in the package: read, written back and counted as the
`hyst` tool reads, writes and counts them; fit() fits a widened candidate
the tool's choice takes on the tool's widened domain and records the range
it was identified on."""
import re

import numpy as np

import hyst
from conftest import run_cli

# tests/cli/fidelity.sh's asymmetric plant
PLANT = {"kind": "everett", "lo": 0.0, "hi": 40.0, "y_lo": 0.0, "degree": 2,
         "terms": [3.0, -0.5, 1.0]}


def triangles():
    """Triangles from 0 to 8, 12, ..., 40, 0.1 a sample (fidelity.sh's drive)."""
    x = []
    for p in range(8, 41, 4):
        x += list(np.arange(0.0, p, 0.1)) + list(np.arange(float(p), 0.0, -0.1))
    return np.array(x + [0.0])


def test_fraction_and_identified_round_trip(tmp_path):
    path = tmp_path / "m.hyst"
    hyst.save_model(path, **PLANT, delay=3.5, identified=(2.5, 30.0))
    text = path.read_text()
    assert "\ndelay 3.5\n" in text and "\nidentified 2.5 30\n" in text, text
    m = hyst.load_model(path)
    assert m["delay"] == 3.5 and m["identified"] == (2.5, 30.0)
    hyst.save_model(tmp_path / "copy.hyst", **m)
    assert (tmp_path / "copy.hyst").read_text() == text
    hyst.save_model(path, **PLANT, delay=2)
    whole = hyst.load_model(path)
    assert whole["delay"] == 2 and isinstance(whole["delay"], int) and "identified" not in whole


def test_identified_outside_the_domain_is_refused(tmp_path):
    for bad in ((-1.0, 30.0), (30.0, 2.5), (2.5, 41.0)):
        try:
            hyst.save_model(tmp_path / "m.hyst", **PLANT, identified=bad)
        except ValueError as e:
            assert "identified" in str(e)
        else:
            raise AssertionError(f"identified {bad} accepted")
    assert not (tmp_path / "m.hyst").exists()


def test_outside_identified_counts_what_sim_counts(c_build, tmp_path):
    path = tmp_path / "m.hyst"
    hyst.save_model(path, **PLANT, identified=(5.0, 25.0))
    x = triangles()
    (tmp_path / "x.txt").write_text("\n".join(f"{v:.17g}" for v in x) + "\n")
    r = run_cli(c_build, "sim", "--model", path, tmp_path / "x.txt")
    said = int(re.search(r"note: \S*x\.txt: (\d+) of \d+ inputs outside", r.stderr).group(1))
    counted = hyst.outside_identified(hyst.load_model(path), x)
    assert counted == said > 0
    assert hyst.outside_identified(PLANT, x) == 0


def test_fit_takes_the_tools_widened_domain(c_build, tmp_path):
    x = triangles()
    y = hyst.model_from(PLANT).process(x)
    n = 2 * len(x) // 3
    rec = tmp_path / "train.txt"
    rec.write_text("".join(f"{a:.17g} {b:.17g}\n" for a, b in zip(x[:n], y[:n])))
    # the choice among the same candidates as Python's (delay 0..8, whole)
    run_cli(c_build, "fit", "--creep", "none", "--delay", "0", "--save", tmp_path / "cli.hyst",
            rec)
    cli = hyst.load_model(tmp_path / "cli.hyst")
    f = hyst.fit(x[:n], y[:n], degree=None, delay=0, creep="none")
    assert any(c.get("widened") for c in f.candidates)
    assert f.kind == cli["kind"] == "everett"
    assert (f.lo, f.hi) == (cli["lo"], cli["hi"])
    # widened above, predicted beyond, not clamped; below not: the record
    # starts at its lowest input, where the model rests (fit_widened_domain())
    assert f.lo == x[:n].min() == x[0] and f.hi > x[:n].max()
    assert f.identified == cli["identified"] == (x[:n].min(), x[:n].max())
    assert f.outside_identified(x) > 0
    f.save(tmp_path / "py.hyst")
    assert hyst.load_model(tmp_path / "py.hyst")["identified"] == cli["identified"]


def test_symmetric_kinds_widened_as_the_tool_widens_them(c_build, tmp_path):
    # a polynomial f0 plant (Eq. 20) on the same drive: f0 a polynomial and a
    # spline continued beyond the range fitted, as the tool chooses and saves them
    plant = {"kind": "poly", "lo": 0.0, "hi": 40.0,
             "coeffs": [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]}
    x = triangles()
    y = hyst.model_from(plant).process(x)
    n = 2 * len(x) // 3
    rec = tmp_path / "train.txt"
    rec.write_text("".join(f"{a:.17g} {b:.17g}\n" for a, b in zip(x[:n], y[:n])))
    for kind, cli_kind in (("spline", "spline"), ("poly", "tcm")):
        run_cli(c_build, "fit", "--kind", cli_kind, "--creep", "none", "--delay", "0",
                "--save", tmp_path / f"{cli_kind}.hyst", rec)
        cli = hyst.load_model(tmp_path / f"{cli_kind}.hyst")
        f = hyst.fit(x[:n], y[:n], kind=kind, degree=None, delay=0, creep="none")
        assert any(c.get("widened") for c in f.candidates if c["kind"] == kind)
        assert f.kind == cli["kind"] == kind
        assert (f.lo, f.hi) == (cli["lo"], cli["hi"]) and f.hi > x[:n].max()
        assert f.identified == cli["identified"] == (x[:n].min(), x[:n].max())
        assert f.outside_identified(x) > 0
        # predicted beyond the range fitted: within 2 % of the output range
        # (1 % for the spline); clamped, the spline's error was 2.9 %
        err = np.sqrt(np.mean((f.process(x) - y) ** 2)) / np.ptp(y)
        assert err < (0.01 if kind == "spline" else 0.02), (kind, err)
