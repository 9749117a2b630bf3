#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the measured records that carry no licence, for bench/fidelity, to
build/records/ (never committed). Give it clones of their repositories:

    git clone https://github.com/danny-bit/preisach
    git clone https://github.com/HaammiiD/Genetic-Algorithm-System-Identification
    bench/fidelity_records.py --preisach preisach \\
        --ga Genetic-Algorithm-System-Identification

Files read with `git show COMMIT:PATH` (the pinned commit for preisach):
- valve_20hz.txt, valve_40hz.txt, valve_100hz.txt: preisach's
  Final_files_for_master/cont_id_and_inv/lp_and_delay/{20,40,100}_hz_no_lp.mat
  (MAT v5, read by the small reader below): drive `Pdrag` (column 1), output
  `Mling` (column 2), 10 kHz.
- valve_tri50.txt, valve_sine100.txt, valve_prbn.txt: the same valve's
  Final_files_for_master/discrete_id_and_inv/inv_compare/exp_design_test/
  {tri50,sine100,prbn}_1.mat: 1 s at rest in the middle of the range, then
  excursions growing to both ends (a triangle, a sine, a random binary
  sequence), the same signals.
- sma_ga.txt: input_data.m's v and y, y - 20 + 17.72, the major loop then the
  ten reversal curves appended as the script assembles them (773 samples).
"""
import argparse
import os
import re
import struct
import subprocess
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PREISACH_COMMIT = "8d1d16b8"
VALVE_DIR = "Final_files_for_master/cont_id_and_inv/lp_and_delay/"
GROWING_DIR = "Final_files_for_master/discrete_id_and_inv/inv_compare/exp_design_test/"

# MAT v5 data types: struct format of each numeric one
NUMERIC = {1: "b", 2: "B", 3: "h", 4: "H", 5: "i", 6: "I", 7: "f", 9: "d", 12: "q", 13: "Q"}
MI_MATRIX, MI_COMPRESSED = 14, 15
CLASS_CELL, CLASS_STRUCT, CLASS_CHAR = 1, 2, 4


def elements(buf, pos=0, end=None):
    """(type, bytes) of each data element of buf[pos:end]."""
    end = len(buf) if end is None else end
    while pos < end:
        t, n = struct.unpack_from("<II", buf, pos)
        if t >> 16:  # small element: its bytes in the tag's second word
            n, t = t >> 16, t & 0xFFFF
            yield t, buf[pos + 4:pos + 4 + n]
            pos += 8
        else:
            yield t, buf[pos + 8:pos + 8 + n]
            pos += 8 + n + (-n % 8)


def value(t, data):
    if t == MI_COMPRESSED:
        return value(*next(elements(zlib.decompress(data))))
    if t == MI_MATRIX:
        return matrix(data)[1]
    size = struct.calcsize(NUMERIC[t])
    return list(struct.unpack("<%d%s" % (len(data) // size, NUMERIC[t]), data))


def matrix(data):
    """(name, value) of a miMATRIX: a list (numeric, real part only), a str,
    a dict (a 1x1 struct) or a list of dicts (a struct array), or a list
    (a cell array)."""
    if not data:
        return "", None
    els = list(elements(data))
    cls = struct.unpack_from("<I", els[0][1])[0] & 0xFF
    name = els[2][1].decode("latin-1")
    if cls == CLASS_STRUCT:
        width = struct.unpack_from("<i", els[3][1])[0]
        raw = els[4][1]
        fields = [raw[i:i + width].split(b"\0")[0].decode() for i in range(0, len(raw), width)]
        vals = [matrix(e[1])[1] for e in els[5:]]
        recs = [dict(zip(fields, vals[i:i + len(fields)])) for i in range(0, len(vals),
                                                                          len(fields))]
        return name, recs[0] if len(recs) == 1 else recs
    if cls == CLASS_CELL:
        return name, [matrix(e[1])[1] for e in els[3:]]
    if cls == CLASS_CHAR:
        return name, "".join(chr(c) for c in value(*els[3]))
    return name, value(*els[3])


def load_mat(buf):
    out = {}
    for t, data in elements(buf, 128):
        if t == MI_COMPRESSED:
            t, data = next(elements(zlib.decompress(data)))
        if t == MI_MATRIX:
            name, v = matrix(data)
            out[name] = v
    return out


def git_show(repo, spec):
    gitdir = os.path.join(repo, ".git") if os.path.isdir(os.path.join(repo, ".git")) else repo
    return subprocess.run(["git", "--git-dir", gitdir, "show", spec], check=True,
                          capture_output=True).stdout


def write(path, xs, ys):
    with open(path, "w") as f:
        f.writelines("%.17g %.17g\n" % (a, b) for a, b in zip(xs, ys))
    print("wrote %s (%d samples)" % (os.path.relpath(path, ROOT), len(xs)))


def valve_signals(repo, path):
    """(drive, output) of one of the valve's records."""
    (rec,) = load_mat(git_show(repo, "%s:%s" % (PREISACH_COMMIT, path))).values()
    signals = {s["Name"].split('"/"')[1]: s["Data"] for s in rec["Y"]}
    # the names are Swedish (P\xe5drag, M\xe4ling), saved in a code page
    drive = next(v for k, v in signals.items() if k.startswith("P") and k.endswith("drag"))
    output = next(v for k, v in signals.items() if k.startswith("M") and k.endswith("ling"))
    return drive, output


def valve(repo, out):
    for rate in ("20", "40", "100"):
        write(os.path.join(out, "valve_%shz.txt" % rate),
              *valve_signals(repo, "%s%s_hz_no_lp.mat" % (VALVE_DIR, rate)))
    for name in ("tri50", "sine100", "prbn"):
        write(os.path.join(out, "valve_%s.txt" % name),
              *valve_signals(repo, "%s%s_1.mat" % (GROWING_DIR, name)))


def sma(repo, out):
    src = git_show(repo, "HEAD:input_data.m").decode()

    def vec(name):
        m = re.search(r"^%s=\[(.*?)\];" % name, src, re.M | re.S)
        return [float(t) for t in m.group(1).replace(";", " ").replace(",", " ").split()]

    v, y = vec("v"), [a - 20 + 17.72 for a in vec("y")]
    # the script's pieces, 1-based inclusive (None: to the end): the major
    # loop, then each reversal curve after the rise it starts from
    pieces = [(1, 97, None, None), (1, 41, 98, 138), (1, 37, 139, 175), (1, 36, 176, 211),
              (1, 35, 212, 246), (1, 34, 247, 280), (1, 33, 281, 313), (1, 32, 314, 345),
              (1, 31, 346, 376), (1, 30, 377, 406), (1, 29, 407, None)]
    xs, ys = [], []
    for a, b, c, d in pieces:
        xs += v[a - 1:b]
        ys += y[a - 1:b]
        if c is not None:
            xs += v[c - 1:d]
            ys += y[c - 1:d]
    write(os.path.join(out, "sma_ga.txt"), xs, ys)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--preisach", help="clone (or git directory) of danny-bit/preisach")
    ap.add_argument("--ga", help="clone of HaammiiD/Genetic-Algorithm-System-Identification")
    ap.add_argument("--out", default=os.path.join(ROOT, "build/records"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.preisach:
        valve(args.preisach, args.out)
    if args.ga:
        sma(args.ga, args.out)


if __name__ == "__main__":
    main()
