"""Sinumerik 840D part programs through the sinumerik front end: syntax, R parameters and
expressions, control structures, subprograms, frames, circles, units, tool data, radius
compensation with the modal G groups, and the alarms with their numbers and lines. Every
expected number is worked by hand (comments) from the programmed contour."""
import math
import pathlib

import numpy as np
import pytest

import toolcomp as tc

# T1 D1: end mill r = 5, L1 = 100 (type 120); T2 D1: r = 3.
TOOLS = """$TC_DP1[1,1]=120
$TC_DP3[1,1]=100
$TC_DP6[1,1]=5
$TC_DP1[2,1]=120
$TC_DP6[2,1]=3
"""


def run(body, tools=TOOLS, **kw):
    prog = tc.Program.parse(tools + body, dialect="sinumerik")
    return tc.run(prog, **kw)


def ends(path):
    return [tuple(float(v) for v in np.round(e[:3], 9)) for e in path.end]


def segs(path):
    return [(int(k), tuple(np.round(s[:2], 9)), tuple(np.round(e[:2], 9)), bool(g))
            for k, s, e, g in zip(path.kind, path.start, path.end, path.generated)]


def raises(body, code_or_alarm, line, tools=TOOLS, **kw):
    with pytest.raises(tc.Error) as e:
        run(body, tools, **kw)
    assert e.value.code == code_or_alarm or e.value.message.startswith(code_or_alarm), e.value
    assert e.value.line == line + (tools.count("\n") if tools else 0), (e.value.line, e.value)
    return e.value


# ---- syntax -----------------------------------------------------------------------------------

def test_block_numbers_labels_comments_header_and_case():
    text = "%_N_PART_MPF\n;$PATH=/_N_MPF_DIR\nN10 g0 x10 y20 z5 ; approach\n:20 START: G1 X=15 F=200\nN30 M30\n"
    res = tc.run(tc.Program.parse(text, dialect="sinumerik"))
    assert ends(res.nominal) == [(10, 20, 5), (15, 20, 5)]
    assert list(res.nominal.line) == [3, 4]


def test_suffixes_select_the_dialect(tmp_path):
    for suffix in ("mpf", "spf", "MPF"):
        p = tmp_path / f"a.{suffix}"
        p.write_text("G0 X1\nM30\n")
        assert tc.Program.read(p).dialect == "sinumerik"


def test_words_without_blanks_and_signed_values():
    res = run("G0X10Y-5.5Z.5\nM30\n", tools="")
    assert ends(res.nominal) == [(10, -5.5, 0.5)]


@pytest.mark.parametrize("text, col", [("G1 X=(10\n", 9), ("G1 X=10 Y=*3\n", 11), ("G1 X10 @\n", 8)])
def test_syntax_errors_have_line_and_column(text, col):
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse("G0 X0\n" + text, dialect="sinumerik")
    assert e.value.line == 2 and e.value.column == col


# ---- R parameters, DEF, expressions -------------------------------------------------------------

def test_r_parameters_and_functions_in_degrees():
    # R2 = 2*10 + SIN(30) = 20.5; R3 = POT(3) + SQRT(16) = 13; R[4] = ATAN2(1,1) = 45
    res = run("R1=10 R2=2*R1+SIN(30)\nR3=POT(3)+SQRT(16) R[4]=ATAN2(1,1)\nG0 X=R2 Y=R3 Z=R4\nM30\n", tools="")
    assert ends(res.nominal) == [(20.5, 13, 45)]


def test_assignment_takes_effect_inside_its_block():
    res = run("R1=7 G0 X=R1\nM30\n", tools="")
    assert ends(res.nominal)[0][0] == 7


def test_def_locals_int_rounding_and_arrays():
    text = "DEF INT N=2.6\nDEF REAL P[3]\nP[0]=1.5 P[2]=N*2\nG0 X=P[0] Y=P[2] Z=N\nM30\n"
    assert ends(run(text, tools="").nominal) == [(1.5, 6, 3)]


def test_comparisons_bind_weakest_as_on_the_control():
    # 1 == 1 AND 0 parses as 1 == (1 AND 0) -> 0; with brackets it is 0 too; 2+1 == 3 -> 1
    res = run("R1=1==1 AND 0\nR2=(1==1) AND (2==2)\nR3=2+1==3\nG0 X=R1 Y=R2 Z=R3\nM30\n", tools="")
    assert ends(res.nominal) == [(0, 1, 1)]


@pytest.mark.parametrize("stmt, code", [("R1=1/0", "math_error"), ("R1=SQRT(-1)", "math_error"),
                                        ("R1=UNKNOWN+1", "12550"), ("R1000=1", "12550")])
def test_expression_errors(stmt, code):
    raises(f"G0 X0\n{stmt}\nM30\n", code, 2, tools="")


def test_def_after_an_executable_block_is_14500():
    raises("G0 X0\nDEF REAL A\nM30\n", "14500", 2, tools="")


# ---- control structures -------------------------------------------------------------------------

def unrolled(xs):
    return [(float(x), 0.0, 0.0) for x in xs]


def test_while_for_repeat_loop_and_if_else():
    prog = """DEF INT I
R1=0
WHILE R1<3
  R1=R1+1
  G0 X=R1
ENDWHILE
FOR I=5 TO 6
  G0 X=I
ENDFOR
REPEAT
  R1=R1-1
  G0 X=R1*10
UNTIL R1<=1
IF R1==1
  G0 X=100
ELSE
  G0 X=200
ENDIF
M30
"""
    assert ends(run(prog, tools="").nominal) == unrolled([1, 2, 3, 5, 6, 20, 10, 100])


def test_gotof_gotob_labels_and_block_numbers():
    prog = """R1=0
BACK: R1=R1+1
G0 X=R1
IF R1<3 GOTOB BACK
GOTOF N90
G0 X=50
N90 G0 X=99
M30
"""
    assert ends(run(prog, tools="").nominal) == unrolled([1, 2, 3, 99])


def test_jump_to_a_missing_label_is_14080():
    raises("G0 X0\nGOTOF NOWHERE\nM30\n", "14080", 2, tools="")


def test_unclosed_structure_is_an_error_with_its_line():
    raises("G0 X0\nWHILE 1\nG0 X1\nM30\n", "14060", 2, tools="")


def test_endless_loop_stops_at_the_block_limit():
    prof = tc.ControlProfile("sinumerik")
    prof.block_limit = 10_000
    # executed: LOOP, then G0 / ENDLOOP alternately: block 10 001 is an ENDLOOP (line 3)
    e = raises("LOOP\nG0 X1\nENDLOOP\nM30\n", "block_limit", 3, tools="", profile=prof)
    assert "10000" in e.message


# ---- subprograms ----------------------------------------------------------------------------------

def test_subprograms_from_the_search_path_with_passes(tmp_path):
    (tmp_path / "L10.SPF").write_text("G91 G0 X10\nG90\nM17\n")
    (tmp_path / "pocket.spf").write_text("PROC POCKET\nG0 Y=R5\nRET\n")
    res = run("G0 X0 Y0\nL10 P3\nR5=7\nPOCKET\nM30\n", tools="", search_path=[str(tmp_path)])
    assert ends(res.nominal) == [(0, 0, 0), (10, 0, 0), (20, 0, 0), (30, 0, 0), (30, 7, 0)]
    assert list(res.nominal.line) == [1, 1, 1, 1, 2]  # lines of the subprogram files
    assert list(res.nominal.file) == [0, 1, 1, 1, 2]  # ... and which files those are
    assert [pathlib.Path(f).name for f in res.nominal.files[1:]] == ["L10.SPF", "pocket.spf"]
    assert res.path.files == res.nominal.files


def test_missing_subprogram_is_14011():
    raises("G0 X0\nL77\nM30\n", "14011", 2, tools="")


# ---- frames -------------------------------------------------------------------------------------

def test_trans_atrans_rot_mirror_scale():
    prog = """TRANS X10 Y5
G0 X1 Y0
ATRANS X1
G0 X0 Y0
ROT Z90
G0 X10 Y0
AROT RPL=90
G0 X10 Y0
SCALE X2 Y2
G0 X3 Y4
MIRROR X0
G0 X3 Y4
TRANS
G0 X3 Y4
M30
"""
    e = ends(run(prog, tools="").nominal)
    assert e[0] == (11, 5, 0) and e[1] == (11, 5, 0)  # ATRANS adds in the frame: (10+1, 5)
    assert np.allclose(e[2], (0, 10, 0), atol=1e-12)   # ROT Z90: (10,0) -> (0,10)
    assert np.allclose(e[3], (-10, 0, 0), atol=1e-12)  # AROT adds 90 more
    assert e[4] == (6, 8, 0) and e[5] == (-3, 4, 0) and e[6] == (3, 4, 0)


def test_mirror_reverses_circles_and_compensation_side():
    # G2 from (10,0) to (0,10)... mirrored in X: the output arc runs from (-10,0) to (0,10),
    # now counter-clockwise; G41 becomes G42 so the tool stays outside the mirrored contour.
    prog = "MIRROR X0\nG0 X10 Y0\nG3 X0 Y10 CR=10 F100\nM30\n"
    res = run(prog, tools="")
    assert res.nominal.kind[1] == tc.ARC_CW
    np.testing.assert_allclose(res.nominal.center[1][:2], [0, 0], atol=1e-12)


# ---- circles ------------------------------------------------------------------------------------

@pytest.mark.parametrize("block, centre", [
    ("G2 X10 Y0 I5 J0", (5, 0)),              # centre incremental from the start
    ("G2 X10 Y0 I=AC(5) J=AC(0)", (5, 0)),    # absolute centre
    ("G2 X10 Y0 CR=5", (5, 0)),               # half circle: centre on the chord
    ("G2 X10 Y0 CR=-5", (5, 0)),              # chord = diameter: the same half circle
    ("G2 I5 J0 AR=180", (5, 0)),              # opening angle about a centre: end (10, 0)
    ("G2 X10 Y0 AR=180", (5, 0)),             # opening angle to an end point
    ("CIP X10 Y0 I1=5 J1=5", (5, 0)),         # through (5,5): clockwise
])
def test_circle_forms_from_zero_to_ten(block, centre):
    res = run(f"G0 X0 Y0\n{block} F100\nM30\n", tools="")
    np.testing.assert_allclose(res.nominal.end[1][:2], [10, 0], atol=1e-6)
    np.testing.assert_allclose(res.nominal.center[1][:2], centre, atol=1e-6)
    assert res.nominal.kind[1] == tc.ARC_CW


def test_ar_90_to_an_end_point_and_ct_tangent_arc():
    # G3 (10,0)->(0,10) with AR=90: centre (0,0). Then a line to (0,20) leaves the arc's
    # tangent (-1,0) ... CT after G1 X0 Y0 -> X10 (tangent +X) to (20,10): centre (10,10), ccw.
    res = run("G0 X10 Y0\nG3 X0 Y10 AR=90 F100\nG1 X0 Y0\nX10\nCT X20 Y10\nM30\n", tools="")
    np.testing.assert_allclose(res.nominal.center[1][:2], [0, 0], atol=1e-9)
    assert res.nominal.kind[4] == tc.ARC_CCW
    np.testing.assert_allclose(res.nominal.center[4][:2], [10, 10], atol=1e-9)


def test_helix_with_turn():
    res = run("G0 X10 Y0 Z0\nG3 X10 Y0 Z-6 I-10 J0 TURN=2 F100\nM30\n", tools="")
    assert res.nominal.turns[1] == 2 and res.nominal.end[1][2] == -6


def test_circle_end_point_error_is_14040():
    raises("G0 X0 Y0\nG2 X10 Y0 I4 J0 F100\nM30\n", "14040", 2, tools="")


# ---- units, diameter -----------------------------------------------------------------------------

def test_g70_inch_and_g700_feed():
    res = run("G70 G1 X1 F10\nG700 X2 F10\nG71 X3\nM30\n", tools="")
    assert ends(res.nominal) == [(25.4, 0, 0), (50.8, 0, 0), (3, 0, 0)]
    assert res.nominal.feed[0] == 10 and res.nominal.feed[1] == pytest.approx(254)


def test_diamon_halves_x():
    res = run("G18 DIAMON G0 X40 Z0\nG91 X-10\nDIAMOF G90 X40\nM30\n", tools="")
    assert ends(res.nominal) == [(20, 0, 0), (15, 0, 0), (40, 0, 0)]


def test_diam90_diameter_absolute_radius_incremental():
    # DIAM90: X is a diameter under G90 and a radius under G91 (840D: dimensions, DIAM90)
    res = run("G18 DIAM90 G90 G0 X40 Z0\nG91 X-10\nG90 X30\nDIAMOF X30\nM30\n", tools="")
    assert ends(res.nominal) == [(20, 0, 0), (10, 0, 0), (15, 0, 0), (30, 0, 0)]


# ---- tool data ------------------------------------------------------------------------------------

def test_spec_3_2_worked_lengths_by_plane():
    # DP3 = 120, DP12 = -0.15, DP21 = 10 -> L1 = 129.85 on Z (G17), Y (G18), X (G19); R = 5.98
    tools = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=120\n$TC_DP12[1,1]=-0.15\n$TC_DP21[1,1]=10\n$TC_DP6[1,1]=6\n$TC_DP15[1,1]=-0.02\n"
    res = run("T1 M6\nG17 G0 X0\nG18 X1\nG19 X2\nM30\n", tools=tools)
    off = res.nominal.tool_offset
    np.testing.assert_allclose(off[0], [0, 0, 129.85], atol=1e-9)
    np.testing.assert_allclose(off[1], [0, 129.85, 0], atol=1e-9)
    np.testing.assert_allclose(off[2], [129.85, 0, 0], atol=1e-9)


def test_d0_removes_the_offsets_and_unknown_t_or_d_are_alarms():
    res = run("T1 M6\nG0 X0\nD0 X1\nM30\n")
    np.testing.assert_allclose(res.nominal.tool_offset[1], [0, 0, 0])
    raises("T9 M6\nM30\n", "17190", 1)
    raises("T1 M6 D4\nM30\n", "17180", 1)


def test_tool_by_name_from_a_tool_table():
    table = tc.ToolTable()
    t = tc.Tool(number=7, name="MILL10")
    e = t.edges[0]
    e.radius = 5
    e.length = [0, 0, 42]
    t.edges = [e]
    table.set(t)
    res = tc.run(tc.Program.parse('T="mill10" M6\nG0 X0\nM30\n', dialect="sinumerik"), table)
    np.testing.assert_allclose(res.nominal.tool_offset[0], [0, 0, 42])
    assert res.nominal.tool[0] == 7


def test_gettcor_in_a_program_is_usable_in_expressions():
    # Milling tool in G17: abscissa X = L3, ordinate Y = L2, applicate Z = L1 (geometry + wear)
    tools = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n$TC_DP4[1,1]=20\n$TC_DP5[1,1]=3\n$TC_DP12[1,1]=0.5\n$TC_DP6[1,1]=5\n"
    prog = 'DEF REAL _LEN[11]\n' + tools + 'T1 M6\nR1=GETTCOR(_LEN,"GW")\nG0 X=_LEN[2] Y=_LEN[3] Z=_LEN[4]\nR2=GETTCOR(_LEN,"GQ")\nG0 X=R1 Y=R2 Z=_LEN[5]\nM30\n'
    e = ends(run(prog, tools="").nominal)
    assert e[0] == (3, 20, 100.5)
    assert e[1] == (0, -3, 5)  # status 0, then -3 for an invalid component letter; radius kept


# ---- radius compensation ----------------------------------------------------------------------------

L_SHAPE = "T1 M6\nG0 X0 Y-10\nG1 G41 X0 Y0 F100\nX50\nY30\nX80\nG40 G0 X90 Y40\nM30\n"


def test_l_shape_g450_transition_arc_and_g451_intersection():
    # Spec 1.4 L-shape with r = 5: inside corner (45,5); outside corner C(50,30): G450 circles
    # about C from (45,30) to (50,35), G451 meets at (45,35).
    g450 = segs(run(L_SHAPE).path)
    assert (1, (45.0, 5.0), (45.0, 30.0), False) in g450
    assert (tc.ARC_CW, (45.0, 30.0), (50.0, 35.0), True) in g450
    g451 = segs(run("G451\n" + L_SHAPE).path)
    assert (1, (45.0, 5.0), (45.0, 35.0), False) in g451
    assert (1, (45.0, 35.0), (80.0, 35.0), False) in g451


def test_norm_and_kont_differ_exactly_when_the_start_is_behind():
    behind = "T1 M6\nG0 X0 Y-10\nG1 G41 X0 Y0 F100\nX50\nG40 X60 Y10\nM30\n"
    front = behind.replace("X0 Y-10", "X-10 Y10")
    assert segs(run("NORM\n" + front).path) == segs(run("KONT\n" + front).path)
    norm = segs(run("NORM\n" + behind).path)
    kont = segs(run("KONT\n" + behind).path)
    assert norm[1] == (1, (0.0, -10.0), (0.0, 5.0), False)
    assert kont[1] == (1, (0.0, -10.0), (-5.0, 0.0), False)
    assert kont[2] == (tc.ARC_CW, (-5.0, 0.0), (0.0, 5.0), True)


def test_disc_100_is_the_intersection_on_a_line_corner():
    # DISC=100: the fillet radius r(1 - 1) = 0, the sharp intersection (45,35) of the L-shape
    s = segs(run("DISC=100\n" + L_SHAPE).path)
    assert any(e == (45.0, 35.0) for _, _, e, _ in s)


def test_cdon_skips_a_step_and_cdof_raises_10751():
    step = "T1 M6\nG0 X0 Y10\nG1 G41 X0 Y0 F100\nX30\nY-2\nX60\nG40 X70 Y10\nM30\n"
    s = segs(run("CDON\n" + step).path)
    assert (tc.ARC_CW, (30.0, 5.0), (34.0, 3.0), True) in s  # 30 + sqrt(25 - 9) = 34
    raises("CDOF\n" + step, "10751", 7)  # found at X60, the element after the riser


def test_offn_adds_to_the_radius():
    s = segs(run("T1 M6\nG0 X0 Y-10\nG1 G41 OFFN=1 X0 Y0 F100\nX50\nG40 X60 Y-10\nM30\n").path)
    assert (1, (0.0, 6.0), (50.0, 6.0), False) in s


def test_mirrored_contour_keeps_the_tool_outside():
    # Side along +X at y = 0 with G41: in program coordinates the tool is on +Y, away from
    # the material. Mirrored in Y the side still runs along +X, the start is at y = -10 and
    # the tool stays on the start's side, -Y: the output path is a G42 path.
    s = segs(run("MIRROR Y0\nT1 M6\nG0 X0 Y10\nG1 G41 X0 Y0 F100\nX50\nG40 X60 Y10\nM30\n").path)
    assert (1, (0.0, -5.0), (50.0, -5.0), False) in s


@pytest.mark.parametrize("body, alarm, line", [
    ("G0 X0 Y0\nG1 G41 X10 F100\nM30\n", "10750", 2),                    # no tool
    ("T1 M6\nG0 X0 Y-10\nG2 G41 X10 Y0 CR=20 F100\nM30\n", "10753", 3),  # selection in a circle
    ("T1 M6\nG0 X0 Y-10\nG1 G41 X0 Y0 F100\nX10\nG2 G40 X20 Y10 CR=10\nM30\n", "10754", 5),
    ("T1 M6\nG0 X0 Y-10\nG1 G41 X0 Y0 F100\nG18 X10\nM30\n", "10757", 4),
    ("T1 M6\nG0 X0 Y-10\nG1 G41 X0 Y0 F100\nX20\nZ-1\nZ-2\nZ-3\nZ-4\nY20\nG40 X-10 Y30\nM30\n", "10762", 8),
    ("G0 X0\nG1 X10\nM30\n", "10860", 2),
])
def test_alarms_with_numbers_and_lines(body, alarm, line):
    raises(body, alarm, line)


def test_unsupported_words_are_explicit():
    raises("G0 X0\nKONTC\nM30\n", "unsupported_word", 2)
    raises("G0 X0\nG112 X0 Y0\nM30\n", "unsupported_word", 2)
    raises("G0 X0\nG1 X10 U5 F100\nM30\n", "unsupported_word", 2)


def test_kont_retract_goes_round_the_end_point_only_when_it_lies_behind():
    # Contour X0 -> X50 on y = 0, G41 r = 5: the tool ends the contour at C = (50, 5).
    # In front (60, 10): NORM and KONT both leave from (50, 5) straight to (60, 10).
    # Behind (60, -10): KONT goes round P = (50, 0) by G450: a circle from (50, 5) to
    # P + 5 (1, 1)/sqrt 2, perpendicular to the cancel move's start, then to (60, -10).
    base = "T1 M6\nG0 X-10 Y10\nG1 G41 X0 Y0 F100\nX50\nG40 X60 Y{}\nM30\n"
    for mode in ("NORM", "KONT"):
        s = segs(run(mode + "\n" + base.format(10)).path)
        assert s[-2:] == [(1, (0.0, 5.0), (50.0, 5.0), False), (1, (50.0, 5.0), (60.0, 10.0), False)]
    assert segs(run("NORM\n" + base.format(-10)).path)[-1] == (1, (50.0, 5.0), (60.0, -10.0), False)
    k = 5 / math.sqrt(2)
    s = segs(run("KONT\n" + base.format(-10)).path)
    assert s[-2] == (tc.ARC_CW, (50.0, 5.0), (round(50 + k, 9), round(k, 9)), True)
    assert s[-1] == (1, (round(50 + k, 9), round(k, 9)), (60.0, -10.0), False)


def test_toolholder_type_p_shifts_the_zero_point_spec_3_6():
    # l4 = (0, 0, 15), table axis v1 = Y at 45 degrees: offset Rot(Y, 45) l4 - l4 =
    # (15 sin 45, 0, 15 cos 45 - 15) = (10.607, 0, -4.393); the tool length is not changed.
    prog = ('$TC_CARR23[1]="P"\n$TC_CARR8[1]=1\n$TC_CARR13[1]=45\n$TC_CARR20[1]=15\n'
            "TCARR=1 TCOABS\nT1 M6\nG0 X0 Y0 Z0\nM30\n")
    res = run(prog)
    s = 15 * math.sqrt(0.5)
    np.testing.assert_allclose(res.nominal.end[0], [s, 0, s - 15], atol=1e-12)
    np.testing.assert_allclose(res.nominal.tool_offset[0], [0, 0, 100], atol=1e-12)


def test_toolholder_type_t_tool_length_spec_3_6():
    # l1 = (-200, 0, 0), l3 = (-100, 0, 0), v1 = X, v2 = (-1, 0, 1)/sqrt 2, tool L1 = 250 on
    # Z: L_res = (-300, 0, 250) at zero angles.
    tools = "$TC_DP1[3,1]=120\n$TC_DP3[3,1]=250\n"
    holder = ('$TC_CARR23[2]="T"\n$TC_CARR1[2]=-200\n$TC_CARR15[2]=-100\n$TC_CARR7[2]=1\n'
              "$TC_CARR10[2]=-1\n$TC_CARR12[2]=1\n")
    res = run(holder + "TCARR=2\nT3 M6\nG0 X0\nM30\n", tools=tools)
    np.testing.assert_allclose(res.nominal.tool_offset[0], [-300, 0, 250], atol=1e-12)


def test_settcor_corrects_the_tool_data_the_next_selection_uses():
    # Wear of L1 set to -0.2 (component W, _CORCOMP 3 = L1, replace); then +0.05 added to
    # the geometry radius (G, 6, add): L1 = 100 - 0.2, R = 5.05. The active edge keeps its
    # old values until D is programmed again (spec 3.3).
    prog = ("DEF REAL V[3]\n" + TOOLS + "T1 M6\nG0 X0\n"
            'V[0]=-0.2\nR1=SETTCOR(V,"W",3,0)\nV[0]=0.05\nR2=SETTCOR(V,"G",6,1)\nG0 X1\nD1\n'
            "G0 X=R1 Y=R2 Z=$TC_DP6[1,1]\nR3=SETTCOR(V,\"GX\",3)\nG0 X=R3\nM30\n")
    res = run(prog, tools="")
    off = res.nominal.tool_offset
    np.testing.assert_allclose(off[:2], [[0, 0, 100], [0, 0, 100]])
    np.testing.assert_allclose(off[2], [0, 0, 99.8], atol=1e-12)
    np.testing.assert_allclose(res.nominal.end[2], [0, 0, 5.05], atol=1e-12)
    assert res.nominal.end[3][0] == -3  # invalid component letter


def test_settcor_in_the_workpiece_system_follows_the_plane():
    e = tc.sinumerik.Edge(dp={1: 120, 3: 100})
    # G18: L1 acts on Y; a WCS vector (0, 0.3, 0) corrects L1 only (replace with 0.3).
    assert tc.sinumerik.settcor(e, (0, 0.3, 0), "W", corcomp=1, plane=18) == 0
    assert e.get_dp(12) == pytest.approx(0.3) and e.get_dp(13) == 0 and e.get_dp(14) == 0
    # scalar along Z (geoax 3) in G17 is L1 too; adding to geometry
    assert tc.sinumerik.settcor(e, (1.5, 0, 0), "G", corcomp=0, cormode=1, geoax=3) == 0
    assert e.get_dp(3) == pytest.approx(101.5)
    assert tc.sinumerik.settcor(e, (1, 0, 0), "C", corcomp=6) == tc.sinumerik.SETTCOR_NO_RADIUS
    assert tc.sinumerik.settcor(e, (1, 0, 0), "G", corcomp=9) == tc.sinumerik.SETTCOR_BAD_CORCOMP


@pytest.mark.parametrize("body, alarm, line", [
    # KONT, start (0,-3) behind the contour start (0,0) and within r = 5 of it: no room
    ("KONT T1 M6\nG0 X0 Y-3\nG1 G41 X0 Y0 F100\nX50\nG40 X60 Y10\nM30\n", "10755", 3),
    # KONT, cancel end (52,-2) behind the contour end (50,0), 2.83 < 5 from it
    ("KONT T1 M6\nG0 X-10 Y10\nG1 G41 X0 Y0 F100\nX50\nG40 X52 Y-2\nM30\n", "10756", 5),
    # helix with TRC while a type T toolholder tilts the tool 30 degrees about X
    ('$TC_CARR23[1]="T"\n$TC_CARR7[1]=1\n$TC_CARR13[1]=30\nTCARR=1 T1 M6\nG0 X0 Y-10\n'
     "G1 G41 X0 Y0 F100\nG3 X0 Y20 Z-5 CR=10\nM30\n", "10760", 7),
    # a circle in a non-uniform SCALE is an ellipse
    ("SCALE X2 Y1\nT1 M6\nG0 X0 Y-10\nG1 G41 X0 Y0 F100\nG3 X0 Y20 CR=10\nM30\n", "10761", 5),
])
def test_more_alarms_with_numbers_and_lines(body, alarm, line):
    raises(body, alarm, line)


def test_d_change_during_trc_ends_and_starts_perpendicular():
    # D1 r = 5 -> D2 r = 3 at (30,0) on a straight contour along +X: (30,5), then a link to
    # (30,3), then on at y = 3.
    tools = TOOLS + "$TC_DP1[1,2]=120\n$TC_DP3[1,2]=100\n$TC_DP6[1,2]=3\n"
    s = segs(run("T1 M6\nG0 X0 Y10\nG1 G41 X0 Y0 F100\nX30\nD2 X60\nG40 X70 Y10\nM30\n", tools=tools).path)
    assert (1, (0.0, 5.0), (30.0, 5.0), False) in s
    assert (1, (30.0, 5.0), (30.0, 3.0), True) in s
    assert (1, (30.0, 3.0), (60.0, 3.0), False) in s


def test_direct_g41_g42_change():
    s = segs(run("T1 M6\nG0 X0 Y10\nG1 G41 X0 Y0 F100\nX50\nG42 X100\nG40 X110 Y-10\nM30\n").path)
    assert (1, (0.0, 5.0), (50.0, 5.0), False) in s
    assert (1, (50.0, 5.0), (50.0, -5.0), True) in s
    assert (1, (50.0, -5.0), (100.0, -5.0), False) in s


def test_machine_data_from_the_profile():
    # SD42940 = 17 fixes the G17 assignment: in G18 the milling tool's L1 stays on Z.
    # SD42930 (wear_sign -1): L1 = 100 - (-0.5) = 100.5.
    tools = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n$TC_DP12[1,1]=-0.5\n"
    prof = tc.ControlProfile("sinumerik")
    prof.tool_length_const = 17
    prof.wear_sign = -1
    res = run("T1 M6\nG18 G0 X0\nM30\n", tools=tools, profile=prof)
    np.testing.assert_allclose(res.nominal.tool_offset[0], [0, 0, 100.5], atol=1e-12)
    res = run("T1 M6\nG18 G0 X0\nM30\n", tools=tools)
    np.testing.assert_allclose(res.nominal.tool_offset[0], [0, 99.5, 0], atol=1e-12)


def test_an_error_in_a_subprogram_file_names_that_file(tmp_path):
    # L20.SPF line 2 divides by zero (R1 is 0): the alarm comes with that file and line.
    (tmp_path / "L20.SPF").write_text("G0 X1\nR2=1/R1\nM17\n")
    prog = tc.Program.parse("G0 X0\nL20\nM30\n", dialect="sinumerik")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(prog, search_path=[str(tmp_path)])
    assert e.value.line == 2 and pathlib.Path(e.value.file).name == "L20.SPF"


def test_a_block_with_many_g_functions_takes_them_all():
    # Eight G functions in one block (more than are kept in place): G91 makes X5 Y5 a move
    # of +5 +5 from (1, 2), G1 makes it a feed move; the next block's G90 G0 goes back.
    p = run("T1 D1 M6\nG0 X1 Y2 Z0\nG17 G71 G94 G40 G64 G450 G91 G1 X5 Y5 F100\nG90 G0 X0\n").nominal
    assert list(p.kind) == [0, 1, 0]
    assert ends(p) == [(1.0, 2.0, 0.0), (6.0, 7.0, 0.0), (0.0, 7.0, 0.0)]
