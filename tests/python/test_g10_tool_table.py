"""LinuxCNC G10 L1: a program editing the tool table. The run edits its own copy (Result.tools);
the table passed in is never changed. Paths are compared with rs274 in
tests/programs/oracle/g10_l1_tool_table.ngc; here the copy, the radius a later G41 takes, and
LinuxCNC's refusals (messages from its convert_setup_tool)."""
import numpy as np
import pytest

import toolcomp as tc


def _tools():
    t = tc.ToolTable()
    t.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=3.0, length=[1.0, 0.0, 30.5])]))
    return t


def test_the_run_edits_its_copy_and_returns_it():
    tools = _tools()
    res = tc.run(tc.Program.parse("G21 T2 M6\nG10 L1 P2 R1.25 Z12 Q3 I80 J10\nM2\n"), tools=tools)
    edge = res.tools[2].edges[0]
    assert (edge.radius, list(edge.length), edge.orientation, edge.front_angle, edge.back_angle) == \
        (1.25, [1.0, 0.0, 12.0], 3, 80.0, 10.0)
    assert tools[2].edges[0].radius == 3.0 and list(tools[2].edges[0].length) == [1.0, 0.0, 30.5]
    assert tc.run(tc.Program.parse("G21 G0 X1\nM2\n"), tools=tools).tools is None
    # inch: R0.1 is 2.54 mm in the table
    res = tc.run(tc.Program.parse("G20 G10 L1 P2 R0.1\nM2\n"), tools=tools)
    assert res.tools[2].edges[0].radius == pytest.approx(2.54, abs=1e-12)


def test_a_later_g41_takes_the_new_radius():
    # G41 D2 after R1 (was 3): the path along +X at Y0 is 1 mm to its left (Y1).
    text = "G21 G17 G0 X-10 Y0 Z0\nG10 L1 P2 R1\nG41 D2 G1 X0 Y0 F100\nX20\nG40 G0 X30 Y10\nM2\n"
    res = tc.run(tc.Program.parse(text), tools=_tools())
    np.testing.assert_allclose(res.path.end[res.path.line == 4][-1][:2], (20, 1), atol=1e-12)


@pytest.mark.parametrize("block, message", [
    ("G10 L1 P2", "G10 L1 without offsets has no effect"),
    ("G10 L1 P2 Q10", "Invalid tool orientation"),
    ("G10 L1 P2 Q1.5", "Q number in G10 is not an integer"),
    ("G10 L1 P9 R1", "Requested tool 9 not found in the tool table"),
])
def test_what_linuxcnc_refuses(block, message):
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(f"G21\n{block}\nM2\n"), tools=_tools())
    assert (str(e.value.message), e.value.line) == (message, 2)


def _edge(res, n):
    return res.tools[n].edges[0]


def test_l10_sets_the_offset_that_makes_here_read_the_word():
    # G54 (25, 50, 75), T1 (Z25) with G43, the tool at Z37.5, G92 Z12.5 (a 25 mm shift):
    # L10 P1 Z5 = 12.5 (the point) + 25 (the offset in effect) - 5 = 32.5; G5x and G92 cancel out.
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, 25.0])]))
    tools.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=3.0, length=[1.0, 0.0, 30.5])]))
    text = ("G21 G10 L2 P1 X25 Y50 Z75\nG10 L2 P9 X0 Y0 Z-50\nG54 T1 M6\nG43\nG0 X7.5 Y10 Z37.5\nG92 Z12.5\n"
            "G10 L10 P1 Z5\nG10 L11 P2 X0 Z0\nM2\n")
    res = tc.run(tc.Program.parse(text), tools=tools)
    assert _edge(res, 1).length[2] == pytest.approx(32.5, abs=1e-12)
    # L11: the machine point (X 7.5 + 25 = 32.5; Z 12.5 + 25 + 75 + 25 = 137.5) less G59.3 (0, 0, -50)
    assert list(_edge(res, 2).length) == pytest.approx([32.5, 0.0, 187.5], abs=1e-12)
    assert res.nominal.tool_offset[-1].tolist() == [0, 0, 25.0]  # in effect until G43 takes it again


def test_l10_in_a_rotated_system_turns_x_and_y():
    # LinuxCNC's own g10-l1-l10 test: G54 turned 45 degrees, tool 1 at the origin, offsets zero.
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=1.0, length=[0.0, 0.0, 0.0])]))
    res = tc.run(tc.Program.parse("G21 G10 L2 P1 R45\nG54 T1 M6\nG10 L10 P1 X1\nM2\n"), tools=tools)
    h = 0.5 ** 0.5
    assert list(_edge(res, 1).length[:2]) == pytest.approx([-h, -h], abs=1e-12)
    res = tc.run(tc.Program.parse("G21 G10 L2 P1 R45\nG54 T1 M6\nG10 L10 P1 X1\nG10 L10 P1 Y1\nM2\n"),
                 tools=tools)  # Y alone keeps the part along the turned X: (0, -2 h)
    assert list(_edge(res, 1).length[:2]) == pytest.approx([0.0, -2 * h], abs=1e-12)


def test_in_diameter_mode_x_is_a_diameter():
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=0.4, length=[0.0, 0.0, 0.0])]))
    res = tc.run(tc.Program.parse("G21 G18 G7 T1 M6\nG0 X20 Z0\nG10 L10 P1 X10\nM2\n"), tools=tools)
    assert _edge(res, 1).length[0] == pytest.approx(5.0)  # the tool at radius 10, the word a 5 mm radius
    res = tc.run(tc.Program.parse("G21 G18 G7 T1 M6\nG10 L1 P1 X10\nM2\n"), tools=tools)
    assert _edge(res, 1).length[0] == pytest.approx(5.0)


def test_g10_l0_reloads_the_table_only_without_a_tool_in_the_spindle():
    # the run's table is the file's (a G10 L1 edit is in it): G10 L0 changes nothing; with a tool
    # loaded LinuxCNC refuses it ("G10 L0 not allowed with loaded tool <2>", rs274)
    res = tc.run(tc.Program.parse("G21\nG10 L1 P2 R1\nG10 L0\nM2\n"), tools=_tools())
    assert res.tools[2].edges[0].radius == 1.0
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 T2 M6\nG10 L0\nM2\n"), tools=_tools())
    assert (str(e.value.message), e.value.line) == ("G10 L0 not allowed with loaded tool <2>", 2)
