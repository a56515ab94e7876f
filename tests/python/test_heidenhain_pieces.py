"""Heidenhain program files without labels or jumps are read a piece at a time as they run (as
LinuxCNC, Fanuc and Sinumerik files are): the path is that of the program read whole, segment
for segment, whatever the pieces' size; a cycle definition continued with '~' is never cut
between pieces; the unit of BEGIN PGM and the blank of BLK FORM hold for the whole file; labels
(LBL, CALL LBL, FN 9-12 jumps) make a file be read whole; a syntax error, BEGIN PGM or END PGM
missing are raised with the code and line they have when the file is read whole."""
import numpy as np
import pytest

import toolcomp as tc
from same_path import assert_same


def contour(groups, unit=1.0, tilde_every=1):
    """A CAM-style Klartext body: per group of 10 blocks a contour step with RL (a line, a
    rounding, a line, a chamfer, a line, an arc about CC), then R0; every `tilde_every`-th group
    a drilling cycle defined over 10 lines continued with '~' (one of them blank), called at a
    position, Q parameters set and used (so that most pieces' ends fall in such a definition). Lengths times `unit` (INCH programs: 0.1)."""
    out = []
    u = unit
    for g in range(groups):
        y = (g % 20) * 20 * u
        out += [f"L X+0 Y{y:+.4f} R0 FMAX", f"L X{5 * u:+.4f} Y{y:+.4f} RL F{300 * u:.1f}",
                f"L X{40 * u:+.4f} Y{y:+.4f}", f"RND R{3 * u:.4f}", f"L X{40 * u:+.4f} Y{y + 5 * u:+.4f}",
                f"CHF {0.5 * u:.4f}", f"L X{60 * u:+.4f} Y{y + 5 * u:+.4f}", f"CC X{60 * u:+.4f} Y{y + 10 * u:+.4f}",
                f"C X{60 * u:+.4f} Y{y + 15 * u:+.4f} DR+", f"L X{70 * u:+.4f} Y{y + 15 * u:+.4f} R0 F MAX ; off"]
        if g % tilde_every == 0:
            out += ["CYCL DEF 200 DRILLING ~", "  Q200=2 ;SET-UP CLEARANCE ~", "", "  Q201=-5 ;DEPTH ~",
                    "  Q206=+150 ;FEED RATE FOR PLNGNG ~", "  Q202=2 ;PLUNGING DEPTH ~",
                    "  Q210=0 ;DWELL TIME AT TOP ~", "  Q203=+0 ;SURFACE COORDINATE ~",
                    "  Q204=20 ;2ND SET-UP CLEARANCE ~", "  Q211=0 ;DWELL TIME AT DEPTH",
                    f"CYCL CALL POS X{10 * u:+.4f} Y{y:+.4f} Z+0 FMAX", "FN 0: Q1 = +5", "Q2 = Q1 * 2 + 1",
                    "L Z+Q2 R0 FMAX", "* - next step", f"L Z{-1 * u:+.4f} R0 F200"]
    return out


def program(body, name="PART", inch=False, head=None, foot=None):
    unit = "INCH" if inch else "MM"
    r = 0.02 if inch else 0.5
    if head is None:
        head = [f"BEGIN PGM {name} {unit}", "BLK FORM 0.1 Z X+0 Y+0 Z-20", "BLK FORM 0.2 X+100 Y+400 Z+0",
                f"TOOL DEF 1 L+0 R+{r}", "TOOL CALL 1 Z S5000", "L X-10 Y-10 Z+5 R0 FMAX M3", "L Z-1 F200"]
    if foot is None:
        foot = ["L Z+50 R0 FMAX M30", f"END PGM {name} {unit}"]
    lines = head + body + foot
    n, out = 0, []
    for line in lines:
        if line and not line.startswith(" "):
            out.append(f"{n} {line}")
            n += 1
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_bytes(text.encode())
    return str(p)


def diagnostics(res):
    return [(d.code, d.severity, d.message, d.line, d.column) for d in res.diagnostics]


@pytest.fixture(scope="module")
def cam_text():
    text = program(contour(1500))
    assert len(text) > 300_000  # pieces of 64 kB, 128 kB, then the rest
    return text


@pytest.mark.parametrize("piece", [1, 37, 70_000, 1 << 20])
def test_a_cam_program_in_pieces_is_the_program_read_whole(tmp_path, cam_text, piece):
    f = write(tmp_path, "PART.H", cam_text)
    whole = tc.run(tc.Program.parse(cam_text, dialect="heidenhain", name=f))
    assert whole.ok and whole.path.side.any() and len(whole.path) > 15_000
    # RL with a tool of radius 0.5: the line from (5, 0) to (40, 0) (line 10) runs 0.5 mm left
    # of it, up to the rounding of R3 (its start 3 mm before the corner, at x = 37), whose arc
    # of radius 3 - 0.5 about (37, 3) ends at (39.5, 3).
    at = int(np.flatnonzero(np.asarray(whole.path.line) == 10)[0])
    np.testing.assert_allclose(whole.path.end[at][:2], [37, 0.5], atol=1e-9)
    np.testing.assert_allclose(whole.path.end[at + 1][:2], [39.5, 3], atol=1e-9)
    np.testing.assert_allclose(whole.path.center[at + 1][:2], [37, 3], atol=1e-9)
    # The drilling cycle (Q201=-5 from the surface Z+0) goes down to Z-5, and is called in
    # every group: 1500 times.
    assert whole.path.end[:, 2].min() == pytest.approx(-5)
    assert np.count_nonzero(np.isclose(whole.path.end[:, 2], -5)) == 1500
    assert_same(whole.path, list(tc.iter_run(f, chunk=997, piece_bytes=piece)))
    from_file = tc.run(f)
    assert_same(whole.path, [from_file.path])
    assert diagnostics(from_file) == diagnostics(whole) == []
    assert from_file.dwell_time == whole.dwell_time and from_file.path.files == whole.path.files
    assert from_file.blocks == whole.blocks
    assert from_file.blank == whole.blank == ((0, 0, -20), (100, 400, 0))
    assert tc.Program.check_file(f) == whole.blocks


@pytest.mark.parametrize("nl", ["\r\n", "\r", "\r\r\n"])
def test_other_line_ends(tmp_path, cam_text, nl):
    text = cam_text.replace("\n", nl)
    f = write(tmp_path, "CRLF.H", text)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", name=f))
    assert_same(whole.path, [tc.run(f).path])
    assert_same(whole.path, list(tc.iter_run(f, chunk=5000)))


def test_an_inch_program_in_pieces(tmp_path):
    text = program(contour(1500, unit=0.1), inch=True)
    f = write(tmp_path, "INCH.H", text)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", name=f))
    assert whole.ok
    # INCH: 0.5 in of depth is 12.7 mm (Q201=-5 of the cycle stays -5 in: -127 mm); the
    # blank's corners too.
    assert whole.path.end[:, 2].min() == pytest.approx(-127)
    from_file = tc.run(f)
    assert_same(whole.path, [from_file.path])
    assert from_file.blank == whole.blank == ((0, 0, -508), (2540, 10160, 0))
    assert_same(whole.path, list(tc.iter_run(f, chunk=4096)))


def test_a_called_program_between_pieces(tmp_path, cam_text):
    (tmp_path / "SIDE.H").write_text("0 BEGIN PGM SIDE MM\n1 L IX+5 R0 F500\n2 L IY+5\n3 L IX-5\n4 L IY-5\n"
                                     "5 END PGM SIDE MM\n")
    lines = cam_text.splitlines()
    starts = [i for i, l in enumerate(lines) if "L X+0 Y" in l]  # the first block of a group
    lines[starts[len(starts) // 3]:starts[len(starts) // 3]] = ["CALL PGM SIDE"]
    lines[starts[2 * len(starts) // 3] + 1:starts[2 * len(starts) // 3] + 1] = ["CALL PGM SIDE.H"]
    text = "\n".join(lines) + "\n"
    f = write(tmp_path, "MAIN.H", text)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", name=f), search_path=[str(tmp_path)])
    assert whole.ok
    stream = tc.iter_run(f, chunk=777, search_path=[str(tmp_path)])
    assert_same(whole.path, list(stream))
    assert stream.files == whole.path.files and len(stream.files) == 2
    from_file = tc.run(f, search_path=[str(tmp_path)])
    assert_same(whole.path, [from_file.path])
    sq = whole.path.end[np.asarray(whole.path.file) == 1][:4, :2]
    start = whole.path.end[np.flatnonzero(np.asarray(whole.path.file) == 1)[0] - 1][:2]
    np.testing.assert_allclose(sq - start, [[5, 0], [5, 5], [0, 5], [0, 0]], atol=1e-9)


@pytest.mark.parametrize("flow", [
    ["LBL 7", "L IX+1 R0 F500", "CALL LBL 7 REP 3"],  # a section repeated: 4 passes
    ["FN 0: Q5 = +0", "LBL 7", "L IX+1 R0 F500", "FN 1: Q5 = +Q5 + +1", "FN 12: IF +Q5 LT +4 GOTO LBL 7"],
    ["CALL LBL \"SUB\"", "CALL LBL \"SUB\"", "CALL LBL \"SUB\"", "CALL LBL \"SUB\"", "L Z+60 R0 FMAX M30",
     "LBL \"SUB\"", "L IX+1 R0 F500", "LBL 0"],
])
def test_programs_with_labels_give_the_same_path(tmp_path, cam_text, flow):
    lines = cam_text.splitlines()
    at = len(lines) - 2  # before M30
    lines[at:at] = ["L X+0 Y+0 R0 FMAX"] + flow
    text = "\n".join(lines) + "\n"
    f = write(tmp_path, "FLOW.H", text)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", name=f))
    assert whole.ok
    np.testing.assert_array_equal(whole.path.end[-6:-1, 0], [0, 1, 2, 3, 4])  # four passes of IX+1
    assert_same(whole.path, [tc.run(f).path])
    assert_same(whole.path, list(tc.iter_run(f, chunk=1313)))


def test_a_blank_defined_in_a_later_piece_is_the_whole_programs(tmp_path, cam_text):
    lines = cam_text.splitlines()
    lines[len(lines) - 100:len(lines) - 100] = ["BLK FORM 0.2 X+200 Y+500 Z+5"]
    text = "\n".join(lines) + "\n"
    f = write(tmp_path, "BLK.H", text)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", name=f))
    assert whole.blank == ((0, 0, -20), (200, 500, 5))
    res = tc.run(f)
    assert res.blank == whole.blank
    assert_same(whole.path, [res.path])


@pytest.mark.parametrize("piece", [1, 1 << 20])
def test_a_syntax_error_in_a_later_piece(tmp_path, cam_text, piece):
    lines = cam_text.splitlines()
    bad = [i for i, l in enumerate(lines) if "L X+0 Y" in l][-2]  # a block of its own, near the end
    lines[bad] = "7 L X+1&"
    text = "\n".join(lines) + "\n"
    f = write(tmp_path, "BAD.H", text)
    with pytest.raises(tc.ParseError) as whole_error:
        tc.Program.parse(text, dialect="heidenhain")
    assert whole_error.value.line == bad + 1
    for run in (lambda: tc.run(f), lambda: list(tc.iter_run(f, piece_bytes=piece)), lambda: tc.Program.check_file(f)):
        with pytest.raises(tc.ParseError) as e:
            run()
        assert (e.value.code, e.value.line, e.value.column) == ("bad_word", bad + 1, 8)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", strict=False, name=f), strict=False)
    res = tc.run(f, strict=False)
    assert diagnostics(res) == diagnostics(whole)
    assert [(d.code, d.line) for d in res.diagnostics if d.severity == "error"] == [("bad_word", bad + 1)]
    assert_same(whole.path, [res.path])  # the path up to the bad line
    stream = tc.iter_run(f, strict=False, piece_bytes=piece)
    assert_same(whole.path, list(stream))
    assert [(d.code, d.line) for d in stream.diagnostics] == [("bad_word", bad + 1)]


def test_a_syntax_error_after_m30_is_raised_as_when_read_whole(tmp_path, cam_text):
    text = cam_text.replace("M30\n", "M30\n9 L X+1&\n")
    f = write(tmp_path, "AFTER.H", text)
    line = text[:text.index("9 L X+1&")].count("\n") + 1
    for run in (lambda: tc.run(tc.Program.parse(text, dialect="heidenhain", strict=False)),
                lambda: tc.run(f), lambda: list(tc.iter_run(f, piece_bytes=8))):
        with pytest.raises(tc.ParseError) as e:
            run()
        assert (e.value.code, e.value.line) == ("bad_word", line)


@pytest.mark.parametrize("case", ["no_end", "no_begin", "tilde_at_the_end"])
def test_the_frame_is_checked_as_when_read_whole(tmp_path, cam_text, case):
    lines = cam_text.splitlines()
    if case == "no_end":
        lines = lines[:-1]  # END PGM missing: raised after the run, at the last line
        want = ("end_pgm_missing", len(lines), 1)
    elif case == "no_begin":
        lines[0] = "; BEGIN PGM written as a comment"
        want = ("begin_pgm_missing", 2, 3)  # the first block with words: "1 BLK FORM ..."
    else:
        lines = lines[:-1] + ["CYCL DEF 200 DRILLING ~", "  Q200=2 ~"]  # the file ends inside a block
        want = ("end_pgm_missing", len(lines), 1)
    text = "\n".join(lines) + "\n"
    f = write(tmp_path, "FRAME.H", text)
    whole = tc.run(tc.Program.parse(text, dialect="heidenhain", strict=False, name=f), strict=False)
    assert [(d.code, d.line, d.column) for d in whole.diagnostics if d.severity == "error"] == [want]
    res = tc.run(f, strict=False)
    assert diagnostics(res) == diagnostics(whole)
    assert_same(whole.path, [res.path])
    assert len(res.path) > 15_000  # the whole program ran before the error
    with pytest.raises(tc.ParseError) as e:
        list(tc.iter_run(f, chunk=10_000))
    assert (e.value.code, e.value.line, e.value.column) == want
    with pytest.raises(tc.ParseError) as e:
        tc.Program.check_file(f)
    assert (e.value.code, e.value.line, e.value.column) == want


def test_text_after_end_pgm_is_not_read(tmp_path, cam_text):
    text = cam_text + "garbage & ~\nLBL 1\n" * 3
    f = write(tmp_path, "TAIL.H", text)
    whole = tc.run(tc.Program.parse(cam_text, dialect="heidenhain", name=f))
    assert_same(whole.path, [tc.run(f).path])
    assert_same(whole.path, list(tc.iter_run(f, chunk=8192)))
    assert tc.Program.check_file(f) == whole.blocks
