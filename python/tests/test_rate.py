# SPDX-License-Identifier: MIT
"""The rate term (hyst/rate.h, docs/rate.md) in the package: a model file
with rate_tau and rate_weight is read and run as `hyst sim --model` and
`hyst inv --model` run it, bit for bit; the term is the library's low-pass
of the change of the input as the model took it."""

import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, inv_matches_cli, numbers, run_cli, signal

# an asymmetric model with a creep lag and a rate term, and a poly on a
# domain that does not start at 0 with a rate term alone
EV_RATE = """hyst-model-text 1
kind everett
lo 0
hi 40
y_lo 0.5
delay 2
degree 3
terms 3 1 0 2 -0.5 0.4
creep_tau 300
creep_weight 0.02
rate_tau 4
rate_weight 0.3
"""
POLY_RATE = ("hyst-model-text 1\nkind poly\nlo 5\nhi 40\n"
             "coeffs " + " ".join("%.17g" % c for c in PAPER_F0) + "\n"
             "rate_tau 1\nrate_weight -0.05\n")


def low_pass(u, x_rest, tau, weight):
    """The rate term by its definition, in double: r[n] = w v[n],
    v[n+1] = v[n] + ((u[n] - u[n-1]) - v[n]) / tau, u[-1] = x_rest, v[0] = 0."""
    v, last, out = 0.0, float(x_rest), []
    for x in u:
        out.append(weight * v)
        v = v + ((x - last) - v) / tau
        last = x
    return np.array(out)


@pytest.mark.parametrize("text", [EV_RATE, POLY_RATE], ids=["everett", "poly"])
def test_sim_and_inv_match_the_cli_bit_for_bit(c_build, tmp_path, text):
    path = tmp_path / "m.hyst"
    path.write_text(text)
    desc = hyst.load_model(path)
    assert desc["rate_tau"] in (4.0, 1.0) and desc["rate_weight"] in (0.3, -0.05)
    d = desc["delay"]
    x = signal(5000, desc["lo"], desc["hi"], seed=11)  # clamped samples included
    inp = tmp_path / "x.txt"
    np.savetxt(inp, x, fmt="%.17g")
    cli = numbers(run_cli(c_build, "sim", "--model", path, "--digits", 17, inp).stdout)
    y = hyst.model_from(desc).process(x)
    assert len(cli) == len(x) and np.array_equal(cli[d:], y[:len(y) - d])
    # the rate term is there: without it the model differs by the low-pass
    # of the clamped input's change
    bare = {k: v for k, v in desc.items() if not k.startswith("rate_")}
    u = np.clip(x, desc["lo"], desc["hi"])
    rate = low_pass(u, desc["lo"], desc["rate_tau"], desc["rate_weight"])
    diff = y - hyst.model_from(bare).process(x)
    assert np.max(np.abs(diff)) > 0.1
    assert np.allclose(diff, rate, rtol=0, atol=1e-12)
    # the compensator, as inv --model; sim's outputs give back the inputs
    comp, drive = inv_matches_cli(c_build, tmp_path, path, desc, y)
    assert np.max(np.abs(drive - u)) < 1e-9 * (desc["hi"] - desc["lo"])
    # sample by sample the same numbers; reset: the term back at rest too
    comp.reset()
    assert np.array_equal([comp.step(v) for v in y], drive)
    m = hyst.model_from(desc)
    assert np.array_equal([m.step(v) for v in x], y)
    m.reset()
    assert np.array_equal(m.process(x), y)


@pytest.mark.parametrize("text", [EV_RATE, POLY_RATE], ids=["everett", "poly"])
def test_snapshot_keeps_the_rate_term(tmp_path, text):
    """save() holds the hysteresis model's memory, the creep's lags and the
    rate term's state (hyst_rate_snapshot_save): restored into a new model
    of the file, it continues bit for bit; a snapshot without the rate term
    into a model with one, or the other way round, is refused."""
    path = tmp_path / "m.hyst"
    path.write_text(text)
    desc = hyst.load_model(path)
    x = signal(4000, desc["lo"], desc["hi"], seed=12)
    m = hyst.model_from(desc)
    m.process(x[:1500])
    snap = m.save()
    want = m.process(x[1500:])
    other = hyst.model_from(desc)
    other.restore(snap)
    assert np.array_equal(other.process(x[1500:]), want)
    bare = hyst.model_from({k: v for k, v in desc.items() if not k.startswith("rate_")})
    bare.process(x[:1500])
    with pytest.raises(hyst.HystError, match="the snapshot has a rate term"):
        bare.restore(snap)
    with pytest.raises(hyst.HystError, match="the model has a rate term"):
        other.restore(bare.save())


def test_refused_where_not_applied(tmp_path):
    path = tmp_path / "m.hyst"
    path.write_text(POLY_RATE)
    m = hyst.model_from(hyst.load_model(path))
    with pytest.raises(hyst.HystError, match="rate_tau and rate_weight"):
        m.set_rate(2.0, None)
    with pytest.raises(hyst.HystError):
        m.set_rate(0.5, 1.0)  # below 1 sample: the library refuses it
    assert m.rate_tau == 1.0
    m.set_rate(None, None)  # removed
    assert m.rate_tau is None and m.rate_weight is None
    with pytest.raises(ValueError, match="rate_tau and rate_weight"):
        hyst.save_model(tmp_path / "again.hyst", coeffs=[1.0, 0.0], lo=0, hi=1, rate_tau=2.0)
    with pytest.raises(ValueError, match="rate_tau"):  # the reader's check
        hyst.save_model(tmp_path / "again.hyst", coeffs=[1.0, 0.0], lo=0, hi=1, rate_tau=0.5,
                        rate_weight=1.0)
    assert not (tmp_path / "again.hyst").exists()


@pytest.mark.parametrize("text", [EV_RATE, POLY_RATE], ids=["everett", "poly"])
def test_written_as_the_cli_writes_it(c_build, tmp_path, text):
    """save_model(**load_model(f)) keeps the rate term, in the tool's words;
    header_text's rate block is `hyst header --model`'s (kind poly: the
    whole text from the include guard on)."""
    path = tmp_path / "m.hyst"
    path.write_text(text)
    desc = hyst.load_model(path)
    again = tmp_path / "again.hyst"
    hyst.save_model(again, **desc)
    assert hyst.load_model(again) == desc
    lines = again.read_text().splitlines()
    assert lines[-2:] == ["rate_tau %.17g" % desc["rate_tau"],
                          "rate_weight %.17g" % desc["rate_weight"]]
    run_cli(c_build, "header", "--model", path, "--dir", tmp_path, "mdl")
    cli_text = (tmp_path / "mdl.h").read_text()
    mine = hyst.header_text("mdl", **desc)
    block = mine[mine.index("/* rate:"):mine.index(";", mine.index("mdl_rate_weight")) + 1]
    assert block in cli_text and "mdl_rate_tau" in block
    assert '#include "hyst/rate.h"' in mine
    if desc["kind"] == "poly":
        assert mine[mine.index("#ifndef"):] == cli_text[cli_text.index("#ifndef"):]


@pytest.mark.parametrize("rate", ["1", "auto"])
def test_fit_chooses_the_rate_term_as_the_cli(c_build, tmp_path, rate):
    """fit(x, y, rate=R) scores and fits the rate term as `hyst fit --rate R`:
    the same model file, bit for bit; rate with a degree given is refused."""
    plant = tmp_path / "plant.hyst"
    plant.write_text(EV_RATE)
    x = signal(3000, 0.0, 40.0, seed=5)
    y = hyst.model_from(hyst.load_model(plant)).process(x)
    rec = tmp_path / "rec.txt"
    rec.write_text("".join(f"{a:.17g} {b:.17g}\n" for a, b in zip(x, y)))
    run_cli(c_build, "fit", "--rate", rate, "--save", tmp_path / "cli.hyst", rec)
    f = hyst.fit(x, y, rate=rate if rate == "auto" else float(rate))
    f.save(tmp_path / "py.hyst")
    assert (tmp_path / "py.hyst").read_text() == (tmp_path / "cli.hyst").read_text()
    if rate == "1":  # always kept: the model runs it
        assert f.rate_tau == 1.0 and f.rate["holdout_rms"] > 0
        assert "rate_tau 1" in (tmp_path / "py.hyst").read_text()
    with pytest.raises(ValueError, match="rate applies to the automatic choice"):
        hyst.fit(x, y, 3, rate=1)
    with pytest.raises(ValueError, match="rate must be"):
        hyst.fit(x, y, rate=0.5)
