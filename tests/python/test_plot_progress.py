"""The command line's progress for ``run --plot``: the run's blocks, then the drawing's steps,
on stderr; only on a terminal (for long programs) or when asked with --progress."""

import io
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from toolcomp import cli

ROOT = Path(__file__).resolve().parents[2]
SQUARE = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG3 X0 Y10 I-5 J0\nG1 Y0\nG0 Z5\nM2\n"

pytest.importorskip("matplotlib")


def toolcomp(*args, without_tqdm=False):
    env = dict(os.environ, MPLBACKEND="Agg")
    code = "import sys\n"
    if without_tqdm:
        code += "sys.modules['tqdm'] = None  # as if it were not installed\n"
    code += "from toolcomp.cli import main\nsys.exit(main(sys.argv[1:]))\n"
    return subprocess.run([sys.executable, "-c", code, *map(str, args)], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)


@pytest.fixture
def square(tmp_path):
    p = tmp_path / "square.ngc"
    p.write_text(SQUARE)
    return p


def test_no_progress_unless_asked_when_stderr_is_no_terminal(square, tmp_path):
    r = toolcomp("run", square, "--plot", tmp_path / "a.png")
    assert r.returncode == 0 and r.stderr == ""
    assert (tmp_path / "a.png").read_bytes()[:4] == b"\x89PNG"
    r = toolcomp("run", square, "--plot", tmp_path / "b.png", "--no-progress")
    assert r.returncode == 0 and r.stderr == ""


def test_progress_when_asked_shows_the_run_then_the_plot(square, tmp_path):
    pytest.importorskip("tqdm")
    quiet = toolcomp("run", square, "--plot", tmp_path / "a.png")
    r = toolcomp("run", square, "--plot", tmp_path / "b.png", "--progress")
    assert r.returncode == 0
    assert r.stdout == quiet.stdout  # the summary on stdout is the same
    run, plot = r.stderr.find("run:"), r.stderr.find("plot:")
    assert 0 <= run < plot
    assert "block" in r.stderr and "step" in r.stderr
    assert (tmp_path / "b.png").read_bytes()[:4] == b"\x89PNG"


def test_progress_without_tqdm_is_plain_lines(square, tmp_path):
    r = toolcomp("run", square, "--plot", tmp_path / "a.png", "--progress", without_tqdm=True)
    assert r.returncode == 0
    lines = r.stderr.splitlines()
    # the 9 lines of SQUARE are 9 blocks; the run is reported at its start and its end
    assert lines[0] == "toolcomp: run: 0 of 9 blocks (0%)"
    assert lines[1] == "toolcomp: run: 9 of 9 blocks (100%)"
    steps = [re.fullmatch(r"toolcomp: plot: (.+) \((\d+) of (\d+) steps\)", line) for line in lines[2:]]
    assert all(steps), lines
    done = [int(m.group(2)) for m in steps]
    total = int(steps[0].group(3))
    assert done == sorted(done) and done[0] == 0 and done[-1] == total
    names = [m.group(1) for m in steps]
    assert names[0] == "programmed path" and "writing a.png" in names and names[-1] == "done"


def test_no_progress_when_there_is_nothing_to_run_or_plot(square, tmp_path):
    # a tool table that cannot be read: no run, no path, no plot
    bad = tmp_path / "bad.tbl"
    bad.write_text("T1 P1 Zfoo D6\n")
    r = toolcomp("run", square, "--tools", bad, "--plot", tmp_path / "a.png", "--progress", without_tqdm=True)
    assert r.returncode == 1
    assert r.stderr.splitlines() == [f"toolcomp: no path to plot for {square}"]
    assert not (tmp_path / "a.png").exists()


class Tty(io.StringIO):
    def isatty(self):
        return True


def test_on_a_terminal_progress_for_a_million_segments_or_more():
    assert cli._plot_progress(2_000_000, Tty()) is not None
    assert cli._plot_progress(999_999, Tty()) is None
    assert cli._plot_progress(2_000_000, io.StringIO()) is None  # not a terminal
    assert cli._plot_progress(10, io.StringIO(), force=True) is not None
    assert cli._plot_progress(2_000_000, Tty(), force=False) is None
    assert cli._progress_bar(10, io.StringIO(), force=True) is not None
    assert cli._progress_bar(2_000_000, Tty(), force=False) is None
