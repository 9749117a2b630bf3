# SPDX-License-Identifier: MIT
"""header_text(..., compensator=True): the compensator's table built by the
library in float and in double and sealed, as `hyst header --compensator`
writes it: the same text as the CLI's byte for byte but for the first
comment (the generator's), for both kinds and a non-default size; the tables are the compensators' own (ModelFromEverett /
compensator_from with intervals=N): their numbers and their seal; a damaged
number no longer matches the seal's checksum; bad sizes are refused."""
import re
import subprocess
import zlib

import numpy as np
import pytest

import hyst

EV = {"kind": "everett", "lo": 0.0, "hi": 40.0, "y_lo": 0.5, "degree": 3,
      "terms": [3.0, 1.0, 0.0, 2.0, -0.5, 0.4]}
POLY = {"kind": "poly", "lo": 0.0, "hi": 40.0,
        "coeffs": [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1]}


def after_first_comment(text):
    """The header but its first comment, which names the generator."""
    return text[text.index("*/\n") + len("*/\n"):]


def table_part(text, name):
    """From the first #define of the table's sizes to the #endif of its variants."""
    start = text.index(f"#define {name}_")
    return text[start:text.index("#endif\n", start) + len("#endif\n")]


@pytest.mark.parametrize("model, sizes", [
    (EV, {}), (EV, {"intervals": 16, "rows": 8}), (POLY, {}), (POLY, {"intervals": 64})])
def test_same_table_as_the_cli(c_build, tmp_path, model, sizes):
    path = tmp_path / "m.hyst"
    hyst.save_model(path, **model)
    args = [str(c_build["cli"]), "header", "--model", str(path), "--dir", str(tmp_path),
            "--compensator"]
    for k, v in sizes.items():
        args += [f"--{k}", str(v)]
    r = subprocess.run(args + ["comp"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    cli_text = (tmp_path / "comp.h").read_text()
    py_text = hyst.header_text("comp", **model, compensator=True, **sizes)
    assert after_first_comment(py_text) == after_first_comment(cli_text)
    assert "comp_seal = {0x" in table_part(py_text, "comp")
    assert py_text.endswith("#endif /* COMP_H */\n")


def seal_of(text, name, double):
    part = text.split("#else\n")[0 if double else 1]
    m = re.search(rf"{name}_seal = \{{0x([0-9A-F]{{8}})ul, ([0-9.e+-]+)\}}", part)
    return int(m.group(1), 16), float(m.group(2))


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_tables_are_the_compensators(dtype):
    c = hyst.ModelFromEverett(EV["degree"], EV["lo"], EV["hi"], EV["y_lo"], EV["terms"],
                              dtype=dtype, inverse=True, intervals=32, rows=16)
    text = hyst.header_text("comp", **EV, compensator=True)
    double = dtype == "float64"
    part = table_part(text, "comp").split("#else\n")[0 if double else 1]
    body = part[part.index("= {") + 3:part.index("};")]
    numbers = [float(v.rstrip("f")) for v in body.replace("\n", " ").split(",")]
    assert np.array_equal(np.asarray(numbers, dtype=dtype), np.asarray(c.table, dtype=dtype))
    assert seal_of(text, "comp", double) == c.table_seal
    crc, max_err = c.table_seal
    assert max_err == c.inverse_error


def test_the_seal_is_a_crc_of_the_table():
    """The seal's CRC covers every number: recomputed here from the
    documented serialisation (kind, variant, rows, intervals as 32-bit
    little-endian words, the error as a float, then the numbers' bit
    patterns), and one number one unit off changes it."""
    c = hyst.ModelFromEverett(EV["degree"], EV["lo"], EV["hi"], EV["y_lo"], EV["terms"],
                              dtype="float32", inverse=True, intervals=32, rows=16)
    crc, max_err = c.table_seal
    kind_everett_inv_table, variant_f32 = 8, 1
    head = np.array([kind_everett_inv_table, variant_f32, 16, 32], dtype="<u4").tobytes()
    table = np.asarray(c.table, dtype="<f4")
    data = head + np.float32(max_err).astype("<f4").tobytes() + table.tobytes()
    assert zlib.crc32(data) == crc
    table[100] = np.nextafter(table[100], np.float32(1e30))
    assert zlib.crc32(head + np.float32(max_err).astype("<f4").tobytes() + table.tobytes()) != crc


def test_bad_sizes_are_refused():
    with pytest.raises(ValueError, match="rows applies to kind everett only"):
        hyst.header_text("comp", **POLY, compensator=True, rows=8)
    with pytest.raises(ValueError, match="compensator=True"):
        hyst.header_text("comp", **EV, intervals=8)
    with pytest.raises(hyst.HystError):
        hyst.header_text("comp", **EV, compensator=True, intervals=0)
