"""Error parity with LinuxCNC: tests/programs/errors/*.ngc.

Each file starts with
    ; <exact rs274 error message>
    ; line <n>                      (1-based source line of the offending block)
toolcomp must raise tc.ProgramError or tc.ParseError with that message and line.
test_rs274_agrees re-checks the recorded expectation against rs274 itself (skipped without rs274).
The files need no tool table: tool lookups are expected to fail ("Requested tool 99 not found…").
"""
import re
from pathlib import Path

import pytest

import lcnc

ROOT = Path(__file__).resolve().parents[2]
ERRORS = sorted((ROOT / "tests" / "programs" / "errors").glob("*.ngc"))


def expectation(path: Path):
    lines = path.read_text().splitlines()
    assert lines[0].startswith("; "), path
    m = re.fullmatch(r";\s*line\s+(\d+)\s*", lines[1])
    assert m, path
    return lines[0][2:], int(m.group(1))


@pytest.mark.skipif(not lcnc.available(), reason="LinuxCNC rs274 not installed")
@pytest.mark.parametrize("prog", ERRORS, ids=lambda p: p.stem)
def test_rs274_agrees(prog):
    message, line = expectation(prog)
    e = lcnc.run_error(prog)
    assert e is not None, "rs274 accepted %s" % prog.name
    assert (e.message, e.line) == (message, line)


@pytest.mark.parametrize("prog", ERRORS, ids=lambda p: p.stem)
def test_toolcomp_raises_same_error(prog, tmp_path):
    tc = pytest.importorskip("toolcomp")
    message, line = expectation(prog)
    empty = tmp_path / "empty.tbl"          # rs274 ran these with an empty tool table too
    empty.write_text("")
    tools = tc.ToolTable.read(str(empty))
    with pytest.raises((tc.ProgramError, tc.ParseError, tc.CompensationError)) as info:
        tc.run(tc.Program.read(str(prog)), tools=tools, start="machine_zero")   # parse errors may come from read()
    err = info.value
    got = getattr(err, "message", None) or str(err)
    assert got == message
    assert err.line == line
