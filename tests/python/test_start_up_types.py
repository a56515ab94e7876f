"""Start-up types on the spec's worked example (1.6.1): S = (-10, -10), G41 G1 X0 Y0, then
X50 Y0, r = 5.

* type A (perpendicular to the next element): S -> (0, 5) -> (50, 5);
* type B (perpendicular to the entry, then the corner rule; Fanuc SUP, 9/Series type B): the
  entry line moved by r to its left, y - 5/sqrt(2) = x + 5/sqrt(2), meets y = 5 at
  x = 5 - 10/sqrt(2): S -> V -> (50, 5);
* LinuxCNC: perpendicular to the entry at (-5/sqrt(2), 5/sqrt(2)), a CW arc about (0, 0) to
  (0, 5).
"""
import math

import numpy as np
import pytest

import toolcomp as tc

TEXT = "G21 G17 G90\nT1 M6\nG0 X-10 Y-10\nG41 G1 X0 Y0 D1 F100\nG1 X50 Y0\nG40 X60 Y-20\nM30\n"
TOOLS = tc.ToolTable.parse("T1 P1 D10\n", "linuxcnc")
H = 5 / math.sqrt(2)


def plane_path(dialect, profile=None):
    p = tc.run(tc.Program.parse(TEXT, dialect), tools=TOOLS, profile=profile).path
    keep = (p.line == 4) | (p.line == 5)
    return p.kind[keep], p.start[keep, :2], p.end[keep, :2]


def test_type_a():
    kind, start, end = plane_path("fanuc")
    np.testing.assert_allclose(start, [[-10, -10], [0, 5]], atol=1e-12)
    np.testing.assert_allclose(end, [[0, 5], [50, 5]], atol=1e-12)


@pytest.mark.parametrize("dialect", ["fanuc", "linuxcnc"])
def test_type_b_meets_the_moved_entry_line(dialect):
    prof = tc.ControlProfile(dialect)
    prof.radius.entry = tc.EntryStyle.perpendicular_to_entry
    prof.radius.outside_corner = tc.OutsideCorner.extension  # the Fanuc rule: intersection up to 90 degrees
    prof.radius.corner_limit = math.pi / 2
    kind, start, end = plane_path(dialect, prof)
    v = [5 - 10 / math.sqrt(2), 5]
    np.testing.assert_allclose(start, [[-10, -10], v], atol=1e-12)
    np.testing.assert_allclose(end, [v, [50, 5]], atol=1e-12)


def test_linuxcnc_arc_round_the_corner():
    kind, start, end = plane_path("linuxcnc")
    np.testing.assert_allclose(end, [[-H, H], [0, 5], [50, 5]], atol=1e-12)
    assert kind[1] == tc.ARC_CW
