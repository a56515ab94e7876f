"""Long paths are drawn as the figure can show them: decimated, yet with the extent, the
corners and the small features of the path, arcs as arcs, rapids apart from feeds."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

import toolcomp as tc
from toolcomp.plot import RAPID, LINE, ARC_CCW, sample_path

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NAN = math.nan


def columns_path(kind, start, end, center=None, generated=None):
    """A Path-like object from columns (no sampler, no plane column: the plot guesses)."""
    kind = np.asarray(kind, np.uint8)
    n = len(kind)
    start, end = np.asarray(start, float).reshape(n, 3), np.asarray(end, float).reshape(n, 3)
    center = np.full((n, 3), NAN) if center is None else np.asarray(center, float).reshape(n, 3)
    return SimpleNamespace(
        kind=kind, start=start, end=end, center=center, line=np.arange(1, n + 1, dtype=np.int32),
        tool=np.ones(n, np.int32), feed=np.where(kind == RAPID, NAN, 500.0), side=np.zeros(n, np.int8),
        generated=np.zeros(n, bool) if generated is None else np.asarray(generated, bool),
        tool_offset=np.zeros((n, 3)), abc=np.zeros((n, 3)))


def polyline(points):
    """Consecutive points as line segments (kind LINE)."""
    p = np.asarray(points, float)
    if p.shape[1] == 2:
        p = np.column_stack([p, np.zeros(len(p))])
    return columns_path(np.full(len(p) - 1, LINE), p[:-1], p[1:])


def result_of(path, nominal=None):
    return SimpleNamespace(ok=True, nominal=nominal, path=path, diagnostics=[])


def drawn(ax, label):
    """The (x, y) data of the line labelled ``label``, NaN rows (breaks) left out."""
    lines = [ln for ln in ax.get_lines() if ln.get_label() == label]
    assert len(lines) == 1, [ln.get_label() for ln in ax.get_lines()]
    xy = np.column_stack(lines[0].get_data()).astype(float)
    return xy[~np.isnan(xy).any(axis=1)]


@pytest.fixture
def ax():
    fig, ax = plt.subplots(figsize=(8.5, 6))
    yield ax
    plt.close(fig)


def zigzag(rows, length=1000.0, pitch=0.001):
    """Rows `length` mm long, `pitch` apart, cut back and forth: 2 * rows - 1 segments."""
    y = np.arange(rows) * pitch
    x = np.where(np.arange(rows) % 2 == 0, 0.0, length)
    pts = np.empty((2 * rows, 2))
    pts[0::2, 0], pts[1::2, 0] = x, length - x
    pts[0::2, 1] = pts[1::2, 1] = y
    return pts


def test_a_dense_path_is_decimated_and_keeps_its_extent_exactly(ax):
    # 20 000 rows 1 um apart over 1000 mm: the figure cannot tell most of them apart
    # (drawing tolerance 1000 / 20000 = 0.05 mm, 50 rows a cell), so most are drawn once.
    pts = zigzag(20_000)
    # one row reaches 0.4 um further than the others, and one 0.3 um lower than the first:
    # far below the tolerance, but they are the path's extent.
    pts[20_001, 0] = 1000.0004
    pts[0, 1] = -0.0003
    path = polyline(pts)
    ax = tc.plot.plot_result(result_of(path), ax=ax)
    xy = drawn(ax, "compensated")
    assert len(xy) < len(pts) / 10
    assert xy[:, 0].min() == 0.0 and xy[:, 0].max() == 1000.0004
    assert xy[:, 1].min() == -0.0003 and xy[:, 1].max() == pytest.approx(19_999 * 0.001, abs=1e-12)
    # what is drawn lies on the path: every point on a row (y a multiple of 1 um, or the
    # lowered start) and x at one of the rows' ends
    assert np.all(np.isclose(xy[:, 0], 0) | np.isclose(xy[:, 0], 1000, atol=1e-3))
    on_row = np.isclose(xy[:, 1] * 1000, np.round(xy[:, 1] * 1000), atol=1e-6) | (xy[:, 1] == -0.0003)
    assert on_row.all()


def test_a_small_step_in_a_long_path_of_tiny_segments_stays(ax):
    # 1000 mm along X in 5 um segments with a 0.1 mm step up at X500: 200 000 segments.
    x = np.linspace(0.0, 500.0, 100_001)
    pts = np.concatenate([np.column_stack([x, np.zeros_like(x)]),
                          np.column_stack([x + 500.0, np.full_like(x, 0.1)])])
    ax = tc.plot.plot_result(result_of(polyline(pts)), ax=ax)
    xy = drawn(ax, "compensated")
    # of consecutive points in one cell of the tolerance (1000 / 20000 = 0.05 mm) only the
    # first and the last: at most 2 a cell, 2 * 20 000 + the step's, of 200 002
    assert len(xy) <= 40_004
    # both corners of the step are drawn where they are
    assert np.any((xy[:, 0] == 500.0) & (xy[:, 1] == 0.0))
    assert np.any((xy[:, 0] == 500.0) & (xy[:, 1] == 0.1))
    assert set(np.unique(xy[:, 1])) == {0.0, 0.1}
    assert xy[:, 0].min() == 0.0 and xy[:, 0].max() == 1000.0


def test_arcs_are_drawn_as_arcs(ax):
    # A semicircle of radius 100 about (500, 0) from (600, 0) counter-clockwise to (400, 0),
    # between two long lines, repeated 5000 times 1 um higher each time.
    rows = 5000
    kind, start, end, center = [], [], [], []
    for i in range(rows):
        y = i * 0.001
        kind += [LINE, ARC_CCW, LINE]
        start += [(0, y, 0), (600, y, 0), (400, y, 0)]
        end += [(600, y, 0), (400, y, 0), (0, y + 0.001, 0)]
        center += [(NAN, NAN, NAN), (500, y, 0), (NAN, NAN, NAN)]
    path = columns_path(kind, start, end, center)
    tol = 0.01
    ax = tc.plot.plot_result(result_of(path), ax=ax, tolerance=tol)
    xy = drawn(ax, "compensated")
    upper = xy[xy[:, 1] > 5.0 + 1e-9]  # points on the arcs, clear of the lines
    assert len(upper) >= 50  # chords of at most 2 acos(1 - 0.01 / 100) = 0.028 rad: > 110 a half turn
    # every drawn arc point is on a circle of radius 100 about (500, y) of one of the rows
    r_lo = np.hypot(upper[:, 0] - 500, upper[:, 1] - 4.999)
    r_hi = np.hypot(upper[:, 0] - 500, upper[:, 1])
    assert r_lo.max() <= 100 + 1e-9 and r_hi.min() >= 100 - 5 - 1e-9
    r0 = np.array([np.hypot(p[0] - 500, p[1] - np.clip(p[1] - math.sqrt(max(0.0, 100**2 - (p[0] - 500)**2)),
                                                                0, 4.999)) for p in upper])
    np.testing.assert_allclose(r0, 100, atol=1e-6)
    # the top of the arc is drawn: a point within the chord tolerance of (500, y + 100)
    top = upper[np.argmax(upper[:, 1])]
    assert abs(top[0] - 500) < 2.5 and top[1] >= 100 - tol
    assert xy[:, 1].max() == pytest.approx(4.999 + 100, abs=tol)


def test_arcs_of_an_engine_path_in_every_plane_drawn_on_their_circles(ax):
    # G17 quarter helix r 10 about (0, 0); G18 half circle r 5 about X15 Z-10; a 3-turn helix.
    text = ("G21 G90 G17\nG0 X10 Y0 Z0\nG1 Z0 F300\nG3 X0 Y10 Z-2 I-10 J0\nG3 X0 Y10 Z-10 I0 J-10 P3\n"
            "G18\nG1 X10 Y10 Z-10\nG2 X20 Z-10 I5 K0\nM2\n")
    res = tc.run(tc.Program.parse(text))
    tol = 0.002
    top = tc.plot.plot_result(res, ax=ax, tolerance=tol, show_nominal=False)
    xy = drawn(top, "compensated")
    quarter = xy[(xy[:, 0] > 0.01) & (xy[:, 0] < 9.99) & (xy[:, 1] > 0.01)]
    r = np.hypot(quarter[:, 0], quarter[:, 1])
    assert len(quarter) > 20 and np.all(np.abs(r - 10) <= tol + 1e-9)
    fig, side = plt.subplots()
    try:
        tc.plot.plot_result(res, ax=side, plane="xz", tolerance=tol, show_nominal=False)
        xz = drawn(side, "compensated")
        half = xz[(xz[:, 0] > 10.01) & (xz[:, 0] < 19.99)]  # only the G18 arc has X in (10, 20)
        r = np.hypot(half[:, 0] - 15, half[:, 1] + 10)
        assert len(half) > 20 and np.all(np.abs(r - 5) <= tol + 1e-9)
        # G2 in G18 (seen from +Y: Z right, X up) from X10 (6 o'clock) clockwise to X20
        # (12 o'clock): through 9 o'clock, Z-10 - 5 = -15
        assert half[:, 1].min() == pytest.approx(-15, abs=tol) and half[:, 1].max() <= -10
    finally:
        plt.close(fig)


def test_the_sampler_of_the_plot_is_the_engines():
    # The plot samples arcs itself (only those it draws); it must chord them as
    # Path.sample does: the same points, plane and extra turns from the Path's columns.
    text = ("G21 G90 G17\nG0 X10 Y0 Z0\nG3 X0 Y10 Z-2 I-10 J0 F300\nG2 X10 Y0 Z-4 R10\n"
            "G3 X10 Y0 Z-10 I-10 J0 P3\nG18\nG2 X20 Y0 Z-10 I5 K0\nG19\nG3 Y10 Z0 J5 K5\nM2\n")
    path = tc.run(tc.Program.parse(text)).path
    like = SimpleNamespace(**{name: getattr(path, name) for name in
                              ("kind", "start", "end", "center", "plane", "turns")})
    for tol in (0.1, 0.001):
        engine, engine_idx = path.sample(tol)
        ours, our_idx = sample_path(like, tol)
        np.testing.assert_array_equal(our_idx, engine_idx)
        np.testing.assert_allclose(ours, engine, atol=1e-9)
        r = np.hypot(ours[our_idx == 2][:, 0], ours[our_idx == 2][:, 1])  # the 3-turn helix, r 10
        np.testing.assert_allclose(r, 10, atol=1e-9)


def test_rapids_and_feeds_are_drawn_apart(ax):
    # 3000 passes: rapid down at X0 to the row, feed along it to X100, rapid back above it.
    n = 3000
    kind, start, end = [], [], []
    for i in range(n):
        y = i * 0.001
        kind += [RAPID, LINE, RAPID, RAPID]
        start += [(0, y - 10, 0), (0, y, 0), (100, y, 0), (100, y - 10, 0)]
        end += [(0, y, 0), (100, y, 0), (100, y - 10, 0), (0, y - 9.999, 0)]
    ax = tc.plot.plot_result(result_of(columns_path(kind, start, end)), ax=ax)
    feed, rapid = drawn(ax, "compensated"), drawn(ax, "rapid")
    # feeds only along the rows (y from 0 to 2.999), rapids only where the rapids go
    assert np.all((feed[:, 1] >= 0) & (feed[:, 1] <= 2.999 + 1e-9))
    assert np.all((rapid[:, 0] == 0) | (rapid[:, 0] == 100) | (rapid[:, 1] < -6.999))
    assert feed[:, 0].min() == 0 and feed[:, 0].max() == 100
    assert rapid[:, 1].min() == -10 and rapid[:, 1].max() == pytest.approx(2.999, abs=1e-12)
    styles = {ln.get_label(): ln.get_linestyle() for ln in ax.get_lines()}
    assert styles["rapid"] == "--" and styles["compensated"] == "-"
    # one artist a kind of move, however many segments
    assert sum(ln.get_label() in ("rapid", "compensated") for ln in ax.get_lines()) == 2


def test_a_compensated_corner_arc_stays_among_many_segments(ax):
    # 30 000 short feeds (a dense zigzag, 10 um rows) then a contour cut with G42, r 0.1
    # (D0.2): at the outside corner X100 Y50 an arc of radius 0.1 about the corner is
    # inserted, from (100, 49.9) to (100.1, 50).
    zig = zigzag(15_000, length=100.0, pitch=0.01)
    lines = ["G21 G90 G17 G40", "G0 X0 Y0", "G1 F600"] + [f"X{x:.3f} Y{y:.3f}" for x, y in zig]
    lines += ["G0 X0 Y48", "G42.1 D0.2", "G1 X10 Y50", "X100", "Y100", "G40 G0 X110 Y110", "M2"]
    res = tc.run(tc.Program.parse("\n".join(lines) + "\n"))
    ax = tc.plot.plot_result(res, ax=ax)
    xy = drawn(ax, "inserted by compensation")
    near = xy[np.hypot(xy[:, 0] - 100, xy[:, 1] - 50) < 1.0]
    tol = math.hypot(110, 110) / 20000  # the default tolerance: 1/20000 of the extent
    assert len(near) >= 3
    np.testing.assert_allclose(np.hypot(near[:, 0] - 100, near[:, 1] - 50), 0.1, atol=tol)
    assert np.any(np.all(np.isclose(near, [100, 49.9]), axis=1))
    assert np.any(np.all(np.isclose(near, [100.1, 50]), axis=1))
    # chords of at most 2 acos(1 - tol / 0.1): at least one point inside the quarter
    angle = np.degrees(np.arctan2(near[:, 1] - 50, near[:, 0] - 100))
    assert np.any((angle > -85) & (angle < -5))


def test_the_3d_view_of_a_long_path_is_decimated_and_keeps_its_extent():
    pts = zigzag(20_000)
    path = polyline(np.column_stack([pts, np.linspace(0, -5, len(pts))]))
    fig = plt.figure()
    try:
        ax = fig.add_subplot(projection="3d")
        tc.plot.plot_result(result_of(path), ax=ax, plane="3d")
        line = [ln for ln in ax.get_lines() if ln.get_label() == "compensated"][0]
        xyz = np.column_stack(line.get_data_3d())
        xyz = xyz[~np.isnan(xyz).any(axis=1)]
        assert len(xyz) < len(pts) / 5
        assert xyz[:, 0].min() == 0 and xyz[:, 0].max() == 1000
        assert xyz[:, 2].min() == -5 and xyz[:, 2].max() == 0
    finally:
        plt.close(fig)


def test_save_plot_tells_its_progress(tmp_path):
    pts = zigzag(100)
    seen = []
    tc.plot.save_plot(result_of(polyline(pts), polyline(pts)), tmp_path / "p.png",
                      progress=lambda done, total, what: seen.append((done, total, what)))
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG"
    done = [d for d, _, _ in seen]
    total = seen[0][1]
    assert done == sorted(done) and done[0] == 0 and seen[-1] == (total, total, "done")
    whats = [w for _, _, w in seen]
    assert "programmed path" in whats and "writing p.png" in whats
