"""Progress reports of long runs: the callback of tc.run and the command line's bar."""
import io

import pytest

import toolcomp as tc
from toolcomp import cli

PROG = "G21\n" + "G1 X1 F100\nX0\n" * 100000 + "M2\n"  # 200 002 blocks


def test_progress_is_called_every_n_blocks_and_can_stop_the_run():
    prog = tc.Program.parse(PROG)
    seen = []
    res = tc.run(prog, progress=seen.append, progress_every=50000)
    assert seen == [50000, 100000, 150000, 200000] and len(res.path) == 200000

    class Stop(Exception):
        pass

    def stop(n):
        raise Stop(n)

    with pytest.raises(Stop, match="3000"):
        tc.run(prog, progress=stop, progress_every=3000)


class Tty(io.StringIO):
    def isatty(self):
        return True


class Big:
    def __len__(self):
        return 2_000_000


def test_the_command_line_bar_only_for_a_million_blocks_on_a_terminal():
    pytest.importorskip("tqdm")
    assert cli._progress_bar(Big(), io.StringIO()) is None      # not a terminal: silent
    assert cli._progress_bar(tc.Program.parse(PROG), Tty()) is None  # 200k blocks: no bar
    stream = Tty()
    bar = cli._progress_bar(Big(), stream)
    assert bar is not None and bar.total == 2_000_000
    bar.update(1_000_000)
    bar.close()
    assert "block" in stream.getvalue()


def test_heidenhain_progress_counts_executed_blocks_with_loops():
    # 2 moves in a section repeated 10 000 times: over 20 000 blocks executed.
    prog = tc.Program.parse("0 BEGIN PGM P MM\n1 TOOL DEF 1 L+0 R+0\n2 TOOL CALL 1 Z\n3 L X+0 Y+0 F100\n"
                            "4 LBL 1\n5 L X+1\n6 L X+0\n7 CALL LBL 1 REP 9999\n8 END PGM P MM\n",
                            dialect="heidenhain")
    seen = []
    res = tc.run(prog, progress=seen.append, progress_every=5000)
    assert len(res.path) >= 20000
    assert seen[:4] == [5000, 10000, 15000, 20000]


def test_a_stream_tells_the_blocks_read_and_the_command_line_bar_takes_a_count(tmp_path):
    p = tmp_path / "p.ngc"
    p.write_text(PROG)
    seen = []
    with tc.iter_run(p, chunk=30_000) as stream:
        for chunk in stream:
            seen.append(stream.blocks_read)
        assert stream.blocks_read == stream.blocks == 200_002
        assert stream.programmed_segments == 200_000
    # read ahead of the chunks handed out, every 65 536 blocks: never backwards
    assert seen == sorted(seen) and seen[-1] <= 200_002 and len(seen) == 7
    pytest.importorskip("tqdm")
    assert cli._progress_bar(200_002, Tty()) is None
    bar = cli._progress_bar(2_000_000, Tty())
    assert bar is not None and bar.total == 2_000_000
    bar.close()
