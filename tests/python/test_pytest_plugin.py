"""The pytest plugin (NC programs as test items) and the toolcomp.testing helpers."""
import math
import pathlib
import re
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
    (nc / "lathe" / "od.nc").write_text("G21 G18 G40 T0101 S800 M3\nG0 X50 Z2\nG42 G1 X40 Z0 F0.2\nZ-20\nG40 G0 X60 Z5\nM30\n")
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


def test_where_the_axes_start(tmp_path):
    # X travel -5..200 mm: an incremental first move of X-10 leaves it from machine zero (an
    # error), not from X100 (the folder's start) nor from X50 (a program's own header).
    (tmp_path / "pyproject.toml").write_text('[tool.toolcomp]\nprograms = "nc/"\nstart = "machine_zero"\n')
    nc = tmp_path / "nc"
    (nc / "from100").mkdir(parents=True)
    (nc / "m.toml").write_text('control = "linuxcnc"\nkind = "mill"\n[travel]\nx = [-5, 200]\ny = [-100, 100]\n'
                               'z = [-100, 100]\n')
    body = "(toolcomp: machine=m.toml%s)\nG21 G91 G0 X-10\nG90 G1 X20 F100\nM2\n"
    (nc / "from_zero.ngc").write_text(body % "")
    (nc / "from_header.ngc").write_text(body % " start=50,0,0")
    (nc / "from100" / "toolcomp.toml").write_text("start = [100, 0, 0]\n")
    (nc / "from100" / "p.ngc").write_text(body.replace("m.toml", "../m.toml") % "")
    r = run_pytest(tmp_path)
    assert "1 failed, 2 passed" in r.stdout, r.stdout
    assert "nc/from_zero.ngc:2:" in r.stdout


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
    # The entry move runs straight from (0, -10) to (-5, 0) and passes the contour's first
    # corner (0, 0) at 50 / sqrt(125) = 4.472136 mm, at (-4, -2): a 5 mm tool cuts
    # 0.527864 mm into it there.
    contour = [(0, 0), (30, 0), (30, 20), (0, 20)]
    with pytest.raises(AssertionError, match=r"comes 0\.527864 mm into the contour at \[-4\.0, -2\.0\] "
                                             r"\(move of line 3\)"):
        assert_no_gouge(res, contour, radius=5)
    # Without that corner the rest of the contour is 5 mm from the tool centre throughout.
    walls = [(30, 0), (30, 20), (0, 20)]
    assert_no_gouge(res, walls, radius=5)
    with pytest.raises(AssertionError, match=r"comes 1\.0+ mm into the contour at .* \(move of line 4\)"):
        assert_no_gouge(res, walls, radius=6)
    # A path computed for a smaller tool than the one in the spindle gouges.
    small = tc.run(tc.Program.parse(GOOD.replace("D10", "D8")))
    with pytest.raises(AssertionError):
        assert_no_gouge(small, walls, radius=5)


ARCS = """G21 G0 X-20 Y-20
G41.1 D8 G1 X0 Y0 F400
G1 X40
G2 X60 Y20 R20
G1 Y40
G3 X40 Y60 I-20 J0
G1 X10 Y50
G1 X0 Y0
G40 G0 X-20 Y-20
M2
"""
OUTLINE = "G21 G0 X-10 Y-10\nG42.1 D10 G1 X0 Y0 F600\nX60\nY40\nX0\nY0\nG40 G0 X-10 Y-10\nM2\n"


def test_assert_no_gouge_takes_corner_arcs_as_arcs():
    # G42 around the outside of a 60 x 40 rectangle: corner arcs of exactly the tool radius
    # about its corners (chords of them would come up to the chord tolerance closer).
    res = tc.run(tc.Program.parse(OUTLINE))
    rect = [(0, 0), (60, 0), (60, 40), (0, 40), (0, 0)]
    assert_no_gouge(res, rect, radius=5)
    assert_no_gouge(res, rect, radius=5.000001, tol=2e-6)
    # A larger tool: 0.5 mm into the bottom edge from the end of the entry move on.
    with pytest.raises(AssertionError, match=r"comes 0\.500000 mm into the contour at \[2\.071068, -5\.0\] "
                                             r"\(move of line 2\)"):
        assert_no_gouge(res, rect, radius=5.5)
    # A speck 5.2 mm from the corner (60, 0) at -45 degrees: 0.2 mm from the corner arc of
    # line 4, at its middle (60 + 5 cos 45, -5 sin 45).
    s45 = math.sqrt(0.5)
    speck = [(60 + 5.2 * s45, -5.2 * s45), (60 + 5.3 * s45, -5.3 * s45)]
    assert_no_gouge(res, speck, radius=0.2 - 1e-5)
    with pytest.raises(AssertionError, match=r"comes 0\.800000 mm into the contour at \[63\.535534, -3\.535534\] "
                                             r"\(move of line 4\)"):
        assert_no_gouge(res, speck, radius=1)


SPIKE_PASS = "G21 G0 X-20 Y5\nG41.1 D12 G1 X-10 Y5 F100\nG1 X10 Y5\nG40 G0 X20 Y20\nM2\n"


def test_assert_no_gouge_measures_between_the_end_points():
    # The tool centre runs along y = 11 from x = -10 to 10 (line 3); a spike of the contour
    # reaches (0, 6): 5 mm from the track's middle, over 11 mm from both its ends.
    res = tc.run(tc.Program.parse(SPIKE_PASS))
    with pytest.raises(AssertionError, match=r"comes 1\.000000 mm into the contour at \[0\.0, 11\.0\] "
                                             r"\(move of line 3\)"):
        assert_no_gouge(res, [(-1, 0), (0, 6), (1, 0)], radius=6)
    assert_no_gouge(res, [(-1, 0), (0, 4.99), (1, 0)], radius=6)  # 6.01 away
    # A contour edge crossing the track with both its ends far from it: the tool cuts through.
    with pytest.raises(AssertionError, match=r"comes 6\.000000 mm into the contour at \[2\.0, 11\.0\]"):
        assert_no_gouge(res, [(-8, -20), (12, 42)], radius=6)


def test_assert_no_gouge_agrees_with_shapely():
    # Random contours against a compensated contour of lines and arcs: the first move that
    # comes too close and how far, against shapely's distances between the contour and the
    # moves as chords within 1e-5 mm.
    shapely = pytest.importorskip("shapely")
    import numpy as np

    from toolcomp.testing import _chords

    res = tc.run(tc.Program.parse(ARCS))
    a, b, seg = _chords(res.path, 1e-5)  # within 1e-5 mm of the arcs
    feed = (res.path.side[seg] != 0) & (res.path.kind[seg] != tc.RAPID)
    rng = np.random.default_rng(7)
    lo, hi = res.path.end[:, :2].min(axis=0), res.path.end[:, :2].max(axis=0)
    reported = 0
    for _ in range(30):
        contour = rng.uniform(lo - 10, hi + 10, size=(int(rng.integers(2, 5)), 2))
        line = shapely.LineString(contour)
        moves = sorted(set(seg[feed].tolist()))
        dist = {i: min(shapely.distance(shapely.LineString([a[k], b[k]]), line)
                       for k in np.nonzero(feed & (seg == i))[0]) for i in moves}
        radius = float(rng.uniform(0.1, 4))
        gouging = [i for i in moves if dist[i] < radius - 1e-6]
        if not gouging:
            assert_no_gouge(res, contour, radius=radius)
            continue
        with pytest.raises(AssertionError) as e:
            assert_no_gouge(res, contour, radius=radius)
        i = gouging[0]
        m = re.match(r"the tool comes ([0-9.]+) mm into the contour at .* \(move of line (\d+)\)", str(e.value))
        assert int(m.group(2)) == res.path.line[i]
        assert abs(float(m.group(1)) - (radius - dist[i])) < 2e-5
        reported += 1
    assert 5 < reported < 30


def test_assert_paths_close_names_the_first_difference():
    a = tc.run(tc.Program.parse(GOOD)).path
    assert_paths_close(a, tc.run(tc.Program.parse(GOOD)).path)
    b = tc.run(tc.Program.parse(GOOD.replace("X30", "X30.001"))).path
    assert_paths_close(a, b, tol=2e-3)
    with pytest.raises(AssertionError, match=r"segment \d+ \(line 4\): end"):
        assert_paths_close(a, b, tol=1e-6)
