#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the seed corpora (small, committed): fuzz/corpus/ for fuzz_hyst.c,
fuzz/corpus_models/ for fuzz_models.c, fuzz/corpus_code/ for fuzz_code.c, fuzz/corpus_q31/ for fuzz_q31.c, fuzz/corpus_grid/ for fuzz_grid.c,
fuzz/corpus_spline/ for fuzz_spline.c
(layouts in their header comments) and fuzz/corpus_model_file/ for fuzz_model_file.c (model files: tests/cli/models/*.hyst, tests/model_files/*.hyst, a valid one
in several spellings, and malformed variants of it).
regress_* files are fuzzer finds, kept by hand, never written here."""
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
    "requests_reset": structured(0, 40, *cubic) + shrinking(3) + bytes([0xF5, 3, 128]) + shrinking(2)
        + bytes([0xF5, 0, 0, 0xF7]) + shrinking(1),
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
    # flags bit4: the curve moved far from 0 (2^(8 + byte % 36)) and expanded about 0 again
    "offset_domain_cubic": structured(16, 40, *cubic) + bytes([12]) + shrinking(),
    "offset_domain_linear": structured(16, 8, 1, -1.0, 2.0, [1.0, 0.5], 0) + bytes([35]) + shrinking(2, 2),
    "offset_domain_degree9": structured(16, 47, 9, 0.0, 1.0, [0.1] * 10, 40) + bytes([4]) + shrinking(3, 3),
    "forged_restore": structured(0, 16, *cubic) + shrinking(2) + bytes([0xF2, 60, 0]) + b"HYSS" + bytes(56)
        + bytes([0xF3, 100, 0]) + bytes(range(100)) + bytes([0xF6, 77, 1, 0xF6, 5, 0]),
}

# ---- fuzz_models.c: [module % 4][flags] then the module's bytes ----
PI, PWL, INV, IDENT = 0, 1, 2, 3
RAW, CORRUPT, NULLS, KNOWN, PIFIT = 2, 4, 8, 16, 32

def pi(flags, steps, weights, hi, ops=b"", r0=None):
    """steps: r_i - r_(i-1) in 1/16 (i >= 1); weights: w_1 in (1..64)/32 as a
    byte, then w_i as signed bytes / 64; hi: r_N + signed byte / 16."""
    b = bytes([PI, flags, len(weights)]) + bytes([weights[0]])
    for st, w in zip(steps, weights[1:]):
        b += bytes([st]) + sbyte(w)
    if r0 is not None:
        b += sbyte(r0)
    return b + sbyte(hi) + ops

def pos(u, kind=5):  # sample as a position in [-0.1, 1.1] of the span
    v = int(round((u + 0.1) / 1.2 * 65535))
    return bytes([kind]) + struct.pack("<H", max(0, min(65535, v)))

def tri(levels=4, steps=4, lo=0.0, hi=1.0):
    b, at = b"", lo
    for k in range(levels):
        for target in (hi - (hi - lo) * 0.1 * k, lo + (hi - lo) * 0.1 * (k + 1)):
            for i in range(1, steps + 1):
                b += pos(at + (target - at) * i / steps)
            at = target
    return b

def block(us):
    return bytes([0xF1, len(us)]) + b"".join(pos(u) for u in us)

def pwl(flags, dys, dxs, cap, probes=b"", ops=b""):
    """dys: value steps in 1/16 (first: y_0 = dy/16 - 1); dxs: x_0 as a signed
    byte / 16, then steps in 1/16."""
    b = bytes([PWL, flags, len(dys)])
    for i, (dy, dx) in enumerate(zip(dys, dxs)):
        b += bytes([dy]) + (sbyte(dx) if i == 0 else bytes([dx]))
    return b + bytes([cap]) + probes + ops

def poly(module, flags, degree, lo, span, coeffs, slope, tail=b""):
    c = list(coeffs) + [0.0] * (10 - len(coeffs))
    b = bytes([module, flags, degree]) + sbyte(lo * 32) + bytes([int(span * 16) % 64])
    b += b"".join(sbyte(v * 64) for v in c)
    if 1 <= degree <= 9:
        b += bytes([slope])
    return b + tail

def ident(flags, degree, method, lo, span, ops, skip=0, delay=0):
    return bytes([IDENT, flags, degree]) + sbyte(method) + sbyte(lo * 16) + bytes([int(span * 16)]) + ops + bytes([skip, delay])

def add(u, yb=0x10, check=False):  # one sample at position u of the domain
    return bytes([0x85 if check else 0x05, yb]) + pos(u)[1:]

SOLVE, RESID, POLY, REINIT = 0xC0, 0xC1, 0xC2, 0xC3
ramp = [i / 6 for i in range(7)]
loops = [0, 1, 0.25, 0.75, 0.4, 0.6, 0.1, 0.9, 0] + [i / 8 for i in range(9)]  # nested minor loops
wave = ramp + ramp[::-1][1:] + ramp[1:]
table1 = [3, 15, 12, 13, 13, 13, 13, 13, 13, 13]  # paper Table 1 weights, about
cubic_c = [-1 / 64, 8 / 64, 32 / 64, 36 / 64]
models = {
    "pi_table1_walk": pi(0, [2] * 9, [3] + [w / 64 for w in [15, 12, 13, 13, 13, 13, 13, 13, 13]], 1.0,
                         tri(4, 4) + b"\xf0" + tri(2, 3) + block([0.2, 0.9, 0.4]) + b"\xf2" + pos(-0.05)),
    "pi_inverse_chain": pi(0, [1, 3, 5], [40, 0.3, -0.2, 0.5], 0.5, tri(3, 5) + pos(0.0, 3) + bytes([4, 200])),
    "pi_block_nan": pi(0, [4], [20, 0.5], 1.0, bytes([0xF1, 0x85, 0, 0, 4, 9, 1, 5, 0, 128, 2]) + bytes(8) + b"\xf3"),
    "pi_bad_r0": pi(CORRUPT, [4, 4], [20, 0.5, 0.5], 1.0, pos(0.5), r0=0.25),
    "pi_equal_thresholds": pi(0, [4, 0], [20, 0.5, 0.5], 1.0, pos(0.5)),
    "pi_bad_weights": pi(NULLS, [4, 4], [1, -0.5, 0.2], 1.0, pos(0.5)),
    "pi_n0": bytes([PI, NULLS, 0]),
    "pi_hi_below": pi(0, [4], [20, 0.5], -0.5, tri(1, 3)),
    "pi_raw": bytes([PI, RAW, 2]) + struct.pack("<4d", 0.0, 0.5, 0.25, 1e-3) + struct.pack("<d", 2.0) + tri(1, 3),
    "pwl_round_trip": pwl(0, [16, 4, 20, 1, 9, 30, 2, 7], [-16, 3, 1, 8, 2, 15, 4, 6], 16, bytes(range(0, 255, 37)) * 2,
                          tri(4, 4) + b"\xf0" + pos(1.05) + pos(-0.05) + bytes([0])),
    "pwl_flat_piece": pwl(0, [16, 4, 0, 9], [0, 3, 1, 8], 8, bytes([100, 50, 200])),
    "pwl_decreasing": pwl(CORRUPT, [16, 1, 9], [0, 3, 1], 8),
    "pwl_equal_breakpoints": pwl(NULLS, [16, 3, 9], [0, 3, 0], 8),
    "pwl_cap1": pwl(NULLS, [16, 3, 9], [0, 3, 5], 1, bytes([10, 20, 30, 40])),
    "pwl_raw": bytes([PWL, RAW, 3]) + struct.pack("<6d", -1.0, 0.0, 0.5, math.nan, 2.0, 1.0),
    "inv_cubic": poly(INV, 0, 3, 0.0, 3.9, cubic_c, 2, bytes([40]) + tri(4, 4) + b"\xf0" + pos(1.08) + b"\xf2"),
    "inv_flat_x3": poly(INV, 0, 3, -1.0, 2.0, [1.0, 0.0, 0.0, 0.0], 0, bytes([20]) + tri(2, 6)),
    "inv_not_increasing": poly(INV, NULLS, 2, -1.0, 2.0, [1.0, 0.0, 0.0], 0, bytes([20])),
    "inv_cap1": poly(INV, NULLS, 3, 0.0, 3.9, cubic_c, 2, bytes([1])),
    # the tabulated compensator (flag 16): cap, then intervals - 1
    "inv_table_cubic": poly(INV, KNOWN, 3, 0.0, 3.9, cubic_c, 2, bytes([40, 31]) + tri(4, 4) + b"\xf0" + pos(1.08)),
    "inv_table_flat_x3": poly(INV, KNOWN, 3, -1.0, 2.0, [1.0, 0.0, 0.0, 0.0], 0, bytes([20, 7]) + tri(2, 6)),
    "inv_table_one_interval": poly(INV, KNOWN | NULLS, 3, 0.0, 3.9, cubic_c, 2, bytes([4, 0]) + tri(3, 3)),
    "inv_raw_eq20": bytes([INV, RAW, 3]) + struct.pack("<dd", 0.0, 40.0)
        + struct.pack("<10d", -6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1, *[0.0] * 6) + bytes([40]),
    "ident_stream": ident(NULLS, 3, 0, -1.0, 3.0, b"".join(add(u) for u in wave) + bytes([RESID, SOLVE])
                          + b"".join(add(u, check=True) for u in wave) + bytes([RESID, POLY, SOLVE, REINIT])
                          + add(0.5) + add(1.2) + bytes([0x00, 5, 0x01, 2]) + struct.pack("<d", 1e300) + bytes([SOLVE]), 2, 1),
    "ident_few_samples": ident(CORRUPT, 5, 2, 0.0, 1.0, add(0.1) + add(0.2) + add(0.2) + bytes([SOLVE, RESID])),
    "ident_bad_config": ident(0, 10, 0, 0.0, 1.0, add(0.5)),
    "ident_bad_method": ident(0, 2, 3, 0.0, 1.0, add(0.5)),
    "ident_known_joint": poly(IDENT, KNOWN, 3, 0.0, 3.9, cubic_c, 2, bytes([5])),
    "ident_known_reflect": poly(IDENT, KNOWN | CORRUPT | NULLS, 5, -1.0, 2.5, [0.1, 0.0, -0.3, 0.2, 0.5, 0.1], 3, bytes([0])),
    "ident_known_deg9": poly(IDENT, KNOWN, 9, 0.5, 1.0, [0.1] * 10, 40, bytes([31])),
    # PI weights by NNLS (flag PIFIT): n, threshold mode (bit0 given), span, samples, SOLVE
    "pifit_uniform_loops": bytes([IDENT, PIFIT, 4, 0, 31]) + b"".join(add(u) for u in loops) + bytes([SOLVE, 1, 2]),
    "pifit_given_nulls": bytes([IDENT, PIFIT | NULLS, 3, 1, 31, 0, 8, 8]) + b"".join(add(u) for u in loops)
        + bytes([SOLVE, REINIT]) + add(0.5) + bytes([0x00, 5]) + bytes([SOLVE, 0, 0]),
    "pifit_bad_r1": bytes([IDENT, PIFIT, 2, 1, 31, 0x84, 8]),
    "pifit_short_work": bytes([IDENT, PIFIT | CORRUPT, 2, 0, 31]) + add(0.5),
    "pifit_n0": bytes([IDENT, PIFIT, 0, 0, 31]),
    "pifit_n65": bytes([IDENT, PIFIT, 65, 0, 31]),
    "pifit_few_samples": bytes([IDENT, PIFIT, 5, 0, 31]) + add(0.1) + add(0.9) + bytes([SOLVE]),
}

# fuzz_models.c's creep module (first byte 252..255): [flags][terms] then per term tau byte
# (1 + b^2 / 4 samples; 255: 0.5) and weight ((signed char) / 16), the rest drive ((signed
# char) / 8), then ops: 0xF0 reset, 0xF1 NaN, 0xF2 fit, 0xF3 next residual missing, 0xF4
# snapshot (octet to damage, mask), else a sample (op, (signed char) / 8)
CREEP = 252

def creep(terms, taus, weights, rest, drives, ops=b"", flags=0):
    b = bytes([CREEP, flags, terms]) + b"".join(bytes([t]) + sbyte(w * 16) for t, w in zip(taus, weights))
    return b + sbyte(rest * 8) + b"".join(bytes([1]) + sbyte(d * 8) for d in drives) + ops

steps = [((i * 37) % 33) / 2.0 - 8.0 for i in range(60)]  # a deterministic jumpy drive
models.update({
    "creep_one_lag": creep(1, [40], [0.5], 1.0, steps, bytes([0xF2, 0xF1, 0xF0, 1, 24, 0xF2])),
    "creep_two_lags_missing": creep(2, [20, 90], [0.75, -0.25], 0.0, steps[:30],
                                    bytes([0xF3, 1, 40, 0xF2]) + b"".join(bytes([1]) + sbyte(d * 8) for d in steps[30:]) + b"\xf2"),
    "creep_four_fast": creep(4, [0, 1, 2, 3], [0.5, 0.5, -0.5, 1.0], -2.0, steps[:40], b"\xf2\xf1\xf2"),
    "creep_tau_half": creep(1, [255], [0.5], 0.0, steps[:4]),
    "creep_terms5": creep(5, [9] * 5, [0.1] * 5, 0.0, steps[:4]),
    "creep_snapshot": creep(3, [5, 60, 200], [0.5, -0.25, 1.0], 2.0, steps[:25],
                            bytes([0xF4, 0, 1, 0xF1, 0xF4, 30, 0x80]) + b"".join(bytes([1]) + sbyte(d * 8) for d in steps[25:35])
                            + bytes([0xF4, 255, 0x41])),
    "creep_raw": bytes([CREEP, 2, 1]) + struct.pack("<3d", 5000.0, 0.3, 0.0)
        + b"".join(bytes([1]) + struct.pack("<d", d / 4) for d in steps[:20]) + b"\xf2",
})


# fuzz_models.c's rate module (first byte 248..251): [flags] tau byte (1 + b^2 / 4 samples;
# 0: 0.5, 255: 1e308, both refused), weight ((signed char) / 16), rest drive ((signed char) /
# 8), then ops: 0xF0 reset, 0xF1 + which refused reset, 0xF2 NaN, 0xF3 + how far beyond the
# limit, 0xF4 snapshot (octet to damage, mask), 0xF5 clear events, else a sample (op, (signed
# char) / 8)
RATE = 248

def rate(tb, w, rest, drives, ops=b"", flags=0):
    return bytes([RATE, flags, tb]) + sbyte(w * 16) + sbyte(rest * 8) + \
        b"".join(bytes([1]) + sbyte(d * 8) for d in drives) + ops

models.update({
    "rate_tau1_last_change": rate(1, -1.75, 0.5, steps[:30], bytes([0xF2, 0xF5, 0xF0, 1, 40])),
    "rate_long_tau_snapshot": rate(40, 0.5, 2.0, steps[:20], bytes([0xF4, 5, 0x80]) + b"".join(bytes([1]) + sbyte(d * 8) for d in steps[20:40])
                                   + bytes([0xF4, 40, 1, 0xF0]) + b"".join(bytes([1]) + sbyte(d * 8) for d in steps[40:50])),
    "rate_bad_drives": rate(6, 7.9, -1.0, steps[:10], bytes([0xF3, 0, 0xF3, 3, 0xF2, 0xF1, 0, 0xF1, 1, 0xF1, 2, 0xF1, 3, 0xF1, 4, 0xF5])
                            + b"".join(bytes([1]) + sbyte(d * 8) for d in steps[10:20])),
    "rate_tau_below_1": rate(0, 0.5, 0.0, steps[:4]),
    "rate_tau_huge": rate(255, 0.5, 0.0, steps[:4]),
    "rate_raw_nan_weight": bytes([RATE + 1, 2]) + struct.pack("<3d", 5.0, math.nan, 0.0),
    "rate_raw_float_limits": bytes([RATE + 2, 2]) + struct.pack("<3d", 3.0, 1e10, 1e28)
        + b"".join(bytes([1]) + struct.pack("<d", d * 1e27) for d in steps[:20]) + bytes([0xF4, 30, 4]),
    "rate_raw_beyond_float": bytes([RATE + 3, 2]) + struct.pack("<3d", 2.5, 1e39, 0.0)
        + b"".join(bytes([1]) + struct.pack("<d", d * 1e300) for d in steps[:12]) + bytes([0xF3, 2, 0xF4, 0, 0x10]),
})

# ---- fuzz_code.c: [flags][cap % 20] config, code range, [deadband], ops ----
RAWCFG, VIACURVE, CNULLS, CKIND, RAWRANGE, DEADBAND, BADDB, DEEP = 1, 2, 4, 8, 16, 32, 64, 128
convex = (3, 0.0, 3.9, [1 / 64, 8 / 64, 32 / 64, 0.0], 2)    # f0'' > 0
concave = (2, 0.0, 3.9, [-4 / 64, 1.0, 0.0], 0)              # f0'' < 0
wavy = (3, 0.0, 3.9, [-1 / 64, 8 / 64, 32 / 64, 36 / 64], 2)  # f0'' changes sign

def code_cfg(flags, cap, curve, clo=0, span=65535, shift=0, db=None):
    b = structured(flags & ~RAWCFG, cap, *curve)
    b = bytes([flags, cap]) + b[2:]
    b += bytes([shift]) + struct.pack("<HH", span << shift if span << shift < 65536 else span, clo)
    if flags & DEADBAND:
        b += struct.pack("<H", db or 0)
    return b

def code_raw_range(flags, cap, curve, lo, hi):
    b = structured(0, cap, *curve)
    return bytes([flags | RAWRANGE, cap]) + b[2:] + struct.pack("<I", lo)[:3] + struct.pack("<I", hi)[:3]

def c16(v):  # one in-range code, kind 0 (u16 % (span + 1))
    return bytes([0]) + struct.pack("<H", v)

def shrink_codes(levels=6, steps=4, top=65535):
    b, at = b"", 0
    for k in range(levels):
        for target in (int(top * (1 - 0.07 * k)), int(top * 0.07 * (k + 1))):
            for i in range(1, steps + 1):
                b += c16(at + (target - at) * i // steps)
            at = target
    return b

noise = bytes([0]) + struct.pack("<H", 30000) + b"".join(bytes([10, v & 0xFF]) for v in (5, -3, 4, -6, 2, 7, -2, -5) * 3)
code_seeds = {
    "exact_convex": code_cfg(0, 19, convex) + shrink_codes(),
    "merge_cap2": code_cfg(0, 2, convex) + shrink_codes(6, 3),
    "merge_cap4_concave": code_cfg(0, 4, concave) + shrink_codes(7, 3),
    "deadband_noise": code_cfg(DEADBAND, 6, convex, db=6) + noise + shrink_codes(2, 2),
    "deadband_zero": code_cfg(DEADBAND, 8, convex, db=0) + noise,
    "block_clamp": code_cfg(VIACURVE, 5, convex, clo=1000, span=4000)
        + bytes([0xF1, 6, 3, 11, 4, 7, 0, 0x10, 0x00, 0x14, 9, 12]) + bytes([0xF5, 0xF0]) + shrink_codes(2, 2, 4000),
    "one_bit_range": code_cfg(0, 3, convex, clo=7, span=1) + bytes([3, 11, 3, 11, 4, 5]),
    "probes": code_cfg(CNULLS | CKIND | BADDB, 8, convex) + shrink_codes(2, 2),
    "wavy_cap3": code_cfg(0, 3, wavy) + shrink_codes(5, 2),
    "deep_nesting": code_cfg(DEEP, 255, convex) + bytes([0xF2, 255]) + c16(60000) + c16(5000)
        + bytes([0xF0, 0xF2, 160]) + c16(50000) + bytes([0xF2, 100]) + c16(20000) + shrink_codes(2, 2),
    "deep_nesting_deadband": code_cfg(DEEP | DEADBAND, 250, concave, db=9) + bytes([0xF2, 200]) + noise,
    "nesting_cap3": code_cfg(0, 3, convex) + bytes([0xF2, 40, 3, 11]),
    "bad_cap1": code_cfg(0, 1, convex),
    "bad_range_empty": code_raw_range(0, 8, convex, 500, 500),
    "bad_range_wide": code_raw_range(0, 8, convex, 0, 70000),
    "bad_curve_and_range": code_raw_range(0, 8, (2, -1.0, 2.0, [1.0, 0.0, 0.0], 0), 9, 3),
    "bad_degree0": code_cfg(VIACURVE, 8, (0, 0.0, 1.0, [1.0], 0)),
}
# Model files (hyst-model-text 1): the CLI tests' malformed files as they are,
# a valid model in several spellings, and one defect each.
models_dir = os.path.join(here, "..", "tests", "cli", "models")
model_files = {}
for name in sorted(os.listdir(models_dir)):
    if name.endswith(".hyst"):
        with open(os.path.join(models_dir, name), "rb") as f:
            model_files["cli_" + name[:-5]] = f.read()
MAGIC = b"hyst-model-text 1\n"
valid = MAGIC + b"# a comment\nkind poly\nlo 0\nhi 40\ndelay 3\ncoeffs -6.1876e-06 0.0011949 0.086444 0.58517\n"
model_files.update({
    "valid": valid,
    "valid_written": MAGIC + b"# hyst model: f0 on [lo, hi]\nkind poly\nlo 0\nhi 3.6000000000000001\n"
        b"delay 4\ncoeffs -0.035382239014971698 0.15731673924940101 0.65908169990876799 9.7436721940450303 -118.40773443033701\n",
    "valid_crlf_tabs": valid.replace(b"\n", b"\r\n").replace(b" ", b"\t"),
    "valid_no_delay_no_newline": MAGIC + b"kind poly\nhi 1\nlo -0\ncoeffs 1 0",
    "valid_ten_coeffs": MAGIC + b"kind poly\nlo -1e-300\nhi 1e300\ncoeffs" + b" 4.9e-324" * 9 + b" -0\n",
    "valid_blank_lines": MAGIC + b"\n   \n\tkind   poly  \n\nlo 1e-5\nhi 16\ncoeffs 1 2 3\n#\n",
    "bad_hex": MAGIC + b"kind poly\nlo 1e-5\nhi 0x1p4\ncoeffs 1 2 3\n",
    "bad_empty": b"",
    "bad_magic_only": MAGIC,
    "bad_magic_crlf_space": b"hyst-model-text 1 \r\n",
    "bad_nul": valid.replace(b"hi 40", b"hi 4\x000"),
    "bad_nul_magic": b"hyst\x00model-text 1\n",
    "bad_long_line": MAGIC + b"kind poly\nlo 0\nhi 1\ncoeffs 1 " + b"0" * 1100 + b"\n",
    "bad_eleven_coeffs": MAGIC + b"kind poly\nlo 0\nhi 1\ncoeffs" + b" 1" * 11 + b"\n",
    "bad_one_coeff": MAGIC + b"kind poly\nlo 0\nhi 1\ncoeffs 1\n",
    "bad_lo_two_values": valid.replace(b"lo 0", b"lo 0 1"),
    "bad_hi_no_value": valid.replace(b"hi 40", b"hi"),
    "bad_overflow": valid.replace(b"hi 40", b"hi 1e999"),
    "bad_nan": valid.replace(b"lo 0", b"lo nan"),
    "bad_delay_negative": valid.replace(b"delay 3", b"delay -1"),
    "bad_delay_huge": valid.replace(b"delay 3", b"delay 1e10"),
    "bad_kind_missing": valid.replace(b"kind poly\n", b""),
    "bad_kind_extra": valid.replace(b"kind poly", b"kind poly pwl"),
    "bad_binary": bytes(range(256)),
    # a fraction of a sample of delay, and the range the model was identified on
    "valid_delay_fraction": valid.replace(b"delay 3", b"delay 3.75"),
    "valid_identified": valid + b"identified 2.5 38\n",
    "bad_identified_outside": valid + b"identified -1 38\n",
    "bad_identified_reversed": valid + b"identified 38 2.5\n",
    "bad_identified_one_value": valid + b"identified 2.5\n",
})
# the crafted files every front end's reader is held to (tests/model_files:
# line ends, blanks, number spellings, limits, an empty domain)
crafted_dir = os.path.join(here, "..", "tests", "model_files")
for name in sorted(os.listdir(crafted_dir)):
    if name.endswith(".hyst"):
        with open(os.path.join(crafted_dir, name), "rb") as f:
            model_files["crafted_" + name[:-5]] = f.read()
# the asymmetric kind: as fit --save writes it, other spellings, one defect each
everett_valid = MAGIC + b"# an everett model\nkind everett\nlo 0\nhi 40\ny_lo 0.5\ndelay 2\ndegree 2\nterms 3 1 2\n"
model_files.update({
    "valid_everett": everett_valid,
    "valid_everett_written": MAGIC + b"# hyst model: asymmetric\nkind everett\nlo 0\nhi 3.6000000000000001\n"
        b"y_lo -118.93881789566279\ndelay 4\ndegree 2\nterms 39.496171907084637 -6.2357175138474199 5.8010223097682525\n",
    "valid_everett_deg4_keys_reordered": MAGIC + b"terms" + b" 0.5" * 10 + b"\ndegree 4\ny_lo -1\nhi 1\nlo -1\nkind everett",
    "valid_everett_not_monotone": everett_valid.replace(b"terms 3 1 2", b"terms 1 0 -2"),
    "bad_everett_terms_count": everett_valid.replace(b"terms 3 1 2", b"terms 3 1"),
    "bad_everett_eleven_terms": everett_valid.replace(b"terms 3 1 2", b"terms" + b" 1" * 11),
    "bad_everett_degree": everett_valid.replace(b"degree 2", b"degree 2.5"),
    "bad_everett_coeffs": everett_valid + b"coeffs 1 0\n",
    "bad_everett_no_terms": everett_valid.replace(b"terms 3 1 2\n", b""),
    "bad_poly_degree": valid + b"degree 3\n",
})
# fuzz_everett.c: flags, degree, capacity, lo, span, y_lo (structured bytes),
# the coefficients e[i][j] with i + j + 1 <= degree in row order, then samples.
def everett(flags, degree, cap, lo, span, coeffs, samples, y_lo_byte=16):
    return bytes([flags, degree, cap]) + sbyte(lo * 8) + bytes([span * 4 - 1]) + sbyte(y_lo_byte) + \
        b"".join(sbyte(c * 32) for c in coeffs) + bytes(samples)


zigzag = [0, 255, 40, 200, 80, 160, 100, 140, 120, 130, 125, 250, 5, 128, 64, 192, 32, 224]
everett_seeds = {
    "everett_linear": everett(0, 1, 8, 0.0, 10, [0.0], zigzag),
    "everett_asym_deg2": everett(2, 2, 16, -1.0, 20, [0.5, 0.3, 1.0], zigzag * 3),
    "everett_deg3_full": everett(2, 3, 3, 0.0, 16, [0.0, 0.5, -0.2, 1.0, 0.2, 0.5], zigzag * 4),
    "everett_deg4": everett(0, 4, 30, 2.0, 8, [0.2, 0.1, 0.0, -0.1, 0.5, 0.1, 0.0, 0.3, 0.0, 0.1],
                            zigzag * 2),
    "everett_not_monotone": everett(0, 2, 8, 0.0, 10, [0.0, 3.5, -3.9], zigzag),
    "everett_bad_capacity": everett(0, 2, 1, 0.0, 10, [0.0, 0.1, 0.1], zigzag),
    # the tabulated compensator too (flags bit2): rows 15, intervals 31; rows 7, intervals 1
    "everett_table_default_like": everett(0xF4, 2, 16, -1.0, 20, [0.5, 0.3, 1.0], zigzag * 3),
    "everett_table_one_interval": everett(0x14, 3, 8, 0.0, 16, [0.0, 0.5, -0.2, 1.0, 0.2, 0.5],
                                          zigzag * 2),
    # few rows, many intervals (3 and 31): the blend of far rows, measured at the outputs
    "everett_table_few_rows": everett(0xC4, 3, 16, 0.0, 16, [0.0, 0.5, -0.2, 1.0, 0.2, 0.5],
                                      zigzag * 3),
    # y_lo byte 0x80: 2^23, a 24-bit ADC's mid-scale; the fit's RMS (it cancelled) and the table
    "everett_fit_24bit_offset": everett(0x06, 2, 16, -1.0, 20, [0.5, 0.3, 1.0], zigzag * 3, -128),
    "everett_fit_24bit_offset_t1": everett(0x0A, 3, 16, 0.0, 16, [0.0, 0.5, -0.2, 1.0, 0.2, 0.5],
                                           zigzag * 4, -128),
    # one interval, 15 rows: the error between init's probes exceeded the
    # measured one by 3 % (the harness allows twice the measured error)
    "regress_table_between_probes": bytes([0x3E, 0x81, 0x7F, 0x02, 0x00, 0x03, 0x0F, 0x00, 0xFF, 0x03]) +
    bytes(74) + bytes([0x7F, 0x24, 0xFF, 0xB1]),
    # capacity 3: a reversal while the output was held off the full model's branch after the
    # merges were left stored the held output in the new LTP, and the bound dropped to 0 with
    # the model 0.034 off (the TP now takes the full model's output: release_held())
    "regress_reversal_while_settling": bytes.fromhex(
        "2a1003000a00005d027083007e28c8508064baa7a7fa058040c020e000ff28c850a0748c717dfa71"
        "8040a0648c78827d03e0fa0580932d732c018e40a0648c78827dfa058020932d732c018e78827dfa"
        "07e0804049"),
}
# fuzz_q31.c: [flags][cap % 20] config, code range, [intervals], [deadband], [bad width], ops
QRAW, QCOMP, QPROBES, QRAWRANGE, QDEADBAND, QBADDB, QDEEP, QWIDE = 1, 2, 4, 8, 16, 32, 64, 128
eq20_like = (3, 0.0, 3.9375, [-1 / 64, 8 / 64, 55 / 64, 37 / 64], 0)  # Eq. 20 on [0, 40], x = 10 t
cube = (3, -1.0, 2.0, [1.0, 0.0, 0.0, 0.0], 0)                       # flat at 0: marked intervals

def q31_cfg(flags, cap, curve, clo=0, span=4095, intervals=None, db=None, bad=None):
    if flags & QRAW:
        b = raw(0, cap, *curve)[2:]
    else:
        b = structured(0, cap, *curve)[2:]
    b = bytes([flags, cap]) + b
    if flags & QRAWRANGE:
        b += struct.pack("<I", clo)[:3] + struct.pack("<I", clo + span)[:3]
    else:
        b += bytes([0]) + struct.pack("<HH", span, clo)
    if flags & QCOMP:
        b += struct.pack("<H", intervals) if flags & QWIDE else bytes([intervals])
    if flags & QDEADBAND:
        b += struct.pack("<H", db) if not flags & QCOMP else struct.pack("<I", db)[:3]
    if flags & QBADDB:
        b += bytes([bad or 0])
    return b

def qc(v):  # one in-range code, kind 0 (u16 % (span + 1))
    return bytes([0]) + struct.pack("<H", v)

def qd(frac):  # one desired output, kind 0: -2^27 + frac 2^28 (24 bits)
    return bytes([0]) + struct.pack("<I", max(0, min(0xFFFFFF, int(round(frac * 0xFFFFFF)))))[:3]

def q_shrink(unit, levels=6, steps=4, top=1.0):
    b, at = b"", 0.0
    for k in range(levels):
        for target in (top * (1 - 0.07 * k), top * 0.07 * (k + 1)):
            for i in range(1, steps + 1):
                b += unit(at + (target - at) * i / steps)
            at = target
    return b

def qcodes(frac, top=4095):
    return qc(int(round(frac * top)))

qnoise = qc(2000) + b"".join(bytes([10, v & 0xFF]) for v in (5, -3, 4, -6, 2, 7, -2, -5) * 3)
dnoise = qd(0.5) + b"".join(bytes([10, v & 0xFF]) for v in (5, -3, 4, -6, 2, 7, -2, -5) * 3)
q31_seeds = {
    # the model: Eq. 20-like cubic on 12-bit codes, nested loops, a block, reset, accessors
    "model_eq20_12bit": q31_cfg(0, 19, eq20_like) + q_shrink(qcodes) + bytes([0xF1, 5, 0, 0, 4, 3, 11, 0x10, 0x00, 0x14, 9])
        + bytes([0xF4, 128, 1, 0xF0]) + q_shrink(qcodes, 2, 3),
    "model_deep_nesting": q31_cfg(QDEEP, 255, eq20_like, span=65535) + bytes([0xF2, 200]) + qc(60000)
        + bytes([0xF0, 0xF2, 100, 0xF4, 200, 0x41]) + qc(30000),
    "model_deadband_requests": q31_cfg(QDEADBAND | QBADDB, 6, eq20_like, db=6, bad=3) + qnoise
        + bytes([0xF3, 1]) + struct.pack("<H", 0) + bytes([0]) + struct.pack("<H", 100) + qnoise
        + bytes([0xF3, 7]) + struct.pack("<H", 9) + bytes([0]) + struct.pack("<H", 3000) + qnoise
        + bytes([0xF3, 9, 5, 3, 0xF5, 255, 0x80]),
    "model_clamped": q31_cfg(0, 5, eq20_like, clo=1000, span=2000) + bytes([4, 7, 0x14, 9, 0x0C, 1, 2, 3, 3, 11, 0x1C, 4, 0])
        + bytes([0xF1, 6, 3, 11, 4, 7, 0, 0x10, 0x00, 0x14, 9, 0x1C, 0x0C, 1, 2, 3]) + bytes([0xF6, 30, 4]),
    "model_merge_cap2": q31_cfg(0, 2, eq20_like, span=65535) + q_shrink(lambda u: qcodes(u, 65535), 6, 3),
    "model_probes": q31_cfg(QPROBES | QBADDB, 8, eq20_like, bad=200) + q_shrink(qcodes, 2, 2) + bytes([0xF7, 0, 2]),
    "model_raw_eq20": q31_cfg(QRAW, 40, (3, 0.0, 40.0, [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]))
        + q_shrink(qcodes, 3, 3),
    # the compensator (flag bit1): intervals, then desired outputs
    "comp_eq20_12bit": q31_cfg(QCOMP, 19, eq20_like, intervals=32) + q_shrink(qd)
        + bytes([0xF1, 64 | 5, 0, 0, 0, 4, 0x0C, 3, 0x0B, 2, 200, 0x24, 1, 2, 3]) + bytes([0xF4, 128, 1, 0xF0]) + q_shrink(qd, 2, 3),
    "comp_flat_x3": q31_cfg(QCOMP, 12, cube, span=65535, intervals=64) + q_shrink(qd, 4, 4)
        + bytes([0xF2, 30]),
    "comp_deadband_requests": q31_cfg(QCOMP | QDEADBAND | QBADDB, 6, eq20_like, intervals=16, db=1 << 16, bad=9) + dnoise
        + bytes([0xF3, 1]) + struct.pack("<I", 0)[:3] + qd(0.9) + dnoise
        + bytes([0xF3, 7]) + struct.pack("<I", 1 << 12)[:3] + qd(0.1) + dnoise,
    "comp_clamped_blocks": q31_cfg(QCOMP, 3, eq20_like, clo=100, span=4095, intervals=8)
        + bytes([0x0C, 4, 0x1C, 0, 0x14, 0x24, 1, 2, 3, 0x2C, 4, 0x2C]) + bytes([0xF1, 8]) + qd(0.3) + qd(0.7)
        + bytes([0x0C, 4, 0x1C, 9, 0x03, 0x0B, 0x05]) + q_shrink(qd, 3, 2),
    "comp_wide_n_probes": q31_cfg(QCOMP | QWIDE | QPROBES, 10, eq20_like, intervals=1000) + q_shrink(qd, 2, 3),
    "comp_deep_nesting": q31_cfg(QCOMP | QDEEP, 250, eq20_like, span=65535, intervals=255) + bytes([0xF2, 150])
        + bytes([0xF4, 100, 0x10]) + q_shrink(qd, 2, 2),
    # slow sweeps over the flat point of x^3 (one code, one q per sample), where rounding
    # alone could step the output back: the monotone guard
    "model_flat_sweep": q31_cfg(0, 8, cube, span=65535) + qc(32740) + bytes([0x0A, 1]) * 60
        + bytes([0x0A, 0xFF]) * 60,
    "comp_flat_sweep": q31_cfg(QCOMP, 8, cube, span=65535, intervals=64) + qd(0.4999) + bytes([0x02, 1]) * 60
        + bytes([0x02, 0xFF]) * 60,
    # refusals
    "bad_cap1": q31_cfg(0, 1, eq20_like),
    "bad_range_empty": q31_cfg(QRAWRANGE, 8, eq20_like, clo=500, span=0),
    "bad_range_wide": q31_cfg(QRAWRANGE, 8, eq20_like, clo=0, span=70000),
    "bad_not_increasing": q31_cfg(QPROBES, 8, (2, -1.0, 2.0, [1.0, 0.0, 0.0], 0)),
    "bad_raw_coeff_x7": q31_cfg(QRAW, 8, (7, 0.0, 1.0, [1.0, -3.5, 5.25, -4.375, 2.1875, -0.65625, 0.109375, -0.0078125])),
    "comp_bad_intervals0": q31_cfg(QCOMP | QPROBES, 8, eq20_like, intervals=0),
    "comp_bad_cap1": q31_cfg(QCOMP, 1, eq20_like, intervals=4),
    "comp_raw_coeff_x7": q31_cfg(QCOMP | QRAW, 8, (7, 0.0, 1.0, [1.0, -3.5, 5.25, -4.375, 2.1875, -0.65625, 0.109375, -0.0078125]), intervals=8),
}
# fuzz_grid.c: flags, intervals, capacity, fit byte, probe byte, then lo, the widths, y_lo
# and the cells' masses (structured bytes), then opcodes (0xF0 snapshot + which mass the
# other grid changes, 0xF1 reset, 0xF2 + knot, 0xF3 + where: an excursion, 0xF4 + a raw
# double: the fit's output, + the sample, 0xF5 hi, 0xF6 lo, else a sample b / 239).
G_RAW, G_COMP, G_FIT, G_PROBE, G_F32 = 1, 2, 4, 8, 16

def grid(flags, widths, masses, ops, cap=30, fit=40, probe=0, lo=0.0, y_lo_byte=16):
    k = len(widths)
    assert len(masses) == k * (k + 1) // 2
    b = bytes([flags, k, cap, fit, probe]) + sbyte(lo * 8) + bytes([int(w * 4) - 1 for w in widths])
    b += sbyte(y_lo_byte) + bytes([0 if m == 0 else (255 if m > 12 else int(m * 16) + 40) for m in masses])
    return b + ops

def gwalk(levels=4, steps=3):
    b, at = b"", 0
    for j in range(levels):
        for target in (239 - 20 * j, 20 * (j + 1)):
            for i in range(1, steps + 1):
                b += bytes([at + (target - at) * i // steps])
            at = target
    return b

def graw(flags, knots, y_lo, masses, ops=b"", cap=30):
    return bytes([flags | G_RAW, len(knots) - 1, cap, 40, 0]) + struct.pack("<%dd" % len(knots), *knots) + \
        struct.pack("<d", y_lo) + struct.pack("<%dd" % len(masses), *masses) + ops

tri3 = [1.0, 0.5, 2.0, 0.0, 1.0, 3.0]  # cells (0,0) (1,0) (1,1) (2,0) (2,1) (2,2)
sharp4 = [0.5, 0, 4.0, 0.25, 13, 0.5, 0, 0, 1.0, 2.0]
many12 = [((i * 7) % 11) / 4.0 for i in range(78)]
grid_seeds = {
    "grid_one_cell": grid(0, [2.0], [8.0], gwalk(2, 2) + bytes([0xF2, 1, 0xF2, 0])),
    "grid_three_all": grid(G_COMP | G_FIT | G_F32, [1.0, 2.5, 0.75], tri3, gwalk(4, 3), lo=-1.0),
    "grid_sharp_cell": grid(G_COMP | G_FIT, [0.5, 4.0, 1.0, 2.0], sharp4, gwalk(5, 2) + bytes([0xF3, 100]) + gwalk(1, 4)),
    "grid_snapshot_reset": grid(0, [1.0, 2.5, 0.75], tri3, gwalk(2, 3) + bytes([0xF0, 3]) + gwalk(1, 3) +
                                bytes([0xF3, 50, 0xF1]) + gwalk(2, 2) + bytes([0xF0, 0])),
    "grid_twelve_intervals": grid(G_COMP | G_FIT | G_F32, [0.25 * (1 + i % 5) for i in range(12)], many12,
                                  gwalk(5, 3) + bytes([0xF2, 6, 0xF5, 0xF6]), cap=39, fit=47),
    "grid_small_capacity": grid(G_COMP | G_F32, [0.5, 4.0, 1.0, 2.0], sharp4, gwalk(6, 2), cap=3),
    "grid_fit_nospace": grid(G_FIT, [1.0, 2.5, 0.75], tri3, gwalk(4, 2), fit=3),
    "grid_fit_raw_outputs": grid(G_FIT, [1.0, 2.5, 0.75], tri3, gwalk(1, 2) + bytes([0xF4]) + struct.pack("<d", math.nan)
                                 + bytes([100, 0xF4]) + struct.pack("<d", 1.5e308) + bytes([30, 0xF4])
                                 + struct.pack("<d", -1.5e308) + bytes([101])),
    "grid_24bit_offset": grid(G_COMP | G_FIT, [1.0, 2.5, 0.75], tri3, gwalk(3, 3), y_lo_byte=-128),
    "grid_knot_bins_short": grid(G_FIT, [1.0, 2.5], [1.0, 0.5, 2.0], gwalk(1, 2), fit=0),
}
for p_ in range(12):
    grid_seeds["grid_probe_%d" % p_] = grid(G_PROBE, [1.0, 2.5, 0.75], tri3, gwalk(1, 2), probe=p_)
grid_seeds.update({
    "grid_bad_intervals0": grid(0, [], [], b""),
    "grid_bad_all_zero": grid(0, [1.0, 2.0], [0, 0, 0], gwalk(1, 2)),
    "grid_bad_capacity": grid(0, [1.0, 2.0], [1.0, 0, 1.0], gwalk(1, 2), cap=1),
    "grid_raw_valid": graw(G_COMP | G_FIT, [-2.0, 0.5, 3.0], 0.25, [1.0, 0.5, 2.0], gwalk(2, 3)),
    "grid_raw_nan_knot": graw(G_FIT, [0.0, math.nan, 3.0], 0.0, [1.0, 0.5, 2.0], gwalk(1, 2)),
    "grid_raw_huge_density": graw(G_F32, [0.0, 1e-300, 1.0], 0.0, [1e300, 1.0, 1.0], gwalk(1, 2)),
    # finds, fixed: desired y_lo from above with the first diagonal cell empty drove to the end
    # of the flat first piece, not to lo (the plant kept its first column switched up)
    "regress_grid_comp_empty_first_cell": grid(G_COMP, [1.0, 2.0], [0, 1.5, 2.0], bytes([120, 0xF5, 0xF6, 60])),
    # outputs of 1e176 and a last cell of 1: a desired output past the branch's reach by a
    # rounding drove to 1.8e88, past hi = 3 (the drive now stops at the piece's end)
    "regress_grid_comp_beyond_reach": bytes.fromhex(
        "07021e280000000000000000c0000000000000e03f00000000000008406464646464646464646464646464646464"
        "64646464646464000000000000d03f000000000000f03f000000000000e03f00000000000000404f9fefa65d56db"
        "63989f28"),
    # a width of 1e160: its square overflowed, the mass tabulated as 0 (the model never reached
    # y_hi); refused now (HYST_ERR_COEFF)
    "regress_grid_density_underflow": graw(G_COMP, [0.0, 1e160], 0.0, [1.0], gwalk(1, 2)),
    # a width of 1.6e-159: its square subnormal, the density off by 1.3e-7 (now divided in turn)
    "regress_grid_width_square_subnormal": bytes.fromhex(
        "c5c5c5c5c5c516031e0403588128b17c775003f71e04300358c78828b33c7750031e04b33c7750031e0403811477"
        "db822b775877ef77c7882828b33c7750031e04035877ef77c78828b33c7750031e04b33c7750031e0403811477db"
        "812b772f033c7750031e04035877882828b33c7750031e04035877ef77c78828b33c28b33c7750031e04b3775003"
        "1e04b33c7750031e0403811477db812b772f033c7750031e04035877ef77c78828b33c7750031e04b33c7750031e"
        "0403811400000077db822b772f031e0403ef05050577c7883f28b33c7740031e04b33c7750031e040381146777db"
        "812b772f031e0403587721811477db28b33c774141"),
    # back to a setpoint one rounding above an LTP's output, the branch flat below it: the
    # drive crossed the flat stretch past the LTP, the plant wiped it out (8.7 off); the drive
    # now stops at the stored TP the branch would wipe out next
    "regress_grid_comp_setpoint_flat": bytes.fromhex(
        "120403280000010f0307100100001325ffffffffff77ef811477f100db81281c1c1c1c1c9f50817777641c8b8178"),
    # a raw output of -1.4e308: the fit answered HYST_OK with an infinite mass (now HYST_ERR_COEFF)
    "regress_grid_fit_overflow": bytes.fromhex("04031e2800000309021038304800385877eface1486db3ea7f1ef4f0ace1486db3eaff65"),
    # output steps of 1.5e308 in one bin: their sum overflowed and the knots were NaN
    "regress_grid_knots_overflow": grid(G_FIT, [1.0, 2.5, 0.75], tri3, bytes([50, 0xF4]) + struct.pack("<d", 1.5e308)
                                        + bytes([120, 50, 0xF4]) + struct.pack("<d", 1.5e308) + bytes([120, 50])),
    # a domain of 4 units in the last place: the knots collapsed to equal ones (now HYST_ERR_DOMAIN)
    "regress_grid_knots_narrow_domain": graw(G_FIT, [1.0, 1.0 + 2 ** -51, 1.0 + 2 ** -50], 0.0, [1.0, 0.5, 2.0],
                                             bytes([200, 0xF5] * 4)),
})
# fuzz_spline.c: flags, intervals, capacity, fit byte, fit intervals, probe byte, then lo, the
# span, value[0], each piece's rise and each knot's slope (structured bytes; with flags bit5
# the K + 2 I-spline weights instead), then opcodes (0xF0 snapshot + which change the other
# spline makes, 0xF1 reset, 0xF2 + knot, 0xF3 + where: an excursion, 0xF4 + a raw double: the
# fit's output, + the sample, 0xF5 hi, 0xF6 lo, else a sample b / 239).
S_RAW, S_COMP, S_FIT, S_PROBE, S_F32, S_SPACE = 1, 2, 4, 8, 16, 32
LARGER = 64  # a slope byte's bit6: the larger secant beside the knot

def spline(flags, rises, slopes, ops, cap=30, fit=40, fit_k=None, probe=0, lo=0.0, span=4.0, v0_byte=16):
    """rises in 1/16 (0: flat, above 12: 134.375); slopes as bytes: (b & 63) / 16 times a secant."""
    k = len(rises)
    assert len(slopes) == k + 1
    b = bytes([flags, k, cap, fit, k if fit_k is None else fit_k, probe]) + sbyte(lo * 8)
    b += bytes([int(span * 4) - 1]) + sbyte(v0_byte)
    b += bytes([0 if r == 0 else (255 if r > 12 else int(r * 16) + 40) for r in rises])
    return b + bytes(slopes) + ops

def sspace(flags, weights, ops, cap=30, fit=40, lo=0.0, span=4.0, v0_byte=16):
    """a spline of the fit's space (flags bit5): the K + 2 I-spline weights as bytes, (b - 64) / 16"""
    k = len(weights) - 2
    b = bytes([flags | S_SPACE, k, cap, fit, k, 0]) + sbyte(lo * 8) + bytes([int(span * 4) - 1]) + sbyte(v0_byte)
    return b + bytes([0 if w == 0 else int(w * 16) + 64 for w in weights]) + ops

def sraw(flags, lo, hi, values, slopes, ops=b"", cap=30, fit=40, fit_k=None):
    k = len(values) - 1
    return bytes([flags | S_RAW, k, cap, fit, k if fit_k is None else fit_k, 0]) + struct.pack("<dd", lo, hi) + \
        struct.pack("<%dd" % len(values), *values) + struct.pack("<%dd" % len(slopes), *slopes) + ops

five = [0.5, 2.0, 0.25, 4.0, 1.0]
five_s = [16, 16, 32, 8, 48, 16]
steps12 = [(0, 0.25, 3.0, 0.0625, 13, 1.0)[i % 6] for i in range(12)]
spline_seeds = {
    "spline_one_piece": spline(0, [2.0], [16, 16], gwalk(2, 2) + bytes([0xF2, 1, 0xF2, 0])),
    "spline_five_all": spline(S_COMP | S_FIT | S_F32, five, five_s, gwalk(4, 3), lo=-1.0, span=2.5),
    "spline_flat_piece": spline(S_COMP | S_FIT, [1.0, 0, 2.0], [16, 0, 0, 16], gwalk(3, 3)),
    "spline_steep": spline(S_COMP | S_FIT | S_F32, [0.0625, 13, 0.0625], [48, 48, 48, 48], gwalk(4, 3) +
                           bytes([0xF3, 100]) + gwalk(1, 4)),
    "spline_twelve_flat_and_steep": spline(S_COMP | S_FIT | S_F32, steps12, [16 + 8 * (i % 5) for i in range(13)],
                                           gwalk(5, 3) + bytes([0xF2, 6, 0xF5, 0xF6]), cap=39, fit=47, fit_k=9),
    "spline_snapshot_reset": spline(0, five, five_s, gwalk(2, 3) + bytes([0xF0, 0]) + gwalk(1, 3) + bytes([0xF0, 4]) +
                                    bytes([0xF3, 50, 0xF1]) + gwalk(2, 2) + bytes([0xF0, 2])),
    "spline_thirty_two": spline(S_COMP | S_FIT | S_F32, [0.25 * (1 + i % 7) for i in range(32)],
                                [16 + (i * 5) % 40 for i in range(33)], gwalk(6, 3), cap=39, fit=47, span=15.75),
    "spline_small_capacity": spline(S_COMP | S_F32, five, five_s, gwalk(6, 2), cap=3),
    "spline_fit_nospace": spline(S_FIT, five, five_s, gwalk(4, 2), fit=3),
    "spline_fit_one_interval": spline(S_FIT, five, five_s, gwalk(3, 3), fit_k=1),
    "spline_fit_raw_outputs": spline(S_FIT, five, five_s, gwalk(1, 2) + bytes([0xF4]) + struct.pack("<d", math.nan)
                                     + bytes([100, 0xF4]) + struct.pack("<d", 1.5e308) + bytes([30, 0xF4])
                                     + struct.pack("<d", -1.5e308) + bytes([101])),
    "spline_fit_flat_record": spline(S_FIT, five, five_s, bytes([0, 0xF6, 0, 0xF6])),
    "spline_24bit_offset": spline(S_COMP | S_FIT | S_F32, five, five_s, gwalk(3, 3), v0_byte=-128),
    "spline_larger_secant_dips": spline(S_COMP, [0.25, 4.0, 0.25], [16, 48 | LARGER, 48 | LARGER, 16], gwalk(2, 2)),
    "spline_touching_zero": spline(S_COMP | S_FIT, [1.0], [48, 48], gwalk(3, 3), span=1.0),
    "spline_fit_space_five": sspace(S_FIT | S_COMP, [1.0, 0.5, 0, 2.0, 0.25, 1.5, 0.75],
                                    gwalk(4, 3) + bytes([0xF1]) + gwalk(2, 2)),
    "spline_fit_space_twenty": sspace(S_FIT | S_F32, [(i * 5 % 9) / 4.0 for i in range(22)], gwalk(6, 3), cap=39,
                                      fit=47, lo=-2.0, span=10.0),
    "spline_fit_space_offset": sspace(S_FIT, [0.5, 1.0, 0.25, 0, 3.0], gwalk(3, 3), v0_byte=-128),
}
for p_ in range(15):
    spline_seeds["spline_probe_%d" % p_] = spline(S_PROBE, five, five_s, gwalk(1, 2), probe=p_)
spline_seeds["spline_probe_11_nospace"] = spline(S_PROBE, five, five_s, gwalk(1, 2), probe=26)
spline_seeds["spline_probe_12_nospace"] = spline(S_PROBE, five, five_s, gwalk(1, 2), probe=27)
spline_seeds.update({
    "spline_bad_intervals0": spline(0, [], [0], b""),
    "spline_bad_intervals33": bytes([0, 33, 30, 40, 33, 0]),
    "spline_bad_constant": spline(S_FIT, [0, 0], [0, 0, 0], gwalk(1, 2)),
    "spline_bad_capacity": spline(0, [1.0, 2.0], [16, 16, 16], gwalk(1, 2), cap=1),
    "spline_raw_valid": sraw(S_COMP | S_FIT | S_F32, -2.0, 3.0, [0.25, 1.0, 1.5, 4.0], [0.5, 0.25, 1.0, 2.0],
                             gwalk(2, 3)),
    "spline_raw_offset_domain": sraw(S_COMP | S_FIT, 1e6, 1e6 + 0.5, [-3.0, -2.0, 5.0], [1.0, 4.0, 0.0], gwalk(3, 3)),
    "spline_raw_nan_lo": sraw(S_FIT, math.nan, 3.0, [0.0, 1.0], [1.0, 1.0], gwalk(1, 2)),
    "spline_raw_tiny_span": sraw(S_FIT | S_F32, 1.0, 1.0 + 2 ** -52, [0.0, 1.0], [0.0, 0.0], gwalk(1, 2)),
    # finds, fixed: values beyond float, their rises within it: the float variant wrote its table,
    # then refused the ends' outputs (HYST_ERR_COEFF); the ends are checked first now
    "regress_spline_f32_refusal_wrote_table": sraw(S_F32 | S_COMP, 0.0, 1.0, [1e39, 1e39 + 1e31], [0.0, 0.0],
                                                   gwalk(2, 2)),
    # slopes whose piece's numbers overflow: HYST_ERR_COEFF before the piece's shape (it dips:
    # HYST_ERR_NOT_INCREASING) and before NOSPACE; the shape is checked scaled now
    "regress_spline_overflow_dips": sraw(0, 0.0, 10.0, [0.0, 1.0], [1e308, 1e308], gwalk(1, 2)),
    # the same shape scaled near the type's largest: a rise of 0.75 2^1024 overflows 3 rise, and
    # that piece answered HYST_ERR_COEFF before NOSPACE (a table one number short)
    "regress_spline_overflow_before_nospace": spline(S_PROBE, [0.25, 12.0, 0.25], [16, 16, 16, 16], gwalk(1, 2),
                                                     probe=26),
    # an increasing piece whose c2^2 overflows (values near 2e200): refused as not increasing
    "regress_spline_vertex_square_overflow": sraw(S_COMP | S_FIT, 0.0, 1.0, [0.0, 2e200 - 1e190],
                                                  [1e200, 4e200 - 2e190], gwalk(2, 2)),
})
for d, group in ((out, seeds), (os.path.join(here, "corpus_models"), models),
                 (os.path.join(here, "corpus_code"), code_seeds),
                 (os.path.join(here, "corpus_model_file"), model_files),
                 (os.path.join(here, "corpus_everett"), everett_seeds),
                 (os.path.join(here, "corpus_q31"), q31_seeds),
                 (os.path.join(here, "corpus_grid"), grid_seeds),
                 (os.path.join(here, "corpus_spline"), spline_seeds)):
    os.makedirs(d, exist_ok=True)
    for name, data in group.items():
        assert len(data) < (8192 if group is model_files else 300), name
        with open(os.path.join(d, name), "wb") as f:
            f.write(data)
    print(f"{len(group)} seeds in {d}")
