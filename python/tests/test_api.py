# SPDX-License-Identifier: MIT
"""The Python surface: version, dtypes, arrays in and out, accessors, plot."""
import re
import sys

import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, REPO, same_bits, signal


def test_version_is_the_headers():
    text = (REPO / "include" / "hyst" / "version.h").read_text()
    parts = [re.search(rf"#define HYST_VERSION_{p} (\d+)", text).group(1)
             for p in ("MAJOR", "MINOR", "PATCH")]
    assert hyst.__version__ == ".".join(parts)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_arrays_in_and_out(dtype):
    m = hyst.Model(PAPER_F0, 0, 40, dtype=dtype)
    x = signal(500, 0, 40, seed=11).astype(dtype)
    y = m.process(x)
    assert isinstance(y, np.ndarray) and y.dtype == dtype and y.shape == x.shape
    # into a caller array (no allocation), from a list, from a strided view
    out = np.empty_like(x)
    m.reset()
    assert m.process(x, out=out) is out and same_bits(out, y)
    m.reset()
    assert same_bits(m.process(x.tolist()), y)
    m.reset()
    assert same_bits(m.process(np.repeat(x, 2)[::2]), y)
    with pytest.raises(TypeError):
        m.process(x, out=np.empty(x.size, dtype=np.int64))
    with pytest.raises(ValueError):
        m.process(x, out=np.empty(x.size + 1, dtype=dtype))
    assert m.process(np.empty(0, dtype=dtype)).size == 0


def test_accessors_follow_the_library():
    m = hyst.Model(PAPER_F0, 0, 40, capacity=100)
    assert (m.capacity, m.tp_count, m.rising, m.input, m.lo, m.hi) == (100, 0, True, 0.0, 0, 40)
    assert m.output == pytest.approx(PAPER_F0[-1])
    assert m.coeffs == PAPER_F0 and not m.inverse
    m.process(np.array([0.0, 30.0, 10.0, 20.0]))
    assert (m.tp_count, m.ltp_count, m.rtp_count, m.rising) == (2, 1, 1, True)
    assert m.input == 20.0 and m.output == m.step(20.0)
    m.reset()
    assert m.tp_count == 0 and m.events == 0
    m.deadband = 0.5
    assert m.deadband == 0.5
    assert hyst.Compensator(PAPER_F0, 0, 40).inverse


def test_code_model_and_pi_accessors():
    c = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16)
    assert (c.code_lo, c.code_hi, c.capacity, c.input) == (0, 4095, 16, 0)
    assert c.step(2048) == c.output and c.input == 2048
    assert c.process([0, 4095]).dtype == np.float32
    p = hyst.PI([0.0, 0.5], [1.0, 0.5])
    assert (p.size, p.thresholds, p.weights, p.output) == (2, [0.0, 0.5], [1.0, 0.5], 0.0)
    assert p.step(1.0) == p.output == 1.0 + 0.5 * 0.5
    p.reset()
    assert p.output == 0.0


def test_plot(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    x = signal(400, 0, 40, seed=12, outside=False)
    meas = hyst.Model(PAPER_F0, 0, 40).process(x) + 0.01
    fig = hyst.plot(x, hyst.Model(PAPER_F0, 0, 40), meas, path=tmp_path / "loop.png")
    assert len(fig.axes) == 3
    assert (tmp_path / "loop.png").stat().st_size > 1000
    assert len(hyst.plot(x, meas).axes) == 1


def test_plot_without_matplotlib(monkeypatch):
    for name in [n for n in sys.modules if n.startswith("matplotlib")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib fails
    with pytest.raises(ImportError, match="pip install matplotlib"):
        hyst.plot([0.0, 1.0], [0.0, 1.0])
