"""A plain-Python writer of the G-code export (the engine's is cpp/src/path_gcode.cpp): the
same rules written out independently, one segment at a time with Python's own float
formatting, for test_export_text.py to compare the engine's text with, byte for byte.
"""
from __future__ import annotations

import math
from typing import List

import numpy as np

from toolcomp import _core
from toolcomp.plot import _ARC_PLANES as _PLANE_AXES

DIALECTS = ("linuxcnc", "fanuc", "grbl")
_PLANE_WORD = ("G17", "G18", "G19")
# centre word of each axis; _PLANE_AXES gives (first, second, applicate) per plane
_CENTRE_WORD = ("I", "J", "K")


def _num(v: float, digits: int) -> str:
    s = f"{v:.{digits}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s == "-0" else s


def _sweep(start, end, centre, plane: int, ccw: bool, turns: int) -> float:
    a, b, _ = _PLANE_AXES[plane]
    a0 = math.atan2(start[b] - centre[b], start[a] - centre[a])
    a1 = math.atan2(end[b] - centre[b], end[a] - centre[a])
    d = (a1 - a0) if ccw else (a0 - a1)
    d %= 2 * math.pi
    if d < 1e-12:
        d = 2 * math.pi
    return d + 2 * math.pi * turns


def _arc_pieces(start, end, centre, plane: int, ccw: bool, turns: int):
    """Split an arc of several turns into full circles and the rest (for controls without P)."""
    a, b, h = _PLANE_AXES[plane]
    total = _sweep(start, end, centre, plane, ccw, turns)
    rest = total - 2 * math.pi * turns
    pieces = []
    p = np.array(start, dtype=float)
    for _ in range(turns):
        q = p.copy()
        q[h] += (end[h] - start[h]) * (2 * math.pi / total)
        pieces.append((p, q))
        p = q
    pieces.append((p, np.array(end, dtype=float)))
    assert rest > 0
    return pieces


def to_gcode(path: "_core.Path", dialect: str = "linuxcnc", *, digits: int = 6,
             comments: bool = True, tool_length: bool = True) -> str:
    """The path as a G-code program of ``dialect`` (``linuxcnc``, ``fanuc`` or ``grbl``).

    ``digits`` decimals are written (6: 1e-6 mm). With ``comments``, the blocks of each source
    line of the original program are preceded by ``(line N)``.
    """
    if dialect not in DIALECTS:
        raise ValueError(f"unknown export dialect {dialect!r} (expected one of {', '.join(DIALECTS)})")
    n = len(path)
    kind, start, end, centre = path.kind, path.start, path.end, path.center
    if tool_length:
        start, end, centre = (a + path.tool_offset for a in (start, end, centre))
    plane, turns, feed, abc, src = path.plane, path.turns, path.feed, path.abc, path.line
    for i in range(1, n):
        if np.max(np.abs(start[i] - end[i - 1])) > 1e-9:
            raise ValueError(f"the path jumps before the move of line {int(src[i])} (a work "
                             "offset or, with tool_length=False, a tool length offset changed); it cannot be written as one program")
    out: List[str] = []
    if dialect == "fanuc":
        out.append("%")
    out.append("G21 G90 G94 G40 G17" + (" G91.1" if dialect == "linuxcnc" else ""))
    cur_plane, cur_feed, cur_line = 0, math.nan, None
    cur_abc = np.zeros(3)
    pos = np.zeros(3) if n == 0 else np.array(start[0], dtype=float)
    if n and np.max(np.abs(pos)) > 1e-9:
        out.append("G0 " + " ".join(f"{ax}{_num(v, digits)}" for ax, v in zip("XYZ", pos)))

    def words_to(p, q) -> str:
        return " ".join(f"{ax}{_num(q[k], digits)}" for k, ax in enumerate("XYZ")
                        if _num(q[k], digits) != _num(p[k], digits) or k == 0)

    for i in range(n):
        k = int(kind[i])
        if comments and int(src[i]) != cur_line:
            cur_line = int(src[i])
            out.append(f"(line {cur_line})")
        words: List[str] = []
        if k in (_core.ARC_CW, _core.ARC_CCW) and int(plane[i]) != cur_plane:
            cur_plane = int(plane[i])
            words.append(_PLANE_WORD[cur_plane])
        rot = "".join(f" {ax}{_num(abc[i][j], digits)}" for j, ax in enumerate("ABC")
                      if _num(abc[i][j], digits) != _num(cur_abc[j], digits))
        cur_abc = np.array(abc[i], dtype=float)
        if k == _core.RAPID:
            out.append(" ".join(words + ["G0", words_to(start[i], end[i])]) + rot)
            continue
        f = ""
        if math.isnan(feed[i]):
            raise ValueError(f"the move of line {int(src[i])} has no known feed rate")
        if _num(feed[i], digits) != _num(cur_feed, digits):
            f = f" F{_num(feed[i], digits)}"
            cur_feed = float(feed[i])
        if k == _core.LINE:
            out.append(" ".join(words + ["G1", words_to(start[i], end[i])]) + rot + f)
            continue
        if k not in (_core.ARC_CW, _core.ARC_CCW):
            raise ValueError(f"segment {i} (line {int(src[i])}) has kind {k}, which has no G-code form")
        g = "G3" if k == _core.ARC_CCW else "G2"
        a, b, _ = _PLANE_AXES[cur_plane]
        t = int(turns[i])
        pieces = ([(start[i], end[i])] if dialect == "linuxcnc" or t == 0
                  else _arc_pieces(start[i], end[i], centre[i], cur_plane, k == _core.ARC_CCW, t))
        for j, (p, q) in enumerate(pieces):
            ij = " ".join(f"{_CENTRE_WORD[ax]}{_num(centre[i][ax] - p[ax], digits)}" for ax in (a, b))
            pw = f" P{t + 1}" if dialect == "linuxcnc" and t else ""
            out.append(" ".join(words + [g, words_to(p, q), ij]) + pw + (rot if j == len(pieces) - 1 else "") + f)
            words, f = [], ""
    out.append("M30" if dialect == "fanuc" else "M2")
    if dialect == "fanuc":
        out.append("%")
    return "\n".join(out) + "\n"

