"""The Sinumerik 840D radius-compensation profile on ISO programs: G450/G451 on the spec's
L-shape, NORM against KONT when the start point is in front of or behind the contour, direct
G41 <-> G42 change, bottleneck detection skipping a groove, and the alarms with their numbers.
Every number below is worked by hand from the programmed contour and r = 5."""
import numpy as np
import pytest

import toolcomp as tc

L_SHAPE = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nY30\nX80\nG40 G0 X90 Y40\nM2\n"


def run(text, **radius):
    prof = tc.ControlProfile("sinumerik")
    for k, v in radius.items():
        setattr(prof.radius, k, v)
    return tc.run(tc.Program.parse(text, dialect="linuxcnc"), profile=prof)


def segments(path):
    return [(int(k), tuple(np.round(s[:2], 9)), tuple(np.round(e[:2], 9)), bool(g))
            for k, s, e, g in zip(path.kind, path.start, path.end, path.generated)]


def test_profile_defaults_are_the_power_on_groups():
    prof = tc.ControlProfile("sinumerik")
    assert prof.radius.entry == tc.EntryStyle.perpendicular_to_next  # NORM
    assert prof.radius.outside_corner == tc.OutsideCorner.arc  # G450
    assert prof.radius.gouge == tc.GougeReaction.skip and prof.radius.lookahead == 3  # CDON, 3 blocks
    assert prof.radius.side_change


def test_g450_transition_circle_and_g451_intersection_on_the_l_shape():
    # spec 1.4: A(0,0) B(50,0) C(50,30) D(80,30), G41 r = 5. B is an inside corner: (45, 5).
    # C is outside: G450 circles about C from (45,30) to (50,35); G451 meets at (45,35).
    g450 = segments(run(L_SHAPE).path)
    assert (1, (0.0, 5.0), (45.0, 5.0), False) in g450
    assert (1, (45.0, 5.0), (45.0, 30.0), False) in g450
    assert (2, (45.0, 30.0), (50.0, 35.0), True) in g450
    g451 = segments(run(L_SHAPE, outside_corner=tc.OutsideCorner.intersection).path)
    assert (1, (45.0, 5.0), (45.0, 35.0), False) in g451
    assert (1, (45.0, 35.0), (80.0, 35.0), False) in g451
    assert not any(s[3] for s in g451)


KONT = tc.EntryStyle.around_start_when_behind


@pytest.mark.parametrize("start", ["X-10 Y10", "X10 Y10"])
def test_kont_equals_norm_when_the_start_is_in_front(start):
    text = f"G21 G0 {start}\nG41.1 D10\nG1 X0 Y0 F100\nX50\nG40 G1 X60 Y10\nM2\n"
    norm, kont = run(text).path, run(text, entry=KONT).path
    np.testing.assert_allclose(norm.end, kont.end, atol=1e-12)
    np.testing.assert_allclose(norm.end[1], [0, 5, 0], atol=1e-12)  # perpendicular point of X50


def test_kont_goes_round_the_start_point_when_it_lies_behind():
    # Start (0,-10) is on the material side of the first element (X0 -> X50, tool on +Y).
    text = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nG40 G1 X60 Y10\nM2\n"
    norm = segments(run(text).path)
    assert norm[1] == (1, (0.0, -10.0), (0.0, 5.0), False)  # NORM: straight to (0,5)
    kont = segments(run(text, entry=KONT).path)
    # KONT with G450: perpendicular to the entry at (−5,0), circle about (0,0) to (0,5).
    assert kont[1] == (1, (0.0, -10.0), (-5.0, 0.0), False)
    assert kont[2] == (tc.ARC_CW, (-5.0, 0.0), (0.0, 5.0), True)
    kont451 = segments(run(text, entry=KONT, outside_corner=tc.OutsideCorner.intersection).path)
    # KONT with G451: the intersection of the equidistants (spec 3.3), the approach line
    # x = 0 moved to the tool's side (left of +Y: x = -5) and the first element's y = 5.
    assert kont451[1] == (1, (0.0, -10.0), (-5.0, 5.0), False)
    assert kont451[2] == (1, (-5.0, 5.0), (50.0, 5.0), False)


def test_direct_side_change_links_the_perpendiculars():
    text = "G21 G0 X0 Y10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nG42.1 D10\nX100\nG40 G1 X110 Y-10\nM2\n"
    s = segments(run(text).path)
    assert (1, (0.0, 5.0), (50.0, 5.0), False) in s
    assert (1, (50.0, 5.0), (50.0, -5.0), True) in s
    assert (1, (50.0, -5.0), (100.0, -5.0), False) in s


def test_bottleneck_detection_leaves_out_a_step_lower_than_the_tool_radius():
    # A 2 mm step down at x = 30 under a tool of r = 5 on the left: the riser's equidistant
    # x = 35 would meet y = 3 above the riser, so the riser is left out and y = 3 meets the
    # transition circle about (30,0) at x = 30 + sqrt(5^2 - 3^2) = 34.
    text = "G21 G0 X0 Y10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY-2\nX60\nG40 G1 X70 Y10\nM2\n"
    res = run(text)
    s = segments(res.path)
    assert (tc.ARC_CW, (30.0, 5.0), (34.0, 3.0), True) in s
    assert (1, (34.0, 3.0), (60.0, 3.0), False) in s
    assert [d.code for d in res.diagnostics] == ["comp_skipped"]


def test_a_groove_the_look_ahead_cannot_bridge_is_alarm_10751_not_a_backwards_move():
    # V groove 4 wide, 3 deep under r = 5: both flanks are unreachable; joining the second
    # flank to the circle about (20,0) would run it backwards, so the control stops.
    text = "G21 G0 X0 Y10\nG41.1 D10\nG1 X0 Y0 F100\nX20\nX22 Y-3\nX24 Y0\nX50\nG40 G1 X60 Y10\nM2\n"
    with pytest.raises(tc.Error) as e:
        run(text)
    assert e.value.message.startswith("10751") and e.value.line == 6


@pytest.mark.parametrize("text, alarm, line", [
    ("G21 G0 X-10 Y0\nG41.1 D10\nG3 X10 Y0 R10 F100\nM2\n", "10753", 3),
    ("G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX20\nZ-1\nZ-2\nZ-3\nZ-4\nY20\nG40 G0 X-10 Y30\nM2\n", "10762", 8),
])
def test_alarms_carry_their_numbers_and_lines(text, alarm, line):
    with pytest.raises(tc.Error) as e:
        run(text)
    assert e.value.message.startswith(alarm) and e.value.line == line


def test_three_blocks_without_plane_motion_are_looked_past():
    text = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX20\nZ-1\nZ-2\nZ-3\nY20\nG40 G0 X-10 Y30\nM2\n"
    ends = [tuple(np.round(e[:2], 9)) for e in run(text).path.end]
    assert (15.0, 5.0) in ends  # the inside corner at (20,0) is reached across the Z moves


def test_d_change_during_trc_ends_and_starts_perpendicular():
    # r 5 -> 3 at (30,0) on a straight contour along +X: (30,5) then a link to (30,3).
    text = "G21 G0 X0 Y10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nG41.1 D6\nX60\nG40 G1 X70 Y10\nM2\n"
    s = segments(run(text).path)
    assert (1, (0.0, 5.0), (30.0, 5.0), False) in s
    assert (1, (30.0, 5.0), (30.0, 3.0), True) in s
    assert (1, (30.0, 3.0), (60.0, 3.0), False) in s
