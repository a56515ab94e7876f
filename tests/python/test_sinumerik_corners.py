"""840D contour corners programmed in the block before the corner: RND= a rounding arc tangent
to both moves, CHF= a chamfer of that length, CHR= a chamfer with legs of that length (the
840D programming manual's definitions), worked by hand."""
import math

import numpy as np
import pytest

import toolcomp as tc


def run(text, **kw):
    return tc.run(tc.Program.parse(text, "sinumerik"), **kw)


def segs(path):
    return [(int(k), tuple(np.round(s, 4)), tuple(np.round(e, 4)),
             None if k in (tc.RAPID, tc.LINE) else tuple(np.round(c, 4)))
            for k, s, e, c in zip(path.kind, path.start, path.end, path.center)]


L_, CCW, CW = tc.LINE, tc.ARC_CCW, tc.ARC_CW


def test_rounding_and_both_chamfers_on_a_square():
    # Corner (10, 0), a left turn: RND=2 is the arc from (8, 0) to (10, 2) about (8, 2). Corner
    # (10, 10): CHR=1 cuts 1 off each leg. Corner (0, 10): CHF=sqrt(2) is a chamfer sqrt(2)
    # long, its legs sqrt(2) / (2 cos 45 deg) = 1.
    res = run("G0 X0 Y0\nG1 X10 Y0 F100 RND=2\nG1 Y10 CHR=1\nG1 X0 CHF=1.41421356237\nG1 Y0\nM30\n")
    assert segs(res.nominal)[1:] == [
        (L_, (0, 0, 0), (8, 0, 0), None), (CCW, (8, 0, 0), (10, 2, 0), (8, 2, 0)),
        (L_, (10, 2, 0), (10, 9, 0), None), (L_, (10, 9, 0), (9, 10, 0), None),
        (L_, (9, 10, 0), (1, 10, 0), None), (L_, (1, 10, 0), (0, 9, 0), None), (L_, (0, 9, 0), (0, 0, 0), None)]
    assert list(res.nominal.line) == [1, 2, 2, 3, 3, 4, 4, 5]


def test_a_rounding_between_a_circle_and_a_line_and_a_chamfer_at_an_obtuse_corner():
    # G3 from (10, 0) to (0, 10), CR=10: the quarter about (0, 0); then up the line X0. At
    # (0, 10) the path turns right (from -X to +Y): RND=2 lies on the right, outside the circle.
    # Its centre is 2 from the line (X = 2) and 12 from (0, 0): (2, sqrt(140)); it touches the
    # line at (0, sqrt(140)) and the circle at 10/12 of its centre.
    res = run("G0 X10 Y0\nG3 X0 Y10 CR=10 F100 RND=2\nG1 X0 Y20\nM30\n")
    c = math.sqrt(140)
    t1 = (round(2 * 10 / 12, 4), round(c * 10 / 12, 4), 0)
    assert segs(res.nominal)[1:] == [(CCW, (10, 0, 0), t1, (0, 0, 0)), (CW, t1, (0, round(c, 4), 0), (2, round(c, 4), 0)),
                                     (L_, (0, round(c, 4), 0), (0, 20, 0), None)]


def test_a_chamfer_at_an_obtuse_corner():
    # CHF at a 135 deg corner (turn 45 deg): legs = 2 / (2 cos 22.5 deg)
    res = run("G0 X0 Y0\nG1 X10 Y0 F100 CHF=2\nG1 X20 Y10\nM30\n")
    legs = 1 / math.cos(math.radians(22.5))
    chamfer = segs(res.nominal)[2]
    np.testing.assert_allclose(chamfer[1], (10 - legs, 0, 0), atol=1e-4)
    np.testing.assert_allclose(chamfer[2], (10 + legs / math.sqrt(2), legs / math.sqrt(2), 0), atol=1e-4)
    assert math.dist(chamfer[1], chamfer[2]) == pytest.approx(2, abs=1e-4)


def test_corners_in_inches_and_with_radius_compensation():
    # G70: RND=0.1 in = 2.54 mm.
    res = run("G70 G0 X0 Y0\nG1 X1 Y0 F10 RND=0.1\nG1 Y1\nM30\n")
    arc = segs(res.nominal)[2]
    assert arc[0] == CCW and arc[3] == (round(25.4 - 2.54, 4), 2.54, 0)
    # G41 (radius 1) outside a square's corner rounded with RND=2: the compensated corner is the
    # rounding arc offset outward, radius 3, about the same centre (8, 2).
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=1.0, length=[0.0, 0.0, 0.0])]))
    res = run("T1 M6 D1\nG0 X-5 Y-5\nG42 G1 X0 Y0 F100\nG1 X10 RND=2\nG1 Y10\nG40 G1 X15 Y15\nM30\n", tools=t)
    arcs = [s for s in segs(res.path) if s[0] == CCW]
    assert arcs and arcs[0][3] == (8, 2, 0)
    assert math.dist(arcs[0][1][:2], (8, 2)) == pytest.approx(3, abs=1e-9)


@pytest.mark.parametrize("text, code", [
    ("G1 X10 F100 RND=20\nG1 Y1\n", "rounding_too_large"),
    ("G1 X10 F100 RND=1\nG0 Y10\n", "corner_next_to_rapid"),
    ("G1 X10 F100 RND=1\nM30\n", "corner_without_element"),
    ("G1 X10 F100 CHF=1\nG2 X20 Y0 CR=5\n", "chamfer_next_to_arc"),
    ("G1 X10 F100 CHR=20\nG1 Y1\n", "chamfer_not_permitted"),
    ("G1 X10 F100 CHF=1 RND=1\nG1 Y1\n", "12190"),
    ("F100 RND=1\nG1 X10\n", "corner_without_element"),
    ("G1 X10 F100 RNDM=1\nG1 Y1\n", "unsupported_word"),
])
def test_corner_errors(text, code):
    with pytest.raises(tc.ProgramError) as e:
        run("G0 X0 Y0\n" + text + "M30\n")
    assert e.value.code == code
    assert e.value.line == 2  # the block the corner is programmed in


def test_an_error_after_a_held_corner_is_the_error_and_the_path_keeps_the_move():
    res = run("G0 X0 Y0\nG1 X10 F100 RND=1\nG1 Y10 F0\nM30\n", strict=False)
    assert [d.code for d in res.diagnostics] == ["10860"]
    assert segs(res.nominal)[-1] == (L_, (0, 0, 0), (10, 0, 0), None)
