"""The Python API contract (../shared/DESIGN.md), column by column, with hand-calculated
numbers: units, work offsets, tool length offsets, arcs, errors with line and column."""
import math
import threading

import numpy as np
import pytest

import toolcomp as tc

TOOLS = "T1 P1 Z25 D10 ;end mill\nT2 P2 X1 Z30.5 D6\nT3 P3 X0.5 Y-0.25 Z40 D12\n"


def run(text, tools=None, dialect="linuxcnc", **kw):
    table = tc.ToolTable.parse(tools, "linuxcnc") if tools else None
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text, dialect=dialect), tools=table, **kw)


# ---- columns ------------------------------------------------------------------------------

COLUMNS = {
    "kind": (np.uint8, 1), "start": (np.float64, 3), "end": (np.float64, 3),
    "center": (np.float64, 3), "abc": (np.float64, 3), "line": (np.int32, 1),
    "tool": (np.int32, 1), "feed": (np.float64, 1), "side": (np.int8, 1),
    "generated": (np.bool_, 1), "tool_offset": (np.float64, 3),
}

PROGRAM = """G21 G17 G90 (contract program)
T1 M6
G43 H1
G0 X0 Y0 Z5 A10
G1 Z-1 F200
G2 X10 Y0 I5 J0
G3 X0 Y0 R5
M2
"""


@pytest.mark.parametrize("name", sorted(COLUMNS))
def test_column_dtype_shape_and_readonly(name):
    res = run(PROGRAM, TOOLS)
    for path in (res.nominal, res.path):
        col = getattr(path, name)
        dtype, width = COLUMNS[name]
        assert col.dtype == dtype
        assert col.shape == ((len(path),) if width == 1 else (len(path), 3))
        assert not col.flags.writeable
        with pytest.raises(ValueError):
            col[...] = 0


def test_columns_are_views_not_copies():
    res = run(PROGRAM, TOOLS)
    a, b = res.path.end, res.path.end
    assert np.shares_memory(a, b)
    assert a.base is not None
    del res  # the arrays keep the result alive
    assert a.shape == (4, 3) and np.isfinite(a).all()


def test_column_values():
    res = run(PROGRAM, TOOLS)
    p = res.nominal
    assert list(p.kind) == [tc.RAPID, tc.LINE, tc.ARC_CW, tc.ARC_CCW]
    assert list(p.line) == [4, 5, 6, 7]
    assert list(p.tool) == [1, 1, 1, 1]
    np.testing.assert_allclose(p.end, [[0, 0, 5], [0, 0, -1], [10, 0, -1], [0, 0, -1]])
    np.testing.assert_allclose(p.start[1:], p.end[:-1])
    assert np.isnan(p.center[:2]).all()
    np.testing.assert_allclose(p.center[2:], [[5, 0, -1], [5, 0, -1]], atol=1e-12)
    np.testing.assert_allclose(p.abc[:, 0], 10)
    assert math.isnan(p.feed[0]) and list(p.feed[1:]) == [200, 200, 200]
    assert list(p.side) == [0, 0, 0, 0] and not p.generated.any()
    np.testing.assert_allclose(p.tool_offset, [[0, 0, 25]] * 4)
    assert res.ok and res.diagnostics == []


def test_sample_chords_arcs_within_tolerance():
    res = run("G21 G0 X10 Y0\nG3 X10 Y0 I-10 J0 F100\nM2\n")
    pts, seg = res.path.sample(0.01)
    assert pts.shape[1] == 3 and len(pts) == len(seg)
    assert seg[0] == 0 and (seg[1:] >= 0).all()
    r = np.hypot(pts[1:, 0], pts[1:, 1])
    np.testing.assert_allclose(r, 10, atol=1e-9)  # vertices on the circle
    mids = 0.5 * (pts[1:-1] + pts[2:])
    assert (10 - np.hypot(mids[:, 0], mids[:, 1])).max() <= 0.01  # chords within tolerance
    np.testing.assert_allclose(res.path.length(include_rapids=False), 2 * math.pi * 10)


# ---- units, offsets, tool length ----------------------------------------------------------

def test_inch_program_gives_millimetres():
    res = run("G20 G0 X1 Y2 Z0.5\nG1 X2 F10\nG2 X3 Y2 R0.5\nM2\n")
    np.testing.assert_allclose(res.path.end, [[25.4, 50.8, 12.7], [50.8, 50.8, 12.7], [76.2, 50.8, 12.7]])
    assert res.path.feed[1] == pytest.approx(254.0)
    np.testing.assert_allclose(res.path.center[2, :2], [63.5, 50.8])


def test_work_offsets_report_program_coordinates():
    # G54 origin (10, 20): the program point stays what was programmed; G53 goes to machine 0.
    res = run("G21 G10 L2 P1 X10 Y20\nG0 X1 Y1\nG53 G0 X0 Y0\nG55 G10 L2 P2 X-5\nG0 X0\nM2\n")
    np.testing.assert_allclose(res.path.end[0], [1, 1, 0])
    np.testing.assert_allclose(res.path.end[1], [-10, -20, 0])  # machine 0 in G54 coordinates
    np.testing.assert_allclose(res.path.end[2], [0, 0, 0])  # G55 origin (-5, 0): machine (-5, 0)


def test_g92_shifts_the_frame():
    res = run("G21 G0 X10 Y10\nG92 X0 Y0\nG0 X5\nG92.1\nG0 Y0\nM2\n")
    np.testing.assert_allclose(res.path.end[1], [5, 0, 0])
    np.testing.assert_allclose(res.path.end[2], [15, 0, 0])


def test_tool_length_offsets():
    res = run("G21 G0 X0 Y0 Z5\nG43 H2\nG0 X1\nG43.2 H1\nG0 X2\nG43.1 Z7.5\nG0 X3\nG49\nG0 X4\nM2\n", TOOLS)
    p = res.path
    np.testing.assert_allclose(p.tool_offset, [[0, 0, 0], [1, 0, 30.5], [1, 0, 55.5], [1, 0, 7.5], [0, 0, 0]])
    # The machine stays put when the offset changes: the program Z re-expresses it.
    np.testing.assert_allclose(p.end[:, 2], [5, 5 - 30.5, 5 - 55.5, 5 - 7.5, 5])
    # and every start with it: the end before, plus the old offset, less the new one
    np.testing.assert_allclose(p.start, [[0, 0, 0], [0 - 1, 0, 5 - 30.5], [1 + 1 - 1, 0, 5 - 30.5 + 30.5 - 55.5],
                                         [2 + 1 - 1, 0, 5 - 55.5 + 55.5 - 7.5], [3 + 1 - 0, 0, 5 - 7.5 + 7.5]])


def test_start_center_and_feed_are_written_out_once_when_asked_for():
    res = run(PROGRAM, TOOLS)
    p = res.nominal
    n, stored = len(p), p.nbytes
    # stored: a jump for the first start, the two arcs' centres; no start or centre row else
    # kind side generated line end; a jump row and start, two centres, one rank, two runs of the
    # feed (NaN, then 200); the uniform columns once: five 3-vectors, tool, turns, file, plane,
    # the work rotation
    assert stored == n * (1 + 1 + 1 + 4 + 24) + 8 + 24 + 2 * 24 + 8 + 2 * 16 + 5 * 24 + 3 * 4 + 1 + 8
    a = p.start
    assert p.nbytes == stored + 24 * n
    assert np.shares_memory(a, p.start)  # kept: the same rows the next time
    c = p.center
    assert p.nbytes == stored + 48 * n and np.shares_memory(c, p.center)
    f = p.feed
    assert p.nbytes == stored + 56 * n and np.shares_memory(f, p.feed)
    del res, p
    # they keep the Path alive; the first starts at machine zero in program Z (tool length 25 active)
    np.testing.assert_allclose(a, [[0, 0, -25], [0, 0, 5], [0, 0, -1], [10, 0, -1]])
    np.testing.assert_allclose(c[2:], [[5, 0, -1], [5, 0, -1]], atol=1e-12)
    assert np.isnan(f[0]) and list(f[1:]) == [200, 200, 200]


def test_fanuc_g44_subtracts_and_acts_on_z_only():
    res = run("G21 G0 Z5\nG44 H2\nG0 X1\nG43 H2\nG0 X2\nM30\n", TOOLS, dialect="fanuc")
    np.testing.assert_allclose(res.path.tool_offset[1:], [[0, 0, -30.5], [0, 0, 30.5]])
    with pytest.raises(tc.ProgramError, match="Unknown g code used"):
        run("G21 G44 H2\nM2\n", TOOLS)


def test_profile_setting_changes_length_axes():
    prof = tc.ControlProfile("linuxcnc")
    prof.length_axes = tc.LengthAxes.z_only
    res = run("G21 G43 H2\nG0 X1\nM2\n", TOOLS, profile=prof)
    np.testing.assert_allclose(res.path.tool_offset[0], [0, 0, 30.5])


# ---- errors ---------------------------------------------------------------------------------

@pytest.mark.parametrize("text, cls, code, message, line, column", [
    ("G21\nG1 X1 F100\nG2 X10 R4\nM2\n", tc.ProgramError, "arc_radius_too_small",
     "Arc radius too small to reach end point", 3, 8),
    ("G21\nG7.5 X1\nM2\n", tc.ProgramError, "unknown_g_code", "Unknown g code used", 2, 1),
    ("G21\nG0 G1 X1\nM2\n", tc.ProgramError, "modal_group_conflict",
     "Two g codes used from same modal group", 2, 4),
    ("G21\nG0 X1 X2\nM2\n", tc.ProgramError, "multiple_words", "Multiple x words on one line", 2, 7),
    ("G21\nG0 X1 (open\nM2\n", tc.ParseError, "unclosed_comment", "Unclosed comment found", 2, 7),
    ("G21\nT9 M6\nM2\n", tc.ProgramError, "tool_not_found",
     "Requested tool 9 not found in the tool table", 2, 1),
    ("G21\nG41 D1\nG1 X1 F100\nM2\n", tc.CompensationError, "comp_entry_too_short",
     "Length of cutter compensation entry move is not greater than the tool radius", 3, 0),
    ("G21\nG19 G41 D1\nM2\n", tc.ProgramError, "comp_plane",
     "Cutter radius compensation allowed only in XY, XZ planes", 2, 5),
    ("G21\nG41 D1\nT2 M6\nM2\n", tc.ProgramError, "comp_tool_change",
     "Cannot change tools with cutter radius compensation on", 3, 4),
    ("G21\nG17.1 X1\nM2\n", tc.ProgramError, "unsupported_g_code", "G17.1 is not supported by toolcomp", 2, 1),
    ("G21\nG0 X1\n", tc.ProgramError, "no_program_end", "File ended with no percent sign or program end", 2, 0),
])
def test_errors_have_code_message_line_column(text, cls, code, message, line, column):
    with pytest.raises(cls) as info:
        run(text, TOOLS)
    err = info.value
    assert isinstance(err, tc.Error)
    assert (err.code, err.message, err.line, err.column) == (code, message, line, column)


def test_strict_false_returns_the_path_up_to_the_error():
    res = run("G21 G0 X1\nG1 X2 F100\nG2 X10 R1\nG0 X0\nM2\n", strict=False)
    assert not res.ok
    assert len(res.path) == 2
    (d,) = res.diagnostics
    assert (d.code, d.severity, d.line) == ("arc_radius_too_small", "error", 3)
    assert isinstance(d, tc.Diagnostic)


def test_dialect_and_suffix(tmp_path):
    f = tmp_path / "p.tap"
    f.write_text("G21 G0 X1\nM30\n")
    assert tc.Program.read(f).dialect == "fanuc"
    assert tc.Program.read(f, dialect="linuxcnc").dialect == "linuxcnc"
    with pytest.raises(tc.ParseError):
        tc.Program.read(tmp_path / "p.xyz")
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse("G1 X1", dialect="mazatrol")
    assert e.value.code == "unknown_dialect"


def test_run_accepts_paths(tmp_path):
    (tmp_path / "t.tbl").write_text(TOOLS)
    (tmp_path / "p.ngc").write_text("G21 G43 H1\nG0 X1\nM2\n")
    res = tc.run(tmp_path / "p.ngc", tools=tmp_path / "t.tbl")
    assert res.path.tool_offset[0, 2] == 25


def test_threads_run_in_parallel_safely():
    text = "G21 G1 F100 X0\n" + "".join(f"X{i % 50} Y{(i * 7) % 30}\n" for i in range(20000)) + "M2\n"
    prog = tc.Program.parse(text)
    out = []
    threads = [threading.Thread(target=lambda: out.append(len(tc.run(prog).path))) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert out == [20001] * 4


def test_block_delete_switch():
    text = "G21 G0 X1\n/G0 X2\nG0 X3\nM2\n"
    assert len(run(text).path) == 3
    assert len(run(text, block_delete=True).path) == 2


def test_type_stub_names_exist():
    """Every class, method and property the stub declares exists in the compiled module."""
    import ast
    import pathlib

    stub = pathlib.Path(tc.__file__).with_name("_core.pyi")
    if not stub.exists():  # editable installs keep the stub in the source tree
        stub = pathlib.Path(__file__).resolve().parents[2] / "python" / "toolcomp" / "_core.pyi"
    tree = ast.parse(stub.read_text())
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            cls = getattr(tc._core, node.name)
            for item in node.body:
                name = getattr(item, "name", None) or getattr(getattr(item, "target", None), "id", None)
                if name and not (name.startswith("__") and name != "__len__"):
                    assert hasattr(cls, name), f"{node.name}.{name}"
        elif isinstance(node, ast.FunctionDef):
            assert hasattr(tc._core, node.name)


def test_syntax_errors_are_met_when_the_run_reaches_them(tmp_path):
    f = tmp_path / "p.ngc"
    f.write_text("G21 G0 X1\nG1 X2 F100\nG1 X3 & Y1\nG0 X0\nM2\n")
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read(f)  # a whole-file syntax check
    assert (e.value.line, e.value.column) == (3, 7)
    res = tc.run(f, strict=False)
    assert len(res.path) == 2
    (d,) = res.diagnostics
    assert (d.code, d.line, d.column, d.message) == ("bad_character", 3, 7, "Bad character '&' used")
    with pytest.raises(tc.ParseError):
        tc.run(f)
    # After M2 the control reads no further: a bad line there is no error.
    f.write_text("G21 G0 X1\nM2\nG1 X3 & Y1\n")
    assert tc.run(f).ok


def test_constant_columns_are_stride_0_views_until_they_vary():
    # abc is the same on every row here: a read-only view of one row repeated; a program
    # that moves A gets its rows stored.
    res = tc.run(tc.Program.parse("G21 G0 X1\nX2\nM2\n"))
    assert res.path.abc.strides[0] == 0 and res.path.abc.shape == (2, 3)
    assert not res.path.abc.flags.writeable
    np.testing.assert_array_equal(res.path.tool_axis, [[0, 0, 1], [0, 0, 1]])
    res = tc.run(tc.Program.parse("G21 G0 X1\nX2 A90\nM2\n"))
    np.testing.assert_array_equal(res.path.abc, [[0, 0, 0], [90, 0, 0]])
    assert res.path.abc.strides[0] == 24


def test_a_path_no_stage_changes_is_the_programmed_path_stored_once():
    res = run(PROGRAM, TOOLS)  # no radius compensation: every segment passes unchanged
    assert res.path is res.nominal
    np.testing.assert_allclose(res.path.end, [[0, 0, 5], [0, 0, -1], [10, 0, -1], [0, 0, -1]])
    # with compensation the two differ: the compensated path is stored on its own
    comp = run("G21 G0 X0 Y0\nG41.1 D2 G1 X20 F100\nG1 X40 Y10\nG40 G1 X60\nM2\n")
    assert comp.path is not comp.nominal
    assert len(comp.path) == len(comp.nominal) == 4
    # radius 1 on the left: an inside corner, where y = 1 meets the next line's offset
    np.testing.assert_allclose(comp.path.end[1], [22 - 5 ** 0.5, 1, 0])
    np.testing.assert_allclose(comp.nominal.end[1], [20, 0, 0])
    # an error the stages meet after the programmed path stored the move: the compensated
    # path ends one segment earlier (strict=False returns both up to the error)
    bad = run("G21 G0 X0 Y0\nG1 X5 F100\nG41.1 D20 G1 X10\nM2\n", strict=False)
    assert not bad.ok and bad.path is not bad.nominal
    assert (len(bad.nominal), len(bad.path)) == (3, 2)
    np.testing.assert_allclose(bad.path.end, bad.nominal.end[:2])


def test_a_percent_line_after_the_end_is_never_read():
    # LinuxCNC stops at M2: a "%" after it (without one opening the program) is not reached;
    # one before it is a bad character when the program gets there (errors/percent_in_the_middle.ngc).
    assert len(tc.run(tc.Program.parse("G21\nG1 X5 F100\nM2\n%\n")).path) == 1
    res = tc.run(tc.Program.parse("G21\nG1 X5 F100\n%\nG1 X10\nM2\n"), strict=False)
    assert len(res.path) == 1
    assert [(d.code, d.line, d.column) for d in res.diagnostics] == [("bad_character", 3, 1)]
