# SPDX-License-Identifier: MIT
"""Right or refused at the package's edges: codes that step() refuses are
refused by process() too (not wrapped through uint16), arrays of another
shape are refused in words, an out= overlapping the input is refused, a
Fit's model comes whole (its creep term) and plot() applies its delay."""
import os

import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, signal

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "piezo_major_loop.dat")


@pytest.mark.parametrize("codes", [[-1], [np.nan], [0.5], [1e9], [np.inf], [100, -3, 7]])
def test_code_process_refuses_what_step_refuses(codes):
    c = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16)
    before = c.output
    with pytest.raises(ValueError, match="is not a whole number in 0..65535"):
        c.process(np.array(codes, dtype=np.float64))
    assert c.output == before and c.tp_count == 0  # nothing ran
    with pytest.raises(TypeError):
        c.step(-1)


def test_code_process_takes_whole_codes_of_any_dtype():
    c = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16)
    codes = [0, 4095, 2000, 3000.0, 10]
    y = c.process(np.array(codes, dtype=np.float64))
    c.reset()
    assert np.array_equal(y, c.process(np.array(codes, dtype=np.uint16)))
    c.reset()
    assert np.array_equal(y, np.array([c.step(int(k)) for k in codes], dtype=np.float32))


@pytest.mark.parametrize("make", [lambda: hyst.Model(PAPER_F0, 0, 40),
                                  lambda: hyst.Model(PAPER_F0, 0, 40, dtype=np.float32),
                                  lambda: hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16),
                                  lambda: hyst.Creep([100.0], [0.1], 0.0)])
@pytest.mark.parametrize("shape", [(2, 3), (), (1, 1, 4)])
def test_process_refuses_other_shapes_in_words(make, shape):
    with pytest.raises(ValueError, match=f"process takes a 1-d array of samples, not a "
                                         f"{len(shape)}-d one"):
        make().process(np.zeros(shape))


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_process_refuses_an_out_overlapping_its_input(dtype):
    x = signal(400, 0, 40, seed=5).astype(dtype)
    want = hyst.Model(PAPER_F0, 0, 40, dtype=dtype).process(x.copy())
    for shift in (1, -1, 17):
        buf = np.concatenate([x, np.zeros(abs(shift), dtype=dtype)])
        m = hyst.Model(PAPER_F0, 0, 40, dtype=dtype)
        inp, out = (buf[:len(x)], buf[shift:shift + len(x)]) if shift > 0 else \
            (buf[-shift:-shift + len(x)], buf[:len(x)])
        saved = buf.copy()
        with pytest.raises(ValueError, match="out overlaps the input"):
            m.process(inp, out=out)
        assert np.array_equal(buf, saved) and m.tp_count == 0
    # in place (out is the input itself) is the library's documented case
    m = hyst.Model(PAPER_F0, 0, 40, dtype=dtype)
    y = x.copy()
    assert m.process(y, out=y) is y and np.array_equal(y, want)
    # a code model's float outputs over its uint16 codes: any overlap
    codes = np.zeros(8, dtype=np.uint16)
    with pytest.raises(ValueError, match="out overlaps the input"):
        hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16).process(codes[:4],
                                                             out=codes.view(np.float32)[:4])


def _record():
    d = np.loadtxt(DATA)
    return d[:, 0], d[:, 4]


def test_fit_makes_its_model_whole():
    """The README's fit: the model made from the Fit keeps the creep term
    the fit chose; a model rebuilt from its coefficients loses it and misses
    the record by more."""
    x, y = _record()
    f = hyst.fit(x, y, degree=3, skip=350, delay=1)
    assert f.creep_tau  # creep="auto" chose one here
    whole = f.make_model().process(x[350:])
    assert np.array_equal(whole, f.predict(x[350:]))
    bare = hyst.Model(f.coeffs, f.lo, f.hi).process(x[350:])
    rms = lambda p: float(np.sqrt(np.mean((p[:-1] - y[351:]) ** 2)))  # noqa: E731
    assert rms(whole) < 0.9 * rms(bare)
    drive = f.make_compensator().process(whole)
    assert np.max(np.abs(drive - np.clip(x[350:], f.lo, f.hi))) < 1e-6
    f32 = f.make_model(dtype=np.float32)
    assert f32.dtype == "float32" and f32.creep_tau == f.creep_tau


def test_plot_applies_the_fits_delay(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    x, y = _record()
    x, y = x[350:], y[350:]
    f = hyst.fit(x, y, degree=3, delay=4)
    fig = hyst.plot(x, f, y, path=tmp_path / "fit.png")
    pred = f.predict(x)
    shifted = np.concatenate([np.full(4, hyst.model_from(f.description()).output),
                              pred[:-4]])
    rms = float(np.sqrt(np.mean((shifted - y) ** 2)))
    title = fig.axes[2].get_title()
    assert title == f"error (RMS {rms:.4g})", title
    assert rms < 0.5 * float(np.sqrt(np.mean((pred - y) ** 2)))
