"""Line ends as each control's files have them: Fanuc, the 9/Series, Sinumerik and Heidenhain
read CR, LF and CRLF alike (a lone CR ends a line; "\\r\\n" and "\\r\\r\\n" are one line end),
whether a program is parsed, read whole, read in pieces or called; LinuxCNC reads up to LF
only, as rs274 does (a CR-only file is one long line there)."""
import numpy as np
import pytest

import toolcomp as tc

LINES = ["G21 G90 G0 X0 Z0", "G1 Z2 F100", "(a comment)", "G1 Z5", "M30"]  # Z: a lathe's X is a diameter
ENDS = {"LF": "\n", "CR": "\r", "CRLF": "\r\n", "CRCRLF": "\r\r\n"}


def _text(end):
    return end.join(LINES) + end


def _check(res):
    np.testing.assert_array_equal(res.nominal.end[:, 2], [0, 2, 5])
    assert list(res.nominal.line) == [1, 2, 4]


@pytest.mark.parametrize("dialect", ["fanuc", "rockwell"])
@pytest.mark.parametrize("end", sorted(ENDS))
def test_iso_controls_read_every_line_end(dialect, end):
    _check(tc.run(tc.Program.parse(_text(ENDS[end]), dialect=dialect)))


@pytest.mark.parametrize("end", sorted(ENDS))
def test_a_program_file_read_in_pieces(tmp_path, end):
    # 200 000 lines in pieces of 64 KiB and more: line ends fall at every piece boundary.
    body = ["G21 G90 G0 X0 Y0"] + [f"G1 X{k % 7} F100" for k in range(200_000)] + ["M30"]
    path = tmp_path / "long.nc"
    path.write_bytes(ENDS[end].join(body).encode() + ENDS[end].encode())
    res = tc.run(path)
    assert len(res.nominal) == 200_001
    assert res.nominal.line[-1] == 200_001
    np.testing.assert_array_equal(res.nominal.end[1:, 0], [k % 7 for k in range(200_000)])
    stream = tc.iter_run(path, chunk=50_000)
    assert sum(len(p) for p in stream) == 200_001


def test_blank_cr_lines_across_a_read_are_no_long_line(tmp_path):
    # 300 blank lines (lone CRs) around the first read's end (64 KiB): the CRs not yet known to
    # end lines are no line content, so max_line_length=100 holds.
    n = 5940
    head = "G21 G0 X0\r" + "".join(f"G1 X{k % 7} F100\r" for k in range(n))  # 10 + 11 n bytes
    assert len(head) < 65536 < len(head) + 300
    path = tmp_path / "blank.nc"
    path.write_bytes((head + "\r" * 300 + "G1 X9\rM30\r").encode())
    res = tc.run(path, max_line_length=100)
    assert res.nominal.end[-1, 0] == 9
    assert res.nominal.line[-1] == 1 + n + 300 + 1


def test_a_called_fanuc_file_with_cr_ends(tmp_path):
    (tmp_path / "O1000.nc").write_bytes(b"O1000\rG1 X1 F100\r(x)\rG1 Y1\rM99\r")
    res = tc.run(tc.Program.parse("G21 G0 X0 Y0\nM98 P1000\nM30\n", dialect="fanuc"), search_path=[tmp_path])
    np.testing.assert_array_equal(res.nominal.end[-1, :2], [1, 1])
    assert list(res.nominal.line[1:]) == [2, 4]


def test_the_line_of_an_error_counts_cr_ends():
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse("G21 G0 X0\rG1 X1 F100\rG1 X2 Q\rM30\r", dialect="fanuc"))
    assert e.value.line == 3


def test_linuxcnc_reads_a_cr_file_as_one_line_as_rs274_does():
    # rs274 (LinuxCNC 2.9): "Two g codes used from same modal group" for this file.
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse("G21 G0 X0\rG1 X2 F10\rG1 Y3\rM2\r"))
    assert e.value.code == "modal_group_conflict" and e.value.line == 1
