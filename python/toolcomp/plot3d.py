"""3D view of programmed and compensated paths (matplotlib's mplot3d), used by
``plot_result(res, plane="3d")``."""
from __future__ import annotations

import numpy as np

from .plot import RAPID, _drawing_tolerance, _runs, path_size, segment_polylines


def plot_result_3d(result, ax=None, show_nominal=True, tolerance=None, title=None, legend=True):
    """Programmed path thin grey, compensated feed moves blue, rapids dashed red, inserted
    segments orange, equal scaling on X, Y and Z. Returns the 3D Axes."""
    if ax is None:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=(8.5, 6), layout="constrained")
        ax = fig.add_subplot(projection="3d")
    path = result.path
    if tolerance is None:
        tolerance = _drawing_tolerance(path)
    everything = []

    def draw(p, mask_of, **style):
        pts, owner = segment_polylines(p, tolerance)
        xyz = _runs(pts, owner, mask_of(np.asarray(p.kind), p))
        if len(xyz):
            ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], **style)
            everything.append(xyz[~np.isnan(xyz).any(axis=1)])

    nominal = getattr(result, "nominal", None)
    if show_nominal and nominal is not None and path_size(nominal):
        draw(nominal, lambda k, p: k != RAPID, color="0.55", lw=0.8, label="programmed")
    if path_size(path):
        draw(path, lambda k, p: k == RAPID, color="crimson", lw=0.8, ls=(0, (4, 3)), alpha=0.7, label="rapid")
        draw(path, lambda k, p: k != RAPID, color="tab:blue", lw=1.4, label="compensated")
        gen = np.asarray(path.generated, dtype=bool)
        if gen.any():
            draw(path, lambda k, p: gen, color="darkorange", lw=2.6, label="inserted by compensation")
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
    return ax
