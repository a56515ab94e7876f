"""Every ISO program of the test corpus read piece by piece (7-byte pieces: a piece boundary
at every line end, so every line is a piece of its own or shares one with a neighbour) and
streamed in 3-segment chunks gives what the whole program, parsed at once, gives to run():
the same path segment for segment, the same warnings, the same error (type, code, line)."""
import pathlib

import numpy as np
import pytest

import toolcomp as tc

HERE = pathlib.Path(__file__).resolve().parent
PROGRAMS = sorted(p for p in (HERE.parent / "programs").rglob("*") if p.suffix in (".ngc", ".nc", ".tap"))
COLUMNS = ("kind", "start", "end", "center", "abc", "line", "file", "tool", "feed", "side", "generated",
           "tool_offset", "plane", "turns", "normal", "tool_axis")
# Tools 1..20 with lengths and diameters, for the programs that call any of them.
TOOLS = tc.ToolTable.parse("".join(f"T{t} P{t} Z{10 + t} D{0.5 * t}\n" for t in range(1, 21)), "linuxcnc")


def outcome(fn):
    try:
        return fn(), None
    except tc.Error as e:
        return None, (type(e).__name__, e.code, e.line)


@pytest.mark.parametrize("path", PROGRAMS, ids=[str(p.relative_to(HERE.parent / "programs")) for p in PROGRAMS])
def test_streamed_in_pieces_equals_whole(path):
    kwargs = dict(strict=False, search_path=[str(path.parent), str(path.parent / "subs")])
    whole, whole_err = outcome(lambda: tc.run(tc.Program.read(str(path), strict=False), TOOLS, **kwargs))

    def streamed():
        s = tc.iter_run(str(path), TOOLS, chunk=3, piece_bytes=7, **kwargs)
        return list(s), s

    got, got_err = outcome(streamed)
    assert got_err == whole_err
    if whole is None:
        return
    chunks, stream = got
    assert sum(len(c) for c in chunks) == len(whole.path)
    for c in COLUMNS:
        joined = np.concatenate([getattr(x, c) for x in chunks]) if chunks else getattr(whole.path, c)[:0]
        np.testing.assert_array_equal(joined, getattr(whole.path, c), err_msg=c)
    assert [(d.code, d.line, d.file) for d in stream.diagnostics] == [(d.code, d.line, d.file) for d in whole.diagnostics]
    assert stream.blocks == whole.blocks
    assert stream.files == whole.path.files
