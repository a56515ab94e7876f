"""Values that overflow are refused with the block's line, never carried into the path as
infinity or NaN; a huge iter_run chunk is not asked for at once."""
import math

import pytest

import toolcomp as tc


@pytest.mark.parametrize("text, line", [
    ("G21 G0 X0\nG91 G1 X[10**308] F10\nX[10**308]\nM2\n", 3),      # G91 sums past the doubles
    ("G20 G0 X0\nG1 X[10**307] F10\nM2\n", 2),                       # inch to mm
    ("G21 G0 X0\nG95 S[10**200] G1 X10 F[10**200]\nM2\n", 2),        # feed F x S
])
def test_overflowing_moves_are_refused(text, line):
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text))
    assert e.value.code == "not_finite" and e.value.line == line
    res = tc.run(tc.Program.parse(text), strict=False)  # the path up to the block
    assert all(math.isfinite(v) for v in res.path.end.ravel())


def test_sinumerik_inch_overflow():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("R1=1EX308\nG70 G1 X=R1 F100\nM30\n", "sinumerik"))
    assert e.value.code == "not_finite" and e.value.line == 2


def test_tool_values_must_be_finite():
    with pytest.raises(tc.ToolTableError) as e:  # 1e308 inch is infinite in mm
        tc.ToolTable.parse("tool,z,diameter\n1,1e308,10\n", "csv", units="inch")
    assert e.value.code == "tool_bad_value"
    with pytest.raises(tc.ToolTableError):  # length + wear
        tc.ToolTable.parse("tool,z,z_wear,diameter\n1,1e308,1e308,10\n", "csv")
    edge = tc.CuttingEdge(number=1)
    edge.radius = float("nan")
    tool = tc.Tool(1)
    tool.set_edge(edge)
    table = tc.ToolTable("mm")
    with pytest.raises(tc.ToolTableError) as e:
        table.set(tool)
    assert e.value.code == "tool_bad_value" and 1 not in table.numbers


def test_a_huge_chunk_is_filled_as_it_comes():
    chunks = list(tc.iter_run(tc.Program.parse("G21 G0 X1\nG0 X2\nM2\n"), chunk=2**31))
    assert [len(c) for c in chunks] == [2]
    with pytest.raises(ValueError, match="piece_bytes"):
        tc.iter_run(tc.Program.parse("G21 G0 X1\nM2\n"), piece_bytes=2**40)


@pytest.mark.parametrize("field, value", [("wear_sign", 7.0), ("radius.overcut_neighbours", 10**9)])
def test_profile_ranges(field, value):
    p = tc.ControlProfile("rockwell")
    obj, name = (p.radius, field.split(".")[1]) if "." in field else (p, field)
    setattr(obj, name, value)
    with pytest.raises(ValueError, match=name):
        tc.run(tc.Program.parse("G21 G0 X1\nM2\n"), profile=p)
