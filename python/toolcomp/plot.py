"""Plot programmed and compensated tool paths with matplotlib.

matplotlib is an optional dependency (``pip install toolcomp[plot]``); it is imported only
inside the functions that draw, so ``import toolcomp.plot`` is cheap and works without it.

    import toolcomp as tc
    from toolcomp.plot import plot_result, save_plot
    res = tc.run("part.ngc", tools="tools.tbl")
    ax = plot_result(res, plane="xy")
    save_plot(res, "part.png")

The geometry helpers here (:func:`sample_path`, :func:`segment_lengths`) need only numpy.
"""

from __future__ import annotations

import math
import os
import sys

from typing import Any, Callable, Optional, Union

import numpy as np

from ._core import ARC_CCW, ARC_CW, LINE, RAPID
from ._optional import require

KIND_NAMES = {RAPID: "rapid", LINE: "line", ARC_CW: "arc_cw", ARC_CCW: "arc_ccw"}

# Plane name -> (horizontal axis, vertical axis) as column indices of start/end.
PLANES = {
    "xy": (0, 1), "g17": (0, 1),
    "xz": (0, 2), "zx": (2, 0), "g18": (2, 0),
    "yz": (1, 2), "g19": (1, 2),
    "lathe": (2, 0),  # half section: Z horizontal, X (radius) vertical, spindle axis drawn
}
_AXIS_NAMES = "XYZ"

# Arc planes as (first in-plane axis, second in-plane axis, normal): a counter-clockwise
# arc turns from the first axis towards the second, seen from the tip of the normal
# (G17 about +Z, G18 about +Y, G19 about +X; all right-handed).
_ARC_PLANES = ((0, 1, 2), (2, 0, 1), (1, 2, 0))

DEFAULT_TOLERANCE = 1e-3  # mm, chord error when arcs are sampled for lengths
_SAME_POINT = 1e-9  # mm: points closer than this are the same point (the engine's tol::length)


# ---------------------------------------------------------------------------------------
# geometry (numpy only)
# ---------------------------------------------------------------------------------------

def _columns(path):
    """kind, start, end, center of a Path as plain numpy arrays."""
    kind = np.asarray(path.kind).astype(np.int64, copy=False).reshape(-1)
    n = kind.shape[0]
    start = np.asarray(path.start, dtype=float).reshape(n, 3)
    end = np.asarray(path.end, dtype=float).reshape(n, 3)
    center = np.asarray(path.center, dtype=float).reshape(n, 3)
    return kind, start, end, center


def path_size(path) -> int:
    """Number of segments of a Path (or of a Path-like object of columns, which may have no
    ``len``)."""
    try:
        return len(path)
    except TypeError:
        return int(np.asarray(path.kind).shape[0])


# Per plane index (the Path's `plane` column: 0 G17, 1 G18, 2 G19): first in-plane axis,
# second in-plane axis, normal.
_PLANE_A, _PLANE_B, _PLANE_N = (np.array(c) for c in zip(*_ARC_PLANES))
_MAX_CHORDS = 50_000_000  # per arc, as the engine's sampler


def _arc_planes(path, rows, start, end, center):
    """Plane index of the arcs ``rows`` of ``path`` (``start``, ``end``, ``center``: theirs):
    its ``plane`` column, or for a Path-like without one the plane in which start and end
    are equally far from the centre (ties to the earlier plane, G17 first)."""
    plane = getattr(path, "plane", None)  # a Path has one; a Path-like of columns may not
    if plane is not None:
        return np.clip(np.asarray(plane).reshape(-1)[rows].astype(np.intp), 0, 2)
    best = np.zeros(len(rows), dtype=np.intp)
    best_err = np.full(len(rows), np.inf)
    with np.errstate(invalid="ignore", divide="ignore"):
        for k, (a, b, _) in enumerate(_ARC_PLANES):
            rs = np.hypot(start[:, a] - center[:, a], start[:, b] - center[:, b])
            re = np.hypot(end[:, a] - center[:, a], end[:, b] - center[:, b])
            err = np.abs(rs - re) / np.maximum(1.0, rs)
            better = (rs > 0) & (err < best_err - 1e-9)  # False for a centre not given here
            best = np.where(better, k, best)
            best_err = np.where(better, err, best_err)
    return best


def _arc_chords(path, rows, tolerance, kind, start, end, center):
    """The arcs ``rows`` of ``path`` (``kind``, ``start``, ``end``, ``center``: theirs)
    sampled as the engine samples them (cpp/src/geometry/arc.cpp: plane and extra turns from
    the Path's columns, angle and radius linear in the parameter, chord count so that no
    chord leaves the arc by more than ``tolerance``).

    Returns ``(coordinates, counts (len(rows),))``: the X, Y and Z (three arrays of T) of
    each arc's points in order, start excluded, end included (exactly its ``end``).

    Why not ``Path.sample``: it samples the whole path, and a drawing needs only the arcs it
    draws after decimation. For the 1M-segment path of ``make bench`` (600k arcs, 74k of
    them drawn) ``path.sample`` takes 1.1 s (0.5 s more for the programmed path), this 0.07 s
    for the drawn arcs (0.54 s for all of them), and ``res.plot()`` 1.05 s in all: the
    engine's sampler would make it about 2.5 times slower. A Path-like of columns has no
    sampler at all.
    tests/python/test_plot_decimation.py checks that the points are the engine's."""
    m = len(rows)
    if m == 0:
        return [np.empty(0)] * 3, np.zeros(0, dtype=np.int64)
    plane = _arc_planes(path, rows, start, end, center)
    a, b, nrm = _PLANE_A[plane], _PLANE_B[plane], _PLANE_N[plane]
    i = np.arange(m)
    ca, cb = center[i, a], center[i, b]
    su, sv = start[i, a] - ca, start[i, b] - cb
    eu, ev = end[i, a] - ca, end[i, b] - cb
    r0, r1 = np.hypot(su, sv), np.hypot(eu, ev)
    direction = np.where(kind == ARC_CCW, 1.0, -1.0)
    turns = getattr(path, "turns", None)  # a Path has them; a Path-like of columns may not
    turns = np.zeros(m) if turns is None else np.asarray(turns).reshape(-1)[rows].astype(float)
    with np.errstate(invalid="ignore", divide="ignore"):
        sweep = np.arctan2(su * ev - sv * eu, su * eu + sv * ev) * direction  # (-pi, pi]
        sweep = np.where(sweep <= 1e-12, sweep + 2 * math.pi, sweep) + 2 * math.pi * turns
        r = np.maximum(r0, r1)
        step = np.where(r <= tolerance, math.pi / 8,
                        2 * np.arccos(np.clip(1 - tolerance / r, -1.0, 1.0)))
        count = np.ceil(sweep / step)
    count = np.where(np.isfinite(count), count, 1)
    if count.max(initial=0) > _MAX_CHORDS:
        raise ValueError(f"an arc would need more than {_MAX_CHORDS:,} chords at tolerance {tolerance}: "
                         "sample with a coarser tolerance")
    count = np.maximum(count, 1).astype(np.int64)
    total = int(count.sum())
    first = np.cumsum(count) - count

    def each(x):  # an arc's value at each of its points
        return np.repeat(x, count)

    u = np.arange(1, total + 1, dtype=float)
    u -= each(first.astype(float))
    u /= each(count.astype(float))
    phi = each(direction * sweep) * u
    phi += each(np.arctan2(sv, su))
    rad = each(r1 - r0) * u
    rad += each(r0)
    ns, ne = start[i, nrm], end[i, nrm]
    along = [each(ca) + rad * np.cos(phi), each(cb) + rad * np.sin(phi),
             each(ns) + each(ne - ns) * u]  # a helix rises linearly
    if plane.min() == plane.max():  # all in one plane
        xyz = [along[_ARC_PLANES[plane[0]].index(k)] for k in range(3)]
    else:
        on = each(plane)
        xyz = [np.empty(total) for _ in range(3)]
        for p, axes in enumerate(_ARC_PLANES):
            sel = on == p
            for col, axis in zip(along, axes):
                xyz[axis][sel] = col[sel]
    last = first + count - 1
    for k in range(3):
        xyz[k][last] = end[:, k]  # exact end points
    return xyz, count


def sample_path(path, tolerance=DEFAULT_TOLERANCE):
    """``path.sample(tolerance)``: an (M,3) polyline with arcs chorded within ``tolerance``
    and the segment index of every point.

    Uses the engine's own sampler; a Path-like object without one is sampled the same way
    by the sampler the drawing uses (:func:`_arc_chords`, which samples only the arcs it
    draws).
    """
    if hasattr(path, "sample"):  # a Path; a Path-like of columns has no sampler
        pts, idx = path.sample(tolerance)
        pts = np.asarray(pts, dtype=float).reshape(-1, 3)
        idx = np.asarray(idx).astype(np.int64, copy=False).reshape(-1)
        return pts, idx
    kind, start, end, center = _columns(path)
    n = kind.shape[0]
    if n == 0:
        return np.empty((0, 3)), np.empty(0, dtype=np.int64)
    arc = (kind == ARC_CW) | (kind == ARC_CCW)
    ai = np.flatnonzero(arc)
    xyz, counts = _arc_chords(path, ai, tolerance, kind[ai], start[ai], end[ai], center[ai])
    body = np.ones(n, dtype=np.int64)
    body[ai] = counts
    jump = np.ones(n, dtype=bool)  # the start point first, and where the path jumps
    jump[1:] = np.linalg.norm(start[1:] - end[:-1], axis=1) > _SAME_POINT
    last = np.cumsum(body + jump) - 1
    first = last - body + 1
    pts = np.empty((int(last[-1]) + 1, 3))
    pts[first[jump] - 1] = start[jump]
    line = np.flatnonzero(~arc)
    pts[last[line]] = end[line]
    if len(ai):
        at = np.repeat(first[ai] - np.cumsum(counts) + counts, counts) + np.arange(len(xyz[0]))
        for k in range(3):
            pts[at, k] = xyz[k]
    return pts, np.repeat(np.arange(n), body + jump)


def segment_polylines(path, tolerance=DEFAULT_TOLERANCE):
    """Every segment as a polyline of its own, lines and arcs alike.

    Returns ``(points (K,3), owner (K,))`` sorted by segment, where each segment's run
    starts at its ``start`` point, goes through the sampled points the engine gave for it
    and ends at its ``end`` point. This holds whatever convention the sampler uses for
    points shared by neighbouring segments.
    """
    kind, start, end, center = _columns(path)
    n = kind.shape[0]
    if n == 0:
        return np.empty((0, 3)), np.empty(0, dtype=np.int64)
    is_arc = (kind == ARC_CW) | (kind == ARC_CCW)
    if is_arc.any():
        pts, idx = sample_path(path, tolerance)
        keep = (idx >= 0) & (idx < n)
        keep[keep] &= is_arc[idx[keep]]  # lines need no interior points
        pts, idx = pts[keep], idx[keep]
    else:
        pts, idx = np.empty((0, 3)), np.empty(0, dtype=np.int64)
    seg = np.arange(n)
    allp = np.concatenate([start, pts, end])
    owner = np.concatenate([seg, idx, seg])
    order_in = np.concatenate([np.zeros(n), np.ones(len(idx)), np.full(n, 2.0)])
    rank = np.concatenate([np.zeros(n), np.arange(len(idx), dtype=float), np.zeros(n)])
    order = np.lexsort((rank, order_in, owner))
    return allp[order], owner[order]


def segment_lengths(path, tolerance=DEFAULT_TOLERANCE):
    """Length in mm of every segment: lines exactly, arcs and helices exactly too.

    ``path`` is a Path or a Path-like of columns (which may have no ``plane`` column), so
    the arc's plane and sweep are read off the points of :func:`sample_path`: the plane is the one in which every sampled point is at the
    same distance from the centre, and the sweep is the sum of the angles the chords
    subtend there. Length = sqrt((r * sweep)^2 + rise^2). An arc whose plane cannot be
    told falls back to its chorded length (short by about tolerance / (3 r), relative).
    """
    kind, start, end, center = _columns(path)
    n = kind.shape[0]
    lengths = np.linalg.norm(end - start, axis=1)
    is_arc = (kind == ARC_CW) | (kind == ARC_CCW)
    if not (n and is_arc.any()):
        return lengths
    pts, owner = segment_polylines(path, tolerance)
    sel = is_arc[owner]
    p, o = pts[sel], owner[sel]
    first = np.nonzero(np.r_[True, o[1:] != o[:-1]])[0]
    last = np.r_[first[1:] - 1, len(o) - 1]
    arcs = o[first]
    same = o[1:] == o[:-1]
    chords = np.linalg.norm(p[1:] - p[:-1], axis=1)
    best = np.bincount(o[1:][same], weights=chords[same], minlength=n)[arcs]
    best_dev = np.full(len(arcs), 1e-4)  # relative radius spread still "on the arc"
    c = center[o]
    with np.errstate(invalid="ignore"):
        for a, b, normal in _ARC_PLANES:
            du, dv = p[:, a] - c[:, a], p[:, b] - c[:, b]
            r = np.hypot(du, dv)
            r0 = r[first]
            spread = (np.maximum.reduceat(r, first) - np.minimum.reduceat(r, first))
            spread = spread / np.maximum(1.0, r0)
            step = np.diff(np.arctan2(dv, du))
            step = np.abs((step + np.pi) % (2 * np.pi) - np.pi)
            sweep = np.bincount(o[1:][same], weights=step[same], minlength=n)[arcs]
            rise = p[last, normal] - p[first, normal]
            exact = np.hypot(r0 * sweep, rise)
            better = spread < best_dev  # False for NaN (centre not given in this plane)
            best = np.where(better, exact, best)
            best_dev = np.where(better, spread, best_dev)
    lengths[arcs] = best
    return lengths


# ---------------------------------------------------------------------------------------
# what a figure can show: decimated polylines (numpy only)
# ---------------------------------------------------------------------------------------

_CHUNK = 1 << 17  # segments at a time: temporaries of 1 MB stay in the cache (and off huge pages)


def _segment_keys(path, columns, axes, cell):
    """Two 64-bit hashes per segment of what it looks like on a drawing of the coordinates
    ``axes`` to within a few ``cell``: the cell of its start in a grid of that size, the
    vectors from the start to its end and (arcs) its centre in cells, and for arcs their
    direction, plane and sweep to within half a turn. A line is the same from either end (it
    is keyed from the lower one); the coordinate the view looks along does not count,
    except for arcs that do not lie in the drawing's plane. Segments with equal keys are
    drawn once (:func:`_distinct`); vectors, not cells of the end and centre, so that a copy
    of a segment moved by less than a cell (the next pass of a CAM path) keys alike.

    Returns ``(h1, h2, short)``: ``short`` is True for segments that end in the cell they
    start in (arcs: of a radius within a cell too); a run of them is left to :func:`_thin`
    (the next of the run keys alike and would leave a gap if dropped)."""
    kind, start, end, center = columns
    n = len(kind)
    h1 = np.empty(n, dtype=np.uint64)
    h2 = np.empty(n, dtype=np.uint64)
    short = np.empty(n, dtype=bool)
    for i in range(0, n, _CHUNK):
        j = min(n, i + _CHUNK)
        h1[i:j], h2[i:j], short[i:j] = _chunk_keys(path, i, kind[i:j], start[i:j], end[i:j], center[i:j],
                                                   axes, cell)
    return h1, h2, short


def _chunk_keys(path, offset, kind, start, end, center, axes, cell):
    """:func:`_segment_keys` of the segments from ``offset`` on (their columns given)."""
    n = len(kind)
    inv = 1.0 / cell
    h1 = np.full(n, 0x243F6A8885A308D3, dtype=np.uint64)
    h2 = np.full(n, 0x13198A2E03707344, dtype=np.uint64)

    def mix(col):
        col += 0.0  # -0.0 and 0.0 alike
        bits = col.view(np.uint64)
        for h, mul in ((h1, 0x9E3779B97F4A7C15), (h2, 0xC2B2AE3D27D4EB4F)):
            h ^= bits
            h *= np.uint64(mul)
            h ^= h >> np.uint64(31)

    arc = (kind == ARC_CW) | (kind == ARC_CCW)
    ai = np.flatnonzero(arc)
    coords = list(axes)
    short = np.ones(n, dtype=bool)  # ends in the cell it starts in (an arc: and is that small)
    if len(ai):
        c, s, e = center[ai], start[ai], end[ai]
        plane = _arc_planes(path, ai + offset, s, e, c)
        a, b = _PLANE_A[plane], _PLANE_B[plane]
        j = np.arange(len(ai))
        su, sv = s[j, a] - c[j, a], s[j, b] - c[j, b]
        eu, ev = e[j, a] - c[j, a], e[j, b] - c[j, b]
        with np.errstate(invalid="ignore"):
            half_turns = np.floor(np.mod(np.arctan2(su * ev - sv * eu, su * eu + sv * ev)
                                         * np.where(kind[ai] == ARC_CCW, 1.0, -1.0) - 1e-12, 2 * math.pi) / math.pi)
        turns = getattr(path, "turns", None)  # as in _arc_chords
        turns = 0 if turns is None else np.asarray(turns).reshape(-1)[ai + offset]
        tag = np.zeros(n)
        tag[ai] = 1 + (kind[ai] == ARC_CCW) + 2 * plane + 6 * (half_turns + 2 * turns)
        mix(tag)
        short[ai] = np.hypot(su, sv) <= cell
        along = [k for k in range(3) if k not in axes]
        deep = ai[_PLANE_N[plane] != along[0]] if along else ai[:0]  # arcs whose depth shapes the drawing
        if len(deep):
            coords += along
    swap = np.zeros(n, dtype=bool)
    undecided = ~arc
    for k in axes:
        sk, ek = start[:, k], end[:, k]
        swap |= undecided & (ek < sk)
        undecided &= ek == sk
    any_swap = swap.any()
    col = np.empty(n)
    for k in coords:
        sk, ek = start[:, k], end[:, k]
        if any_swap:
            sk, ek = np.where(swap, ek, sk), np.where(swap, sk, ek)
        if k not in axes:  # the depth, of the arcs it shapes only
            for value in (sk[deep], ek[deep] - sk[deep], center[deep, k] - sk[deep]):
                col[:] = 0.0
                col[deep] = np.floor(value * inv)
                mix(col)
            continue
        np.multiply(sk, inv, out=col)
        np.floor(col, out=col)
        short &= np.floor(ek * inv) == col
        mix(col)
        np.subtract(ek, sk, out=col)
        col *= inv
        mix(np.floor(col, out=col))
        if len(ai):
            col[:] = 0.0
            col[ai] = np.floor((c[:, k] - sk[ai]) * inv)
            mix(col)
    mix(short.astype(float))
    return h1, h2, short


def _distinct(keys, rows, columns, axes):
    """Which of the segments ``rows`` (ascending) to draw: of those with equal keys
    (:func:`_segment_keys`), only the first; short ones only when neither neighbour in the
    path is drawn (one of a run of short segments is part of the line). The segments that
    reach the extremes of the drawn coordinates always, so the drawing's extent is exact."""
    m = len(rows)
    keep = np.ones(m, dtype=bool)
    if m < 2:
        return keep
    h1, h2, short = keys
    # The first hash's high bits, the segment's place in the low bits: one sort of integers
    # brings equal keys together, the first segment first. The second hash tells a collision
    # of the first from a duplicate.
    bits = max(1, int(m - 1).bit_length())
    low = np.uint64((1 << bits) - 1)
    packed = h1[rows]
    packed &= ~low
    packed |= np.arange(m, dtype=np.uint64)
    packed.sort()
    same = (packed[1:] >> np.uint64(bits)) == (packed[:-1] >> np.uint64(bits))
    later = (packed[1:][same] & low).astype(np.intp)
    earlier = (packed[:-1][same] & low).astype(np.intp)
    del packed, same
    equal = h2[rows[later]] == h2[rows[earlier]]
    later, earlier = later[equal], earlier[equal]
    is_short = short[rows[later]]  # equal keys: both short or both not
    keep[later[~is_short]] = False
    if is_short.any():
        drawn = np.zeros(len(h1) + 1, dtype=bool)  # by place in the path, one past the end
        drawn[rows[keep]] = True
        alone = ~drawn[rows - 1] & ~drawn[rows + 1]  # before the first: [-1], the spare one
        later, earlier = later[is_short], earlier[is_short]
        keep[later[alone[later] & alone[earlier]]] = False
    _, start, end, _ = columns
    for k in axes:
        for col in (start[:, k], end[:, k]):
            sub = col[rows]
            keep[np.argmin(sub)] = keep[np.argmax(sub)] = True
    return keep


class _Drawing:
    """A path as a drawing of the coordinates ``axes``: its segment keys computed once for
    the several polylines drawn of it (:func:`_polyline`)."""

    def __init__(self, path, axes, tolerance):
        self.path, self.axes, self.tolerance = path, tuple(axes), tolerance
        self.columns = _columns(path)
        self._keys = None

    @property
    def keys(self):
        if self._keys is None:
            self._keys = _segment_keys(self.path, self.columns, self.axes, self.tolerance)
        return self._keys

    def polyline(self, mask):
        return _polyline(self, mask)


def _polyline(drawing, mask):
    """The segments of a :class:`_Drawing`'s path selected by ``mask`` as one polyline in
    its coordinates (an (M, len(axes)) array), NaN rows where it is not continuous, arcs
    chorded within its tolerance, decimated to that tolerance: segments that coincide within
    it are drawn once (:func:`_distinct`), and of consecutive points in one cell of a grid of
    that size only the first and the last are kept (:func:`_thin`). The extremes of every
    coordinate are kept exactly."""
    path, axes, tolerance = drawing.path, drawing.axes, drawing.tolerance
    kind_all, start_all, end_all, center_all = drawing.columns
    rows = np.flatnonzero(mask)
    d = len(axes)
    if len(rows) == 0:
        return np.empty((0, d))
    rows = rows[_distinct(drawing.keys, rows, drawing.columns, axes)]
    m = len(rows)
    kind = kind_all[rows]
    arc = (kind == ARC_CW) | (kind == ARC_CCW)
    start, end = np.take(start_all, rows, axis=0), np.take(end_all, rows, axis=0)
    ax = list(axes)
    s, e = start[:, ax], end[:, ax]
    # continuous with the segment drawn before it: the next in the path and starting where it ended
    cont = np.zeros(m, dtype=bool)
    if m > 1:
        cont[1:] = (rows[1:] == rows[:-1] + 1) & np.all(np.abs(s[1:] - e[:-1]) <= _SAME_POINT, axis=1)
    ai = np.flatnonzero(arc)
    if len(ai):
        xyz, counts = _arc_chords(path, rows[ai], tolerance, kind[ai], start[ai], end[ai],
                                  np.take(center_all, rows[ai], axis=0))
    else:
        counts = np.zeros(0, dtype=np.int64)
    body = np.ones(m, dtype=np.int64)
    body[ai] = counts
    gap = ~cont  # a NaN row and the start point before the segment (only the start for the first)
    gap[0] = False
    lead = ~cont
    last = np.cumsum(body + lead + gap) - 1
    first = last - body + 1
    out = np.empty((int(last[-1]) + 1, d))
    out[first[gap] - 2] = np.nan
    out[first[lead] - 1] = s[lead]
    line = np.flatnonzero(~arc)
    out[last[line]] = e[line]
    if len(ai):
        at = np.repeat(first[ai] - np.cumsum(counts) + counts, counts) + np.arange(len(xyz[0]))
        for i, k in enumerate(ax):
            out[at, i] = xyz[k]
    return _thin(out, tolerance)


def _thin(out, cell):
    """Of consecutive points of a polyline (NaN rows between its pieces) that lie in one cell
    of a grid of ``cell`` mm, only the first and the last; the points at the extremes of
    every coordinate are kept."""
    if len(out) < 3:
        return out
    inv = 1.0 / cell
    same = None
    for k in range(out.shape[1]):
        q = np.floor(out[:, k] * inv)
        eq = q[1:] == q[:-1]  # NaN rows: never the same
        same = eq if same is None else same & eq
    inner = same[:-1] & same[1:]
    if not inner.any():
        return out
    keep = np.ones(len(out), dtype=bool)
    keep[1:-1] = ~inner
    with np.errstate(invalid="ignore"):
        for k in range(out.shape[1]):
            col = out[:, k]
            if not np.isnan(col).all():
                keep[np.nanargmin(col)] = keep[np.nanargmax(col)] = True
    return out[keep]


# ---------------------------------------------------------------------------------------
# drawing (matplotlib, imported lazily)
# ---------------------------------------------------------------------------------------

def _pyplot():
    """Import pyplot, choosing the Agg backend when nothing can show a window."""
    matplotlib = require("matplotlib", "plot", "Result.plot")

    headless = not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    if (headless and "matplotlib.pyplot" not in sys.modules
            and not os.environ.get("MPLBACKEND") and sys.platform.startswith("linux")):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _plane_axes(plane):
    try:
        return PLANES[str(plane).lower()]
    except KeyError:
        raise ValueError(f"plane must be one of {sorted(PLANES)}, not {plane!r}") from None


def _diagnostic_position(diag, path_points, line_col, last_point):
    """Where to mark a diagnostic: the start of the first segment of its line; an error
    after the last segment (the control stopped there) at the end of the path."""
    line = diag.line
    if line <= 0:
        return None
    if line_col is not None and len(line_col):
        hits = np.nonzero(line_col == line)[0]
        if len(hits):
            return path_points[hits[0]]
    if diag.severity == "error" and last_point is not None:
        return last_point
    return None


_TOOL_COLOURS = ("tab:blue", "tab:green", "tab:purple", "tab:brown", "tab:cyan",
                 "tab:olive", "tab:pink", "navy", "darkgreen", "indigo")
_SEVERITY_STYLE = {
    "error": dict(marker="X", color="crimson", s=70),
    "fatal": dict(marker="X", color="crimson", s=70),
    "warning": dict(marker="^", color="darkorange", s=55),
}


def _extent(path):
    """Lowest and highest X, Y, Z of the path's segment ends (finite ones), or None."""
    if path_size(path) == 0:
        return None
    _, start, end, _ = _columns(path)
    # a column at a time (a reduction across the rows of an (N, 3) array is slow); NaN ignored
    lo = np.array([min(np.fmin.reduce(p[:, k]) for p in (start, end)) for k in range(3)])
    hi = np.array([max(np.fmax.reduce(p[:, k]) for p in (start, end)) for k in range(3)])
    if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
        pts = np.concatenate([start, end])
        pts = pts[np.all(np.isfinite(pts), axis=1)]
        if not len(pts):
            return None
        lo, hi = pts.min(axis=0), pts.max(axis=0)
    return lo, hi


def _drawing_tolerance(path):
    """Chord tolerance fine enough to look round at any screen size: 1/20000 of the
    path's extent, at least 1 micron."""
    box = _extent(path)
    extent = float(np.linalg.norm(box[1] - box[0])) if box is not None else 0.0
    return max(DEFAULT_TOLERANCE, extent / 20000.0)


def plot_result(result: Any, ax: Any = None, plane: str = "xy", show_nominal: bool = True,
                tolerance: Optional[float] = None, title: Optional[str] = None, legend: bool = True,
                color_by: str = "tool") -> Any:
    """Draw a run result: programmed path thin grey, compensated path coloured by tool,
    rapids dashed, segments inserted by compensation highlighted, diagnostics marked with
    their line number. Arcs are drawn as arcs, chorded within ``tolerance`` mm (default:
    1/20000 of the path's extent, finer than a pixel at any reasonable zoom).

    Long paths are drawn as the figure can show them, to the same ``tolerance``: segments
    that coincide within it are drawn once, and of consecutive points closer than it only
    the first and last are kept; corners, small features and the extent of the path stay
    exact. A million segments draw in about a second.

    ``plane`` is "xy" (default), "xz", "zx", "yz", "g17"/"g18"/"g19", "lathe" (a half
    section: Z horizontal, X vertical, the spindle axis drawn) or "3d". ``color_by`` is
    "tool" or "side" (G41/RL blue, G42/RR green, uncompensated black). Returns the Axes.
    """
    return _plot_result(result, ax=ax, plane=plane, show_nominal=show_nominal, tolerance=tolerance,
                        title=title, legend=legend, color_by=color_by)


def _plot_result(result, ax=None, plane="xy", show_nominal=True, tolerance=None, title=None, legend=True,
                 color_by="tool", progress=None, steps_after=0):
    """:func:`plot_result`, telling ``progress(done, total, what)`` (if given) before each
    path it draws; ``steps_after``: steps the caller adds to the total (e.g. rendering)."""
    if str(plane).lower() == "3d":
        from .plot3d import plot_result_3d

        return plot_result_3d(result, ax=ax, show_nominal=show_nominal, tolerance=tolerance,
                              title=title, legend=legend, progress=progress, steps_after=steps_after)
    h, v = _plane_axes(plane)
    if color_by not in ("tool", "side"):
        raise ValueError(f"color_by must be 'tool' or 'side', not {color_by!r}")
    if ax is None:
        plt = _pyplot()
        _, ax = plt.subplots(figsize=(8.5, 6), layout="constrained")

    path, nominal = result.path, result.nominal
    if tolerance is None:
        tolerance = _drawing_tolerance(path)

    # The drawing's steps in order, as (what, function): each path's polyline, the marks.
    steps = []

    def polyline(drawing, mask, style):
        xy = drawing.polyline(mask)
        if len(xy):
            ax.plot(xy[:, 0], xy[:, 1], **style)

    def step(what, fn, *args):
        steps.append((what, lambda: fn(*args)))

    if show_nominal and nominal is not None and path_size(nominal):
        drawn = _Drawing(nominal, (h, v), tolerance)
        step("programmed path", polyline, drawn, drawn.columns[0] != RAPID,
             dict(color="0.55", lw=0.8, zorder=1, label="programmed"))

    n = path_size(path)
    last_point = None
    starts = line_col = None
    if n:
        drawn = _Drawing(path, (h, v), tolerance)
        kind, s, e, _ = drawn.columns
        feed = kind != RAPID
        tool = np.asarray(path.tool).reshape(-1)
        generated = np.asarray(path.generated, dtype=bool).reshape(-1)
        step("rapids", polyline, drawn, kind == RAPID,
             dict(color="crimson", lw=0.8, ls=(0, (4, 3)), alpha=0.7, zorder=2, label="rapid"))
        lo, hi = (int(tool.min()), int(tool.max())) if n else (0, 0)
        tools = ([lo] if feed.any() else []) if lo == hi else [int(t) for t in np.unique(tool[feed])]
        colour = {t: _TOOL_COLOURS[k % len(_TOOL_COLOURS)] for k, t in enumerate(tools)}
        if color_by == "side":
            side = np.asarray(path.side).reshape(-1)
            for sd, name, col in ((1, "left (G41 / RL)", "tab:blue"), (-1, "right (G42 / RR)", "tab:green"),
                                  (0, "uncompensated", "black")):
                step(f"compensated path, {name}", polyline, drawn, feed & (side == sd),
                     dict(color=col, lw=1.6, zorder=3, label=name, solid_capstyle="round"))
        else:
            for t in tools:
                label = f"T{t} compensated" if len(tools) > 1 else "compensated"
                step(f"compensated path, T{t}", polyline, drawn, feed & (tool == t) if len(tools) > 1 else feed,
                     dict(color=colour[t], lw=1.6, zorder=3, label=label, solid_capstyle="round"))

        def plunges():
            # Seen from above, feeds along Z only (plunges, drilled holes) have no extent in
            # the plot: mark where they are.
            if 3 - h - v != 2:
                return
            flat = np.hypot(e[:, h] - s[:, h], e[:, v] - s[:, v]) < 1e-9
            plunge = (kind == LINE) & flat & (np.abs(e[:, 2] - s[:, 2]) > 1e-9)
            label = "plunge / drill"
            for t in tools:
                sel = plunge & (tool == t)
                if sel.any():
                    spots = np.unique(np.round(e[sel][:, [h, v]], 6), axis=0)
                    ax.plot(spots[:, 0], spots[:, 1], "o", ms=6, mfc="white", mec=colour[t],
                            mew=1.3, zorder=5, label=label)
                    label = None

        step("plunges and drilled holes", plunges)
        if generated.any():
            step("segments inserted by compensation", polyline, drawn, generated,
                 dict(color="darkorange", lw=3.0, alpha=0.8, zorder=4, label="inserted by compensation",
                      solid_capstyle="round"))
        step("start", lambda: ax.plot(s[0, h], s[0, v], "o", color="black", ms=5, zorder=5, label="start"))
        last_point = e[-1]
        starts = s
        line_col = np.asarray(path.line).reshape(-1)

    total = len(steps) + 1 + steps_after  # the steps, the diagnostics and axes, the caller's steps
    for done, (what, fn) in enumerate(steps):
        if progress is not None:
            progress(done, total, what)
        fn()
    if progress is not None:
        progress(len(steps), total, "diagnostics and axes")

    labelled = set()
    for d in result.diagnostics:
        pos = _diagnostic_position(d, starts, line_col, last_point)
        if pos is None:
            continue
        sev = d.severity
        style = _SEVERITY_STYLE.get(sev, dict(marker="o", color="steelblue", s=45))
        ax.scatter([pos[h]], [pos[v]], zorder=6, edgecolors="white", linewidths=0.6,
                   label=sev if sev not in labelled else None, **style)
        labelled.add(sev)
        ax.annotate(f"L{d.line} {d.code}".strip(), (pos[h], pos[v]), xytext=(5, 5),
                    textcoords="offset points", fontsize=8, color=style["color"], zorder=7)

    if str(plane).lower() == "lathe":
        ax.axhline(0.0, color="0.3", lw=0.8, ls=(0, (8, 3, 2, 3)), zorder=0, label="spindle axis")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"{_AXIS_NAMES[h]} [mm]")
    ax.set_ylabel(f"{_AXIS_NAMES[v]} [mm]")
    ax.grid(True, color="0.92", lw=0.6)
    ax.set_axisbelow(True)
    if title is not None:
        ax.set_title(title)
    if legend and ax.get_legend_handles_labels()[0]:
        # beside the drawing, so it never hides part of the path
        ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8,
                  frameon=False, borderaxespad=0.0)
    if progress is not None and not steps_after:
        progress(total, total, "done")
    return ax


def save_plot(result: Any, filename: Union[str, "os.PathLike[str]"], plane: str = "xy", dpi: int = 150,
              title: Optional[str] = None, progress: Optional[Callable[[int, int, str], Any]] = None,
              **kwargs: Any) -> Union[str, "os.PathLike[str]"]:
    """Write :func:`plot_result` of ``result`` to ``filename`` (PNG, or any format matplotlib
    knows from the suffix). Uses no GUI backend, so it works on headless machines.

    ``progress(done, total, what)``, if given, is called before each step of the drawing
    (each path drawn, then the rendering to the file) and once at the end with
    ``done == total``; the command line's ``--plot`` shows it as a progress bar."""
    require("matplotlib", "plot", "save_plot")
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.5, 6), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(projection="3d") if str(plane).lower() == "3d" else fig.add_subplot()
    steps = [1]

    def told(done, total, what):
        steps[0] = total
        progress(done, total, what)

    _plot_result(result, ax=ax, plane=plane, title=title, progress=told if progress else None, steps_after=1,
                 **kwargs)
    if progress is not None:
        progress(steps[0] - 1, steps[0], "writing " + os.path.basename(os.fspath(filename)))
    fig.savefig(os.fspath(filename), dpi=dpi)
    if progress is not None:
        progress(steps[0], steps[0], "done")
    return filename
