"""Heidenhain conversational (Klartext) programs: the spec's worked numbers through real
programs (§1.4 L-shape, §2.2 TOOL CALL deltas), contour functions, RL/RR/R0 and the TNC
errors at their lines."""
import math

import numpy as np
import pytest

import toolcomp as tc


def pgm(body, tools=None, strict=True):
    """A program with BEGIN PGM on line 1: the body's k-th line is source line k + 1."""
    lines = ["BEGIN PGM T MM"] + body.strip().splitlines() + ["END PGM T MM"]
    text = "\n".join(f"{i} {l.strip()}" for i, l in enumerate(lines))
    return tc.run(tc.Program.parse(text, dialect="heidenhain"), tools=tools, strict=strict, start="machine_zero")


def ends(p, i=None):
    return p.end[:, :2] if i is None else p.end[i, :2]


L_SHAPE = """
TOOL DEF 1 L+0 R+5
TOOL CALL 1 Z S3500
L X-10 Y-20 Z+10 R0 FMAX
L Z-5 F200
L X+0 Y+0 RL F300
L X+50
L Y+30
L X+80
L X+90 Y+40 R0
"""


def test_l_shape_inside_intersection_and_outside_transition_arc():
    # spec 1.4: A(0,0) B(50,0) C(50,30) D(80,30), RL, r = 5: inside joint B (45,5), outside
    # joint C: transition arc (45,30) -> (50,35) about (50,30); RL starts perpendicular at A.
    p = pgm(L_SHAPE).path
    on = np.flatnonzero(p.side == 1)
    np.testing.assert_allclose(ends(p)[on], [[0, 5], [45, 5], [45, 30], [50, 35], [80, 35]], atol=1e-12)
    arc = on[3]
    assert p.kind[arc] == tc.ARC_CW and p.generated[arc]
    np.testing.assert_allclose(p.center[arc, :2], [50, 30])
    assert list(p.line[on]) == [6, 7, 8, 9, 9]
    np.testing.assert_allclose(ends(p, -1), [90, 40])  # R0 leaves to the programmed point


def test_cr_arc_and_rnd():
    # CR from (40,40) to (70,40) R+20 DR-: centre (55, 26.771) (spec 1.3), then RND R5 between
    # two lines meeting at (80,40)...(80,10) (a right turn): tangent points 5 before and after.
    p = pgm("""
TOOL DEF 1 L+0 R+0
TOOL CALL 1 Z
L X+40 Y+40 Z+0 R0 F100
CR X+70 Y+40 R+20 DR-
L X+80 Y+40
RND R5
L X+80 Y+10
""").path
    arc = np.flatnonzero(p.line == 5)[0]
    np.testing.assert_allclose(p.center[arc, :2], [55, 40 - math.sqrt(400 - 225)])
    rnd = np.flatnonzero(p.line == 7)[0]
    assert p.kind[rnd] == tc.ARC_CW
    np.testing.assert_allclose(p.start[rnd, :2], [75, 40])
    np.testing.assert_allclose(ends(p, rnd), [80, 35])
    np.testing.assert_allclose(p.center[rnd, :2], [75, 35])


def test_tool_call_deltas_are_summed_as_the_manual_states():
    # L_eff = L + DL(TOOL CALL) + DL(table), R_eff = R + DR(TOOL CALL) + DR(table).
    table = tc.ToolTable.parse("tool,z,radius,z_wear,radius_wear\n5,100,6,0.1,-0.05\n", "csv")
    p = pgm("""
TOOL CALL 5 Z S2500 F350 DL+0.2 DR-1
L X-20 Y+0 R0 FMAX
L X+0 Y+0 RL
L X+50 Y+0
L X+60 Y-20 R0
""", tools=table).path
    np.testing.assert_allclose(p.tool_offset[0], [0, 0, 100 + 0.2 + 0.1])
    r = 6 - 1 - 0.05
    comp = np.flatnonzero(p.side == 1)
    np.testing.assert_allclose(ends(p, comp[-1]), [50, r])


def test_tool_axis_sets_the_working_plane():
    p = pgm("""
TOOL DEF 2 L+10 R+2
TOOL CALL 2 Y
L X+0 Y+0 Z+0 R0 FMAX
CC X+0 Z+10
C X+10 Z+10 DR+ F100
""").path
    assert p.plane[-1] == 1  # ZX plane for tool axis Y
    np.testing.assert_allclose(p.tool_offset[-1], [0, 10, 0])


def test_polar_moves_and_helix():
    p = pgm("""
TOOL DEF 1 L+0 R+0
TOOL CALL 1 Z
CC X+0 Y+0
L X+10 Y+0 Z+0 R0 F100
LP PR+10 PA+90
CP IPA+720 IZ-5 DR+
""").path
    np.testing.assert_allclose(p.end[1], [0, 10, 0], atol=1e-12)
    assert p.kind[2] == tc.ARC_CCW and p.turns[2] == 1
    np.testing.assert_allclose(p.end[2], [0, 10, -5], atol=1e-12)


def test_ctp_tangential_arc_to_a_polar_end_point():
    # From (10,0) heading +X, tangent arc to PR 10 PA 90 about the pole (0,0) = (0,10):
    # chord v = (-10,10), rho = |v|^2 / (2 v.n) = 200 / 20 = 10: CCW about (10,10).
    p = pgm("""
TOOL DEF 1 L+0 R+0
TOOL CALL 1 Z
CC X+0 Y+0
L X+0 Y+0 Z+0 R0 F100
L X+10
CTP PR+10 PA+90
""").path
    assert p.kind[-1] == tc.ARC_CCW
    np.testing.assert_allclose(p.end[-1], [0, 10, 0], atol=1e-12)
    np.testing.assert_allclose(p.center[-1], [10, 10, 0], atol=1e-12)
    with pytest.raises(tc.Error, match="CIRCLE CENTER UNDEFINED"):
        pgm("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nL X+10\nCTP PR+10 PA+90")


@pytest.mark.parametrize("body, message, line", [
    ("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nL X+10 RL\nL Y+10 RR", "RL and RR must be separated by an R0 block", 6),
    ("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nCC X+5 Y+0\nC X+10 Y+0 DR+ RL", "Radius compensation cannot start in a circle block", 6),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nC X+10 Y+0 DR+", "CIRCLE CENTER UNDEFINED", 5),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nCR X+50 Y+0 R+20 DR+", "ARC END POS. INCORRECT", 5),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nCC X+5 Y+0\nC X+10.1 Y+0 DR+", "ARC END POS. INCORRECT", 6),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 R0 F100\nL X+10\nRND R50\nL Y+10", "ROUNDING-OFF RADIUS TOO LARGE", 6),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nCHF 2\nL X+10 F100", "CHAMFER NOT PERMITTED", 4),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 Z+0 R0 F100\nL X+10\nRND R2\nLN X+10 Y+10 Z+0 NX+0 NY+0 NZ+1",
     "RND is not allowed next to an LN block", 6),
    ("TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+0 Y+0 Z+0 R0 F100\nL Z-5\nCHF 1\nL X+10", "CHF needs moves in the working plane on both sides", 6),
    ("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+0 Y-10 R0 F100\nL X+0 Y+0 RL\nL X+20\nCR X+24 Y+0 R+2 DR+\nL X+40", "TOOL RADIUS TOO LARGE", 7),
    ("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+0 Y-10 R0 F100\nL X+0 Y+0 RL\nL X+30\nL Y+4\nL X+0", "TOOL RADIUS TOO LARGE", 8),
])
def test_errors_at_their_lines(body, message, line):
    with pytest.raises(tc.Error) as e:
        pgm(body)
    assert (e.value.message, e.value.line) == (message, line)


STEP = """
TOOL DEF 1 L+0 R+5
TOOL CALL 1 Z
L X-10 Y+5 R0 F100
L X+0 Y+0 RL{m}
L X+30
L Y-2
L X+60
L X+70 Y+10 R0
"""


def test_m120_look_ahead_skips_what_the_tool_cannot_reach():
    with pytest.raises(tc.CompensationError, match="TOOL RADIUS TOO LARGE"):
        pgm(STEP.format(m=""))
    res = pgm(STEP.format(m=" M120 LA3"))
    assert any(d.code == "comp_skipped" for d in res.diagnostics)
    # the 2 mm step down is left out: the tool meets y = -2 + 5 on the corner arc about (30,0)
    assert any(np.allclose(e, [34, 3]) for e in ends(res.path))


def test_m97_meets_at_the_intersection_and_m98_leaves_the_corner_open():
    base = """
TOOL DEF 1 L+0 R+5
TOOL CALL 1 Z
L X+0 Y-10 R0 F100
L X+0 Y+0 RL
L X+50{m}
L Y-30
L X+60 Y-40 R0
"""
    plain = pgm(base.format(m="")).path
    assert plain.generated.any()  # transition arc at the outside corner (50,0)
    m97 = pgm(base.format(m=" M97")).path
    assert not m97.generated.any()
    assert any(np.allclose(e, [55, 5]) for e in ends(m97))  # intersection of y = 5 and x = 55
    m98 = pgm(base.format(m=" M98")).path
    link = np.flatnonzero(m98.generated)
    assert len(link) == 1 and m98.kind[link[0]] == tc.LINE
    np.testing.assert_allclose(m98.start[link[0], :2], [50, 5])
    np.testing.assert_allclose(ends(m98, link[0]), [55, 0])


def test_blank_and_units():
    text = "0 BEGIN PGM B INCH\n1 BLK FORM 0.1 Z X+0 Y+0 Z-1\n2 BLK FORM 0.2 X+4 Y+3 Z+0\n3 TOOL DEF 1 L+0 R+0\n4 TOOL CALL 1 Z\n5 L X+1 Y+1 Z+0 R0 F10\n6 END PGM B INCH\n"
    prog = tc.Program.parse(text, dialect="heidenhain")
    res = tc.run(prog, start="machine_zero")
    np.testing.assert_allclose(res.path.end[0], [25.4, 25.4, 0])
    assert res.path.feed[0] == pytest.approx(25.4)  # F in 1/10 inch/min
    np.testing.assert_allclose(res.blank, [[0, 0, -25.4], [101.6, 76.2, 0]])


# spec 2.5.4: r = 5, RR, PS = (40,10) via L X+40 Y+10 R0 FMAX.
APPR = """
TOOL DEF 1 L+0 R+5
TOOL CALL 1 Z
L X+40 Y+10 Z+0 R0 FMAX
{appr}
{next}
L X+40 Y+60
DEP LT LEN5
"""


@pytest.mark.parametrize("appr, nxt, ph, pa", [
    ("APPR LT X+20 Y+20 Z-10 LEN15 RR F100", "L X+35 Y+35", (12.929, 5.858), (23.536, 16.464)),
    ("APPR LN X+10 Y+20 Z-10 LEN+15 RR F100", "L X+20 Y+35", (26.641, 8.906), (14.160, 17.226)),
    ("APPR CT X+10 Y+20 Z-10 CCA180 R+10 RR F100", "L X+20 Y+35", (22.481, 11.679), (14.160, 17.226)),
    ("APPR LCT X+10 Y+20 Z-10 R10 RR F100", "L X+20 Y+35", (18.447, 9.455), (14.160, 17.226)),
])
def test_appr_worked_examples(appr, nxt, ph, pa):
    res = pgm(APPR.format(appr=appr, next=nxt))
    p = res.path
    appr_moves = np.flatnonzero(p.line == 5)
    if appr.startswith("APPR LCT"):
        # spec 2.5.1: LCT with X, Y and Z moves from PS to PH in all three axes, then in the plane
        assert len(appr_moves) == 2
        np.testing.assert_allclose(p.start[appr_moves[0]], [40, 10, 0], atol=1e-9)
        np.testing.assert_allclose(p.end[appr_moves[0]], [*ph, -10], atol=1e-3)
    else:
        np.testing.assert_allclose(p.end[appr_moves[0], :2], ph, atol=1e-3)       # PS -> PH in the plane
        np.testing.assert_allclose(p.end[appr_moves[1]], [*ph, -10], atol=1e-3)  # then to depth at PH
    np.testing.assert_allclose(p.end[appr_moves[-1]], [*pa, -10], atol=1e-3)     # PH -> PA (tool centre)
    assert (p.side[appr_moves] == 0).all()
    first = np.flatnonzero(p.line == 6)[0]  # the first contour element starts at PA_tool
    np.testing.assert_allclose(p.start[first, :2], pa, atol=1e-3)
    assert p.side[first] == -1


@pytest.mark.parametrize("dep, pn", [
    ("DEP LT LEN12.5", (15, 32.5)),
    ("DEP LN LEN+20", (35, 20)),
    ("DEP CT CCA180 R+8", (21, 20)),
    ("DEP LCT X+40 Y+40 R8", (40, 40)),
])
def test_dep_worked_examples(dep, pn):
    # last element L X+10 Y+20 RR coming from (10,0): t_E = +Y, PE_tool = (15, 20)
    res = pgm(f"""
TOOL DEF 1 L+0 R+5
TOOL CALL 1 Z
L X+10 Y-10 Z+0 R0 F100
L X+10 Y+0 RR
L X+10 Y+20
{dep}
""")
    p = res.path
    dep_moves = np.flatnonzero(p.line == 7)
    np.testing.assert_allclose(p.start[dep_moves[0], :2], [15, 20], atol=1e-9)
    np.testing.assert_allclose(p.end[dep_moves[-1], :2], pn, atol=1e-3)
    assert (p.side[dep_moves] == 0).all()
    if dep.startswith("DEP LCT"):
        np.testing.assert_allclose(p.end[dep_moves[0], :2], [16.216, 22.412], atol=1e-3)
    if dep.startswith("DEP CT"):
        np.testing.assert_allclose(p.center[dep_moves[0], :2], [18, 20], atol=1e-9)


def test_appr_lct_three_axes_only_when_all_three_are_given():
    # The tool circle of the spec 2.5.4 LCT example: centre (18.3205, 14.4530) (PA + 10 n_R,
    # n_R the right normal of (10, 15)), radius 10 - 5. PH is where the line from PS = (40, 10)
    # touches it.
    c = np.array([10, 20]) + 10 * np.array([15, -10]) / np.hypot(10, 15)
    base = "TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+40 Y+10 Z+0 R0 FMAX\n{appr}\nL X+20 Y+35\nL X+40 Y+60\nDEP LT LEN5\n"
    three = pgm(base.format(appr="APPR LCT X+10 Y+20 Z-10 R10 RR F100")).path
    lead = np.flatnonzero(three.line == 5)[0]
    ph = three.end[lead, :2]
    assert np.hypot(*(ph - c)) == pytest.approx(5, abs=1e-9)
    assert np.dot(ph - [40, 10], ph - c) == pytest.approx(0, abs=1e-9)  # tangent
    assert three.end[lead, 2] == -10 and three.start[lead, 2] == 0
    assert three.kind[lead + 1] == tc.ARC_CW  # then the arc at depth, no plunge at PH
    # Incremental words count: IX/IY/IZ reach the same points.
    inc = pgm(base.format(appr="APPR LCT IX-30 IY+10 IZ-10 R10 RR F100")).path
    np.testing.assert_allclose(inc.end, three.end, atol=1e-12)
    # Without Y the block gives no full point: PH in the plane first, then the depth.
    two = pgm(base.replace("Y+10 Z+0", "Y+20 Z+0").format(appr="APPR LCT X+10 Z-10 R10 RR F100")).path
    moves = np.flatnonzero(two.line == 5)
    assert two.end[moves[0], 2] == 0
    np.testing.assert_allclose(two.end[moves[1], :2], two.end[moves[0], :2], atol=1e-12)
    assert two.end[moves[1], 2] == -10


def test_appr_lct_needs_a_feed_and_ct_radius_too_large():
    with pytest.raises(tc.Error, match="feed"):
        pgm("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+40 Y+10 Z+0 R0 FMAX\nAPPR LCT X+10 Y+20 R10 RR\nL X+20 Y+35")
    with pytest.raises(tc.CompensationError, match="TOOL RADIUS TOO LARGE") as e:
        pgm("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+40 Y+10 Z+0 R0 FMAX\nAPPR CT X+10 Y+20 CCA90 R+4 RR F100\nL X+20 Y+35")
    assert e.value.line == 5


def test_appr_with_r0_computes_the_path_for_radius_0_and_rr():
    p = pgm("TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+40 Y+10 Z+0 R0 FMAX\nAPPR LN X+10 Y+20 LEN+15 R0 F100\nL X+20 Y+35").path
    # PH = PA + LEN * n_s with r = 0 and n_s the right normal of (0.5547, 0.8321)
    np.testing.assert_allclose(p.end[np.flatnonzero(p.line == 5)[0], :2], [10 + 15 * 0.83205, 20 - 15 * 0.5547], atol=1e-3)
    assert (p.side == 0).all()


def test_ct_radius_reading_is_a_profile_option():
    prof = tc.ControlProfile("heidenhain")
    prof.radius.ct_radius_on_contour = False  # R is the tool-centre radius
    text = "0 BEGIN PGM T MM\n1 TOOL DEF 1 L+0 R+5\n2 TOOL CALL 1 Z\n3 L X+40 Y+10 Z+0 R0 FMAX\n4 APPR CT X+10 Y+20 CCA180 R+10 RR F100\n5 L X+20 Y+35\n6 END PGM T MM\n"
    p = tc.run(tc.Program.parse(text, dialect="heidenhain"), profile=prof).path
    arc = np.flatnonzero((p.line == 5) & (p.kind >= tc.ARC_CW))[0]
    assert math.dist(p.start[arc, :2], p.center[arc, :2]) == pytest.approx(10)


def test_paraxial_r_plus_and_minus():
    body = "TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+0 Y+0 Z+0 R0 F100\nL X+50 R+\nL Y+30 R-"
    p = pgm(body).path
    np.testing.assert_allclose(p.end[-2, :2], [55, 0])   # lengthened by the radius
    np.testing.assert_allclose(p.end[-1, :2], [55, 25])  # shortened by the radius
    with pytest.raises(tc.ProgramError, match="single axis"):
        pgm(body + "\nL X+10 Y+10 R+")


def test_q_parameters_labels_subprograms_and_repeats():
    res = pgm("""
FN 0: Q1 = +10
FN 1: Q2 = +Q1 + +5
Q3 = Q2 * 2 - SQRT(16) + SIN(90)
TOOL DEF 1 L+0 R+0
TOOL CALL 1 Z
L X+0 Y+0 Z+0 R0 F100
L X+Q1 Y+Q3
FN 0: Q10 = +0
LBL 1
FN 1: Q10 = +Q10 + +1
L IY+1
FN 12: IF +Q10 LT +3 GOTO LBL 1
CALL LBL 5
LBL 2
L IX+2
CALL LBL 2 REP 2/2
M30
LBL 5
L X-Q2
LBL 0
""")
    p = res.path
    np.testing.assert_allclose(p.end[0, :2], [10, 27])  # Q3 = 15 * 2 - 4 + 1
    np.testing.assert_allclose(p.end[1:4, 1], [28, 29, 30])  # the loop ran three times
    np.testing.assert_allclose(p.end[4, :2], [-15, 30])  # the subprogram
    np.testing.assert_allclose(p.end[5:, 0], [-13, -11, -9])  # the section ran once and twice more
    assert len(p) == 8


def test_q_errors_and_the_block_limit():
    with pytest.raises(tc.ProgramError, match="FN 14: ERROR 7") as e:
        pgm("FN 14: ERROR = 7")
    assert e.value.line == 2
    with pytest.raises(tc.ProgramError, match="division by zero") as e:
        pgm("FN 0: Q1 = +0\nFN 4: Q2 = +5 DIV +Q1")
    assert e.value.line == 3
    prof = tc.ControlProfile("heidenhain")
    prof.block_limit = 1000
    text = "0 BEGIN PGM L MM\n1 LBL 1\n2 FN 9: IF +0 EQU +0 GOTO LBL 1\n3 END PGM L MM\n"
    with pytest.raises(tc.ProgramError, match="block_limit|endless loop"):
        tc.run(tc.Program.parse(text, dialect="heidenhain"), profile=prof)


def test_m_functions_of_appr_and_dep_act():
    # DEP ... M2 ends the program after the departure: the L block after it never runs.
    text = APPR.format(appr="APPR LT X+20 Y+20 Z-10 LEN15 RR F100", next="L X+35 Y+35").replace(
        "DEP LT LEN5", "DEP LT LEN5 F200 M2\nL X+0 Y+0 R0 FMAX")
    res = pgm(text)
    assert res.path.line.max() == 8  # the DEP block
    assert res.path.feed[-1] == 200
    with pytest.raises(tc.Error) as e:  # M91 (machine datum) acts in L blocks only
        pgm(APPR.format(appr="APPR LT X+20 Y+20 Z-10 LEN15 RR F100 M91", next="L X+35 Y+35"))
    assert (e.value.code, e.value.line) == ("bad_word", 5) and "L blocks only" in str(e.value)


@pytest.mark.parametrize("appr, code", [
    ("APPR LT X+20 Y+20 Z-10 LEN15 RR", "no_feed"),           # no F up to the approach
    ("APPR LT X+20 Y+20 Z-10 LEN15 RR FMAX", "unsupported_word"),
])
def test_appr_needs_a_feed(appr, code):
    with pytest.raises(tc.Error) as e:
        pgm(APPR.format(appr=appr, next="L X+35 Y+35"))
    assert (e.value.code, e.value.line) == (code, 5)
