# SPDX-License-Identifier: MIT
"""The asymmetric kind on a grid (hyst_everett_grid_t, model files of kind
everett_grid) in the package: a file read by the one reader in C, its model
and its compensator bit for bit as `hyst sim --model` and `hyst inv
--model`; save_model and header_text write it as the tool does."""

import warnings

import numpy as np
import pytest

import hyst
from conftest import inv_matches_cli, run_cli, signal, sim_matches_cli

# tests/cli/grid.sh's plant: a near step between 1 and 1.4 of 0..3
PLANT = """hyst-model-text 1
kind everett_grid
lo 0
hi 3
y_lo 0
knots 0 1 1.4 3
weights 1 0.5 8 0.2 0.5 1
"""
# with a delay, a creep term and an identified range
PLANT_CREEP = PLANT + "delay 2\nidentified 0.5 2.5\ncreep_tau 300\ncreep_weight 0.05\n"


def loops():
    """tests/cli/grid.sh's record's input: minor loops of decreasing size."""
    out = []
    for c in range(12):
        a, b = 3 - c * 0.2, c * 0.2
        out += list(np.arange(b, a, 0.01)) + list(np.arange(a, b, -0.01))
    return np.array(out)


def test_load_model_gives_the_grid(tmp_path):
    path = tmp_path / "p.hyst"
    path.write_text(PLANT_CREEP)
    m = hyst.load_model(path)
    assert m["kind"] == "everett_grid" and m["knots"] == [0.0, 1.0, 1.4, 3.0]
    assert m["weights"] == [1.0, 0.5, 8.0, 0.2, 0.5, 1.0] and m["y_lo"] == 0.0
    assert m["delay"] == 2 and m["identified"] == (0.5, 2.5)
    assert m["creep_tau"] == [300.0] and m["creep_weight"] == [0.05]
    assert "coeffs" not in m and "terms" not in m


@pytest.mark.parametrize("text", [PLANT, PLANT_CREEP], ids=["plain", "creep"])
def test_sim_and_inv_match_the_cli_bit_for_bit(c_build, tmp_path, text):
    path = tmp_path / "p.hyst"
    path.write_text(text)
    x = np.concatenate([signal(3000, 0.0, 3.0, seed=4), loops()])
    desc, y = sim_matches_cli(c_build, tmp_path, path, x)
    # the compensator: sim's own outputs give the inputs back (clamped)
    comp, drive = inv_matches_cli(c_build, tmp_path, path, desc, y)
    # the model driven by it gives the desired outputs back; without a
    # creep term the drive is the input itself (clamped). With one, the
    # desired outputs may rise while the input falls (the lag rises): the
    # branch's slope is 0 at a turning point (a density, no step), so a
    # rounding's false reversal moves the drive by its square root (1.2e-4
    # here), not the output
    assert np.max(np.abs(hyst.model_from(desc).process(drive) - y)) < 1e-8 * np.ptp(y)
    if "creep_tau" not in desc:
        assert np.max(np.abs(drive - np.clip(x, 0.0, 3.0))) < 1e-9 * 3.0
    comp.reset()
    assert np.array_equal([comp.step(v) for v in y], drive)


def test_float32_follows_float64(tmp_path):
    path = tmp_path / "p.hyst"
    path.write_text(PLANT)
    desc = hyst.load_model(path)
    x = loops()
    y64 = hyst.model_from(desc).process(x)
    y32 = hyst.model_from(desc, dtype=np.float32).process(x.astype(np.float32))
    assert y32.dtype == np.float32
    assert np.max(np.abs(y32 - y64)) < 1e-5 * (np.max(y64) - np.min(y64))


def test_writer_writes_the_cli_text(c_build, tmp_path):
    """A grid fitted and saved by `hyst fit --kind everett_grid --save`, read
    and written back by the package: the same text, byte for byte."""
    x = loops()
    y = hyst.model_from(hyst.load_model(_plant(tmp_path))).process(x)
    rec = tmp_path / "rec.txt"
    np.savetxt(rec, np.column_stack([x, y]), fmt="%.17g")
    path = tmp_path / "fitted.hyst"
    run_cli(c_build, "fit", "--kind", "everett_grid", "--degree", 3, "--delay", 0, "--creep",
            "none", "--save", path, rec)
    m = hyst.load_model(path)
    assert m["kind"] == "everett_grid" and len(m["knots"]) == 4
    again = tmp_path / "again.hyst"
    hyst.save_model(again, **m)
    assert again.read_text() == path.read_text()
    # with a creep term, a delay and an identified range too
    p2 = tmp_path / "p2.hyst"
    p2.write_text(PLANT_CREEP)
    hyst.save_model(again, **hyst.load_model(p2))
    assert hyst.load_model(again) == hyst.load_model(p2)
    run_cli(c_build, "sim", "--model", again, "--digits", 17, rec)


def _plant(tmp_path):
    path = tmp_path / "plant.hyst"
    path.write_text(PLANT)
    return path


def test_header_is_the_clis(c_build, tmp_path):
    path = _plant(tmp_path)
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path, "g")
    cli_text = (tmp_path / "g.h").read_text()
    text = hyst.header_text("g", **hyst.load_model(path))
    guard = "#ifndef"
    assert text[text.index(guard):] == cli_text[cli_text.index(guard):]
    # the compensator: the same header, saying how firmware builds it; no table to size
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path, "--compensator", "g")
    cli_text = (tmp_path / "g.h").read_text()
    assert "hyst_curve_everett_grid_inverse()" in cli_text
    text = hyst.header_text("g", **hyst.load_model(path), compensator=True)
    assert "hyst_curve_everett_grid_inverse()" in text
    assert text[text.index(guard):] == cli_text[cli_text.index(guard):]
    with pytest.raises(ValueError, match="no compensator table"):
        hyst.header_text("g", **hyst.load_model(path), compensator=True, intervals=32)


def test_refusals(tmp_path):
    desc = hyst.load_model(_plant(tmp_path))
    with pytest.raises(hyst.HystError):
        hyst.compensator_from(desc, intervals=64)
    bad = dict(desc, weights=[1.0, -0.5, 8.0, 0.2, 0.5, 1.0])
    with pytest.raises(hyst.HystError):
        hyst.model_from(bad)
    with pytest.raises(ValueError):
        hyst.save_model(tmp_path / "bad.hyst", **dict(desc, weights=[1.0, 0.5]))
    with pytest.raises(ValueError):
        hyst.save_model(tmp_path / "bad.hyst", **dict(desc, knots=[0.5, 1.0, 1.4, 3.0]))
    assert not (tmp_path / "bad.hyst").exists()
    # a malformed file: the reader's words, naming file, line and field
    p = tmp_path / "m.hyst"
    p.write_text(PLANT.replace("knots 0 1", "knots 0.5 1"))
    with pytest.raises(hyst.ModelFileError, match=r"m.hyst:6: field 2: knots must run from lo"):
        hyst.load_model(p)


# ---- fit: the grid among the candidates, as `hyst fit` ----

def _record(tmp_path):
    x = loops()
    y = hyst.model_from(hyst.load_model(_plant(tmp_path))).process(x)
    rec = tmp_path / "rec.txt"
    np.savetxt(rec, np.column_stack([x, y]), fmt="%.17g")
    return x, y, rec


def test_fit_of_a_grid_is_the_clis(c_build, tmp_path):
    """fit(kind="everett_grid") runs the tool's grid fit: the same knots and
    masses as `hyst fit --kind everett_grid`, the knots near the plant's."""
    x, y, rec = _record(tmp_path)
    run_cli(c_build, "fit", "--kind", "everett_grid", "--degree", 3, "--delay", 0, "--creep",
            "none", "--save", tmp_path / "cli.hyst", rec)
    cli = hyst.load_model(tmp_path / "cli.hyst")
    f = hyst.fit(x, y, 3, kind="everett_grid", delay=0, creep="none")
    assert f.kind == "everett_grid" and f.degree == 3
    f.save(tmp_path / "py.hyst")
    assert hyst.load_model(tmp_path / "py.hyst") == cli
    assert abs(f.knots[1] - 1.0) < 0.02 and abs(f.knots[2] - 1.4) < 0.02
    span = np.max(y) - np.min(y)
    assert np.sqrt(np.mean((f.predict(x) - y) ** 2)) < 0.01 * span
    assert "everett_grid" in repr(f)


def test_auto_choice_is_the_clis_with_the_grid_kind(c_build, tmp_path):
    """On a record of a near step (an SMA-like sharp loop), fit() without a
    degree chooses a grid, as `hyst fit` does, with its degree and delay;
    the grid candidates are listed, and the saved models are the same."""
    x, y, rec = _record(tmp_path)
    cli = run_cli(c_build, "fit", "--creep", "none", "--save", tmp_path / "cli.hyst", rec).stdout
    f = hyst.fit(x, y, None, delay=None, creep="none")
    assert f.kind == "everett_grid"
    assert f"# chosen by hold-out: degree {f.degree}, delay {f.delay} (kind everett_grid" in cli
    kinds = {c["kind"] for c in f.candidates}
    assert kinds == {"poly", "everett", "everett_grid", "spline"}
    grid = [c for c in f.candidates if c["kind"] == "everett_grid"]
    assert all(c["t_degree"] is None for c in grid)
    f.save(tmp_path / "py.hyst")
    assert hyst.load_model(tmp_path / "py.hyst") == hyst.load_model(tmp_path / "cli.hyst")
    # kind="everett" alone: no grid candidate
    e = hyst.fit(x, y, None, kind="everett", delay=None, creep="none")
    assert {c["kind"] for c in e.candidates} == {"everett"}



def test_fit_says_when_the_record_does_not_determine_the_masses(c_build, tmp_path):
    """Major loops determine every mass of 3 intervals, not how the inner
    cells of 4 share theirs: fit(kind="everett_grid") then has determined
    False and warns (FitWarning) in hyst fit's words, which warns too."""
    x = np.concatenate([np.r_[np.arange(0, 3, 0.01), np.arange(3, 0, -0.01)]] * 3)
    y = hyst.model_from(hyst.load_model(_plant(tmp_path))).process(x)
    rec = tmp_path / "major.txt"
    np.savetxt(rec, np.column_stack([x, y]), fmt="%.17g")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        f3 = hyst.fit(x, y, 3, kind="everett_grid", delay=0, creep="none")
    assert f3.determined
    with pytest.warns(hyst.FitWarning, match="do not determine every mass of this grid") as w:
        f4 = hyst.fit(x, y, 4, kind="everett_grid", delay=0, creep="none")
    assert not f4.determined
    cli = run_cli(c_build, "fit", "--kind", "everett_grid", "--degree", 4, "--delay", 0,
                  "--creep", "none", rec)
    assert f"hyst fit: warning: {rec}: {w[0].message}" in cli.stderr
