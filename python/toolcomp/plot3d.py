"""3D view of programmed and compensated paths (matplotlib's mplot3d), used by
``plot_result(res, plane="3d")``."""
from __future__ import annotations

import numpy as np

from .plot import RAPID, _Drawing, _drawing_tolerance, _pyplot, path_size


def plot_result_3d(result, ax=None, show_nominal=True, tolerance=None, title=None, legend=True,
                   progress=None, steps_after=0):
    """Programmed path thin grey, compensated feed moves blue, rapids dashed red, inserted
    segments orange, equal scaling on X, Y and Z. Long paths are decimated to ``tolerance``
    as in :func:`toolcomp.plot.plot_result`. Returns the 3D Axes."""
    if ax is None:
        plt = _pyplot()
        fig = plt.figure(figsize=(8.5, 6), layout="constrained")
        ax = fig.add_subplot(projection="3d")
    path = result.path
    if tolerance is None:
        tolerance = _drawing_tolerance(path)
    everything = []

    jobs = []
    nominal = result.nominal
    if show_nominal and nominal is not None and path_size(nominal):
        drawn = _Drawing(nominal, (0, 1, 2), tolerance)
        jobs.append(("programmed path", drawn, drawn.columns[0] != RAPID,
                     dict(color="0.55", lw=0.8, label="programmed")))
    if path_size(path):
        drawn = _Drawing(path, (0, 1, 2), tolerance)
        kind = drawn.columns[0]
        jobs.append(("rapids", drawn, kind == RAPID,
                     dict(color="crimson", lw=0.8, ls=(0, (4, 3)), alpha=0.7, label="rapid")))
        jobs.append(("compensated path", drawn, kind != RAPID,
                     dict(color="tab:blue", lw=1.4, label="compensated")))
        gen = np.asarray(path.generated, dtype=bool).reshape(-1)
        if gen.any():
            jobs.append(("segments inserted by compensation", drawn, gen,
                         dict(color="darkorange", lw=2.6, label="inserted by compensation")))
    total = len(jobs) + 1 + steps_after
    for done, (what, drawing, mask, style) in enumerate(jobs):
        if progress is not None:
            progress(done, total, what)
        xyz = drawing.polyline(mask)
        if len(xyz):
            ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], **style)
            everything.append(xyz[~np.isnan(xyz).any(axis=1)])
    if progress is not None:
        progress(len(jobs), total, "axes and legend")
    if everything:
        allp = np.concatenate(everything)
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        ax.set_box_aspect(np.maximum(hi - lo, 1e-3 * max(1e-9, float((hi - lo).max()))))
    ax.set_xlabel("X [mm]")
    ax.set_ylabel("Y [mm]")
    ax.set_zlabel("Z [mm]")
    if title is not None:
        ax.set_title(title)
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper left", fontsize=8, frameon=False)
    if progress is not None and not steps_after:
        progress(total, total, "done")
    return ax
