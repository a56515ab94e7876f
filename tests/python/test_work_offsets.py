"""G10 L2/L20 as LinuxCNC takes them (each case checked against LinuxCNC 2.9's gcode module):
an L20 giving only X or Y of a rotated system moves the origin's X and Y both (the other axis
keeps the current point's coordinate in that system), and P rounds the way LinuxCNC rounds
it. Positions are observed through G53 moves (machine coordinates)."""
import numpy as np
import pytest

import toolcomp as tc

HEAD = "G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z0\n"


def run(text):
    return tc.run(tc.Program.parse(HEAD + text + "M2\n"))


def test_l20_x_only_in_the_active_rotated_system():
    # G54 turned 90 deg; at program (3, 4) the machine is at (-4, 3). L20 X0 keeps Y = 4:
    # origin = (-4, 3) - rot90(0, 4) = (0, 3). The next Z move stays at program (0, 4); the
    # machine's (0, 0) is program rot-90((0, 0) - (0, 3)) = (-3, 0).
    p = run("G10 L2 P1 R90\nG0 X3 Y4\nG10 L20 P1 X0\nG0 Z1\nG53 G0 X0 Y0\n").path
    np.testing.assert_allclose(p.end[-2], [0, 4, 1], atol=1e-12)
    np.testing.assert_allclose(p.end[-1], [-3, 0, 1], atol=1e-12)


def test_l20_y_only_in_the_active_rotated_system():
    # the same with Y0: X keeps 3, origin = (-4, 3) - rot90(3, 0) = (-4, 0)
    p = run("G10 L2 P1 R90\nG0 X3 Y4\nG10 L20 P1 Y0\nG0 Z1\n").path
    np.testing.assert_allclose(p.end[-1], [3, 0, 1], atol=1e-12)


def test_l20_x_only_in_another_rotated_system():
    # G54 plain, machine at (3, 4); G55 turned 90 deg with origin 0: the point is (4, -3)
    # there. L20 P2 X0 -> (0, -3): origin = (3, 4) - rot90(0, -3) = (0, 4); in G55 the
    # point reads (0, -3).
    p = run("G10 L2 P2 R90\nG0 X3 Y4\nG10 L20 P2 X0\nG55 G0 Z1\n").path
    np.testing.assert_allclose(p.end[-1], [0, -3, 1], atol=1e-12)


@pytest.mark.parametrize("p, system", [("1.9999", 2), ("0.99999", 1), ("1.5", 1), ("-0.4", 0), ("2.00009", 2)])
def test_g10_p_rounding(p, system):
    # G10 L2 P.. X5: in the system it names, X0 is machine X5 (P0: the active one, G54)
    text = f"G10 L2 P{p} X5\n" + ("G55\n" if system == 2 else "") + "G0 X0\nG53 G0 X0\n"
    path = run(text).path
    assert path.end[-2][0] == 0
    assert path.end[-1][0] == -5   # machine X0 is program X-5 in the shifted system


@pytest.mark.parametrize("p", ["9.5", "9.9999"])
def test_g10_p_rounding_out_of_range(p):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G10 L2 P{p} X5\n")
    assert (e.value.message, e.value.line) == ("P value out of range (0-9) with G10 L2", 3)


COMP = "T1 M6\nG0 X-10 Y0 Z0\nG41.1 D2 G1 X0 F100\n"


@pytest.mark.parametrize("code", ["G28.1", "G30.1"])
def test_setting_a_reference_point_under_compensation_is_refused(code):
    with pytest.raises(tc.ProgramError) as e:
        run(COMP + code + "\nG40 G1 X-20\n")
    assert (e.value.message, e.value.line) == ("Cannot set reference point with cutter compensation in effect", 6)
    assert len(run(COMP + "G40 " + code + "\nG1 X-20\n").path) == 4


def test_m61_under_compensation_is_refused():
    # LinuxCNC 2.9 takes it and loses the held move (the next corner becomes a spiral arc)
    with pytest.raises(tc.ProgramError) as e:
        run(COMP + "M61 Q2\nG1 X20\nG40 G1 X30\n")
    assert e.value.line == 6 and e.value.code == "comp_m61"
