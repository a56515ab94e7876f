"""LinuxCNC's tool and G92 parameters as a program reads them (each value checked against
LinuxCNC 2.9's gcode module): #5401-#5413 are the tool table's row of the tool in the
spindle, whatever offset is applied; #5211-#5219 keep the G92 offsets through G92.2 and #5210
says whether they are in force."""
import pathlib

import pytest

import toolcomp as tc

TOOLS = pathlib.Path(__file__).resolve().parents[1] / "programs" / "comp" / "tools.tbl"
HEAD = "G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z0\n"


def read(body, names):
    """The values of the parameters `names`, read by a program after `body`."""
    moves = "".join(f"G0 X#{n}\n" for n in names)
    res = tc.run(tc.Program.parse(HEAD + body + moves + "M2\n"), tools=tc.ToolTable.read(str(TOOLS)))
    return res.path.end[-len(names):, 0].tolist()


@pytest.mark.parametrize("body, names, values", [
    # T2: X1 Z30.5 D6; T3: X0.5 Y-0.25 Z40 D12
    ("T2 M6\n", [5400, 5401, 5403, 5410], [2, 1, 30.5, 6]),
    ("T2 M6\nG43 H1\n", [5403], [30.5]),            # the spindle tool's row, not tool 1's applied length
    ("M61 Q3\n", [5401, 5402, 5403, 5410, 5411, 5413], [0.5, -0.25, 40, 12, 0, 0]),
    ("G43.1 Z7\n", [5400, 5403], [0, 0]),           # a dynamic offset is no row of the table
    ("G92 X1 Y2\nG92.2\n", [5211, 5212, 5210], [-1, -2, 0]),
    ("G92 X1 Y2\nG92.2\nG92.3\n", [5211, 5212, 5210], [-1, -2, 1]),
    ("G92 X1 Y2\nG92.1\n", [5211, 5210], [0, 0]),
    ("G92 X0 Y0\n", [5211, 5210], [0, 1]),           # in force although zero
    ("G52 X3\n", [5211, 5210], [3, 1]),
    ("G92.3\n", [5210], [1]),
    ("G92.2\n", [5210], [0]),
])
def test_parameters(body, names, values):
    assert read(body, names) == values
