"""Cycle time: Path.duration per segment, Path.tool_changes, Result.dwell_time and
Result.cycle_time, from the feeds and the machine's rates (doc/cycle-time.md). Every expected
number is worked by hand: minutes = mm / (mm/min), times 60."""
import math

import numpy as np

import pytest

import toolcomp as tc


def _run(text, dialect="linuxcnc", machine=None, tools=None):
    return tc.run(tc.Program.parse(text, dialect=dialect), tools=tools, machine=machine)


def _machine(control="linuxcnc", kind="mill", **fields):
    m = tc.Machine(control, kind, "test")
    for k, v in fields.items():
        setattr(m, k, v)
    return m


def _tools(*numbers):
    t = tc.ToolTable()
    for n in numbers:
        t.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=3.0, length=[0.0, 0.0, 50.0])]))
    return t


def test_feed_move_takes_its_length_over_its_feed_and_a_dwell_adds_its_seconds():
    res = _run("G21 G90 G94\nG0 X0 Y0 Z0\nG1 X100 F600\nG4 P2.5\nG0 X0\nM2\n")
    d = res.path.duration
    assert d.shape == (3,)
    assert d[0] == 0  # the path starts at the first position: no way there
    assert d[1] == pytest.approx(100 / 600 * 60)  # 10 s
    assert d[2] == pytest.approx(100 / 10000 * 60)  # no machine: rapids at 10 m/min per axis
    assert res.dwell_time == pytest.approx(2.5)
    assert res.cycle_time == pytest.approx(10 + 0.6 + 2.5)


def test_rapid_takes_as_long_as_its_slowest_axis():
    m = _machine(rapid_rate=(5000, 5000, 2000))
    res = _run("G21 G90\nG0 X100 Z-40\nG0 X0 Y50 Z0\nM2\n", machine=m)
    # X 100 / 5000 = Z 40 / 2000 = 0.02 min; then Y 50 / 5000 = 0.01 min < Z 40 / 2000.
    assert res.path.duration == pytest.approx([1.2, 1.2])


def test_axis_max_feed_slows_a_line_by_its_share_of_the_move():
    m = _machine(max_feed=(300, 1000, 1000))
    res = _run("G21 G90 G94\nG1 X100 F600\nG1 Y100 F600\nG1 X200 Y110 F600\nM2\n", machine=m)
    d = res.path.duration
    assert d[0] == pytest.approx(100 / 300 * 60)  # X alone: 300 mm/min, not 600
    assert d[1] == pytest.approx(100 / 600 * 60)  # Y may go 1000: the programmed 600
    # X 100 at most 300 mm/min (20 s) against the path's hypot(100, 10) at 600 (10.05 s)
    assert d[2] == pytest.approx(20.0)


def test_arc_runs_at_its_feed_along_the_arc_capped_by_its_plane_axes():
    text = "G21 G90 G94 G17\nG0 X10 Y0\nG3 X0 Y10 R10 F100\nM2\n"
    quarter = math.pi * 10 / 2  # 15.708 mm
    res = _run(text)
    assert res.path.duration[1] == pytest.approx(quarter / 100 * 60)
    slow = _run(text, machine=_machine(max_feed=(50, 1000, 1000)))
    assert slow.path.duration[1] == pytest.approx(quarter / 50 * 60)


def test_feed_per_revolution_runs_at_feed_times_speed():
    res = _run("G21 G90 G95\nS1000 M3\nG0 X0\nG1 X100 F0.2\nM2\n")  # 0.2 mm/rev * 1000 rev/min
    assert res.path.duration[1] == pytest.approx(100 / 200 * 60)


def test_tool_changes_count_each_new_tool_and_take_the_machine_time():
    text = """G21 G90 G94
T1 M6
G0 X10
G1 X20 F600
T2 M6
G0 X0
T1 M6
G0 X10
M2
"""
    m = _machine(tool_change_time=4.0)
    res = _run(text, machine=m, tools=_tools(1, 2))
    assert res.path.tool_changes == 3
    # From the machine's zero: X10 at 10 m/min 0.06 s, X20 at 600 mm/min 1 s, X0 0.12 s, X10 0.06 s.
    assert res.path.duration.sum() == pytest.approx(1.24)
    assert res.cycle_time == pytest.approx(1.24 + 3 * 4.0)
    # Without a machine the path starts at X10 and a tool change takes no time (counted still).
    plain = _run(text, tools=_tools(1, 2))
    assert plain.path.tool_changes == 3
    assert plain.cycle_time == pytest.approx(1.18)


def test_fanuc_dwell_p_is_milliseconds_and_x_seconds():
    res = _run("O1000\nG21 G90 G94\nG04 P1500\nG04 X2.\nM30\n", dialect="fanuc")
    assert res.dwell_time == pytest.approx(3.5)


def test_canned_cycle_dwell_counts_at_every_hole():
    # LinuxCNC G82: P seconds at the bottom of each of the three holes.
    res = _run("G21 G90 G94 G17\nG0 Z5\nG82 X0 Y0 Z-5 R2 P0.5 F100\nX10\nX20\nG80\nM2\n")
    assert res.dwell_time == pytest.approx(1.5)
    fanuc = _run("O1\nG21 G90 G94 G17\nG0 Z5\nG82 X0 Y0 Z-5 R2 P500 F100\nX10\nG80\nM30\n", dialect="fanuc")
    assert fanuc.dwell_time == pytest.approx(1.0)


def test_sinumerik_dwell_f_seconds_and_s_revolutions():
    res = _run("G71 G90 G94\nS1000 M3\nG4 F3\nG4 S500\nM30\n", dialect="sinumerik")
    assert res.dwell_time == pytest.approx(3 + 500 / 1000 * 60)


def test_heidenhain_dwell_cycle():
    text = """0 BEGIN PGM DW MM
1 CYCL DEF 9.0 DWELL TIME
2 CYCL DEF 9.1 DWELL 1.5
3 L X+10 R0 FMAX
4 END PGM DW MM
"""
    assert _run(text, dialect="heidenhain").dwell_time == pytest.approx(1.5)


def test_machine_file_tool_change_time_reads_and_writes_back():
    m = tc.Machine.parse('control = "fanuc"\nunits = "inch"\n[rates]\nrapid = [1000, 1000, 500]\ntool_change = 3.5\n')
    assert m.tool_change_time == 3.5  # seconds, whatever the units
    assert m.rapid_rate == pytest.approx((25400, 25400, 12700))
    assert tc.Machine.parse(m.dumps()).tool_change_time == 3.5
    with pytest.raises(tc.ParseError, match="tool_change"):
        tc.Machine.parse('control = "fanuc"\n[rates]\ntool_change = -1\n')


HAAS_INCH = """%
O1001 (TWO HOLES, AS A HAAS POST WRITES THEM)
(T1 D=0.25 CARBIDE DRILL)
G20 G17 G40 G49 G80 G90
T1 M06
G00 G90 G54 X1. Y1. S2000 M03
G43 H01 Z1. M08
G81 G98 Z-0.5 R0.1 F10.
X2.
G80
G00 Z1. M09
G28 G91 Z0.
M30
%
"""


def test_an_inch_haas_program_on_its_machine():
    m = _machine("fanuc", work_origin=(-400.0, -200.0, -500.0), rapid_rate=(25400, 25400, 25400),
                 tool_change_time=4.0)
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=3.175, length=[0.0, 0.0, 50.0])]))
    res = _run(HAAS_INCH, dialect="fanuc", machine=m, tools=t)
    p = res.path
    # The bottom of the first hole: X1 Y1 Z-0.5 in, G54 and the 50 mm tool added.
    bottom = p.machine_end[np.isclose(p.end[:, 2], -12.7)][0]
    assert bottom == pytest.approx([25.4 - 400, 25.4 - 200, -12.7 - 500 + 50])
    # From machine zero, program (400, 200, 500): rapids at 25.4 m/min take the longest axis.
    rapid = lambda mm: mm / 25400 * 60  # noqa: E731
    moves = (rapid(400 - 25.4)               # G00 X1. Y1.
             + rapid(450 - 25.4)             # G43 H01 Z1.: from Z 500 - 50
             + 2 * (rapid(25.4 - 2.54)       # down to R0.1
                    + 15.24 / 254 * 60       # feed 0.6 in at 10 in/min
                    + rapid(25.4 + 12.7))    # G98: back to the initial Z1.
             + rapid(25.4)                   # X2.
             + rapid(450 - 25.4))            # G28 G91 Z0.: machine Z0, program Z 500 - 50
    assert p.duration.sum() == pytest.approx(moves)
    assert res.cycle_time == pytest.approx(moves + 4.0)  # one tool change
