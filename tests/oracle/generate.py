"""Seeded random G-code programs within toolcomp's foundation scope (LinuxCNC dialect).

    python tests/oracle/generate.py SEED [COUNT] [OUTDIR]     # writes gen_<seed>.ngc files

Deterministic: the same seed gives the same text (random.Random(seed), no global state).
Programs use only plain words (no #parameters, expressions or O-words) and the tool table
tests/programs/oracle/tools.tbl (tools 1, 2, 3, 4, 7). Content: G20 or G21, lines and rapids,
arcs in G17/G18/G19 in IJK and R form (R never near 180 degrees, where the sign choice is
ill-conditioned), helices, P turns, G91 segments, G92 / G10 L2 / G54-G56 offsets and tool length
changes (T M6, G43 Hn, G43.1, G43.2 Hn, G49). After every offset change the generator programs
an absolute G90 rapid in X, Y and Z, so it always knows the current program position exactly
(the position rs274 holds is re-expressed when offsets change).
"""
from __future__ import annotations

import math
import random
import sys
from pathlib import Path

TOOLS = (1, 2, 3, 4, 7)
PLANES = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}  # first, second, normal axis index
LETTER = "XYZ"
OFFSET_LETTER = "IJK"


def _f(v: float) -> str:
    s = "%.4f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


class _Gen:
    def __init__(self, seed: int):
        self.rnd = random.Random(seed)
        self.inch = self.rnd.random() < 0.2
        self.k = 1 / 25.4 if self.inch else 1.0          # program units per mm
        self.pos = [0.0, 0.0, 0.0]
        self.plane = 17
        self.incremental = False
        self.lines: list[str] = []

    def u(self, lo, hi):
        """Random length in program units (range given in mm), rounded to the printed 4 decimals."""
        return round(self.rnd.uniform(lo, hi) * self.k, 4)

    def emit(self, s):
        self.lines.append(s)

    def set_incremental(self, inc):
        if inc != self.incremental:
            self.emit("G91" if inc else "G90")
            self.incremental = inc

    def axis_words(self, target, axes):
        words = []
        for ax in axes:
            v = target[ax] - self.pos[ax] if self.incremental else target[ax]
            words.append(LETTER[ax] + _f(v))
        return words

    def land(self, target, axes):
        """Position after programming ``target`` on ``axes`` with 4-decimal words."""
        new = list(self.pos)
        for ax in axes:
            if self.incremental:
                new[ax] = self.pos[ax] + round(target[ax] - self.pos[ax], 4)
            else:
                new[ax] = round(target[ax], 4)
        return new

    # -- blocks ---------------------------------------------------------------------------------
    def absolute_rapid(self):
        self.set_incremental(False)
        t = [self.u(-60, 60), self.u(-60, 60), self.u(0, 40)]
        self.emit("G0 " + " ".join(self.axis_words(t, (0, 1, 2))))
        self.pos = self.land(t, (0, 1, 2))

    def move(self):
        self.set_incremental(self.rnd.random() < 0.3)
        axes = sorted(self.rnd.sample((0, 1, 2), self.rnd.randint(1, 3)))
        t = list(self.pos)
        for ax in axes:
            t[ax] = self.pos[ax] + self.u(-30, 30)
        code = "G0" if self.rnd.random() < 0.25 else "G1"
        words = self.axis_words(t, axes)
        if code == "G1" and self.rnd.random() < 0.2:
            words.append("F" + _f(self.u(50, 2000)))
        self.emit(" ".join([code] + words))
        self.pos = self.land(t, axes)

    def arc(self):
        if self.rnd.random() < 0.3:
            self.plane = self.rnd.choice((17, 18, 19))
            self.emit("G%d" % self.plane)
        self.set_incremental(self.rnd.random() < 0.3)
        a, b, n = PLANES[self.plane]
        r = self.u(2, 30)
        th0 = self.rnd.uniform(0, 2 * math.pi)
        cw = self.rnd.random() < 0.5
        use_r = self.rnd.random() < 0.35
        while True:
            s = self.rnd.uniform(math.radians(10), math.radians(350))
            if not (use_r and abs(s - math.pi) < math.radians(15)):
                break
        ca = self.pos[a] - r * math.cos(th0)
        cb = self.pos[b] - r * math.sin(th0)
        th1 = th0 - s if cw else th0 + s
        target = list(self.pos)
        target[a] = ca + r * math.cos(th1)
        target[b] = cb + r * math.sin(th1)
        helix = self.rnd.random() < 0.25
        axes = [a, b] + ([n] if helix else [])
        if helix:
            target[n] = self.pos[n] + self.u(-10, 10)
        words = ["G2" if cw else "G3"] + self.axis_words(target, sorted(axes))
        if use_r:
            words.append("R" + _f(-r if s > math.pi else r))
        else:
            words.append(OFFSET_LETTER[a] + _f(ca - self.pos[a]))
            words.append(OFFSET_LETTER[b] + _f(cb - self.pos[b]))
        if self.rnd.random() < 0.1:
            words.append("P%d" % self.rnd.randint(2, 3))
        self.emit(" ".join(words))
        self.pos = self.land(target, axes)

    def offsets(self):
        choice = self.rnd.random()
        if choice < 0.3:
            self.emit("G92 X%s Y%s" % (_f(self.u(-20, 20)), _f(self.u(-20, 20))))
        elif choice < 0.45:
            self.emit(self.rnd.choice(("G92.1", "G92.2", "G92.3")))
        elif choice < 0.75:
            p = self.rnd.randint(1, 3)
            self.emit("G10 L2 P%d X%s Y%s Z%s" % (p, _f(self.u(-50, 50)), _f(self.u(-50, 50)),
                                                 _f(self.u(-20, 20))))
        else:
            self.emit(self.rnd.choice(("G54", "G55", "G56")))
        self.absolute_rapid()

    def tool(self):
        choice = self.rnd.random()
        t = self.rnd.choice(TOOLS)
        if choice < 0.3:
            self.emit("T%d M6" % t)                   # M6 alone: G43 on its own line (rs274 quirk)
            self.emit("G43")
        elif choice < 0.6:
            self.emit("G43 H%d" % t)
        elif choice < 0.75:
            self.emit("G43.1 Z%s" % _f(self.u(-30, 30)))
        elif choice < 0.9:
            self.emit("G43.2 H%d" % t)
        else:
            self.emit("G49")
        self.absolute_rapid()

    def program(self, blocks: int) -> str:
        self.emit("(toolcomp oracle generated program)")
        self.emit("%s G17 G90 G94 G40 G49 G54" % ("G20" if self.inch else "G21"))
        self.emit("F" + _f(self.u(100, 1500)))
        self.absolute_rapid()
        for _ in range(blocks):
            x = self.rnd.random()
            if x < 0.35:
                self.move()
            elif x < 0.8:
                self.arc()
            elif x < 0.9:
                self.offsets()
            else:
                self.tool()
        self.set_incremental(False)
        self.emit("G49 G17")
        self.emit("M2")
        return "\n".join(self.lines) + "\n"


def generate(seed: int, blocks: int = 40) -> str:
    """Program text for ``seed`` (deterministic)."""
    return _Gen(seed).program(blocks)


if __name__ == "__main__":
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 0
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    out = Path(sys.argv[3]) if len(sys.argv) > 3 else Path(".")
    out.mkdir(parents=True, exist_ok=True)
    for s in range(seed, seed + count):
        (out / ("gen_%d.ngc" % s)).write_text(generate(s))
