"""Cutter radius compensation (G40/G41/G42/G41.1/G42.1) against LinuxCNC's interpreter, to 1e-6 mm.

Oracle: LinuxCNC's ``gcode`` Python module (Debian's /usr/bin/python3, see gcode_oracle.py), which
runs the same rs274ngc interpreter as rs274 but hands over full doubles, the source line of every
canon move and the exact line of an error. Programs:

* ``tests/programs/comp/*.ngc`` (hand-written: the worked vectors V1..V5 of the comp research note,
  the inch experiments, lathe orientations L1..L9 / table Q, error cases), table
  ``tests/programs/comp/tools.tbl`` (or ``<stem>.tbl``);
* ``TOOLCOMP_COMP_N`` (default 200) programs from generate_comp.py, seeds
  ``TOOLCOMP_COMP_SEED`` (default 100000) onward, table ``tests/programs/comp/tools.tbl``.

What is compared, per program:

(a) accept/reject: LinuxCNC's error (message from ``gcode.strerror``, exact 1-based line) against
    the tc.Error toolcomp raises with strict=True (``.message`` and ``.line``);
(b) accepted by both: every segment of ``res.path`` (compensated; one segment per LinuxCNC canon
    motion, corner arcs included) against LinuxCNC's moves: kind, line, end, in-plane arc centre,
    turns (toolcomp's extra full turns = |rotation| - 1), abc, tool_offset, feed; all to 1e-6
    (mm, degrees, mm/min). Also toolcomp's own continuity: start[i] == end[i-1];
(c) rejected by both: ``tc.run(..., strict=False)`` must report the same error in
    ``res.diagnostics`` and its path must begin with exactly the moves LinuxCNC emitted before the
    error. LinuxCNC never emits what is still in its comp queue when an error stops it (the pending
    compensated move and anything queued behind it); toolcomp's strict=False path may carry those
    queued moves too. Such extra segments are allowed only if they come from blocks *before* the
    error line (they are the documented queue difference, not compared geometrically).

Feed: LinuxCNC's inverse-time (G93) rates are units/min (length x F); the batch script converts
them to mm/min in G20 programs too (gcode_oracle.py reports them in inch/min there).

Speed: the gcode module is started once per batch of programs (the tool mmap is created once per
process; ``gcode.parse`` re-initialises the interpreter for every program, and each program gets a
fresh parameter file; test_batching_is_transparent checks batched == one process per program).
Batches run in parallel (one per CPU), each with its own HOME.

Skipped when /usr/bin/python3 cannot import LinuxCNC's gcode module, or toolcomp cannot be imported.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import gcode_oracle
import generate_comp

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
COMP = ROOT / "tests" / "programs" / "comp"
TABLE = COMP / "tools.tbl"
N_GENERATED = int(os.environ.get("TOOLCOMP_COMP_N", "200"))
SEED_BASE = int(os.environ.get("TOOLCOMP_COMP_SEED", "100000"))
TOL = 1e-6
COLUMNS = ("kind", "line", "end", "center", "turns", "abc", "tool_offset", "feed", "plane")
PLANE_INDEX = {17: 0, 18: 1, 19: 2}

pytestmark = pytest.mark.skipif(not gcode_oracle.available(),
                                reason="/usr/bin/python3 cannot import LinuxCNC's gcode module")

# ---------------------------------------------------------------------------------------------
# the oracle, batched: one /usr/bin/python3 process parses many programs

_BATCH = r"""
import json, os, sys, tempfile
sys.path.insert(0, sys.argv[1])
import gcode_oracle as go
jobs = json.load(open(sys.argv[2]))
home = tempfile.mkdtemp(prefix="gcode_comp_")
os.environ["HOME"] = home                       # private $HOME/.tool.mmap
import ctypes
lookup, find = go._tooldata(None)                # the mmap: once per process
lib = ctypes.CDLL("libtooldata.so.0", mode=ctypes.RTLD_GLOBAL)
load = lib._Z13tooldata_loadPKcPPc
load.argtypes = [ctypes.c_char_p, ctypes.c_void_p]
import gcode


class Collector(go.Collector):
    # In G93 the interpreter emits SET_FEED_RATE(length * F) in program units/min, which the module
    # divides by 25.4 in G21 like any feed: the value is always inch/min, in G20 programs too
    # (gcode_oracle.Collector leaves G20 inverse-time rates in inch/min).
    def _feed_mm(self):
        return self.feed * go.MM_PER_INCH


loaded = None
out = []
for program, table in jobs:
    if table != loaded:                          # tooldata_load replaces the whole table
        if load(os.fsencode(table), None) != 0:
            raise RuntimeError("tooldata_load(%s) failed" % table)
        loaded = table
    go.reset_interpreter(gcode, lookup, find, home)  # as in a fresh process
    var = os.path.join(home, "oracle.var")
    open(var, "w").close()                       # fresh parameters for every program
    source = open(program, errors="replace").read().splitlines()
    canon = Collector(lookup, find, source, var)
    result, near = gcode.parse(os.path.abspath(program), canon, "G21", "F0")
    error = None
    if result > gcode.MIN_ERROR:
        error = {"message": gcode.strerror(result), "line": int(canon.line), "code": int(result)}
    d = dict(canon.cols)
    d["error"] = error
    out.append(d)
json.dump(out, open(sys.argv[3], "w"))
"""


def _columns(raw: dict) -> dict:
    n = len(raw["kind"])
    vec = lambda k: np.array(raw[k], dtype=float).reshape(n, 3)  # noqa: E731
    return {
        "kind": np.array(raw["kind"], dtype=np.int64),
        "line": np.array(raw["line"], dtype=np.int64),
        "end": vec("end"), "center": vec("center"),
        "turns": np.array(raw["turns"], dtype=np.int64),
        "abc": vec("abc"), "tool_offset": vec("tool_offset"),
        "feed": np.array(raw["feed"], dtype=float),
        "plane": np.array(raw["plane"], dtype=np.int64),
        "error": raw["error"],
    }


def _run_batch(jobs, timeout=600.0):
    with tempfile.TemporaryDirectory(prefix="gcode_comp_batch_") as tmp:
        jf, of = Path(tmp) / "jobs.json", Path(tmp) / "out.json"
        jf.write_text(json.dumps([[str(Path(p).resolve()), str(Path(t).resolve())] for p, t in jobs]))
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
        env["HOME"] = tmp
        proc = subprocess.run([gcode_oracle.SYSTEM_PYTHON, "-c", _BATCH, str(HERE), str(jf), str(of)],
                              capture_output=True, text=True, timeout=timeout, env=env,
                              stdin=subprocess.DEVNULL, cwd=tmp)
        if proc.returncode != 0 or not of.exists():
            raise gcode_oracle.GcodeModuleFailure("gcode batch failed (rc=%d):\n%s"
                                                  % (proc.returncode, proc.stderr[-3000:]))
        return [_columns(r) for r in json.loads(of.read_text())]


def run_oracle(jobs, workers=None):
    """LinuxCNC results for [(program, table), ...], in order, in parallel batches."""
    jobs = list(jobs)
    if not jobs:
        return []
    workers = workers or max(1, min(len(jobs), os.cpu_count() or 2))
    chunks = [jobs[i::workers] for i in range(workers)]
    with ThreadPoolExecutor(workers) as pool:
        results = list(pool.map(_run_batch, chunks))
    out = [None] * len(jobs)
    for w, res in enumerate(results):
        for j, r in enumerate(res):
            out[w + j * workers] = r
    return out


# ---------------------------------------------------------------------------------------------
# toolcomp side

def _tc():
    return pytest.importorskip("toolcomp")


def toolcomp_run(program: Path, table: Path, strict=True):
    """(columns of res.path or None, error or None, result or None)."""
    tc = _tc()
    tools = tc.ToolTable.read(str(table))
    try:
        # rs274 starts at machine zero
        res = tc.run(tc.Program.read(str(program), strict=False), tools=tools, strict=strict, start="machine_zero")
    except tc.Error as e:
        return None, e, None
    return path_columns(res.path), None, res


def path_columns(path) -> dict:
    cols = {name: np.asarray(getattr(path, name)) for name in COLUMNS + ("start",)}
    for name in ("kind", "line", "turns", "plane"):
        cols[name] = cols[name].astype(np.int64)
    return cols


def _vec(v):
    return "(%s)" % ", ".join("%.9f" % x for x in v)


def differences(mod: dict, t: dict, limit: int = 12, upto: int | None = None) -> list:
    """Differences between LinuxCNC's moves and toolcomp's segments (first ``upto`` toolcomp rows)."""
    out = []
    n_m, n_t = len(mod["kind"]), len(t["kind"]) if upto is None else upto
    if n_m != n_t:
        out.append("segment count: LinuxCNC %d, toolcomp %d" % (n_m, n_t))
    for i in range(min(n_m, n_t)):
        def diff(what, mv, tv):
            out.append("segment #%d (LinuxCNC line %d): %s: LinuxCNC %s, toolcomp %s"
                       % (i, mod["line"][i], what, mv, tv))
        kind = int(mod["kind"][i])
        if int(t["kind"][i]) != kind:
            diff("kind", kind, int(t["kind"][i]))
            if len(out) >= limit:
                break
            continue
        if int(t["line"][i]) != int(mod["line"][i]):
            diff("line", int(mod["line"][i]), int(t["line"][i]))
        if not np.all(np.abs(t["end"][i] - mod["end"][i]) <= TOL):
            diff("end", _vec(mod["end"][i]), _vec(t["end"][i]))
        if kind >= 2:
            inplane = ~np.isnan(mod["center"][i])
            c_t = t["center"][i][inplane]
            if np.any(np.isnan(c_t)) or not np.all(np.abs(c_t - mod["center"][i][inplane]) <= TOL):
                diff("centre (in-plane)", _vec(mod["center"][i]), _vec(t["center"][i]))
            want = abs(int(mod["turns"][i])) - 1
            if int(t["turns"][i]) != want:
                diff("turns (extra full turns)", "%d (rotation %d)" % (want, mod["turns"][i]),
                     int(t["turns"][i]))
            if int(t["plane"][i]) != PLANE_INDEX[int(mod["plane"][i])]:
                diff("plane", "G%d" % mod["plane"][i], int(t["plane"][i]))
        elif not np.all(np.isnan(t["center"][i])):
            diff("centre of a line/rapid", "NaN", _vec(t["center"][i]))
        if not np.all(np.abs(t["abc"][i] - mod["abc"][i]) <= TOL):
            diff("abc", _vec(mod["abc"][i]), _vec(t["abc"][i]))
        if not np.all(np.abs(t["tool_offset"][i] - mod["tool_offset"][i]) <= TOL):
            diff("tool_offset", _vec(mod["tool_offset"][i]), _vec(t["tool_offset"][i]))
        fm, ft = float(mod["feed"][i]), float(t["feed"][i])
        if np.isnan(fm) != np.isnan(ft) or (not np.isnan(fm) and abs(fm - ft) > TOL):
            diff("feed", fm, ft)
        if len(out) >= limit:
            out.append("... (stopped after %d differences)" % limit)
            break
    return out


def continuity(t: dict, upto: int | None = None) -> list:
    """toolcomp's own consistency: every segment starts where the previous one ended."""
    n = len(t["kind"]) if upto is None else upto
    out = []
    for i in range(1, n):
        if not np.all(np.abs(t["start"][i] - t["end"][i - 1]) <= 1e-9):
            out.append("toolcomp segment #%d starts at %s, segment #%d ended at %s"
                       % (i, _vec(t["start"][i]), i - 1, _vec(t["end"][i - 1])))
            break
    return out


def check(program: Path, table: Path, mod: dict) -> list:
    """Every disagreement between LinuxCNC (``mod``) and toolcomp on ``program`` (empty: agree)."""
    tc = _tc()
    cols, err, _ = toolcomp_run(program, table)
    merr = mod["error"]
    if merr is None and err is None:
        return differences(mod, cols) + continuity(cols)
    if merr is None:
        return ["LinuxCNC accepts the program; toolcomp raises %s on line %d: %s"
                % (type(err).__name__, err.line, err.message)] + _before(mod, program, table, None)
    if err is None:
        return ["LinuxCNC rejects line %d: %r; toolcomp accepts the program"
                % (merr["line"], merr["message"])] + differences(mod, cols)
    out = []
    if (err.message, err.line) != (merr["message"], merr["line"]):
        out.append("error: LinuxCNC line %d %r; toolcomp %s line %d %r"
                   % (merr["line"], merr["message"], type(err).__name__, err.line, err.message))
    if not isinstance(err, (tc.CompensationError, tc.ProgramError)):
        out.append("toolcomp raised %s (expected CompensationError or ProgramError)" % type(err).__name__)
    return out + _before(mod, program, table, merr)


def _before(mod, program, table, merr) -> list:
    """(c): strict=False path vs the moves LinuxCNC emitted before its error."""
    cols, err, res = toolcomp_run(program, table, strict=False)
    if err is not None:
        return ["strict=False still raises %s: %s" % (type(err).__name__, err.message)]
    if merr is None:
        return []
    errs = [d for d in res.diagnostics if d.severity == "error"]
    out = []
    if not errs or (errs[0].message, errs[0].line) != (merr["message"], merr["line"]):
        out.append("strict=False diagnostics %s, LinuxCNC %r line %d"
                   % ([(d.message, d.line) for d in errs], merr["message"], merr["line"]))
    n_m, n_t = len(mod["kind"]), len(cols["kind"])
    if n_t < n_m:
        out.append("strict=False path has %d segments, LinuxCNC emitted %d before the error" % (n_t, n_m))
        return out + differences(mod, cols)
    extra = cols["line"][n_m:]
    if np.any(extra >= merr["line"]):
        out.append("strict=False path has segments from line >= the error line %d beyond LinuxCNC's "
                   "%d moves: lines %s" % (merr["line"], n_m, extra.tolist()))
    return out + differences(mod, cols, upto=n_m) + continuity(cols)


def _table_for(prog: Path) -> Path:
    own = prog.with_suffix(".tbl")
    return own if own.exists() else TABLE


# ---------------------------------------------------------------------------------------------
# the programs

HAND = sorted(COMP.glob("*.ngc"))


@pytest.fixture(scope="session")
def generated(tmp_path_factory):
    """seed -> (program path, LinuxCNC result), for the whole session (one batched oracle run)."""
    d = tmp_path_factory.mktemp("comp_generated")
    progs = []
    for seed in range(SEED_BASE, SEED_BASE + N_GENERATED):
        p = d / ("comp_%d.ngc" % seed)
        p.write_text(generate_comp.generate(seed))
        progs.append(p)
    hand = [(p, _table_for(p)) for p in HAND]
    results = run_oracle([(p, TABLE) for p in progs] + hand)
    out = {seed: (p, r) for seed, p, r in zip(range(SEED_BASE, SEED_BASE + N_GENERATED), progs, results)}
    out.update({p.stem: (p, r) for (p, _), r in zip(hand, results[len(progs):])})
    return out


@pytest.mark.parametrize("prog", HAND, ids=lambda p: p.stem)
def test_hand_written_program(prog, generated):
    _, mod = generated[prog.stem]
    diffs = check(prog, _table_for(prog), mod)
    assert not diffs, "%s: toolcomp differs from LinuxCNC:\n  %s" % (prog.name, "\n  ".join(diffs))


@pytest.mark.parametrize("seed", range(SEED_BASE, SEED_BASE + N_GENERATED))
def test_generated_program(seed, generated):
    prog, mod = generated[seed]
    diffs = check(prog, TABLE, mod)
    assert not diffs, "%s (python tests/oracle/generate_comp.py %d):\n  %s" % (
        prog.name, seed, "\n  ".join(diffs))


def test_hand_written_expectations(generated):
    """The hand-written programs that state ``; error: <message> @ <line>`` or ``; ok`` in their first
    line make LinuxCNC do exactly that (checks the programs and the oracle, not toolcomp)."""
    for prog in HAND:
        first = prog.read_text().splitlines()[0]
        _, mod = generated[prog.stem]
        if first.startswith("; error: "):
            msg, _, line = first[len("; error: "):].rpartition(" @ ")
            assert mod["error"] is not None, "%s: LinuxCNC accepted it" % prog.name
            assert (mod["error"]["message"], mod["error"]["line"]) == (msg, int(line)), prog.name
        elif first.startswith("; ok"):
            assert mod["error"] is None, "%s: %s" % (prog.name, mod["error"])


def test_generator_is_deterministic():
    assert generate_comp.generate(SEED_BASE) == generate_comp.generate(SEED_BASE)
    assert generate_comp.generate(SEED_BASE) != generate_comp.generate(SEED_BASE + 1)


def test_batching_is_transparent(generated):
    """One process per program (gcode_oracle.run_gcode_module) == the batched results."""
    picks = [s for s in range(SEED_BASE, SEED_BASE + N_GENERATED)][:6] + [p.stem for p in HAND[:3]]
    for key in picks:
        prog, batched = generated[key]
        table = TABLE if isinstance(key, int) else _table_for(prog)
        single = gcode_oracle.run_gcode_module(prog, table)
        assert (single["error"] or {}).get("message") == (batched["error"] or {}).get("message"), key
        assert (single["error"] or {}).get("line") == (batched["error"] or {}).get("line"), key
        for k in ("kind", "line", "turns", "plane"):
            assert np.array_equal(single[k], batched[k]), (key, k)
        for k in ("end", "center", "abc", "tool_offset", "feed"):
            assert np.array_equal(np.nan_to_num(single[k], nan=1e300),
                                  np.nan_to_num(batched[k], nan=1e300)), (key, k)
