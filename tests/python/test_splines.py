"""LinuxCNC's G5, G5.1 and G5.2/G5.3 as its machine cuts them: biarcs, 4 spans of 2 arcs per
control point. The numbers below are the ARC_FEED calls of LinuxCNC 2.9's own NURBS code
(nurbs_additional_functions.cc and emccanon.cc's NURBS_FEED, biarc, arc, compiled unmodified
and fed the same control points; printed with 6 decimals). The curve's points are also
compared with LinuxCNC's gcode module in tests/programs/oracle/splines_g5_nurbs.ngc, the
errors in tests/programs/errors/spline_*.ngc and nurbs_*.ngc."""
import numpy as np
import pytest

import toolcomp as tc


def _run(text, **kw):
    return tc.run(tc.Program.parse(text), **kw)


def _arcs(res, line):
    n = res.nominal
    rows = np.flatnonzero(n.line == line)
    return [(n.end[i][0], n.end[i][1], n.center[i][0], n.center[i][1], 1 if n.kind[i] == 3 else -1) for i in rows]


# G5 I0 J3 P0 Q-3 X1 Y1 from (0, 0): the first arcs of LinuxCNC's machine
G5_FIRST = [(0.002262, 0.236423, 12.359523, -0.000041, -1), (0.011230, 0.472656, 6.284819, 0.116202, -1),
            (0.022611, 0.627472, 4.674253, 0.207712, -1), (0.042969, 0.781250, 1.878902, 0.459962, -1)]
# G5.1 X2 I2 J-8 from (-2, 4)
G51_FIRST = [(-1.840430, 3.386938, 29.835905, 11.959056, 1), (-1.666667, 2.777778, 20.664526, 9.477136, 1),
             (-1.508406, 2.274944, 17.081476, 8.402221, 1), (-1.333333, 1.777778, 10.889235, 6.361241, 1)]
# the manual's NURBS: G5.2 P1 L3, X0 Y1 P1, X2 Y2 P1, X2 Y0 P1, X0 Y0 P2, G5.3 from (0, 0)
NURBS_FIRST = [(0.005446, 0.144843, 1.929209, -0.000010, -1), (0.022500, 0.288750, 1.693945, 0.017705, -1),
               (0.050307, 0.423393, 1.604770, 0.032166, -1), (0.090000, 0.555000, 1.488335, 0.061470, -1)]


@pytest.mark.parametrize("text, line, want, count", [
    ("G21 G17 F100\nG0 X0 Y0\nG5 I0 J3 P0 Q-3 X1 Y1\nM2\n", 3, G5_FIRST, 32),
    ("G21 G17 F100\nG0 X-2 Y4\nG5.1 X2 I2 J-8\nM2\n", 3, G51_FIRST, 24),
    ("G21 G17 F10\nG0 X0 Y0\nG5.2 P1 L3\nX0 Y1 P1\nX2 Y2 P1\nX2 Y0 P1\nX0 Y0 P2\nG5.3\nM2\n", 8, NURBS_FIRST, 40),
])
def test_the_arcs_are_linuxcnc_machine_s(text, line, want, count):
    arcs = _arcs(_run(text), line)
    assert len(arcs) == count  # 4 spans of 2 arcs per control point
    for got, ref in zip(arcs, want):
        assert got[4] == ref[4]
        assert got[:4] == pytest.approx(ref[:4], abs=5e-7)  # the reference has 6 decimals


def test_g5_leaves_the_motion_mode_and_goes_on_tangent():
    # without I J the second G5 starts with the first's -P -Q; a bare X Y after them is G1's
    res = _run("G21 G17 F100\nG0 X0 Y0\nG1 X0\nG5 I0 J3 P0 Q-3 X1 Y1\nG5 P0 Q-3 X2 Y2\nX3 Y2\nM2\n")
    n = res.nominal
    assert n.end[-1].tolist() == [3, 2, 0] and n.kind[-1] == 1
    # tangent at the joint: the last arc of the first curve and the first of the second meet
    first, second = np.flatnonzero(n.line == 4), np.flatnonzero(n.line == 5)
    assert n.end[first[-1]].tolist() == pytest.approx([1, 1, 0], abs=1e-12)
    assert len(second) == 32


def test_g5_3_leaves_no_motion_mode():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G17 F10\nG0 X0 Y0\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3\nX3 Y0\nM2\n")
    assert str(e.value.message) == "Cannot use axis values without a g code that uses them"


def test_what_toolcomp_refuses_rather_than_cut_wrong():
    with pytest.raises(tc.ProgramError) as e:  # collinear control points: LinuxCNC's biarcs give NaN
        _run("G21 G17 F100\nG0 X4 Y0\nG5.1 X6 Y0 I1 J0\nM2\n")
    assert e.value.code == "spline_degenerate"
    with pytest.raises(tc.ProgramError) as e:  # LinuxCNC 2.9 weighs it -1, its manual says 1
        _run("G21 G17 F10\nG0 X0 Y0\nG5.2 X1 Y1\nX2 Y0 P1\nG5.3\nM2\n")
    assert e.value.code == "spline_words" and "weight P" in str(e.value)


def test_other_controls_have_no_splines():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G17 F100\nG5.1 X2 I1 J1\nM30\n", "fanuc"))
    assert e.value.code == "unsupported_g_code"
