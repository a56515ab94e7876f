"""Heidenhain RND next to arcs, CHF next to an arc (refused as on the TNC) and APPR with
radius compensation already on (a connecting element), with hand-computed numbers."""
import math

import numpy as np
import pytest

import toolcomp as tc


def test_rnd_between_line_and_arc():
    # Line (0,0) -> (30,0), CW arc about (40,0) R10 to (40,10); RND R5: centre
    # (40 - 10*sqrt(2), 5), tangent points (40 - 10*sqrt(2), 0) and (40 - 20*sqrt(2)/3, 10/3).
    text = ("0 BEGIN PGM T MM\n1 TOOL DEF 1 L+0 R+0\n2 TOOL CALL 1 Z\n3 L X+0 Y+0 Z+0 R0 F100\n"
            "4 L X+30 Y+0\n5 RND R5\n6 CC X+40 Y+0\n7 C X+40 Y+10 DR-\n8 END PGM T MM\n")
    p = tc.run(tc.Program.parse(text, dialect="heidenhain")).path
    s2 = math.sqrt(2)
    (rnd,) = np.flatnonzero(p.line == 6)
    assert p.kind[rnd] == tc.ARC_CCW
    np.testing.assert_allclose(p.start[rnd, :2], [40 - 10 * s2, 0], atol=1e-9)
    np.testing.assert_allclose(p.center[rnd, :2], [40 - 10 * s2, 5], atol=1e-9)
    np.testing.assert_allclose(p.end[rnd, :2], [40 - 20 * s2 / 3, 10 / 3], atol=1e-9)


def test_chf_next_to_an_arc_is_not_permitted():
    text = ("0 BEGIN PGM T MM\n1 TOOL DEF 1 L+0 R+0\n2 TOOL CALL 1 Z\n3 L X+0 Y+0 Z+0 R0 F100\n"
            "4 L X+30 Y+0\n5 CHF 2\n6 CC X+40 Y+0\n7 C X+40 Y+10 DR-\n8 END PGM T MM\n")
    with pytest.raises(tc.ProgramError, match="CHAMFER NOT PERMITTED") as e:
        tc.run(tc.Program.parse(text, dialect="heidenhain"))
    assert e.value.line == 6


def test_appr_ct_with_compensation_on_is_a_connecting_element():
    # r = 2, RL along y = 5 to (20,5); APPR CT X+40 Y+10 CCA90 R+5 without RL/RR: on the
    # contour PH = (35,5) and a CCW arc about (35,10) to PA; the tool: (35,7), then an arc of
    # radius 3 to (38,10), compensation still on.
    text = ("0 BEGIN PGM T MM\n1 TOOL DEF 1 L+0 R+2\n2 TOOL CALL 1 Z\n3 L X+0 Y-10 Z+0 R0 F100\n"
            "4 L X+0 Y+5 RL\n5 L X+20 Y+5\n6 APPR CT X+40 Y+10 CCA90 R+5\n7 L X+40 Y+30\n"
            "8 L X+40 Y+50 R0\n9 END PGM T MM\n")
    p = tc.run(tc.Program.parse(text, dialect="heidenhain")).path
    appr = np.flatnonzero(p.line == 7)
    np.testing.assert_allclose(p.end[appr, :2], [[35, 7], [38, 10]], atol=1e-9)
    assert p.kind[appr[1]] == tc.ARC_CCW
    np.testing.assert_allclose(p.center[appr[1], :2], [35, 10], atol=1e-9)
    assert (p.side[appr] == 1).all()


def test_a_pole_in_the_zx_plane_moves_the_arc_there():
    # Fusion 360's facing lead-in and lead-out (TOOL CALL Z): CC X.. Z.. puts the pole in the
    # ZX plane and CP turns about it there, Y staying. From (X491, Z197) about (X483, Z197),
    # +90 degrees counter-clockwise in (Z, X): down to (X483, Z189); the lead-out from
    # (X-40, Z189) about (X-40, Z197): up to (X-48, Z197).
    text = """0  BEGIN PGM face-189 MM
1  TOOL DEF 23 L+0 R+40
2  TOOL CALL 23 Z S5000
3  L  X+491  Y-15 R0 FMAX
4  L  Z+197 FMAX
5  CC  X+483  Z+197
6  CP IPA+90 DR+ F1000
7  L  X+479  Z+189
8  L  X-40
9  CC  X-40  Z+197
10 CP IPA+90 DR+
11 L  X-48  Z+231 FMAX
12 END PGM face-189 MM
"""
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"))
    p = res.nominal
    arcs = np.flatnonzero(p.kind == tc.ARC_CCW)
    np.testing.assert_allclose(p.end[arcs], [[483, -15, 189], [-48, -15, 197]], atol=1e-12)
    np.testing.assert_allclose(p.center[arcs], [[483, -15, 197], [-40, -15, 197]], atol=1e-12)
    np.testing.assert_allclose(p.tool_axis[arcs], [[0, 0, 1], [0, 0, 1]])  # the tool axis stays Z
    # the first arc's points lie in the ZX plane 8 mm from the pole, on the side of +X, -Z
    pts, seg = p.sample(0.001)
    on_arc = pts[seg == arcs[0]]
    np.testing.assert_allclose(on_arc[:, 1], -15, atol=1e-12)
    np.testing.assert_allclose(np.hypot(on_arc[:, 0] - 483, on_arc[:, 2] - 197), 8, atol=1e-9)
    assert np.all(on_arc[:, 0] >= 483 - 1e-9) and np.all(on_arc[:, 2] <= 197 + 1e-9)


def test_a_pole_in_the_yz_plane():
    # CC Y+14 Z-30 from (X-2, Y16, Z-30): CP IPA-90 DR- in (Y, Z) to (Y14, Z-32), X staying.
    text = """0 BEGIN PGM A MM
1 L X-2 Y+16 Z-30 R0 FMAX
2 CC Y+14 Z-30
3 CP IPA-90 DR- F1000
4 END PGM A MM
"""
    p = tc.run(tc.Program.parse(text, dialect="heidenhain")).nominal
    assert p.kind[-1] == tc.ARC_CW
    np.testing.assert_allclose(p.end[-1], [-2, 14, -32], atol=1e-12)
    np.testing.assert_allclose(p.center[-1], [-2, 14, -30], atol=1e-12)


@pytest.mark.parametrize("body, code", [
    ("2 CC Z+5\n3 C X+20 Z+5 DR+ F100", "cc_outside_plane"),        # one axis, outside the plane
    ("2 CC X+1 Y+2 Z+3\n3 C X+2 DR+ F100", "cc_outside_plane"),     # three axes
    ("2 L X+0 Y+0 RL F100\n3 CC X+10 Z+5\n4 C X+20 Z+5 DR+", "comp_plane"),  # RL with an arc in ZX
    ("2 CC X+10 Z+10\n3 CP IPA+90 DR+ F100\n4 RND R1\n5 L X+30", "unsupported_block"),
])
def test_what_a_pole_in_another_plane_does_not_allow(body, code):
    text = f"0 BEGIN PGM A MM\n1 TOOL DEF 1 L+0 R+2\n1 TOOL CALL 1 Z\n1 L X+0 Y+0 Z+10 R0 FMAX\n{body}\n9 END PGM A MM\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="heidenhain"))
    assert e.value.code == code


def test_a_pole_in_the_plane_still_runs():
    # From (0, 0) around (10, 5) to (20, 0): radius sqrt(125), counter-clockwise.
    text = "0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+10 R0 FMAX\n2 CC X+10 Y+5\n3 C X+20 Y+0 DR+ F100\n4 END PGM A MM\n"
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"))
    np.testing.assert_allclose(res.nominal.center[-1], [10, 5, 10])
    np.testing.assert_allclose(res.nominal.end[-1], [20, 0, 10])


def test_the_feed_of_rnd_and_chf_is_for_the_corner_only():
    # TNC: F in an RND / CHF block is the feed of the rounding or chamfer; the next element
    # runs at the contour's F100 again.
    text = ("0 BEGIN PGM A MM\n1 L X+0 Y+0 R0 F100\n2 L X+10\n3 RND R2 F10\n4 L Y+10\n5 CHF 2 F20\n"
            "6 L X+0\n7 END PGM A MM\n")
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"))
    assert list(res.nominal.kind) == [tc.LINE, tc.ARC_CCW, tc.LINE, tc.LINE, tc.LINE]
    np.testing.assert_array_equal(res.nominal.feed, [100, 10, 100, 20, 100])
    np.testing.assert_array_equal(res.nominal.line, [3, 4, 5, 6, 7])


def test_r0_in_a_cr_block_under_compensation_is_refused_as_in_c():
    # The first R of CR is its radius; an R0 after it would end compensation in an arc block,
    # which C, CP and CT refuse: CR did keep RL on without a word.
    text = ("0 BEGIN PGM A MM\n1 TOOL DEF 1 L+0 R+2\n2 TOOL CALL 1 Z\n3 L X+0 Y+0 Z-1 R0 F100\n"
            "4 L X+10 Y+0 RL\n5 CR X+20 Y+10 R+10 DR+ R0\n6 L X+30\n7 END PGM A MM\n")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="heidenhain"))
    assert (e.value.code, e.value.line, e.value.column) == ("comp_exit_arc", 6, 25)
