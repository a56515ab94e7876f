"""Where a path starts: without a machine, each axis where the program first sends it; with
a machine, at the machine's start (its zero unless its file says otherwise); start= says it
for a run. Numbers worked by hand from the programs."""
import math

import numpy as np
import pytest

import toolcomp as tc
from toolcomp.testing import assert_within

BRACKET_HEAD = """G21 G17 G90 G94 G54 G40 G49
T1 M6
G0 G43 H1 Z50
S8000 M3
G0 X-20 Y-20
G0 Z5
G1 Z-6 F300
M2
"""


def _tools(length=50.0):
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, length])]))
    return t


def _run(text, dialect="linuxcnc", **kw):
    return tc.run(tc.Program.parse(text, dialect=dialect), tools=_tools(), **kw)


def test_without_a_machine_each_axis_starts_where_the_program_first_sends_it():
    p = _run(BRACKET_HEAD).path
    # Z is first sent to 50 (after G43 H1), X and Y to -20: the first two rapids have no length.
    assert p.start[0].tolist() == [-20, -20, 50]
    assert p.end[:2].tolist() == [[-20, -20, 50], [-20, -20, 50]]
    assert p.end[2:].tolist() == [[-20, -20, 5], [-20, -20, -6]]
    # The tool never goes below the program's lowest point (with machine zero it started at Z-50).
    assert_within(p, ((-20, -20, -6), (-20, -20, 50)))


def test_machine_zero_start_is_linuxcncs():
    p = _run(BRACKET_HEAD, start="machine_zero").path
    # rs274 starts at machine zero; G43 H1 takes the program Z to -50 where the machine stands.
    assert p.start[0].tolist() == [0, 0, -50]
    assert p.end[1].tolist() == [-20, -20, 50]


def test_a_start_in_machine_coordinates():
    m = tc.Machine("linuxcnc", "mill", "m")
    m.work_origin = (-300.0, -200.0, -400.0)
    p = _run(BRACKET_HEAD, machine=m).path
    # With a machine the run starts at its zero: program Z = 0 + 400 - 50.
    assert p.start[0].tolist() == [300, 200, 350]
    m.start = (-100.0, -50.0, 0.0)
    p = _run(BRACKET_HEAD, machine=m).path
    assert p.start[0].tolist() == [200, 150, 350]
    p = _run(BRACKET_HEAD, machine=m, start=(-300, -200, -350)).path
    assert p.start[0].tolist() == [0, 0, 0]


def test_incremental_first_moves_and_axes_never_set():
    # X is first set incrementally (+10 from where it stands), Y never: X starts where its
    # move ends, Y at the machine's zero.
    p = _run("G21 G91 G0 X10\nG90 G0 Z5\nG1 X20 F100\nM2\n").path
    assert p.start[0].tolist() == [10, 0, 5]
    assert p.end[2].tolist() == [20, 0, 5]


def test_the_start_stops_looking_at_radius_compensation():
    # Z is first named under G41: what compensation does must not depend on a guessed start,
    # so Z stays at the machine's zero.
    text = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX20\nZ-1\nY20\nG40 G0 X-10 Y30\nM2\n"
    p = tc.run(tc.Program.parse(text, dialect="linuxcnc")).nominal
    assert p.start[0].tolist() == [0, -10, 0]
    assert p.end[3].tolist() == [20, 0, -1]


def test_a_first_arc_keeps_the_machine_zero():
    p = _run("G21 G17 G90\nG2 X10 Y0 I5 J0 F100\nM2\n").path
    assert p.start[0].tolist() == [0, 0, 0]
    assert p.center[0].tolist() == [5, 0, 0]


def test_sinumerik_and_heidenhain_start_at_their_first_positions():
    mpf = "G71 G90 G54\nT1\nM6\nD1\nG0 X30 Y40\nG0 Z10\nG1 Z-2 F200\nM30\n"
    p = tc.run(tc.Program.parse(mpf, dialect="sinumerik"), tools=_tools()).path
    assert p.start[0].tolist() == [30, 40, 10]
    h = """0 BEGIN PGM S MM
1 TOOL CALL 1 Z S3000
2 L Z+100 R0 FMAX
3 L X+30 Y+40 R0 FMAX
4 L Z-2 F200
5 END PGM S MM
"""
    p = tc.run(tc.Program.parse(h, dialect="heidenhain"), tools=_tools()).path
    # The first two positioning moves have no length: the TNC makes none.
    assert p.start[0].tolist() == [30, 40, 100]
    assert p.end.tolist() == [[30, 40, -2]]


def test_iter_run_and_run_file_start_the_same_way(tmp_path):
    f = tmp_path / "part.ngc"
    f.write_text(BRACKET_HEAD)
    whole = tc.run(f, tools=_tools()).path
    with tc.iter_run(f, _tools(), chunk=2) as stream:
        chunks = list(stream)
    np.testing.assert_array_equal(np.concatenate([c.start for c in chunks]), whole.start)
    assert whole.start[0].tolist() == [-20, -20, 50]


def test_a_bad_start_is_refused():
    with pytest.raises(ValueError, match="start"):
        _run(BRACKET_HEAD, start="home")
    with pytest.raises(ValueError, match="start"):
        _run(BRACKET_HEAD, start=(1, 2))


def test_machine_file_start_reads_and_writes_back():
    m = tc.Machine.parse('control = "linuxcnc"\n[positions]\nstart = [-10, -20, 0]\n')
    assert list(m.start) == [-10, -20, 0]
    assert list(tc.Machine.parse(m.dumps()).start) == [-10, -20, 0]


def test_the_command_line_takes_the_start(tmp_path):
    import json
    import subprocess
    import sys

    f = tmp_path / "part.ngc"
    f.write_text("G21 G90\nG0 X10 Y20\nG1 X30 F100\nM2\n")

    def rapid_length(*opts):
        out = tmp_path / "s.json"
        r = subprocess.run([sys.executable, "-m", "toolcomp", "run", str(f), "--json", str(out), *opts],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        return json.loads(out.read_text())["length_mm"]["rapid"]

    assert rapid_length() == 0  # the path starts at X10 Y20, the first position
    assert rapid_length("--start", "machine_zero") == pytest.approx(math.hypot(10, 20))
    assert rapid_length("--start", "13,24,0") == pytest.approx(5)  # from (13, 24): 3-4-5
    r = subprocess.run([sys.executable, "-m", "toolcomp", "run", str(f), "--start", "1,2"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "X,Y,Z" in r.stderr
