"""Parameters, expressions, O-word control flow and subroutines (LinuxCNC dialect) against
LinuxCNC's interpreter, with cutter compensation switched on and off inside and around them.

    .venv/bin/python -m pytest -q tests/oracle/test_oracle_macros.py
    TOOLCOMP_MACRO_N=500 TOOLCOMP_MACRO_SEED=0 .venv/bin/python -m pytest -q tests/oracle/test_oracle_macros.py
    python tests/oracle/generate_macros.py SEED [COUNT] [OUTDIR]   # look at generated programs

Oracle: LinuxCNC's ``gcode`` Python module (Debian's /usr/bin/python3, see gcode_oracle.py), the
same rs274ngc interpreter as rs274, batched and run in parallel like test_oracle_comp.py, whose
comparison rules are reused unchanged (``differences``, ``continuity``: kind, line, end, in-plane
centre, turns, abc, tool offset, feed, plane, all to 1e-6). Programs:

* ``tests/programs/macros/*.ngc``: hand-written, one construct each; first line ``; ok`` or
  ``; error: <message> @ <line>``. Subroutine files in ``tests/programs/macros/subs`` (LinuxCNC's
  ``[RS274NGC]SUBROUTINE_PATH``, toolcomp's ``search_path``). Table ``<stem>.tbl`` if it exists,
  else ``tests/programs/comp/tools.tbl``;
* ``TOOLCOMP_MACRO_N`` (default 100) programs of generate_macros.py, seeds ``TOOLCOMP_MACRO_SEED``
  (default 300000) onward, table tests/programs/comp/tools.tbl.

Per program: (a) accept/reject: LinuxCNC's message and line against ``tc.Error``'s ``.message``
and ``.line``; (b) accepted by both: every segment of ``res.path`` (``line`` included) and the file
it comes from (``res.path.files[res.path.file[i]]``; compared only once toolcomp has those columns,
a warning says when they are missing and test_subroutine_file_attribution skips); (c) rejected by
both: ``strict=False`` reports the same error and its path starts with LinuxCNC's moves; up to
MAX_QUEUED more segments are allowed (LinuxCNC never emits what its comp queue still holds when an
error stops it, and in loops and subroutines "queued" is not "from an earlier line").

Lines and files, as the oracle reports them:

* a move made inside a subroutine file carries the 1-based line **in that file** (the module's
  ``next_line(linecode).sequence_number``); the callbacks say nothing about the file. The file
  being executed when a callback runs is ``interpreter.this.filename`` (the module embeds the
  ``interpreter`` Python module), but with compensation on a move is emitted when the *next* move
  is known: the last compensated move of a subroutine file comes out while the caller's block
  runs, with the subroutine file's line number, and a caller's entry move comes out inside the
  subroutine file. So the executing file is only the move's file with compensation off.
* exact attribution: the oracle runs programs that call subroutine files a second time, with a
  copy of the subroutine directory in which the i-th file (sorted by name) is preceded by
  (i+1) * OFFSET empty lines, so a move's line tells its file (line // OFFSET) and its line
  (line % OFFSET). test_offset_attribution_is_transparent checks that both runs agree move for
  move, and agree with the executing file wherever compensation is off.
* an error inside a subroutine (inline or in a file, at any depth) is reported at the **main
  program's line of the outermost call**: the interpreter unwinds the calls before the module
  reads the line (Interp::unwind_call; rs274 prints the failing block's text, not a line). That is
  the line toolcomp must report.

Also (no oracle needed): every generated program against its *unrolled* form (the same blocks in
execution order with plain numbers, written by generate_macros.py's model) through toolcomp: the
same path (geometry, not lines). test_generator_unrolled_matches_linuxcnc checks that model
against LinuxCNC.

LinuxCNC behaviours this pins down (Debian 12 linuxcnc-uspace 2.9.0~pre1; generate_macros.py
documents the expression and scoping rules; the hand-written programs show each): ``-2 ** 2`` is
4, ``2 ** 3 ** 2`` is 64; ``#1 = 5 #2 = #1`` gives #2 the old #1; ``#<x> = 1 G1 X#<x>`` moves to
X0 when #<x> was undefined (declared, 0, as the assignment is read) and ``#<x> = [#<x> + 1]`` on
an undefined #<x> gives 1; the main program's named parameters are not visible in subroutines; a
call clears #1..#30 beyond its arguments and restores the caller's; a call without a value sets
#<_value> and #<_value_returned> to 0; repeat [2.7] runs 3 times; break/continue in a repeat loop
is an error whose message quotes the raw line, indentation included; EQ/NE have a 1e-4 tolerance;
O-word and parameter names fold to lower case without blanks (o<MX_RRECT> finds mx_rrect.ngc).
Left out on purpose (LinuxCNC bugs, see generate_macros._Gen): a do/while loop after a while loop
left by break runs once; a repeat loop after a do/while loop with continue starts over.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import tempfile
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import gcode_oracle
import generate_macros as gm
import test_oracle_comp as oc

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
MACROS = ROOT / "tests" / "programs" / "macros"
SUBS = MACROS / "subs"
TABLE = ROOT / "tests" / "programs" / "comp" / "tools.tbl"
N_GENERATED = int(os.environ.get("TOOLCOMP_MACRO_N", "100"))
SEED_BASE = int(os.environ.get("TOOLCOMP_MACRO_SEED", "300000"))
SEEDS = range(SEED_BASE, SEED_BASE + N_GENERATED)
OFFSET = 100000                  # empty lines per file index in the attribution copy
MAX_QUEUED = 3                   # strict=False: segments beyond LinuxCNC's moves at an error
TOL = oc.TOL

needs_oracle = pytest.mark.skipif(not gcode_oracle.available(),
                                  reason="/usr/bin/python3 cannot import LinuxCNC's gcode module")

# ---------------------------------------------------------------------------------------------
# the oracle, batched: one /usr/bin/python3 process parses many programs

_BATCH = r"""
import json, os, sys, tempfile
sys.path.insert(0, sys.argv[1])
import gcode_oracle as go
jobs = json.load(open(sys.argv[2]))
OFFSET = int(sys.argv[4])
home = tempfile.mkdtemp(prefix="gcode_macros_")
os.environ["HOME"] = home                       # private $HOME/.tool.mmap
import ctypes
lookup, find = go._tooldata(None)                # the mmap: once per process
lib = ctypes.CDLL("libtooldata.so.0", mode=ctypes.RTLD_GLOBAL)
load = lib._Z13tooldata_loadPKcPPc
load.argtypes = [ctypes.c_char_p, ctypes.c_void_p]
import gcode

_inis = {}


def ini(subdir):
    # the interpreter reads getenv("INI_FILE_NAME") at every gcode.parse (init)
    if subdir not in _inis:
        path = os.path.join(home, "sub%d.ini" % len(_inis))
        with open(path, "w") as f:
            f.write("[RS274NGC]\nSUBROUTINE_PATH = %s\n" % subdir)
        _inis[subdir] = path
    return _inis[subdir]


_offset_dirs = {}


def offset_copy(subdir):
    # the i-th file (sorted) preceded by (i + 1) * OFFSET empty lines: the line tells the file
    if subdir not in _offset_dirs:
        d = os.path.join(home, "offset%d" % len(_offset_dirs))
        os.mkdir(d)
        names = sorted(n for n in os.listdir(subdir) if n.endswith(".ngc"))
        for i, n in enumerate(names):
            text = open(os.path.join(subdir, n), errors="replace").read()
            if text.count("\n") >= OFFSET:
                raise RuntimeError("%s has too many lines for the attribution copy" % n)
            with open(os.path.join(d, n), "w") as f:
                f.write("\n" * ((i + 1) * OFFSET) + text)
        _offset_dirs[subdir] = (d, [os.path.realpath(os.path.join(subdir, n)) for n in names])
    return _offset_dirs[subdir]


class Collector(go.Collector):
    def _feed_mm(self):                         # G93 rates: see test_oracle_comp.py
        return self.feed * go.MM_PER_INCH

    def _row(self, kind, *args):
        super()._row(kind, *args)
        try:
            import interpreter                 # embedded in the gcode module
            this = interpreter.this
            f, side = this.filename, int(this.cutter_comp_side)
        except Exception:                       # noqa: BLE001 (an older/newer module)
            f, side = None, None
        self.cols.setdefault("emit_file", []).append(f)
        self.cols.setdefault("emit_comp", []).append(side)


def parse(program, subdir):
    # As in a fresh process (the spindle tool does not leak: it is the Collector's).
    go.reset_interpreter(gcode, lookup, find, home)
    os.environ["INI_FILE_NAME"] = ini(subdir)
    var = os.path.join(home, "oracle.var")
    open(var, "w").close()                       # fresh parameters for every program
    source = open(program, errors="replace").read().splitlines()
    canon = Collector(lookup, find, source, var)
    result, near = gcode.parse(os.path.abspath(program), canon, "G21", "F0")
    error = None
    if result > gcode.MIN_ERROR:
        error = {"message": gcode.strerror(result), "line": int(canon.line), "code": int(result)}
    d = dict(canon.cols)
    d.setdefault("emit_file", [])
    d.setdefault("emit_comp", [])
    d["error"] = error
    return d


loaded = None
out = []
for program, table, subdir, attribute in jobs:
    if table != loaded:                          # tooldata_load replaces the whole table
        if load(os.fsencode(table), None) != 0:
            raise RuntimeError("tooldata_load(%s) failed" % table)
        loaded = table
    d = parse(program, subdir)
    if attribute:
        odir, files = offset_copy(subdir)
        d["offset_run"] = parse(program, odir)
        d["offset_files"] = files
    out.append(d)
json.dump(out, open(sys.argv[3], "w"))
"""


def _columns(raw: dict) -> dict:
    d = oc._columns(raw)
    d["emit_file"] = list(raw.get("emit_file", []))
    d["emit_comp"] = list(raw.get("emit_comp", []))
    return d


def _attribute(d: dict, raw: dict, program: str) -> None:
    """Fill d['file'] (the file of every move) from the offset run, when there is one."""
    d["offset_run"] = None
    d["file"] = None
    if raw.get("offset_run") is None:
        return
    off = _columns(raw["offset_run"])
    names = [os.path.realpath(program)] + list(raw["offset_files"])
    idx = off["line"] // OFFSET
    off["file_index"] = idx
    off["line"] = off["line"] % OFFSET
    d["offset_run"] = off
    d["file"] = [names[i] for i in idx]
    if off["error"] is not None:
        e = dict(off["error"])
        e["line"] %= OFFSET              # (always the main program's: LinuxCNC unwinds the calls)
        off["error"] = e


def _run_batch(jobs, timeout=600.0):
    with tempfile.TemporaryDirectory(prefix="gcode_macros_batch_") as tmp:
        jf, of = Path(tmp) / "jobs.json", Path(tmp) / "out.json"
        jf.write_text(json.dumps([[str(Path(p).resolve()), str(Path(t).resolve()), str(Path(s).resolve()),
                                   bool(a)] for p, t, s, a in jobs]))
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
        env["HOME"] = tmp
        proc = subprocess.run([gcode_oracle.SYSTEM_PYTHON, "-c", _BATCH, str(HERE), str(jf), str(of),
                               str(OFFSET)], capture_output=True, text=True, timeout=timeout, env=env,
                              stdin=subprocess.DEVNULL, cwd=tmp)
        if proc.returncode != 0 or not of.exists():
            raise gcode_oracle.GcodeModuleFailure("gcode batch failed (rc=%d):\n%s"
                                                  % (proc.returncode, proc.stderr[-3000:]))
        out = []
        for (p, _, _, _), raw in zip(jobs, json.loads(of.read_text())):
            d = _columns(raw)
            _attribute(d, raw, str(p))
            out.append(d)
        return out


def run_oracle(jobs, workers=None):
    """LinuxCNC results for [(program, table, subroutine dir, attribute files?), ...], in order,
    in parallel batches (one per CPU)."""
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


_CALL = re.compile(r"^\s*o\s*<\s*([^>]+?)\s*>\s*call\b", re.I | re.M)


def calls_files(text: str) -> bool:
    """True when the program calls a subroutine that lives in a file of SUBS."""
    return any((SUBS / (gm.norm(n) + ".ngc")).exists() for n in _CALL.findall(text))


# ---------------------------------------------------------------------------------------------
# toolcomp side

def _tc():
    return pytest.importorskip("toolcomp")


def toolcomp_run(program: Path, table: Path, strict=True):
    """(columns of res.path or None, error or None, result or None)."""
    tc = _tc()
    tools = tc.ToolTable.read(str(table))
    try:
        res = tc.run(tc.Program.read(str(program), strict=False), tools=tools, strict=strict,
                     search_path=[str(SUBS)], start="machine_zero")  # rs274 starts at machine zero
    except tc.Error as e:
        return None, e, None
    return oc.path_columns(res.path), None, res


def _same_file(linuxcnc: str, toolcomp: str) -> bool:
    if os.path.realpath(toolcomp) == os.path.realpath(linuxcnc):
        return True
    return os.path.basename(toolcomp) == toolcomp and toolcomp == os.path.basename(linuxcnc)


def file_differences(program: Path, mod: dict, res, upto=None, limit=8):
    """Differences of the file column (None: toolcomp has no res.path.files / .file yet)."""
    path = res.path
    if not (hasattr(path, "files") and hasattr(path, "file")):
        return None
    names = list(path.files)
    idx = np.asarray(path.file).astype(np.int64)
    out = []
    if not names or not _same_file(str(program), names[0]):
        out.append("res.path.files[0] is %r, not the main program %s" % (names[:1], program))
    want = mod["file"]
    if want is None:                               # no subroutine files: everything is main
        want = [os.path.realpath(program)] * len(mod["kind"])
    n = min(len(want), len(idx) if upto is None else upto)
    for i in range(n):
        got = names[idx[i]] if 0 <= idx[i] < len(names) else "<index %d>" % idx[i]
        if not _same_file(want[i], got):
            out.append("segment #%d (LinuxCNC %s line %d): file: LinuxCNC %s, toolcomp %s"
                       % (i, os.path.basename(want[i]), mod["line"][i], want[i], got))
            if len(out) >= limit:
                break
    return out


def continuity(t: dict, upto=None) -> list:
    """toolcomp's own consistency: every segment starts where the previous one ended, in machine
    coordinates (program position + tool length offset: a G43/G49 between two segments moves the
    program position, not the tool). test_oracle_comp.continuity without the offset."""
    n = len(t["kind"]) if upto is None else upto
    for i in range(1, n):
        a = t["start"][i] + t["tool_offset"][i]
        b = t["end"][i - 1] + t["tool_offset"][i - 1]
        if not np.all(np.abs(a - b) <= 1e-9):
            return ["toolcomp segment #%d starts at %s (tool offset %s), segment #%d ended at %s "
                    "(tool offset %s)" % (i, oc._vec(t["start"][i]), oc._vec(t["tool_offset"][i]),
                                          i - 1, oc._vec(t["end"][i - 1]), oc._vec(t["tool_offset"][i - 1]))]
    return []


_warned_files = []


def _files_or_warn(program, mod, res, upto=None):
    diffs = file_differences(program, mod, res, upto)
    if diffs is None:
        if not _warned_files:
            _warned_files.append(1)
            warnings.warn("toolcomp's Path has no 'files'/'file' columns yet: the file of each segment "
                          "is not compared (test_subroutine_file_attribution is skipped)")
        return []
    return diffs


def check(program: Path, table: Path, mod: dict) -> list:
    """Every disagreement between LinuxCNC (``mod``) and toolcomp on ``program`` (empty: agree)."""
    tc = _tc()
    cols, err, res = toolcomp_run(program, table)
    merr = mod["error"]
    if merr is None and err is None:
        return oc.differences(mod, cols) + continuity(cols) + _files_or_warn(program, mod, res)
    if merr is None:
        return ["LinuxCNC accepts the program; toolcomp raises %s on line %d: %s"
                % (type(err).__name__, err.line, err.message)]
    if err is None:
        return ["LinuxCNC rejects line %d: %r; toolcomp accepts the program"
                % (merr["line"], merr["message"])] + oc.differences(mod, cols)
    out = []
    if (err.message, err.line) != (merr["message"], merr["line"]):
        out.append("error: LinuxCNC line %d %r; toolcomp %s line %d %r%s"
                   % (merr["line"], merr["message"], type(err).__name__, err.line, err.message,
                      _in_file(mod, program) if err.line != merr["line"] else ""))
    if not isinstance(err, (tc.ProgramError, tc.CompensationError, tc.ParseError)):
        out.append("toolcomp raised %s" % type(err).__name__)
    return out + _before(program, table, mod)


def _in_file(mod, program=None):
    """A hint when the error may come from inside a subroutine."""
    if program is not None and re.search(r"\bcall\b", Path(program).read_text(), re.I):
        return (" (for an error inside a subroutine, or a call of an unknown O-word, LinuxCNC "
                "reports the main program's line of the outermost call)")
    return ""


def _before(program, table, mod) -> list:
    """(c): strict=False path vs the moves LinuxCNC emitted before its error (queued comp moves
    of blocks before the error may be extra in toolcomp, as in test_oracle_comp.py)."""
    merr = mod["error"]
    cols, err, res = toolcomp_run(program, table, strict=False)
    if err is not None:
        return ["strict=False still raises %s: %s" % (type(err).__name__, err.message)]
    errs = [d for d in res.diagnostics if d.severity == "error"]
    out = []
    if not errs or (errs[0].message, errs[0].line) != (merr["message"], merr["line"]):
        out.append("strict=False diagnostics %s, LinuxCNC %r line %d"
                   % ([(d.message, d.line) for d in errs], merr["message"], merr["line"]))
    n_m, n_t = len(mod["kind"]), len(cols["kind"])
    if n_t < n_m:
        out.append("strict=False path has %d segments, LinuxCNC emitted %d before the error" % (n_t, n_m))
        return out + oc.differences(mod, cols)
    if n_t - n_m > MAX_QUEUED:
        out.append("strict=False path has %d segments beyond LinuxCNC's %d moves (at most %d "
                   "queued compensated moves may be): lines %s"
                   % (n_t - n_m, n_m, MAX_QUEUED, cols["line"][n_m:].tolist()))
    return (out + oc.differences(mod, cols, upto=n_m) + continuity(cols)
            + _files_or_warn(program, mod, res, upto=n_m))


def _table_for(prog: Path) -> Path:
    own = prog.with_suffix(".tbl")
    return own if own.exists() else TABLE


# ---------------------------------------------------------------------------------------------
# the programs

HAND = sorted(MACROS.glob("*.ngc"))


@pytest.fixture(scope="session")
def programs(tmp_path_factory):
    """seed -> gm.Generated with .path / .unrolled_path set (files in a temp dir)."""
    d = tmp_path_factory.mktemp("macros_generated")
    out = {}
    for seed in SEEDS:
        g = gm.build(seed)
        g.path = (d / ("macro_%d.ngc" % seed)).resolve()
        g.path.write_text(g.text)
        g.unrolled_path = None
        if g.unrolled is not None:
            g.unrolled_path = (d / ("macro_%d_unrolled.ngc" % seed)).resolve()
            g.unrolled_path.write_text(g.unrolled)
        out[seed] = g
    return out


@pytest.fixture(scope="session")
def oracle(programs):
    """key -> LinuxCNC result: seed (generated), ('unrolled', seed), stem (hand-written)."""
    keys, jobs = [], []
    for seed, g in programs.items():
        keys.append(seed)
        jobs.append((g.path, TABLE, SUBS, calls_files(g.text)))
        if g.unrolled_path is not None:
            keys.append(("unrolled", seed))
            jobs.append((g.unrolled_path, TABLE, SUBS, False))
    for p in HAND:
        keys.append(p.stem)
        jobs.append((p, _table_for(p), SUBS, calls_files(p.read_text())))
    return dict(zip(keys, run_oracle(jobs)))


def _fail(diffs, what):
    assert not diffs, "%s:\n  %s" % (what, "\n  ".join(diffs))


@needs_oracle
@pytest.mark.parametrize("prog", HAND, ids=lambda p: p.stem)
def test_hand_written_program(prog, oracle):
    _fail(check(prog, _table_for(prog), oracle[prog.stem]), "%s: toolcomp differs from LinuxCNC" % prog.name)


@needs_oracle
@pytest.mark.parametrize("seed", SEEDS)
def test_generated_program(seed, programs, oracle):
    g = programs[seed]
    _fail(check(g.path, TABLE, oracle[seed]),
          "%s (python tests/oracle/generate_macros.py %d): toolcomp differs from LinuxCNC" % (g.path.name, seed))


@needs_oracle
def test_hand_written_expectations(oracle):
    """The first line of every hand-written program is what LinuxCNC does (checks the programs and
    the oracle, not toolcomp): ``; ok`` or ``; error: <message> @ <line>``; ``{file}`` in the
    message stands for the program's absolute path. For an error inside a subroutine, <line> is the
    main program's line of the (outermost) call: see ``check``."""
    bad = []
    for prog in HAND:
        first = prog.read_text().splitlines()[0]
        err = oracle[prog.stem]["error"]
        got = None if err is None else (err["message"], err["line"])
        if first.startswith("; error: "):
            msg, _, line = first[len("; error: "):].rpartition(" @ ")
            want = (msg.replace("{file}", str(prog.resolve())), int(line))
            if got != want:
                bad.append("%s: LinuxCNC %s, the program says %r" % (prog.name, got, want))
        elif first.startswith("; ok"):
            if got is not None:
                bad.append("%s: LinuxCNC rejects it: %s" % (prog.name, got))
        else:
            bad.append("%s: first line must be '; ok' or '; error: <message> @ <line>'" % prog.name)
    _fail(bad, "hand-written programs")


@needs_oracle
def test_generated_programs_fail_only_as_intended(programs, oracle):
    """LinuxCNC accepts every generated program except the intended error ones, and rejects those
    with the message the generator's model predicts (checks the generator, not toolcomp)."""
    bad = []
    for seed, g in programs.items():
        err = oracle[seed]["error"]
        if g.error is None and err is not None:
            bad.append("seed %d: unintended LinuxCNC error line %d: %s" % (seed, err["line"], err["message"]))
        elif g.error is not None and (err is None or not re.match(g.error_regex(), err["message"])):
            bad.append("seed %d: intended %r (%s), LinuxCNC %s" % (seed, g.error, g.fail, err))
    _fail(bad, "generated programs")


def geometry_differences(a: dict, b: dict, names=("macro", "unrolled"), limit=8) -> list:
    """Everything but the line: kind, end, centre, turns, abc, tool offset, feed (1e-6)."""
    out = []
    if len(a["kind"]) != len(b["kind"]):
        out.append("segment count: %s %d, %s %d" % (names[0], len(a["kind"]), names[1], len(b["kind"])))
    for i in range(min(len(a["kind"]), len(b["kind"]))):
        for k in ("kind", "turns", "end", "center", "abc", "tool_offset", "feed"):
            x, y = np.asarray(a[k][i], dtype=float), np.asarray(b[k][i], dtype=float)
            if np.any(np.isnan(x) != np.isnan(y)) or np.any(np.abs(np.nan_to_num(x) - np.nan_to_num(y)) > TOL):
                out.append("segment #%d %s: %s %s, %s %s" % (i, k, names[0], x, names[1], y))
                break
        if len(out) >= limit:
            break
    return out


@needs_oracle
def test_generator_unrolled_matches_linuxcnc(programs, oracle):
    """LinuxCNC makes the same moves from a generated program and from the generator's unrolled
    version of it: the model that writes the unrolled text is right (no toolcomp involved)."""
    bad = []
    for seed, g in programs.items():
        if g.unrolled_path is None:
            continue
        diffs = geometry_differences(oracle[seed], oracle[("unrolled", seed)])
        if oracle[("unrolled", seed)]["error"] is not None:
            diffs.append("unrolled program rejected: %s" % oracle[("unrolled", seed)]["error"])
        if diffs:
            bad.append("seed %d: %s" % (seed, "; ".join(diffs[:3])))
    _fail(bad, "unrolled programs differ in LinuxCNC")


@needs_oracle
def test_offset_attribution_is_transparent(programs, oracle):
    """The attribution copy (empty lines in front of every subroutine file) changes nothing but
    the line numbers, and agrees with the file LinuxCNC executes where compensation is off."""
    bad, checked = [], 0
    for key, mod in oracle.items():
        off = mod["offset_run"]
        if off is None:
            continue
        checked += 1
        diffs = geometry_differences(mod, off, ("plain", "attribution copy"))
        if not np.array_equal(mod["line"], off["line"][:len(mod["line"])]):
            diffs.append("lines differ: %s / %s" % (mod["line"].tolist(), off["line"].tolist()))
        me, oe = mod["error"], off["error"]
        if (me is None) != (oe is None) or (me and (me["line"] != oe["line"] or (
                "/" not in me["message"] and me["message"] != oe["message"]))):
            diffs.append("errors differ: %s / %s" % (me, oe))
        for i, (f, side) in enumerate(zip(mod["emit_file"], mod["emit_comp"])):
            if side == 0 and f is not None and os.path.realpath(f) != mod["file"][i]:
                diffs.append("move #%d with comp off: executing %s, attribution copy says %s"
                             % (i, f, mod["file"][i]))
                break
        if diffs:
            bad.append("%s: %s" % (key, "; ".join(diffs[:3])))
    assert checked, "no program calls a subroutine file"
    _fail(bad, "attribution copy")


@needs_oracle
def test_subroutine_file_attribution(programs, oracle):
    """The file of every segment of the programs that call subroutine files (skipped while
    toolcomp's Path has no ``files``/``file`` columns)."""
    tc = _tc()
    cases = [(p, _table_for(p), oracle[p.stem]) for p in HAND if oracle[p.stem]["offset_run"] is not None]
    cases += [(g.path, TABLE, oracle[s]) for s, g in programs.items() if oracle[s]["offset_run"] is not None]
    assert cases
    probe = tc.run(tc.Program.parse("G0 X1\nM2\n"))
    if not (hasattr(probe.path, "files") and hasattr(probe.path, "file")):
        pytest.skip("toolcomp's Path has no 'files'/'file' columns yet: the file of a segment "
                    "cannot be compared (lines are compared by the other tests)")
    bad = []
    for prog, table, mod in cases:
        cols, err, res = toolcomp_run(prog, table, strict=mod["error"] is None)
        if res is None:
            bad.append("%s: toolcomp raises %s" % (prog.name, err))
            continue
        n = len(mod["kind"]) if mod["error"] is not None else None
        diffs = file_differences(prog, mod, res, upto=n)
        if diffs:
            bad.append("%s: %s" % (prog.name, "; ".join(diffs[:3])))
    _fail(bad, "file attribution")


@pytest.mark.parametrize("seed", SEEDS)
def test_loop_program_equals_unrolled(seed, programs):
    """toolcomp only: a generated program and its unrolled form (plain numbers, no parameters, no
    O-words) give the same path, compensated, segment by segment (lines aside)."""
    g = programs[seed]
    if g.unrolled_path is None:
        pytest.skip("error program (intended %s): nothing to unroll" % g.fail)
    a, ea, _ = toolcomp_run(g.path, TABLE)
    b, eb, _ = toolcomp_run(g.unrolled_path, TABLE)
    if ea is not None and eb is not None:
        # The geometry itself is refused (a gouge the generator cannot foresee): then both
        # forms must be refused for the same reason (LinuxCNC's verdict is checked by
        # test_generated_program).
        assert (ea.code, str(ea.args[0])) == (eb.code, str(eb.args[0]))
        return
    assert eb is None, "unrolled program rejected by toolcomp: %s" % eb
    assert ea is None, "toolcomp rejects %s (its unrolled form runs): %s" % (g.path.name, ea)
    _fail(geometry_differences(a, b), "%s vs its unrolled form" % g.path.name)


def test_library_files_match_generator():
    """subs/mx_*.ngc are exactly what the generator models (it calls them)."""
    for name in gm.LIBRARY:
        assert (SUBS / (name + ".ngc")).read_text() == gm.library_text(name), name


def test_generator_is_deterministic():
    assert gm.generate(SEED_BASE) == gm.generate(SEED_BASE)
    assert gm.generate(SEED_BASE) != gm.generate(SEED_BASE + 1)
    assert gm.unrolled(SEED_BASE) == gm.unrolled(SEED_BASE)


@needs_oracle
def test_batching_is_transparent(programs, oracle):
    """One process per program (gcode_oracle.run_gcode_module, no subroutine path) == batched."""
    picks = [s for s, g in programs.items() if not calls_files(g.text)][:4]
    for seed in picks:
        single = gcode_oracle.run_gcode_module(programs[seed].path, TABLE)
        batched = oracle[seed]
        assert (single["error"] or {}).get("message") == (batched["error"] or {}).get("message"), seed
        assert (single["error"] or {}).get("line") == (batched["error"] or {}).get("line"), seed
        for k in ("kind", "line", "turns", "plane"):
            assert np.array_equal(single[k], batched[k]), (seed, k)
        for k in ("end", "center", "abc", "tool_offset", "feed"):
            assert np.array_equal(np.nan_to_num(single[k], nan=1e300),
                                  np.nan_to_num(batched[k], nan=1e300)), (seed, k)
