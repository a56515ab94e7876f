"""Batches: run_many on a thread pool, and the same work on a local Dask cluster."""
import os

import numpy as np
import pytest

import toolcomp as tc

TOOLS = "T1 P1 D10 Z25 ;r5\n"


def square(side):
    # G41 counter-clockwise round a square of the given side from (0, 0), r = 5: the tool runs
    # inside, its first inside corner at (side - 5, 5).
    return (f"G21 G17 G90\nT1 M6\nG43\nG0 X-10 Y-10 Z5\nG1 Z-1 F100\nG41 X0 Y0\nX{side}\nY{side}\n"
            f"X0\nY0\nG40 X-10 Y-10\nM2\n")


@pytest.fixture
def programs(tmp_path):
    paths = []
    for i, side in enumerate((20, 30, 40, 50, 60, 70, 80, 90)):
        p = tmp_path / f"p{i}.ngc"
        p.write_text(square(side))
        paths.append(p)
    (tmp_path / "t.tbl").write_text(TOOLS)
    return paths, tmp_path / "t.tbl"


def test_run_many_equals_run_in_order(programs):
    paths, tools = programs
    many = tc.run_many(paths, tools, workers=2)
    table = tc.ToolTable.read(tools)
    for p, res in zip(paths, many):
        one = tc.run(p, table)
        np.testing.assert_array_equal(res.path.end, one.path.end)
    np.testing.assert_allclose(many[0].path.end[4][:2], [15, 5], atol=1e-12)
    np.testing.assert_allclose(many[7].path.end[4][:2], [85, 5], atol=1e-12)


def test_run_many_errors_raise_or_come_back_in_place(programs, tmp_path):
    paths, tools = programs
    bad = tmp_path / "bad.ngc"
    bad.write_text("G21\nG1 X10 F100 &\nM2\n")
    with pytest.raises(tc.ParseError):
        tc.run_many([paths[0], bad], tools)
    out = tc.run_many([paths[0], bad, paths[1]], tools, return_exceptions=True)
    assert isinstance(out[1], tc.ParseError) and out[1].line == 2
    assert isinstance(out[0], tc.Result) and isinstance(out[2], tc.Result)
    with pytest.raises(ValueError):
        tc.run_many(paths, tools, workers=0)


def feed_length(path_and_tools):
    path, tools = path_and_tools
    res = tc.run(path, tools)
    return float(res.path.length(False))


def test_the_same_work_on_a_dask_bag(programs):
    distributed = pytest.importorskip("distributed")
    db = pytest.importorskip("dask.bag")
    paths, tools = programs
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=2, dashboard_address=None):
        lengths = db.from_sequence([(str(p), str(tools)) for p in paths], npartitions=4).map(feed_length).compute()
    expected = [feed_length((str(p), str(tools))) for p in paths]
    assert lengths == expected
    # each side 10 longer: three of the inside sides are 10 longer, and the last side up to
    # the exit too: 40 more feed per program
    np.testing.assert_allclose(np.diff(lengths), 40, atol=1e-9)


def test_run_many_runs_without_threads_of_their_own_when_the_pool_fills_the_cores(programs, monkeypatch):
    # Each run's helper threads (overcut watch, read-ahead) would only contend with the other
    # workers for the cores: run_many passes threads=False then, and leaves them otherwise.
    paths, tools = programs
    seen = []

    def fake_run(program, tools=None, **kwargs):
        seen.append(kwargs.get("threads", True))
        return program

    monkeypatch.setattr(tc, "run", fake_run)
    monkeypatch.setattr("toolcomp.batch.cores", lambda: 2)
    tc.run_many(paths, tools, workers=2)
    assert seen == [False] * 8
    seen.clear()
    tc.run_many(paths, tools, workers=1)  # one worker: the other core is free for its helpers
    assert seen == [True] * 8
    seen.clear()
    tc.run_many(paths[:1], tools, workers=2)
    assert seen == [True]
    seen.clear()
    tc.run_many(paths, tools, workers=2, threads=True)  # asked for
    assert seen == [True] * 8


def test_cores_are_those_the_process_may_use(monkeypatch):
    # A process pinned to one core of a larger machine (taskset, a container's cpuset) has
    # one core for its workers.
    from toolcomp.batch import cores
    monkeypatch.setattr("os.cpu_count", lambda: 8)
    monkeypatch.setattr("os.sched_getaffinity", lambda pid: {3}, raising=False)
    assert cores() == 1
    monkeypatch.delattr("os.sched_getaffinity", raising=False)
    assert cores() == 8
