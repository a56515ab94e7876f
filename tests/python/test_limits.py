"""Resource limits: input file size (programs, called programs, tool tables), non-regular
files, line length and the number of Path segments a run may produce. Each is exceeded
with a tc.Error subclass carrying a stable code (and the line where one applies), and just
below it the input runs."""
import inspect
import os
import pathlib
import re
import resource
import subprocess
import sys

import pytest

import toolcomp as tc

GiB = 2**30
MiB = 2**20

TEN_MOVES = "G21 G90\nG0 X0 Y0 Z5\n" + "".join(f"G1 X{i} F100\n" for i in range(1, 11)) + "M2\n"


def sparse(path, size):
    """A file of `size` bytes that takes no disk space (a hole)."""
    with open(path, "wb") as f:
        f.truncate(size)
    return path


def peak_rss_bytes():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # Linux: KiB


# ---- input size ----------------------------------------------------------------------------

def test_a_10_gib_program_is_refused_before_it_is_read(tmp_path):
    big = sparse(tmp_path / "big.ngc", 10 * GiB)
    before = peak_rss_bytes()
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read(big)
    assert e.value.code == "input_too_large"
    assert "10737418240 bytes (10.0 GiB)" in e.value.message
    assert "2147483648 bytes (2.0 GiB)" in e.value.message
    with pytest.raises(tc.ParseError) as e:
        tc.run(big)
    assert e.value.code == "input_too_large"
    # Nothing of the file was loaded: the peak memory of the process grew by far less than
    # even one GiB.
    assert peak_rss_bytes() - before < 100 * MiB


def test_max_bytes_is_the_largest_size_read(tmp_path):
    p = tmp_path / "ten.ngc"
    p.write_text(TEN_MOVES)
    n = len(TEN_MOVES)
    assert n == 134
    assert len(tc.Program.read(p, max_bytes=n)) == 13
    assert len(tc.run(p, max_bytes=n).nominal) == 11
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read(p, max_bytes=n - 1)
    assert e.value.code == "input_too_large"
    assert e.value.line == 0
    assert "it is 134 bytes, more than the limit of 133 bytes (max_bytes)" in e.value.message
    with pytest.raises(tc.ParseError, match="more than the limit of 133 bytes") as e:
        tc.run(str(p), max_bytes=n - 1)


def test_dev_zero_is_refused_not_read_forever():
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read("/dev/zero", dialect="linuxcnc")
    assert e.value.code == "not_a_regular_file"
    assert "a character device" in e.value.message
    with pytest.raises(tc.ToolTableError) as e:
        tc.ToolTable.read("/dev/zero", format="linuxcnc")
    assert e.value.code == "not_a_regular_file"


def test_a_directory_is_refused(tmp_path):
    d = tmp_path / "part.ngc"
    d.mkdir()
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read(d)
    assert e.value.code == "not_a_regular_file"
    assert "a directory" in e.value.message
    t = tmp_path / "tools.tbl"
    t.mkdir()
    with pytest.raises(tc.ToolTableError) as e:
        tc.ToolTable.read(t)
    assert e.value.code == "not_a_regular_file"


_FIFO_CHILD = """
import sys, toolcomp as tc
codes = []
for read in (lambda p: tc.Program.read(p + '.ngc'), lambda p: tc.ToolTable.read(p + '.tbl')):
    try:
        read(sys.argv[1])
        codes.append('read')
    except tc.Error as e:
        codes.append(e.code)
print(' '.join(codes))
"""


def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path):
    base = str(tmp_path / "pipe")
    os.mkfifo(base + ".ngc")
    os.mkfifo(base + ".tbl")
    # In a child process, so that a reader blocking on the FIFO cannot stop the test suite.
    p = subprocess.run([sys.executable, "-c", _FIFO_CHILD, base], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["not_a_regular_file", "not_a_regular_file"]


def test_a_missing_program_keeps_its_code(tmp_path):
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read(tmp_path / "missing.ngc")
    assert e.value.code == "file_not_found"


def test_tool_tables_have_a_size_limit(tmp_path):
    big = sparse(tmp_path / "big.tbl", 10 * GiB)
    with pytest.raises(tc.ToolTableError) as e:
        tc.ToolTable.read(big)
    assert e.value.code == "input_too_large"
    assert "10737418240 bytes (10.0 GiB), more than the limit of 268435456 bytes (256.0 MiB)" in e.value.message
    with pytest.raises(tc.ToolTableError) as e:
        tc.run(tc.Program.parse(TEN_MOVES), tools=big)
    assert e.value.code == "input_too_large"
    t = tmp_path / "tools.tbl"
    text = "T1 P1 Z25 D6\nT2 P2 Z30 D10\n"
    t.write_text(text)
    assert len(tc.ToolTable.read(t, max_bytes=len(text))) == 2
    with pytest.raises(tc.ToolTableError) as e:
        tc.ToolTable.read(t, max_bytes=len(text) - 1)
    assert e.value.code == "input_too_large"
    assert "it is 27 bytes, more than the limit of 26 bytes" in e.value.message


def test_called_program_files_over_2_gib_are_refused_at_the_call(tmp_path):
    sparse(tmp_path / "huge.ngc", 3 * GiB)
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse("G0 X0\no<huge> call\nM2\n"), search_path=[tmp_path])
    assert e.value.code == "input_too_large"
    assert e.value.line == 2
    assert "3221225472 bytes (3.0 GiB)" in e.value.message

    sparse(tmp_path / "HUGE.h", 3 * GiB)
    prog = tc.Program.parse("0 BEGIN PGM M MM\n1 CALL PGM HUGE\n2 END PGM M MM\n", dialect="heidenhain")
    with pytest.raises(tc.Error) as e:
        tc.run(prog, search_path=[tmp_path])
    assert (e.value.code, e.value.line) == ("input_too_large", 2)

    sparse(tmp_path / "L10.spf", 3 * GiB)
    prog = tc.Program.parse("G0 X0 Y0\nL10\nM30\n", dialect="sinumerik")
    with pytest.raises(tc.Error) as e:
        tc.run(prog, search_path=[tmp_path])
    assert (e.value.code, e.value.line) == ("input_too_large", 2)


# ---- line length ---------------------------------------------------------------------------

def _with_comment_line(dialect, length):
    """A program whose line 3 is a comment of exactly `length` bytes."""
    if dialect in ("sinumerik", "heidenhain"):
        comment = ";" + "a" * (length - 1)
    else:
        comment = "(" + "a" * (length - 2) + ")"
    if dialect == "heidenhain":
        return f"0 BEGIN PGM T MM\n1 L X+1 Y+0 R0 FMAX\n{comment}\n3 L X+2 R0 FMAX\n4 END PGM T MM\n"
    end = "M30" if dialect == "sinumerik" else "M2"
    return f"G0 X0 Y0\nG0 X1\n{comment}\nG0 X2\n{end}\n"


@pytest.mark.parametrize("dialect", ["fanuc", "sinumerik", "heidenhain"])
def test_a_line_over_1_mib_is_refused_with_its_line(dialect):
    ok = tc.Program.parse(_with_comment_line(dialect, MiB), dialect=dialect)
    assert len(tc.run(ok, start="machine_zero").nominal) >= 2
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(_with_comment_line(dialect, MiB + 1), dialect=dialect)
    assert (e.value.code, e.value.line) == ("line_too_long", 3)
    assert e.value.message == "Line 3 is 1048577 bytes long, more than the limit of 1048576 bytes (max_line_length)"
    # Also when read leniently: a resource limit is not a syntax error kept for later.
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(_with_comment_line(dialect, MiB + 1), dialect=dialect, strict=False)
    assert e.value.code == "line_too_long"


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc", "sinumerik", "heidenhain", "rockwell"])
def test_max_line_length_is_a_parameter(dialect, tmp_path):
    text = _with_comment_line(dialect, 100)
    assert len(tc.Program.parse(text, dialect=dialect, max_line_length=100)) >= 3
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(_with_comment_line(dialect, 101), dialect=dialect, max_line_length=100)
    assert (e.value.code, e.value.line) == ("line_too_long", 3)
    p = tmp_path / "part.txt"
    p.write_text(_with_comment_line(dialect, 101))
    with pytest.raises(tc.ParseError) as e:
        tc.Program.read(p, dialect=dialect, max_line_length=100)
    assert (e.value.code, e.value.line) == ("line_too_long", 3)
    with pytest.raises(tc.ParseError) as e:
        tc.run(p, dialect=dialect, max_line_length=100)
    assert (e.value.code, e.value.line) == ("line_too_long", 3)
    assert len(tc.run(p, dialect=dialect, max_line_length=101, start="machine_zero").nominal) >= 2


def test_line_ends_count_as_each_dialect_reads_them():
    long = ";" + "a" * 200
    # Sinumerik: CRLF and a lone CR each end a line; the CRs of CRLF are not line content.
    text = "G0 X0\r\nG0 X1\rG0 X2\n" + long + "\r\nM30\n"
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(text, dialect="sinumerik", max_line_length=200)
    assert (e.value.line, e.value.message) == (4, "Line 4 is 201 bytes long, more than the limit of 200 bytes "
                                                   "(max_line_length)")
    assert len(tc.Program.parse(text, dialect="sinumerik", max_line_length=201)) == 4
    # LinuxCNC: a CR is no end of block, so "G0 X1\r(...)" is one line (line 2 here).
    iso = "G0 X0\r\nG0 X1\r(" + "a" * 200 + ")\nM2\n"
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(iso, dialect="linuxcnc", max_line_length=200)
    assert (e.value.line, e.value.code) == (2, "line_too_long")
    assert "208 bytes long" in e.value.message
    # Fanuc: the lone CR ends line 2; the comment is line 3.
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(iso, dialect="fanuc", max_line_length=200)
    assert (e.value.line, e.value.code) == (3, "line_too_long")
    assert "202 bytes long" in e.value.message


def test_a_called_file_with_a_line_over_1_mib_is_refused_at_the_call(tmp_path):
    (tmp_path / "wide.ngc").write_text("o<wide> sub\n(" + "a" * MiB + ")\no<wide> endsub\n")
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse("G0 X0\nG0 X1\no<wide> call\nM2\n"), search_path=[tmp_path])
    assert (e.value.code, e.value.line) == ("line_too_long", 3)
    assert "Line 2 is 1048578 bytes long" in e.value.message


# ---- segments (memory per run) -------------------------------------------------------------

def test_max_segments_bounds_the_programmed_path():
    prog = tc.Program.parse(TEN_MOVES)
    res = tc.run(prog, max_segments=11)
    assert len(res.nominal) == 11 and len(res.path) == 11
    with pytest.raises(tc.ProgramError) as e:
        tc.run(prog, max_segments=10)
    assert (e.value.code, e.value.line) == ("memory_limit", 12)  # G1 X10: the 11th segment
    assert e.value.message == "The programmed path would hold more than 10 segments (max_segments)"
    res = tc.run(prog, max_segments=10, strict=False)
    assert len(res.nominal) == 10
    assert res.nominal.end[-1, 0] == 9.0
    (d,) = [d for d in res.diagnostics if d.severity == "error"]
    assert (d.code, d.line) == ("memory_limit", 12)


def test_max_segments_in_a_called_file(tmp_path):
    # The segment beyond the limit is in the called file: a Heidenhain CALL PGM names that
    # file and its line (sub1.h line 2, the third segment: see test_heidenhain_call_pgm).
    heidenhain = pathlib.Path(__file__).resolve().parents[1] / "programs" / "heidenhain"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(heidenhain / "call_main.h", search_path=[heidenhain], max_segments=2)
    assert (e.value.code, e.value.line) == ("memory_limit", 2)
    assert pathlib.Path(e.value.file).name.lower() == "sub1.h"
    # LinuxCNC unwinds its calls before it reports any error raised inside one: the line of
    # the outermost call in the main program (as for the errors of its own).
    (tmp_path / "moves.ngc").write_text("o<moves> sub\nG1 X1 F100\nG1 X2\nG1 X3\no<moves> endsub\nM2\n")
    prog = tc.Program.parse("G21\nG0 X0 Y0\no<moves> call\nM2\n")
    assert len(tc.run(prog, search_path=[tmp_path]).nominal) == 4
    with pytest.raises(tc.ProgramError) as e:
        tc.run(prog, search_path=[tmp_path], max_segments=3)
    assert (e.value.code, e.value.line, e.value.file) == ("memory_limit", 3, None)


SQUARE = """G21 G90 G17
T1 M6
G0 X-10 Y-10 Z5
G42 G1 X0 Y0 F100
X50
Y50
X0
Y0
G40 G1 X-10 Y-10
M2
"""


def test_max_segments_bounds_the_compensated_path():
    tools = tc.ToolTable.parse("T1 P1 Z0 D6\n", "linuxcnc")
    prog = tc.Program.parse(SQUARE)
    res = tc.run(prog, tools)
    # the compensated path has a corner arc at each of the three outside corners
    assert (len(res.nominal), len(res.path)) == (7, 10)
    assert len(tc.run(prog, tools, max_segments=10).path) == 10
    with pytest.raises(tc.ProgramError) as e:
        tc.run(prog, tools, max_segments=9)
    assert e.value.code == "memory_limit"
    assert e.value.message == "The compensated path would hold more than 9 segments (max_segments)"
    assert e.value.line == res.path.line[9] == 9  # G40 G1 X-10 Y-10, the 10th segment
    res = tc.run(prog, tools, max_segments=9, strict=False)
    assert (len(res.nominal), len(res.path)) == (7, 9)
    assert [d.code for d in res.diagnostics if d.severity == "error"] == ["memory_limit"]


def test_the_defaults():
    assert tc.ControlProfile("linuxcnc").block_limit == 100_000_000
    assert tc.ControlProfile("linuxcnc").call_depth_limit == 9
    params = inspect.signature(tc.run).parameters
    assert params["max_segments"].default == 20_000_000
    assert params["max_bytes"].default == 2 * GiB
    assert params["max_line_length"].default == MiB
    assert re.search(r"max_bytes: [^=]* = 2147483648", tc.Program.read.__doc__)
    assert re.search(r"max_line_length: [^=]* = 1048576", tc.Program.parse.__doc__)
    assert re.search(r"max_bytes: [^=]* = 268435456", tc.ToolTable.read.__doc__)


def test_parameter_files_have_a_size_limit(tmp_path):
    from toolcomp.params import read_var

    big = sparse(tmp_path / "big.var", 10 * GiB)
    with pytest.raises(tc.ParseError) as e:
        read_var(big)
    assert e.value.code == "input_too_large"
    assert "it is 10737418240 bytes, more than the limit of 67108864 bytes" in e.value.message
    with pytest.raises(tc.ParseError) as e:
        tc.run(tc.Program.parse(TEN_MOVES), parameters=big)
    assert e.value.code == "input_too_large"
    with pytest.raises(tc.ParseError) as e:
        read_var(tmp_path)
    assert e.value.code == "not_a_regular_file"
    v = tmp_path / "sim.var"
    v.write_text("5161\t1.5\n")
    assert read_var(v, max_bytes=9) == {5161: 1.5}
    with pytest.raises(tc.ParseError, match="it is 9 bytes, more than the limit of 8 bytes"):
        read_var(v, max_bytes=8)


def test_the_command_line_reports_a_too_large_program_without_reading_it(tmp_path):
    # A run that keeps the whole path (--plot) reads the program whole: refused by its size.
    pytest.importorskip("matplotlib")
    big = sparse(tmp_path / "big.ngc", 10 * GiB)
    p = subprocess.run([sys.executable, "-m", "toolcomp", "run", str(big), "--plot", str(tmp_path / "p.png")],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode in (1, 2), p.stderr
    assert "input_too_large" in p.stdout + p.stderr


def test_the_command_line_writes_the_csv_of_a_huge_program_a_piece_at_a_time(tmp_path):
    # run --csv streams (the CSV is written chunk by chunk): the 10 GiB of zeros are one line
    # too long, refused after its first MiB with its line; the CSV has its header only.
    big = sparse(tmp_path / "big.ngc", 10 * GiB)
    out = tmp_path / "p.csv"
    p = subprocess.run([sys.executable, "-m", "toolcomp", "run", str(big), "--csv", str(out)],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 1, p.stderr
    assert f"{big}:1:" in p.stdout and "line_too_long" in p.stdout
    assert len(out.read_text().splitlines()) == 1


def test_the_command_line_checks_a_huge_program_a_piece_at_a_time(tmp_path):
    # check streams a large program (no size limit, as iter_run): the 10 GiB of zeros are one
    # line too long, refused after its first MiB with its line.
    big = sparse(tmp_path / "big.ngc", 10 * GiB)
    p = subprocess.run([sys.executable, "-m", "toolcomp", "check", str(big)], capture_output=True, text=True,
                       timeout=300)
    assert p.returncode == 1, p.stderr
    assert f"{big}:1:" in p.stdout and "line_too_long" in p.stdout


def test_a_lenient_run_keeps_the_block_before_a_line_too_long():
    # LinuxCNC refuses a line of more than 252 characters (line 4); the blocks before it run:
    # the rapid of line 2 and the feed move of line 3 (2 segments, ending at Z-1).
    text = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 (" + "c" * 300 + ")\nM2\n"
    res = tc.run(tc.Program.parse(text, strict=False), strict=False)
    assert list(res.path.line) == [2, 3]
    assert res.path.end[-1].tolist() == [0, 0, -1]
    assert [(d.code, d.line) for d in res.diagnostics] == [("line_too_long", 4)]


_ADDRESS_SPACE_CHILD = r"""
import resource, sys
import toolcomp as tc
path, rows = sys.argv[1], int(sys.argv[2])
vm = next(int(l.split()[1]) * 1024 for l in open("/proc/self/status") if l.startswith("VmSize:"))
# Room for both Paths at one segment a block (about 90 bytes a row each) and some to spare,
# not for the compensated Path's reservation of two segments a block on top.
resource.setrlimit(resource.RLIMIT_AS, (vm + int(2.7 * 90 * rows), resource.RLIM_INFINITY))
res = tc.run(path, threads=False)
print(len(res.nominal), len(res.path))
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc are Linux's")
def test_a_run_under_an_address_space_limit_grows_the_paths_it_could_not_reserve(tmp_path):
    # The Paths are reserved up front (the compensated one for two segments a block); a
    # process whose address space is limited (ulimit -v) is refused that reservation, and the
    # run goes on with what it is granted instead of failing with MemoryError.
    rows = 3_000_000
    prog = tmp_path / "long.ngc"
    with open(prog, "w") as f:
        f.write("G21 G90 G0 X0 Y0\n")
        f.writelines(f"G1 X{i % 1000} Y{i % 7} F100\n" for i in range(1, rows))
        f.write("M2\n")
    p = subprocess.run([sys.executable, "-c", _ADDRESS_SPACE_CHILD, str(prog), str(rows)], capture_output=True,
                       text=True, timeout=300)
    assert p.returncode == 0, p.stderr[-2000:]
    assert p.stdout.split() == [str(rows), str(rows)]


_OOM_CHILD = """
import resource, sys
import toolcomp as tc
resource.setrlimit(resource.RLIMIT_AS, (2 * 2**30, 2 * 2**30))
prog = tc.Program.parse("G21 G0 X0\\no1 repeat [100000000]\\nG1 X1 F100\\nG1 X0\\no1 endrepeat\\nM2\\n")
try:
    tc.run(prog, max_segments=10**9, threads=sys.argv[1] == "1")
except tc.ProgramError as e:
    print(e.code)
"""


@pytest.mark.skipif("asan" in os.environ.get("LD_PRELOAD", ""),
                    reason="AddressSanitizer reserves terabytes of address space: no address-space limit")
@pytest.mark.parametrize("threads", ["0", "1"])
def test_memory_exhausted_is_a_toolcomp_error(threads):
    # 200 million segments asked for within 2 GiB of address space: the Paths' columns
    # cannot grow; the run raises ProgramError out_of_memory, not a bare MemoryError.
    p = subprocess.run([sys.executable, "-c", _OOM_CHILD, threads], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["out_of_memory"]
