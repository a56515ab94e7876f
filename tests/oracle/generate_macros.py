"""Seeded random LinuxCNC programs that COMPUTE: parameters, expressions, O-word control flow and
subroutines, with cutter radius compensation switched on and off inside and around them.

    python tests/oracle/generate_macros.py SEED [COUNT] [OUTDIR]   # macro_<seed>.ngc (+ _unrolled)

Deterministic: the same seed gives the same text (random.Random(seed), no global state).
Tool table: tests/programs/comp/tools.tbl (metric). Subroutine files: tests/programs/macros/subs
(the LinuxCNC SUBROUTINE_PATH / toolcomp search_path); :data:`LIBRARY` holds the Python model of
the three ``mx_*.ngc`` library files there, ``test_library_files_match_generator`` checks that
the files are exactly what :func:`library_text` renders.

How it works: a program is built as a small syntax tree (expressions :class:`Num`, :class:`Par`,
:class:`Bin`, :class:`Fun`, ...; statements :class:`Assign`, :class:`Move`, :class:`While`,
:class:`Call`, ...). The tree is rendered to LinuxCNC text and also *executed* by a Python model
of the rs274ngc semantics (:class:`Machine`), which

* yields the *unrolled* program: the same motion blocks with every value as a plain number, in
  execution order, no parameters, no O-words (:func:`unrolled`);
* predicts the error of the intended error programs (``Generated.error``, ``error_regex``).

:func:`build` returns both (a :class:`Generated`); :func:`generate` / :func:`unrolled` the texts.
Also avoided (LinuxCNC bugs, see ``_Gen.__init__``): a do loop after a while loop left by break,
a repeat loop after a do loop with continue. Named global parameters are ``#<_g...>`` (LinuxCNC
predefines read-only ones such as #<_a>, #<_x>, #<_ccomp>: assigning them is an error).

The shapes are valid by construction (sizes are chosen against the comp radius) so LinuxCNC
accepts every program except the intended error ones (about 4 %): an undefined named parameter
(also a caller's local read inside a subroutine), division by zero (also in the n-th iteration of
a loop, with compensation on), a call of an unknown O-word, an endwhile without while.

Semantics modelled (all measured with LinuxCNC 2.9.0~pre1, see test_oracle_macros.py):

* precedence ``**`` > ``* / MOD`` > ``+ -`` > ``EQ NE LT LE GT GE`` > ``AND OR XOR``, all
  left-associative (``2 ** 3 ** 2`` = 64); a literal's sign and unary minus bind tighter than
  ``**`` (``-2 ** 2`` = 4, ``-#1 ** 2`` = #1 squared); MOD is fmod plus |b| when negative
  (``-7 MOD 3`` = 2, ``7 MOD -3`` = 1, ``x MOD 0`` is "Calculation resulted in 'not a number'");
  EQ/NE compare with a tolerance of 1e-4, LT/LE/GT/GE exactly; a condition is true when not 0;
  SIN/COS/TAN/ASIN/ACOS/ATAN in degrees, ``ATAN[y]/[x]`` = atan2; FIX = floor, FUP = ceil,
  ROUND = half away from zero;
* O-word labels are unique per program (a reused loop label is "duplicate O-word label");
  subroutines are defined before they are called;
* all parameter assignments of a line take effect after the line has been read, left to right
  (``#1 = 5 #2 = #1`` gives #2 the old #1; a move on the line reads the old values), but a named
  parameter is *declared* (value 0) when its assignment is read, so a later read on the same line
  (or the assignment's own right-hand side) sees 0 instead of failing;
* a call gives the subroutine fresh #1..#30 (the arguments, the rest 0) and restores the caller's
  afterwards; named parameters without a leading underscore are local to the call level (the main
  program's too), ``#<_...>`` are global; endsub/return [v] set #<_value> = v and
  #<_value_returned> = 1, a call returning nothing sets both to 0;
* repeat [n] runs ROUND(n) times; break/continue are only for while/do loops.
"""
from __future__ import annotations

import math
import random
import re
import sys
from pathlib import Path

from generate_comp import read_table  # the comp generator's reader of the same tools.tbl

ROOT = Path(__file__).resolve().parents[2]
TOOLS_TABLE = ROOT / "tests" / "programs" / "comp" / "tools.tbl"
MACROS = ROOT / "tests" / "programs" / "macros"
SUBS = MACROS / "subs"
TOLERANCE_EQUAL = 0.0001
MAX_STEPS = 200000


# =============================================================================================
# numbers

def lit(v: float, digits: int = 4) -> str:
    """A G-code number with at most ``digits`` decimals, no exponent."""
    s = ("%%.%df" % digits) % v
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "", "-") else s


def exact(v: float) -> str:
    """A G-code number that reads back within ~1e-12 of v (the unrolled programs)."""
    return lit(v, 12)


class LinuxCNCError(Exception):
    """An error the model predicts LinuxCNC reports (message as gcode.strerror gives it)."""


# =============================================================================================
# expressions

PREC = {"AND": 2, "OR": 2, "XOR": 2, "EQ": 3, "NE": 3, "LT": 3, "LE": 3, "GT": 3, "GE": 3,
        "+": 4, "-": 4, "*": 5, "/": 5, "MOD": 5, "**": 6}


class Expr:
    def atom(self) -> str:          # usable as a word value / operand / right-hand side
        raise NotImplementedError

    def inner(self) -> str:         # inside brackets
        return self.atom()

    def value(self, m: "Machine") -> float:
        raise NotImplementedError


class Num(Expr):
    def __init__(self, v, digits=4):
        self.text = v if isinstance(v, str) else lit(v, digits)

    def atom(self):
        return self.text

    def value(self, m):
        return float(self.text)


class Par(Expr):
    """#n, #<name>, or #[expr] / ##n (indirect: ref is an Expr)."""

    def __init__(self, ref, spell=None):
        self.ref = ref
        self.spell = spell          # how a name is written (case / blanks vary; same parameter)

    def atom(self):
        if isinstance(self.ref, int):
            return "#%d" % self.ref
        if isinstance(self.ref, str):
            return "#<%s>" % (self.spell or self.ref)
        if isinstance(self.ref, Par):
            return "#" + self.ref.atom()
        return "#[%s]" % self.ref.inner()

    def value(self, m):
        return m.get(self.key(m))

    def key(self, m):
        if isinstance(self.ref, (int, str)):
            return norm(self.ref) if isinstance(self.ref, str) else self.ref
        return int(round(self.ref.value(m)))


class Neg(Expr):
    def __init__(self, a):
        self.a = a

    def atom(self):
        return "-" + self.a.atom()

    def value(self, m):
        return -self.a.value(m)


class Bin(Expr):
    def __init__(self, op, a, b, paren=False):
        self.op, self.a, self.b, self.paren = op, a, b, paren

    def atom(self):
        return "[" + self.inner() + "]"

    def _operand(self, e, left):
        if isinstance(e, Bin):
            p, q = PREC[self.op], PREC[e.op]
            if e.paren or q < p or (not left and q == p):
                return "[" + e.inner() + "]"
            return e.inner()
        return e.atom()

    def inner(self):
        return "%s %s %s" % (self._operand(self.a, True), self.op, self._operand(self.b, False))

    def value(self, m):
        a, b = self.a.value(m), self.b.value(m)
        return binop(self.op, a, b)


def binop(op, a, b):
    if op == "+":
        return a + b
    if op == "-":
        return a - b
    if op == "*":
        return a * b
    if op == "/":
        if b == 0.0:
            raise LinuxCNCError("Attempt to divide by zero")
        return a / b
    if op == "MOD":
        if b == 0.0:
            raise LinuxCNCError("Calculation resulted in 'not a number'")
        r = math.fmod(a, b)
        return r + abs(b) if r < 0 else r
    if op == "**":
        if a < 0 and b != int(b):
            raise LinuxCNCError("Attempt to raise negative to non integer power")
        return a ** b
    if op == "EQ":
        return 1.0 if abs(a - b) < TOLERANCE_EQUAL else 0.0
    if op == "NE":
        return 1.0 if abs(a - b) >= TOLERANCE_EQUAL else 0.0
    if op == "LT":
        return 1.0 if a < b else 0.0
    if op == "LE":
        return 1.0 if a <= b else 0.0
    if op == "GT":
        return 1.0 if a > b else 0.0
    if op == "GE":
        return 1.0 if a >= b else 0.0
    if op == "AND":
        return 1.0 if (a != 0 and b != 0) else 0.0
    if op == "OR":
        return 1.0 if (a != 0 or b != 0) else 0.0
    if op == "XOR":
        return 1.0 if ((a != 0) != (b != 0)) else 0.0
    raise ValueError(op)


def _round(v):
    return float(int(v + (-0.5 if v < 0 else 0.5)))


FUNCS = {
    "SIN": lambda v: math.sin(math.radians(v)),
    "COS": lambda v: math.cos(math.radians(v)),
    "TAN": lambda v: math.tan(math.radians(v)),
    "ABS": abs,
    "FIX": lambda v: float(math.floor(v)),
    "FUP": lambda v: float(math.ceil(v)),
    "ROUND": _round,
    "EXP": math.exp,
}


class Fun(Expr):
    def __init__(self, name, a):
        self.name, self.a = name, a

    def atom(self):
        return "%s[%s]" % (self.name, self.a.inner())

    def value(self, m):
        v = self.a.value(m)
        if self.name == "SQRT":
            if v < 0:
                raise LinuxCNCError("Negative argument to sqrt")
            return math.sqrt(v)
        if self.name == "LN":
            if v <= 0:
                raise LinuxCNCError("Zero or negative argument to ln")
            return math.log(v)
        if self.name in ("ASIN", "ACOS"):
            if v < -1 or v > 1:
                raise LinuxCNCError("Argument to %s out of range" % self.name.lower())
            return math.degrees(math.asin(v) if self.name == "ASIN" else math.acos(v))
        return FUNCS[self.name](v)


class Atan(Expr):
    def __init__(self, y, x):
        self.y, self.x = y, x

    def atom(self):
        return "ATAN[%s]/[%s]" % (self.y.inner(), self.x.inner())

    def value(self, m):
        return math.degrees(math.atan2(self.y.value(m), self.x.value(m)))


class Exists(Expr):
    def __init__(self, name):
        self.name = name

    def atom(self):
        return "EXISTS[#<%s>]" % self.name

    def value(self, m):
        return 1.0 if m.defined(norm(self.name)) else 0.0


def norm(name: str) -> str:
    """LinuxCNC folds parameter and O-word names to lower case and drops blanks."""
    return re.sub(r"\s+", "", name).lower()


def add(a, b):
    return Bin("+", a, b)


def sub(a, b):
    return Bin("-", a, b)


def mul(a, b):
    return Bin("*", a, b)


def div(a, b):
    return Bin("/", a, b)


def P(ref, spell=None):
    return Par(ref, spell)


# =============================================================================================
# statements

class Stmt:
    def lines(self, ind: str) -> list[str]:
        raise NotImplementedError


class Raw(Stmt):
    """A block written as is (no parameters): G40, M8, comments, G0 Z5 ..."""

    def __init__(self, text):
        self.text = text

    def lines(self, ind):
        return [ind + self.text]

    def run(self, m):
        m.out(self.text)


class Assign(Stmt):
    """One line of parameter assignments (applied after the line is read, left to right)."""

    def __init__(self, pairs, comment=""):
        self.pairs = pairs
        self.comment = comment

    def text(self):
        return " ".join("%s = %s" % (p.atom(), e.atom()) for p, e in self.pairs)

    def lines(self, ind):
        return [ind + self.text() + (" " + self.comment if self.comment else "")]

    def run(self, m):
        m.assign_line(self.pairs)


class Move(Stmt):
    """A block of words; values may be expressions. ``post``: assignments after the words on
    the same line (they see nothing of it: the words are read first, assignments apply after)."""

    def __init__(self, words, post=()):
        self.words = words               # [(letter, str | Expr)]
        self.post = list(post)

    def _w(self, v):
        return v if isinstance(v, str) else v.atom()

    def lines(self, ind):
        s = " ".join(l + self._w(v) for l, v in self.words)
        if self.post:
            s += " " + " ".join("%s = %s" % (p.atom(), e.atom()) for p, e in self.post)
        return [ind + s]

    def run(self, m):
        vals = []
        for l, v in self.words:
            vals.append(l + (v if isinstance(v, str) else exact(v.value(m))))
        if self.post:
            m.assign_line(self.post, before=lambda: None)
        m.out(" ".join(vals))


class Block(Stmt):
    def __init__(self, body):
        self.body = list(body)

    def lines(self, ind):
        return [l for s in self.body for l in s.lines(ind)]

    def run(self, m):
        for s in self.body:
            m.step()
            s.run(m)


def _body_lines(body, ind, step="  "):
    return [l for s in body for l in s.lines(ind + step)]


class _Break(Exception):
    def __init__(self, label):
        self.label = label


class _Continue(Exception):
    def __init__(self, label):
        self.label = label


class _Return(Exception):
    def __init__(self, value):
        self.value = value


def ow(label) -> str:
    return "o%d" % label if isinstance(label, int) else "o<%s>" % label


class While(Stmt):
    def __init__(self, label, cond, body):
        self.label, self.cond, self.body = label, cond, list(body)

    def lines(self, ind):
        return ([ind + "%s while [%s]" % (ow(self.label), self.cond.inner())]
                + _body_lines(self.body, ind) + [ind + "%s endwhile" % ow(self.label)])

    def run(self, m):
        while self.cond.value(m) != 0:
            m.step()
            try:
                Block(self.body).run(m)
            except _Break as b:
                if b.label != self.label:
                    raise
                break
            except _Continue as c:
                if c.label != self.label:
                    raise


class DoWhile(Stmt):
    def __init__(self, label, body, cond):
        self.label, self.body, self.cond = label, list(body), cond

    def lines(self, ind):
        return ([ind + "%s do" % ow(self.label)] + _body_lines(self.body, ind)
                + [ind + "%s while [%s]" % (ow(self.label), self.cond.inner())])

    def run(self, m):
        while True:
            m.step()
            try:
                Block(self.body).run(m)
            except _Break as b:
                if b.label != self.label:
                    raise
                break
            except _Continue as c:
                if c.label != self.label:
                    raise
            if self.cond.value(m) == 0:
                break


class Repeat(Stmt):
    def __init__(self, label, count, body):
        self.label, self.count, self.body = label, count, list(body)

    def lines(self, ind):
        return ([ind + "%s repeat [%s]" % (ow(self.label), self.count.inner())]
                + _body_lines(self.body, ind) + [ind + "%s endrepeat" % ow(self.label)])

    def run(self, m):
        for _ in range(int(_round(self.count.value(m)))):
            m.step()
            Block(self.body).run(m)


class If(Stmt):
    def __init__(self, label, branches, orelse=None):
        self.label, self.branches, self.orelse = label, branches, orelse

    def lines(self, ind):
        out = []
        for k, (c, body) in enumerate(self.branches):
            out.append(ind + "%s %s [%s]" % (ow(self.label), "if" if k == 0 else "elseif", c.inner()))
            out += _body_lines(body, ind)
        if self.orelse is not None:
            out.append(ind + "%s else" % ow(self.label))
            out += _body_lines(self.orelse, ind)
        return out + [ind + "%s endif" % ow(self.label)]

    def run(self, m):
        for c, body in self.branches:
            if c.value(m) != 0:
                Block(body).run(m)
                return
        if self.orelse is not None:
            Block(self.orelse).run(m)


class Break(Stmt):
    def __init__(self, label):
        self.label = label

    def lines(self, ind):
        return [ind + "%s break" % ow(self.label)]

    def run(self, m):
        raise _Break(self.label)


class Continue(Stmt):
    def __init__(self, label):
        self.label = label

    def lines(self, ind):
        return [ind + "%s continue" % ow(self.label)]

    def run(self, m):
        raise _Continue(self.label)


class Return(Stmt):
    def __init__(self, name, value=None):
        self.name, self.value = name, value

    def lines(self, ind):
        v = "" if self.value is None else " [%s]" % self.value.inner()
        return [ind + "%s return%s" % (ow(self.name), v)]

    def run(self, m):
        raise _Return(None if self.value is None else self.value.value(m))


class Call(Stmt):
    def __init__(self, name, args=(), spell=None):
        self.name, self.args, self.spell = name, list(args), spell

    def lines(self, ind):
        name = ow(self.spell if self.spell is not None else self.name)
        return [ind + " ".join([name, "call"] + ["[%s]" % a.inner() for a in self.args])]

    def run(self, m):
        m.call(self.name, [a.value(m) for a in self.args])


class SubDef(Stmt):
    def __init__(self, name, body, value=None, comment=""):
        self.name, self.body, self.value, self.comment = name, list(body), value, comment

    def lines(self, ind):
        head = ind + "%s sub" % ow(self.name) + (" " + self.comment if self.comment else "")
        v = "" if self.value is None else " [%s]" % self.value.inner()
        return [head] + _body_lines(self.body, ind) + [ind + "%s endsub%s" % (ow(self.name), v)]

    def run(self, m):
        m.define(self)


class Fail(Stmt):
    """An intended error block: written as ``text``, the model raises ``message``."""

    def __init__(self, text, message):
        self.text, self.message = text, message

    def lines(self, ind):
        return [ind + self.text]

    def run(self, m):
        raise LinuxCNCError(self.message)


# =============================================================================================
# the model of the interpreter

class Machine:
    """Executes a statement tree the way rs274ngc does; collects the unrolled blocks."""

    def __init__(self, library=None):
        self.glob = {"_value": 0.0, "_value_returned": 0.0}
        self.num = {}                      # numbered parameters 31.. (global)
        self.frames = [({}, {})]           # per call level: (#1..#30, named locals)
        self.subs = dict(library or {})
        self.lines: list[str] = []
        self.steps = 0

    def step(self):
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise RuntimeError("generated program does not terminate")

    def out(self, text):
        self.lines.append(text)

    # parameters
    def defined(self, key):
        if isinstance(key, int):
            return True
        return key in (self.glob if key.startswith("_") else self.frames[-1][1])

    def get(self, key):
        if isinstance(key, int):
            if key < 1 or key > 5602:
                raise LinuxCNCError("Parameter number out of range")
            if key <= 30:
                return self.frames[-1][0].get(key, 0.0)
            return self.num.get(key, 0.0)
        table = self.glob if key.startswith("_") else self.frames[-1][1]
        if key not in table:
            raise LinuxCNCError("Named parameter #<%s> not defined" % key)
        return table[key]

    def set(self, key, v):
        if isinstance(key, int):
            (self.frames[-1][0] if key <= 30 else self.num)[key] = v
        else:
            (self.glob if key.startswith("_") else self.frames[-1][1])[key] = v

    def assign_line(self, pairs, before=None):
        """Assignments of one line: named ones are declared (0) as read, all apply after."""
        pending = []
        for p, e in pairs:
            key = p.key(self)
            if isinstance(key, str) and not self.defined(key):
                self.set(key, 0.0)            # declared when its assignment is read
            pending.append((key, e.value(self)))
        for key, v in pending:
            self.set(key, v)

    # subroutines
    def define(self, s: SubDef):
        self.subs[s.name if isinstance(s.name, int) else norm(s.name)] = s

    def call(self, name, args):
        key = name if isinstance(name, int) else norm(name)
        s = self.subs.get(key)
        if s is None:
            raise LinuxCNCError("EOF in file:%s seeking o-word: o<%s> from line: %%d" % ("%s", key))
        if len(self.frames) > 50:
            raise RuntimeError("recursion too deep")
        self.frames.append(({i + 1: v for i, v in enumerate(args[:30])}, {}))
        value = s.value
        try:
            Block(s.body).run(self)
            value = None if s.value is None else s.value.value(self)
        except _Return as r:
            value = r.value
        finally:
            self.frames.pop()
        self.glob["_value"] = 0.0 if value is None else value
        self.glob["_value_returned"] = 0.0 if value is None else 1.0


# =============================================================================================
# the library subroutine files (tests/programs/macros/subs/mx_*.ngc)

def _lib_rrect():
    """o<mx_rrect> [x0] [y0] [w] [h] [rc]: rounded rectangle, counter-clockwise, from and back to
    (x0 + rc, y0); no comp words (the caller's compensation applies)."""
    x0, y0, w, h, rc = P(1), P(2), P(3), P(4), P(5)
    body = [
        Assign([(P("x1"), add(x0, w))]),
        Assign([(P("y1"), add(y0, h))]),
        Move([("G1", ""), ("X", sub(P("x1"), rc)), ("Y", y0)]),
        Move([("G3", ""), ("X", P("x1")), ("Y", add(y0, rc)), ("R", rc)]),
        Move([("G1", ""), ("Y", sub(P("y1"), rc))]),
        Move([("G3", ""), ("X", sub(P("x1"), rc)), ("Y", P("y1")), ("I", Neg(rc)), ("J", Num(0))]),
        Move([("G1", ""), ("X", add(x0, rc))]),
        Move([("G3", ""), ("X", x0), ("Y", sub(P("y1"), rc)), ("R", rc)]),
        Move([("G1", ""), ("Y", add(y0, rc))]),
        Move([("G3", ""), ("X", add(x0, rc)), ("Y", y0), ("I", rc), ("J", Num(0))]),
    ]
    return SubDef("mx_rrect", body, comment="(x0 y0 w h rc: rounded rectangle, ccw)")


def _lib_hole():
    """o<mx_hole> [x] [y] [r] [tool] [depth] [safe]: a compensated circular pocket wall:
    plunge at the centre, G41 D<tool>, entry to (x + r, y), full circle G3, G40, back to the
    centre, retract. Returns the circle's length."""
    x, y, r, t, d, s = P(1), P(2), P(3), P(4), P(5), P(6)
    body = [
        Move([("G0", ""), ("X", x), ("Y", y)]),
        Move([("G1", ""), ("Z", Neg(d))]),
        Move([("G41", ""), ("D", t)]),
        Move([("G1", ""), ("X", add(x, r))]),
        Move([("G3", ""), ("I", Neg(r)), ("J", Num(0))]),
        Raw("G40"),
        Move([("G1", ""), ("X", x), ("Y", y)]),
        Move([("G0", ""), ("Z", s)]),
    ]
    return SubDef("mx_hole", body, value=mul(mul(Num(2), r), Num("3.14159265")),
                  comment="(x y r tool depth safe: compensated circle; returns its length)")


def _lib_polar():
    """o<mx_polar> [cx] [cy] [r] [angle] [axis]: returns cx + r cos(a) (axis 0) or cy + r sin(a)."""
    cx, cy, r, a, axis = P(1), P(2), P(3), P(4), P(5)
    body = [
        If(10, [(Bin("EQ", axis, Num(0)), [Return("mx_polar", add(cx, mul(r, Fun("COS", a))))])]),
    ]
    return SubDef("mx_polar", body, value=add(cy, mul(r, Fun("SIN", a))),
                  comment="(cx cy r angle axis: a polar coordinate, X for axis 0, else Y)")


def _library():
    return {norm(s.name): s for s in (_lib_rrect(), _lib_hole(), _lib_polar())}


LIBRARY = _library()


def library_text(name: str) -> str:
    """The text of subs/<name>.ngc as the generator models it."""
    s = LIBRARY[name]
    head = "(%s.ngc: library subroutine of tests/oracle/generate_macros.py; edit both together)" % name
    return "\n".join([head] + s.lines("") + [""])


# =============================================================================================
# the generator

def inside_cap(r: float, gaps: list, margin: float = 1.0) -> float:
    """Largest comp radius (mm, with a safety factor) for a closed polygon inscribed in a circle of
    radius r with central angles ``gaps`` (degrees), the tool inside, entered from the centre.

    A concave corner with turn t trims r_t * tan(t / 2) off both segments; each side (and the entry
    line from the centre, which also needs length > r_t) must keep ``margin`` mm. The entry turns
    by 90 + g0 / 2; the polygon ends at its first vertex, where G40 follows (no corner)."""
    turns = [90 + gaps[0] / 2] + [(a + b) / 2 for a, b in zip(gaps, gaps[1:])] + [0.0]
    tan = [math.tan(math.radians(t) / 2) for t in turns]
    caps = [(r - margin) / (1 + tan[0])]
    for j, gj in enumerate(gaps):
        side = 2 * r * math.sin(math.radians(gj) / 2)
        caps.append((side - margin) / max(tan[j] + tan[j + 1], 1e-9))
    return max(0.0, 0.8 * min(caps))


NAMES = ("cx", "cy", "rad", "ang", "da", "cnt", "n", "k", "px", "py", "nx", "ny", "w", "h",
         "step", "dep", "tool", "dia", "ar", "sg", "x0", "y0", "pitch", "rh", "turns", "zz",
         "row", "xe", "ye", "sel", "lim", "stop", "half", "bulge", "q")


class _Gen:
    def __init__(self, seed: int):
        self.rnd = random.Random(seed)
        self.seed = seed
        self.tools = read_table()
        self.mill = [t for t, (d, q) in self.tools.items() if q in (0, 9) and t != 8]
        self.inch = self.rnd.random() < 0.12
        self.k = 1 / 25.4 if self.inch else 1.0          # program units per mm
        self.label = 1000 + self.rnd.randrange(0, 9000, 100)
        self.subno = 100
        self.used_names = set()
        self.subs: list[SubDef] = []                     # defined at the top of the program
        self.uses_library = False
        self.fail = None                                 # intended error kind
        self.known = {}                                  # global parameters with values: key -> (Par, value)
        self.next_num = self.rnd.randrange(100, 4000)             # see par()
        # LinuxCNC 2.9 bugs (interp_o_word.cc; unchanged in upstream's 0164ed73): 'break' out of a
        # while/endwhile loop sets doing_break, which only the end of a do/while loop clears, so
        # the next do/while loop of the program runs once; 'continue' in a do/while loop sets
        # doing_continue, which only an endwhile/endrepeat reached by continue clears, so the next
        # repeat loop starts over when its count runs out. So: continue only in while loops, and
        # a program has either while loops left by break, or do loops.
        self.while_break = self.rnd.random() < 0.25

    def no_do(self, kind):
        return "while" if kind == "do" and self.while_break else kind

    # -- helpers -----------------------------------------------------------------------------
    def new_label(self):
        self.label += 1
        return self.label

    def name(self, glob=False):
        """A fresh parameter: named local / global, or numbered global."""
        for _ in range(1000):
            base = self.rnd.choice(NAMES) + str(self.rnd.randrange(100))
            nm = ("_g" + base) if glob else base
            if nm not in self.used_names:
                self.used_names.add(nm)
                return nm
        raise RuntimeError("out of names")

    def par(self, glob=False, numbered_ok=True):
        """A fresh parameter reference (Par)."""
        if numbered_ok and self.rnd.random() < 0.25 and self.next_num < 4990:
            # 31..5000: plain globals (#5001.. hold offsets, the coordinate system ...)
            self.next_num += self.rnd.randint(1, 7)
            return P(self.next_num)
        nm = self.name(glob)
        spell = None
        if self.rnd.random() < 0.08:                    # case / blanks do not matter
            spell = nm.upper() if self.rnd.random() < 0.5 else nm[:2] + " " + nm[2:]
        return P(nm, spell)

    def num(self, v, digits=4):
        return Num(lit(v, digits))

    def obf(self, v, depth=2, integral=False):
        """An expression worth (about; exactly when integral) v, using known parameters."""
        rnd = self.rnd
        if depth <= 0 or rnd.random() < 0.3:
            return Num(lit(v, 0 if integral else 4))
        x = rnd.random()
        if integral:
            n = int(v)
            if x < 0.2:
                return Fun("ABS", Num(str(-n))) if n > 0 else Fun("ABS", Num(str(n)))
            if x < 0.4:
                return Fun("FIX", add(self.obf(n, depth - 1, True), Num("0.4")))
            if x < 0.55:
                return Fun("FUP", sub(self.obf(n, depth - 1, True), Num("0.7")))
            if x < 0.7:
                return Fun("ROUND", add(Num(str(n)), Num("0.3")))
            if x < 0.85:
                m = rnd.randint(max(n + 1, 2), n + 9)
                return Bin("MOD", Num(str(n + m * rnd.randint(1, 3))), Num(str(m)))
            if x < 0.92:
                return mul(Exists("_gsafe"), Num(str(n)))            # 1 * n
            return div(mul(self.obf(n, depth - 1, True), Num("4")), Num("4"))
        if x < 0.25 and self.known:
            key = rnd.choice(sorted(self.known, key=str))
            p, pv = self.known[key]
            if isinstance(key, int) and rnd.random() < 0.25:        # #[a + b]: indirect
                a = rnd.randrange(key)
                p = Par(Bin("+", Num(str(a)), Num(str(key - a))))
            return add(p, self.obf(v - pv, depth - 1)) if rnd.random() < 0.5 else \
                Bin("-", self.obf(v + pv, depth - 1), p)
        if x < 0.4:
            f = rnd.choice((2, 4, 0.5, -2, 1.5))
            return mul(self.obf(v / f, depth - 1), Num(lit(f)))
        if x < 0.5:
            f = rnd.choice((2, 4, 8, -4))
            return div(self.obf(v * f, depth - 1), Num(lit(f)))
        if x < 0.58 and v >= 0:
            return Fun("SQRT", self.obf(v * v, depth - 1))
        if x < 0.64:
            return Fun("ABS", Num(lit(-abs(v)))) if v >= 0 else Neg(Fun("ABS", Num(lit(v))))
        if x < 0.72 and v >= 0:
            m = max(1.0, math.ceil(v + 1))
            return Bin("MOD", add(self.obf(v, depth - 1), Num(lit(m * rnd.randint(1, 3)))),
                       Num(lit(m)))
        if x < 0.8:
            a = rnd.uniform(-3, 3)
            return Bin("-", self.obf(v + a, depth - 1), Num(lit(a)), paren=rnd.random() < 0.3)
        if x < 0.88 and v > 0:
            return Bin("**", Fun("SQRT", self.obf(v, depth - 1)), Num("2"))
        if x < 0.91 and -170 < v < 170:
            # an angle-sized value through atan2: ATAN[SIN[v]]/[COS[v]] (degrees)
            h = rnd.choice((1, 2.5, 10))
            return Atan(mul(Num(lit(h)), Fun("SIN", Num(lit(v, 6)))), mul(Num(lit(h)), Fun("COS", Num(lit(v, 6)))))
        if x < 0.94 and -1000 < v < 1000:
            # v = h * SIN[t] with t in degrees
            t = rnd.choice((30, 90, 150))
            return mul(Fun("SIN", Num(str(t))), Num(lit(v / math.sin(math.radians(t)), 6)))
        return add(self.obf(v / 2, depth - 1), self.obf(v / 2, depth - 1))

    def setp(self, value, glob=False, integral=False, numbered_ok=True, depth=2, remember=True):
        """(Assign statement, Par, exact value) for a fresh parameter ~ value."""
        p = self.par(glob, numbered_ok)
        e = self.obf(value, depth, integral)
        v = e.value(_ValueMachine(self.known))
        if remember and (glob or isinstance(p.ref, int)):
            self.known[p.key(None) if isinstance(p.ref, str) else p.ref] = (p, v)
        return Assign([(p, e)]), p, v

    # -- compensation ------------------------------------------------------------------------
    def comp_on(self, ccw: bool, inside: bool, r_max: float, glob: bool = False):
        """Words that turn comp on with the tool inside/outside a ccw/cw contour, radius <= r_max
        (mm). Returns (words list for Move, radius mm, setup statements). ``glob``: parameters
        the words use are global (the words are used inside a subroutine, the setup outside)."""
        rnd = self.rnd
        setup = []
        left = (ccw == inside)                        # ccw + inside -> left of the path
        cands = [t for t in self.mill if abs(self.tools[t][0]) / 2 <= r_max]
        if rnd.random() < 0.4 or not cands:
            dia = rnd.uniform(0.4, min(2 * r_max, 14)) * (1 if rnd.random() < 0.85 else -1)
            if not cands and r_max < 0.2:
                dia = 0.0
            if dia < 0:
                left = not left
            code = "G41.1" if left else "G42.1"
            if rnd.random() < 0.5:
                st, p, v = self.setp(abs(dia) * self.k / 2, glob=glob, numbered_ok=False, depth=1)
                setup.append(st)
                sign = "-" if dia < 0 else ""
                dexpr = mul(P(p.ref, p.spell), Num("2")) if not sign else mul(P(p.ref, p.spell), Num("-2"))
                words = [(code, ""), ("D", dexpr)]
                r = abs(2 * v) / 2 / self.k
            else:
                dtext = lit(dia * self.k)
                words = [(code, ""), ("D", dtext)]
                r = abs(float(dtext)) / 2 / self.k
            return words, r, setup
        t = rnd.choice(cands)
        d = self.tools[t][0]
        if d < 0:
            left = not left
        code = "G41" if left else "G42"
        if rnd.random() < 0.4:
            st, p, v = self.setp(t, glob=glob, integral=True, numbered_ok=True, depth=1)
            setup.append(st)
            words = [(code, ""), ("D", p)]
        else:
            words = [(code, ""), ("D", str(t))]
        return words, abs(d) / 2, setup

    # -- shapes ------------------------------------------------------------------------------
    def min_bulge(self) -> float:
        """The smallest arc radius of a polygon's edges, in polygon radii. At 1 the edges are
        one circle; just above it they meet at corners turning less than LinuxCNC's 0.05 rad,
        which it takes as tangent: it pulls the arc's end there, and in inch refuses the few
        0.001 rad its sweep then grows by (its inch tolerance; 0.0254 rad in mm), which this
        model does not predict (that error: tests/programs/comp/inch_s1_arc_sweep_growth.ngc).
        From 1.1 on a corner turns at least 0.065 rad for 3 to 9 edges."""
        return 1.1 if self.inch else 1.0

    def polygon(self, comp: bool, loop: str = None, arcs: str = None, centre_args: bool = False):
        """A regular polygon (or its vertices on a circle with some skipped) drawn by a loop.

        Returns a list of statements: setup, rapid + plunge, comp on, entry, loop, closing,
        comp off, exit, retract. ``centre_args``: the centre is the caller's #1, #2 (the
        statements are a subroutine body)."""
        rnd = self.rnd
        k = self.k
        loop = self.no_do(loop or rnd.choice(("while", "do", "repeat", "continue", "break", "inc")))
        arcs = arcs if arcs is not None else (rnd.choice((None, None, "R", "IJ", "circle"))
                                              if loop in ("while", "do", "repeat") else None)
        ccw = rnd.random() < 0.6
        inside = comp and rnd.random() < 0.45
        n = rnd.randint(3, 9) if loop not in ("continue",) else rnd.choice((6, 8, 10))
        if loop == "break":
            n = rnd.randint(4, 9)
            stop = rnd.randint(n // 2 + 1, n)
        r_mm = rnd.uniform(14, 40)
        g = 360.0 / n
        if loop == "continue":
            gaps = [2 * g] * (n // 2)
        elif loop == "break":
            gaps = [g] * stop + ([(n - stop) * g] if stop < n else [])
        else:
            gaps = [g] * n
        r_cap = inside_cap(r_mm, gaps) if inside else min(r_mm / 3, 8)
        out = []
        cx, cy = rnd.uniform(-60, 60), rnd.uniform(-60, 60)
        st, pcx, cxv = self.setp(cx * k, remember=not centre_args)
        out.append(Assign([(pcx, P(1))]) if centre_args else st)
        st, pcy, cyv = self.setp(cy * k, remember=not centre_args)
        out.append(Assign([(pcy, P(2))]) if centre_args else st)
        st, pr, rv = self.setp(r_mm * k, depth=1)
        out.append(st)
        r_mm = rv / k
        a0 = rnd.choice((0, 15, 30, 45, 90, rnd.uniform(-180, 180)))
        st, pa0, a0v = self.setp(a0, depth=1)
        out.append(st)
        st, pn, nv = self.setp(n, integral=True, depth=1)
        out.append(st)
        sg = 1 if ccw else -1
        pda = self.par()
        out.append(Assign([(pda, div(Num(str(360 * sg)), pn))]))

        def vx(ang):
            return add(pcx, mul(pr, Fun("COS", ang)))

        def vy(ang):
            return add(pcy, mul(pr, Fun("SIN", ang)))

        # start point, plunge
        if inside:
            start = (pcx, pcy)
        else:
            ext = (r_mm + 2.5 * min(r_cap, 8) + rnd.uniform(3, 12)) * k
            pe = self.par()
            out.append(Assign([(pe, Num(lit(ext)))]))
            start = (add(pcx, mul(pe, Fun("COS", pa0))), add(pcy, mul(pe, Fun("SIN", pa0))))
        out.append(Move([("G0", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G1", ""), ("Z", self.depth_expr())]))
        comp_words = []
        if comp:
            comp_words, rad, setup = self.comp_on(ccw, inside, r_cap)
            out += setup
            if rnd.random() < 0.6:
                out.append(Move(comp_words))
                comp_words = []
        out.append(Move(comp_words + [("G1", ""), ("X", vx(pa0)), ("Y", vy(pa0))]))
        # the loop
        i = self.par(numbered_ok=True)
        lab = self.new_label()
        ang_i = add(pa0, mul(i, pda))
        arc_code = "G3" if ccw else "G2"
        body_move = None
        pre = []
        if arcs is None:
            body_move = [Move([("G1", ""), ("X", vx(ang_i)), ("Y", vy(ang_i))])]
        elif arcs == "R":
            st, par_, arv = self.setp(r_mm * k * rnd.uniform(self.min_bulge(), 2.5))
            pre.append(st)
            body_move = [Move([(arc_code, ""), ("X", vx(ang_i)), ("Y", vy(ang_i)), ("R", par_)])]
        elif arcs == "circle":
            ppx, ppy = self.par(), self.par()
            pre.append(Assign([(ppx, vx(pa0)), (ppy, vy(pa0))]))
            body_move = [
                Move([(arc_code, ""), ("X", vx(ang_i)), ("Y", vy(ang_i)),
                      ("I", sub(pcx, ppx)), ("J", sub(pcy, ppy))]),
                Assign([(ppx, vx(ang_i)), (ppy, vy(ang_i))]),
            ]
        else:                                             # IJ: centre of a flatter arc
            ppx, ppy, pnx, pny = self.par(), self.par(), self.par(), self.par()
            pmx, pmy, ps, ph, pccx, pccy = (self.par(numbered_ok=False) for _ in range(6))
            st, par_, arv = self.setp(r_mm * k * rnd.uniform(self.min_bulge(), 2.5))
            pre += [st, Assign([(ppx, vx(pa0)), (ppy, vy(pa0))])]
            body_move = [
                Assign([(pnx, vx(ang_i)), (pny, vy(ang_i))]),
                Assign([(pmx, div(add(ppx, pnx), Num("2")))]),
                Assign([(pmy, div(add(ppy, pny), Num("2")))]),
                Assign([(ps, Fun("SQRT", add(Bin("**", sub(pnx, ppx), Num("2")),
                                              Bin("**", sub(pny, ppy), Num("2")))))]),
                Assign([(ph, Fun("SQRT", sub(Bin("**", par_, Num("2")),
                                             Bin("**", div(ps, Num("2")), Num("2")))))]),
                Assign([(pccx, Bin("-", pmx, div(mul(mul(Num(str(sg)), ph), sub(pny, ppy)), ps)))]),
                Assign([(pccy, add(pmy, div(mul(mul(Num(str(sg)), ph), sub(pnx, ppx)), ps)))]),
                Move([(arc_code, ""), ("X", pnx), ("Y", pny),
                      ("I", sub(pccx, ppx)), ("J", sub(pccy, ppy))]),
                Assign([(ppx, pnx), (ppy, pny)]),
            ]
        out += pre
        closing = []
        if loop == "while":
            out.append(Assign([(i, Num("1"))]))
            cond = Bin("LE", i, pn) if rnd.random() < 0.5 else Bin("LT", i, add(pn, Num("0.5")))
            out.append(While(lab, cond, body_move + [Assign([(i, add(i, Num("1")))])]))
        elif loop == "do":
            out.append(Assign([(i, Num("0"))]))
            out.append(DoWhile(lab, [Assign([(i, add(i, Num("1")))])] + body_move,
                               Bin("LT", i, pn)))
        elif loop == "repeat":
            out.append(Assign([(i, Num("1"))]))
            out.append(Repeat(lab, pn, body_move + [Assign([(i, add(i, Num("1")))])]))
        elif loop == "continue":
            # skip every other vertex (never the last): the polygon of the remaining ones
            out.append(Assign([(i, Num("0"))]))
            lab2 = self.new_label()
            skip = If(lab2, [(Bin("AND", Bin("EQ", Bin("MOD", i, Num("2")), Num("1")), Bin("LT", i, pn)),
                              [Continue(lab)])])
            # (continue only in while loops: see _Gen.__init__)
            body = [Assign([(i, add(i, Num("1")))]), skip] + body_move
            out.append(While(lab, Bin("LT", i, pn), body))
        elif loop == "break":
            # stop after vertex `stop` (> n/2) and close with a chord back to vertex 0
            st, pstop, _ = self.setp(stop, integral=True, depth=1)
            out.append(st)
            out.append(Assign([(i, Num("0"))]))
            lab2 = self.new_label()
            body = [Assign([(i, add(i, Num("1")))])] + body_move + \
                   [If(lab2, [(Bin("GE", i, pstop), [Break(lab)])])]
            if self.while_break:
                out.append(While(lab, Num("1") if rnd.random() < 0.5 else Bin("LT", i, Num("1000")), body))
            else:
                out.append(DoWhile(lab, body, Bin("LT", i, Num("1000"))))
            if stop < n:
                closing.append(Move([("G1", ""), ("X", vx(pa0)), ("Y", vy(pa0))]))
        else:                                             # inc: G91 moves of side length
            pang = self.par()
            ps = self.par()
            out.append(Assign([(ps, mul(mul(Num("2"), pr), Fun("SIN", div(Num("180"), pn))))]))
            # direction of side j: a0 + (j + 0.5) * da + 90 * sg
            out.append(Assign([(pang, add(add(pa0, div(pda, Num("2"))), Num(str(90 * sg))))]))
            out.append(Raw("G91"))
            out.append(Repeat(lab, pn, [
                Move([("G1", ""), ("X", mul(ps, Fun("COS", pang))), ("Y", mul(ps, Fun("SIN", pang)))]),
                Assign([(pang, add(pang, pda))]),
            ]))
            out.append(Raw("G90"))
        out += closing
        if comp:
            if rnd.random() < 0.3:
                out.append(Move([("G40", ""), ("G1", ""), ("X", start[0]), ("Y", start[1])]))
            else:
                out.append(Raw("G40"))
                out.append(Move([("G1", ""), ("X", start[0]), ("Y", start[1])]))
        else:
            out.append(Move([("G1", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        return out

    def depth_expr(self):
        d = self.rnd.uniform(0.5, 3) * self.k
        return Neg(Num(lit(d))) if self.rnd.random() < 0.5 else sub(Num("0"), Num(lit(d)))

    def holes(self):
        """A row of compensated circles in a loop: comp switched on and off in every iteration,
        inline, through an inline subroutine, or through the library o<mx_hole>."""
        rnd = self.rnd
        k = self.k
        m = rnd.randint(2, 4)
        how = rnd.choice(("inline", "sub", "library", "library"))
        r_tool_max = 4.0
        rh = rnd.uniform(2 * r_tool_max + 2, 14)
        out = []
        st, prh, rhv = self.setp(rh * k, depth=1)
        out.append(st)
        st, pp, ppv = self.setp((2 * rh + rnd.uniform(4, 15)) * k, depth=1)
        out.append(st)
        phx, phy = self.par(), self.par()
        out.append(Assign([(phx, self.num(rnd.uniform(-80, 40) * k)), (phy, self.num(rnd.uniform(-80, 80) * k))]))
        lab = self.new_label()
        if how == "library":
            self.uses_library = True
            t = rnd.choice([t for t in self.mill if 0 < abs(self.tools[t][0]) / 2 <= r_tool_max
                            and self.tools[t][0] > 0])
            plen = self.par(glob=True, numbered_ok=False)
            body = [Call("mx_hole", [phx, phy, prh, Num(str(t)), self.depth_abs(), P("_gsafe")]),
                    Assign([(plen, P("_value"))]) if rnd.random() < 0.5 else
                    Assign([(plen, add(P("_value"), P("_value_returned")))]),
                    Assign([(phx, add(phx, pp))])]
        else:
            ccw = rnd.random() < 0.5
            cw_, rad, setup = self.comp_on(ccw, True, r_tool_max, glob=(how == "sub"))
            out += setup
            arc = "G3" if ccw else "G2"
            helix = rnd.random() < 0.4
            if how == "sub":
                name = self.sub_name()
                hx, hy, hr = P(1), P(2), P(3)
            else:
                hx, hy, hr = phx, phy, prh
            inner = [
                Move([("G0", ""), ("X", hx), ("Y", hy)]),
                Move([("G1", ""), ("Z", Num(lit(-0.2 * k)))]),
                Move(cw_) if rnd.random() < 0.5 else None,
            ]
            if inner[-1] is None:
                inner.pop()
                inner.append(Move(cw_ + [("G1", ""), ("X", add(hx, hr))]))
            else:
                inner.append(Move([("G1", ""), ("X", add(hx, hr))]))
            if helix:
                pz = self.par(numbered_ok=False)
                pt = self.par(numbered_ok=False)
                inner.append(Assign([(pz, Num(lit(-0.2 * k)))]))
                inner.append(Assign([(pt, Num(str(rnd.randint(1, 3))))]))
                hl = self.new_label()
                inner.append(Repeat(hl, pt, [
                    Assign([(pz, sub(pz, Num(lit(0.5 * k))))]),
                    Move([(arc, ""), ("I", Neg(hr)), ("J", Num("0")), ("Z", pz)]),
                ]))
            inner.append(Move([(arc, ""), ("I", Neg(hr)), ("J", Num("0"))]))
            inner.append(Raw("G40"))
            inner.append(Move([("G1", ""), ("X", hx), ("Y", hy)]))
            inner.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
            if how == "sub":
                self.subs.append(SubDef(name, inner))
                body = [Call(name, [phx, phy, prh]), Assign([(phx, add(phx, pp))])]
            else:
                body = inner + [Assign([(phx, add(phx, pp))])]
        kind = self.no_do(rnd.choice(("repeat", "while", "do")))
        if kind == "repeat":
            out.append(Repeat(lab, Num(str(m)), body))
        else:
            pc = self.par()
            out.append(Assign([(pc, Num("0"))]))
            body = body + [Assign([(pc, add(pc, Num("1")))])]
            out.append(While(lab, Bin("LT", pc, Num(str(m))), body) if kind == "while"
                       else DoWhile(lab, body, Bin("LT", pc, Num(str(m)))))
        return out

    def depth_abs(self):
        return Num(lit(self.rnd.uniform(0.5, 2) * self.k))

    def sub_name(self):
        if self.rnd.random() < 0.5:
            self.subno += self.rnd.randint(1, 9)
            return self.subno
        return self.name()

    def rect(self):
        """A (rounded) rectangle drawn by a subroutine; compensation is turned on by the caller,
        the entry move is the caller's, the sides are the subroutine's, G40 is the caller's."""
        rnd = self.rnd
        k = self.k
        ccw = True
        inside = rnd.random() < 0.4
        w, h = rnd.uniform(20, 60), rnd.uniform(20, 60)
        rc = rnd.uniform(3, min(w, h) / 4)
        lib = rnd.random() < 0.5
        out = []
        x0, y0 = rnd.uniform(-80, 30), rnd.uniform(-80, 30)
        st, px0, x0v = self.setp(x0 * k)
        out.append(st)
        st, py0, y0v = self.setp(y0 * k)
        out.append(st)
        args = [px0, py0, self.obf(w * k, 1), self.obf(h * k, 1), self.obf(rc * k, 1)]
        vm = _ValueMachine(self.known)
        w, h, rc = (a.value(vm) / k for a in args[2:])
        # inside: the entry from the centre turns by up to ~150 degrees at the first point
        # (trim 3.8 r), the straight sides lose 2 rc to the corner arcs, the arcs need rc > r
        r_cap = min(rc - 1.0, (min(w, h) - 2 * rc - 1) / 4.8) if inside else 6
        if lib:
            self.uses_library = True
            name = "mx_rrect"
            spell = rnd.choice(("mx_rrect", "MX_RRECT", "mx_ rrect")) if rnd.random() < 0.2 else None
            call = Call(name, args, spell=spell)
            first = (add(px0, args[4]), py0)                 # the sub starts at (x0 + rc, y0)
        else:
            name = self.sub_name()
            a1, a2, a3, a4 = P(1), P(2), P(3), P(4)
            body = [
                Assign([(P("xr"), add(a1, a3)), (P("yt"), add(a2, a4))]),
                Move([("G1", ""), ("X", P("xr")), ("Y", a2)]),
                Move([("G1", ""), ("Y", P("yt"))]),
                Move([("X", a1)]),
                Move([("G1", ""), ("X", a1), ("Y", a2)]),
            ]
            self.subs.append(SubDef(name, body))
            call = Call(name, args[:4])
            first = (px0, py0)
            r_cap = (min(w, h) - 1) / 4.8 if inside else 6
        if inside:
            start = (add(px0, Num(lit(w * k / 2))), add(py0, Num(lit(h * k / 2))))
        else:
            start = (sub(first[0], Num(lit(rnd.uniform(8, 20) * k))),
                     sub(first[1], Num(lit(rnd.uniform(12, 25) * k))))
        out.append(Move([("G0", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G1", ""), ("Z", self.depth_expr())]))
        words, rad, setup = self.comp_on(ccw, inside, r_cap)
        out += setup
        out.append(Move(words + [("G1", ""), ("X", first[0]), ("Y", first[1])]))
        out.append(call)
        out.append(Raw("G40"))
        out.append(Move([("G1", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        return out

    def polar_polygon(self):
        """Polygon vertices from value-returning subroutines (#<_value>), one call per axis,
        nested in a loop; comp around the loop. Inline function or the library o<mx_polar>."""
        rnd = self.rnd
        k = self.k
        lib = rnd.random() < 0.5
        n = rnd.randint(3, 8)
        r_mm = rnd.uniform(15, 35)
        cx, cy = rnd.uniform(-50, 50), rnd.uniform(-50, 50)
        out = []
        st, pcx, _ = self.setp(cx * k)
        out.append(st)
        st, pcy, _ = self.setp(cy * k)
        out.append(st)
        st, pr, rv = self.setp(r_mm * k, depth=1)
        out.append(st)
        if lib:
            self.uses_library = True
            fname = "mx_polar"
        else:
            fname = self.sub_name()
            if rnd.random() < 0.5:
                self.subs.append(SubDef(fname, [
                    If(self.new_label(), [(Bin("EQ", P(5), Num("0")),
                                           [Return(fname, add(P(1), mul(P(3), Fun("COS", P(4)))))])]),
                ], value=add(P(2), mul(P(3), Fun("SIN", P(4))))))
            else:
                loc = P(self.name())
                self.subs.append(SubDef(fname, [
                    Assign([(loc, add(P(2), mul(P(3), Fun("SIN", P(4)))))]),
                    If(self.new_label(), [(Bin("NE", P(5), Num("1")),
                                           [Assign([(loc, add(P(1), mul(P(3), Fun("COS", P(4)))))])])]),
                ], value=loc))
        pa = self.par()
        px, py = self.par(), self.par()
        a0 = rnd.uniform(0, 360)
        sg = 1 if rnd.random() < 0.5 else -1
        out.append(Assign([(pa, Num(lit(a0)))]))
        calls = [Call(fname, [pcx, pcy, pr, pa, Num("0")]), Assign([(px, P("_value"))]),
                 Call(fname, [pcx, pcy, pr, pa, Num("1")]), Assign([(py, P("_value"))])]
        pe = self.par()
        out.append(Assign([(pe, add(pr, Num(lit(rnd.uniform(15, 25) * k))))]))
        start = (add(pcx, mul(pe, Fun("COS", pa))), add(pcy, mul(pe, Fun("SIN", pa))))
        out.append(Move([("G0", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G1", ""), ("Z", self.depth_expr())]))
        # outside comp (a0 arbitrary: the entry comes from +X, far enough out)
        words, rad, setup = self.comp_on(sg > 0, False, min(r_mm / 3, 6))
        out += setup
        out.append(Move(words))
        out += calls
        out.append(Move([("G1", ""), ("X", px), ("Y", py)]))
        lab = self.new_label()
        out.append(Repeat(lab, Num(str(n)), [
            Assign([(pa, add(pa, Num(lit(sg * 360.0 / n, 8))))]),
        ] + calls + [Move([("G1", ""), ("X", px), ("Y", py)])]))
        out.append(Raw("G40"))
        out.append(Move([("G1", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        return out

    def zigzag(self):
        """Uncompensated raster with a do-while: the X end of each row computed from the row
        parity with comparison arithmetic."""
        rnd = self.rnd
        k = self.k
        out = []
        rows = rnd.randint(2, 6)
        st, px0, _ = self.setp(rnd.uniform(-60, 20) * k)
        out.append(st)
        st, pw, _ = self.setp(rnd.uniform(10, 50) * k, depth=1)
        out.append(st)
        py_, prow = self.par(), self.par()
        out.append(Assign([(py_, self.num(rnd.uniform(-60, 20) * k)), (prow, Num("0"))]))
        out.append(Move([("G0", ""), ("X", px0), ("Y", py_)]))
        out.append(Move([("G1", ""), ("Z", self.depth_expr())]))
        dy = lit(rnd.uniform(2, 8) * k)
        lab = self.new_label()
        xe = add(px0, mul(pw, Bin("EQ", Bin("MOD", prow, Num("2")), Num("0"), paren=True)))
        body = [
            Move([("G1", ""), ("X", xe)], post=[(py_, add(py_, Num(dy)))]),
            Move([("G1", ""), ("Y", py_)]),
            Assign([(prow, add(prow, Num("1")))]),
        ]
        cond = Bin("LT", prow, Num(str(rows)))
        out.append(While(lab, cond, body) if self.while_break else DoWhile(lab, body, cond))
        out.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        return out

    def branches(self):
        """if / elseif / else picking one of several shapes (only the chosen one runs)."""
        rnd = self.rnd
        nb = rnd.randint(2, 3)
        sel = rnd.randrange(nb + 1)
        st, psel, _ = self.setp(sel, integral=True, depth=1)
        lab = self.new_label()
        bodies = []
        for j in range(nb + 1):
            before = dict(self.known)
            bodies.append(self.polygon(comp=rnd.random() < 0.7, loop=rnd.choice(("while", "repeat", "do"))))
            if j != sel:                    # never runs: its parameters stay unset
                self.known = before
        conds = [Bin("EQ", psel, Num(str(j))) for j in range(nb)]
        if rnd.random() < 0.3:
            conds[0] = Bin("LT", psel, Num("0.5"))
        return [st, If(lab, list(zip(conds, bodies[:nb])), bodies[nb])]

    def comp_across(self):
        """Compensation on in the caller, the contour in a subroutine that itself loops, a nested
        call (the subroutine calls another for every side), G40 back in the caller."""
        rnd = self.rnd
        k = self.k
        out = []
        n = rnd.randint(3, 7)
        r_mm = rnd.uniform(18, 40)
        cx, cy = rnd.uniform(-50, 50), rnd.uniform(-50, 50)
        side = self.sub_name()
        shape = self.sub_name()
        while shape == side:
            shape = self.sub_name()
        # side subroutine: one G1 to the vertex #1 of the polygon (#2 cx, #3 cy, #4 r, #5 da)
        self.subs.append(SubDef(side, [
            Assign([(P("a"), mul(P(1), P(5)))]),
            Move([("G1", ""), ("X", add(P(2), mul(P(4), Fun("COS", P("a"))))),
                  ("Y", add(P(3), mul(P(4), Fun("SIN", P("a")))))]),
        ]))
        lab = self.new_label()
        self.subs.append(SubDef(shape, [
            Assign([(P("j"), Num("1"))]),
            While(lab, Bin("LE", P("j"), P(4)), [
                Call(side, [P("j"), P(1), P(2), P(3), div(Num("360"), P(4))]),
                Assign([(P("j"), add(P("j"), Num("1")))]),
            ]),
        ], value=P("j") if rnd.random() < 0.5 else None))
        st, pcx, _ = self.setp(cx * k)
        out.append(st)
        st, pcy, _ = self.setp(cy * k)
        out.append(st)
        st, pr, rv = self.setp(r_mm * k, depth=1)
        out.append(st)
        # local #1..#3 of the main program survive the calls
        keep = rnd.random() < 0.5
        if keep:
            out.append(Assign([(P(1), Num("7")), (P(2), Num("-3"))]))
        start = (add(pcx, Num(lit((r_mm + 20) * k))), add(pcy, Num(lit(-2 * k))))
        out.append(Move([("G0", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G1", ""), ("Z", self.depth_expr())]))
        words, rad, setup = self.comp_on(True, False, min(r_mm / 3, 6))
        out += setup
        out.append(Move(words + [("G1", ""), ("X", add(pcx, pr)), ("Y", pcy)]))
        out.append(Call(shape, [pcx, pcy, pr, Num(str(n))]))
        out.append(Raw("G40"))
        if keep:
            out.append(Move([("G1", ""), ("X", add(start[0], P(1))), ("Y", add(start[1], P(2)))]))
        else:
            out.append(Move([("G1", ""), ("X", start[0]), ("Y", start[1])]))
        out.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        return out

    def comp_inside_sub_loop(self):
        """A subroutine that turns compensation on and off, called from a loop with moving
        centres (comp switched inside a subroutine inside a loop)."""
        rnd = self.rnd
        k = self.k
        name = self.sub_name()
        body = self.polygon(comp=True, loop=rnd.choice(("while", "repeat", "do")),
                            arcs=rnd.choice((None, "R")), centre_args=True)
        self.subs.append(SubDef(name, body))
        out = []
        px, py = self.par(), self.par()
        out.append(Assign([(px, self.num(rnd.uniform(-80, 0) * k)), (py, self.num(rnd.uniform(-60, 60) * k))]))
        lab = self.new_label()
        out.append(Repeat(lab, Num(str(rnd.randint(2, 3))), [
            Call(name, [px, py]),
            Assign([(px, add(px, Num(lit(100 * k))))]),
        ]))
        return out

    def error(self):
        """An intended error block (statements)."""
        rnd = self.rnd
        kind = rnd.choice(("undefined", "undefined_in_sub", "divzero", "divzero_loop",
                           "unknown_call", "stray_endwhile"))
        self.fail = kind
        if kind == "undefined":
            nm = "nodef" + str(rnd.randrange(100))
            return [Move([("G1", ""), ("X", add(Num("1"), P(nm)))])]
        if kind == "undefined_in_sub":
            nm = "callerlocal" + str(rnd.randrange(100))
            name = self.sub_name()
            self.subs.append(SubDef(name, [Move([("G1", ""), ("X", P(nm))])]))
            return [Assign([(P(nm), Num("2"))]), Call(name)]
        if kind == "divzero":
            pz = self.par()
            return [Assign([(pz, sub(Num("3"), Num("3")))]),
                    Move([("G1", ""), ("X", div(Num("10"), pz))])]
        if kind == "divzero_loop":
            # compensation on, the third iteration divides by zero
            pi = self.par()
            lab = self.new_label()
            words, _, setup = self.comp_on(True, False, 5)
            start = [Move([("G0", ""), ("X", Num(lit(-100 * self.k))), ("Y", Num(lit(-80 * self.k)))])]
            return setup + start + [
                Move(words + [("G1", ""), ("X", Num(lit(-100 * self.k))), ("Y", Num(lit(-100 * self.k)))]),
                Assign([(pi, Num("0"))]),
                While(lab, Bin("LT", pi, Num("5")), [
                    Assign([(pi, add(pi, Num("1")))]),
                    Move([("G1", ""), ("X", Num(lit(-100 * self.k))),
                          ("Y", add(Num(lit(-100 * self.k)), div(Num(lit(10 * self.k)), sub(pi, Num("3")))))]),
                ]),
            ]
        if kind == "unknown_call":
            return [Call("nosuch%d" % rnd.randrange(100))] if rnd.random() < 0.6 else [Call(9999)]
        lab = self.new_label()
        return [Fail("%s endwhile" % ow(lab), "%%d: undefined O-word label: '%s endwhile'" % ow(lab))]

    # -- program -----------------------------------------------------------------------------
    def program(self):
        rnd = self.rnd
        k = self.k
        header = [Raw("(generate_macros.py seed %d)" % self.seed),
                  Raw("%s G17 G90 G94 G40 G49" % ("G20" if self.inch else "G21"))]
        main = []
        main.append(Assign([(P("_gsafe"), Num(lit(5 * k)))]))
        self.known["_gsafe"] = (P("_gsafe"), float(lit(5 * k)))
        st, pf, fv = self.setp(rnd.uniform(200, 1500) * k, glob=True, depth=1)
        main.append(st)
        main.append(Move([("F", pf)]))
        if rnd.random() < 0.3:
            t = rnd.choice(sorted(self.tools))
            main.append(Raw("T%d M6" % t))
            main.append(Raw("G43"))
        main.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        features = [rnd.choice(("polygon", "polygon", "polygon", "holes", "rect", "polar",
                                "zigzag", "branches", "across", "subloop"))
                    for _ in range(rnd.randint(1, 4))]
        err_at = rnd.randrange(len(features) + 1) if rnd.random() < 0.04 else None
        for j, f in enumerate(features):
            if j == err_at:
                main += self.error()
            if f == "polygon":
                main += self.polygon(comp=rnd.random() < 0.8)
            elif f == "holes":
                main += self.holes()
            elif f == "rect":
                main += self.rect()
            elif f == "polar":
                main += self.polar_polygon()
            elif f == "zigzag":
                main += self.zigzag()
            elif f == "branches":
                main += self.branches()
            elif f == "across":
                main += self.comp_across()
            else:
                main += self.comp_inside_sub_loop()
            if rnd.random() < 0.2:
                main.append(Move([("F", mul(pf, Num(lit(rnd.choice((0.5, 1.5, 2))))))]))
        if err_at == len(features):
            main += self.error()
        main.append(Move([("G0", ""), ("Z", P("_gsafe"))]))
        main.append(Raw("M2"))
        tree = header + self.subs + main
        return tree


class _ValueMachine(Machine):
    """Evaluates setup expressions at generation time from the known global parameters."""

    def __init__(self, known):
        super().__init__()
        for key, (p, v) in known.items():
            self.set(key, v)


def _indent(tree, rnd):
    """Render a tree (list of statements) as program text; nested blocks indented sometimes."""
    lines = []
    for s in tree:
        lines += s.lines("")
    if rnd.random() < 0.5:                               # flat: no indentation at all
        lines = [l.strip() for l in lines]
    return "\n".join(lines) + "\n"


class Generated:
    """One generated program: ``text``; ``unrolled`` (None for error programs); ``error``: the
    model's error message (None: LinuxCNC must accept the program) with ``%s`` for the program
    path and ``%d`` for a line number; ``fail``: the kind of intended error; ``uses_library``:
    calls a subroutine file of tests/programs/macros/subs."""

    def __init__(self, seed, text, unrolled, error, fail, uses_library):
        self.seed, self.text, self.unrolled, self.error = seed, text, unrolled, error
        self.fail, self.uses_library = fail, uses_library

    def error_regex(self) -> str | None:
        """A regular expression for LinuxCNC's message (placeholders become wildcards)."""
        if self.error is None:
            return None
        parts = re.split(r"(%s|%d)", self.error)
        return "^" + "".join({"%s": ".+", "%d": r"\d+"}.get(x, re.escape(x)) for x in parts) + "$"


def build(seed: int) -> Generated:
    """Generate the program of ``seed`` and run the model on it."""
    g = _Gen(seed)
    tree = g.program()
    text = _indent(tree, random.Random(seed * 7919 + 1))
    m = Machine(LIBRARY)
    err = None
    try:
        Block(tree).run(m)
    except LinuxCNCError as e:
        err = str(e)
    if (err is None) != (g.fail is None):
        raise RuntimeError("seed %d: intended error %r, model says %r" % (seed, g.fail, err))
    unr = None if err else "\n".join(["(unrolled: generate_macros.py seed %d)" % seed] + m.lines) + "\n"
    return Generated(seed, text, unr, err, g.fail, g.uses_library)


def generate(seed: int) -> str:
    """Program text for ``seed`` (deterministic)."""
    return build(seed).text


def unrolled(seed: int) -> str | None:
    """The same program without parameters or O-words (None for the error programs)."""
    return build(seed).unrolled


if __name__ == "__main__":
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 0
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    out = Path(sys.argv[3]) if len(sys.argv) > 3 else Path(".")
    out.mkdir(parents=True, exist_ok=True)
    for s in range(seed, seed + count):
        gen = build(s)
        (out / ("macro_%d.ngc" % s)).write_text(gen.text)
        if gen.unrolled is not None:
            (out / ("macro_%d_unrolled.ngc" % s)).write_text(gen.unrolled)
