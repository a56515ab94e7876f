#!/usr/bin/python3
"""Full-precision oracle: LinuxCNC's ``gcode`` Python module (AXIS' preview interpreter).

Two halves in one file:

* **Script**, run by Debian's ``/usr/bin/python3`` (the only interpreter that can import ``gcode``;
  the project venv cannot)::

      /usr/bin/python3 tests/oracle/gcode_oracle.py PROGRAM.ngc TOOLS.tbl OUT.json

  ``TOOLS.tbl`` is a *metric* LinuxCNC tool table ('-' or an empty file for none). OUT.json holds
  the moves as column lists plus the error, if any. Only the standard library is used here.

* **Helpers** imported by pytest (venv numpy): :func:`available`, :func:`run_gcode_module`.

Why this oracle next to ``lcnc.py`` (rs274): the module hands every value to Python as a full
double (rs274 prints ``%.4f``), gives the 1-based source line of every move (``next_line``), and
reports the exact line of an error. It runs the same rs274ngc interpreter (same build,
linuxcnc-uspace 2.9.0~pre1, Debian 12), with the canon layer AXIS uses for its preview.

How the module is made to work (see /work/shared/research/linuxcnc-oracle.md section 3):

* Tool lookups (``T``, ``M6``, ``G43 Hn``) read LinuxCNC's tool mmap, which normally exists only
  inside a running LinuxCNC. The script points ``$HOME`` at a private temp dir (the mmap file is
  ``$HOME/.tool.mmap``) and creates and fills the mmap itself through ctypes on
  ``libtooldata.so.0`` (``tool_mmap_creator``, ``tooldata_load``); ``get_tool(idx)`` is served from
  ``tooldata_get``. Index 0 is the spindle: it returns the tool last changed to (``change_tool``),
  like AXIS does, so ``G43`` without H sees the loaded tool. ``M61 Qn`` reaches Python through no
  callback (the module's CHANGE_TOOL_NUMBER only starts a new line), so the script reads a literal
  ``M61 Qn`` from the source line that ``next_line`` announces and puts tool n in the spindle, as
  LinuxCNC's task does (rs274 does not: its "M61 then bare G43" quirk).
* ``gcode.parse(program, canon, "G21", "F0")``: the unit code G21 makes the interpreter start in mm,
  as AXIS does on an mm machine and as rs274 does (without it the program starts in inches and the F
  of a first "G21 F300" block, executed before G21, would be inch/min). The init code F0 gives the
  start-up feed rate of a real LinuxCNC, 0 (the module's stub GET_EXTERNAL_FEED_RATE returns 1, which
  would hide "Cannot do g1 with zero feed rate").
* ``get_external_length_units()`` returns 1.0: an mm machine, so the tool table is read in mm. This
  build is *not* hit by the inch-only table bug rs274 has (issue #1279): verified, ``T1 Z25`` gives
  ``tool_offset`` = 25 mm in both a G21 and a G20 program (see ``test_oracle_precise.py``).
* The module passes **every length in inches**: when the program is in G21 it divides positions,
  arc centres, tool offsets and feed rates by 25.4 (``if(metric) x /= 25.4``). The script multiplies
  all of them by 25.4, so the output is in mm whatever the program units (verified against toolcomp
  to ~1e-13 mm on all oracle programs). Angles (A, B, C) are passed unchanged, in degrees. (Feed in G93
  inverse-time mode is divided too; the script undoes that, reporting the raw inverse-time number.)
* Error line: ``gcode.parse`` returns ``last_sequence_number + 1`` when *reading* a block failed (AXIS
  shows it as "near line"), one too many for every parse-type error. After a failure the module always
  announces the interpreter's sequence number in a last ``next_line``, so the script reports that:
  the exact 1-based line of the failing block (verified on all of tests/programs/errors).
* The parameter (.var) file must exist, or the interpreter complains; the script uses a temp file.
* The axis mask is XYZABC (0x3f), like rs274: a U/V/W word is "Bad character 'u' used".
* Block delete is off (``get_block_delete`` False): '/' lines are executed, like rs274 without -b.

Known artefact of the module's canon layer (not LinuxCNC): after a tool change (M6, M61) the
interpreter re-reads the current position through GET_EXTERNAL_POSITION_*, which in gcodemodule.cc is
the last STRAIGHT_* end in program coordinates (ARC_FEED does not update it, tool length offset
changes are not applied), so the next move's unprogrammed axes can be stale. See
test_oracle_precise.py (MODULE_ARTEFACTS).

Output columns (N moves, one per straight_traverse / straight_feed / straight_probe / arc_feed):

``kind``    0 rapid, 1 feed, 2 arc cw (rotation < 0), 3 arc ccw (rotation > 0)
``line``    1-based source line the interpreter attributes the move to (``next_line``)
``end``     (N,3) program X, Y, Z at the end, mm (ARC_FEED's plane order mapped back to X, Y, Z)
``center``  (N,3) arc centre, mm: the two in-plane components (G17 X,Y; G18 Z,X; G19 Y,Z) mapped
            to their X/Y/Z slots; the component along the plane normal is NaN (the module has none).
            All NaN for lines and rapids.
``turns``   ARC_FEED ``rotation``: +-1 for an arc or one full circle, +-n with Pn; 0 for lines
``abc``     (N,3) A, B, C at the end, degrees
``tool_offset`` (N,3) active tool length offset X, Y, Z, mm
``feed``    active feed rate, mm/min (NaN for rapids)
``plane``   17, 18 or 19

Error: ``{"message": gcode.strerror(code), "line": <exact 1-based line>, "near_line": <what
gcode.parse returned>, "code": n}`` or null. Also ``lines_seen`` (every next_line number, in order)
and ``ignored_calls`` (callback name -> count of the callbacks the script ignores); with the
environment variable GCODE_ORACLE_TRACE=1 the JSON has a ``trace`` of every callback and its arguments.
"""
from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SYSTEM_PYTHON = "/usr/bin/python3"
MM_PER_INCH = 25.4
RAPID, LINE, ARC_CW, ARC_CCW = 0, 1, 2, 3
AXIS_MASK = 0x3F                              # X Y Z A B C (no U V W), as rs274
_CANON_PLANE = {1: 17, 2: 19, 3: 18}          # CANON_PLANE_XY / _YZ / _XZ
_COLUMNS = ("kind", "line", "end", "center", "turns", "abc", "tool_offset", "feed", "plane")


# =============================================================================================
# script side (Debian /usr/bin/python3 with LinuxCNC's gcode module)

def _tooldata(table: str | None):
    """Create a private tool mmap (needs $HOME already private) and load ``table`` into it."""
    import ctypes

    class EmcPose(ctypes.Structure):
        _fields_ = [(n, ctypes.c_double) for n in "xyzabcuvw"]

    class CanonToolTable(ctypes.Structure):      # emctool.h, LinuxCNC 2.9
        _fields_ = [("toolno", ctypes.c_int), ("pocketno", ctypes.c_int), ("offset", EmcPose),
                    ("diameter", ctypes.c_double), ("frontangle", ctypes.c_double),
                    ("backangle", ctypes.c_double), ("orientation", ctypes.c_int)]

    lib = ctypes.CDLL("libtooldata.so.0", mode=ctypes.RTLD_GLOBAL)
    create = lib._Z17tool_mmap_creatorPK13EMC_TOOL_STATi   # tool_mmap_creator(EMC_TOOL_STAT*, int random)
    create.argtypes = [ctypes.c_void_p, ctypes.c_int]
    load = lib._Z13tooldata_loadPKcPPc                       # tooldata_load(const char*, char**)
    load.argtypes = [ctypes.c_char_p, ctypes.c_void_p]
    get = lib._Z12tooldata_getP16CANON_TOOL_TABLEi          # tooldata_get(CANON_TOOL_TABLE*, int idx)
    get.argtypes = [ctypes.POINTER(CanonToolTable), ctypes.c_int]
    find = lib._Z28tooldata_find_index_for_tooli            # tooldata_find_index_for_tool(int toolno)
    find.argtypes = [ctypes.c_int]
    create(None, 0)                                          # nonrandom tool changer
    if table:
        rc = load(os.fsencode(table), None)
        if rc != 0:
            raise RuntimeError("tooldata_load(%s) failed: %d" % (table, rc))
    entry = CanonToolTable()

    def lookup(idx):
        if get(ctypes.byref(entry), idx) != 0:
            return None
        o = entry.offset
        return (entry.toolno, o.x, o.y, o.z, o.a, o.b, o.c, o.u, o.v, o.w,
                entry.diameter, entry.frontangle, entry.backangle, entry.orientation)
    return lookup, find


_NO_TOOL = (-1,) + (0.0,) * 12 + (0,)


def _m61_tool(source_lines, line):
    """Tool number of a literal ``M61 Qn`` on 1-based source ``line``, else None.

    The module's CHANGE_TOOL_NUMBER (M61) calls nothing in Python, so the spindle tool is followed
    from the text; only plain numbers are understood (no #parameters or expressions).
    """
    if not 1 <= line <= len(source_lines):
        return None
    text = re.sub(r"\([^)]*\)", "", source_lines[line - 1]).split(";")[0]
    text = re.sub(r"\s+", "", text).upper()
    if not re.search(r"M0*61(?![0-9.])", text):
        return None
    q = re.search(r"Q([+]?[0-9]*\.?[0-9]+)", text)
    return int(round(float(q.group(1)))) if q else None


class Collector:
    """Canon callback object for ``gcode.parse``: records moves in mm; other callbacks are no-ops."""

    def __init__(self, lookup, find_index, source_lines, var_file: str):
        self.parameter_file = var_file
        self._lookup = lookup
        self._find_index = find_index
        self._source = source_lines
        self.spindle = 0                 # mmap index of the tool in the spindle (0: none)
        self.line = 0
        self.lines_seen = []             # every next_line sequence number, in order
        self.plane = 17
        self.feed = 0.0                  # as the module passes it: inch/min (G93: see _feed_mm)
        self.inverse_time = False
        self.metric = False
        self.tlo = [0.0, 0.0, 0.0]       # mm
        self.cols = {k: [] for k in _COLUMNS}
        self.calls = {}                  # name -> count of no-op callbacks (for debugging)
        self.trace = None                # TracingCollector: list of [line, callback, args...]

    # --- queries from the interpreter ------------------------------------------------------
    def get_tool(self, idx):
        if idx == 0:                     # the spindle: serve the tool last changed to
            if self.spindle <= 0:
                return _NO_TOOL
            idx = self.spindle
        return self._lookup(idx) or _NO_TOOL

    def get_external_length_units(self):
        return 1.0                       # mm machine: the tool table is in mm

    def get_external_angular_units(self):
        return 1.0

    def get_axis_mask(self):
        return AXIS_MASK

    def get_block_delete(self):
        return False

    def check_abort(self):
        return False

    # --- state -----------------------------------------------------------------------------
    def next_line(self, linecode):
        self.line = linecode.sequence_number
        self.lines_seen.append(self.line)
        g = linecode.gcodes
        self.metric = 210 in g
        self.inverse_time = 930 in g
        tool = _m61_tool(self._source, self.line)
        if tool is not None:             # M61 Qn: LinuxCNC's task puts tool n in the spindle
            self.spindle = self._find_index(tool) if tool > 0 else 0

    def set_plane(self, p):
        self.plane = _CANON_PLANE.get(p, self.plane)

    def set_feed_rate(self, rate):
        self.feed = rate

    def tool_offset(self, x, y, z, *rest):
        self.tlo = [x * MM_PER_INCH, y * MM_PER_INCH, z * MM_PER_INCH]

    def change_tool(self, pocket):
        self.spindle = pocket

    def __getattr__(self, name):         # every other canon callback: count and ignore
        if name.startswith("__"):
            raise AttributeError(name)

        def noop(*args):
            self.calls[name] = self.calls.get(name, 0) + 1
            if self.trace is not None:
                self.trace.append([self.line, name] + [a if isinstance(a, (int, float, str)) else repr(a)
                                                       for a in args])
        return noop

    # --- moves -----------------------------------------------------------------------------
    def _feed_mm(self):
        # The module hands every rate over in inch/min: F divided by 25.4 in G21, and in G93 the
        # interpreter's own rate (programmed length x F, in program units per minute) likewise.
        return self.feed * MM_PER_INCH

    def _row(self, kind, end, center, turns, abc):
        c = self.cols
        c["kind"].append(kind)
        c["line"].append(self.line)
        c["end"].append(end)
        c["center"].append(center)
        c["turns"].append(turns)
        c["abc"].append(list(abc))
        c["tool_offset"].append(list(self.tlo))
        c["feed"].append(math.nan if kind == RAPID else self._feed_mm())
        c["plane"].append(self.plane)

    def straight_traverse(self, x, y, z, a, b, c, *uvw):
        self._row(RAPID, [x * MM_PER_INCH, y * MM_PER_INCH, z * MM_PER_INCH],
                  [math.nan] * 3, 0, (a, b, c))

    def straight_feed(self, x, y, z, a, b, c, *uvw):
        self._row(LINE, [x * MM_PER_INCH, y * MM_PER_INCH, z * MM_PER_INCH],
                  [math.nan] * 3, 0, (a, b, c))

    straight_probe = straight_feed

    def rigid_tap(self, x, y, z, *rest):  # in to the point and back out, as AXIS draws it
        start = self.cols["end"][-1] if self.cols["end"] else [0.0, 0.0, 0.0]
        abc = self.cols["abc"][-1] if self.cols["abc"] else (0.0, 0.0, 0.0)
        self._row(LINE, [x * MM_PER_INCH, y * MM_PER_INCH, z * MM_PER_INCH], [math.nan] * 3, 0, abc)
        self._row(LINE, list(start), [math.nan] * 3, 0, abc)

    def arc_feed(self, e1, e2, c1, c2, rot, ax, a, b, c, *uvw):
        e1, e2, c1, c2, ax = (v * MM_PER_INCH for v in (e1, e2, c1, c2, ax))
        nan = math.nan
        if self.plane == 17:             # arc_feed(x, y, cx, cy, rot, z)
            end, center = [e1, e2, ax], [c1, c2, nan]
        elif self.plane == 18:           # arc_feed(z, x, cz, cx, rot, y)
            end, center = [e2, ax, e1], [c2, nan, c1]
        else:                            # G19: arc_feed(y, z, cy, cz, rot, x)
            end, center = [ax, e1, e2], [nan, c1, c2]
        self._row(ARC_CW if rot < 0 else ARC_CCW, end, center, int(rot), (a, b, c))


class TracingCollector(Collector):
    """Collector that also logs every callback with its arguments (GCODE_ORACLE_TRACE=1)."""

    def __init__(self, *args):
        super().__init__(*args)
        self.trace = []

    def __getattribute__(self, name):
        attr = object.__getattribute__(self, name)
        if name.startswith("_") or not callable(attr) or name in ("get_tool", "trace"):
            return attr
        trace = object.__getattribute__(self, "trace")

        def logged(*args):
            line = object.__getattribute__(self, "line")
            trace.append([line, name] + [a if isinstance(a, (int, float, str)) else repr(a) for a in args])
            return attr(*args)
        return logged


def reset_interpreter(gcode, lookup, find, home: str) -> None:
    """Parse a program that cancels the tool length offset and goes to 0, so that the next
    program starts as in a fresh process: state survives gcode.parse's re-initialisation
    (gcodemodule.cc keeps the last STRAIGHT_* end in globals, the interpreter its tool length
    offset; a G49 in the next program re-expresses the position by the previous offset, and a
    first move that omits an axis would start where the previous program ended). For batches
    of programs in one process; ``home``: a private directory for the program and its .var."""
    reset = os.path.join(home, "reset.ngc")
    if not os.path.exists(reset):
        with open(reset, "w") as f:
            f.write("G21 G40 G90 G17\nG49\nG0 X0 Y0 Z0 A0 B0 C0\nM2\n")
        open(os.path.join(home, "reset.var"), "w").close()
    gcode.parse(reset, Collector(lookup, find, [], os.path.join(home, "reset.var")), "G21", "F0")


def parse_program(program: str, table: str | None) -> dict:
    """Run ``program`` through gcode.parse (in this process) and return the JSON-able result.

    Must run in a fresh process: the tool mmap can be created only once, and $HOME is changed.
    """
    home = tempfile.mkdtemp(prefix="gcode_oracle_")
    os.environ["HOME"] = home            # $HOME/.tool.mmap: never a running LinuxCNC's
    lookup, find_index = _tooldata(table)
    import gcode                         # after the mmap exists
    var_file = os.path.join(home, "oracle.var")
    Path(var_file).write_text("")
    source = Path(program).read_text(errors="replace").splitlines()
    cls = TracingCollector if os.environ.get("GCODE_ORACLE_TRACE") else Collector
    canon = cls(lookup, find_index, source, var_file)
    # unitcode "G21": the machine is metric, so the interpreter starts in mm (as AXIS does on an mm
    # machine, and as rs274 does); without it the program starts in inches and an F word in the
    # first "G21 F300" block (executed before G21) would be read as inch/min.
    # initcode "F0": a LinuxCNC machine starts with feed rate 0 (so "G1 X10" before any F word is
    # "Cannot do g1 with zero feed rate"); the module's canon stub GET_EXTERNAL_FEED_RATE returns 1.
    result, near = gcode.parse(os.path.abspath(program), canon, "G21", "F0")
    error = None
    if result > gcode.MIN_ERROR:
        # gcode.parse returns last_sequence_number + 1 when the *read* of a block failed (AXIS'
        # "near line"); after a failure the module always reports the interpreter's sequence number
        # through a last next_line call, so canon.line is the exact 1-based line of the failing block.
        error = {"message": gcode.strerror(result), "line": int(canon.line), "near_line": int(near),
                 "code": int(result)}
    out = dict(canon.cols)
    out["error"] = error
    out["lines_seen"] = canon.lines_seen
    out["ignored_calls"] = canon.calls
    if canon.trace is not None:
        out["trace"] = canon.trace
    return out


def _main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: %s PROGRAM.ngc TOOLS.tbl|- OUT.json\n" % argv[0])
        return 2
    program, table, out = argv[1:]
    table = None if table == "-" or not Path(table).read_text().strip() else table
    data = parse_program(program, table)
    Path(out).write_text(json.dumps(data))      # NaN is written as NaN (json reads it back)
    return 0


# =============================================================================================
# pytest side (project venv)

_AVAILABLE = None


def available() -> bool:
    """True when /usr/bin/python3 can import LinuxCNC's gcode module (checked once)."""
    global _AVAILABLE
    if _AVAILABLE is None:
        try:
            with tempfile.TemporaryDirectory(prefix="gcode_probe_") as home:
                proc = subprocess.run([SYSTEM_PYTHON, "-c", "import gcode"], capture_output=True,
                                      timeout=30, env=dict(os.environ, HOME=home),
                                      stdin=subprocess.DEVNULL, cwd=home)
            _AVAILABLE = proc.returncode == 0
        except (OSError, subprocess.SubprocessError):
            _AVAILABLE = False
    return _AVAILABLE


class GcodeModuleFailure(RuntimeError):
    """The oracle script itself failed (crash, timeout, Python exception), not the G-code."""


def run_gcode_module(program, tools=None, *, timeout: float = 60.0) -> dict:
    """Run ``program`` through the gcode module in a subprocess; return numpy columns in mm.

    ``tools``: metric LinuxCNC tool table path, or None. Each call gets its own HOME (tool mmap),
    var file and output file, so calls may run concurrently. Returns the columns listed in the
    module doc as numpy arrays, plus ``error`` (None or dict message/line/code), ``lines_seen``
    and ``ignored_calls``.
    """
    import numpy as np

    with tempfile.TemporaryDirectory(prefix="gcode_oracle_run_") as tmp:
        out = Path(tmp) / "out.json"
        table = str(Path(tools).resolve()) if tools is not None else "-"
        cmd = [SYSTEM_PYTHON, str(Path(__file__).resolve()), str(Path(program).resolve()), table,
               str(out)]
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
        env["HOME"] = tmp
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env,
                                  stdin=subprocess.DEVNULL, cwd=tmp)
        except subprocess.TimeoutExpired as e:
            raise GcodeModuleFailure("gcode oracle timed out after %ss on %s" % (timeout, program)) from e
        if proc.returncode != 0 or not out.exists():
            raise GcodeModuleFailure("gcode oracle failed on %s (rc=%d):\n%s"
                                     % (program, proc.returncode, proc.stderr[-3000:]))
        raw = json.loads(out.read_text())
    n = len(raw["kind"])
    vec = lambda k: np.array(raw[k], dtype=float).reshape(n, 3)  # noqa: E731
    return {
        "kind": np.array(raw["kind"], dtype=np.uint8),
        "line": np.array(raw["line"], dtype=np.int64),
        "end": vec("end"), "center": vec("center"),
        "turns": np.array(raw["turns"], dtype=np.int64),
        "abc": vec("abc"), "tool_offset": vec("tool_offset"),
        "feed": np.array(raw["feed"], dtype=float),
        "plane": np.array(raw["plane"], dtype=np.int64),
        "error": raw["error"],
        "lines_seen": raw["lines_seen"],
        "ignored_calls": raw["ignored_calls"],
    }


if __name__ == "__main__":
    sys.exit(_main(sys.argv))
