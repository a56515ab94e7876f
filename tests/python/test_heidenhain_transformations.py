"""Heidenhain coordinate transformations: CYCL DEF 7 datum shift, 8 mirror image, 10 rotation,
11 scaling, 26 axis-specific scaling, 247 datum setting. A program point P lands, from the
preset, at shift + Mirror(Rotate(Scale(P))) (the TNC's fixed order); the path is given from the
preset, radius compensation offsets the transformed contour by the tool's own radius, and an odd
mirror turns arcs and swaps RL / RR. Numbers worked by hand (doc/heidenhain.md, example E9)."""
import math

import numpy as np
import pytest

import toolcomp as tc

SHIFT = "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+50\nCYCL DEF 7.2 Y+20\n"


def run(body, **kw):
    lines = ["BEGIN PGM T MM", "TOOL DEF 1 L+0 R+5", "TOOL CALL 1 Z S1000"] + body.strip().split("\n") + ["END PGM T MM"]
    text, n = "", 0
    for b in lines:  # continuation lines (indented) carry no block number
        text += (b if b.startswith(" ") else f"{n} {b}") + "\n"
        n += not b.startswith(" ")
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text, "heidenhain"), **kw)


def end(res, k=-1, path="nominal"):
    return tuple(round(float(v), 4) for v in getattr(res, path).end[k])


def test_a_rotated_point_is_turned_about_the_shifted_datum():
    # (10, 0) turned by 30 degrees: (8.6603, 5); shifted by (50, 20): (58.6603, 25).
    res = run(SHIFT + "CYCL DEF 10.0 ROTATION\nCYCL DEF 10.1 ROT+30\nL X+10 Y+0 Z+0 R0 FMAX")
    assert end(res) == (58.6603, 25, 0)


def test_a_mirrored_point_and_arc():
    # Mirror X: (10, 0) -> (-10, 0) -> (40, 20). The arc about (0, 0) from (10, 0) to (0, 10)
    # counter-clockwise runs clockwise about (50, 20) from (40, 20) to (50, 30).
    res = run(SHIFT + "CYCL DEF 8.0 MIRROR IMAGE\nCYCL DEF 8.1 X\nL X+10 Y+0 Z+0 R0 FMAX\nCC X+0 Y+0\n"
                      "C X+0 Y+10 DR+ F100")
    p = res.nominal
    assert end(res, -2) == (40, 20, 0) and end(res) == (50, 30, 0)
    assert p.kind[-1] == tc.ARC_CW and tuple(p.center[-1, :2]) == (50, 20)


def test_mirror_and_rotation_in_the_tncs_order():
    # Fixed order shift(mirror(rotate(P))): (8.6603, 5) -> (-8.6603, 5) -> (41.3397, 25).
    res = run(SHIFT + "CYCL DEF 10.0 ROTATION\nCYCL DEF 10.1 ROT+30\nCYCL DEF 8.0 MIRROR IMAGE\nCYCL DEF 8.1 X\n"
                      "L X+10 Y+0 Z+0 R0 FMAX")
    assert end(res) == (41.3397, 25, 0)


def test_scaling_scales_positions_but_not_the_tool():
    # SCL 0.5: (10, 0) -> (5, 0) -> (55, 20). A 40 x 40 square from the datum scaled to 20 x
    # 20, cut RL (counter-clockwise, the tool R5 inside): the tool centre 5 inside the scaled
    # square, from (55, 25) ... the corners (65, 25), (65, 35), (55, 35).
    res = run(SHIFT + "CYCL DEF 11.0 SCALING\nCYCL DEF 11.1 SCL 0.5\nL X+10 Y+0 Z+0 R0 FMAX")
    assert end(res) == (55, 20, 0)
    square = run(SHIFT + "CYCL DEF 11.0 SCALING\nCYCL DEF 11.1 SCL0.5\nL X-20 Y-20 Z+0 R0 FMAX\nL X+0 Y+0 RL F100\n"
                         "L X+40\nL Y+40\nL X+0\nL Y+0\nL X-20 Y-20 R0")
    corners = {tuple(round(float(v), 4) for v in e[:2]) for e in square.path.end}
    assert {(65, 25), (65, 35), (55, 35)} <= corners


def test_compensation_of_a_mirrored_contour_is_the_mirrored_compensated_contour():
    contour = "L X-10 Y-10 Z+0 R0 FMAX\nL X+0 Y+0 RL F100\nL X+30\nCC X+30 Y+15\nC X+30 Y+30 DR+\nL X+0\nL Y+0\nL X-10 Y-10 R0"
    plain = run(contour).path.end
    mirrored = run("CYCL DEF 8.0 MIRROR IMAGE\nCYCL DEF 8.1 X\n" + contour).path.end
    np.testing.assert_allclose(mirrored, plain * [-1, 1, 1], atol=1e-9)


def test_compensation_of_a_rotated_contour_is_the_rotated_compensated_contour():
    contour = "L X-10 Y-10 Z+0 R0 FMAX\nL X+0 Y+0 RR F100\nL X+30\nL X+30 Y+20\nRND R4\nL X+0\nL Y+0\nL X-10 Y-10 R0"
    plain = run(contour).path.end
    turned = run("CYCL DEF 10.0 ROTATION\nCYCL DEF 10.1 ROT+90\n" + contour).path.end
    np.testing.assert_allclose(turned, np.column_stack([-plain[:, 1], plain[:, 0], plain[:, 2]]), atol=1e-9)


def test_incremental_moves_and_the_position_read_back_are_in_the_transformed_system():
    # After ROT+90 an IX+10 moves along preset +Y; FN 18 ID270 reads the position in the
    # active system, ID210 NR2 the rotation, ID220 NR2 the datum shift.
    res = run("L X+10 Y+0 Z+0 R0 FMAX\nCYCL DEF 10.0 ROTATION\nCYCL DEF 10.1 ROT+90\nL IX+10 R0 FMAX\n"
              "FN 18: SYSREAD Q1 = ID270 NR1 IDX1\nFN 18: SYSREAD Q2 = ID210 NR2\nL X+Q1 Y+Q2 FMAX")
    assert end(res, -2) == (10, 10, 0)
    # program X = 10 (0 + 10 along the turned X), the rotation 90: program (10, 90) -> preset (-90, 10)
    assert end(res) == (-90, 10, 0)


def test_resets_take_every_transformation_back():
    res = run(SHIFT + "CYCL DEF 10.1 ROT+30\nCYCL DEF 8.1 X\nCYCL DEF 11.1 SCL 2\n"
                      "CYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 10.1 ROT+0\nCYCL DEF 8.1\nCYCL DEF 11.1 SCL 1\n"
                      "L X+10 Y+3 Z+0 R0 FMAX")
    assert end(res) == (10, 3, 0)


def test_datum_setting_resets_the_transformations_with_a_note():
    res = run(SHIFT + "CYCL DEF 10.1 ROT+30\nCYCL DEF 247 DATUM SETTING ~\n    Q339=+1 ;DATUM NUMBER\nL X+10 Y+3 Z+0 R0 FMAX")
    assert end(res) == (10, 3, 0)
    assert [d.code for d in res.diagnostics] == ["preset_not_modelled"]


def test_axis_specific_scaling_about_its_centre():
    # X by 2 about CCX+10: (20, 5) -> (10 + 2 * 10, 5) = (30, 5).
    res = run("CYCL DEF 26.0 AXIS-SPECIFIC SCALING\nCYCL DEF 26.1 X2 CCX+10\nL X+20 Y+5 Z+0 R0 FMAX")
    assert end(res) == (30, 5, 0)


def test_a_drilling_pattern_under_a_rotated_datum():
    res = run(SHIFT + "CYCL DEF 10.1 ROT+90\nL Z+50 R0 FMAX\nCYCL DEF 200 DRILLING ~\n Q200=+2 ~\n Q201=-5 ~\n Q206=+100 ~\n"
                      " Q202=+5 ~\n Q210=+0 ~\n Q203=+0 ~\n Q204=+20 ~\n Q211=+0\nPATTERN DEF ~\n"
                      " ROW1 ( X+10 Y+0 D+10 NUM2 ROT+0 Z+0 )\nCYCL CALL PAT FMAX")
    p = res.nominal
    holes = [tuple(round(float(v), 4) for v in e[:2]) for e, k in zip(p.end, p.kind) if k == tc.LINE]
    assert holes == [(50, 30), (50, 40)]


@pytest.mark.parametrize("body, code", [
    ("L X+0 Y+0 Z+0 RL F100\nCYCL DEF 10.1 ROT+10", "comp_plane"),
    ("CYCL DEF 11.1 SCL 0.5\nAPPR LT X+10 Y+0 LEN5 RL F100", "scaling_refused"),
    ("CYCL DEF 26.1 X2 Y1\nL X+10 Y+0 Z+0 R0 FMAX\nCC X+0 Y+0\nC X+0 Y+10 DR+ F100", "scaling_refused"),
    ("CYCL DEF 8.1 Z", "unsupported_word"),
    ("CYCL DEF 11.1 SCL 0", "cycle_bad_value"),
    ("CYCL DEF 7.1 #5", "unsupported_word"),
])
def test_what_the_transformations_refuse(body, code):
    with pytest.raises(tc.ProgramError) as e:
        run(body)
    assert e.value.code == code


def test_m91_stays_in_machine_coordinates_under_a_rotation():
    # The spindle to machine Z+0 (no machine: machine zero is the preset) while turned by 90.
    res = run("L X+10 Y+0 Z+5 R0 FMAX\nCYCL DEF 10.1 ROT+90\nL Z+0 R0 FMAX M91")
    assert end(res) == (10, 0, 0)
