"""Independent geometry check of cutter radius compensation with Shapely: along the contour
the compensated tool centre keeps at least the tool radius from the programmed path, and
touches each programmed element (comes within the radius of it)."""
import numpy as np
import pytest

import toolcomp as tc

shapely = pytest.importorskip("shapely")
from shapely.geometry import LineString  # noqa: E402
from shapely.ops import unary_union  # noqa: E402

CONTOURS = {
    # closed outside profile with arcs, climb (G41) around the outside
    "outside_profile": ("G41.1 D{d}", """G0 X-20 Y-20
{comp}
G1 X0 Y0 F300
G1 X0 Y30
G2 X10 Y40 R10
G1 X40 Y40
G2 X50 Y30 I0 J-10
G1 X50 Y0
G1 X0 Y0
G40
G0 X-20 Y-20
"""),
    # closed pocket inside, G42 going clockwise keeps the tool inside
    "pocket": ("G42.1 D{d}", """G0 X25 Y20
{comp}
G1 X25 Y10 F300
G1 X10 Y10
G2 X5 Y15 R5
G1 X5 Y30
G1 X37 Y30
G2 X45 Y22 I0 J-8
G3 X45 Y10 R10
G1 X25 Y10
G40
G1 X25 Y20
"""),
    # open contour with a convex and a concave arc
    "open_wave": ("G41.1 D{d}", """G0 X-10 Y-10
{comp}
G1 X0 Y0 F300
G1 X20 Y0
G3 X40 Y0 R10
G2 X60 Y0 R10
G1 X80 Y5
G40
G1 X90 Y-10
"""),
}


def element(pts, seg, i):
    """The polyline of segment i: its points and the point it starts from."""
    idx = np.flatnonzero(seg == i)
    return LineString(pts[np.r_[idx[0] - 1, idx]][:, :2])


def profile(name):
    prof = tc.ControlProfile("fanuc" if name.startswith("fanuc") else "linuxcnc")
    if name == "fanuc_type_b":
        prof.radius.entry = tc.EntryStyle.perpendicular_to_entry
    if name == "g451":
        prof.radius.outside_corner = tc.OutsideCorner.intersection
        prof.radius.corner_limit = np.radians(100)
    if name == "skip":
        prof.radius.gouge = tc.GougeReaction.skip
        prof.radius.lookahead = 3
    return prof


def compensated_and_contour(name, d, prof):
    comp, body = CONTOURS[name]
    text = "G21 G17 G90\n" + body.format(comp=comp.format(d=d)) + "M2\n"
    res = tc.run(tc.Program.parse(text), profile=prof)
    return res


PROFILES = ["linuxcnc", "fanuc", "fanuc_type_b", "g451", "skip"]


@pytest.mark.parametrize("prof", PROFILES)
@pytest.mark.parametrize("name", sorted(CONTOURS))
@pytest.mark.parametrize("d", [2.0, 4.0, 6.0])
def test_centre_path_keeps_the_radius_and_touches_the_contour(name, d, prof):
    r = d / 2
    res = compensated_and_contour(name, d, profile(prof))
    path, nom = res.path, res.nominal
    on = np.flatnonzero(path.side != 0)
    # The programmed contour: the nominal moves made with compensation, minus the entry move.
    nom_on = np.flatnonzero(nom.side != 0)[1:]
    pts, seg = nom.sample(1e-7)
    contour_elems = [element(pts, seg, i) for i in nom_on]
    contour = unary_union(contour_elems)
    # The compensated centre path without the entry move (it comes in from outside).
    cpts, cseg = path.sample(1e-4)  # vertices lie exactly on the centre path
    keep = np.isin(cseg, on[1:])
    centre = cpts[keep][:, :2]
    dist = shapely.distance(contour, shapely.points(centre))
    assert dist.min() >= r - 1e-6
    # Every programmed element is touched: some centre point lies at the radius from it.
    # Straight pieces are exact segments; arcs are their (exact) vertices.
    lines = [LineString([path.start[i, :2], path.end[i, :2]]) for i in on[1:] if path.kind[i] <= tc.LINE]
    vertices = shapely.points(cpts[np.isin(cseg, on[1:]) | np.isin(cseg, on[1:] - 1)][:, :2])
    for elem in contour_elems:
        nearest = shapely.distance(elem, vertices).min()
        if lines:
            nearest = min(nearest, min(elem.distance(ln) for ln in lines))
        assert abs(nearest - r) < 1e-6, elem
