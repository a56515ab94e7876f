"""toolcomp tools show / convert / validate, and toolcomp.tool_check."""
import json
import pathlib
import subprocess
import sys

import toolcomp as tc
from toolcomp.tool_check import check_table

ROOT = pathlib.Path(__file__).resolve().parents[2]
BAD = "T1 P1 D10 Z50 ;end mill\nT2 P1 D-6 Z75 ;drill in pocket 1 as well\nT3 P3 D0 Z60\nT4 P4 D1.6 Q0 X1 Z2 ;turning insert\n"


def cli(*args):
    return subprocess.run([sys.executable, "-m", "toolcomp", "tools", *map(str, args)],
                          capture_output=True, text=True)


def test_check_table_findings():
    t = tc.ToolTable.parse(BAD, "linuxcnc")
    mill = {(d.code, d.severity) for d in check_table(t)}
    assert mill == {("pocket_conflict", "error"), ("negative_radius", "warning"), ("zero_radius", "warning")}
    lathe = [d for d in check_table(t, lathe=True) if d.code == "missing_orientation"]
    # T1 (r 5) and T4 (nose radius 0.8) have no tip; T3 has no radius, T2 a negative one.
    assert sorted(d.message.split()[0] for d in lathe) == ["T1", "T4"]


def test_validate_prints_file_line_column_and_fails_on_errors(tmp_path):
    bad = tmp_path / "bad.tbl"
    bad.write_text(BAD)
    r = cli("validate", bad)
    assert r.returncode == 1
    assert f"{bad}:0:0: error pocket_conflict tools T1 and T2 are both in pocket P1" in r.stdout.splitlines()
    good = ROOT / "examples/tools.tbl"
    assert cli("validate", good).returncode == 0
    assert cli("validate", good, "--lathe").returncode == 1  # milling cutters have no tip orientation


def test_validate_reports_a_duplicate_number_at_its_line(tmp_path):
    dup = tmp_path / "dup.tbl"
    dup.write_text("T1 P1 D10 Z50\nT2 P2 D6 Z40\nT1 P3 D8 Z30\n")
    r = cli("validate", dup)
    assert r.returncode == 1
    assert r.stderr.startswith(f"{dup}:3:") and "tbl_duplicate_tool" in r.stderr


def test_show_json_gives_effective_values():
    r = cli("show", ROOT / "examples/tools.tbl", "--format", "json")
    rows = json.loads(r.stdout)
    assert [(x["tool"], x["length_z"], x["radius"]) for x in rows][:2] == [(1, 50.0, 5.0), (2, 75.0, 3.4)]


def test_convert_round_trips_and_never_overwrites_without_force(tmp_path):
    src = ROOT / "examples/tools.tbl"
    out = tmp_path / "tools.json"
    assert cli("convert", src, out).returncode == 0
    a, b = tc.ToolTable.read(src), tc.ToolTable.read(out)
    assert [(t.number, t.pocket, t.comment, t.edge().radius) for t in a] == \
           [(t.number, t.pocket, t.comment, t.edge().radius) for t in b]
    before = out.read_bytes()
    r = cli("convert", src, out)
    assert r.returncode == 2 and "exists" in r.stderr and out.read_bytes() == before
    back = tmp_path / "back.tbl"
    assert cli("convert", out, back).returncode == 0
    assert back.read_text().splitlines()[0].startswith("T1 P1")
    assert cli("show", tmp_path / "missing.tbl").returncode == 2
