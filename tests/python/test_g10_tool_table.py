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


def test_g10_l10_and_l11_stay_refused_by_name():
    for l in (10, 11):
        with pytest.raises(tc.ProgramError) as e:
            tc.run(tc.Program.parse(f"G21\nG10 L{l} P2 Z0\nM2\n"), tools=_tools())
        assert e.value.code == "unsupported_g10" and "not supported by toolcomp" in str(e.value)
