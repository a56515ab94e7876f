"""Sinumerik programs at the edges: a radius near the largest double (CR=1EX300) still gives a
finite centre (as LinuxCNC's R1e300 does), and an address letter without its value (a file cut
short after "Y") is a syntax error, not a call of a subprogram named Y."""
import math

import numpy as np
import pytest

import toolcomp as tc

HEAD = "G17 G90 G71\nG0 X0 Y0 Z5\nG1 Z-1 F100\n"


def test_cr_1ex300_is_refused():
    # Chord (0,0)-(10,0), G2 with CR=1e300: the centre (5, -1e300) is a finite number, but
    # the ends lie 1e-299 rad apart on the circle, which the angle cannot resolve: the arc
    # would be cut as a full circle of 6e300 mm.
    text = HEAD + "G2 X10 Y0 CR=1EX300\nM30\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="sinumerik"))
    assert (e.value.code, e.value.line) == ("arc_radius_too_large", 4)


@pytest.mark.parametrize("text, line, column", [
    (HEAD + "G1 Y", 4, 4),
    (HEAD + "G1 X Y10\nM30\n", 4, 4),
    (HEAD + "G1 X10\nG\nM30\n", 5, 1),
])
def test_address_without_value_is_a_syntax_error(text, line, column):
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(text, dialect="sinumerik")
    assert (e.value.code, e.value.line, e.value.column) == ("syntax_error", line, column)


def test_subprogram_names_are_still_calls():
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(HEAD + "NOSUCHSUB\nM30\n", dialect="sinumerik"))
    assert e.value.message.startswith("14011")
