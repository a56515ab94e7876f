"""Assertion helpers for NC program tests (pytest or plain asserts).

    import toolcomp as tc
    from toolcomp.testing import assert_no_errors, assert_within, assert_no_gouge, assert_paths_close

    res = tc.run("bracket.ngc", tools="mill.tbl")
    assert_no_errors(res)
    assert_within(res.path, ((-5, -5, -12), (205, 105, 100)))     # travel limits, mm
    assert_no_gouge(res, contour=[(0, 0), (100, 0), (100, 50)], radius=5)

Each raises AssertionError with the source line of the first offending segment.
"""
from __future__ import annotations

from typing import Optional

import math

import numpy as np

from . import _core


def _format(d) -> str:
    return f"line {d.line}:{d.column}: {d.severity} {d.code} {d.message}"


def assert_no_errors(res: "_core.Result", warnings: bool = False) -> None:
    """No error diagnostics (and no warnings either with ``warnings=True``)."""
    bad = [d for d in res.diagnostics if d.severity == "error" or (warnings and d.severity == "warning")]
    if bad:
        raise AssertionError("program diagnostics:\n" + "\n".join(_format(d) for d in bad))


def _check(name: str, value, *, positive: bool = False) -> float:
    """A tolerance or radius the assertion can test against: finite, >= 0 (> 0 if
    ``positive``). A NaN would make every comparison false: the assertion would pass."""
    v = float(value)
    if not math.isfinite(v) or v < 0 or (positive and v == 0):
        raise ValueError(f"{name} must be a finite number {'> 0' if positive else '>= 0'}, not {value!r}")
    return v


def _points(path: "_core.Path", tolerance: float, tool_offset: bool):
    pts, seg = path.sample(tolerance)
    if tool_offset and len(seg):
        pts = pts + path.tool_offset[seg]
    return pts, seg


def assert_within(path: "_core.Path", box, *, tolerance: float = 0.001, tool_offset: bool = False) -> None:
    """Every point of the path (arcs sampled within ``tolerance``) lies in ``box`` =
    ((xmin, ymin, zmin), (xmax, ymax, zmax)) in path coordinates (plus the tool length
    offset with ``tool_offset=True``)."""
    lo, hi = (np.asarray(b, dtype=float) for b in box)
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()) or (lo > hi).any():
        raise ValueError(f"box must be two finite corners, the first not above the second: {box!r}")
    pts, seg = _points(path, _check("tolerance", tolerance, positive=True), tool_offset)
    out = np.any((pts < lo - 1e-9) | (pts > hi + 1e-9), axis=1)
    if out.any():
        i = int(np.argmax(out))
        raise AssertionError(f"point {np.round(pts[i], 6).tolist()} of the move of line "
                             f"{int(path.line[seg[i]])} is outside {lo.tolist()}..{hi.tolist()}")


def _polyline(contour) -> np.ndarray:
    if hasattr(contour, "exterior"):  # shapely Polygon
        contour = contour.exterior.coords
    elif hasattr(contour, "coords"):  # shapely LineString
        contour = contour.coords
    c = np.asarray(contour, dtype=float)[:, :2]
    if len(c) < 2:
        raise ValueError("contour needs at least two points")
    if not np.isfinite(c).all():
        raise ValueError("contour points must be finite numbers")
    return c


def _chords(path, tolerance):
    """Each segment as the straight pieces of its XY track (arcs chorded within
    ``tolerance``): start and end points (k, 2) and the segment of each piece."""
    pts, seg = path.sample(tolerance)
    if len(seg) == 0:
        return np.zeros((0, 2)), np.zeros((0, 2)), seg
    # A piece runs from the point before to this one; a segment's first piece from its start.
    first = np.ones(len(seg), dtype=bool)
    first[1:] = seg[1:] != seg[:-1]
    start = np.asarray(path.start)[seg, :2]
    a = np.where(first[:, None], start, np.roll(pts[:, :2], 1, axis=0))
    return a, pts[:, :2], seg


def _xy_elements(path, tolerance):
    """The XY track of each move as elements: lines as they are, arcs in the XY plane as arcs
    (centre and turn: +1 counter-clockwise, -1 clockwise, +-2 a whole circle), arcs in other
    planes as chords within ``tolerance``. Ends (k, 2), centres, turns and the move of each."""
    kind, plane = np.asarray(path.kind), np.asarray(path.plane)
    arc = kind >= _core.ARC_CW
    whole = ~arc | (plane == 0)
    idx = np.flatnonzero(whole)
    a, b = np.asarray(path.start)[idx, :2], np.asarray(path.end)[idx, :2]
    c = np.nan_to_num(np.asarray(path.center)[idx, :2])
    sense = np.where(kind[idx] == _core.ARC_CCW, 1, -1)
    turn = np.where(arc[idx], sense * np.where(np.asarray(path.turns)[idx] > 0, 2, 1), 0).astype(np.int8)
    if whole.all():
        return a, b, c, turn, idx
    ca, cb, cseg = _chords(path, tolerance)
    keep = ~whole[cseg]
    a, b = np.concatenate([a, ca[keep]]), np.concatenate([b, cb[keep]])
    c = np.concatenate([c, np.zeros((int(keep.sum()), 2))])
    turn = np.concatenate([turn, np.zeros(int(keep.sum()), dtype=np.int8)])
    return a, b, c, turn, np.concatenate([idx, cseg[keep]])


def assert_no_gouge(res: "_core.Result", contour, radius: float, *, tol: float = 1e-6,
                    tolerance: float = 0.001, rapids: bool = False) -> None:
    """No compensated feed move comes closer than ``radius - tol`` to the contour (an (N, 2)
    polyline or a shapely geometry) in XY: the cutter does not cut into the part. The whole
    track of each move is measured exactly, not only its end points (a line passing a corner
    of the contour between its ends); arcs in the XY plane (helices too) are measured as
    arcs, arcs in other planes as chords within ``tolerance`` mm. Only moves with
    compensation on are checked; the first one that comes too close (in path order) is
    reported with its line and the point where it comes closest."""
    path = res.path if hasattr(res, "path") else res  # a Result, or a Path given directly
    radius, tol = _check("radius", radius, positive=True), _check("tol", tol)
    tolerance = _check("tolerance", tolerance, positive=True)
    c = _polyline(contour)
    a, b, centre, turn, seg = _xy_elements(path, tolerance)
    keep = np.asarray(path.side)[seg] != 0
    if not rapids:
        keep &= np.asarray(path.kind)[seg] != _core.RAPID
    if not keep.any():
        return
    a, b, centre, turn, seg = a[keep], b[keep], centre[keep], turn[keep], seg[keep]
    d, at = _core._nearest_segments(a, b, c[:-1], c[1:], radius - tol, centre, turn)
    bad = np.flatnonzero(d < radius - tol)
    if len(bad):
        s = seg[bad].min()
        mine = bad[seg[bad] == s]
        worst = mine[np.argmin(d[mine])]  # that move's closest piece
        raise AssertionError(f"the tool comes {radius - d[worst]:.6f} mm into the contour at "
                             f"{np.round(at[worst], 6).tolist()} (move of line {int(path.line[s])})")


def assert_paths_close(a: "_core.Path", b: "_core.Path", tol: float = 1e-6, *,
                       what: Optional[str] = None) -> None:
    """Same segments (kind, end points, arc centres, turns) within ``tol`` mm."""
    tol = _check("tol", tol)
    name = f"{what}: " if what else ""
    if len(a) != len(b):
        raise AssertionError(f"{name}{len(a)} segments against {len(b)}")
    for col in ("kind", "turns"):
        diff = np.nonzero(getattr(a, col) != getattr(b, col))[0]
        if len(diff):
            i = int(diff[0])
            raise AssertionError(f"{name}segment {i} (line {int(a.line[i])}): {col} "
                                 f"{getattr(a, col)[i]} against {getattr(b, col)[i]}")
    arcs = a.kind >= _core.ARC_CW
    errs = {}
    for col in ("start", "end", "center"):
        e = np.abs(getattr(a, col) - getattr(b, col)).max(axis=1) if len(a) else np.zeros(0)
        errs[col] = np.where(arcs, e, 0) if col == "center" else e
    worst = np.maximum.reduce(list(errs.values())) if len(a) else np.zeros(0)
    over = np.nonzero(worst > tol)[0]
    if len(over):
        i = int(over[0])  # the first segment that differs, and its worst column
        col = max(errs, key=lambda c: errs[c][i])
        x, y = getattr(a, col)[i], getattr(b, col)[i]
        raise AssertionError(f"{name}segment {i} (line {int(a.line[i])}): {col} "
                             f"{np.round(x, 9).tolist()} against {np.round(y, 9).tolist()}")


__all__ = ["assert_no_errors", "assert_within", "assert_no_gouge", "assert_paths_close"]
