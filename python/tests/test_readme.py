# SPDX-License-Identifier: MIT
"""The README's Python quick-start runs as written (from the repository root)."""
import re
import subprocess
import sys

from conftest import REPO


def test_readme_python_block_runs():
    text = (REPO / "README.md").read_text()
    section = text.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert len(blocks) == 1, "README: one ```python block under '## Python'"
    r = subprocess.run([sys.executable, "-c", blocks[0]], cwd=REPO, capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip(), "the quick-start prints its results"
