"""Blocks that move nothing (M8, S500, G4) under radius compensation.

Fanuc, the 9/Series and Sinumerik count them with the moves without plane motion (spec 1.7:
the control's look-ahead passes a few of them; Sinumerik alarm 10762 "too many empty
blocks", the 9/Series and Fanuc end the held move perpendicular, which may overcut).
Computations, comments and calls are not such blocks. LinuxCNC holds its move back over any
number of them.

Every program below turns at an inside corner: with r = 5 and G41 along +X to (50, 0), then
up to (50, 30), the tool centre meets the next element at (45, 5); ended perpendicular
instead it stops at (50, 5).
"""
import math

import numpy as np
import pytest

import toolcomp as tc

FANUC = "G21 G17 G90\nT1 M6\nG0 X-10 Y-10\nG41 G1 X0 Y0 D1 F100\nX50 Y0\n{mid}X50 Y30\nG40 X70 Y40\nM30\n"
TOOLS = tc.ToolTable.parse("T1 P1 D10\n", "linuxcnc")  # diameter 10: r = 5

SINUMERIK = ("$TC_DP1[1,1]=120\n$TC_DP3[1,1]=0\n$TC_DP6[1,1]=5\nT1 M6\nG17 G0 X-10 Y-10 Z0\n"
             "G41 G1 X0 Y0 F100\nX50 Y0\n{mid}X50 Y30\nG40 X70 Y40\nM30\n")


def corner(res, line):
    return res.path.end[np.flatnonzero(res.path.line == line)[-1], :2]


def warnings(res):
    return [(d.line, d.code) for d in res.diagnostics if "without plane motion" in d.message]


@pytest.mark.parametrize("mid", ["M8\n", "S500\n", "G4 P1\n", "F200\n"])
def test_fanuc_looks_past_two_and_ends_perpendicular_at_the_third(mid):
    two = tc.run(tc.Program.parse(FANUC.format(mid=mid * 2), "fanuc"), tools=TOOLS)
    np.testing.assert_allclose(corner(two, 5), [45, 5], atol=1e-9)
    assert warnings(two) == []
    three = tc.run(tc.Program.parse(FANUC.format(mid=mid * 3), "fanuc"), tools=TOOLS)
    np.testing.assert_allclose(corner(three, 5), [50, 5], atol=1e-9)
    assert warnings(three) == [(8, "comp_overcut")]


@pytest.mark.parametrize("mid", ["#1=5\n", "(a comment)\n"])
def test_fanuc_computations_and_comments_do_not_count(mid):
    res = tc.run(tc.Program.parse(FANUC.format(mid=mid * 4), "fanuc"), tools=TOOLS)
    np.testing.assert_allclose(corner(res, 5), [45, 5], atol=1e-9)
    assert warnings(res) == []


def test_linuxcnc_holds_the_move_over_any_number_of_them():
    res = tc.run(tc.Program.parse(FANUC.format(mid="M8\nS500\nG4 P1\nM9\nF200\n"), "linuxcnc"), tools=TOOLS)
    np.testing.assert_allclose(corner(res, 5), [45, 5], atol=1e-9)
    assert warnings(res) == []


def test_the_setting_switches_it_off():
    prof = tc.ControlProfile("fanuc")
    assert prof.radius.count_blocks_without_motion
    prof.radius.count_blocks_without_motion = False
    res = tc.run(tc.Program.parse(FANUC.format(mid="M8\n" * 3), "fanuc"), tools=TOOLS, profile=prof)
    np.testing.assert_allclose(corner(res, 5), [45, 5], atol=1e-9)
    assert not tc.ControlProfile("linuxcnc").radius.count_blocks_without_motion


@pytest.mark.parametrize("mid", ["M8\n", "G4 F1\n", "S500\n"])
def test_sinumerik_alarm_10762_after_three_empty_blocks(mid):
    res = tc.run(tc.Program.parse(SINUMERIK.format(mid=mid * 3), "sinumerik"))
    np.testing.assert_allclose(corner(res, 7), [45, 5], atol=1e-9)
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(SINUMERIK.format(mid=mid * 4), "sinumerik"))
    assert e.value.message.startswith("10762") and e.value.line == 11


def test_sinumerik_computations_are_not_empty_blocks():
    res = tc.run(tc.Program.parse(SINUMERIK.format(mid="R1=5\n" * 4), "sinumerik"))
    np.testing.assert_allclose(corner(res, 7), [45, 5], atol=1e-9)


def test_nine_series_ends_the_move_perpendicular():
    # Along -Z at radius 20 (X40) under G42 with a nose radius of 1, then out to radius 25 at
    # Z-20: an inside corner turning by atan(5/10). The nose centre meets the next element at
    # z = -10 + tan(atan(0.5) / 2); ended perpendicular it stops at z = -10. Tip 3 is the
    # centre shifted by (-1, -1).
    text = "G21 G18 G0 X50 Z5\nT0001\nG42 G1 X40 Z0 F0.2\nZ-10\n{mid}G1 X50 Z-20\nZ-30\nG40 G0 X80 Z5\nM30\n"
    table = tc.ToolTable.parse("tool,edge,x,z,radius,orientation\n1,1,0,0,1,3\n", "csv")

    def run(mid):
        return tc.run(tc.Program.parse(text.format(mid=mid), "rockwell"), tools=table,
                      profile=tc.ControlProfile("rockwell"))

    two = run("M8\n" * 2)
    np.testing.assert_allclose(two.path.end[np.flatnonzero(two.path.line == 4)[-1]][[0, 2]],
                               [20, -10 + math.tan(math.atan(0.5) / 2) - 1], atol=1e-9)
    three = run("M8\n" * 3)
    np.testing.assert_allclose(three.path.end[np.flatnonzero(three.path.line == 4)[-1]][[0, 2]], [20, -11], atol=1e-9)
    assert warnings(three) == [(7, "comp_overcut")]
