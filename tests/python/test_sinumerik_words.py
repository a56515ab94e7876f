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
