"""Heidenhain programs as files: BEGIN PGM / END PGM frame every program (a transfer cut short
is an error, not a shorter program) and every line end (LF, CRLF, a lone CR) ends a block."""
import numpy as np
import pytest

import toolcomp as tc

LINES = ["BEGIN PGM F MM", "TOOL DEF 1 L+0 R+2", "TOOL CALL 1 Z S3000", "L X+0 Y+0 Z+5 R0 FMAX",
         "L Z-1 F100", "L X+10", "L Y+10", "L Z+5 R0 FMAX", "END PGM F MM"]


def text(lines, eol="\n"):
    return "".join(f"{i} {l}{eol}" for i, l in enumerate(lines))


def run(src, strict=True):
    # The points below count the first move from machine zero, where the run is told to start.
    return tc.run(tc.Program.parse(src, dialect="heidenhain", strict=strict), strict=strict, start="machine_zero")


@pytest.mark.parametrize("eol", ["\r", "\r\n", "\r\r\n"], ids=["cr", "crlf", "cr-cr-lf"])
def test_every_line_end_gives_the_same_blocks_and_lines(eol):
    ref = run(text(LINES)).path
    p = run(text(LINES, eol)).path
    assert len(p) == len(ref) == 5
    np.testing.assert_array_equal(p.end, ref.end)
    np.testing.assert_array_equal(p.line, [4, 5, 6, 7, 8])  # L blocks on source lines 4..8


def test_empty_program_has_no_begin_pgm():
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse("", dialect="heidenhain")
    assert (e.value.code, e.value.line) == ("begin_pgm_missing", 1)


def test_first_block_must_be_begin_pgm():
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(text(LINES[1:]), dialect="heidenhain")
    assert (e.value.code, e.value.line) == ("begin_pgm_missing", 1)


def test_comment_lines_before_begin_pgm_are_allowed():
    assert len(run("; exported by the CAM system\n" + text(LINES)).path) == 5


@pytest.mark.parametrize("keep, line", [(8, 8), (6, 6)])
def test_missing_end_pgm_is_reported_at_the_last_line(keep, line):
    src = text(LINES[:keep])
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse(src, dialect="heidenhain")
    assert (e.value.code, e.value.line) == ("end_pgm_missing", line)
    # Leniently: the blocks that arrived run, then the error at the last line.
    res = run(src, strict=False)
    assert not res.ok
    assert [(d.code, d.line) for d in res.diagnostics if d.severity == "error"] == [("end_pgm_missing", line)]
    assert len(res.path) == keep - 3  # the L blocks, from line 4 on


def test_blocks_after_end_pgm_are_not_part_of_the_program():
    assert len(run(text(LINES) + "9 L X+99 F100\n").path) == 5
