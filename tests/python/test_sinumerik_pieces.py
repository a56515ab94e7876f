"""Sinumerik program files without control flow are read a piece at a time as they run (as
LinuxCNC / Fanuc files are): the path is that of the program read whole, segment for segment,
however the file is cut (every line boundary is a piece boundary somewhere); macros (DEFINE),
labels, jumps and loops make a file be read whole; a syntax error is raised at its line as
when the file is read whole, after M30 too."""
import numpy as np
import pytest

import toolcomp as tc
from same_path import assert_same


def pocket(rows):
    """A CAM-style 840D program (NX post: header comments, $TC_DP tool data, a G41 contour of
    steps up and right: lines, arcs by CR=, RND= and CHF= at the outside corners; a drilling
    cycle called modally, M30)."""
    out = ["%_N_POCKET_MPF", ";$PATH=/_N_WKS_DIR/_N_POCKET_WPD", "; NX post 840D, metric",
           "$TC_DP1[1,1]=120", "$TC_DP3[1,1]=60", "$TC_DP6[1,1]=2",
           "$TC_DP1[2,1]=200", "$TC_DP3[2,1]=80", "$TC_DP6[2,1]=2.5",
           "N10 G90 G17 G71 G40 G94", "N20 T1 D1 M6", "N30 S8000 M3 M8", "N40 G0 X-10 Y-10 Z5",
           "N50 G1 Z-2 F300", "N60 G41 G1 X0 Y0 F1200"]
    n, x, y = 70, 0, 0
    for r in range(rows):
        corner = "RND=2" if r % 2 == 0 else "CHF=1"
        out += [f"N{n} G1 X{x + 8} Y{y}", f"N{n + 10} G1 Y{y + 8} {corner}", f"N{n + 20} G1 X{x + 16}",
                f"N{n + 30} G3 X{x + 20} Y{y + 12} CR=4", f"N{n + 40} G2 X{x + 24} Y{y + 16} CR=4",
                f"N{n + 50} G1 X{x + 30}"]
        n, x, y = n + 60, x + 30, y + 16
    out += [f"N{n} G40 G1 X{x + 10} Y{y - 10}", f"N{n + 10} G0 Z50", f"N{n + 20} T2 D1 M6", f"N{n + 30} S3000 M3",
            f"N{n + 40} MCALL CYCLE81(10, 0, 2, -15, 0)", f"N{n + 50} X30 Y30", f"N{n + 60} X60 Y30",
            f"N{n + 70} MCALL", f"N{n + 80} G0 Z100 M9", f"N{n + 90} M30"]
    return "\n".join(out) + "\n"


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


@pytest.mark.parametrize("piece", [1, 37, 500, 1 << 20])
def test_a_cam_program_in_pieces_is_the_program_read_whole(tmp_path, piece):
    text = pocket(60)
    f = write(tmp_path, "POCKET.MPF", text)
    whole = tc.run(tc.Program.parse(text, dialect="sinumerik", name=f))
    assert whole.path.side.any() and len(whole.path) > 300
    # G41 with a tool of radius 2 (NORM): the entry ends 2 mm left of the contour's start,
    # (0, 2); the first line, 2 mm left of (0, 0)-(8, 0), ends where the equidistant of the
    # next line up (x = 8 - 2) meets it: (6, 2).
    first = int(np.flatnonzero(np.asarray(whole.path.side) != 0)[0])
    np.testing.assert_allclose(whole.path.end[first][:2], [0, 2], atol=1e-9)
    np.testing.assert_allclose(whole.path.end[first + 1][:2], [6, 2], atol=1e-9)
    assert_same(whole.path, list(tc.iter_run(f, chunk=97, piece_bytes=piece)))
    from_file = tc.run(f)
    assert_same(whole.path, [from_file.path])
    assert from_file.dwell_time == whole.dwell_time and from_file.path.files == whole.path.files


def test_a_called_subprogram_between_pieces(tmp_path):
    (tmp_path / "SIDE.SPF").write_text("G91 G1 X5 F500\nY5\nX-5\nY-5\nG90\nM17\n")
    main = "G90 G17 G71 G94\nG0 X0 Y0 Z5\nG1 Z-1 F400\n" + "".join(f"X{i} Y0\nSIDE\n" for i in range(0, 400, 20)) + "M30\n"
    f = write(tmp_path, "MAIN.MPF", main)
    whole = tc.run(tc.Program.parse(main, dialect="sinumerik", name=f), search_path=[str(tmp_path)])
    stream = tc.iter_run(f, chunk=11, piece_bytes=16, search_path=[str(tmp_path)])
    chunks = list(stream)
    assert_same(whole.path, chunks)
    assert stream.files == whole.path.files and len(stream.files) == 2
    # Each pass of SIDE makes a 5 mm square from where it is called.
    sq = whole.path.end[np.asarray(whole.path.file) == 1][:4, :2]
    np.testing.assert_allclose(sq, [[5, 0], [5, 5], [0, 5], [0, 0]], atol=1e-9)


@pytest.mark.parametrize("flow", [
    "R1=0\nLOOP_A:\nG1 X=R1*10 F500\nR1=R1+1\nIF R1<40 GOTOB LOOP_A\n",
    "FOR R2=0 TO 39\nG1 X=R2*10 F500\nENDFOR\n",
    "DEFINE STEP AS G1 X=R3*10 F500\nR3=0\nWHILE R3<40\nSTEP\nR3=R3+1\nENDWHILE\n",
])
def test_programs_that_steer_give_the_same_path(tmp_path, flow):
    text = "G90 G17 G71 G94\nG0 X0 Y0 Z5\n" + "G1 Y1 F500\n" * 200 + flow + "G0 Z50\nM30\n"
    f = write(tmp_path, "FLOW.MPF", text)
    whole = tc.run(tc.Program.parse(text, dialect="sinumerik", name=f))
    assert whole.path.end[-2][0] == 390.0  # the last pass of the loop: X = 39 x 10
    assert_same(whole.path, list(tc.iter_run(f, chunk=13, piece_bytes=8)))


@pytest.mark.parametrize("piece", [8, 1 << 20])
def test_a_syntax_error_in_a_later_piece(tmp_path, piece):
    text = "G90 G17 G71 G94\nG0 X0 Y0 Z5\n" + "G1 X1 F500\nX0\n" * 300 + "G1 X=(((\nX5\nM30\n"
    f = write(tmp_path, "BAD.MPF", text)
    with pytest.raises(tc.ParseError) as e:
        list(tc.iter_run(f, piece_bytes=piece))
    assert e.value.line == 603 and e.value.code == "syntax_error"
    res = tc.run(f, strict=False)
    assert [(d.code, d.line) for d in res.diagnostics if d.severity == "error"] == [("syntax_error", 603)]
    assert len(res.path) == 601  # the rapid and the 600 moves before the bad line


def test_a_syntax_error_after_m30_is_raised_as_when_read_whole(tmp_path):
    text = "G90 G17 G71 G94\nG0 X0 Y0 Z5\n" + "G1 X1 F500\nX0\n" * 300 + "M30\nG1 X=(((\n"
    f = write(tmp_path, "AFTER.MPF", text)
    for run in (lambda: tc.run(tc.Program.parse(text, dialect="sinumerik", strict=False)),
                lambda: tc.run(f), lambda: list(tc.iter_run(f, piece_bytes=8))):
        with pytest.raises(tc.ParseError) as e:
            run()
        assert e.value.line == 604


def test_check_file_reads_pieces_as_parse_reads_the_whole(tmp_path):
    text = pocket(200)
    f = write(tmp_path, "CHECK.MPF", text)
    assert tc.Program.check_file(f) == len(tc.Program.parse(text, dialect="sinumerik"))
    # A macro defined in the second piece (the first is 64 kB) is known in the third: its
    # text, a syntax error, is met where it is used (line 18002).
    bad = "G1 X1 F100\n" * 8000 + "DEFINE OOPS AS X=(((\n" + "G1 X1 F100\n" * 10000 + "OOPS\nM30\n"
    g = write(tmp_path, "BAD.MPF", bad)
    # A syntax error after M30 is found too.
    h = write(tmp_path, "AFTER.MPF", "G1 X1 F100\n" * 20000 + "M30\nG1 X=(((\n")
    for f, line in ((g, 18002), (h, 20002)):
        text = open(f).read()
        for check in (lambda: tc.Program.check_file(f), lambda: tc.Program.parse(text, dialect="sinumerik")):
            with pytest.raises(tc.ParseError) as e:
                check()
            assert e.value.line == line


def test_an_inch_program_in_pieces_is_the_program_read_whole(tmp_path):
    # A Mastercam-style inch program (G70: geometry in inches; the tool data in the machine's
    # metric basic system, r = 0.125 mm): 8000 steps of 1 inch, 160 kB, so that the file is
    # read in several pieces (a read takes 64 kB at least).
    rows = "".join(f"N{100 + 20 * i} G1 X{i + 1:.4f}\nN{110 + 20 * i} G1 Y{i + 1:.4f}\n" for i in range(4000))
    text = ("%_N_STEPS_MPF\n; Mastercam 840D post, inch\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.125\n"
            "N10 G70 G90 G17 G94\nN20 T1 D1 M6\nN30 G0 X-0.5 Y-0.5 Z0.2\nN40 G1 Z-0.05 F20.\n"
            "N50 G41 G1 X0. Y0.\n" + rows + "N90000 G40 G1 X4002. Y3999.\nN90010 M30\n")
    f = write(tmp_path, "STEPS.MPF", text)
    whole = tc.run(tc.Program.parse(text, dialect="sinumerik", name=f))
    # In mm: left of the first step (0, 0)-(25.4, 0) by 0.125, up to where the equidistant of
    # the step up (x = 25.4 - 0.125) meets it.
    first = int(np.flatnonzero(np.asarray(whole.path.side) != 0)[0])
    np.testing.assert_allclose(whole.path.end[first][:2], [0, 0.125], atol=1e-9)
    np.testing.assert_allclose(whole.path.end[first + 1][:2], [25.275, 0.125], atol=1e-9)
    assert len(text) > 2 * (1 << 16)
    for piece in (1, 64, 4096):
        assert_same(whole.path, list(tc.iter_run(f, chunk=53, piece_bytes=piece)))
    assert_same(whole.path, [tc.run(f).path])
