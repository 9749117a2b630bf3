#!/usr/bin/env python3
"""Writes the seed corpus fuzz/corpus/ (small, committed). Layout: fuzz_hyst.c."""
import os, struct, math

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "corpus")
os.makedirs(out, exist_ok=True)

def sbyte(v):
    return struct.pack("b", max(-128, min(127, int(round(v)))))

def structured(flags, cap, degree, lo, span, coeffs, slope):
    b = bytes([flags, cap, degree]) + sbyte(lo * 32) + bytes([int(span * 16) % 64])
    c = list(coeffs) + [0.0] * (10 - len(coeffs))
    b += b"".join(sbyte(v * 64) for v in c)
    if 1 <= degree <= 9:
        b += bytes([slope])
    return b

def raw(flags, cap, degree, lo, hi, coeffs):
    c = list(coeffs) + [0.0] * (10 - len(coeffs))
    return bytes([flags | 1, cap, degree]) + struct.pack("<dd", lo, hi) + struct.pack("<10d", *c)

def s16(u):  # sample as a position in [-0.1, 1.1] of the span
    v = int(round((u + 0.1) / 1.2 * 65535))
    return bytes([5]) + struct.pack("<H", max(0, min(65535, v)))

def shrinking(levels=7, steps=6):
    b, at = b"", 0.0
    for k in range(levels):
        for target in (1.0 - 0.0625 * k, 0.0625 * (k + 1)):
            for i in range(1, steps + 1):
                b += s16(at + (target - at) * i / steps)
            at = target
    return b

cubic = (3, 0.0, 3.9, [-1 / 64, 8 / 64, 32 / 64, 36 / 64], 2)
seeds = {
    "shrinking_loops": structured(0, 40, *cubic) + shrinking(),
    "snapshot_reset_block": structured(0, 40, *cubic) + shrinking(3) + b"\xf1" + shrinking(2)
        + b"\xf0" + bytes([0xF4, 8]) + b"".join(s16(v / 8) for v in (0, 7, 2, 6, 3, 5, 4, 8)) + b"\xf5",
    "nonfinite_ends_codes": structured(0, 8, *cubic) + bytes([0, 1, 9]) + bytes([2]) + struct.pack("<d", 1e300)
        + bytes([3, 11, 4, 200, 4, 200, 4, 10, 4, 150, 0x0C, 4, 20]),
    "tiny_capacity_full": structured(0, 2, *cubic) + shrinking(5, 3),
    "linear_via_curve": structured(2, 6, 1, -1.0, 2.0, [1.0, 0.5], 0) + shrinking(4, 2),
    "degree9": structured(0, 47, 9, 0.0, 1.0, [0.1] * 10, 40) + shrinking(7, 3),
    "not_increasing": structured(0, 10, 2, -1.0, 2.0, [1.0, 0.0, 0.0], 0) + s16(0.5),
    "bad_degree0": structured(0, 10, 0, 0.0, 1.0, [1.0], 0),
    "bad_degree10": structured(0, 10, 10, 0.0, 1.0, [1.0], 0),
    "bad_capacity": structured(0, 1, *cubic) + s16(0.5),
    "empty_domain": structured(0, 10, 1, 0.0, 0.0, [1.0, 0.0], 0),
    "probes": structured(4 | 8, 12, *cubic) + shrinking(2),
    "raw_paper_eq20": raw(0, 40, 3, 0.0, 40.0, [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]) + shrinking(3),
    "raw_nan_lo": raw(0, 40, 3, math.nan, 40.0, [1.0, 0, 0, 0]),
    "raw_inf_coeff": raw(0, 40, 2, 0.0, 1.0, [math.inf, 1.0, 0.0]),
    "raw_overflow": raw(0, 40, 9, 0.0, 1e40, [1.0] + [0.0] * 9),
    "forged_restore": structured(0, 16, *cubic) + shrinking(2) + bytes([0xF2, 60, 0]) + b"HYSS" + bytes(56)
        + bytes([0xF3, 100, 0]) + bytes(range(100)) + bytes([0xF6, 77, 1, 0xF6, 5, 0]),
}
for name, data in seeds.items():
    with open(os.path.join(out, name), "wb") as f:
        f.write(data)
print(f"{len(seeds)} seeds in {out}")
