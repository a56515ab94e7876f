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


def values(body, names):
    """Like read(), named parameters."""
    moves = "".join(f"G0 X#<{n}>\n" for n in names)
    res = tc.run(tc.Program.parse(HEAD + body + "G90 G17\n" + moves + "M2\n"), tools=tc.ToolTable.read(str(TOOLS)))
    return res.path.end[-len(names):, 0].tolist()


def test_mode_parameters():
    body = "G18 G95 G90.1 G98\nT2 M6\nG43\nM4 S100\nM8\nG59.1\nG0 X2 Z0\nG2 X2 Z0 I2 K1 F1\nG7\n"
    names = ["_motion_mode", "_coord_system", "_plane", "_ccomp", "_units_per_rev", "_ijk_absolute_mode",
             "_lathe_diameter_mode", "_tool_offset", "_retract_old_z", "_spindle_on", "_spindle_cw", "_flood",
             "_mist", "_vmajor", "_task"]
    # G7: the X words that read them back are diameters, so every value comes out halved
    got = [2 * v for v in values(body, names)]
    # parameters are read before their block runs: _motion_mode in the first move is the
    # arc's; the G17 before the moves makes _plane 170
    assert got == [20, 591, 170, 400, 1, 1, 1, 1, 1, 1, 0, 1, 0, 2.9, 1]


def test_switches_follow_their_m_codes():
    body = "M49\nM50 P1\nM52\nM53 P0\nM7\n"
    assert values(body, ["_feed_override", "_speed_override", "_adaptive_feed", "_feed_hold", "_mist",
                         "_units_per_minute", "_retract_r_plane", "_line"]) == [1, 0, 1, 0, 1, 1, 1, 16]


def test_position_parameters_are_refused_under_compensation():
    text = HEAD + "T1 M6\nG42 D1\nG1 X10 Y10 F100\n#1=#5421\nG40 G1 X0 Y0\nM2\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text), tools=tc.ToolTable.read(str(TOOLS)))
    assert (e.value.message, e.value.line) == ("Cannot read current position with cutter radius compensation on", 6)


def test_parameter_numbers_within_a_ten_thousandth():
    assert read("#2=5\n#[1.99995]=3\n", [2, 1.00005, 5599]) == [3, 0, 1]
    with pytest.raises(tc.ProgramError, match="Non integer value for integer"):
        read("", [1.0002])
