"""Bad arguments to the Python helpers are refused, never passed as everything-passes."""
import math
import subprocess
import sys

import pytest

import toolcomp as tc
from toolcomp.testing import assert_no_gouge, assert_paths_close, assert_within

ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]
TEXT = "G21 G17 G90\nG0 X-10 Y0\nG41.1 D2\nG1 X0 Y0 F100\nX10\nY10\nG40 G1 X20\nM2\n"


@pytest.mark.parametrize("call", [
    lambda p, r: assert_within(p, ((math.nan,) * 3, (math.nan,) * 3)),
    lambda p, r: assert_within(p, ((0, 0, 0), (1, 1, 1)), tolerance=math.nan),
    lambda p, r: assert_paths_close(p, p, tol=math.nan),
    lambda p, r: assert_paths_close(p, p, tol=-1),
    lambda p, r: assert_no_gouge(r, [(0, 0), (10, 0)], radius=math.nan),
    lambda p, r: assert_no_gouge(r, [(0, 0), (10, 0)], radius=-5),
    lambda p, r: assert_no_gouge(r, [(0, 0), (10, 0)], radius=1, tol=math.nan),
])
def test_testing_helpers_refuse_nan_and_negative_tolerances(call):
    res = tc.run(tc.Program.parse(TEXT))
    with pytest.raises(ValueError):
        call(res.path, res)


def test_run_many_wants_a_list():
    with pytest.raises(TypeError, match="list"):
        tc.run_many("part.ngc")


def test_tools_convert_reports_a_table_it_cannot_write(tmp_path):
    src = ROOT / "tests" / "programs" / "tables" / "tools_edges.csv"
    for out in ("out.tbl", "out.xyz", "nodir/x.csv"):
        r = subprocess.run([sys.executable, "-m", "toolcomp", "tools", "convert", str(src), str(tmp_path / out)],
                           capture_output=True, text=True)
        assert r.returncode == 1 and "cannot write" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.parametrize("call, error", [
    (lambda p: tc.iter_run(p, chunk=1.5), TypeError),
    (lambda p: tc.iter_run(p, chunk=True), TypeError),
    (lambda p: tc.run(p, max_segments=-1), ValueError),
    (lambda p: tc.run(p, progress_every=0), ValueError),
    (lambda p: tc.iter_run(p, piece_bytes=-1), ValueError),
])
def test_counts_and_sizes_are_whole_numbers(call, error):
    with pytest.raises(error, match="must be"):
        call(tc.Program.parse("G21 G0 X1\nM2\n"))
