"""Seeded random LinuxCNC programs that exercise cutter radius compensation (G40/G41/G42/G41.1/G42.1).

    python tests/oracle/generate_comp.py SEED [COUNT] [OUTDIR]   # writes comp_<seed>.ngc files

Deterministic: the same seed gives the same text (random.Random(seed), no global state). Every
program uses the tool table tests/programs/comp/tools.tbl (metric; random-looking diameters incl.
0 and negative ones, lathe inserts with Q1..Q9) and only plain words (no #parameters, O-words).

What a program contains (all syntactically valid; LinuxCNC may still reject it, e.g. gouges):

* G21 (most) or G20; plane G17, or G18 (a = Z, b = X, third axis Y) with lathe orientations from
  ``G41.1/G42.1 ... L1..L9`` or from the table's Q (G41/G42 Dn with tools 11..20);
* optionally ``T n M6`` + ``G43`` before any motion (tool length offset column, G41 without D);
* one to three compensated sections: comp on (G41/G42 Dn from the table, G41.1/G42.1 with a random
  diameter incl. 0 and negative, sometimes in the same block as the entry move), an entry move
  (straight G0/G1 or an arc), a body of lines, rapids, G2/G3 arcs in IJK and R form (the end always
  lies on the circle: I/J are computed from a chosen centre), helices, P-turn arcs, full circles,
  third-axis-only moves, M8/M9/M3/M5/G4 P0.1/F/S/comments, G90/G91 switches, A-axis words,
  tiny segments and 180-degree reversals, then ``G40`` and a straight exit move (or M2 with comp
  still on);
* ``grid`` programs (about 40 %) use only axis-parallel lines and quarter/half arcs whose centres
  sit on axis-parallel offsets, so tangent joints, 90-degree corners and reversals are exact in
  decimal; the others use random directions, with a good fraction of arcs and lines started
  exactly tangent (to 4 decimals) to the previous element;
* rarely, something LinuxCNC forbids under compensation (M6, G43, G54, plane change, G41 when on,
  canned cycle, arc right after G40, D not in the table, non-integer D ...).

Geometry is generated in comp-plane coordinates (a, b, h): G17 (X, Y, Z), G18 (Z, X, Y). The
generator tracks the *programmed* point exactly as the interpreter does (absolute words parsed,
incremental words added to the previous programmed point), which is what LinuxCNC resolves G91 and
omitted axes against while compensation is on, and after G40.
"""
from __future__ import annotations

import math
import random
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TOOLS_TABLE = ROOT / "tests" / "programs" / "comp" / "tools.tbl"

MM_TOL_ABS = 2 * 0.01 * math.sqrt(2)        # CENTER_ARC_RADIUS_TOLERANCE_MM default
INCH_TOL_ABS = 2 * 0.001 * math.sqrt(2)     # ..._INCH default
QUARTERS = ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))


def read_table(path: Path = TOOLS_TABLE) -> dict:
    """tool number -> (diameter mm, orientation Q) of a LinuxCNC .tbl file."""
    tools = {}
    for line in Path(path).read_text().splitlines():
        body = line.split(";")[0].split()
        words = {w[0].upper(): w[1:] for w in body if len(w) > 1}
        if "T" in words:
            tools[int(words["T"])] = (float(words.get("D", 0)), int(float(words.get("Q", 0))))
    return tools


def _f(v: float) -> str:
    s = "%.4f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "", "-") else s


class _Gen:
    def __init__(self, seed: int):
        self.rnd = rnd = random.Random(seed)
        self.tools = read_table()
        self.inch = rnd.random() < 0.15
        self.k = 1 / 25.4 if self.inch else 1.0            # program units per mm
        self.tol_abs = INCH_TOL_ABS if self.inch else MM_TOL_ABS
        self.plane = 18 if rnd.random() < 0.35 else 17
        self.grid = rnd.random() < 0.4
        self.quantum = 0.05 if self.inch else 0.5      # grid programs: lengths and radii multiples
        if self.plane == 17:
            self.L, self.O = ("X", "Y", "Z"), ("I", "J")
        else:
            self.L, self.O = ("Z", "X", "Y"), ("K", "I")
        self.P = [0.0, 0.0, 0.0]         # programmed point (a, b, h), as the interpreter holds it
        self.exact = True                # P equals the value of its own 4-decimal text
        self.inc = False
        self.tan = None                  # end tangent angle of the last plane move (programmed path)
        self.tanq = None                 # ... as a quarter index 0..3 in grid programs
        self.comp = False
        self.spindle_tool = 0
        self.r_mm = 0.0                  # rough comp radius of the section (sizes the geometry)
        self.lines: list[str] = []
        self.pending: list[str] = []     # words to put in front of the next motion block

    # -- helpers -----------------------------------------------------------------------------------
    def u(self, lo, hi):
        """Random length in program units (range in mm)."""
        return self.rnd.uniform(lo, hi) * self.k

    def emit(self, s):
        if self.pending:
            s = " ".join(self.pending + [s])
            self.pending = []
        self.lines.append(s)

    def flush_pending(self):
        if self.pending:
            self.lines.append(" ".join(self.pending))
            self.pending = []

    def set_inc(self, inc: bool, inline: bool = True):
        if inc != self.inc:
            code = "G91" if inc else "G90"
            if inline and self.rnd.random() < 0.5:
                self.pending.append(code)
            else:
                self.emit(code)
            self.inc = inc

    def words(self, target, axes, omit_same=True):
        """Axis words for target (a, b, h) on ``axes``; returns (words, new programmed point)."""
        new = list(self.P)
        out, every = [], []
        for i in axes:
            if self.inc:
                w = _f(target[i] - self.P[i])
                new[i] = self.P[i] + float(w)
                same = w == "0"
            else:
                w = _f(target[i])
                new[i] = float(w)
                same = new[i] == self.P[i]
            every.append(self.L[i] + w)
            if same and omit_same and self.rnd.random() < 0.6:
                continue
            out.append(self.L[i] + w)
        # never drop every word (an omitted G90 word equals P exactly, so re-adding one is the same)
        return (out or every[:1]), new

    def land(self, new, axes):
        self.exact = all(float(_f(v)) == v for v in new)
        self.P = new

    def dir_angle(self, mode="random"):
        """A direction: tangent to the previous element, reversed, or random."""
        if self.grid:
            if mode == "tangent" and self.tanq is not None:
                q = self.tanq
            elif mode == "reverse" and self.tanq is not None:
                q = (self.tanq + 2) % 4
            else:
                q = self.rnd.randrange(4)
            return q * math.pi / 2, q
        if mode == "tangent" and self.tan is not None:
            return self.tan, None
        if mode == "reverse" and self.tan is not None:
            return self.tan + math.pi, None
        if mode == "near" and self.tan is not None:       # small turns around the 0.05 rad threshold
            return self.tan + self.rnd.choice((-1, 1)) * self.rnd.choice((0.02, 0.04, 0.07, 0.1)), None
        return self.rnd.uniform(-math.pi, math.pi), None

    # -- blocks ------------------------------------------------------------------------------------
    def line(self, code="G1", mode=None, length=None, extra=()):
        if mode is None:
            x = self.rnd.random()
            mode = "tangent" if x < 0.25 else "reverse" if x < 0.32 else "near" if x < 0.37 else "random"
        ang, q = self.dir_angle(mode)
        if length is None:
            x = self.rnd.random()
            if x < 0.04:
                length = self.u(0.001, 0.05)             # tiny segment
            elif x < 0.2:
                length = self.u(0.3, 3)
            else:
                length = self.u(2, 40)
        if self.grid:
            length = max(round(length / self.quantum) * self.quantum, self.quantum)
            dx, dy = QUARTERS[q]
            target = [self.P[0] + length * dx, self.P[1] + length * dy, self.P[2]]
        else:
            target = [self.P[0] + length * math.cos(ang), self.P[1] + length * math.sin(ang), self.P[2]]
        axes = (0, 1)
        if self.rnd.random() < 0.1:
            target[2] = self.P[2] + self.u(-3, 3)
            axes = (0, 1, 2)
        w, new = self.words(target, axes)
        if new[0] != self.P[0] or new[1] != self.P[1]:      # else no plane motion: keep the tangent
            self.tan = math.atan2(new[1] - self.P[1], new[0] - self.P[0])
            self.tanq = q
        self.emit(" ".join([code] + w + list(extra) + self.abc_words()))
        self.land(new, axes)

    def abc_words(self):
        if not self.inc and self.rnd.random() < 0.05:
            return ["A" + _f(self.rnd.uniform(-90, 90))]
        return []

    def arc(self, mode=None, entry=False):
        """G2/G3 from P; returns False if no valid arc was found (nothing emitted)."""
        rnd = self.rnd
        if mode is None:
            x = rnd.random()
            mode = "tangent" if x < 0.5 else "reverse" if x < 0.55 else "random"
        for _ in range(20):
            cw = rnd.random() < 0.5
            ang, q = self.dir_angle(mode)             # start tangent
            x = rnd.random()
            rr = self.r_mm
            if x < 0.04 and rr > 0 and not entry:
                R = self.u(0.3, 1.5) * max(rr, 0.5)         # near or below the comp radius
            elif x < 0.14 and not entry:
                R = self.u(0.5, 5)
            elif x < 0.4:
                R = self.u(1.2 * rr + 0.5, 1.2 * rr + 5)
            else:
                R = self.u(rr + 3, rr + 35)
            full = not entry and rnd.random() < 0.04
            turns = rnd.randint(2, 3) if (not entry and rnd.random() < 0.04) else 1
            use_r = not full and turns == 1 and rnd.random() < 0.35
            if self.grid:
                R = max(round(R / self.quantum) * self.quantum, self.quantum)
                k = rnd.choice((1, 1, 2, 3)) if not use_r else 1
                sweep = 2 * math.pi if full else k * math.pi / 2
                tq = q
                nq = (tq + (3 if cw else 1)) % 4                  # direction start -> centre
                cx, cy = QUARTERS[nq]
                c = [self.P[0] + R * cx, self.P[1] + R * cy]
                sq = (nq + 2) % 4                                  # centre -> start
                eq = (sq + (-k if cw else k)) % 4                  # centre -> end
                ex, ey = QUARTERS[eq]
                end = [c[0] + R * ex, c[1] + R * ey]
                end_tq = (eq + (3 if cw else 1)) % 4
            else:
                if use_r:
                    sweep = rnd.uniform(math.radians(15), math.radians(160)) if rnd.random() < 0.7 \
                        else rnd.uniform(math.radians(200), math.radians(345))
                elif full:
                    sweep = 2 * math.pi
                else:
                    sweep = rnd.uniform(math.radians(3), math.radians(350))
                n = ang - math.pi / 2 if cw else ang + math.pi / 2
                c = [self.P[0] + R * math.cos(n), self.P[1] + R * math.sin(n)]
                th0 = n + math.pi
                th1 = th0 - sweep if cw else th0 + sweep
                end = [c[0] + R * math.cos(th1), c[1] + R * math.sin(th1)]
                end_tq = None
            target = [end[0], end[1], self.P[2]]
            axes = [0, 1]
            if rnd.random() < 0.15:
                target[2] = self.P[2] + self.u(-5, 5)            # helix
                axes.append(2)
            if full:
                w, new = [], list(self.P)
                if 2 in axes:
                    w, new = self.words(target, (2,), omit_same=False)
            else:
                w, new = self.words(target, axes)
            if not full and new[0] == self.P[0] and new[1] == self.P[1]:
                continue
            if use_r:
                Rw = _f(-R if sweep > math.pi else R)
                half = math.hypot(new[0] - self.P[0], new[1] - self.P[1]) / 2
                if float(Rw) == 0 or half > abs(float(Rw)) * 0.999:
                    continue
                if not any(l[0] in self.L[:2] for l in w):
                    continue                                     # R format needs a plane word
                extra = ["R" + Rw]
            else:
                iw, jw = _f(c[0] - self.P[0]), _f(c[1] - self.P[1])
                cc = (self.P[0] + float(iw), self.P[1] + float(jw))
                r1 = math.hypot(cc[0] - self.P[0], cc[1] - self.P[1])
                r2 = math.hypot(cc[0] - new[0], cc[1] - new[1])
                if r1 < 0.01 or abs(r1 - r2) > self.tol_abs / 2 or abs(r1 - r2) / max(r1, r2) > 0.0005:
                    continue
                extra = [self.O[0] + iw, self.O[1] + jw]
                if turns > 1:
                    extra.append("P%d" % turns)
            code = "G2" if cw else "G3"
            self.emit(" ".join([code] + w + extra + self.abc_words()))
            if self.grid:
                self.tanq = end_tq
                self.tan = end_tq * math.pi / 2
            else:
                # end tangent of the programmed arc (about the centre the interpreter will use)
                if use_r:
                    ce = c
                else:
                    ce = cc
                th = math.atan2(new[1] - ce[1], new[0] - ce[0])
                self.tan = th - math.pi / 2 if cw else th + math.pi / 2
                self.tanq = None
            self.land(new, axes)
            return True
        return False

    def h_only(self):
        code = "G0" if self.rnd.random() < 0.3 else "G1"
        target = list(self.P)
        target[2] = self.P[2] + self.u(-4, 4)
        w, new = self.words(target, (2,), omit_same=False)
        self.emit(" ".join([code] + w))
        self.land(new, (2,))

    def misc(self):
        x = self.rnd.random()
        if x < 0.2:
            self.emit("M8")
        elif x < 0.35:
            self.emit("M9")
        elif x < 0.5:
            self.emit("G4 P0.1")
        elif x < 0.6:
            self.emit("M3 S%d" % self.rnd.randint(500, 12000))
        elif x < 0.65:
            self.emit("M5")
        elif x < 0.85:
            self.emit("F" + _f(self.u(50, 2000)))
        elif x < 0.95:
            self.emit("(just a comment)")
        else:
            self.emit("S%d" % self.rnd.randint(500, 12000))

    def forbidden(self):
        """Something LinuxCNC refuses while compensation is on (rare)."""
        other = 19 if self.rnd.random() < 0.3 else (18 if self.plane == 17 else 17)
        choice = self.rnd.choice((
            "T2 M6", "G43 H1", "G49", "G55", "G92 X0", "G%d" % other, "G41.1 D2", "G42 D1",
            "G61", "G64", "G98", "G28", "G81 X1 Y1 Z-1 R1", "G53 G0 X0", "G38.2 Z-50 F100",
            "M48", "M62 P0",
        ))
        if self.plane == 18 and choice.startswith("G81"):
            choice = "G81 X1 Z1 Y-1 R1"
        self.emit(choice)

    def comp_on(self, inline_ok=True):
        rnd = self.rnd
        x = rnd.random()
        side = rnd.choice(("41", "42"))
        lathe = [t for t, (d, q) in self.tools.items() if q not in (0, 9)]
        mill = [t for t, (d, q) in self.tools.items() if q in (0, 9)]
        if x < 0.45:                                       # G41.1/G42.1 D<diameter>
            y = rnd.random()
            if y < 0.05:
                dia = 0.0
            elif y < 0.55:
                dia = rnd.uniform(0.2, 4)
            elif y < 0.85:
                dia = rnd.uniform(4, 16)
            else:
                dia = -rnd.uniform(0.2, 10)
            dw = _f(dia * self.k)
            word = "G%s.1 D%s" % (side, dw)
            self.r_mm = abs(float(dw)) / 2 / self.k
            if self.plane == 18 and rnd.random() < 0.6:
                word += " L%d" % rnd.randint(1, 9)
            elif self.plane == 17 and rnd.random() < 0.01:
                word += " L3"                               # error: L needs G18
        else:
            y = rnd.random()
            if y < 0.02:
                word = "G%s D99" % side                     # not in the table
            elif y < 0.03:
                word = "G%s D1.5" % side                    # not a whole number
            elif y < 0.06 and self.spindle_tool:
                word = "G%s" % side                         # spindle tool
            else:
                pool = lathe if (self.plane == 18 and rnd.random() < 0.6) else mill
                if self.plane == 17 and rnd.random() < 0.02:
                    pool = lathe                            # error: lathe tool in G17
                t = rnd.choice(pool)
                word = "G%s D%d" % (side, t)
            m = re.search(r"D(\d+)$", word)
            t = int(m.group(1)) if m else self.spindle_tool
            self.r_mm = abs(self.tools.get(t, (0.0, 0))[0]) / 2
        if inline_ok and rnd.random() < 0.25:
            self.pending.append(word)
        else:
            self.emit(word)
        self.comp = True

    def entry(self):
        rnd = self.rnd
        self.set_inc(rnd.random() < 0.2)
        if rnd.random() < 0.25:
            if self.arc(mode="random", entry=True):
                return
        x = rnd.random()
        r = max(self.r_mm, 0.1) * self.k
        if x < 0.05:
            length = r * rnd.uniform(0.3, 1.0)                 # too short: error
        else:
            length = r * rnd.uniform(1.2, 3) + self.u(1, 20)
        self.line("G0" if rnd.random() < 0.2 else "G1", mode="random", length=length)

    def body(self):
        rnd = self.rnd
        for _ in range(rnd.randint(1, 14)):
            x = rnd.random()
            if rnd.random() < 0.08:
                self.set_inc(not self.inc)
            if x < 0.36:
                self.line()
            elif x < 0.42:
                self.line("G0")
            elif x < 0.78:
                if not self.arc():
                    self.line()
            elif x < 0.85:
                self.h_only()
            elif x < 0.97:
                self.misc()
            elif x < 0.98:
                self.forbidden()
            else:
                self.line(mode="reverse")

    def exit(self):
        rnd = self.rnd
        if rnd.random() < 0.015:
            self.emit("G40")
            self.comp = False
            self.arc(mode="random")                              # error: arc right after G40
            return
        if rnd.random() < 0.3:
            self.pending.append("G40")
        else:
            self.emit("G40")
        self.comp = False
        self.line("G0" if rnd.random() < 0.4 else "G1", mode="random", length=self.u(2, 30))

    def program(self) -> str:
        rnd = self.rnd
        self.emit("%s G%d G90 G94 G40 G49" % ("G20" if self.inch else "G21", self.plane))
        if rnd.random() < 0.3:
            t = rnd.choice(sorted(self.tools))
            self.emit("T%d M6" % t)
            self.emit("G43")
            self.spindle_tool = t
        start = [self.u(-50, 50), self.u(-50, 50), self.u(0, 20)]
        w, new = self.words(start, (0, 1, 2), omit_same=False)
        self.emit("G0 " + " ".join(sorted(w, key=lambda s: "XYZ".index(s[0]))))
        self.land(new, (0, 1, 2))
        self.emit("F" + _f(self.u(100, 1500)))
        if rnd.random() < 0.5:
            self.h_only()
        for sec in range(rnd.choice((1, 1, 1, 2, 2, 3))):
            if sec:
                self.set_inc(False, inline=False)
                self.line("G0", mode="random", length=self.u(5, 30))
            self.tan = self.tanq = None
            self.comp_on()
            self.entry()
            self.body()
            if sec == 0 or rnd.random() < 0.9:
                if rnd.random() < 0.1:
                    break                                    # M2 with comp still on
                self.exit()
        self.flush_pending()
        self.emit("M2")
        return "\n".join(self.lines) + "\n"


def generate(seed: int) -> str:
    """Program text for ``seed`` (deterministic)."""
    return _Gen(seed).program()


if __name__ == "__main__":
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 0
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    out = Path(sys.argv[3]) if len(sys.argv) > 3 else Path(".")
    out.mkdir(parents=True, exist_ok=True)
    for s in range(seed, seed + count):
        (out / ("comp_%d.ngc" % s)).write_text(generate(s))
