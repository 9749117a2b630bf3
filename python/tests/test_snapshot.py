# SPDX-License-Identifier: MIT
"""A snapshot (bytes) restored into a fresh instance continues bit for bit."""
import numpy as np
import pytest

import hyst
from conftest import PAPER_F0, same_bits, signal


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("capacity,deadband", [(2048, 0.0), (3, 0.0), (3, 0.5)])
def test_round_trip_continues_bit_for_bit(dtype, capacity, deadband):
    x = signal(6000, 0.0, 40.0, seed=7).astype(dtype)
    a = hyst.Model(PAPER_F0, 0, 40, dtype=dtype, capacity=capacity, deadband=deadband)
    a.process(x[:3000])
    snap = a.save()
    assert isinstance(snap, bytes) and snap[:4] == b"HYSS"
    b = hyst.Model(PAPER_F0, 0, 40, dtype=dtype, capacity=capacity, deadband=deadband)
    b.restore(snap)
    assert (b.tp_count, b.events, b.status, b.output) == (a.tp_count, a.events, a.status, a.output)
    assert b.error_bound == a.error_bound
    ya, yb = a.process(x[3000:]), b.process(x[3000:])
    assert same_bits(ya, yb)
    assert a.save() == b.save()
    # a fresh instance that did not restore does not continue the same way
    c = hyst.Model(PAPER_F0, 0, 40, dtype=dtype, capacity=capacity, deadband=deadband)
    assert not same_bits(c.process(x[3000:]), ya)


def test_code_and_compensator_round_trip():
    x = np.clip(signal(4000, 0, 4095, seed=8, outside=False), 0, 4095).astype(np.uint16)
    a = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16)
    a.process(x[:2000])
    b = hyst.CodeModel(PAPER_F0, 0, 40, 0, 4095, 16)
    b.restore(a.save())
    assert same_bits(a.process(x[2000:]), b.process(x[2000:]))
    d = signal(4000, 0.6, 5.5, seed=9)
    a = hyst.Compensator(PAPER_F0, 0, 40)
    a.process(d[:2000])
    b = hyst.Compensator(PAPER_F0, 0, 40)
    b.restore(a.save())
    assert same_bits(a.process(d[2000:]), b.process(d[2000:]))


def test_restore_into_a_larger_instance():
    x = signal(3000, 0.0, 40.0, seed=10)
    a = hyst.Model(PAPER_F0, 0, 40, capacity=64)
    a.process(x[:1500])
    b = hyst.Model(PAPER_F0, 0, 40, capacity=4096)
    b.restore(a.save())
    assert same_bits(a.process(x[1500:]), b.process(x[1500:]))


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_creep_lags_travel_with_the_snapshot(dtype):
    """A model or compensator with a creep term continues bit for bit only if
    its lags are restored with its turning points: save() appends them."""
    x = (20 + 19 * np.sin(np.arange(4000) / 60.0)).astype(dtype)
    creep = dict(creep_tau=[40.0, 900.0], creep_weight=[0.05, -0.02])
    a = hyst.Model(PAPER_F0, 0, 40, dtype=dtype, **creep)
    a.process(x[:2000])
    snap = a.save()
    assert snap.count(b"HYSC") == 1
    b = hyst.Model(PAPER_F0, 0, 40, dtype=dtype, **creep)
    b.restore(snap)
    assert same_bits(a.process(x[2000:]), b.process(x[2000:]))
    assert a.save() == b.save()
    d = (2 + 1.5 * np.sin(np.arange(4000) / 45.0)).astype(dtype)
    a = hyst.Compensator(PAPER_F0, 0, 40, dtype=dtype, **creep)
    a.process(d[:2000])
    b = hyst.Compensator(PAPER_F0, 0, 40, dtype=dtype, **creep)
    b.restore(a.save())
    assert same_bits(a.process(d[2000:]), b.process(d[2000:]))


def test_creep_snapshot_mismatches_are_refused_whole():
    x = 20 + 19 * np.sin(np.arange(3000) / 60.0)
    creep = dict(creep_tau=[40.0], creep_weight=[0.05])
    a = hyst.Model(PAPER_F0, 0, 40, **creep)
    a.process(x[:1500])
    with_creep = a.save()
    plain = hyst.Model(PAPER_F0, 0, 40)
    plain.process(x[:1500])
    before = plain.save()
    with pytest.raises(hyst.HystError, match="creep term, the model none"):
        plain.restore(with_creep)
    assert plain.save() == before
    b = hyst.Model(PAPER_F0, 0, 40, **creep)
    b.process(x[:10])
    before = b.save()
    with pytest.raises(hyst.HystError, match="the model has a creep term, the snapshot none"):
        b.restore(before[:before.index(b"HYSC")])
    other = hyst.Model(PAPER_F0, 0, 40, creep_tau=[41.0], creep_weight=[0.05])
    other.process(x[:10])
    kept = other.save()
    with pytest.raises(hyst.HystError) as e:
        other.restore(with_creep)
    assert e.value.status == hyst.Status.ERR_CURVE
    assert other.save() == kept
    damaged = bytearray(with_creep)
    damaged[-8] ^= 1  # a lag's octet: the creep part's CRC
    with pytest.raises(hyst.HystError) as e:
        b.restore(bytes(damaged))
    assert e.value.status == hyst.Status.ERR_CRC
    assert b.save() == before
