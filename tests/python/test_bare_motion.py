"""A motion code without axis words, as LinuxCNC pairs motion codes and axis words
(ControlProfile.bare_motion_codes): G0/G1 alone is a zero-length move, G2/G3 alone needs I/J/K
(a whole circle), I/J/K alone under a modal G2/G3 make an arc, other motion codes alone are
refused. Every number here was checked against LinuxCNC 2.9's gcode module; the refusals that
need no tool table are in tests/programs/errors/bare_*.ngc (checked against rs274 by the
oracle suite)."""
import numpy as np
import pytest

import toolcomp as tc

HEAD = "G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z0\n"


def run(text, dialect="linuxcnc", **kw):
    return tc.run(tc.Program.parse(text, dialect=dialect), **kw)


def test_g1_alone_is_a_zero_length_feed_move():
    p = run(HEAD + "G1 F100\nG1 X1\nG1\nM2\n").path
    assert p.kind.tolist() == [0, 1, 1, 1]
    assert p.line.tolist() == [2, 3, 4, 5]
    assert p.end.tolist() == [[0, 0, 0], [0, 0, 0], [1, 0, 0], [1, 0, 0]]
    assert p.feed[1] == 100


def test_g0_alone_is_a_zero_length_rapid():
    p = run(HEAD + "G0\nM2\n").path
    assert p.kind.tolist() == [0, 0]
    assert p.end[1].tolist() == [0, 0, 0]


def test_g1_alone_with_zero_feed_is_refused():
    with pytest.raises(tc.ProgramError) as e:
        run(HEAD + "G1\nM2\n")
    assert (e.value.message, e.value.line) == ("Cannot do g1 with zero feed rate", 3)


def test_a_motion_code_alone_only_sets_the_mode_on_fanuc():
    p = run(HEAD + "G1 F100\nX1\nG1\nM2\n", dialect="fanuc").path
    assert p.end.tolist() == [[0, 0, 0], [1, 0, 0]]


def test_the_choice_is_a_profile_setting():
    prof = tc.ControlProfile("linuxcnc")
    assert prof.bare_motion_codes
    prof.bare_motion_codes = False
    assert len(run(HEAD + "G1 F100\nX1\nG1\nM2\n", profile=prof).path) == 2


def test_bare_moves_under_compensation_stay_where_the_tool_is():
    # G41 r = 5: X20 then Y10 is an inside corner at (15, 5); the bare G1 and G0 between them
    # are zero-length moves there, and the corner is taken as if they were not there.
    for bare, kind in (("G1", 1), ("G0", 0)):
        text = ("G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z0\nG1 F100 X0\nG41.1 D10 X10 Y0\nX20\n"
                + bare + "\nY10\nM2\n")
        p = run(text).path
        assert p.line.tolist() == [2, 3, 4, 5, 6, 7]
        np.testing.assert_allclose(p.end[3:], [[15, 5, 0], [15, 5, 0], [15, 10, 0]], atol=1e-12)
        assert p.kind[4] == kind


def test_bare_g1_as_the_entry_move_is_too_short():
    text = "G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z0\nG1 F100 X0\nG41.1 D10\nG1\nX10\nM2\n"
    with pytest.raises(tc.CompensationError) as e:
        run(text)
    assert e.value.line == 5
    assert "entry move is not greater than the tool radius" in e.value.message


def test_g2_with_only_its_centre_is_a_whole_circle():
    p = run(HEAD + "G2 I1 F100\nM2\n").path
    assert p.kind[1] == 2
    assert p.end[1].tolist() == [0, 0, 0]
    assert p.center[1].tolist() == [1, 0, 0]
    np.testing.assert_allclose(p.length(), 2 * np.pi)  # the whole circle of r = 1


def test_i_alone_under_a_modal_arc_is_an_arc():
    # from (1, 1) the centre 1 mm along X: a clockwise whole circle about (2, 1)
    p = run(HEAD + "G2 X1 Y1 I0.5 J0.5 F100\nI1\nM2\n").path
    assert p.kind.tolist() == [0, 2, 2]
    assert p.center[2].tolist() == [2, 1, 0]
    assert p.end[2].tolist() == [1, 1, 0]


@pytest.mark.parametrize("text, message, line", [
    (HEAD + "G1 F100 X1\nG2\nM2\n", "R i j k words all missing for arc", 4),
    (HEAD + "G0 Z5\nG81 X1 Y1 Z-1 R2 F100\nG81\nM2\n", "All axes missing with motion code", 5),
    (HEAD + "G93 G1 X1 F1\nG1\nM2\n", "F word missing with inverse time g1 move", 4),
    (HEAD + "G2 X1 Y1 I.5 J.5 F100\nK2\nM2\n", "K word given for arc in xy plane", 4),
    (HEAD + "G1 G92\nM2\n", "Cannot use two g codes that both use axis values", 3),
])
def test_refusals(text, message, line):
    with pytest.raises(tc.ProgramError) as e:
        run(text)
    assert (e.value.message, e.value.line) == (message, line)


def test_g43_1_beside_a_motion_code_gives_the_offset_and_the_move():
    p = run(HEAD + "G1 F100 G43.1 Z3\nM2\n").path
    assert p.end[1].tolist() == [0, 0, 3]
    assert p.tool_offset[1].tolist() == [0, 0, 3]


def test_inverse_time_least_rate():
    # LinuxCNC feeds an inverse-time move at F x length, at least 0.1 program units a minute;
    # a move of rotary axes only is measured in degrees.
    p = run(HEAD + "G93 G1 X1 F1\nG1 F2\nG1 A10 F2\nM2\n").path
    np.testing.assert_allclose(p.feed[1:], [1, 0.1, 20])
    p = run(HEAD.replace("G21", "G20") + "G93 G1 A10 F2\nG1 X1 F2\nG1 X1.001 F2\nM2\n").path
    np.testing.assert_allclose(p.feed[1:], [20 * 25.4, 2 * 25.4, 0.1 * 25.4])


def test_g96_needs_its_s_word():
    with pytest.raises(tc.ProgramError) as e:
        run(HEAD + "S100 M3\nG96 D1000\nM2\n")
    assert (e.value.message, e.value.line) == ("S word missing with G96", 4)


def test_inverse_time_spiral_arc_is_measured_on_its_start_radius():
    # r 5 at the start, 5.02 at the end (within LinuxCNC's spiral tolerance): half a turn on
    # r = 5 is 5 pi; with a rise of 3 and two turns more, hypot(5 * 3 pi, 3).
    p = run(HEAD + "G93 G2 X10.02 Y0 I5 F1\nM2\n").path
    np.testing.assert_allclose(p.feed[1], 5 * np.pi, rtol=1e-12)
    p = run(HEAD + "G93 G3 X10.02 Y0 Z3 I5 P2 F2\nM2\n").path
    np.testing.assert_allclose(p.feed[1], 2 * np.hypot(15 * np.pi, 3), rtol=1e-12)
