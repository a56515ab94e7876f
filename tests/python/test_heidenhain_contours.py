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


@pytest.mark.parametrize("cc, column", [("CC X+10 Z+5", 11), ("CC IX+10 IZ+5", 12), ("CC Z+5", 6)])
def test_a_pole_outside_the_working_plane_is_refused(cc, column):
    # CC X.. Z.. under the Z tool axis: the TNC cuts the following C in the ZX plane (as
    # Fusion 360 writes lead-in arcs); drawing it in XY moved the tool in Y without a word.
    text = f"0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+10 R0 FMAX\n2 {cc}\n3 C X+20 Z+5 DR+ F100\n4 END PGM A MM\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="heidenhain"))
    assert (e.value.code, e.value.line, e.value.column) == ("cc_outside_plane", 3, column)


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
