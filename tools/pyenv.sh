#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Prints the path of a Python with numpy + matplotlib, creating a venv under
# build/pyenv from PyPI the first time. Only the figure scripts need it; the C
# build and the tests never do.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if python3 -c 'import numpy, matplotlib' >/dev/null 2>&1; then
    command -v python3
    exit 0
fi
venv="$root/build/pyenv"
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c 'import numpy, matplotlib' >/dev/null 2>&1; then
    python3 -m venv "$venv" >&2 || { apt-get install -y -qq --no-install-recommends python3-venv >&2 && python3 -m venv "$venv" >&2; }
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check numpy matplotlib >&2
fi
echo "$venv/bin/python"
