"""Fanuc/Haas G71 / G72 type II: a contour with pockets (its X goes back and forth, its Z
never turns back). Every move below is worked by hand in the frame of the cut: U along the
cut from the start point, V the depth from the start point's X (radius), so a program's
point is Z = z_A - U, X = 2 (x_A - V) (a diameter) for an OD contour roughed towards the chuck.

Each level V = k * depth cuts where the boundary (the P block's line from the start point,
then the contour) lies deeper; a pass goes down the wall, cuts, follows the contour up to the
level before, retracts by R, and returns over the pass's start; a pocket split off by a hump
is roughed after the first, from the top of the hump; then the pass along the contour.
"""
import numpy as np
import pytest

import toolcomp as tc

# Start A: X50 Z2 (radius 25). The contour, in (U, V): (0, 10) (12, 10) (17, 5) (22, 5)
# (27, 13) (37, 13) (42, 0) (43, 0): a first pocket down to V 10, a hump up to V 5, a second pocket
# down to V 13, then up to the start's X.
POCKETS = """\
G21 G18 G40
T0101
G97 S1000 M3
G98
G0 X50 Z2
G71 U2 R0.5
G71 P10 Q20 F200
N10 G0 X30 Z2
G1 Z-10
X40 Z-15
Z-20
X24 Z-25
Z-35
X50 Z-40
N20 Z-41
M30
"""


def _lathe(text, **kw):
    return tc.run(tc.Program.parse(text, dialect="fanuc"), machine="lathe", **kw)


def _uv(res, line):
    sel = res.nominal.line == line
    end = res.nominal.end[sel]
    return np.column_stack([2 - end[:, 2], 25 - end[:, 0]]), res.nominal.kind[sel]


def test_g71_type2_roughs_pocket_by_pocket():
    res = _lathe(POCKETS)
    assert res.ok, res.diagnostics
    got, kind = _uv(res, 7)
    r, f = tc.RAPID, tc.LINE
    # The U where the walls meet the levels: the P block's line at U 0; the hump's near wall
    # (12, 10) -> (17, 5): U = 12 + (10 - V); its far wall (22, 5) -> (27, 13):
    # U = 22 + (V - 5) * 5 / 8; the last wall (37, 13) -> (42, 0): U = 37 + (13 - V) * 5 / 13.
    near = lambda v: 12 + (10 - v)
    far = lambda v: 22 + (v - 5) * 5 / 8
    last = lambda v: 37 + (13 - v) * 5 / 13
    expected = [
        # level 2: one span, to the last wall; up it to the start's X; out by R; back
        ((0, 2), r), ((last(2), 2), f), ((42, 0), f), ((42, -0.5), r), ((0, -0.5), r),
        # level 4
        ((0, 2), r), ((0, 4), r), ((last(4), 4), f), ((last(2), 2), f), ((last(2), 1.5), r), ((0, 1.5), r),
        # level 6: the hump splits it; the first pocket: cut to the near wall, follow it over the
        # hump's top to where the far wall dives
        ((0, 4), r), ((0, 6), r), ((near(6), 6), f), ((17, 5), f), ((22, 5), f), ((22, 4.5), r), ((0, 4.5), r),
        # level 8 of the first pocket, up the near wall to level 6 (level 10 is its bottom)
        ((0, 6), r), ((0, 8), r), ((near(8), 8), f), ((near(6), 6), f), ((near(6), 5.5), r), ((0, 5.5), r),
        # the second pocket: up to level 4 less R, over to the hump's top, down to it
        ((0, 3.5), r), ((22, 3.5), r), ((22, 5), f),
        # its levels 6, 8, 10, 12: down the far wall, cut, up the last wall, out, back
        ((far(6), 6), f), ((last(6), 6), f), ((last(4), 4), f), ((last(4), 3.5), r), ((far(6), 3.5), r),
        ((far(6), 6), f), ((far(8), 8), f), ((last(8), 8), f), ((last(6), 6), f), ((last(6), 5.5), r), ((far(8), 5.5), r),
        ((far(8), 8), f), ((far(10), 10), f), ((last(10), 10), f), ((last(8), 8), f), ((last(8), 7.5), r), ((far(10), 7.5), r),
        ((far(10), 10), f), ((far(12), 12), f), ((last(12), 12), f), ((last(10), 10), f), ((last(10), 9.5), r), ((far(12), 9.5), r),
        # the contour pass: out of the pocket, to A, along the whole contour, back to A
        ((far(12), 0), r), ((0, 0), r), ((0, 10), r),
    ]
    contour = [((12, 10), f), ((17, 5), f), ((22, 5), f), ((27, 13), f), ((37, 13), f), ((42, 0), f), ((43, 0), f), ((0, 0), r)]
    n = len(expected)
    assert len(got) == n + len(contour)
    np.testing.assert_allclose(got[:n], [p for p, _ in expected], atol=1e-9)
    assert list(kind[:n]) == [k for _, k in expected]
    np.testing.assert_allclose(got[n:], [p for p, _ in contour], atol=1e-9)
    assert list(kind[n:]) == [k for _, k in contour]


# G72 (facing): the passes run along X, the levels step in Z. Start A: X80 Z2; U = 40 - X/2,
# V = 2 - Z. The contour in (U, V): (0, 8) (10, 8) (15, 4) (20, 4) (25, 10) (30, 10) (35, 0):
# a face groove beyond a land exactly at level 4.
FACE = """\
G21 G18 G40
T0101
G97 S1000 M3
G98
G0 X80 Z2
G72 W2 R0.5
G72 P10 Q20 F200
N10 G0 X80 Z-6
G1 X60
X50 Z-2
X40
X30 Z-8
X20
N20 X10 Z2
M30
"""


def test_g72_type2_faces_a_groove_beyond_a_land_on_a_level():
    res = _lathe(FACE)
    assert res.ok, res.diagnostics
    sel = res.nominal.line == 7
    end = res.nominal.end[sel]
    got = np.column_stack([40 - end[:, 0], 2 - end[:, 2]])
    kind = res.nominal.kind[sel]
    r, f = tc.RAPID, tc.LINE
    near = lambda v: 10 + (8 - v) * 5 / 4   # (10, 8) -> (15, 4)
    far = lambda v: 20 + (v - 4) * 5 / 6    # (20, 4) -> (25, 10)
    last = lambda v: 30 + (10 - v) / 2      # (30, 10) -> (35, 0)
    expected = [
        ((0, 2), r), ((last(2), 2), f), ((35, 0), f), ((35, -0.5), r), ((0, -0.5), r),
        # level 4 lies on the land: the first span ends at the land, the cut's climb runs along it
        ((0, 2), r), ((0, 4), r), ((15, 4), f), ((20, 4), f), ((20, 3.5), r), ((0, 3.5), r),
        ((0, 4), r), ((0, 6), r), ((near(6), 6), f), ((15, 4), f), ((15, 3.5), r), ((0, 3.5), r),
        # the groove, from the land's far end (level 2 less R above it)
        ((0, 1.5), r), ((20, 1.5), r), ((20, 4), f),
        ((last(4), 4), f), ((last(2), 2), f), ((last(2), 1.5), r), ((20, 1.5), r),
        ((20, 4), f), ((far(6), 6), f), ((last(6), 6), f), ((last(4), 4), f), ((last(4), 3.5), r), ((far(6), 3.5), r),
        ((far(6), 6), f), ((far(8), 8), f), ((last(8), 8), f), ((last(6), 6), f), ((last(6), 5.5), r), ((far(8), 5.5), r),
        ((far(8), 0), r), ((0, 0), r), ((0, 8), r),
        ((10, 8), f), ((15, 4), f), ((20, 4), f), ((25, 10), f), ((30, 10), f), ((35, 0), f), ((0, 0), r),
    ]
    assert len(got) == len(expected)
    np.testing.assert_allclose(got, [p for p, _ in expected], atol=1e-9)
    assert list(kind) == [k for _, k in expected]


def _g71(contour, cycle="G71 P10 Q20 F200", start="G0 X50 Z2"):
    return f"G21 G18 G40\nT0101\nG97 S1000 M3\nG98\n{start}\nG71 U2 R0.5\n{cycle}\n{contour}\nM30\n"


def test_type2_refuses_a_contour_turning_back_along_the_cut():
    with pytest.raises(tc.ProgramError) as e:
        _lathe(_g71("N10 G0 X30 Z2\nG1 Z-10\nX40 Z-5\nN20 X50"))
    assert (e.value.code, e.value.line) == ("cycle_not_monotonic", 10)


def test_r1_selects_type2_and_other_r_values_are_refused():
    # With R1 the P block X alone reads as type II: the contour's pocket is roughed (a type I
    # reading would refuse the contour going deeper again).
    pocket = "N10 G0 X30\nG1 Z-10\nX40 Z-15\nX24 Z-25\nN20 X50 Z-30"
    with pytest.raises(tc.ProgramError) as e:
        _lathe(_g71(pocket))
    assert e.value.code == "cycle_not_monotonic"
    res = _lathe(_g71(pocket, "G71 P10 Q20 R1 F200"))
    assert res.ok, res.diagnostics
    # The deepest level cut is 12 below the start's X (radius 25 - 12 = 13): the pocket's bottom
    # lies at radius 12, less than one depth below it.
    cuts = res.nominal.end[(res.nominal.line == 7) & (res.nominal.kind == tc.LINE)]
    assert cuts[:, 0].min() == pytest.approx(12)
    levels = sorted({round(x, 9) for x in cuts[:, 0] if round(x, 9) in {23, 21, 19, 17, 15, 13}})
    assert levels == [13, 15, 17, 19, 21, 23]
    with pytest.raises(tc.ProgramError) as e:
        _lathe(_g71(pocket, "G71 P10 Q20 R2 F200"))
    assert (e.value.code, e.value.line, e.value.column) == ("cycle_bad_value", 7, 13)


def test_haas_rough_allowances_are_left_by_the_levels_and_taken_by_the_contour_pass():
    # Type I, OD: contour X20 (radius 10) from Z2 to Z-20, then X50. I0.5 (radius) and K0.2
    # leave the levels short of radius 10.5 and Z -19.8; the contour pass runs on the contour
    # itself (no U, W).
    res = _lathe(_g71("N10 G0 X20\nG1 Z-20\nN20 X50", "G71 P10 Q20 D3 I0.5 K0.2 F200", "G0 X50 Z2"))
    assert res.ok, res.diagnostics
    sel = res.nominal.line == 7
    xz = res.nominal.end[sel][:, [0, 2]]
    kind = res.nominal.kind[sel]
    cuts = xz[kind == tc.LINE]
    # Levels 22, 19, 16, 13 (radius; 10.5 + 3 > 13 > 10.5): each cut ends at the shoulder Z -19.8.
    np.testing.assert_allclose(cuts[:4], [(22, -19.8), (19, -19.8), (16, -19.8), (13, -19.8)], atol=1e-9)
    # Then the contour pass: to radius 10 at Z2 (rapid, the P block is G00), Z-20, X50.
    np.testing.assert_allclose(xz[-4:], [(10, 2), (10, -20), (25, -20), (25, 2)], atol=1e-9)


@pytest.mark.parametrize("machine, nose", [("haas-lathe", 0.8), ("lathe", 0.0)])
def test_g42_in_the_contour_adds_the_nose_radius_to_the_roughing_allowance_on_haas(machine, nose):
    # Nose radius 0.8, tip 3 (Fanuc/Haas numbering: the imaginary tip at -X -Z of the nose's
    # centre). Haas: the passes leave 0.8 more in X (radius) and Z; Fanuc: the contour as programmed.
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=0.8, orientation=3)]))
    text = _g71("N10 G0 G42 X20\nG1 Z-20\nN20 G40 X50", "G71 P10 Q20 D3 F200")
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), machine=machine, tools=tools)
    assert res.ok, res.diagnostics
    sel = res.nominal.line == 7
    xz = res.nominal.end[sel][:, [0, 2]]
    cuts = xz[res.nominal.kind[sel] == tc.LINE]
    # Levels 22, 19, 16, 13 (radius), short of 10 + nose; each cut to Z -20 + nose.
    np.testing.assert_allclose(cuts[:4], [(22, -20 + nose), (19, -20 + nose), (16, -20 + nose), (13, -20 + nose)],
                               atol=1e-9)
    # The contour pass on the contour shifted by the nose radius in X and Z.
    np.testing.assert_allclose(xz[-4:], [(10 + nose, 2 + nose), (10 + nose, -20 + nose), (25 + nose, -20 + nose),
                                         (25, 2)], atol=1e-9)


def test_type2_passes_never_enter_the_part_on_random_contours():
    """Independent check with Shapely: on random pocketed contours, no move of the cycle
    (cuts, climbs, rapids) passes inside the part (the region between the contour and the
    axis), and every level's cut ends on the contour."""
    shapely = pytest.importorskip("shapely")
    from shapely.geometry import LineString, Polygon

    rng = np.random.default_rng(7)
    for trial in range(40):
        n = rng.integers(3, 8)
        zs = np.round(np.cumsum(rng.uniform(2, 8, n)) * -1, 3)
        xs = np.round(rng.uniform(4, 20, n), 3)  # radius, as written (the diameter to 0.001)
        x0 = round(rng.uniform(4, 20), 3)
        lines = [f"N10 G0 X{2 * x0:.3f} Z0"] + [f"G1 X{2 * x:.3f} Z{z:.3f}" for x, z in zip(xs, zs)]
        lines.append(f"N20 X50 Z{zs[-1] - 1:.3f}")
        text = _g71("\n".join(lines), f"G71 P10 Q20 D{rng.uniform(0.5, 3):.2f} F200", "G0 X50 Z2")
        res = _lathe(text.replace("G71 U2 R0.5", f"G71 U2 R{rng.uniform(0, 1):.2f}"))
        assert res.ok, (text, res.diagnostics)
        pts = [(0.0, x0)] + list(zip(zs, xs)) + [(zs[-1] - 1, 25.0)]
        part = Polygon(pts + [(pts[-1][0], 0.0), (0.0, 0.0)]).buffer(-1e-6)
        sel = res.nominal.line == 7
        start = res.nominal.start[sel][:, [2, 0]]
        end = res.nominal.end[sel][:, [2, 0]]
        assert np.all(np.isfinite(end))
        for a, b in zip(start, end):
            assert not LineString([a, b]).intersects(part), (trial, a, b, text)


def test_type2_pocket_on_an_arc():
    # A half-circle groove (G2 from Z-5 to Z-15 at X30, R5: centre Z-10 X30, its bottom at
    # radius 10) after a land at radius 15; depth 3. Levels (radius) 22, 19, 16 run to the last
    # wall (X30 Z-20 -> X50 Z-22: Z = -20 - (x - 15) / 5); level 13 lies below the land: it
    # comes down the P block's line and the land and along the arc to where it meets the level,
    # Z = -10 + sqrt(5^2 - 2^2), cuts to Z = -10 - sqrt(21), follows the arc, the land and the
    # wall up to level 16. Level 10 is the groove's bottom: the contour pass takes it.
    text = _g71("N10 G0 X30 Z2\nG1 Z-5\nG2 X30 Z-15 R5\nG1 Z-20\nN20 X50 Z-22", "G71 P10 Q20 F200")
    res = _lathe(text.replace("G71 U2", "G71 U3"))
    assert res.ok, res.diagnostics
    sel = res.nominal.line == 7
    zx = res.nominal.end[sel][:, [2, 0]]
    kind = res.nominal.kind[sel]
    wall = lambda x: -20 - (x - 15) / 5
    h = np.sqrt(21)
    r, f = tc.RAPID, tc.LINE
    level13 = [((2, 16), r), ((2, 15), r), ((-5, 15), f), ((-10 + h, 13), None), ((-10 - h, 13), f),
               ((-15, 15), None), ((-20, 15), f), ((wall(16), 16), f), ((wall(16), 16.5), r), ((-10 + h, 16.5), r)]
    i = 17  # after the passes at 22 (5 moves: down, cut, climb, out, back) and 19, 16 (6: two down)
    np.testing.assert_allclose(zx[i - 5:i], [(2, 16), (wall(16), 16), (wall(19), 19), (wall(19), 19.5), (2, 19.5)],
                               atol=1e-9)
    np.testing.assert_allclose(zx[i:i + len(level13)], [p for p, _ in level13], atol=1e-9)
    for (p, k), got, c in zip(level13, kind[i:], res.nominal.center[sel][i:]):
        if k is None:  # the arc of the groove, about its centre
            assert got in (tc.ARC_CW, tc.ARC_CCW)
            np.testing.assert_allclose(c[[2, 0]], (-10, 15), atol=1e-9)
        else:
            assert got == k
    # Then out of the groove to A and the contour pass.
    np.testing.assert_allclose(zx[i + len(level13):i + len(level13) + 3], [(-10 + h, 25), (2, 25), (2, 15)], atol=1e-9)


def test_a_haas_shaft_with_a_groove_and_a_thread_runs_in_inch():
    """A hand-written Haas program (inch): type II G71 (Z in the P block) over a relief
    groove, G70 with G42, a one-block G76 with Haas's one-lead chamfer."""
    from pathlib import Path
    path = Path(__file__).parent.parent / "programs" / "lathe" / "shaft_groove_thread_haas_inch.nc"
    tools = tc.ToolTable()
    for n, r, tip in [(1, 0.031, 3), (2, 0.015, 3), (3, 0.0, 8)]:
        tools.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=r * 25.4, orientation=tip)]))
    res = tc.run(str(path), dialect="fanuc", machine="haas-lathe", tools=tools)
    assert res.ok, res.diagnostics
    lines = path.read_text().splitlines()
    g71 = lines.index("G71 P100 Q200 U0.02 W0.005 D0.06 F0.012") + 1
    # Levels from A (radius 0.8) by 0.06; the contour shifted by (radius 0.01, Z 0.005). At
    # level 0.44 the groove is a pocket of its own: its near wall (-0.995, 0.4475) ->
    # (-1.095, 0.385) meets it at Z -1.007, its far wall (-1.295, 0.385) -> (-1.395, 0.51) at
    # Z -1.339.
    sel = (res.nominal.line == g71) & (res.nominal.kind == tc.LINE)
    start = res.nominal.start[sel][:, [0, 2]] / 25.4
    end = res.nominal.end[sel][:, [0, 2]] / 25.4
    groove = [i for i in range(len(end)) if abs(start[i, 0] - 0.44) < 1e-9 and abs(end[i, 0] - 0.44) < 1e-9
              and abs(start[i, 1] + 1.007) < 1e-9]
    assert len(groove) == 1
    assert end[groove[0], 1] == pytest.approx(-1.339, abs=1e-9)
    # G76: first pass at 0.012: X (radius) 0.36955 + 0.068 - 0.012, Z moved by -0.012 tan 30;
    # the thread stops one lead (0.1111) short of Z-0.9 and pulls out 0.1111 at 45 degrees.
    g76 = lines.index("G76 X0.7391 Z-0.9 K0.068 D0.012 A60 F0.1111") + 1
    ends = res.nominal.end[res.nominal.line == g76][:, [0, 2]] / 25.4
    s = -0.012 * np.tan(np.radians(30))
    x = 0.36955 + 0.068 - 0.012
    np.testing.assert_allclose(ends[:5], [(x, 0.3 + s), (x, -0.9 + s + 0.1111), (x + 0.1111, -0.9 + s),
                                          (0.5, -0.9 + s), (0.5, 0.3)], atol=1e-9)
