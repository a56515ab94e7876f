"""Machine coordinates: Path.work_offset, Path.work_rotation and Path.machine_end, so that
machine = Rz(work_rotation) end + work_offset + tool_offset in every dialect. The machine's
work origin, G92, G10 and the tool lengths are chosen so that each number is worked by hand."""
import numpy as np
import pytest

import toolcomp as tc


def _tools(length=50.0, radius=3.0):
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=radius, length=[0.0, 0.0, length])]))
    return t


def _machine(control, origin=(-400.0, -200.0, -500.0)):
    m = tc.Machine(control, "mill", "test")
    m.work_origin = origin
    return m


def _run(text, dialect, machine=None, tools=None, **kw):
    return tc.run(tc.Program.parse(text, dialect=dialect), tools=tools or _tools(), machine=machine, **kw)


def test_linuxcnc_machine_end_adds_g54_g92_and_the_tool_length():
    text = "G21 G90\nT1 M6\nG43 H1\nG0 X10 Y20 Z5\nG92 X0\nG1 X5 F100\nM2\n"
    p = _run(text, "linuxcnc", _machine("linuxcnc")).path
    # X10 Y20 Z5 with G54 at (-400, -200, -500) and the tool 50 long: the spindle's gauge
    # point at X-390 Y-180 Z-445.
    assert p.machine_end[0] == pytest.approx([-390, -180, -445])
    # G92 X0 at X10 makes the G92 offset 10: X5 is machine X 5 + 10 - 400.
    assert p.work_offset[1] == pytest.approx([-390, -200, -500])
    assert p.machine_end[1] == pytest.approx([-385, -180, -445])
    assert (p.work_rotation == 0).all()


def test_linuxcnc_work_rotation_turns_the_end_before_the_offset():
    text = "G21 G90\nG92 X-10\nG10 L2 P1 X-400 Y-200 R90\nG0 X0 Y5\nM2\n"
    p = _run(text, "linuxcnc").path
    # At machine zero G92 X-10 gives the offset 10; rotated 90 degrees it lies along Y.
    assert p.work_rotation[0] == 90
    assert p.work_offset[0] == pytest.approx([-400, -190, 0])
    # (0 + 10, 5) turned 90 degrees is (-5, 10); plus G54: (-405, -190).
    assert p.machine_end[0] == pytest.approx([-405, -190, 0])


def test_linuxcnc_g55_from_the_parameters():
    text = "G21 G90\nG55\nG0 X1 Y2 Z3\nM2\n"
    p = _run(text, "linuxcnc", parameters={5241: 100.0, 5242: 50.0, 5243: -25.0}).path
    assert p.work_offset[0] == pytest.approx([100, 50, -25])
    assert p.machine_end[0] == pytest.approx([101, 52, -22])


def test_inch_program_offsets_in_mm():
    text = "G20 G90\nG10 L2 P1 X1 Y2 Z-3\nG0 X1 Y1 Z1\nM2\n"
    p = _run(text, "linuxcnc").path
    assert p.work_offset[0] == pytest.approx([25.4, 50.8, -76.2])
    assert p.machine_end[0] == pytest.approx([50.8, 76.2, -50.8])


def test_compensated_path_keeps_the_offsets_of_its_blocks():
    text = """G21 G90 G17
T1 M6
G43 H1
G0 X-20 Y-20 Z5
G41 D1 G1 X0 Y0 F500
G1 Y40
G1 X40
G40 G1 X60 Y60
M2
"""
    p = _run(text, "linuxcnc", _machine("linuxcnc")).path
    assert p.generated.any()  # the corner arc is in the path, with the offsets of its block
    assert np.allclose(p.work_offset, [-400, -200, -500])
    assert np.allclose(p.machine_end, p.end + p.work_offset + p.tool_offset)


def test_fanuc_g54_from_the_machine_file():
    text = "O1000\nG21 G90 G54\nT1 M06\nG43 H1 Z10.\nG00 X5. Y6.\nM30\n"
    p = _run(text, "fanuc", _machine("fanuc")).path
    assert p.machine_end[-1] == pytest.approx([-395, -194, -440])


def test_sinumerik_machine_end_with_a_frame_and_the_tool():
    text = "G71 G90 G54\nT1\nM6\nD1\nTRANS X5\nG0 X10 Y20 Z5\nM30\n"
    p = _run(text, "sinumerik", _machine("sinumerik")).path
    # The path is in the machine's axes less the work origin: TRANS is in it (X 15).
    assert p.end[-1] == pytest.approx([15, 20, 5])
    assert p.work_offset[-1] == pytest.approx([-400, -200, -500])
    assert p.machine_end[-1] == pytest.approx([-385, -180, -445])


def test_heidenhain_machine_end_from_the_preset():
    text = """0 BEGIN PGM MC MM
1 TOOL CALL 1 Z S3000
2 L X+10 Y+20 Z+5 R0 FMAX
3 END PGM MC MM
"""
    p = _run(text, "heidenhain", _machine("heidenhain")).path
    assert p.machine_end[-1] == pytest.approx([-390, -180, -445])


def test_without_a_machine_machine_end_is_end_plus_tool_offset():
    text = "G21 G90\nT1 M6\nG43 H1\nG0 X10 Y20 Z5\nM2\n"
    p = _run(text, "linuxcnc").path
    assert (p.work_offset == 0).all()
    assert p.machine_end[-1] == pytest.approx([10, 20, 55])
