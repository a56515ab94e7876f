"""Numerical robustness of cutter radius compensation (G41/G42, LinuxCNC dialect): generated
contours with nearly tangent corners (turns down to 1e-9 rad), nearly reversed corners,
tiny segments (1e-9 mm), huge coordinates (1e6 mm), arcs of 1e-6 to 1e5 mm radius and full
circles. Every run either raises a tc.Error with a code and a line, or returns a path that

* holds only finite coordinates (start, end, and the centre of every arc),
* is continuous: each segment starts where the one before it ended (1e-9 mm, relative to
  the coordinates' magnitude where they are large), and
* keeps the tool centre at least r - eps from the programmed contour (Shapely distances to
  the contour as generated here, not as toolcomp read it), or else reports it: a warning
  "comp_overcut" on the line of the segment that comes too close (LinuxCNC cuts such paths
  without an error, and toolcomp keeps its path, see the tests at the end).

Contours that come back within 2r of themselves away from a corner (a loop, a spiral) are
not generated: no control checks for such an interference, so it says nothing about the
compensation's arithmetic. Hypothesis runs derandomized with a fixed number of examples."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings, strategies as st

import toolcomp as tc

shapely = pytest.importorskip("shapely")
from shapely.geometry import LineString  # noqa: E402

ROBUST = settings(max_examples=150, deadline=None, derandomize=True, database=None, print_blob=True,
                  suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

RADII = [0.5, 2.0, 5.0]  # tool radius r


def num(v):
    """Shortest exact decimal spelling (G-code has no exponent notation)."""
    return np.format_float_positional(float(v), unique=True, trim="-")


def log_uniform(lo, hi):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0 ** e)


signs = st.sampled_from([-1.0, 1.0])
turn = st.one_of(
    st.just(0.0),                                                              # tangent
    st.tuples(signs, log_uniform(1e-9, 1e-3)).map(lambda t: t[0] * t[1]),      # nearly tangent
    st.floats(-2.8, 2.8),                                                      # ordinary corner
    st.tuples(signs, log_uniform(1e-9, 1e-3)).map(lambda t: t[0] * (math.pi - t[1])),  # nearly reversed
)
length = st.one_of(log_uniform(1e-9, 1e-6), st.floats(0.5, 50.0))
arc_radius = st.one_of(st.just(1e-6), log_uniform(2e-3, 1.0), st.floats(1.0, 50.0), st.just(1e5))

line_el = st.tuples(st.just("line"), turn, length)
arc_el = st.tuples(st.just("arc"), turn, arc_radius, st.floats(1e-6, 1.0), signs)  # sweep as a fraction of pi
circle_el = st.tuples(st.just("circle"), turn, st.one_of(st.just(1e-6), st.floats(0.5, 30.0)), signs)
elements = st.lists(st.one_of(line_el, line_el, arc_el, circle_el), min_size=1, max_size=6)
origin = st.sampled_from([(0.0, 0.0), (1e6, -1e6), (-1e6, 1e6)])


def build(start, heading, elems):
    """The contour as exact elements: ("line", p, q) or ("arc", p, q, centre, dir, sweep). A
    10 mm lead-in line comes first, so that the entry move always meets a plain element."""
    p = np.array(start, dtype=float)
    phi = heading
    out = []
    for el in [("line", 0.0, 10.0)] + list(elems):
        phi += el[1]
        t = np.array([math.cos(phi), math.sin(phi)])
        if el[0] == "line":
            q = p + el[2] * t
            out.append(("line", p, q))
            p = q
            continue
        if el[0] == "arc":
            _, _, radius, frac, d = el
            # A huge radius sweeps little: the arc stays a few hundred mm long.
            sweep = frac * math.pi * (min(1.0, 500.0 / radius) if radius > 50 else 1.0)
        else:
            _, _, radius, d = el
            sweep = 2 * math.pi
        n = d * np.array([-t[1], t[0]])  # left normal for CCW (d = +1), right for CW
        c = p + radius * n
        a0 = math.atan2(p[1] - c[1], p[0] - c[0])
        a1 = a0 + d * sweep
        q = p.copy() if el[0] == "circle" else c + radius * np.array([math.cos(a1), math.sin(a1)])
        out.append(("arc", p, q, c, int(d), sweep))
        p = q
        phi += d * sweep
    return out


def chords(e, tol):
    """Chord count of an arc element for a sagitta of `tol`, at most 5000, and the sagitta
    that count leaves (the chords lie inside the arc)."""
    _, p, q, c, d, sweep = e
    r = float(np.hypot(*(p - c)))
    step = 2 * math.acos(max(-1.0, 1 - tol / r)) if r > tol else math.pi / 8
    k = int(min(5000, max(2, math.ceil(sweep / step))))
    return k, r * (1 - math.cos(sweep / (2 * k)))


def elem_points(e, tol=1e-8):
    if e[0] == "line":
        return np.array([e[1], e[2]])
    _, p, q, c, d, sweep = e
    r = float(np.hypot(*(p - c)))
    k, _ = chords(e, tol)
    a0 = math.atan2(p[1] - c[1], p[0] - c[0])
    a = a0 + d * sweep * np.linspace(0, 1, k + 1)
    pts = c + r * np.stack([np.cos(a), np.sin(a)], axis=1)
    pts[0], pts[-1] = p, q
    return pts


def elem_length(e):
    if e[0] == "line":
        return float(np.hypot(*(e[2] - e[1])))
    return float(np.hypot(*(e[1] - e[3]))) * e[5]


def interferes(contour, r):
    """Whether two parts of the contour that are apart along it (more than 4r of contour in
    between) come within 2r of each other: a loop that no control checks."""
    geoms = [LineString(elem_points(e, 1e-4)) for e in contour]
    lengths = [elem_length(e) for e in contour]
    for i in range(len(contour)):
        between = 0.0
        for j in range(i + 1, len(contour)):
            if between > 4 * r and geoms[i].distance(geoms[j]) < 2 * r + 1e-3:
                return True
            between += lengths[j]
    return False


def turn_between(a, b):
    t1, t2 = tangents(a)[1], tangents(b)[0]
    return math.atan2(t1[0] * t2[1] - t1[1] * t2[0], float(t1 @ t2))


def wraps_round_short_elements(contour, r):
    """Whether a run of elements shorter than 2r in all, with the corners at both its ends,
    turns back by more than pi: LinuxCNC's corner arcs, one corner at a time, then sweep over
    the neighbouring elements (no control checks it)."""
    for k in range(1, len(contour)):
        total, length = turn_between(contour[k - 1], contour[k]), 0.0
        for m in range(k, len(contour)):
            e = contour[m]
            length += elem_length(e)
            if length >= 2 * r:
                break
            if e[0] == "arc":
                total += e[4] * e[5]
            if m + 1 < len(contour):
                total += turn_between(e, contour[m + 1])
            if abs(total) > math.pi - 0.1:
                return True
    return False


def tool_outside_full_circle(contour, side):
    """A full circle with the tool outside it: the tool's circle of radius R + r about a centre
    R from the element before always crosses that element (an impossible program, which no
    control checks). Inside a full circle the tool stays r clear."""
    s = 1 if side == "G41" else -1
    full = [i for i, e in enumerate(contour) if e[0] == "arc" and e[5] > 2 * math.pi - 1e-12]
    # After an arc, a full circle comes back over that arc (it lies inside or outside it).
    return any(contour[i][4] != s or contour[i - 1][0] != "line" for i in full)


def program(contour, r, side, heading):
    """G41/G42 program: approach from outside, the contour, G40 exit."""
    p0 = contour[0][1]
    t0 = np.array([math.cos(heading + 0.0), math.sin(heading)])
    s = 1.0 if side == "G41" else -1.0
    n0 = s * np.array([-t0[1], t0[0]])
    entry = p0 - 4 * r * t0 + 4 * r * n0
    last = contour[-1]
    pe = last[2]
    lines = ["G21 G17 G90 G91.1 G40 G49", "T1 M6", f"G0 X{num(entry[0])} Y{num(entry[1])} Z5", "G1 Z-1 F100",
             f"{side} D1", f"G1 X{num(p0[0])} Y{num(p0[1])}"]
    for e in contour:
        if e[0] == "line":
            lines.append(f"G1 X{num(e[2][0])} Y{num(e[2][1])}")
        else:
            _, p, q, c, d, _ = e
            lines.append(f"{'G3' if d > 0 else 'G2'} X{num(q[0])} Y{num(q[1])} I{num(c[0] - p[0])} J{num(c[1] - p[1])}")
    # Exit: away from the last point along the contour side.
    lines.append(f"G40 G1 X{num(pe[0] + 4 * r * n0[0] + 3 * r)} Y{num(pe[1] + 4 * r * n0[1] + 3 * r)}")
    lines.append("G0 Z5")
    lines.append("M2")
    return "\n".join(lines) + "\n"


def magnitude(*arrays):
    m = 1.0
    for a in arrays:
        if a.size:
            m = max(m, float(np.nanmax(np.abs(a))))
    return m


def check_finite(path):
    assert np.isfinite(path.start).all() and np.isfinite(path.end).all()
    arcs = path.kind >= tc.ARC_CW
    assert np.isfinite(path.center[arcs]).all()


def check_continuous(path):
    if len(path) < 2:
        return
    mag = magnitude(path.start, path.end)
    gap = np.abs(path.start[1:] - path.end[:-1]).max(axis=1)
    bad = np.flatnonzero(gap > 1e-9 * mag)
    assert not bad.size, (f"gap {gap[bad[0]]:.3g} mm between segments {bad[0]} and {bad[0] + 1} "
                          f"(line {path.line[bad[0] + 1]})")


def check_clearance(path, contour, r, allowance=0.0):
    """None when the tool centre keeps r - eps from the contour, else (distance, line) of the
    worst sample."""
    on = np.flatnonzero(path.side != 0)
    if on.size < 2:
        return None
    pts, seg = path.sample(1e-4)
    keep = np.isin(seg, on[1:])  # without the entry move, which comes in from outside
    if not keep.any():
        return None
    mag = magnitude(pts[keep][:, :2])
    sagitta = max([chords(e, 1e-8)[1] for e in contour if e[0] == "arc"], default=0.0)
    eps = 1e-6 + 1e-12 * mag + sagitta + allowance
    geom = shapely.union_all([LineString(elem_points(e)) for e in contour])
    dist = shapely.distance(geom, shapely.points(pts[keep][:, :2]))
    worst = int(np.argmin(dist))
    if dist[worst] >= r - eps:
        return None
    return float(dist[worst]), int(path.line[seg[keep][worst]])


def tangents(e):
    """Start and end direction of an element, from its coordinates as written (at 1e6 mm a
    1e-9 mm segment points where the rounded coordinates say)."""
    if e[0] == "line":
        d = e[2] - e[1]
        return d, d
    _, p, q, c, d, _ = e
    rot = lambda v: d * np.array([-v[1], v[0]])  # noqa: E731
    return rot(p - c), rot(q - c)


def in_domain(contour, r, side):
    # Corners within corner_tolerance (0.05 rad) of a reversal and inside
    # corners onto elements shorter than their pull-back are in the
    # domain: their paths may cut into the contour, and then must report it (comp_overcut).
    return not (tool_outside_full_circle(contour, side) or interferes(contour, r)
                or wraps_round_short_elements(contour, r))


def run_case(org, heading, elems, r, side, domain=None):
    contour = build(org, heading, elems)
    if domain is not None:
        domain(in_domain(contour, r, side))
    text = program(contour, r, side, heading)
    tools = tc.ToolTable.parse(f"T1 P1 D{num(2 * r)}\n", "linuxcnc")
    rules = tc.ControlProfile("linuxcnc")
    try:
        res = tc.run(tc.Program.parse(text, dialect="linuxcnc"), tools=tools, profile=rules)
    except tc.Error as e:
        assert e.code and e.line >= 1, (type(e).__name__, e.code, e.line, str(e))
        return
    for p in (res.nominal, res.path):
        check_finite(p)
        check_continuous(p)
    # LinuxCNC joins elements that turn by less than corner_tolerance (0.05 rad) as tangent:
    # the next element starts where the last ended, up to r(1 - cos 0.05) off its equidistant.
    tol = rules.radius.corner_tolerance
    near = any(0 < abs(turn_between(a, b)) < tol + 1e-6 for a, b in zip(contour, contour[1:]))
    close = check_clearance(res.path, contour, r, r * (1 - math.cos(tol)) if near else 0.0)
    overcut = [d for d in res.diagnostics if d.code == "comp_overcut"]
    if close is not None:  # the third outcome: a path that cuts into the contour, reported
        dist, line = close
        assert any(d.line == line and d.severity == "warning" for d in overcut), (
            f"tool centre {dist:.9g} mm from the contour, radius {r} (line {line}), no comp_overcut "
            f"warning there: {[(d.line, d.message) for d in overcut]}")
    return res


@ROBUST
@example(org=(0.0, 0.0), heading=0.0, elems=[("line", 1e-9, 10.0)], r=2.0, side="G41")
@example(org=(0.0, 0.0), heading=0.0, elems=[("line", -1e-9, 10.0)], r=2.0, side="G41")
@example(org=(0.0, 0.0), heading=0.0, elems=[("line", math.pi - 1e-9, 10.0)], r=2.0,
         side="G41")
@example(org=(0.0, 0.0), heading=0.0, elems=[("line", -(math.pi - 1e-9), 10.0)], r=2.0,
         side="G41")
@example(org=(1e6, -1e6), heading=0.3, elems=[("line", 0.5, 1e-9), ("line", 0.5, 10.0)],
         r=2.0, side="G42")
@example(org=(0.0, 0.0), heading=0.0, elems=[("arc", 0.0, 1e5, 0.001, -1.0),
                                             ("line", 0.0, 10.0)], r=2.0, side="G41")
@example(org=(0.0, 0.0), heading=0.0, elems=[("circle", 0.0, 10.0, 1.0),
                                             ("line", 0.0, 10.0)], r=2.0, side="G41")
@given(org=origin, heading=st.floats(-math.pi, math.pi), elems=elements, r=st.sampled_from(RADII),
       side=st.sampled_from(["G41", "G42"]))
def test_compensated_contours_are_finite_continuous_and_clear(org, heading, elems, r, side):
    run_case(org, heading, elems, r, side, domain=assume)


# Findings of the property test above. LinuxCNC (its gcode module, through the same
# programs as tests/programs/comp/overcut_*.ngc written with G41.1/G42.1 D1) cuts both
# without an error; toolcomp keeps LinuxCNC's path and warns "comp_overcut".

def overcuts(res):
    return [(d.line, d.severity, d.message) for d in res.diagnostics if d.code == "comp_overcut"]


def test_inside_corner_into_a_tiny_element_then_tangent():
    # Lead-in 10 mm along +X (line 7), G41 r = 0.5, a left turn of 1 rad onto a 1e-6 mm line
    # (line 8), a tangent 1e-6 mm line (line 9), G40. The pull-back r·tan(1/2) = 0.273 mm is
    # longer than line 8, so its equidistant runs backwards, down towards line 7.
    res = run_case((0.0, 0.0), 0.0, [("line", 1.0, 1e-6), ("line", 0.0, 1e-6)], 0.5, "G41")
    # LinuxCNC's moves of lines 7, 8 and 9 (gcode module, full precision).
    lcnc = [(7, 9.726848755116002, 0.49999999999999994), (8, 9.579265047929896, 0.27015199445417354),
            (9, 9.579265588232202, 0.2701528359251584)]
    p = res.path
    for line, x, y in lcnc:
        (i,) = np.flatnonzero(p.line == line)
        assert p.end[i][:2] == pytest.approx([x, y], abs=1e-9)
    # By hand: the moves of lines 8 and 9 end 0.270152 mm above line 7 (y = 0, x in [0, 10]),
    # their nearest point to it: 0.229848 mm into the part.
    got = overcuts(res)
    assert [(line, sev) for line, sev, _ in got] == [(8, "warning"), (9, "warning")]
    for _, _, msg in got:
        assert "0.270152 mm from the programmed contour of line 7" in msg
        assert "tool radius 0.500000 mm" in msg and "0.229848 mm into the part" in msg


def test_nearly_reversed_inside_corner_before_a_circle():
    # G42 r = 0.5: the lead-in along +X (line 7), then a CW full circle of radius 1 (line 8)
    # turning right by pi - 1e-3: an inside corner within corner_tolerance (0.05 rad) of a
    # reversal, which LinuxCNC takes as an outside corner: a transition arc of radius r about
    # the programmed corner (10, 0), CCW from (10, -0.5) round the tip to (9.9995, 0.5).
    res = run_case((0.0, 0.0), 0.0, [("circle", -(math.pi - 1e-3), 1.0, -1.0)], 0.5, "G42")
    p = res.path
    i, j = np.flatnonzero(p.line == 8)
    assert (int(p.kind[i]), int(p.kind[j])) == (int(tc.ARC_CCW), int(tc.ARC_CW))
    assert p.end[i][:2] == pytest.approx([9.999500000083334, 0.49999975000002084], abs=1e-9)  # LinuxCNC
    assert p.center[i][:2] == pytest.approx([10.0, 0.0], abs=1e-9)
    assert p.center[j][:2] == pytest.approx([9.999000000166667, 0.9999995000000417], abs=1e-9)
    # By hand: the transition arc (centre (10, 0), radius 0.5) and the programmed circle
    # (centre c = (10 - 1e-3·cos(1e-3), 1 - 5e-7), radius 1) have centres d = 1.0000005 apart,
    # within 1 - 0.5 < d < 1 + 0.5: they cross, at a = (0.25 - 1 + d²) / 2d = 0.125 along the
    # line of centres and h = sqrt(0.25 - a²) = 0.484 across it, i.e. near (10.484, 0.125),
    # at +14.5 degrees about (10, 0): inside the arc's CCW sweep from -90 to +90 degrees.
    c = np.array([10 - 1e-3 * math.cos(1e-3), 1 - 0.5e-6])
    d = float(np.hypot(*(c - [10.0, 0.0])))
    a = (0.25 - 1 + d * d) / (2 * d)
    h = math.sqrt(0.25 - a * a)
    u = (c - [10.0, 0.0]) / d
    crossings = [np.array([10.0, 0.0]) + a * u + s * h * np.array([u[1], -u[0]]) for s in (1, -1)]
    assert any(x[0] > 10 for x in crossings)  # on the +X side, which the CCW arc sweeps
    got = overcuts(res)
    assert [(line, sev) for line, sev, _ in got] == [(8, "warning")]
    assert "0.000000 mm from the programmed contour of line 8" in got[0][2]
    assert "0.500000 mm into the part" in got[0][2]
