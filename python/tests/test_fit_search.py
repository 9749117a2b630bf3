# SPDX-License-Identifier: MIT
"""fit(degree=None, delay=None) searches the delays as `hyst fit` does, by
the tool's own code (fit_search()): scaled to the drive's period beyond
MAX_DELAY samples, then a fraction of a sample; the model fitted on the
drive interpolated by it, saved with that delay."""
import re
import warnings

import numpy as np
import pytest

import hyst
from conftest import run_cli

PLANT = {"kind": "everett", "lo": 0.0, "hi": 40.0, "y_lo": 0.0, "degree": 2,
         "terms": [3.0, -0.5, 1.0]}
DELAY = 12.5  # samples: beyond MAX_DELAY, and half a sample


def record(tops=(40.0, 30.0, 40.0, 20.0, 40.0, 35.0, 40.0, 25.0, 40.0)):
    """Triangles of 40, 30, 40, 20, ... 0.05 a sample (a period of about
    1600 samples: delays up to 25 searched), the plant's output DELAY
    samples later (interpolated) plus a little noise."""
    x = []
    for top in tops:
        x += list(np.arange(0.0, top, 0.05)) + list(np.arange(top, 0.0, -0.05))
    x = np.array(x + [0.0])
    y = hyst.model_from(PLANT).process(x)
    whole, frac = int(DELAY), DELAY - int(DELAY)
    late = np.concatenate([np.full(whole + 1, y[0]), y])[: len(y) + 1]
    y = (1 - frac) * late[1:] + frac * late[:-1]  # y[k - DELAY]
    return x, y + 1e-4 * np.random.default_rng(5).standard_normal(len(y))


def cli_fit(c_build, tmp_path, x, y, *opts):
    """`hyst fit OPTS --save cli.hyst` on the record (x, y): its output."""
    rec = tmp_path / "rec.txt"
    rec.write_text("".join(f"{a:.17g} {b:.17g}\n" for a, b in zip(x, y)))
    return run_cli(c_build, "fit", *opts, "--save", tmp_path / "cli.hyst", rec)


def test_fit_searches_the_delays_as_the_tool(c_build, tmp_path):
    x, y = record()
    r = cli_fit(c_build, tmp_path, x, y)
    said = float(re.search(r"^# delay (\S+) samples", r.stdout, re.M).group(1))
    assert re.search(r"^# delays searched 0\.\.\d+ ", r.stdout, re.M)  # scaled to the period
    f = hyst.fit(x, y, None, delay=None)
    assert f.delay == said == DELAY
    cli = hyst.load_model(tmp_path / "cli.hyst")
    assert cli["delay"] == DELAY and f.kind == cli["kind"] == "everett"
    f.save(tmp_path / "py.hyst")
    py = hyst.load_model(tmp_path / "py.hyst")
    assert py["delay"] == DELAY and (py["lo"], py["hi"]) == (cli["lo"], cli["hi"])
    np.testing.assert_allclose(py["terms"], cli["terms"], rtol=1e-9, atol=1e-12)


def test_fit_with_no_option_is_the_tools_default(c_build, tmp_path):
    """fit(x, y) chooses as `hyst fit FILE` with no option: the same kind,
    delay and numbers (the model file both write)."""
    x, y = record()
    cli_fit(c_build, tmp_path, x, y)
    f = hyst.fit(x, y)
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()


def test_fit_of_a_degree_chooses_its_delay_as_the_tool(c_build, tmp_path):
    """fit(x, y, D) without a delay chooses the delay of that model as `hyst
    fit --degree D` does (fit_given_delay()): whole samples, then a fraction;
    delay=0 given is kept."""
    x, y = record()
    for kind, opts in (("poly", ["--degree", "3"]),
                       ("everett", ["--kind", "everett", "--degree", "2"])):
        cli_fit(c_build, tmp_path, x, y, *opts)
        cli = hyst.load_model(tmp_path / "cli.hyst")
        f = hyst.fit(x, y, int(opts[-1]), kind=kind)
        assert f.delay == cli["delay"] and f.delay > 10  # the plant's lag, not 0
        f.save(tmp_path / "py.hyst")
        assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    assert hyst.fit(x, y, 3, delay=0).delay == 0


@pytest.mark.parametrize("minor_loops", [False, True])
def test_fit_says_what_the_hold_out_tested_as_the_tool(c_build, tmp_path, minor_loops):
    """fit(x, y).excitation is what `hyst fit` prints of the hold-out, and
    the same warnings come (FitWarning): a last third of major loops only
    was not tested on minor loops."""
    # record()'s last third turns back inside the range (tops 35, 25), or
    # every triangle reaches 40: major loops only
    x, y = record() if minor_loops else record((40.0,) * 9)
    r = cli_fit(c_build, tmp_path, x, y)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        f = hyst.fit(x, y)
    e = f.excitation
    beyond = re.search(r"^# hold-out: (\d+) of its (\d+) inputs outside \[(\S+), (\S+)\]",
                       r.stdout, re.M).groups()
    assert (e["beyond"], e["holdout_n"]) == (int(beyond[0]), int(beyond[1]))
    assert (e["fitted_lo"], e["fitted_hi"]) == (float(beyond[2]), float(beyond[3]))
    said = re.search(r"^# hold-out excitation: its inputs span (\S+) %.*, (\d+) reversals",
                     r.stdout, re.M).groups()
    assert (round(100 * e["span"], 1), e["minor"]) == (float(said[0]), int(said[1]))
    assert (e["minor"] > 0) == minor_loops
    floor = re.search(r"^# hold-out noise floor: rms (\S+),", r.stdout, re.M)
    assert floor and f"{e['noise']:.6g}" == floor.group(1)
    assert abs(e["noise"] - 1e-4) <= 0.05e-4  # record()'s noise
    warned = [str(w.message) for w in caught if issubclass(w.category, hyst.FitWarning)]
    assert any("no minor loop" in m for m in warned) == ("no minor loop" in r.stderr) \
        == (not minor_loops)


def test_fit_leaves_the_noise_floor_unresolved_where_the_record_is_coarse(c_build, tmp_path):
    """A sine of 40 samples a period through the plant, with record()'s
    noise: the output's curvature between the drive's turns dominates its
    third and fourth differences, which then disagree, so neither front end
    states a noise floor."""
    x = 20.0 - 20.0 * np.cos(2.0 * np.pi * np.arange(1200) / 40.0)
    y = hyst.model_from(PLANT).process(x) + 1e-4 * np.random.default_rng(5).standard_normal(1200)
    r = cli_fit(c_build, tmp_path, x, y)
    assert re.search(r"^# hold-out noise floor: not resolved", r.stdout, re.M), r.stdout
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", hyst.FitWarning)
        assert hyst.fit(x, y).excitation["noise"] is None


def write_record(path, x, y):
    path.write_text("".join(f"{a:.17g} {b:.17g}\n" for a, b in zip(x, y)))
    return path


def test_fit_on_a_validation_record_chooses_as_the_tool(c_build, tmp_path):
    """fit(x, y, validate=(x2, y2)) chooses as `hyst fit --validate OTHER`
    (fit_search() scoring every candidate on the second record): the same
    model file, the validation RMS and excitation the tool prints; with a
    degree given, the delay chosen on it as `hyst fit --degree D
    --validate` chooses it."""
    x, y = record()
    x2, y2 = record((40.0, 25.0, 40.0, 35.0, 40.0, 15.0, 40.0))
    other = write_record(tmp_path / "other.txt", x2, y2)
    r = cli_fit(c_build, tmp_path, x, y, "--validate", other)
    said = re.search(r"^# chosen on \S*other\.txt: .*: validation rms (\S+)$", r.stdout, re.M)
    assert said, r.stdout
    f = hyst.fit(x, y, validate=(x2, y2))
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    assert f"{f.validation_rms:.6g}" == said.group(1)
    # the candidates' scores are the validation record's, not the hold-out's
    held_out = hyst.fit(x, y)
    assert [c["holdout_rms"] for c in f.candidates] != [c["holdout_rms"] for c in
                                                         held_out.candidates]
    e = f.excitation
    beyond = re.search(r"^# validation: (\d+) of its (\d+) inputs outside", r.stdout, re.M)
    assert (e["beyond"], e["holdout_n"]) == (int(beyond.group(1)), int(beyond.group(2)))
    floor = re.search(r"^# validation noise floor: rms (\S+),", r.stdout, re.M)
    assert floor and f"{e['noise']:.6g}" == floor.group(1)
    for kind, opts in (("poly", ["--degree", "3"]),
                       ("everett", ["--kind", "everett", "--degree", "2"])):
        r = cli_fit(c_build, tmp_path, x, y, *opts, "--validate", other)
        g = hyst.fit(x, y, int(opts[-1]), kind=kind, validate=(x2, y2))
        g.save(tmp_path / "py.hyst")
        assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
        said = re.search(r"^# validation on \S*other\.txt: rms (\S+) ", r.stdout, re.M)
        assert f"{g.validation_rms:.6g}" == said.group(1)


def test_fit_refuses_a_validation_record_as_the_record():
    """A validation record is refused as the record is: constant, falling,
    of two lengths, too short after skip, not a pair."""
    x, y = record()
    x2, y2 = record((40.0, 20.0, 40.0))
    for validate, message in (((x2, np.full(len(x2), 2.0)), "validate's y is constant"),
                              ((np.full(len(x2), 1.0), y2), "validate's x is constant"),
                              ((x2, -y2), "validate's y falls as validate's x rises"),
                              ((x2, y2[:-1]), "differ in length"),
                              ((x2[:1], y2[:1]), "a validation record needs two or more"),
                              (x2, "must be a record")):
        with pytest.raises(ValueError, match=message):
            hyst.fit(x, y, validate=validate)


def test_a_simulated_plant_is_recovered_not_its_rounding():
    """A record a model computed, without noise: every candidate of the
    plant's class predicts it to its rounding. Those errors count as the
    record's resolution (RESOLUTION of the output's range), so the
    plant's own degree and delay win, without a creep term, rather than
    whichever candidate's rounding happens to be 1 % lower."""
    from hyst._api import RESOLUTION
    coeffs = [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]  # Eq. 20: degree 3 on [0, 40]
    x = np.tile(np.concatenate([np.arange(0.0, 40.0, 0.25), np.arange(40.0, 0.0, -0.25)]), 9)
    y = hyst.Model(coeffs, 0.0, 40.0).process(x)
    x, y = x[3:], y[:-3]  # a sensor 3 samples late
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", hyst.FitWarning)  # major loops: no minor loop held out
        f = hyst.fit(x, y)
    assert (f.kind, f.degree, f.delay, list(f.creep_tau)) == ("poly", 3, 3, [])
    resolution = RESOLUTION * np.ptp(y[3:])
    at3 = [c for c in f.candidates if c["delay"] == 3 and np.isfinite(c["holdout_rms"])]
    exact = {(c["kind"], c["degree"]) for c in at3 if c["holdout_rms"] == resolution}
    assert exact >= {("poly", 3), ("poly", 9)}
    assert all(c["holdout_rms"] >= resolution for c in at3)


def minor_loop_record():
    """Eq. 20's plant (degree 3 on [0, 40]) driven with minor loops, plus
    +-0.0025 of noise: the record of tests/cli/select.sh's minor-loop case."""
    coeffs = [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]
    legs = [(0, 40), (40, 0), (0, 30), (30, 10), (10, 25), (25, 15), (15, 0)]
    x = np.concatenate([np.arange(a, b, 0.25 if b > a else -0.25) for a, b in legs] * 4 + [[0.0]])
    y = hyst.Model(coeffs, 0.0, 40.0).process(x)
    return x, y + 0.005 * (np.random.default_rng(7).random(len(y)) - 0.5)


@pytest.mark.parametrize("creep", ["auto", 100])
def test_e_of_the_width_alone_chosen_is_written_as_f0_as_by_the_tool(c_build, tmp_path, creep):
    """On minor loops f0's estimator is biased and E of t-degree 0 is
    chosen: the symmetric model, written as kind poly (its compensator a
    table) by fit() as by hyst fit, the same model file byte for byte,
    predicting as that E does."""
    x, y = minor_loop_record()
    f = hyst.fit(x, y, creep=creep)
    chosen = next(c for c in f.candidates if c["chosen"])
    assert (chosen["kind"], chosen["t_degree"]) == ("everett", 0)
    assert (f.kind, f.method, f.degree, f.everett["t_degree"]) == ("poly", "branches", 3, 0)
    np.testing.assert_allclose(f.coeffs, [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1],
                               rtol=0.02)
    e = hyst.model_from({"kind": "everett", "degree": 3, "lo": f.lo, "hi": f.hi,
                         "y_lo": f.everett["y_lo"], "terms": f.everett["terms"],
                         "creep_tau": f.creep_tau, "creep_weight": f.creep_weight})
    assert np.max(np.abs(f.predict(x) - e.process(x))) < 1e-9
    drive = f.make_compensator(intervals=256).process(f.predict(x))
    assert np.max(np.abs(drive - x)) < 1e-3
    opts = () if creep == "auto" else ("--creep", str(creep))
    out = cli_fit(c_build, tmp_path, x, y, *opts)
    assert "# written as kind poly: E of t-degree 0 is the symmetric model" in out.stdout
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    # kind="everett" asks for E: kept as E
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", hyst.FitWarning)
        assert hyst.fit(x, y, kind="everett", creep="none").kind == "everett"


def test_e_is_written_as_f0_only_where_it_is_an_increasing_f0():
    """poly_from_everett() (hyst fit's fit_poly_from_everett()) refuses an
    E with a term of t, one whose powers of x cancel (a domain far from 0)
    and one whose f0 falls; it expands the others exactly."""
    from hyst import _hyst
    assert _hyst.poly_from_everett(2, 0.0, 40.0, 0.0, [3.0, -0.5, 1.0]) is None
    np.testing.assert_allclose(_hyst.poly_from_everett(2, 0.0, 40.0, 0.5, [3.0, 0.0, 1.0]),
                               [1 / 1600, 3 / 40, 0.5], rtol=1e-15)
    np.testing.assert_allclose(_hyst.poly_from_everett(1, 10.0, 20.0, 2.0, [5.0]),
                               [0.5, -3.0], rtol=1e-15)
    assert _hyst.poly_from_everett(2, 0.0, 40.0, 0.0, [1.0, 0.0, -2.0]) is None
    far = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0]
    assert _hyst.poly_from_everett(4, 1e6, 1e6 + 1.0, 0.0, far) is None
    assert _hyst.poly_from_everett(4, 0.0, 1.0, 0.0, far) is not None


def test_method_branches_fits_f0_along_every_branch_as_the_tool(c_build, tmp_path):
    """method="branches" is hyst fit --method branches: f0 of kind poly
    fitted as E of t-degree 0 along every branch, unbiased on minor loops
    (no FitWarning, where the joint estimator warns), the same model file;
    refused above degree 4, for another kind, and where its powers of x
    cancel."""
    x, y = minor_loop_record()
    with warnings.catch_warnings():
        warnings.simplefilter("error", hyst.FitWarning)
        f = hyst.fit(x, y, 3, method="branches")
    assert (f.kind, f.method, f.degree, f.everett["t_degree"]) == ("poly", "branches", 3, 0)
    np.testing.assert_allclose(f.coeffs, [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1],
                               rtol=0.02)
    cli_fit(c_build, tmp_path, x, y, "--degree", "3", "--method", "branches")
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    with pytest.warns(hyst.FitWarning, match=r"or fit method='branches'"):
        joint = hyst.fit(x, y, 3)
    assert np.max(np.abs(joint.predict(x) - y)) > 10 * np.max(np.abs(f.predict(x) - y))
    for bad in ({"degree": 5}, {"kind": "everett"}, {"kind": "everett_grid"}):
        with pytest.raises(ValueError, match="method='branches'"):
            hyst.fit(x, y, method="branches", **bad)
    with pytest.raises(ValueError, match=r"no f0 in powers of x on \[1000000, 1000040\]"):
        hyst.fit(x + 1e6, y, 3, method="branches")
