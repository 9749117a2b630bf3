# SPDX-License-Identifier: MIT
"""fit(degree=None, delay=None) searches the delays as `hyst fit` does, by
the tool's own code (fit_search()): scaled to the drive's period beyond
MAX_DELAY samples, then a fraction of a sample; the model fitted on the
drive interpolated by it, saved with that delay."""
import re
import subprocess

import numpy as np

import hyst

PLANT = {"kind": "everett", "lo": 0.0, "hi": 40.0, "y_lo": 0.0, "degree": 2,
         "terms": [3.0, -0.5, 1.0]}
DELAY = 12.5  # samples: beyond MAX_DELAY, and half a sample


def record():
    """Triangles of 40, 30, 40, 20, ... 0.05 a sample (a period of about
    1600 samples: delays up to 25 searched), the plant's output DELAY
    samples later (interpolated) plus a little noise."""
    x = []
    for top in (40.0, 30.0, 40.0, 20.0, 40.0, 35.0, 40.0, 25.0, 40.0):
        x += list(np.arange(0.0, top, 0.05)) + list(np.arange(top, 0.0, -0.05))
    x = np.array(x + [0.0])
    y = hyst.model_from(PLANT).process(x)
    whole, frac = int(DELAY), DELAY - int(DELAY)
    late = np.concatenate([np.full(whole + 1, y[0]), y])[: len(y) + 1]
    y = (1 - frac) * late[1:] + frac * late[:-1]  # y[k - DELAY]
    return x, y + 1e-4 * np.random.default_rng(5).standard_normal(len(y))


def test_fit_searches_the_delays_as_the_tool(c_build, tmp_path):
    x, y = record()
    rec = tmp_path / "rec.txt"
    rec.write_text("".join(f"{a:.17g} {b:.17g}\n" for a, b in zip(x, y)))
    r = subprocess.run([str(c_build["cli"]), "fit", "--save", str(tmp_path / "cli.hyst"),
                        str(rec)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
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
