"""The overcut watch over long programs (it runs on a thread of its own once a program has
made a few thousand of its calls): its warnings come out in the same places among the other
diagnostics as in a short program, in run(), in the stream, and before an error.

The program: N one-millimetre slots under a 10 mm cutter (G41.1 D10), LinuxCNC's gouge error
made a warning (GougeReaction.report). Slot k has the lines X(30+40k) (line 4+4k), Y2, X(31+40k),
Y0 (line 7+4k). A single slot gives (tests elsewhere): the gouge at line 6 (the move of 5) and
at line 8 (the move of 7), the tool centre 2 mm from the slot's sides: lines 5 and 6 from the
contour of line 4, line 7 twice (its two elements) from that of line 8."""
import pytest

import toolcomp as tc

TOOLS = tc.ToolTable.parse("T1 P1 D2\n", "linuxcnc")


def profile():
    p = tc.ControlProfile("linuxcnc")
    r = p.radius
    r.gouge = tc.GougeReaction.report
    p.radius = r
    return p


def slots(n, tail=""):
    out = ["G21 G0 X0 Y-10", "G41.1 D10", "G1 X0 Y0 F100"]
    for k in range(n):
        out += [f"X{30 + 40 * k}", "Y2", f"X{31 + 40 * k}", "Y0"]
    out += [f"X{40 * n + 20}"] + ([tail] if tail else []) + [f"G40 G0 X{40 * n + 30} Y-10", "M2"]
    return "\n".join(out) + "\n"


def expected(n):
    """(code, line, line named in an overcut message) in the order the stage reports them:
    a gouge is reported when the next move settles the corner, an overcut once the three
    programmed elements after its element have been seen."""
    gouges = list(range(6, 4 * n + 5, 2))
    overcuts = []
    for k in range(n):
        overcuts.append([(5 + 4 * k, 4 + 4 * k), (6 + 4 * k, 4 + 4 * k)])
        overcuts.append([(7 + 4 * k, 8 + 4 * k), (7 + 4 * k, 8 + 4 * k)])
    seq = [("comp_gouge", 6, None)]
    for i, pair in enumerate(overcuts):
        if 8 + 2 * i <= 4 * n + 4:
            seq.append(("comp_gouge", 8 + 2 * i, None))
        seq += [("comp_overcut", line, near) for line, near in pair]
    return seq


def seen(diagnostics):
    out = []
    for d in diagnostics:
        near = int(d.message.split("contour of line ")[1].split(",")[0]) if d.code == "comp_overcut" else None
        out.append((d.code, d.line, near))
    return out


@pytest.mark.parametrize("threads", [True, False])
@pytest.mark.parametrize("n", [1, 3, 5000])
def test_warnings_in_place_short_and_long(n, threads):
    res = tc.run(tc.Program.parse(slots(n)), tools=TOOLS, profile=profile(), strict=False, threads=threads)
    assert seen(res.diagnostics) == expected(n)
    assert all(d.severity == "warning" for d in res.diagnostics)


def test_a_file_run_without_threads_is_the_same(tmp_path):
    # Read piece by piece (no control flow), the next piece parsed when the run asks for it
    # and the watch on the run's thread: the same warnings, the same path.
    f = tmp_path / "slots.ngc"
    f.write_text(slots(5000))
    alone = tc.run(str(f), TOOLS, profile=profile(), strict=False, threads=False)
    assert seen(alone.diagnostics) == expected(5000)
    helped = tc.run(str(f), TOOLS, profile=profile(), strict=False)
    assert alone.blocks == helped.blocks == 4 * 5000 + 6
    for col in ("start", "end", "center", "line", "kind"):
        assert getattr(alone.path, col).tobytes() == getattr(helped.path, col).tobytes()


def test_stream_has_the_same_warnings(tmp_path):
    f = tmp_path / "slots.ngc"
    f.write_text(slots(5000))
    s = tc.iter_run(str(f), TOOLS, chunk=3000, piece_bytes=4096, profile=profile(), strict=False)
    chunks = list(s)
    assert sum(len(c) for c in chunks) == len(tc.run(str(f), TOOLS, profile=profile(), strict=False).path)
    assert seen(s.diagnostics) == expected(5000)


def test_warnings_before_an_error_stay_in_the_stream(tmp_path):
    # An unknown G code after the slots: strict, the stream ends with the error, its
    # diagnostics are the warnings reported before it (a prefix of the lenient run's: there
    # the error also settles the last corners and reports the last overcuts).
    n = 5000
    f = tmp_path / "bad.ngc"
    f.write_text(slots(n, tail="G5.3"))
    bad_line = 4 + 4 * n + 1
    s = tc.iter_run(str(f), TOOLS, profile=profile())
    with pytest.raises(tc.Error) as e:
        list(s)
    assert e.value.line == bad_line
    lenient = tc.run(str(f), TOOLS, profile=profile(), strict=False)
    assert seen(lenient.diagnostics)[:-1] == expected(n)[:len(lenient.diagnostics) - 1]
    assert lenient.diagnostics[-1].line == bad_line
    got = seen(s.diagnostics)
    assert got == seen(lenient.diagnostics)[:len(got)]
    assert len(got) >= len(expected(n)) - 4  # all but the last slot's overcuts



def keyhole():
    """A keyhole under G41.1 D2 (r = 1), no inside corner: eight 12.5 mm lines along Y0
    (lines 4-11), a CCW arc of radius 1.25 about (101, 0.75) from (100, 0) to (100, 1.5)
    (line 12), nine lines back to X0 rising from Y1.5 by 0.004 per mm, split half a piece
    off the first ones (lines 13-21). The tool centre runs 1 mm inside, so each line's comes
    within the radius of the lines across the gap: the neighbours watched decide which
    warn. Line 10 (X75-87.5, tool centre at Y1) is 0.55 mm from line 14 (Y1.55 at X87.5)."""
    out = ["G21 G0 X0 Y-5", "G41.1 D2", "G1 X0 Y0 F100"]
    out += [f"X{12.5 * k}" for k in range(1, 9)]
    out += ["G3 X100 Y1.5 I1 J0.75"]
    xs = [93.75 - 12.5 * k for k in range(8)] + [0]
    out += [f"G1 X{x} Y{1.5 + 0.004 * (100 - x):.4f}" for x in xs]
    out += ["G40 G0 X0 Y10", "M2"]
    return "\n".join(out) + "\n"


def overcuts(lookahead):
    p = profile()
    r = p.radius
    r.lookahead = lookahead
    r.gouge = tc.GougeReaction.skip  # only skipping looks ahead (no element here is skipped)
    p.radius = r
    res = tc.run(tc.Program.parse(keyhole()), tools=TOOLS, profile=p, strict=False)
    assert [d.code for d in res.diagnostics if d.code != "comp_overcut"] == []
    return sorted(x[1:] for x in seen(res.diagnostics) if x[0] == "comp_overcut")


@pytest.mark.parametrize("lookahead", [2, 3, 5])
def test_the_window_does_not_move_with_the_lookahead(lookahead):
    # The neighbours watched are counted from the element's own place in the contour, not
    # from where a longer look-ahead releases it. A stage holding its elements two blocks
    # longer used to see two programmed elements fewer before and two more after: line 9
    # warned about line 15, six elements on, and line 14 did not about line 11.
    want = overcuts(1)
    assert (10, 14) in want
    assert all(abs(line - near) <= 4 for line, near in want)  # 3 neighbours, +1 for a corner's
    assert overcuts(lookahead) == want
