"""LinuxCNC's G52: a local offset of the work coordinate system, kept where G92 keeps its
offset (G92.1 cancels it; G92 replaces it). Coordinates are program coordinates, so after
G52 the current point is re-expressed in the offset frame. (The programs were checked
against LinuxCNC's gcode module; the refusals are in tests/programs/errors/*g52*.)"""
import numpy as np
import pytest

import toolcomp as tc


def run(text, dialect="linuxcnc"):
    return tc.run(tc.Program.parse("G21 G90 G94 F300\nG0 X0 Y0 Z0\n" + text + "M2\n", dialect=dialect))


def test_g52_moves_the_origin_and_g92_1_takes_it_back():
    p = run("G52 X5 Y5\nG1 X20 Y5\nG92.1\nG1 X0 Y0\n").path
    # after G52 the machine at (0, 0) is (-5, -5) in the offset frame; X20 Y5 there is
    # (25, 10) without it
    np.testing.assert_allclose(p.start[1, :2], [-5, -5])
    np.testing.assert_allclose(p.end[1, :2], [20, 5])
    np.testing.assert_allclose(p.start[2, :2], [25, 10])
    np.testing.assert_allclose(p.end[2, :2], [0, 0])


def test_g52_axes_not_named_keep_their_offset_and_g52_x0_cancels():
    p = run("G52 X1 Y2\nG52 X0\nG1 X3 Y0\n").path
    np.testing.assert_allclose(p.start[-1, :2], [0, -2])  # Y still offset by 2
    np.testing.assert_allclose(p.end[-1, :2], [3, 0])


def test_g52_in_inch():
    p = tc.run(tc.Program.parse("G20 G90 G94 F30\nG0 X0 Y0 Z0\nG52 X1 Y0.5\nG1 X2 Y1\nM2\n")).path
    np.testing.assert_allclose(p.start[-1, :2], [-25.4, -12.7])
    np.testing.assert_allclose(p.end[-1, :2], [50.8, 25.4])


def test_fanuc_g52_is_refused_as_not_run():
    with pytest.raises(tc.ProgramError, match="G52 is not supported by toolcomp"):
        run("G52 X5\n", dialect="fanuc")

