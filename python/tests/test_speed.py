# SPDX-License-Identifier: MIT
"""Speed of the block call from Python against the same call in C (printed,
never asserted: the machine is shared). 10^6 samples of the measured drive,
rounds of C and Python runs interleaved, the best run of each kept."""
import time

import numpy as np

import hyst
from conftest import DATA, PAPER_F0, same_bits

N, ROUNDS, REPEAT = 1_000_000, 4, 3


def test_block_call_speed(run_ref, capsys):
    drive = np.loadtxt(DATA, usecols=0)
    x = np.resize(drive * (40.0 / drive.max()), N)  # the record, repeated, on [0, 40]
    m = hyst.Model(PAPER_F0, 0, 40)
    out = np.empty_like(x)
    c_ns = py_out = py_new = float("inf")
    for _ in range(ROUNDS):
        for _ in range(REPEAT):
            m.reset()
            t0 = time.perf_counter()
            m.process(x, out=out)
            py_out = min(py_out, (time.perf_counter() - t0) / N * 1e9)
            m.reset()
            t0 = time.perf_counter()
            y = m.process(x)
            py_new = min(py_new, (time.perf_counter() - t0) / N * 1e9)
        y_c, ns, _ = run_ref("bench", x, np.float64, lo=0.0, hi=40.0, coeffs=PAPER_F0,
                             repeat=REPEAT)
        c_ns = min(c_ns, ns)
    assert same_bits(out, y_c) and same_bits(y, y_c)
    with capsys.disabled():
        print(f"\nspeed, {N} samples, block call, best of {ROUNDS * REPEAT}: C {c_ns:.2f} ns/sample; "
              f"Python {py_out:.2f} ns/sample with out= (Python/C speed {c_ns / py_out:.2f}), "
              f"{py_new:.2f} ns/sample with a new output array ({c_ns / py_new:.2f})")
