"""A ToolTable shared between threads: a run sees one consistent table (the one it was given
when it started), whatever other threads do to it meanwhile, and never crashes."""
import threading

import numpy as np
import pytest

import toolcomp as tc

# A G41 pocket side with tool 1 (radius 5): the compensated X of the left wall is 5 mm in.
PROGRAM = "\n".join(
    ["G21 G17 G90 G40", "T1 M6 G43 H1", "G0 X-20 Y-20 Z5", "G1 Z-1 F100", "G41 D1 G1 X0 Y0"]
    + [f"G1 X0 Y{10 * (k + 1)}" for k in range(200)]
    + ["G1 X50", "G40 G1 X70 Y250", "M2"]
)


def _table():
    table = tc.ToolTable()
    table.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, 40.0])]))
    for n in range(100, 400):
        table.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=1.0)]))
    return table


def _hammer(table, stop):
    """Adds and removes tools the program never uses, and rewrites tool 1 with its own values."""
    k = 0
    while not stop.is_set():
        n = 1000 + k % 500
        table.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=float(k % 7))]))
        if k % 3 == 0:
            table.remove(1000 + (k * 7) % 500)
        if k % 50 == 0:
            table.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, 40.0])]))
        k += 1


def _wall_x(res):
    """X of the compensated segments along the left wall (lines of the Y moves)."""
    path = res.path
    on_wall = (path.line >= 6) & (path.line <= 205)
    return path.end[on_wall, 0]


@pytest.mark.parametrize("how", ["run", "run_many"])
def test_runs_while_other_threads_change_the_table(how):
    program = tc.Program.parse(PROGRAM, dialect="linuxcnc")
    table = _table()
    stop = threading.Event()
    hammers = [threading.Thread(target=_hammer, args=(table, stop)) for _ in range(2)]
    for h in hammers:
        h.start()
    try:
        results = []
        if how == "run":
            for _ in range(60):
                results.append(tc.run(program, tools=table))
        else:
            for _ in range(6):
                results.extend(tc.run_many([program] * 10, tools=table, workers=4))
    finally:
        stop.set()
        for h in hammers:
            h.join()
    for res in results:
        assert res.ok
        # G41 with radius 5 on a wall at X0 walked in +Y: the tool centre at X = -5.
        np.testing.assert_allclose(_wall_x(res), -5.0, atol=1e-9)
        assert set(np.unique(res.path.tool)) <= {0, 1}


def test_write_and_dumps_while_other_threads_change_the_table(tmp_path):
    table = _table()
    stop = threading.Event()
    hammer = threading.Thread(target=_hammer, args=(table, stop))
    hammer.start()
    try:
        for k in range(40):
            text = table.dumps("csv")
            assert text.count("\n") >= 300  # the 300 tools that never change, and the header
            table.write(tmp_path / "tools.tbl")
    finally:
        stop.set()
        hammer.join()
    back = tc.ToolTable.read(tmp_path / "tools.tbl")
    assert back[1].edges[0].radius == 5.0
    assert all(back.get(n) is not None for n in range(100, 400))
    # The table knows the file it wrote last: writing it again is not a change made by others.
    table.write(tmp_path / "tools.tbl")


def test_a_run_uses_the_table_as_it_was_when_it_started():
    program = tc.Program.parse(PROGRAM, dialect="linuxcnc")
    table = _table()
    seen = []

    def progress(n):
        # Runs on the run's thread with the GIL: the caller's table changes under the run.
        table.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=1.0, length=[0.0, 0.0, 40.0])]))
        seen.append(n)

    res = tc.run(program, tools=table, progress=progress, progress_every=1)
    assert seen
    np.testing.assert_allclose(_wall_x(res), -5.0, atol=1e-9)
    assert table[1].edges[0].radius == 1.0
