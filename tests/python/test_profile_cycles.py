"""LinuxCNC's lathe profile cycles G70, G71, G72 (and .1 / .2): numbers from LinuxCNC's runs
(rs274 2.9 and its geometry at 2.9.10), and from hand calculation."""
import math

import numpy as np
import pytest

import toolcomp as tc

SHAFT = """G21 G18 G7 G90 G40 F100
o100 sub
G1 X10 Z0
G1 Z-10
G1 X16 Z-15
G1 Z-20
G1 X24
o100 endsub
G0 X30 Z2
G71 Q100 X24 Z2 D0.5 I2 R0.5
G70 Q100 X24 Z2
M2
"""


def run(text, **kw):
    return tc.run(tc.Program.parse(text), **kw)


def moves(res):
    p = res.nominal
    return [(int(k), round(float(e[0]), 4), round(float(e[2]), 4)) for k, e in zip(p.kind, p.end)]


R, F = tc.RAPID, tc.LINE


def test_g71_levels_escape_and_final_contour_as_linuxcnc():
    m = moves(run(SHAFT))
    # rs274: the cycle's rapid, the rapid to the start, the level at X12 (radius) from the start
    assert m[1:9] == [(R, 12, 2), (R, 12, 2), (R, 12, 2), (F, 12, -19.5), (R, 12.5, -19), (R, 12.5, 1.5),
                      (R, 12, 2), (R, 10, 1.3846)]
    # the lead-in from (Z2, X12) to (Z0, X5.5): level X10 is reached at Z = 2 - 2 * 2 / 6.5
    assert m[8][2] == round(2 - 2 * 2 / 6.5, 4)
    # level X8 meets the diagonal offset by D = 0.5 along its normal (5, 3) / sqrt(34)
    # (the diagonal (Z-10, X5)-(Z-15, X8) moved 0.5 toward the stock: Z at X8 = -15 + 0.5 * sqrt(34) / 3)
    assert m[14][1:] == (8, round(-15 + 0.5 * math.sqrt(34) / 3, 4))
    # the final contour: G0 to the profile's start, the concave corner, the convex arc of radius D
    assert m[23:29] == [(R, 5.5, 0), (F, 5.5, -9.8615), (F, 8.4287, -14.7428), (tc.ARC_CCW, 8.5, -15),
                        (F, 8.5, -19.5), (F, 12, -19.5)]
    # G70 (one pass at E = 0): the profile exactly, no return
    assert m[-5:] == [(R, 5, 0), (F, 5, -10), (F, 8, -15), (F, 8, -20), (F, 12, -20)]


def test_g70_passes_from_d_to_e():
    text = SHAFT.replace("G71 Q100 X24 Z2 D0.5 I2 R0.5\n", "").replace(
        "G1 X16 Z-15", "G2 X16 Z-13 R3").replace("G70 Q100 X24 Z2", "G70 Q100 X24 Z2 D1 E0.2 P2")
    m = moves(run(text))
    # pass 2 at (2 - 1) * (1 - 0.2) / 2 + 0.2 = 0.6, pass 1 at E = 0.2
    assert m[3] == (R, 5.6, 0) and m[10] == (R, 5.2, 0)
    res = run(text)
    arc = int(np.flatnonzero(np.asarray(res.nominal.kind) == tc.ARC_CW)[0])
    c = res.nominal.center[arc]
    assert (round(c[0], 4), round(c[2], 4)) == (8, -10)  # the G2 R3 about its own centre, radius 2.4
    assert moves(res)[arc][1:] == (8, -12.4)


@pytest.mark.parametrize("variant, count, bridge", [("G71", 45, None), ("G71.1", 46, (6.2, -11.8764)),
                                                     ("G71.2", 24, None)])
def test_pocket_variants(variant, count, bridge):
    text = """G21 G18 G8 G90 G40 F100
o200 sub
G1 X3 Z0
G1 Z-4
G1 X6 Z-6
G1 Z-8
G1 X4 Z-9
G1 Z-11
G1 X8 Z-13
G1 Z-15
G1 X10
o200 endsub
G0 X12 Z1
%s Q200 X10 Z1 D0.2 I1.5 R0.3
M2
""" % variant
    m = moves(run(text))
    assert len(m) == count  # rs274's count of moves
    if bridge:  # G71.1 leaves the pocket: a feed over it at the pocket's top
        assert (F,) + bridge in m
    if variant == "G71.2":  # no outer levels: down the lead-in at rapid, then the contour
        assert m[3] == (R, 3.2, 0) and m[8] == (F, 6.2, -11.8764)


def test_moves_carry_the_cycle_line_and_leave_the_last_motion_modal():
    res = run(SHAFT.replace("G70 Q100 X24 Z2\n", "X30 Z4\n"))
    lines = np.asarray(res.nominal.line)
    assert set(lines[1:-1]) == {10}
    assert int(res.nominal.kind[-1]) == tc.LINE and lines[-1] == 11  # a bare X Z after G71 feeds


def test_g72_faces_in_levels_of_z():
    text = """G21 G18 G7 G90 G40 F80
o300 sub
G1 X30 Z-6
G1 X20
G1 Z-3
G1 X12 Z-2
G1 Z0
G1 X0
o300 endsub
G0 X40 Z5
G72 Q300 X32 Z1 D0.3 I2 R0.5
M2
"""
    m = moves(run(text))
    # levels Z1, -1, -3, -5 from the start, cut toward the axis; the face offset to Z-5.7
    assert [z for k, x, z in m if k == F][:4] == [1, -1, -3, -5]
    assert m[23] == (R, 15, -5.7)
    # LinuxCNC 2.9.10's leadout: the profile (ending at X0) is offset by D too (2.9.0 ends at X0)
    assert m[4] == (F, 0.3, 1) and m[-1] == (F, 0.3, 1)


def test_g91_start_and_the_first_rapid():
    # LinuxCNC rapids to the words as absolute coordinates, the cycle starts from here + words
    text = SHAFT.replace("G71 Q100 X24 Z2", "G91 G71 Q100 X-6 Z0").replace("G70 Q100 X24 Z2\n", "G90\n")
    m = moves(run(text))
    assert m[1] == (R, -3, 0) and m[2] == (R, 12, 2)


def test_u_and_w_in_the_profile_only():
    text = SHAFT.replace("G1 Z-10\n", "G1 W-10\n").replace("G1 X16 Z-15", "G1 U6 W-5")
    assert moves(run(text)) == moves(run(SHAFT))
    with pytest.raises(tc.ProgramError, match="Bad character 'u' used"):
        run("G21 G18\nG0 X1 U2\nM2\n")
    # a subroutine with U that nothing calls: LinuxCNC runs the program
    assert len(moves(run("o5 sub\nG1 U2\no5 endsub\nG0 X1\nM2\n"))) == 1


def test_a_fillet_and_a_chamfer():
    text = """G21 G18 G8 G90 G40 F100
o100 sub
G1 X5 Z0
G1 Z-10 A1
G1 X8
G1 Z-20 C1
G1 X12
o100 endsub
G0 X12 Z2
G70 Q100 X12 Z2
M2
"""
    res = run(text)
    m = moves(res)
    # the fillet of radius 1 in the concave corner (Z-10, X5): from Z-9 to X6 about (Z-9, X6)
    arc = int(np.flatnonzero(np.asarray(res.nominal.kind) >= tc.ARC_CW)[0])
    assert m[arc - 1] == (F, 5, -9) and m[arc][1:] == (6, -10)
    c = res.nominal.center[arc]
    assert (round(c[0], 4), round(c[2], 4)) == (6, -9)
    # the chamfer of 1 at the convex corner (Z-20, X8): X8 Z-19 to X9 Z-20
    assert (F, 8, -19) in m and (F, 9, -20) in m


def test_errors_and_the_switch():
    with pytest.raises(tc.ProgramError, match="G7X error: Not monotonic") as e:
        run(SHAFT.replace("G1 X16 Z-15", "G1 X16 Z-5"))
    assert e.value.line == 8  # at the endsub, as LinuxCNC
    with pytest.raises(tc.ProgramError, match="cannot be used with cutter compensation enabled"):
        run(SHAFT.replace("G0 X30 Z2", "G0 X30 Z2\nG42.1 D0.8 L3"))
    profile = tc.ControlProfile("linuxcnc")
    profile.profile_cycles = False
    with pytest.raises(tc.ProgramError, match="G71 is not supported"):
        run(SHAFT, profile=profile)


def test_a_cycle_that_linuxcnc_repeats_forever_ends_with_an_error():
    text = """G21
G18 G90 G40 G8 F100
o100 sub
G1 X5.8619 Z0
G1 X8.0299 Z-6.7028
G1 X7.3877 Z-9.5384
G1 X7.3877 Z-14.7338
G2 X9.126 Z-22.1268 R7.9187
G1 X7.4184 Z-29.3187
G1 X7.9535
o100 endsub
G0 X8.9535 Z3
G71.2 Q100 X7.9535 Z2 D0.3599 I1.0982 R0.5124
M2
"""
    with pytest.raises(tc.ProgramError, match="the cycle does not end"):
        run(text)


def test_a_profile_with_one_move():
    res = run("G21 G18 G8 F100\no1 sub\nG1 X5 Z0\no1 endsub\nG0 X10 Z2\nG71 Q1 X10 Z2\nM2\n")
    assert len(res.nominal.kind) == 2
    assert any(d.code == "profile_cycle_empty" for d in res.diagnostics)
