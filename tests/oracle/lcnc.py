"""Run LinuxCNC's standalone interpreter ``rs274`` as a test oracle and parse its output.

Only used by the oracle tests; needs Debian's ``linuxcnc-uspace`` (``/usr/bin/rs274``).
Measured against linuxcnc-uspace 2.9.0~pre1+git20230208 (Debian 12).

What this module handles (see /work/shared/research/linuxcnc-oracle.md):

* every run gets its own temporary ``HOME`` (rs274 truncates and mmaps ``$HOME/.tool.mmap``;
  concurrent runs sharing it corrupt each other) and a throw-away ``.var`` file (rs274 rewrites it);
* this build always reads the tool table as **inches** (LinuxCNC issue #1279), so metric ``.tbl``
  files are converted to inches before the run (:func:`mm_table_to_inch`);
* a timeout, and ``-g`` batch mode (no interactive menu).

Quirks of standalone rs274 that oracle programs avoid (they are artefacts of its printing canon,
not LinuxCNC behaviour):

* ``G43`` in the same block as ``M6``: after a tool change rs274 re-reads the current position from
  its canon, which ignores the new offset, so the next move's unprogrammed Z is the old program Z
  instead of being re-expressed (put G43 on its own line);
* ``M61 Qn`` followed by ``G43`` without H uses the previous spindle tool's data (use ``G43 Hn``);
* ``G43.2`` with axis words is not supported by this build (error "Requested tool -1 not found");
* the block-delete switch is off by default (``/`` lines are executed; ``block_delete=True`` sets ``-b``).

:func:`parse_canon` turns rs274's canonical-call text into numpy arrays in **millimetres**.
rs274 prints ``%.4f`` in the program's current units (``USE_LENGTH_UNITS``): inch values are
multiplied by 25.4, so compare with a tolerance of 6e-5 *program units*.

Columns (N moves; one row per STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED):

``kind``   uint8  0 rapid (STRAIGHT_TRAVERSE), 1 line (STRAIGHT_FEED), 2 arc cw (turn<0), 3 arc ccw (turn>0)
``start``  (N,3)  program X,Y,Z at the start of the move, mm (derived: the previous end, re-expressed after
                  every offset change because the machine does not move when G5x/G92/TLO/rotation change)
``end``    (N,3)  program X,Y,Z, mm; ARC_FEED's plane order is remapped: G17 (X,Y,Z), G18 (Z,X,Y),
                  G19 (Y,Z,X) -> always (X,Y,Z)
``center`` (N,3)  arc centre, mm; NaN for lines/rapids. The centre's coordinate along the plane's normal
                  axis (Z in G17, Y in G18, X in G19) is set to the **start's** coordinate on that axis
                  (rs274 has no such value; comparisons only use the two in-plane components).
``turns``  int32  ARC_FEED ``turn``: +-1 for an arc (or one full circle), +-(n) with P=n; 0 for lines
``abc``    (N,3)  A,B,C at the end, degrees
``tool_offset`` (N,3) active USE_TOOL_LENGTH_OFFSET x,y,z, mm
``feed``   float  active SET_FEED_RATE converted to mm/min; NaN for rapids
``plane``  int8   17, 18 or 19 (active SELECT_PLANE)
``units``  float  1.0 for mm program units at the move, 25.4 for inch (the factor that was applied)
"""
from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

RS274 = shutil.which("rs274") or "/usr/bin/rs274"
MM_PER_INCH = 25.4
PRINT_TOL = 6e-5  # rs274 prints %.4f: half a unit of the last digit plus rounding of the inputs

RAPID, LINE, ARC_CW, ARC_CCW = 0, 1, 2, 3

_PLANES = {"CANON_PLANE_XY": 17, "CANON_PLANE_XZ": 18, "CANON_PLANE_YZ": 19}
# "   8 N1006941SET_FEED_RATE(100.0000)": rs274 pads the N field to six characters, and a
# longer block number runs into the call's name.
_CALL = re.compile(r"^\s*\d+\s+N(?:\.+|\d+)\s*([A-Z_][A-Z_0-9]*)\((.*)\)\s*$")


def available() -> bool:
    """True when rs274 can be run here."""
    return os.path.isfile(RS274) and os.access(RS274, os.X_OK)


def version() -> str:
    """Installed linuxcnc-uspace package version (for test metadata), or ''."""
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "linuxcnc-uspace"],
                             capture_output=True, text=True, timeout=10)
        return out.stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


# ---------------------------------------------------------------------------------------------
# tool tables

_LENGTH_LETTERS = set("XYZUVWD")  # A B C are angles; I J (angles) and Q (orientation) unchanged


def mm_table_to_inch(text: str) -> str:
    """Rewrite a metric LinuxCNC tool table in inches (X Y Z U V W offsets and D diameter / 25.4)."""
    out = []
    for line in text.splitlines():
        body, sep, comment = line.partition(";")
        toks = []
        for tok in body.split():
            if tok[0].upper() in _LENGTH_LETTERS and len(tok) > 1:
                tok = "%s%.12f" % (tok[0].upper(), float(tok[1:]) / MM_PER_INCH)
            toks.append(tok)
        if toks:
            out.append(" ".join(toks) + (" ;" + comment.strip() if sep else ""))
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------------------------
# running rs274

@dataclass
class Rs274Run:
    returncode: int
    canon: str           # stdout: one canonical call per line
    stderr: str          # without the 'executing' line
    program: Path

    @property
    def ok(self) -> bool:
        return self.returncode == 0


def run(program, tools=None, *, tools_in_mm: bool = True, block_delete: bool = False,
        timeout: float = 60.0) -> Rs274Run:
    """Run rs274 on ``program`` with the tool table ``tools`` (metric unless tools_in_mm=False).

    Each call uses a private HOME and var file, so calls may run concurrently.
    """
    program = Path(program).resolve()
    with tempfile.TemporaryDirectory(prefix="lcnc_") as tmp:
        tmp = Path(tmp)
        tbl = tmp / "tool.tbl"
        if tools is None:
            tbl.write_text("")
        else:
            text = Path(tools).read_text()
            tbl.write_text(mm_table_to_inch(text) if tools_in_mm else text)
        var = tmp / "rs274.var"
        var.write_text("")
        out = tmp / "canon.txt"
        cmd = [RS274, "-g"] + (["-b"] if block_delete else []) + \
              ["-t", str(tbl), "-v", str(var), str(program), str(out)]
        env = dict(os.environ, HOME=str(tmp))
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout,
                              env=env, stdin=subprocess.DEVNULL, cwd=str(tmp))
        canon = out.read_text() if out.exists() else ""
    err = "\n".join(l for l in proc.stderr.splitlines() if l.strip() != "executing")
    return Rs274Run(proc.returncode, canon, err, program)


# ---------------------------------------------------------------------------------------------
# errors

@dataclass
class Rs274Error:
    message: str     # exact interpreter message
    source: str      # offending block text as rs274 printed it
    line: int        # 1-based line of that text in the program (0 if not found uniquely)


def error_of(result: Rs274Run) -> Rs274Error | None:
    """The interpreter error of a failed run (rs274 exits 1 and prints message + block text)."""
    if result.returncode == 0:
        return None
    lines = [l for l in result.stderr.splitlines() if l.strip()]
    if not lines:
        return Rs274Error("", "", 0)
    if len(lines) == 1:
        message, source = lines[0], ""
    else:  # upstream tests/interp/bad: message = second-to-last line, then the block text
        message, source = lines[-2], lines[-1]
    return Rs274Error(message.strip(), source, find_line(result.program, source))


def find_line(program, source: str) -> int:
    """1-based line number of ``source`` in ``program``: rs274 prints the block text, not its number.

    Returns 0 if the text is absent or appears more than once (error programs are written so that
    the offending block is unique).
    """
    want = source.strip()
    if not want:
        return 0
    hits = [i + 1 for i, l in enumerate(Path(program).read_text().splitlines()) if l.strip() == want]
    return hits[0] if len(hits) == 1 else 0


def run_error(program, tools=None, **kw) -> Rs274Error | None:
    """Run and return the error (None when the program ran cleanly)."""
    return error_of(run(program, tools, **kw))


# ---------------------------------------------------------------------------------------------
# parsing canonical output

def _floats(args: str):
    return [float(t) for t in args.replace(",", " ").split()]


@dataclass
class _State:
    scale: float = 1.0                                    # mm per program unit
    plane: int = 17
    feed: float = 0.0                                     # as programmed, mm/min or mm/rev
    per_rev: bool = False                                 # G95: SET_FEED_MODE(0, 1)
    speed: float = 0.0                                    # SET_SPINDLE_SPEED: rev/min (G96: surface speed)
    css: bool = False                                     # G96: SET_SPINDLE_MODE(0 max) with max > 0
    tlo: np.ndarray = field(default_factory=lambda: np.zeros(3))
    g5x: np.ndarray = field(default_factory=lambda: np.zeros(3))
    g92: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rot: float = 0.0                                      # degrees
    pos: np.ndarray = field(default_factory=lambda: np.zeros(3))   # program coords, mm
    sync: float = np.nan                                  # START_SPEED_FEED_SYNC lead, mm/rev (NaN: none)

    def feed_now(self):
        """The feed in mm/min, as toolcomp's column has it: per revolution (G95, or the lead of
        a spindle-synchronised move) times the spindle's speed; under constant surface speed the
        speed follows X: NaN, not compared."""
        if not np.isnan(self.sync):
            return np.nan if self.css else self.sync * self.speed
        if not self.per_rev:
            return self.feed
        return np.nan if self.css else self.feed * self.speed

    def to_machine(self, p):
        c, s = math.cos(math.radians(self.rot)), math.sin(math.radians(self.rot))
        q = p + self.g92
        return np.array([c * q[0] - s * q[1], s * q[0] + c * q[1], q[2]]) + self.g5x + self.tlo

    def to_program(self, m):
        c, s = math.cos(math.radians(self.rot)), math.sin(math.radians(self.rot))
        q = m - self.g5x - self.tlo
        return np.array([c * q[0] + s * q[1], -s * q[0] + c * q[1], q[2]]) - self.g92


def _plane_to_xyz(plane, first, second, axis):
    if plane == 17:
        return first, second, axis
    if plane == 18:          # ARC_FEED(z, x, cz, cx, turn, y)
        return second, axis, first
    return axis, first, second  # G19: ARC_FEED(y, z, cy, cz, turn, x)


def parse_canon(text: str) -> dict:
    """Parse rs274 canonical output into numpy columns in millimetres (see module doc)."""
    st = _State()
    rows = []  # kind, start3, end3, center3, turns, abc3, tlo3, feed, plane, scale
    feed_tol = []  # per row: how well the feed is known (a printed lead: 5e-7 units per rev)
    probes = []    # where each STRAIGHT_PROBE stopped (program coordinates, mm)
    for raw in text.splitlines():
        m = _CALL.match(raw)
        if not m:
            continue
        name, args = m.groups()
        if name == "USE_LENGTH_UNITS":
            st.scale = MM_PER_INCH if "INCHES" in args else 1.0
        elif name == "SELECT_PLANE":
            st.plane = _PLANES.get(args.strip(), st.plane)
        elif name == "SET_FEED_RATE":
            st.feed = _floats(args)[0] * st.scale
        elif name == "SET_FEED_MODE":
            st.per_rev = _floats(args)[1] == 1
        elif name == "START_SPEED_FEED_SYNC":   # (lead, velocity mode); rs274 drops the H
            synced = 0.0 if np.isnan(st.sync) else 5e-7 * st.scale * st.speed + 1e-9
            feed_tol += [synced] * (len(rows) - len(feed_tol))
            st.sync = _floats(args)[0] * st.scale
        elif name == "STOP_SPEED_FEED_SYNCH":
            # the rows made while synchronised: their feed from a lead printed to 1e-6
            feed_tol += [5e-7 * st.scale * st.speed + 1e-9] * (len(rows) - len(feed_tol))
            st.sync = np.nan
        elif name == "RIGID_TAP":               # in to the point and back out (the position stays)
            end = np.array(_floats(args)[:3]) * st.scale
            abc = rows[-1][5] if rows else np.zeros(3)
            for a, b in ((st.pos, end), (end, st.pos.copy())):
                rows.append((LINE, a.copy(), b.copy(), np.full(3, np.nan), 0, abc,
                             st.tlo.copy(), st.feed_now(), st.plane, st.scale))
        elif name == "SET_SPINDLE_SPEED":
            st.speed = _floats(args)[1]
        elif name == "SET_SPINDLE_MODE":
            st.css = float(args.split()[-1]) > 0
        elif name in ("USE_TOOL_LENGTH_OFFSET", "SET_G5X_OFFSET", "SET_G92_OFFSET", "SET_XY_ROTATION"):
            machine = st.to_machine(st.pos)
            v = _floats(args)
            if name == "USE_TOOL_LENGTH_OFFSET":
                st.tlo = np.array(v[:3]) * st.scale
            elif name == "SET_G5X_OFFSET":
                st.g5x = np.array(v[1:4]) * st.scale
            elif name == "SET_G92_OFFSET":
                st.g92 = np.array(v[:3]) * st.scale
            else:
                st.rot = v[0]
            st.pos = st.to_program(machine)
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "STRAIGHT_PROBE"):
            v = _floats(args)
            end = np.array(v[:3]) * st.scale
            if name == "STRAIGHT_PROBE":
                # rs274's canon stops the probe 0.254 mm (0.01 in) short of its target, back
                # towards the start; the next move begins there. The row ends where the probe
                # stopped, and that point is the run's probe result (run(probes=...)).
                d = np.linalg.norm(end - st.pos)
                if d > 0:
                    end = end + 0.254 * (st.pos - end) / d
                probes.append(tuple(end))
            kind = RAPID if name == "STRAIGHT_TRAVERSE" else LINE
            rows.append((kind, st.pos.copy(), end, np.full(3, np.nan), 0, np.array(v[3:6]),
                         st.tlo.copy(), np.nan if kind == RAPID else st.feed_now(), st.plane, st.scale))
            st.pos = end
        elif name == "ARC_FEED":
            v = _floats(args)
            e1, e2, c1, c2 = (x * st.scale for x in v[:4])
            turn = int(round(v[4]))
            ax = v[5] * st.scale
            end = np.array(_plane_to_xyz(st.plane, e1, e2, ax))
            normal = {17: 2, 18: 1, 19: 0}[st.plane]
            center = np.array(_plane_to_xyz(st.plane, c1, c2, 0.0))
            center[normal] = st.pos[normal]
            rows.append((ARC_CW if turn < 0 else ARC_CCW, st.pos.copy(), end, center, turn,
                         np.array(v[6:9]), st.tlo.copy(), st.feed_now(), st.plane, st.scale))
            st.pos = end
    n = len(rows)
    col = lambda i: [r[i] for r in rows]  # noqa: E731
    feed_tol += [0.0] * (n - len(feed_tol))
    vec = lambda i: np.array(col(i), dtype=float).reshape(n, 3)  # noqa: E731
    return {
        "kind": np.array(col(0), dtype=np.uint8),
        "start": vec(1), "end": vec(2), "center": vec(3),
        "turns": np.array(col(4), dtype=np.int32),
        "abc": vec(5), "tool_offset": vec(6),
        "feed": np.array(col(7), dtype=float),
        "plane": np.array(col(8), dtype=np.int8),
        "units": np.array(col(9), dtype=float),
        "feed_tol": np.array(feed_tol[:n], dtype=float),
        "probes": probes,
    }


def nominal(program, tools=None, **kw) -> dict:
    """Run rs274 and parse its moves; raises RuntimeError if rs274 reports an error."""
    res = run(program, tools, **kw)
    if res.returncode != 0:
        e = error_of(res)
        raise RuntimeError("rs274 failed on %s: %s [%s] (rc=%d)"
                           % (program, e.message if e else "", e.source if e else "", res.returncode))
    return parse_canon(res.canon)


# ---------------------------------------------------------------------------------------------
# arc geometry helpers shared by the comparisons

_PLANE_AXES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}  # (first, second, normal)


def plane_axes(plane: int):
    return _PLANE_AXES[int(plane)]


def sweep(start, end, center, cw: bool, plane: int, turns: int = 1, tol: float = 1e-9) -> float:
    """Swept angle (radians, > 0) of an arc; start == end counts as one full circle.

    ``turns`` is rs274's |turn|: each count beyond the first adds a full revolution.
    """
    a, b, _ = plane_axes(plane)
    a0 = math.atan2(start[b] - center[b], start[a] - center[a])
    a1 = math.atan2(end[b] - center[b], end[a] - center[a])
    d = (a0 - a1) if cw else (a1 - a0)
    d %= 2 * math.pi
    r = math.hypot(start[a] - center[a], start[b] - center[b])
    if d * max(r, 1.0) <= tol:
        d = 2 * math.pi
    return d + 2 * math.pi * (max(abs(int(turns)), 1) - 1)
