# SPDX-License-Identifier: MIT
"""fit() refuses and warns of a record as `hyst fit` does, by the tool's own
check (fit_record_check()): a response at the edge of "falls as the drive
rises" (correlation -1/2) refused by both or by neither, a missing (NaN)
sample taken as the row left out of the tool's file; f0 of a given degree
on a drive with minor loops warned of (FitWarning) as the tool warns of it."""
import re
import subprocess
import warnings

import numpy as np
import pytest

import hyst

EDGE = 1e-6  # how far the records' correlation lies from -1/2
# rows added to the record for fit() only, before these indices: the drive
# missing, the response, both (the other the next row's)
MISSING = ((5, True, False), (300, False, True), (601, True, True))


def edge_record(r, n=900):
    """Triangles 0..10 and a response whose correlation with them is r:
    minus the drive plus a part orthogonal to it, scaled."""
    t = np.arange(n)
    x = 10.0 * np.abs((t + 50) % 100 - 50) / 50.0
    xc = x - x.mean()
    z = np.cos(0.37 * t)
    z -= z.mean()
    z -= (z @ xc) / (xc @ xc) * xc
    z *= np.linalg.norm(xc) / np.linalg.norm(z)
    return x, 5.0 - xc + np.sqrt(1.0 / (r * r) - 1.0) * z


def with_missing(x, y):
    """x, y with MISSING's rows inserted."""
    for at, no_x, no_y in reversed(MISSING):
        x = np.insert(x, at, np.nan if no_x else x[at])
        y = np.insert(y, at, np.nan if no_y else y[at])
    return x, y


def cli_fit(c_build, tmp_path, x, y, *args):
    path = tmp_path / "rec.txt"
    np.savetxt(path, np.column_stack([x, y]), fmt="%.17g")
    return subprocess.run([str(c_build["cli"]), "fit", *map(str, args), str(path)],
                          capture_output=True, text=True)


def py_fit(x, y, *args, **kwargs):
    """fit()'s error (its text, or None: f0 that does not increase raises
    HystError) and its FitWarnings."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            hyst.fit(x, y, *args, **kwargs)
            refusal = None
        except (ValueError, hyst.HystError) as e:
            refusal = str(e)
    return refusal, [str(w.message) for w in caught if issubclass(w.category, hyst.FitWarning)]


@pytest.mark.parametrize("side", [-1, 1])
@pytest.mark.parametrize("missing", [False, True])
def test_a_response_at_the_edge_is_refused_as_by_the_tool(c_build, tmp_path, side, missing):
    r = -0.5 + side * EDGE
    x, y = edge_record(r)
    assert abs(np.corrcoef(x, y)[0, 1] - r) < EDGE / 10
    cli = cli_fit(c_build, tmp_path, x, y, "--degree", 1, "--delay", 0, "--creep", "none")
    cli_refused = cli.returncode == 1 and "falls as the input (column 1) rises" in cli.stderr
    refusal, _ = py_fit(*(with_missing(x, y) if missing else (x, y)), 1, delay=0, creep="none")
    py_refused = refusal is not None and "y falls as x rises" in refusal
    assert cli_refused == py_refused == (r < -0.5), (cli.stderr, refusal)
    assert cli_refused or cli.returncode in (0, 2)  # fitted (f0 may not increase)


def test_a_column_constant_but_missing_samples_is_refused_as_by_the_tool(c_build, tmp_path):
    x, y = edge_record(-0.25)
    for column in (0, 1):
        rec = [x, y]
        rec[column] = np.full_like(x, 3.0)
        cli = cli_fit(c_build, tmp_path, *rec, "--degree", 1)
        assert cli.returncode == 1 and f"column {column + 1} is constant (3 on every" in cli.stderr
        refusal, _ = py_fit(*with_missing(*rec), 1)
        assert refusal is not None and f"{'xy'[column]} is constant (3 at every" in refusal


def drive(minor_loops):
    """Triangles 0..10, 0.1 a sample; with minor_loops the later ones
    turning at 7, 3 and 7 before 0."""
    up, down = np.linspace(0, 10, 101), np.linspace(10, 0, 101)[1:]
    inner = np.concatenate([np.linspace(0, 7, 71), np.linspace(7, 3, 41)[1:],
                            np.linspace(3, 7, 41)[1:], np.linspace(7, 0, 71)[1:]])
    loops = [up, down] * 3 + ([inner] * 3 if minor_loops else [up[1:], down] * 3)
    return np.concatenate(loops)


@pytest.mark.parametrize("minor_loops", [False, True])
def test_a_degree_on_minor_loops_is_warned_of_as_by_the_tool(c_build, tmp_path, minor_loops):
    x = drive(minor_loops)
    y = hyst.Model([0.05, 1.0, 0.0], 0, 10).process(x)
    cli = cli_fit(c_build, tmp_path, x, y, "--degree", 2, "--delay", 0, "--creep", "none")
    said = re.search(r"^hyst fit: warning: \S*rec\.txt: the drive has (\d+) reversals inside its "
                     r"range \(minor loops\): f0 of --degree 2 is biased", cli.stderr, re.M)
    refusal, warned = py_fit(x, y, 2, delay=0, creep="none")
    assert refusal is None and cli.returncode == 0
    ours = [re.match(r"x has (\d+) reversals inside its range \(minor loops\): f0 of degree 2 "
                     r"is biased.*leave degree=None to let fit choose, or fit method='branches' "
                     r"\(f0 along every branch\)$",
                     m) for m in warned]
    ours = [m for m in ours if m]
    assert (said is not None) == (len(ours) == 1) == minor_loops, (cli.stderr, warned)
    if minor_loops:  # three loops turning at 7, 3 and 7, inside 0..10
        assert int(said.group(1)) == int(ours[0].group(1)) == 9
    # another kind, or a poly fit on major loops only: no such warning
    assert not any("minor loops): f0" in m for m in py_fit(x, y, 2, kind="everett", delay=0,
                                                            creep="none")[1])


@pytest.mark.parametrize("minor_loops", [False, True])
def test_f0_chosen_alone_on_minor_loops_is_warned_of_as_by_the_tool(c_build, tmp_path,
                                                                    minor_loops):
    """kind="poly" without a degree chooses among f0 alone, each as biased
    on minor loops: warned of as ``hyst fit --kind tcm`` warns; the choice
    among every kind is not."""
    x = drive(minor_loops)
    y = hyst.Model([0.05, 1.0, 0.0], 0, 10).process(x)
    cli = cli_fit(c_build, tmp_path, x, y, "--kind", "tcm", "--creep", "none")
    said = re.search(r"^hyst fit: warning: \S*rec\.txt: the drive has (\d+) reversals inside its "
                     r"range \(minor loops\): f0 of every degree is biased.*leave out --kind tcm "
                     r"to let fit compare E too, or fit --method branches "
                     r"\(f0 along every branch\)$",
                     cli.stderr, re.M)
    refusal, warned = py_fit(x, y, kind="poly", creep="none")
    assert refusal is None and cli.returncode == 0
    ours = [re.match(r"x has (\d+) reversals inside its range \(minor loops\): f0 of every "
                     r"degree is biased.*leave kind=None to let fit compare E too, or fit "
                     r"method='branches' \(f0 along every branch\)$", m) for m in warned]
    ours = [m for m in ours if m]
    assert (said is not None) == (len(ours) == 1) == minor_loops, (cli.stderr, warned)
    if minor_loops:
        assert int(said.group(1)) == int(ours[0].group(1)) == 9
    assert not any("minor loops): f0" in m for m in py_fit(x, y, creep="none")[1])
