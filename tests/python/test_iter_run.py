"""iter_run: the compensated path in chunks. The chunks joined equal run()'s path segment for
segment, whatever the chunk size and however the file is cut into pieces (piece_bytes down to
a few bytes: every line boundary is a piece boundary somewhere); errors come with run()'s
code and line; an abandoned stream stops its run."""
import os
import time

import numpy as np
import pytest

import toolcomp as tc
from same_path import assert_same

TOOLS = tc.ToolTable.parse("T1 P1 Z50 D6\nT2 P2 Z40 D10\n", "linuxcnc")


def contour(rows, comp="G42.1 D2"):
    """Rows of lines and arcs under compensation (the bench's contour), as LinuxCNC text."""
    out = ["G21 G17 G90 G94 G40 G49", "T1 M6", "G43 H1", "G0 X0 Y0 Z5", "G1 Z-1 F600", comp]
    y = 0.0
    for _ in range(rows):
        out += [f"G1 X100 Y{y:.3f}", f"G1 X100 Y{y + 2:.3f}", f"G1 X95 Y{y + 2:.3f}",
                f"G3 X95 Y{y + 7:.3f} I0 J2.5", f"G1 X5 Y{y + 7:.3f}", f"G2 X5 Y{y:.3f} I0 J-3.5"]
        y += 0.25
    return "\n".join(out + ["G40 G1 X-10 Y-10", "M2"]) + "\n"


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


@pytest.mark.parametrize("chunk,piece", [(1, 7), (5, 64), (777, 1000), (10**6, 4 << 20)])
def test_chunks_join_to_run_path(tmp_path, chunk, piece):
    f = write(tmp_path, "c.ngc", contour(40))
    ref = tc.run(f, TOOLS)
    chunks = list(tc.iter_run(f, TOOLS, chunk=chunk, piece_bytes=piece))
    assert all(len(c) == chunk for c in chunks[:-1]) and 1 <= len(chunks[-1]) <= chunk
    assert_same(ref.path, chunks)
    # Lines count on across pieces: the last move is line 248 (6 + 6 * 40 + 2), the closing G40.
    assert ref.path.line[-1] == 6 + 6 * 40 + 1


def test_stream_reports_blocks_files_and_warnings(tmp_path):
    # The overcut warning of an inside corner onto a step shorter than the radius (r = 5).
    text = ("G21 G0 X-10 Y5\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY-2\nX60\nG40 G0 X70 Y10\nM2\n")
    f = write(tmp_path, "w.ngc", text)
    ref = tc.run(f, TOOLS, strict=False)
    s = tc.iter_run(f, TOOLS, chunk=2, piece_bytes=8, strict=False)
    chunks = list(s)
    assert_same(ref.path, chunks)
    assert [(d.code, d.line) for d in s.diagnostics] == [(d.code, d.line) for d in ref.diagnostics]
    assert s.blocks == ref.blocks == 8
    assert s.files == ref.path.files == [f]
    assert chunks[0].files == [f]


def test_programs_that_steer_are_read_whole_and_stream_the_same(tmp_path):
    # An o-while loop needs the whole text (its blocks run again); the path still comes in
    # chunks, the same as run()'s.
    text = ("G21 G17 G90 G40 G49\nT1 M6\nG43 H1\nG0 X0 Y0 Z5\nG1 Z-1 F600\nG42.1 D2\n#1=0\n"
            "o1 while [#1 LT 3]\n  G1 X100 Y[#1]\n  G1 X100 Y[#1+2]\n  G1 X95 Y[#1+2]\n  G3 X95 Y[#1+7] I0 J2.5\n"
            "  G1 X5 Y[#1+7]\n  G2 X5 Y[#1] I0 J-3.5\n  #1=[#1+0.25]\no1 endwhile\nG40 G1 X-10 Y-10\nM2\n")
    f = write(tmp_path, "loop.ngc", text)
    ref = tc.run(f, TOOLS)
    assert_same(ref.path, list(tc.iter_run(f, TOOLS, chunk=3, piece_bytes=16)))


def test_called_files_are_named_in_chunks(tmp_path):
    sub = tmp_path / "subs"
    sub.mkdir()
    (sub / "side.ngc").write_text("o<side> sub\nG1 X[#1] Y0\nG1 X[#1] Y20\no<side> endsub\nM2\n")
    f = write(tmp_path, "main.ngc", "G21 G90 G40\nG0 X0 Y0\nG1 F100 X5\no<side> call [30]\nG1 X0 Y0\nM2\n")
    ref = tc.run(f, TOOLS, search_path=[str(sub)])
    s = tc.iter_run(f, TOOLS, chunk=1, search_path=[str(sub)])
    chunks = list(s)
    assert_same(ref.path, chunks)
    assert s.files == ref.path.files == [f, str(sub / "side.ngc")]
    assert chunks[-1].files == s.files


def test_a_parsed_program_and_other_dialects(tmp_path):
    prog = tc.Program.parse(contour(5))
    ref = tc.run(prog, TOOLS)
    assert_same(ref.path, list(tc.iter_run(prog, TOOLS, chunk=4)))
    h = write(tmp_path, "p.h", "0 BEGIN PGM P MM\n1 TOOL DEF 1 L+0 R+2\n2 TOOL CALL 1 Z S1000\n"
              "3 L X-10 Y0 Z-1 R0 FMAX\n4 L X0 Y0 RL F100\n5 L X30\n6 CR X30 Y20 R+10 DR+\n"
              "7 L X0\n8 L Y-10 R0\n9 END PGM P MM\n")
    ref = tc.run(h)
    s = tc.iter_run(h, chunk=2)
    assert_same(ref.path, list(s))
    assert s.files == [h]


def test_percent_delimited_program_in_pieces(tmp_path):
    # Text after the closing '%' is not part of the program, even pieces later.
    text = "%\n" + contour(3).replace("M2\n", "") + "%\nthis is no G-code\n"
    f = write(tmp_path, "pct.ngc", text)
    ref = tc.run(f, TOOLS)
    assert_same(ref.path, list(tc.iter_run(f, TOOLS, chunk=7, piece_bytes=5)))
    g = write(tmp_path, "open.ngc", "%\n" + contour(3).replace("M2\n", ""))
    with pytest.raises(tc.ProgramError) as e:
        tc.run(g, TOOLS)
    with pytest.raises(tc.ProgramError) as s:
        list(tc.iter_run(g, TOOLS, piece_bytes=5))
    assert (s.value.code, s.value.line) == (e.value.code, e.value.line) == ("no_program_end", 26)


def test_errors_raise_with_runs_code_and_line_after_the_path_before_them(tmp_path):
    # A syntax error 200 lines in (later pieces), and a gouge: the same code and line as run().
    body = contour(40).splitlines()
    bad = "\n".join(body[:200] + ["G1 X1 Y2 Q"] + body[200:]) + "\n"
    f = write(tmp_path, "bad.ngc", bad)
    with pytest.raises(tc.Error) as e:
        tc.run(f, TOOLS)
    got = []
    with pytest.raises(tc.Error) as s:
        for c in tc.iter_run(f, TOOLS, chunk=50, piece_bytes=100):
            got.append(c)
    assert (type(s.value), s.value.code, s.value.line) == (type(e.value), e.value.code, e.value.line)
    assert e.value.line == 201
    lenient = tc.run(f, TOOLS, strict=False)
    stream = tc.iter_run(f, TOOLS, chunk=50, piece_bytes=100, strict=False)
    assert_same(lenient.path, list(stream))
    assert [(d.code, d.line) for d in stream.diagnostics] == [(d.code, d.line) for d in lenient.diagnostics]
    # Segments before the error came out (strict): the path up to the error's block.
    assert sum(len(c) for c in got) >= 50 * (len(lenient.path) // 50)


def test_line_limits_in_later_pieces(tmp_path):
    text = contour(10).splitlines()
    text.insert(30, "(" + "x" * 5000 + ")")
    f = write(tmp_path, "long.ngc", "\n".join(text) + "\n")
    with pytest.raises(tc.ParseError) as e:
        list(tc.iter_run(f, TOOLS, piece_bytes=100, max_line_length=1000))
    assert (e.value.code, e.value.line) == ("line_too_long", 31)
    with pytest.raises(tc.ParseError) as w:
        tc.run(f, TOOLS, max_line_length=1000)
    assert (w.value.code, w.value.line) == ("line_too_long", 31)
    # Whatever strict says, as when the file is read whole: the run stops with the error.
    with pytest.raises(tc.ParseError) as w:
        tc.run(f, TOOLS, max_line_length=1000, strict=False)
    assert (w.value.code, w.value.line) == ("line_too_long", 31)
    with pytest.raises(tc.ParseError) as w:
        list(tc.iter_run(f, TOOLS, piece_bytes=100, max_line_length=1000, strict=False))
    assert (w.value.code, w.value.line) == ("line_too_long", 31)
    # A program read whole (one that steers) stops the same way, before it runs.
    steer = write(tmp_path, "long_o.ngc", "\n".join(text[:3] + ["o1 if [1]", "o1 endif"] + text[3:]) + "\n")
    with pytest.raises(tc.ParseError) as w:
        tc.run(steer, TOOLS, max_line_length=1000, strict=False)
    assert (w.value.code, w.value.line) == ("line_too_long", 33)


def test_missing_file_and_bad_chunk_fail_at_once(tmp_path):
    with pytest.raises(tc.ParseError) as e:
        tc.iter_run(str(tmp_path / "none.ngc"), TOOLS)
    assert e.value.code == "file_not_found"
    with pytest.raises(ValueError):
        tc.iter_run(str(tmp_path / "none.ngc"), TOOLS, chunk=0)


def test_abandoned_stream_stops_its_run(tmp_path):
    # 60 000 blocks in chunks of 10: leaving after two chunks must not wait for the rest.
    f = write(tmp_path, "big.ngc", contour(10_000))
    t = time.perf_counter()
    with tc.iter_run(f, TOOLS, chunk=10) as s:
        for i, c in enumerate(s):
            assert len(c) == 10
            if i == 1:
                break
    s.close()  # twice is fine
    assert list(s) == []  # a closed stream yields nothing more
    it = tc.iter_run(f, TOOLS, chunk=10)
    next(it)
    del it  # dropped without close: the destructor stops the run
    assert time.perf_counter() - t < 60


def test_ctrl_c_while_a_chunk_is_made_interrupts_the_wait():
    # A loop of 4M moves in one chunk takes seconds; Ctrl-C after 0.2 s raises
    # KeyboardInterrupt from inside next(), before the chunk is taken: the run goes on and
    # the next call hands over the whole chunk. The press is _thread.interrupt_main(), what
    # the interpreter's own SIGINT handler does (the kernel's choice of the thread that takes a
    # real SIGINT is not what this tests).
    import _thread
    import signal
    import threading

    # Python's own Ctrl-C handler, whatever the test process was given (the sanitizer suite's
    # Python was seen with SIGINT ignored by the time this test ran).
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)

    text = ("G21 G90 G0 X0 Y0\n#1=0\no1 while [#1 LT 2000000]\n  G1 X10 Y#1 F100\n  G1 X0\n"
            "  #1=[#1+1]\no1 endwhile\nM2\n")
    s = tc.iter_run(tc.Program.parse(text), chunk=5_000_000)
    stop = threading.Event()
    presses = []

    def ctrl_c():  # Ctrl-C every 0.2 s until the wait is interrupted (as a user presses it again)
        while not stop.wait(0.2):
            presses.append(time.perf_counter())
            _thread.interrupt_main()

    presser = threading.Thread(target=ctrl_c)
    t0 = time.perf_counter()
    presser.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            next(s)
            pytest.fail(f"no KeyboardInterrupt: the chunk came after {time.perf_counter() - t0:.3f} s, "
                        f"{len(presses)} presses, SIGINT handler {signal.getsignal(signal.SIGINT)!r}, "
                        f"main thread {threading.current_thread() is threading.main_thread()}")
    finally:
        stop.set()
        while presser.is_alive():  # a press that crossed the stop: absorbed here
            try:
                presser.join()
            except KeyboardInterrupt:
                pass
        try:
            time.sleep(0.3)
        except KeyboardInterrupt:
            pass
        signal.signal(signal.SIGINT, previous)
    try:
        chunk = next(s)
        assert len(chunk) == 1 + 2 * 2_000_000
        with pytest.raises(StopIteration):
            next(s)
    finally:
        s.close()
