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

from typing import Any, Optional, Union

import numpy as np

RAPID, LINE, ARC_CW, ARC_CCW = 0, 1, 2, 3

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
    """Number of segments of a Path."""
    try:
        return len(path)
    except TypeError:
        return int(np.asarray(path.kind).shape[0])


def _arc_plane(s, e, c):
    """The plane an arc lies in, guessed from where start and end are equidistant from
    the centre. Used only when the Path cannot sample itself."""
    best, best_err = _ARC_PLANES[0], math.inf
    for plane in _ARC_PLANES:
        a, b, _ = plane
        if not (math.isfinite(c[a]) and math.isfinite(c[b])):
            continue
        rs = math.hypot(s[a] - c[a], s[b] - c[b])
        re = math.hypot(e[a] - c[a], e[b] - c[b])
        err = abs(rs - re) / max(1.0, rs)
        if rs > 0 and err < best_err - 1e-9:  # ties keep the earlier plane (G17 first)
            best, best_err = plane, err
    return best


def _sample_arc(kind, s, e, c, tolerance):
    """Points of one arc (start excluded, end included), chord error <= tolerance."""
    a, b, n = _arc_plane(s, e, c)
    r = math.hypot(s[a] - c[a], s[b] - c[b])
    a0 = math.atan2(s[b] - c[b], s[a] - c[a])
    a1 = math.atan2(e[b] - c[b], e[a] - c[a])
    sweep = (a1 - a0) % (2 * math.pi)  # counter-clockwise sweep in [0, 2pi)
    if kind == ARC_CW:
        sweep = (2 * math.pi - sweep) % (2 * math.pi)
    if sweep < 1e-12:  # start == end: a full circle
        sweep = 2 * math.pi
    if kind == ARC_CW:
        sweep = -sweep
    if r <= tolerance:
        steps = 1
    else:
        step = 2 * math.acos(max(-1.0, 1 - tolerance / r))
        steps = max(1, int(math.ceil(abs(sweep) / step)))
    t = np.arange(1, steps + 1) / steps
    ang = a0 + sweep * t
    pts = np.empty((steps, 3))
    pts[:, a] = c[a] + r * np.cos(ang)
    pts[:, b] = c[b] + r * np.sin(ang)
    pts[:, n] = s[n] + (e[n] - s[n]) * t  # helix: linear along the normal
    pts[-1] = e
    return pts


def sample_path(path, tolerance=DEFAULT_TOLERANCE):
    """``path.sample(tolerance)``: an (M,3) polyline with arcs chorded within ``tolerance``
    and the segment index of every point.

    Uses the engine's own sampler; the numpy fallback is only for Path-like objects
    without one.
    """
    if hasattr(path, "sample"):
        pts, idx = path.sample(tolerance)
        pts = np.asarray(pts, dtype=float).reshape(-1, 3)
        idx = np.asarray(idx).astype(np.int64, copy=False).reshape(-1)
        return pts, idx
    kind, start, end, center = _columns(path)
    chunks, owners = [], []
    for i in range(kind.shape[0]):
        if i == 0 or not np.allclose(start[i], end[i - 1]):
            chunks.append(start[i][None, :])
            owners.append(np.full(1, i))
        if kind[i] in (ARC_CW, ARC_CCW):
            p = _sample_arc(kind[i], start[i], end[i], center[i], tolerance)
        else:
            p = end[i][None, :]
        chunks.append(p)
        owners.append(np.full(len(p), i))
    if not chunks:
        return np.empty((0, 3)), np.empty(0, dtype=np.int64)
    return np.concatenate(chunks), np.concatenate(owners)


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

    The Path has no plane column, so the arc's plane and sweep are read off the points of
    ``path.sample(tolerance)``: the plane is the one in which every sampled point is at the
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
# drawing (matplotlib, imported lazily)
# ---------------------------------------------------------------------------------------

def _pyplot():
    """Import pyplot, choosing the Agg backend when nothing can show a window."""
    import matplotlib

    headless = not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    if (headless and "matplotlib.pyplot" not in sys.modules
            and not os.environ.get("MPLBACKEND") and sys.platform.startswith("linux")):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _runs(points, owner, mask):
    """The points of the segments selected by ``mask`` as one polyline with NaN rows
    wherever the selection is not continuous (gap in segment order or jump in space)."""
    sel = mask[owner]
    p, o = points[sel], owner[sel]
    if len(p) == 0:
        return p
    new_seg = o[1:] != o[:-1]
    jump = np.linalg.norm(p[1:] - p[:-1], axis=1) > 1e-9
    brk = np.nonzero(new_seg & ((o[1:] != o[:-1] + 1) | jump))[0] + 1
    return np.insert(p, brk, np.nan, axis=0)


def _plane_axes(plane):
    try:
        return PLANES[str(plane).lower()]
    except KeyError:
        raise ValueError(f"plane must be one of {sorted(PLANES)}, not {plane!r}") from None


def _severity_name(sev) -> str:
    name = getattr(sev, "name", None) or str(sev)
    return name.rsplit(".", 1)[-1].lower()


def _diagnostic_position(diag, path_points, line_col, last_point):
    """Where to mark a diagnostic: the start of the first segment of its line; an error
    after the last segment (the control stopped there) at the end of the path."""
    line = getattr(diag, "line", None)
    if line is None or line <= 0:
        return None
    if line_col is not None and len(line_col):
        hits = np.nonzero(line_col == line)[0]
        if len(hits):
            return path_points[hits[0]]
    if _severity_name(getattr(diag, "severity", "")) in ("error", "fatal") and last_point is not None:
        return last_point
    return None


_TOOL_COLOURS = ("tab:blue", "tab:green", "tab:purple", "tab:brown", "tab:cyan",
                 "tab:olive", "tab:pink", "navy", "darkgreen", "indigo")
_SEVERITY_STYLE = {
    "error": dict(marker="X", color="crimson", s=70),
    "fatal": dict(marker="X", color="crimson", s=70),
    "warning": dict(marker="^", color="darkorange", s=55),
}


def _drawing_tolerance(path):
    """Chord tolerance fine enough to look round at any screen size: 1/20000 of the
    path's extent, at least 1 micron."""
    if path_size(path) == 0:
        return DEFAULT_TOLERANCE
    _, start, end, _ = _columns(path)
    pts = np.concatenate([start, end])
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    extent = float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0))) if len(pts) else 0.0
    return max(DEFAULT_TOLERANCE, extent / 20000.0)


def plot_result(result: Any, ax: Any = None, plane: str = "xy", show_nominal: bool = True,
                tolerance: Optional[float] = None, title: Optional[str] = None, legend: bool = True,
                color_by: str = "tool") -> Any:
    """Draw a run result: programmed path thin grey, compensated path coloured by tool,
    rapids dashed, segments inserted by compensation highlighted, diagnostics marked with
    their line number. Arcs are drawn as arcs, chorded within ``tolerance`` mm (default:
    1/20000 of the path's extent).

    ``plane`` is "xy" (default), "xz", "zx", "yz", "g17"/"g18"/"g19", "lathe" (a half
    section: Z horizontal, X vertical, the spindle axis drawn) or "3d". ``color_by`` is
    "tool" or "side" (G41/RL blue, G42/RR green, uncompensated black). Returns the Axes.
    """
    if str(plane).lower() == "3d":
        from .plot3d import plot_result_3d

        return plot_result_3d(result, ax=ax, show_nominal=show_nominal, tolerance=tolerance,
                              title=title, legend=legend)
    h, v = _plane_axes(plane)
    if ax is None:
        plt = _pyplot()
        _, ax = plt.subplots(figsize=(8.5, 6), layout="constrained")

    path = result.path
    nominal = getattr(result, "nominal", None)
    if tolerance is None:
        tolerance = _drawing_tolerance(path)

    if show_nominal and nominal is not None and path_size(nominal):
        pts, owner = segment_polylines(nominal, tolerance)
        kind = np.asarray(nominal.kind)
        xy = _runs(pts, owner, kind != RAPID)
        if len(xy):
            ax.plot(xy[:, h], xy[:, v], color="0.55", lw=0.8, zorder=1, label="programmed")

    n = path_size(path)
    last_point = None
    starts = line_col = None
    if n:
        pts, owner = segment_polylines(path, tolerance)
        kind = np.asarray(path.kind)
        tool = np.asarray(getattr(path, "tool", np.zeros(n, dtype=int))).reshape(-1)
        generated = np.asarray(getattr(path, "generated", np.zeros(n, dtype=bool)), dtype=bool)

        rapid = _runs(pts, owner, kind == RAPID)
        if len(rapid):
            ax.plot(rapid[:, h], rapid[:, v], color="crimson", lw=0.8, ls=(0, (4, 3)),
                    alpha=0.7, zorder=2, label="rapid")
        tools = [int(t) for t in np.unique(tool[kind != RAPID])]
        colour = {t: _TOOL_COLOURS[k % len(_TOOL_COLOURS)] for k, t in enumerate(tools)}
        if color_by == "side":
            side = np.asarray(path.side).reshape(-1)
            for sd, name, col in ((1, "left (G41 / RL)", "tab:blue"), (-1, "right (G42 / RR)", "tab:green"),
                                  (0, "uncompensated", "black")):
                sel = (kind != RAPID) & (side == sd)
                if sel.any():
                    xy = _runs(pts, owner, sel)
                    ax.plot(xy[:, h], xy[:, v], color=col, lw=1.6, zorder=3, label=name,
                            solid_capstyle="round")
        elif color_by != "tool":
            raise ValueError(f"color_by must be 'tool' or 'side', not {color_by!r}")
        for t in tools if color_by == "tool" else ():
            xy = _runs(pts, owner, (kind != RAPID) & (tool == t))
            label = f"T{t} compensated" if len(tools) > 1 else "compensated"
            ax.plot(xy[:, h], xy[:, v], color=colour[t], lw=1.6, zorder=3, label=label,
                    solid_capstyle="round")
        # Seen from above, feeds along Z only (plunges, drilled holes) have no extent in
        # the plot: mark where they are.
        s = np.asarray(path.start, dtype=float).reshape(n, 3)
        e = np.asarray(path.end, dtype=float).reshape(n, 3)
        flat = np.hypot(e[:, h] - s[:, h], e[:, v] - s[:, v]) < 1e-9
        plunge = (kind == LINE) & flat & (np.abs(e[:, 2] - s[:, 2]) > 1e-9) & (3 - h - v == 2)
        label = "plunge / drill"
        for t in tools:
            sel = plunge & (tool == t)
            if sel.any():
                spots = np.unique(np.round(e[sel][:, [h, v]], 6), axis=0)
                ax.plot(spots[:, 0], spots[:, 1], "o", ms=6, mfc="white", mec=colour[t],
                        mew=1.3, zorder=5, label=label)
                label = None
        if generated.any():
            xy = _runs(pts, owner, generated)
            ax.plot(xy[:, h], xy[:, v], color="darkorange", lw=3.0, alpha=0.8, zorder=4,
                    label="inserted by compensation", solid_capstyle="round")

        ax.plot(s[0, h], s[0, v], "o", color="black", ms=5, zorder=5, label="start")
        last_point = e[-1]
        starts = s
        line_col = np.asarray(getattr(path, "line", np.zeros(n, dtype=int))).reshape(-1)

    labelled = set()
    for d in getattr(result, "diagnostics", ()) or ():
        pos = _diagnostic_position(d, starts, line_col, last_point)
        if pos is None:
            continue
        sev = _severity_name(getattr(d, "severity", "note"))
        style = _SEVERITY_STYLE.get(sev, dict(marker="o", color="steelblue", s=45))
        ax.scatter([pos[h]], [pos[v]], zorder=6, edgecolors="white", linewidths=0.6,
                   label=sev if sev not in labelled else None, **style)
        labelled.add(sev)
        code = getattr(d, "code", "")
        ax.annotate(f"L{d.line} {code}".strip(), (pos[h], pos[v]), xytext=(5, 5),
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
    return ax


def save_plot(result: Any, filename: Union[str, "os.PathLike[str]"], plane: str = "xy", dpi: int = 150,
              title: Optional[str] = None, **kwargs: Any) -> Union[str, "os.PathLike[str]"]:
    """Write :func:`plot_result` of ``result`` to ``filename`` (PNG, or any format matplotlib
    knows from the suffix). Uses no GUI backend, so it works on headless machines."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.5, 6), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(projection="3d") if str(plane).lower() == "3d" else fig.add_subplot()
    plot_result(result, ax=ax, plane=plane, title=title, **kwargs)
    fig.savefig(os.fspath(filename), dpi=dpi)
    return filename
