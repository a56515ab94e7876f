"""The command line, run as users run it: ``python -m toolcomp`` in a subprocess."""

import csv
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "pocket.ngc"
TOOLS = ROOT / "examples" / "tools.tbl"

DIAG_RE = re.compile(
    r"^(?P<file>.+?):(?P<line>\d+):(?P<column>\d+): (?P<severity>\w+) (?P<code>\S+) (?P<message>.+)$")

# A square with a semicircle on top and a full circle at the start: the feed length is
# 6 (plunge) + 10 + 10 + 5*pi + 10 + 10*pi, whatever the sampling tolerance.
SQUARE = """\
G21 G90 G17
T1 M6
G43
G0 X0 Y0 Z5
G1 Z-1 F100
G1 X10
G1 Y10
G3 X0 Y10 I-5 J0
G1 Y0
G2 X0 Y0 I5 J0
G0 Z5
M2
"""
SQUARE_FEED = 36 + 15 * math.pi

# Feed length of examples/pocket.ngc, from LinuxCNC's own canonical output (rs274) of the
# same program: 2 x (clearing + contour) + recess + 4 drilled holes of 25 mm.
EXAMPLE_FEED = 855.748346

# Line 4 is wrong; lines 1-3 give a partial path.
BAD_PROGRAMS = {
    "unknown_gcode": "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG7.5 X10\nG1 X20\nM2\n",
    "arc_end_off_circle": "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG2 X10 Y0 I3 J0\nG1 X20\nM2\n",
    "bad_character": "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 &\nG1 X20\nM2\n",
}
BAD_LINE = 4


def toolcomp(*args, cwd=ROOT):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, "-m", "toolcomp", *map(str, args)], cwd=cwd,
                          env=env, capture_output=True, text=True, timeout=300)


@pytest.fixture
def square(tmp_path):
    p = tmp_path / "square.ngc"
    p.write_text(SQUARE)
    return p


@pytest.fixture(params=sorted(BAD_PROGRAMS))
def bad_program(request, tmp_path):
    p = tmp_path / f"{request.param}.ngc"
    p.write_text(BAD_PROGRAMS[request.param])
    return p


# ---- run ----------------------------------------------------------------------------

def test_run_example_is_clean(tmp_path):
    r = toolcomp("run", EXAMPLE, "--tools", TOOLS)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "pocket.ngc" in r.stdout
    assert "linuxcnc" in r.stdout
    for field in ("blocks:", "segments:", "tools:", "path length:", "diagnostics:"):
        assert field in r.stdout
    assert "T1" in r.stdout and "T2" in r.stdout


def test_run_example_feed_length_matches_linuxcnc(tmp_path):
    out = tmp_path / "summary.json"
    r = toolcomp("run", EXAMPLE, "--tools", TOOLS, "--json", out)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads(out.read_text())
    assert s["length_mm"]["feed"] == pytest.approx(EXAMPLE_FEED, abs=1e-3)
    assert s["tools"] == [1, 2] or s["tools"] == [0, 1, 2]


def test_run_summary_json(square, tmp_path):
    out = tmp_path / "summary.json"
    r = toolcomp("run", square, "--tools", TOOLS, "--json", out)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads(out.read_text())
    assert s["ok"] is True
    assert s["dialect"] == "linuxcnc"
    assert s["tools"] == [1]
    assert s["segments"]["compensated"] >= 8
    assert s["segments"]["nominal"] >= 8
    assert s["length_mm"]["feed"] == pytest.approx(SQUARE_FEED, rel=1e-6)
    assert s["length_mm"]["rapid"] >= 6.0
    assert s["diagnostics"] == []
    assert f"{s['length_mm']['feed']:.3f} mm" in r.stdout


def test_run_with_error_exits_1_and_reports_partial_path(bad_program, tmp_path):
    out = tmp_path / "summary.json"
    r = toolcomp("run", bad_program, "--json", out)
    assert r.returncode == 1, r.stdout + r.stderr
    s = json.loads(out.read_text())
    assert s["ok"] is False
    errors = [d for d in s["diagnostics"] if d["severity"] == "error"]
    assert errors and errors[0]["line"] == BAD_LINE
    # the error line is printed in the summary too
    assert any(DIAG_RE.match(line) for line in r.stdout.splitlines())


def test_run_csv_has_one_row_per_segment(tmp_path):
    import toolcomp as tc

    out = tmp_path / "path.csv"
    r = toolcomp("run", EXAMPLE, "--tools", TOOLS, "--csv", out)
    assert r.returncode == 0, r.stdout + r.stderr
    with out.open(newline="") as f:
        rows = list(csv.DictReader(f))
    res = tc.run(tc.Program.read(str(EXAMPLE)), tools=tc.ToolTable.read(str(TOOLS)))
    assert len(rows) == len(res.path.kind)
    assert f"{len(rows)} compensated" in r.stdout
    assert [int(row["index"]) for row in rows] == list(range(len(rows)))
    assert {row["kind"] for row in rows} <= {"rapid", "line", "arc_cw", "arc_ccw"}
    assert {"arc_cw", "arc_ccw", "rapid", "line"} <= {row["kind"] for row in rows}
    first = rows[0]
    for col in ("start_x", "end_z", "tool_offset_z", "line", "tool", "feed", "side", "generated"):
        assert col in first
    # rapids have no feed, lines no centre: empty fields, not "nan"
    assert all(row["feed"] == "" for row in rows if row["kind"] == "rapid")
    assert all(row["center_x"] == "" for row in rows if row["kind"] in ("rapid", "line"))
    assert all(row["center_x"] != "" for row in rows if row["kind"].startswith("arc"))


def test_the_csv_is_written_a_block_of_rows_at_a_time(tmp_path, monkeypatch):
    # Rows written 7 at a time are the rows written all at once, numbered on across blocks.
    import toolcomp as tc
    from toolcomp import cli

    path = tc.run(str(EXAMPLE), tools=str(TOOLS)).path
    whole, blocks = tmp_path / "whole.csv", tmp_path / "blocks.csv"
    assert cli.write_csv(path, whole) == len(path) > 7
    monkeypatch.setattr(cli, "CSV_ROWS_AT_ONCE", 7)
    assert cli.write_csv(path, blocks) == len(path)
    assert blocks.read_text() == whole.read_text()
    assert len(whole.read_text().splitlines()) == len(path) + 1


def test_run_plot_writes_png(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "pocket.png"
    r = toolcomp("run", EXAMPLE, "--tools", TOOLS, "--plot", out)
    assert r.returncode == 0, r.stdout + r.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


# ---- usage errors -----------------------------------------------------------------------

@pytest.mark.parametrize("args", [
    [],
    ["run"],
    ["frobnicate", "x.ngc"],
    ["run", "x.ngc", "--dialect", "nonsense"],
    ["check", "x.ngc", "--format", "xml"],
])
def test_usage_errors_exit_2(args):
    r = toolcomp(*args)
    assert r.returncode == 2, r.stdout + r.stderr
    assert "usage:" in r.stderr


@pytest.mark.parametrize("command", ["run", "check"])
def test_missing_program_exits_2(command, tmp_path):
    missing = tmp_path / "nope.ngc"
    r = toolcomp(command, missing)
    assert r.returncode == 2
    assert "nope.ngc" in r.stderr and "does not exist" in r.stderr
    assert "Traceback" not in r.stderr


def test_missing_tool_table_exits_2(square, tmp_path):
    r = toolcomp("run", square, "--tools", tmp_path / "nope.tbl")
    assert r.returncode == 2
    assert "nope.tbl" in r.stderr
    assert "Traceback" not in r.stderr


# ---- check ------------------------------------------------------------------------------

def test_check_clean_program_reports_no_error(square):
    r = toolcomp("check", square, "--tools", TOOLS)
    assert r.returncode == 0, r.stdout + r.stderr
    assert " error " not in r.stdout  # warnings and notes may be printed, nothing else
    assert all(DIAG_RE.match(line) for line in r.stdout.splitlines())


def test_check_reports_file_line_column(bad_program):
    r = toolcomp("check", bad_program)
    assert r.returncode == 1, r.stdout + r.stderr
    lines = r.stdout.splitlines()
    assert lines, r.stderr
    matches = [DIAG_RE.match(line) for line in lines]
    assert all(matches), lines
    m = next(m for m in matches if m["severity"] == "error")
    assert m["file"] == str(bad_program)
    assert int(m["line"]) == BAD_LINE
    assert int(m["column"]) >= 0


def test_check_json(bad_program):
    r = toolcomp("check", bad_program, "--format", "json")
    assert r.returncode == 1, r.stdout + r.stderr
    doc = json.loads(r.stdout)
    assert doc["ok"] is False
    assert doc["program"] == str(bad_program)
    d = next(d for d in doc["diagnostics"] if d["severity"] == "error")
    assert d["line"] == BAD_LINE
    assert set(d) >= {"file", "line", "column", "severity", "code", "message"}


def test_check_several_programs(square, bad_program):
    r = toolcomp("check", square, bad_program, "--tools", TOOLS)
    assert r.returncode == 1
    assert all(line.startswith(str(bad_program)) for line in r.stdout.splitlines())


def test_main_in_process(square, capsys):
    from toolcomp.cli import main

    assert main(["check", str(square), "--tools", str(TOOLS)]) == 0
    assert main(["run", str(square), "--tools", str(TOOLS)]) == 0
    assert "square.ngc" in capsys.readouterr().out


def test_check_a_gouging_program_names_the_block(tmp_path):
    # A 1 mm slot under a 10 mm cutter: LinuxCNC's gouge error at line 6 (the move after the slot floor).
    gouge = tmp_path / "gouge.ngc"
    gouge.write_text("G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY2\nX31\nY0\nX60\nG40 G0 X70 Y-10\nM2\n")
    r = toolcomp("check", gouge)
    assert r.returncode == 1
    # The first error (warnings "comp_overcut" may name the slot's moves before it).
    m = next(m for m in map(DIAG_RE.match, r.stdout.splitlines()) if m and m["severity"] == "error")
    assert (m["file"], m["line"], m["severity"], m["code"]) == (str(gouge), "6", "error", "comp_gouge")


def test_search_path_finds_sinumerik_subprograms(tmp_path):
    # The main program calls L10 twice (P2); L10 moves 10 in X incrementally: ends at X20.
    subs = tmp_path / "subs"
    subs.mkdir()
    (subs / "L10.SPF").write_text("G91 G1 X10 F100\nG90\nM17\n")
    main = tmp_path / "main.mpf"
    main.write_text("G0 X0 Y0\nL10 P2\nM30\n")
    out = toolcomp("check", main)
    assert out.returncode == 1 and "14011" in out.stdout
    js = tmp_path / "s.json"
    out = toolcomp("run", main, "--search-path", subs, "--json", js)
    assert out.returncode == 0, out.stdout + out.stderr
    assert json.loads(js.read_text())["segments"]["nominal"] == 3


def test_parameters_from_a_var_file(tmp_path):
    # #31 comes from the .var file: the program moves to X #31 * 2 = 5, and an undefined
    # parameter file is a usage error.
    var = tmp_path / "sim.var"
    var.write_text("31\t2.500000\n")
    main = tmp_path / "p.ngc"
    main.write_text("G21 G0 X[#31*2]\nM2\n")
    table = tmp_path / "s.csv"
    out = toolcomp("run", main, "--parameters", var, "--csv", table)
    assert out.returncode == 0, out.stdout + out.stderr
    rows = list(csv.DictReader(table.open()))
    assert len(rows) == 1 and float(rows[0]["end_x"]) == 5.0
    out = toolcomp("run", main, "--parameters", tmp_path / "missing.var")
    assert out.returncode == 2
