# SPDX-License-Identifier: MIT
"""The readers of hyst-model-text 1 agree: on every crafted file of
tests/model_files (line ends, blanks, hexadecimal and decimal-comma numbers,
long lines, counts, limits, an empty domain...) the package reads the values
`hyst header --model` reads (the header's numbers are 17-digit literals, the
delay stated in its comment), or refuses the file with the tool's words.
matlab/tests/run_tests.m holds the MATLAB/Octave reader to the same."""
import os
import re
import subprocess

import pytest

import hyst

FILES = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "model_files")
CRAFTED = sorted(f for f in os.listdir(FILES) if f.endswith(".hyst"))


def cli_read(cli, path, out_dir):
    """What the tool reads: (header from the guard on, delay) or its message."""
    r = subprocess.run([str(cli), "header", "--model", path, "--dir", str(out_dir), "m"],
                       capture_output=True)
    if r.returncode != 0:
        msg = r.stderr.decode("utf-8", "replace").strip()
        assert msg.startswith("hyst header: "), msg
        return None, msg[len("hyst header: "):]
    text = (out_dir / "m.h").read_text()
    delay = float(re.search(r"follows its input\s+\*?\s*([0-9.e+]+) samples later",
                            text).group(1))
    return (text[text.index("#ifndef"):], delay), None


def test_there_are_crafted_files_of_both_outcomes():
    assert sum(f.startswith("ok_") for f in CRAFTED) >= 15
    assert sum(f.startswith("bad_") for f in CRAFTED) >= 30


@pytest.mark.parametrize("name", CRAFTED)
def test_python_reads_what_the_tool_reads(c_build, tmp_path, name):
    path = os.path.join(FILES, name)
    read, refusal = cli_read(c_build["cli"], path, tmp_path)
    assert (refusal is None) == name.startswith("ok_"), refusal
    if refusal is not None:
        with pytest.raises(hyst.ModelFileError) as err:
            hyst.load_model(path)
        assert str(err.value) == refusal
        return
    m = hyst.load_model(path)
    header, delay = read
    assert m["delay"] == delay
    text = hyst.header_text("m", **m)
    assert text[text.index("#ifndef"):] == header
