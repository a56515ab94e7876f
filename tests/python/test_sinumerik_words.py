"""Sinumerik words that change the feed or would be left out.

* G95: F in mm per revolution times S; G96: S is the cutting speed (m/min), the spindle turns
  at S * 1000 / (2 pi r) with r the radius (X) where the move ends; G97 keeps the speed reached;
  G94 mm/min again. At X40 under G96 S200 F0.2: 0.2 * 200000 / (2 pi 40) = 159.1549 mm/min.
* G4 stands in a block of its own; frames act on X, Y, Z only here: both refused otherwise.
"""
import math

import numpy as np
import pytest

import toolcomp as tc


def run(text):
    return tc.run(tc.Program.parse(text, "sinumerik"))


def test_g95_feed_per_revolution():
    assert run("G17 G90 G71\nS1000 M3\nG95 F0.1\nG1 X10\nM30\n").path.feed[-1] == pytest.approx(100)
    assert math.isnan(run("G17 G90 G71\nG95 F0.1\nG1 X10\nM30\n").path.feed[-1])  # no S: not known


def test_g96_constant_cutting_speed_and_g97():
    p = run("G18 G90 G71\nG0 X50 Z5\nG96 S200 F0.2\nG1 X40\nX20\nG97\nG1 Z-10\nG94 F100\nX30\nM30\n").path
    rpm = lambda r: 200 * 1000 / (2 * math.pi * r)  # noqa: E731
    np.testing.assert_allclose(p.feed[1:], [0.2 * rpm(40), 0.2 * rpm(20), 0.2 * rpm(20), 100])


@pytest.mark.parametrize("block", ["G4 F1 G1 X2", "G4 S5 X2"])
def test_g4_with_axis_words_is_refused(block):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G17 G90 G71\nG1 X0 Y0 F100\n{block}\nG1 Y5\nM30\n")
    assert e.value.code == "12190" and e.value.line == 3


@pytest.mark.parametrize("block", ["TRANS X10 A10", "ATRANS A10", "SCALE A2", "MIRROR A0", "AROT A30"])
def test_frames_on_rotary_axes_are_refused(block):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G17 G90 G71\nG0 X0 A0\n{block}\nG0 X0 A0\nM30\n")
    assert e.value.code == "unsupported_word" and e.value.line == 3


@pytest.mark.parametrize("attrs, body, x", [
    ("SAVE", "G91 G0 X1", 5.0),          # G90 again after the return: X5
    ("", "G91 G0 X1", 6.0),              # without SAVE G91 stays: X5 is 5 more than X1
    ("SAVE DISPLOF", "TRANS X100\nG90 G0 X0", 5.0),  # the frame comes back too
])
def test_proc_save_restores_the_callers_g_functions_and_frame(tmp_path, attrs, body, x):
    (tmp_path / "SVB.SPF").write_text(f"PROC SVB {attrs}\n{body}\nM17\n")
    p = tc.run(tc.Program.parse("G17 G90 G71\nSVB\nG0 X5\nM30\n", "sinumerik"), search_path=[tmp_path]).path
    assert p.end[-1, 0] == x


@pytest.mark.parametrize("block, code, column", [
    ("G1 X10 R5 F100", "unused_word", 8),                   # an R parameter alone
    ("G1 X10 P3 F100", "unused_word", 8),                   # passes without a call
    ("G17 G2 X10 Y0 I5 J0 K3 F100", "14040", 21),           # K is no centre coordinate in G17
    ("G2 X10 Y0 CR=5 AR=90 F100", "14040", 16),             # the circle defined twice
    ("CIP X10 Y0 I1=5 J1=5 CR=5 F100", "14040", 22),
    ("G2 X10 Y0 I5 J0 I1=3 F100", "14040", 17),             # an intermediate point without CIP
    ("CIP X10 Y0 I1=5 J1=5 K1=5 F100", "unsupported_word", 5),    # a circle in space
    ("CIP X10 Y0 Z10 I1=5 J1=5 F100", "unsupported_word", 5),
])
def test_words_a_circle_would_drop_are_refused(block, code, column):
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(f"G0 X0 Y0 Z0\n{block}\nM30\n", dialect="sinumerik"))
    assert (e.value.code, e.value.line, e.value.column) == (code, 2, column)


def test_ct_with_a_centre_is_refused():
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse("G0 X0 Y0\nG1 X5 F100\nCT X10 Y5 I3\nM30\n", dialect="sinumerik"))
    assert (e.value.code, e.value.line) == ("14040", 3)


def test_cip_in_the_working_plane_still_runs():
    # Through (0,0), (5,5), (10,0): the circle about (5,0) of radius 5, clockwise.
    res = tc.run(tc.Program.parse("G0 X0 Y0 Z0\nCIP X10 Y0 I1=5 J1=5 K1=0 F100\nM30\n", dialect="sinumerik"))
    np.testing.assert_allclose(res.nominal.center[-1], [5, 0, 0], atol=1e-12)
    assert res.nominal.kind[-1] == tc.ARC_CW


@pytest.mark.parametrize("block, message", [
    ("G1.5 X2", "12470 G function G1.5 is unknown"),
    ("M1.5", "M1.5 is not an M function"),
    ("M=2.25", "M2.25 is not an M function"),
])
def test_a_code_that_is_no_whole_number_is_quoted_as_written(block, message):
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G0 X1\n" + block + "\nM30\n", dialect="sinumerik"))
    assert (e.value.line, e.value.message) == (2, message)
