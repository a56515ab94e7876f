"""Arcs that no control cuts as written are refused at their block, in every dialect: turn
counts beyond what the path's turns column holds (and beyond the Sinumerik's TURN limit of
999999), and radii so large that the arc's length is not a number or its end cannot be told
from its start on the circle."""
import math

import numpy as np
import pytest

import toolcomp as tc


def _error(text, dialect="linuxcnc"):
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect=dialect))
    return e.value


@pytest.mark.parametrize("p", ["3000000000", "[10**12]", "1000001"])
def test_turn_counts_beyond_the_limit_are_refused(p):
    e = _error(f"G21 G17 G90 G0 X0 Y0\nG3 X10 Y0 I5 J0 P{p} F100\nM2\n")
    assert (e.code, e.line) == ("arc_too_many_turns", 2)
    profile = tc.ControlProfile("fanuc")  # Fanuc arcs take no P: with LinuxCNC's reading, the same limit
    profile.arc_turns_word = True
    text = f"G21 G17 G90 G0 X0 Y0\nG3 X10 Y0 I5 J0 P{p if p[0] != '[' else '1000000000000'} F100\nM30\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), profile=profile)
    assert (e.value.code, e.value.line) == ("arc_too_many_turns", 2)


@pytest.mark.parametrize("dialect", ["fanuc", "rockwell"])
def test_a_p_on_an_arc_of_a_control_without_turn_counts_is_refused(dialect):
    # A Fanuc G02 has no P: reading it as LinuxCNC's turns cut two circles where the control
    # cuts one (or alarms).
    e = _error("G21 G17 G90 G0 X0 Y0\nG2 X10 Y0 I5 J0 P2 F100\nM30\n", dialect)
    assert (e.code, e.line, e.column) == ("unused_word", 2, 17)


def test_the_largest_turn_count_runs():
    # P1000000: 999999 extra turns of a 5 mm circle plus the half turn to X10.
    res = tc.run(tc.Program.parse("G21 G17 G90 G0 X0 Y0\nG3 X10 Y0 I5 J0 P1000000 F100\nM2\n"))
    assert res.path.turns[-1] == 999_999
    assert res.path.length() == pytest.approx(5 * math.pi * (2 * 999_999 + 1), rel=1e-12)


def test_sinumerik_turn_limit():
    e = _error("G17 G90 G0 X0 Y0\nG3 X10 Y0 I5 J0 TURN=1000000 F100\nM30\n", "sinumerik")
    assert e.code == "14040" and e.line == 2
    res = tc.run(tc.Program.parse("G17 G90 G0 X0 Y0\nG3 X10 Y0 I5 J0 TURN=999999 F100\nM30\n", dialect="sinumerik"))
    assert res.path.turns[-1] == 999_999


@pytest.mark.parametrize("r", ["[10**300]", "[10**200]"])
def test_radii_whose_geometry_overflows_are_refused(r):
    text = f"G21 G17 G90 G0 X0 Y0\nG2 X1 Y0 R{r} F100\nM2\n"
    e = _error(text)
    assert (e.code, e.line) == ("arc_radius_too_large", 2)
    res = tc.run(tc.Program.parse(text), strict=False)  # the path up to the block: the rapid
    assert len(res.path) == 1 and np.isfinite(res.path.length())


def test_a_radius_whose_circle_cannot_see_the_chord_is_refused():
    # R 1e15 mm for a 1 mm chord: the two ends lie 1e-15 rad apart on the circle, below what
    # the angle can resolve, so the arc would be a full circle of 6.3e15 mm.
    e = _error("G21 G17 G90 G0 X0 Y0\nG2 X1 Y0 R[10**15] F100\nM2\n")
    assert (e.code, e.line) == ("arc_radius_too_large", 2)


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_a_slightly_spiral_full_circle_still_runs(dialect):
    # From (10, 0) about (0, 0) to (10.0005, 0): the end on the start's ray, 0.0005 further
    # out (within the spiral tolerance): a full circle, as LinuxCNC cuts it. Its length: the
    # mean radius 10.00025 times 2 pi.
    res = tc.run(tc.Program.parse("G21 G17 G0 X10 Y0\nG2 X10.0005 Y0 I-10 J0 F100\nM30\n", dialect=dialect))
    assert res.nominal.length(include_rapids=False) == pytest.approx(2 * math.pi * 10.00025, rel=1e-12)


def test_a_flat_arc_of_large_radius_still_runs():
    # R 100 m over a 1 mm chord: sagitta 1.25e-9 mm; the arc is the chord, 1 mm long
    # (r * 2 asin(c / 2r) = 1 + c^3 / (24 r^2) = 1 + 4.2e-12).
    res = tc.run(tc.Program.parse("G21 G17 G90 G0 X0 Y0\nG2 X1 Y0 R100000 F100\nM2\n"))
    assert res.path.length(include_rapids=False) == pytest.approx(1 + 1 / (24 * 1e10), abs=1e-9)


def test_a_programmed_full_circle_runs():
    res = tc.run(tc.Program.parse("G21 G17 G90 G0 X10 Y0\nG3 X10 Y0 I-10 J0 F100\nM2\n"))
    assert res.path.length(include_rapids=False) == pytest.approx(20 * math.pi, rel=1e-15)


@pytest.mark.parametrize("q, line", [("10 ^ 300", 4), ("1000000 * 1000000 * 1000000 * 1000000 * 1000000 * 1000000", 4)])
def test_heidenhain_cr_with_an_absurd_radius_is_refused(q, line):
    text = f"BEGIN PGM A MM\nQ1 = {q}\nL X+1 Y+0 R0 F100\nCR X+0 Y+1 R+Q1 DR+\nEND PGM A MM\n"
    e = _error(text, "heidenhain")
    assert (e.code, e.line) == ("arc_radius_too_large", line)
