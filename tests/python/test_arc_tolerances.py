"""LinuxCNC's arc end-point tolerances as ControlProfile settings.

LinuxCNC 2.9 refuses an arc by its centre when the start and end radius differ by more than
0.0283 mm (0.00283 in) and by more than 0.1 % of the larger radius, or by more than 100 times
0.0283 mm; an R-format chord may exceed 2|R| by 0.00127 mm (0.00005 in). The numbers below are
worked by hand from those rules: a CW arc from (0, 0) about (5, 0) has start radius 5, and an
end at X10.03 has end radius 5.03 (0.03 mm off, 0.6 %).
"""
import math

import pytest

import toolcomp as tc

PROGRAM = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG2 X{end} Y0 I5 J0\nM2\n"


def run(end, profile=None):
    return tc.run(tc.Program.parse(PROGRAM.format(end=end), "linuxcnc"), profile=profile)


def test_linuxcnc_values_are_the_defaults():
    p = tc.ControlProfile("linuxcnc")
    assert p.arc_spiral_abs == pytest.approx((2 * 0.01 * math.sqrt(2), 2 * 0.001 * math.sqrt(2)))
    assert p.arc_spiral_rel == 0.001
    assert p.arc_spiral_hard_factor == 100
    assert p.arc_min_radius == pytest.approx((0.00005 * 25.4, 0.00005))


def test_absolute_tolerance():
    with pytest.raises(tc.ProgramError) as e:
        run(10.03)  # 0.03 mm > 0.0283 mm and 0.6 % > 0.1 %
    assert e.value.code == "arc_end_off_circle" and e.value.line == 4
    assert run(10.02).path.end[-1, 0] == pytest.approx(10.02)  # 0.02 mm: a slight spiral

    loose = tc.ControlProfile("linuxcnc")
    loose.arc_spiral_abs = (0.05, 0.005)
    assert run(10.03, loose).path.end[-1, 0] == pytest.approx(10.03)

    tight = tc.ControlProfile("linuxcnc")
    tight.arc_spiral_abs = (0.01, 0.001)
    with pytest.raises(tc.ProgramError, match="differs from radius to start"):
        run(10.02, tight)


def test_relative_tolerance_and_hard_limit():
    p = tc.ControlProfile("linuxcnc")
    p.arc_spiral_rel = 0.01  # 0.6 % is within 1 %
    assert run(10.03, p).path.end[-1, 0] == pytest.approx(10.03)
    p.arc_spiral_hard_factor = 1  # but 0.03 mm is more than 1 x 0.0283 mm, whatever the radius
    with pytest.raises(tc.ProgramError) as e:
        run(10.03, p)
    assert e.value.code == "arc_end_off_circle"


def test_inch_programs_use_the_second_value():
    # In G20, about (0.5, 0) from (0, 0) to X1.002: radii 0.5 in and 0.502 in, 0.002 in off
    # (0.4 %), within 0.00283 in.
    text = "G20 G90 G17\nG0 X0 Y0 Z0.2\nG1 Z-0.1 F10\nG2 X1.002 Y0 I0.5 J0\nM2\n"

    def run_inch(profile=None):
        return tc.run(tc.Program.parse(text, "linuxcnc"), profile=profile)

    assert run_inch().path.end[-1, 0] == pytest.approx(1.002 * 25.4)
    p = tc.ControlProfile("linuxcnc")
    p.arc_spiral_abs = (0.0283, 0.001)
    with pytest.raises(tc.ProgramError) as e:
        run_inch(p)
    assert e.value.code == "arc_end_off_circle"
    p.arc_spiral_abs = (0.001, 0.00283)  # the mm value does not apply to an inch program
    assert run_inch(p).path.end[-1, 0] == pytest.approx(1.002 * 25.4)


def test_r_format_chord_allowance():
    # Chord 10.001 with R5: half of it exceeds R by 0.0005 mm, within 0.00127 mm: a half circle
    # about the chord's midpoint.
    text = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG2 X10.001 Y0 R5\nM2\n"
    res = tc.run(tc.Program.parse(text, "linuxcnc"))
    assert res.path.center[-1, :2] == pytest.approx([5.0005, 0])
    p = tc.ControlProfile("linuxcnc")
    p.arc_min_radius = (0.0001, 0.00005)
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, "linuxcnc"), profile=p)
    assert e.value.code == "arc_radius_too_small"


@pytest.mark.parametrize("field", ["arc_spiral_rel", "arc_spiral_hard_factor"])
@pytest.mark.parametrize("value", [math.nan, math.inf, -0.1])
def test_bad_values_are_refused(field, value):
    p = tc.ControlProfile("linuxcnc")
    before = getattr(p, field)
    with pytest.raises(ValueError, match=field):
        setattr(p, field, value)
    assert getattr(p, field) == before


@pytest.mark.parametrize("field", ["arc_spiral_abs", "arc_min_radius"])
def test_bad_pairs_are_refused(field):
    p = tc.ControlProfile("linuxcnc")
    with pytest.raises(ValueError, match=field):
        setattr(p, field, (0.01, math.nan))
    with pytest.raises(ValueError, match=field):
        setattr(p, field, (-1, 0.01))


def test_a_refused_pair_changes_neither_value():
    p = tc.ControlProfile("linuxcnc")
    before = p.arc_spiral_abs
    with pytest.raises(ValueError):
        p.arc_spiral_abs = (0.5, -1)
    assert p.arc_spiral_abs == before
