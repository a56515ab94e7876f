"""Sinumerik programs at the edges: a radius near the largest double (CR=1EX300) still gives a
finite centre (as LinuxCNC's R1e300 does), and an address letter without its value (a file cut
short after "Y") is a syntax error, not a call of a subprogram named Y."""
import math

import numpy as np
import pytest

import toolcomp as tc

HEAD = "G17 G90 G71\nG0 X0 Y0 Z5\nG1 Z-1 F100\n"


def test_cr_1ex300_has_a_finite_centre():
    # Chord (0,0)-(10,0), G2 with CR > 0 (at most 180 degrees): centre right of the chord,
    # h = R*sqrt(1 - (5/R)^2) = 1e300 -> centre (5, -1e300).
    res = tc.run(tc.Program.parse(HEAD + "G2 X10 Y0 CR=1EX300\nM30\n", dialect="sinumerik"))
    arc = np.flatnonzero(res.path.kind == tc.ARC_CW)
    assert len(arc) == 1
    c = res.path.center[arc[0]]
    assert np.isfinite(c).all()
    assert c[0] == pytest.approx(5)
    assert c[1] == pytest.approx(-1e300)
    np.testing.assert_array_equal(res.path.end[arc[0], :2], [10, 0])


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
