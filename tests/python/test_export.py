"""G-code export of compensated paths: re-run without compensation, the written program
reproduces the compensated path (shifted by the tool length offsets it folds in) to 1e-6 mm,
in each output dialect."""
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import toolcomp as tc
from toolcomp.export import to_gcode

ROOT = pathlib.Path(__file__).resolve().parents[2]
READ_AS = {"linuxcnc": "linuxcnc", "fanuc": "fanuc", "grbl": "linuxcnc"}


def rerun(path, dialect, **kw):
    text = to_gcode(path, dialect, **kw)
    assert "G41" not in text and "G42" not in text and "G43" not in text
    return text, tc.run(tc.Program.parse(text, dialect=READ_AS[dialect]), start="machine_zero").path


def same(p, q, shifted=True, lead=0):
    """q (the written program run again) is p; its first `lead` moves are the positioning the
    program adds to reach p's start."""
    off = p.tool_offset if shifted else 0
    assert len(q) == len(p) + lead
    np.testing.assert_allclose(q.start[lead:], p.start + off, atol=1e-6)
    np.testing.assert_allclose(q.end[lead:], p.end + off, atol=1e-6)
    arcs = p.kind >= tc.ARC_CW
    np.testing.assert_allclose(q.center[lead:][arcs], (p.center + off)[arcs], atol=1e-6)
    np.testing.assert_array_equal(q.kind[lead:], p.kind)
    np.testing.assert_allclose(q.feed[lead:], p.feed, atol=1e-6)  # NaN for rapids on both


CONTOUR = """G21 G0 X-20 Y-20 Z10
G43.1 Z30
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


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc", "grbl"])
def test_a_compensated_contour_re_runs_to_its_compensated_path(dialect):
    res = tc.run(tc.Program.parse(CONTOUR, dialect="linuxcnc"), start="machine_zero")
    p = res.path
    assert (p.side != 0).any() and p.generated.any() and (p.tool_offset[:, 2] == 30).any()
    _, q = rerun(p, dialect)
    same(p, q)


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc", "grbl"])
def test_the_pocket_with_two_tool_lengths_re_runs(dialect):
    res = tc.run(ROOT / "examples/pocket.ngc", tools=ROOT / "examples/tools.tbl", start="machine_zero")
    assert len(np.unique(res.path.tool_offset[:, 2])) > 1
    _, q = rerun(res.path, dialect)
    same(res.path, q)


HELIX = "G21 G17 G0 X10 Y0\nG1 Z0 F300\nG3 X10 Y0 Z-6 I-10 J0 P3 F200\nG18 G2 X20 Z-6 I5 K0\nG19 G3 Y5 Z-1 J0 K5\nM2\n"


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc", "grbl"])
def test_helices_and_planes(dialect):
    p = tc.run(tc.Program.parse(HELIX, dialect="linuxcnc"), start="machine_zero").path
    assert p.turns[2] == 2
    text, q = rerun(p, dialect)
    if dialect == "linuxcnc":
        assert "P3" in text
        same(p, q)
    else:
        # Without P the three turns are three blocks: two full circles of 2 mm each, then the last.
        assert "P3" not in text
        assert len(q) == len(p) + 2
        np.testing.assert_allclose(q.end[2:5, 2], [-2, -4, -6], atol=1e-6)
        np.testing.assert_allclose(q.end[5:], p.end[3:], atol=1e-6)
        np.testing.assert_allclose(q.end[2:5, :2], [[10, 0]] * 3, atol=1e-6)


def test_a_work_offset_change_is_refused_not_flattened():
    p = tc.run(tc.Program.parse("G21 G0 X1\nG10 L2 P2 X100\nG55 G0 X2\nM2\n", dialect="linuxcnc"), start="machine_zero").path
    with pytest.raises(ValueError, match="jumps before the move of line 3"):
        to_gcode(p)


def test_a_feed_move_of_unknown_rate_is_refused():
    # G96 at X0 without a speed limit: the spindle speed, and so the feed, has no value
    text = "G18 G21 G0 X10 Z0\nS100 M3\nG95 G96 S100 F0.1\nG1 X0\nG1 Z-5\nM2\n"
    p = tc.run(tc.Program.parse(text, dialect="linuxcnc"), start="machine_zero").path
    assert math.isnan(p.feed[-1])
    with pytest.raises(ValueError, match="the move of line 4 has no known feed rate"):
        to_gcode(p)


def test_an_arc_of_very_many_turns_is_written_with_p_only():
    # The most turns a run takes (P1000000: 999999 extra turns, as the Sinumerik's TURN).
    p = tc.run(tc.Program.parse("G21 G0 X0 Y0 Z0\nG2 X0 Y0 I1 Z-1 P1000000 F100\nM2\n",
                                dialect="linuxcnc"), start="machine_zero").path
    assert to_gcode(p, comments=False).splitlines()[-2].endswith("P1000000 F100")


def test_tool_length_offsets_are_folded_in_or_the_jump_is_refused():
    res = tc.run(tc.Program.parse("G21 G0 Z10\nG43.1 Z25\nG0 X5 Z10\nG1 X10 F100\nM2\n", dialect="linuxcnc"), start="machine_zero")
    # G43.1 Z25 at Z10: the point is Z-15 in program coordinates, Z10 with the offset.
    shifted = to_gcode(res.path, comments=False).splitlines()
    assert shifted[1:4] == ["G0 X0 Z10", "G0 X5 Z35", "G1 X10 F100"]
    with pytest.raises(ValueError, match="jumps before the move of line 3"):
        to_gcode(res.path, tool_length=False)


def test_cli_export_writes_a_file_and_refuses_a_program_with_errors(tmp_path):
    out = tmp_path / "pocket_grbl.nc"
    r = subprocess.run([sys.executable, "-m", "toolcomp", "export", str(ROOT / "examples/pocket.ngc"),
                        "--tools", str(ROOT / "examples/tools.tbl"), "--to", "grbl", "-o", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    # The path starts at the program's first position; the written program goes there first.
    res = tc.run(ROOT / "examples/pocket.ngc", tools=ROOT / "examples/tools.tbl")
    assert res.path.start[0].tolist() == [31, 31, 50]  # the first Z50 (G43 H1 Z50), then G0 X31 Y31
    same(res.path, tc.run(tc.Program.parse(out.read_text(), dialect="linuxcnc"), start="machine_zero").path, lead=1)
    bad = tmp_path / "gouge.ngc"
    bad.write_text("G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY2\nX31\nY0\nX60\nG40 G0 X70 Y-10\nM2\n")
    r = subprocess.run([sys.executable, "-m", "toolcomp", "export", str(bad)], capture_output=True, text=True)
    assert r.returncode == 1 and ":5:" in r.stderr or ":6:" in r.stderr
    assert r.stdout == ""
