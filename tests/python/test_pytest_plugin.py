"""The pytest plugin (NC programs as test items) and the toolcomp.testing helpers."""
import pathlib
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import toolcomp as tc
from toolcomp.testing import assert_no_errors, assert_no_gouge, assert_paths_close, assert_within

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOOD = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY20\nX0\nG40 G0 X-10 Y30\nM2\n"
# A 2 mm wide slot under a 10 mm cutter: LinuxCNC's gouge error at line 6.
GOUGE = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY2\nX31\nY0\nX60\nG40 G0 X70 Y-10\nM2\n"


def run_pytest(root, *args):
    return subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--color=no", *args],
                          cwd=root, capture_output=True, text=True)


def test_programs_in_the_configured_folder_are_tests(tmp_path):
    (tmp_path / "pyproject.toml").write_text('[tool.toolcomp]\nprograms = "nc/"\n')
    nc = tmp_path / "nc"
    (nc / "lathe").mkdir(parents=True)
    (nc / "good.ngc").write_text(GOOD)
    (nc / "gouge.ngc").write_text(GOUGE)
    (nc / "notes.txt").write_text("not a program")
    (tmp_path / "other.ngc").write_text(GOUGE)  # outside the folder: not collected
    # Per-folder settings: a Fanuc lathe with its offset table.
    (nc / "lathe" / "toolcomp.toml").write_text('dialect = "fanuc"\nmachine = "lathe"\ntools = "offsets.csv"\n')
    (nc / "lathe" / "offsets.csv").write_text("offset,x,z,nose_radius,tip\n1,0,0,0.8,3\n")
    (nc / "lathe" / "od.nc").write_text("G21 G18 G40 T0101\nG0 X50 Z2\nG42 G1 X40 Z0 F0.2\nZ-20\nG40 G0 X60 Z5\nM30\n")
    r = run_pytest(tmp_path)
    assert "1 failed, 2 passed" in r.stdout, r.stdout
    assert "nc/gouge.ngc:6:0: error" in r.stdout


def test_a_header_line_overrides_the_folder(tmp_path):
    (tmp_path / "pyproject.toml").write_text('[tool.toolcomp]\nprograms = "nc/"\nfail_on_warnings = true\n')
    nc = tmp_path / "nc"
    nc.mkdir()
    # T1 without a tool table warns; the header gives the table, so the warning goes away.
    (nc / "tools.tbl").write_text("T1 P1 D10 Z50\n")
    body = "G21 T1 M6\nG43 H1\nG0 X0 Y0 Z10\nM2\n"
    (nc / "with_table.ngc").write_text("(toolcomp: tools=tools.tbl)\n" + body)
    (nc / "without_table.ngc").write_text(body)
    r = run_pytest(tmp_path)
    assert "1 failed, 1 passed" in r.stdout, r.stdout
    assert "without_table.ngc:" in r.stdout and "warning" in r.stdout


def test_no_configuration_no_items(tmp_path):
    (tmp_path / "a.ngc").write_text(GOUGE)
    r = run_pytest(tmp_path)
    assert r.returncode == 5, r.stdout  # pytest: no tests collected


def test_assert_no_errors_and_within():
    res = tc.run(tc.Program.parse(GOOD))
    assert_no_errors(res)
    # G41 runs inside the 30 x 20 box: x up to 30 - 5 = 25 (line 4); the rapids span
    # x -10..0 and y -10..30; the entry arc about (0,0) reaches x = -5.
    assert_within(res.path, ((-10, -10, 0), (25, 30, 0)))
    with pytest.raises(AssertionError, match="line 4"):
        assert_within(res.path, ((-10, -10, 0), (24.9, 30, 0)))
    bad = tc.run(tc.Program.parse(GOUGE), strict=False)
    with pytest.raises(AssertionError, match="line 6:0: error"):
        assert_no_errors(bad)


def test_assert_no_gouge_against_the_contour():
    res = tc.run(tc.Program.parse(GOOD))
    contour = [(0, 0), (30, 0), (30, 20), (0, 20)]
    assert_no_gouge(res, contour, radius=5)
    with pytest.raises(AssertionError, match=r"comes 1\.0+ mm into the contour"):
        assert_no_gouge(res, contour, radius=6)
    # A path computed for a smaller tool than the one in the spindle gouges.
    small = tc.run(tc.Program.parse(GOOD.replace("D10", "D8")))
    with pytest.raises(AssertionError):
        assert_no_gouge(small, contour, radius=5)


def test_assert_paths_close_names_the_first_difference():
    a = tc.run(tc.Program.parse(GOOD)).path
    assert_paths_close(a, tc.run(tc.Program.parse(GOOD)).path)
    b = tc.run(tc.Program.parse(GOOD.replace("X30", "X30.001"))).path
    assert_paths_close(a, b, tol=2e-3)
    with pytest.raises(AssertionError, match=r"segment \d+ \(line 4\): end"):
        assert_paths_close(a, b, tol=1e-6)
