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

import numpy as np

from . import _core


def _format(d) -> str:
    return f"line {d.line}:{d.column}: {d.severity} {d.code} {d.message}"


def assert_no_errors(res: "_core.Result", warnings: bool = False) -> None:
    """No error diagnostics (and no warnings either with ``warnings=True``)."""
    bad = [d for d in res.diagnostics if d.severity == "error" or (warnings and d.severity == "warning")]
    if bad:
        raise AssertionError("program diagnostics:\n" + "\n".join(_format(d) for d in bad))


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
    pts, seg = _points(path, tolerance, tool_offset)
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
    return c


def _distance_to_polyline(p: np.ndarray, c: np.ndarray) -> np.ndarray:
    step = max(1, 4_000_000 // max(1, len(c)))  # bounded memory: points in chunks
    if len(p) > step:
        return np.concatenate([_distance_to_polyline(p[i:i + step], c) for i in range(0, len(p), step)])
    a, b = c[:-1], c[1:]
    ab = b - a
    L2 = np.maximum((ab * ab).sum(axis=1), 1e-300)
    t = np.clip(((p[:, None, :] - a[None]) * ab[None]).sum(axis=2) / L2[None], 0, 1)
    q = a[None] + t[..., None] * ab[None]
    return np.sqrt(((p[:, None, :] - q) ** 2).sum(axis=2)).min(axis=1)


def assert_no_gouge(res: "_core.Result", contour, radius: float, *, tol: float = 1e-6,
                    tolerance: float = 0.001, rapids: bool = False) -> None:
    """No point of the compensated feed moves (XY, arcs sampled within ``tolerance``) comes
    closer than ``radius - tol`` to the contour (an (N, 2) polyline or a shapely geometry):
    the cutter does not cut into the part. Only moves with compensation on are checked."""
    path = res.path if hasattr(res, "path") else res
    c = _polyline(contour)
    pts, seg = path.sample(tolerance)
    keep = path.side[seg] != 0
    if not rapids:
        keep &= path.kind[seg] != _core.RAPID
    if not keep.any():
        return
    d = _distance_to_polyline(pts[keep, :2], c)
    bad = d < radius - tol
    if bad.any():
        i = int(np.argmax(bad))
        s = seg[keep][i]
        raise AssertionError(f"the tool comes {radius - d[i]:.6f} mm into the contour at "
                             f"{np.round(pts[keep][i], 6).tolist()} (move of line {int(path.line[s])})")


def assert_paths_close(a: "_core.Path", b: "_core.Path", tol: float = 1e-6, *,
                       what: Optional[str] = None) -> None:
    """Same segments (kind, end points, arc centres, turns) within ``tol`` mm."""
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
