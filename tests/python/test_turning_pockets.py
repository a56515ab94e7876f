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
