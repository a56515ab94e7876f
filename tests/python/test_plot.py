"""Plotting and the path geometry behind it (lengths, sampling)."""

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from toolcomp.plot import sample_path, segment_lengths, segment_polylines

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "pocket.ngc"
TOOLS = ROOT / "examples" / "tools.tbl"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
NAN = math.nan


def fake_path(rows):
    """A Path-like object without a sampler: (kind, start, end, center) rows."""
    kind, start, end, center = zip(*rows)
    n = len(rows)
    return SimpleNamespace(
        kind=np.array(kind, np.uint8), start=np.array(start, float), end=np.array(end, float),
        center=np.array(center, float), line=np.arange(1, n + 1, dtype=np.int32),
        tool=np.ones(n, np.int32), feed=np.full(n, 500.0), side=np.zeros(n, np.int8),
        generated=np.zeros(n, bool), tool_offset=np.zeros((n, 3)), abc=np.zeros((n, 3)))


def test_segment_lengths_exact_for_arcs_in_every_plane():
    path = fake_path([
        (0, (0, 0, 10), (0, 0, 0), (NAN, NAN, NAN)),            # rapid down 10
        (1, (0, 0, 0), (3, 4, 0), (NAN, NAN, NAN)),             # line 5
        (3, (10, 0, 0), (0, 10, 3), (0, 0, 0)),                 # G17 CCW quarter helix, rise 3
        (2, (0, 10, 3), (10, 0, 3), (0, 0, 3)),                 # G17 CW quarter, same circle back
        (2, (0, 0, 0), (0, 0, 0), (5, 0, 0)),                   # G18 full circle r=5 (X-Z)
        (3, (0, 0, 0), (0, 0, 8), (0, 0, 4)),                   # G19 half circle r=4 (Y-Z)
    ])
    lengths = segment_lengths(path)
    expected = [10, 5, math.hypot(math.pi / 2 * 10, 3), math.pi / 2 * 10, 10 * math.pi, 4 * math.pi]
    np.testing.assert_allclose(lengths, expected, rtol=1e-9)


def test_cw_and_ccw_arcs_sweep_opposite_ways():
    # same end points and centre: CCW is the short way here, CW the long way
    ccw = fake_path([(3, (10, 0, 0), (0, 10, 0), (0, 0, 0))])
    cw = fake_path([(2, (10, 0, 0), (0, 10, 0), (0, 0, 0))])
    assert segment_lengths(ccw)[0] == pytest.approx(5 * math.pi)
    assert segment_lengths(cw)[0] == pytest.approx(15 * math.pi)
    pts, _ = sample_path(cw, 0.01)
    assert pts[:, 1].min() == pytest.approx(-10, abs=0.02)  # goes round through -Y


def test_sampled_arcs_stay_within_tolerance():
    path = fake_path([(2, (0, 0, 0), (0, 0, 0), (20, 0, 0))])
    tol = 0.01
    pts, idx = sample_path(path, tol)
    assert set(idx.tolist()) == {0}
    r = np.hypot(pts[:, 0] - 20, pts[:, 1])
    np.testing.assert_allclose(r, 20, atol=1e-9)
    mid = (pts[1:] + pts[:-1]) / 2  # chord midpoints: worst chord error
    assert (20 - np.hypot(mid[:, 0] - 20, mid[:, 1])).max() <= tol + 1e-12


def test_segment_polylines_start_and_end_each_segment():
    path = fake_path([
        (1, (0, 0, 0), (10, 0, 0), (NAN, NAN, NAN)),
        (3, (10, 0, 0), (10, 10, 0), (10, 5, 0)),
    ])
    pts, owner = segment_polylines(path, 0.01)
    for i in range(2):
        run = pts[owner == i]
        np.testing.assert_allclose(run[0], path.start[i])
        np.testing.assert_allclose(run[-1], path.end[i])


# ---- drawing --------------------------------------------------------------------------

@pytest.fixture(scope="module")
def mpl():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    return matplotlib


@pytest.fixture(scope="module")
def example_result():
    import toolcomp as tc

    return tc.run(tc.Program.read(str(EXAMPLE)), tools=tc.ToolTable.read(str(TOOLS)))


def fake_result(path, diagnostics=()):
    return SimpleNamespace(ok=not diagnostics, nominal=path, path=path,
                           diagnostics=list(diagnostics))


def test_save_plot_writes_png(mpl, example_result, tmp_path):
    from toolcomp.plot import save_plot

    out = tmp_path / "pocket.png"
    save_plot(example_result, out)
    data = out.read_bytes()
    assert data[:8] == PNG_MAGIC and len(data) > 5000


@pytest.mark.parametrize("plane", ["xy", "xz", "yz", "G18"])
def test_plot_result_returns_axes_in_mm(mpl, example_result, plane):
    import matplotlib.pyplot as plt
    from toolcomp.plot import plot_result

    fig, ax = plt.subplots()
    try:
        assert plot_result(example_result, ax=ax, plane=plane) is ax
        assert ax.get_xlabel().endswith("[mm]") and ax.get_ylabel().endswith("[mm]")
        assert ax.get_legend() is not None
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert "programmed" in labels and "rapid" in labels
    finally:
        plt.close(fig)


def test_plot_result_makes_its_own_axes(mpl, example_result):
    import matplotlib.pyplot as plt
    from toolcomp.plot import plot_result

    ax = plot_result(example_result)
    try:
        assert ax.get_aspect() == 1.0
    finally:
        plt.close(ax.figure)


def test_plot_marks_diagnostics_and_generated_segments(mpl, tmp_path):
    import matplotlib.pyplot as plt
    from toolcomp.plot import plot_result, save_plot

    path = fake_path([
        (0, (0, 0, 5), (0, 0, 0), (NAN, NAN, NAN)),
        (1, (0, 0, 0), (10, 0, 0), (NAN, NAN, NAN)),
        (3, (10, 0, 0), (10, 10, 0), (10, 5, 0)),
    ])
    path.generated[2] = True
    diags = [SimpleNamespace(code="W1", severity="warning", message="m", line=2, column=1),
             SimpleNamespace(code="E1", severity="error", message="m", line=9, column=1)]
    res = fake_result(path, diags)
    fig, ax = plt.subplots()
    try:
        plot_result(res, ax=ax)
        texts = [t.get_text() for t in ax.texts]
        assert "L2 W1" in texts and "L9 E1" in texts  # the error at the end of the path
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert "inserted by compensation" in labels
    finally:
        plt.close(fig)
    out = tmp_path / "partial.png"
    save_plot(res, out)
    assert out.read_bytes()[:8] == PNG_MAGIC


def test_plot_empty_result(mpl, tmp_path):
    from toolcomp.plot import save_plot

    empty = fake_path([(1, (0, 0, 0), (1, 0, 0), (NAN, NAN, NAN))])
    for name in vars(empty):
        setattr(empty, name, getattr(empty, name)[:0])
    out = tmp_path / "empty.png"
    save_plot(fake_result(empty), out)
    assert out.read_bytes()[:8] == PNG_MAGIC


def test_bad_plane(mpl, example_result):
    from toolcomp.plot import plot_result

    with pytest.raises(ValueError, match="plane"):
        plot_result(example_result, plane="uv")


def test_plunges_and_drilled_holes_are_marked_from_above(mpl, example_result):
    import matplotlib.pyplot as plt
    from toolcomp.plot import plot_result

    fig, (top, side) = plt.subplots(1, 2)
    try:
        plot_result(example_result, ax=top, plane="xy")
        plot_result(example_result, ax=side, plane="xz")
        top_labels = [t.get_text() for t in top.get_legend().get_texts()]
        side_labels = [t.get_text() for t in side.get_legend().get_texts()]
        assert "plunge / drill" in top_labels and "plunge / drill" not in side_labels
        spots = np.concatenate([ln.get_xydata() for ln in top.lines if ln.get_marker() == "o"
                                and ln.get_label() != "start" and ln.get_linestyle() == "None"])
        for hole in ([10, 10], [90, 10], [90, 70], [10, 70]):  # the G81 holes of pocket.ngc
            assert np.any(np.all(np.isclose(spots, hole), axis=1)), hole
    finally:
        plt.close(fig)


def test_result_plot_method(mpl, example_result):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    try:
        assert example_result.plot(ax=ax, plane="yz") is ax
    finally:
        plt.close(fig)


@pytest.mark.parametrize("program", ["pocket", "helix"])
def test_segment_lengths_agree_with_the_engine(program, tmp_path):
    import toolcomp as tc

    if program == "pocket":
        res = tc.run(str(EXAMPLE), tools=str(TOOLS))
    else:  # helices in all three planes, a multi-turn one with P
        text = ("G21 G90 G17\nG0 X10 Y0 Z0\nG3 X0 Y10 Z-2 I-10 J0 F300\nG2 X10 Y0 Z-4 R10\n"
                "G3 X10 Y0 Z-10 I-10 J0 P3\nG18\nG2 X20 Y0 Z-10 I5 K0\nG19\n"
                "G3 Y10 Z0 J5 K5\nM2\n")
        res = tc.run(tc.Program.parse(text))
    path = res.path
    lengths = segment_lengths(path, tolerance=0.01)
    kind = np.asarray(path.kind)
    assert lengths.sum() == pytest.approx(path.length(True), rel=1e-9)
    assert lengths[kind != 0].sum() == pytest.approx(path.length(False), rel=1e-9)


L_SHAPE = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nY30\nG42.1 D10\nX80\nG40 G0 X90 Y40\nM2\n"


def _line(ax, label):
    found = [ln for ln in ax.get_lines() if ln.get_label() == label]
    assert found, [ln.get_label() for ln in ax.get_lines()]
    return np.column_stack(found[0].get_data())


def test_colour_by_side(mpl):
    import toolcomp as tc
    prof = tc.ControlProfile("fanuc")  # G41 <-> G42 without G40 between
    res = tc.run(tc.Program.parse(L_SHAPE), profile=prof)
    from toolcomp.plot import plot_result
    ax = plot_result(res, color_by="side")
    left, right = _line(ax, "left (G41 / RL)"), _line(ax, "right (G42 / RR)")
    # G41 r = 5 along y = 0 runs at y = 5; G42 along y = 30 (X50 -> X80) runs at y = 25.
    assert np.isclose(left[:, 1], 5).any() and not np.isclose(left[:, 1], 25).any()
    # The side change links the old perpendicular (45, 30) to the new one (50, 25).
    assert np.allclose(right[0], [45, 30]) and np.allclose(right[1:, 1], 25)
    with pytest.raises(ValueError, match="color_by"):
        plot_result(res, color_by="feed")


def test_lathe_half_section_and_3d_view(mpl, tmp_path):
    import toolcomp as tc
    from toolcomp.plot import plot_result, save_plot
    res = tc.run(tc.Program.parse("G21 G18 G8 G0 X20 Z2\nG1 Z-30 F100\nX30 Z-40\nG0 X40\nZ2\nM2\n"))
    ax = plot_result(res, plane="lathe")
    assert ax.get_xlabel() == "Z [mm]" and ax.get_ylabel() == "X [mm]"
    axis = _line(ax, "spindle axis")
    assert np.allclose(axis[:, 1], 0)
    xy = _line(ax, "compensated")
    assert np.isclose(xy[:, 0], -40).any() and np.isclose(xy[:, 1], 30).any()  # (Z-40, X30)
    helix = tc.run(tc.Program.parse("G21 G0 X10 Y0 Z0\nG3 X10 Y0 Z-6 I-10 J0 P3 F100\nM2\n"))
    ax3 = plot_result(helix, plane="3d")
    assert ax3.name == "3d"
    comp = [ln for ln in ax3.get_lines() if ln.get_label() == "compensated"][0]
    x, y, z = comp.get_data_3d()
    assert np.isclose(z.min(), -6) and np.isclose(x.min(), -10, atol=1e-3) and np.isclose(y.max(), 10, atol=1e-3)
    out = save_plot(helix, tmp_path / "helix.png", plane="3d")
    assert (tmp_path / "helix.png").stat().st_size > 1000 and out
