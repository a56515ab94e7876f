"""What LinuxCNC refuses while cutter radius compensation is on, as it works through a block
(M codes and the plane before G40/G41/G42, the rest after), and its rule that an arc may not
follow G40 before a straight G0/G1 (G28/G30 and canned cycle moves do not count). The cases
that need no tool table are in tests/programs/errors/comp_block_*.ngc and comp_exit_arc_*,
checked against rs274; these need one or are accepted."""
import numpy as np
import pytest

import toolcomp as tc

TOOLS = "T1 P1 D10\nT2 P2 D6\n"
HEAD = "G21 G90 G94 F300\nG0 X0 Y0 Z0\n"


def run(text):
    return tc.run(tc.Program.parse(HEAD + text + "M2\n"), tools=tc.ToolTable.parse(TOOLS, "linuxcnc"))


@pytest.mark.parametrize("block, message", [
    ("G41 D1 G10 L2 P1 X1", "Cannot change the active coordinate system with cutter radius compensation on"),
    ("G41 D1 G43 H1", "Cannot change tool offset with cutter radius compensation on"),
    ("G41 D1 G54", "Cannot change coordinate systems with cutter radius compensation on"),
    ("G41 D1 G30", "Cannot use g28 or g30 with cutter radius comp"),
])
def test_comp_turned_on_in_the_block_refuses_what_follows_it(block, message):
    with pytest.raises(tc.ProgramError) as e:
        run(block + "\nG1 X10 Y0\n")
    assert (e.value.message, e.value.line) == (message, 3)


def test_comp_turned_off_in_the_block_allows_what_follows_it():
    res = run("G41 D1\nG1 X10 Y0\nG1 Y10\nG40 G43 H1 G54 G1 X20 Y10\nG2 X30 Y10 R5\n")
    assert res.path.kind[-1] == tc.ARC_CW


def test_an_arc_right_after_g40_without_a_move_under_compensation_is_allowed():
    # LinuxCNC sets the rule only when compensation moved the tool (rs274 accepts this)
    res = run("G41 D1\nG40\nG2 X10 Y0 R5\n")
    assert res.path.kind[-1] == tc.ARC_CW


def test_g53_straight_moves_count():
    res = run("G41 D1\nG1 X10 Y0\nG40\nG53 G0 X20 Y0\nG2 X30 Y0 R5\n")
    assert res.path.kind[-1] == tc.ARC_CW


def test_a_tool_table_edit_under_compensation_leaves_the_radius_in_effect():
    # LinuxCNC allows G10 L1 while compensating (only L2/L20 of the active system are refused):
    # the radius G41 took stays until the next G41, so the path is the one without the edit.
    edited = run("G41 D1\nG1 X10 Y0\nG10 L1 P1 R3\nG1 Y10\nG40 G0 X20\n")
    plain = run("G41 D1\nG1 X10 Y0\nS1000\nG1 Y10\nG40 G0 X20\n")
    np.testing.assert_array_equal(edited.path.end, plain.path.end)
    assert edited.tools[1].edges[0].radius == 3
    with pytest.raises(tc.ProgramError, match="Cannot change the active coordinate system"):
        run("G41 D1\nG1 X10 Y0\nG10 L20 P1 X3\nG1 Y10\n")


def test_g41_and_g43_in_the_block_of_a_tool_change():
    # T2 (D6) in the spindle, then G41 T1 M6 (D10): the new tool's radius 5, or with
    # tool_change_after_block the old one's 3 (rs274 and the gcode module: (7, 3), (7, 10))
    text = "T2 M6\nG41 T1 M6\nG1 X10 Y0\nG1 Y10\n"
    np.testing.assert_allclose(run(text).path.end[-2:, :2], [[5, 5], [5, 10]], atol=1e-9)
    prof = tc.ControlProfile("linuxcnc")
    prof.tool_change_after_block = True
    res = tc.run(tc.Program.parse(HEAD + text + "M2\n"), tools=tc.ToolTable.parse(TOOLS, "linuxcnc"), profile=prof)
    np.testing.assert_allclose(res.path.end[-2:, :2], [[7, 3], [7, 10]], atol=1e-9)
    lengths = tc.ToolTable.parse("T1 P1 Z10\nT2 P2 Z20\n", "linuxcnc")
    for after, z in ((False, 10), (True, 20)):
        prof.tool_change_after_block = after
        res = tc.run(tc.Program.parse(HEAD + "T2 M6\nT1 M6 G43\nG1 X1\nM2\n"), tools=lengths, profile=prof)
        assert res.path.tool_offset[-1, 2] == z
