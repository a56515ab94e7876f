"""The command line's streamed run of large programs (cli_stream.py) against its whole run:
``check`` and ``run`` (summary only) of the same programs both ways give the same records
and the same summary. The size from which a program streams is lowered to 0 here (the real
one, 64 MB, would make slow tests); the paths' totals are checked against hand-worked
values too, and the syntax check against Program.read."""

import json
import math
from pathlib import Path

import pytest

import toolcomp as tc
from toolcomp import cli, cli_stream

ROOT = Path(__file__).resolve().parents[2]
TOOLS = ROOT / "examples" / "tools.tbl"

SQUARE = "G21 G90 G17\nT1 M6\nG43\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG3 X0 Y10 I-5 J0\nG1 Y0\n" \
         "G2 X0 Y0 I5 J0\nG0 Z5\nM2\n"
SQUARE_FEED = 36 + 15 * math.pi  # 6 (plunge) + 10 + 10 + 5 pi + 10 + 10 pi

PROGRAMS = {
    "square.ngc": SQUARE,
    # an error at line 4: the path before it, the record with its line
    "unknown_gcode.ngc": "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG7.5 X10\nG1 X20\nM2\n",
    # a syntax error after M2: the run never reads it, the check does
    "after_end.ngc": "G21 G90 G0 X0 Y0\nG1 X10 F100\nM2\nG1 X10 &\n",
    # LinuxCNC's gouge error at line 6, overcut warnings before it
    "gouge.ngc": "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY2\nX31\nY0\nX60\nG40 G0 X70 Y-10\nM2\n",
    # compensation with corner arcs (segments inserted by compensation), a Fanuc program
    "corners.nc": "G21 G17 G90\nG0 X-10 Y-10\nG42.1 D4 G1 X0 Y0 F200\nX40\nY30\nX0\nY0\nG40 G0 X-10 Y-10\nM30\n",
}


@pytest.fixture(params=sorted(PROGRAMS))
def program(request, tmp_path):
    p = tmp_path / request.param
    p.write_text(PROGRAMS[request.param])
    return p


def run_cli(argv, capsys, stream):
    old = cli_stream.STREAM_MIN_BYTES
    cli_stream.STREAM_MIN_BYTES = 0 if stream else 2**62
    try:
        code = cli.main([str(a) for a in argv])
    finally:
        cli_stream.STREAM_MIN_BYTES = old
    return code, capsys.readouterr().out


def close(a, b):
    """Summaries equal, their lengths to rounding (summed chunk by chunk when streamed)."""
    if isinstance(a, float) or isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-9)
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(close(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    return a == b


def test_check_streamed_equals_check_whole(program, capsys):
    whole = run_cli(["check", program, "--tools", TOOLS], capsys, stream=False)
    streamed = run_cli(["check", program, "--tools", TOOLS], capsys, stream=True)
    assert streamed == whole
    assert whole[0] == (0 if program.stem in ("square", "corners") else 1)


def test_run_summary_streamed_equals_run_whole(program, capsys, tmp_path):
    summaries = []
    for stream in (False, True):
        js = tmp_path / f"{stream}.json"
        code, _ = run_cli(["run", program, "--tools", TOOLS, "--json", js], capsys, stream=stream)
        summaries.append((code, json.loads(js.read_text())))
    assert close(summaries[1], summaries[0]), summaries


def test_run_csv_streamed_equals_run_csv_whole(program, capsys, tmp_path, monkeypatch):
    # Chunks of 3 segments: rows numbered on across chunks, the same text as from the whole
    # path; a program that stops with an error has the same rows (or header only) both ways.
    monkeypatch.setattr(cli_stream, "STREAM_CHUNK", 3)
    texts = []
    for stream in (False, True):
        out = tmp_path / f"{stream}.csv"
        code, summary = run_cli(["run", program, "--tools", TOOLS, "--csv", out], capsys, stream=stream)
        texts.append((code, summary, out.read_text()))
    assert texts[1] == texts[0]
    rows = texts[0][2].splitlines()
    assert rows[0].startswith("index,kind,line,tool,start_x")
    if program.stem in ("square", "corners"):
        assert len(rows) - 1 == len(tc.run(str(program), tools=str(TOOLS)).path) > 3


def square_csv_streamed(tmp_path, capsys, monkeypatch):
    """run --csv of SQUARE as a stream of chunks of 2 segments: (exit code, CSV path)."""
    monkeypatch.setattr(cli_stream, "STREAM_CHUNK", 2)
    p = tmp_path / "square.ngc"
    p.write_text(SQUARE)
    out = tmp_path / "s.csv"
    code, _ = run_cli(["run", p, "--tools", TOOLS, "--csv", out], capsys, stream=True)
    return code, out


def test_a_streamed_csv_of_a_square_has_its_segments(tmp_path, capsys, monkeypatch):
    code, out = square_csv_streamed(tmp_path, capsys, monkeypatch)
    assert code == 0
    import csv

    rows = list(csv.DictReader(out.open()))
    # G0, plunge, X10, Y10, the semicircle, Y0, the full circle, the retract
    assert [r["index"] for r in rows] == [str(i) for i in range(8)]
    assert [r["kind"] for r in rows] == ["rapid", "line", "line", "line", "arc_ccw", "line", "arc_cw", "rapid"]
    assert [float(rows[4][k]) for k in ("end_x", "end_y", "center_x", "center_y")] == [0, 10, 5, 10]


def test_a_csv_is_not_made_for_an_unreadable_program(tmp_path, capsys):
    out = tmp_path / "never.csv"
    for stream in (False, True):
        code, _ = run_cli(["run", tmp_path / "missing.ngc", "--csv", out], capsys, stream=stream)
        assert code == 2 and not out.exists()


def test_streamed_totals_are_the_programs(tmp_path, capsys):
    p = tmp_path / "square.ngc"
    p.write_text(SQUARE)
    js = tmp_path / "s.json"
    code, _ = run_cli(["run", p, "--tools", TOOLS, "--json", js], capsys, stream=True)
    s = json.loads(js.read_text())
    assert code == 0
    assert s["blocks"] == 12 and s["dialect"] == "linuxcnc"
    # moves: G0, plunge, three lines, the semicircle, the full circle, the retract
    assert s["segments"] == {"nominal": 8, "compensated": 8, "generated": 0}
    assert s["tools"] == [1]
    assert s["length_mm"]["feed"] == pytest.approx(SQUARE_FEED, abs=1e-9)


def test_a_syntax_error_after_the_end_is_an_error_of_its_line(tmp_path, capsys):
    p = tmp_path / "after_end.ngc"
    p.write_text(PROGRAMS["after_end.ngc"])
    code, out = run_cli(["check", p], capsys, stream=True)
    assert code == 1
    assert f"{p}:4:" in out


def test_check_file_counts_blocks_and_raises_what_read_raises(tmp_path):
    many = tmp_path / "many.ngc"
    # more than one piece of text (the first pieces are 64 kB)
    many.write_text("G21 G90 G0 X0 Y0\n" + "".join(f"G1 X{i % 50} Y{i % 3} F100\n" for i in range(200_000)) + "M2\n")
    assert tc.Program.check_file(many) == len(tc.Program.read(many)) == 200_002
    bad = tmp_path / "bad.ngc"
    bad.write_text(many.read_text() + "G1 X10 &\n")
    with pytest.raises(tc.ParseError) as whole:
        tc.Program.read(bad)
    with pytest.raises(tc.ParseError) as pieces:
        tc.Program.check_file(bad)
    assert (pieces.value.code, pieces.value.line) == (whole.value.code, whole.value.line) == (
        whole.value.code, 200_003)
    with pytest.raises(tc.Error) as missing:
        tc.Program.check_file(tmp_path / "missing.ngc")
    assert missing.value.code == "file_not_found"


def test_only_large_files_stream(tmp_path, monkeypatch):
    p = tmp_path / "p.ngc"
    p.write_text(SQUARE)
    assert not cli_stream.streams(p)
    monkeypatch.setattr(cli_stream, "STREAM_MIN_BYTES", p.stat().st_size)
    assert cli_stream.streams(p)
    assert not cli_stream.streams(tmp_path)  # a directory: the whole run reports it


def test_a_stream_that_stops_with_an_error_leaves_a_csv_of_its_header(tmp_path, capsys, monkeypatch):
    # A run that raises has no path (as a whole run that raises has none): the rows of the
    # chunks that came before the error are taken back.
    real = tc.iter_run

    class Breaks:
        def __init__(self, *a, **kw):
            self.stream = real(*a, **kw)

        def __enter__(self):
            self.stream.__enter__()
            return self

        def __exit__(self, *exc):
            return self.stream.__exit__(*exc)

        @property
        def dialect(self):
            return self.stream.dialect

        def __iter__(self):
            for i, chunk in enumerate(self.stream):
                if i == 2:
                    raise tc.ProgramError("stopped")
                yield chunk

    monkeypatch.setattr(tc, "iter_run", Breaks)
    code, out = square_csv_streamed(tmp_path, capsys, monkeypatch)
    assert code == 1
    assert out.read_text().splitlines() == [",".join(cli.CSV_HEADER)]
