"""Rich display in Jupyter: ``_repr_html_`` for Result, Path, ToolTable and Diagnostic, and a
Result repr that names its first error. Everything shown is read from the objects (no run is
repeated); a path's picture is drawn from at most a few thousand of its end points."""
from __future__ import annotations

import html
from typing import Any, List

import numpy as np

MAX_ROWS = 50           # rows of a table shown; the rest counted
THUMB_POINTS = 4000     # end points a path's picture is drawn from, at most
THUMB_SIZE = (260, 180)  # pixels


def _esc(v: Any) -> str:
    return html.escape(str(v))


def _extent(path) -> str:
    if len(path) == 0:
        return "no segments"
    pts = np.vstack([path.start[:1], path.end])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    return ", ".join(f"{a} {_mm(lo[i])} … {_mm(hi[i])}" for i, a in enumerate("XYZ"))


def _mm(v: float) -> str:
    return f"{round(float(v), 3) + 0.0:.3f}"  # + 0.0: no "-0.000"


def _lengths(path) -> str:
    if len(path) == 0:
        return ""
    total = path.length(include_rapids=True)
    feed = path.length(include_rapids=False)
    return f"{_mm(feed)} mm at feed, {_mm(total - feed)} mm rapid"


def _polyline_points(path) -> np.ndarray:
    """The start and up to THUMB_POINTS end points, evenly taken (first and last kept)."""
    n = len(path)
    step = max(1, -(-n // THUMB_POINTS))
    idx = np.arange(0, n, step)
    if idx[-1] != n - 1:
        idx = np.append(idx, n - 1)
    return np.vstack([path.start[:1], path.end[idx]])


def _svg(paths: List[Any], colours: List[str]) -> str:
    """The paths seen from above (XY), or from the front (XZ) when nothing moves in Y."""
    drawn = [(_polyline_points(p), c) for p, c in zip(paths, colours) if len(p)]
    if not drawn:
        return ""
    allpts = np.vstack([pts for pts, _ in drawn])
    v = 1 if np.ptp(allpts[:, 1]) > 1e-9 else 2  # the drawing's vertical axis: Y, or Z
    lo = np.array([allpts[:, 0].min(), allpts[:, v].min()])
    span = max(np.ptp(allpts[:, 0]), np.ptp(allpts[:, v]), 1e-9)
    w, h = THUMB_SIZE
    pad = 6
    scale = min(w - 2 * pad, h - 2 * pad) / span
    lines = []
    for pts, colour in drawn:
        xs = pad + (pts[:, 0] - lo[0]) * scale
        ys = h - pad - (pts[:, v] - lo[1]) * scale
        coords = " ".join(f"{x:.1f},{y:.1f}" for x, y in zip(xs, ys))
        lines.append(f'<polyline points="{coords}" fill="none" stroke="{colour}" stroke-width="1"/>')
    label = "XY" if v == 1 else "XZ"
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" '
            f'style="border:1px solid #ddd"><title>{label}</title>{"".join(lines)}</svg>')


def _diagnostic_row(d) -> str:
    where = f"{d.line}" + (f" ({_esc(d.file)})" if d.file else "")
    return (f"<tr><td>{_esc(d.severity)}</td><td><code>{_esc(d.code)}</code></td><td>{where}</td>"
            f"<td>{_esc(d.message)}</td></tr>")


def _more(n: int) -> str:
    return f"<p>… and {n - MAX_ROWS} more</p>" if n > MAX_ROWS else ""


def result_html(res) -> str:
    diags = res.diagnostics
    errors = [d for d in diags if d.severity == "error"]
    status = ("<b style='color:#1a7f37'>ran to the end</b>" if res.ok
              else f"<b style='color:#cf222e'>stopped</b>: {_esc(errors[0].message) if errors else ''}")
    rows = "".join(_diagnostic_row(d) for d in diags[:MAX_ROWS])
    table = (f"<table><tr><th>severity</th><th>code</th><th>line</th><th>message</th></tr>{rows}</table>"
             + _more(len(diags))) if diags else ""
    return (f"<div><p>toolcomp Result: {status}; {res.blocks} blocks, {len(res.nominal)} programmed and "
            f"{len(res.path)} compensated segments</p>"
            f"<p>Extent (compensated): {_extent(res.path)}<br>Length: {_lengths(res.path)}</p>"
            f"{_svg([res.nominal, res.path], ['#999999', '#0550ae'])}{table}</div>")


def path_html(path) -> str:
    return (f"<div><p>toolcomp Path: {len(path)} segments</p><p>Extent: {_extent(path)}<br>"
            f"Length: {_lengths(path)}</p>{_svg([path], ['#0550ae'])}</div>")


def table_html(table) -> str:
    rows = []
    numbers = list(table.numbers)
    for n in numbers[:MAX_ROWS]:
        tool = table.get(n)
        for e in tool.edges:
            length = ", ".join(f"{v:g}" for v in e.length)
            rows.append(f"<tr><td>{n}</td><td>{e.number}</td><td>{e.radius:g}</td><td>{length}</td>"
                        f"<td>{_esc(tool.name)}</td><td>{_esc(tool.comment)}</td></tr>")
    return (f"<div><p>toolcomp ToolTable: {len(numbers)} tools, units {_esc(table.units)}</p>"
            "<table><tr><th>tool</th><th>edge</th><th>radius</th><th>length (x, y, z)</th><th>name</th>"
            f"<th>comment</th></tr>{''.join(rows)}</table>{_more(len(numbers))}</div>")


def diagnostic_html(d) -> str:
    return f"<table>{_diagnostic_row(d)}</table>"


def result_repr(res) -> str:
    errors = [d for d in res.diagnostics if d.severity == "error"]
    first = f"; {errors[0].code} at line {errors[0].line}: {errors[0].message}" if errors else ""
    return f"Result(ok={res.ok}, segments={len(res.path)}, diagnostics={len(res.diagnostics)}{first})"
