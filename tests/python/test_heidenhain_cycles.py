"""Heidenhain fixed cycles with their calls: 1, 17, 203, 205, 208, CYCL CALL POS, PATTERN DEF with
CYCL CALL PAT, 220 / 221, M89; the untilted working plane (CYCL DEF 19, PLANE), FUNCTION TCPM,
M126. Every number is worked by hand from the TNC manuals' description of the cycle (the
worked examples of doc/heidenhain.md, "Fixed cycles")."""
import math

import numpy as np
import pytest

import toolcomp as tc

R, F = tc.RAPID, tc.LINE


def run(text, **kw):
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text, "heidenhain"), **kw)


def program(*blocks, tool="1 TOOL DEF 5 L+0 R+6\n2 TOOL CALL 5 Z S1000\n"):
    body = "".join(f"{n} {b}\n" for n, b in enumerate(blocks, start=3))
    return f"0 BEGIN PGM C MM\n{tool}{body}{len(blocks) + 3} END PGM C MM\n"


def axis_moves(p, line):
    """(kind, Z, feed or None) of the moves of one source line."""
    sel = np.flatnonzero(p.line == line)
    return [(int(p.kind[i]), round(float(p.end[i, 2]), 4), None if p.kind[i] == R else round(float(p.feed[i]), 4))
            for i in sel]


def line_of(text, marker):
    """The source line of the block that contains `marker` (its first line)."""
    return text.count("\n", 0, text.index(marker)) + 1


def plane_points(p, kind=R):
    return [(round(float(e[0]), 4), round(float(e[1]), 4)) for e, k in zip(p.end, p.kind) if k == kind]


CYCLE_203 = """CYCL DEF 203 UNIVERSAL DRILLING ~
    Q200=+2    ;SET-UP CLEARANCE ~
    Q201=-20   ;DEPTH ~
    Q206=+150  ;FEED RATE FOR PLNGNG ~
    Q202=+6    ;PLUNGING DEPTH ~
    Q210=+0    ;DWELL TIME AT TOP ~
    Q203=+0    ;SURFACE COORDINATE ~
    Q204=+50   ;2ND SET-UP CLEARANCE ~
    Q212=+1    ;DECREMENT ~
    Q213=+2    ;BREAKS ~
    Q205=+3    ;MIN. PLUNGING DEPTH ~
    Q211=+0    ;DWELL TIME AT DEPTH ~
    Q208=+500  ;RETRACTION FEED RATE ~
    Q256=+0.2  ;DIST. FOR CHIP BRKNG"""


def test_203_plunges_shrink_by_the_decrement_and_break_chips_twice_before_leaving_the_hole():
    # Plunges 6, 5, 4, 3 and the remaining 2: depths -6, -11, -15, -18, -20. After the first
    # two a chip break (back 0.2 at Q208), after the third out of the hole at Q208 to the
    # set-up clearance and back at FMAX to 2 above -15, then the count starts again.
    text = program("L X+0 Y+0 Z+50 R0 FMAX", CYCLE_203, "L X+0 Y+0 R0 FMAX M99")
    expected = [(R, 2, None), (F, -6, 150), (F, -5.8, 500), (F, -11, 150), (F, -10.8, 500), (F, -15, 150),
                (F, 2, 500), (R, -13, None), (F, -18, 150), (F, -17.8, 500), (F, -20, 150), (F, 2, 500),
                (R, 50, None)]
    assert axis_moves(run(text).nominal, line_of(text, "M99")) == expected


CYCLE_205 = """CYCL DEF 205 UNIVERSAL PECKING ~
    Q200=+2    ;SET-UP CLEARANCE ~
    Q201=-30   ;DEPTH ~
    Q206=+150  ;FEED RATE FOR PLNGNG ~
    Q202=+10   ;PLUNGING DEPTH ~
    Q203=+0    ;SURFACE COORDINATE ~
    Q204=+50   ;2ND SET-UP CLEARANCE ~
    Q212=+2    ;DECREMENT ~
    Q205=+4    ;MIN. PLUNGING DEPTH ~
    Q258=+0.5  ;UPPER ADV STOP DIST ~
    Q259=+0.5  ;LOWER ADV STOP DIST ~
    Q257=+0    ;DEPTH FOR CHIP BRKNG ~
    Q256=+0.2  ;DIST FOR CHIP BRKNG ~
    Q211=+0    ;DWELL TIME AT DEPTH ~
    Q379=+0    ;STARTING POINT ~
    Q253=+750  ;F PRE-POSITIONING"""


def run_205(**changes):
    cycle = CYCLE_205
    for q, v in changes.items():
        cycle = cycle.replace(f"{q}=+{'0.5' if q in ('Q258', 'Q259') else '0'} ", f"{q}=+{v} ")
    text = program("L X+10 Y+10 Z+50 R0 FMAX", cycle, "L X+10 Y+10 R0 FMAX M99")
    return axis_moves(run(text).nominal, line_of(text, "M99"))


def test_205_pecks_out_of_the_hole_and_back_to_the_advanced_stop_distance():
    # Plunges 10, 8, 6, 4 and the remaining 2 (Q205 = 4 holds them at 4): depths -10, -18,
    # -24, -28, -30; after each out at FMAX to +2 and back to 0.5 above the depth reached.
    z = [(R, 2, None)]
    for depth, back in [(-10, -9.5), (-18, -17.5), (-24, -23.5), (-28, -27.5)]:
        z += [(F, depth, 150), (R, 2, None), (R, back, None)]
    z += [(F, -30, 150), (R, 2, None), (R, 50, None)]
    assert run_205() == z


def test_205_advanced_stop_distance_goes_evenly_from_q258_to_q259():
    # Q259 = 1: the four returns at 0.5, 0.5 + 0.5/3, 0.5 + 1/3, 1 above -10, -18, -24, -28.
    backs = [m[1] for m in run_205(Q259="1")[3::3]][:4]
    assert backs == [-9.5, round(-18 + 0.5 + 0.5 / 3, 4), round(-24 + 0.5 + 1 / 3, 4), -27.0]


def test_205_breaks_the_chip_every_q257_within_a_plunge():
    # Q257 = 3: in the first plunge (0 to -10) back by Q256 = 0.2 at -3, -6 and -9.
    assert run_205(Q257="3")[:9] == [(R, 2, None), (F, -3, 150), (F, -2.8, 150), (F, -6, 150), (F, -5.8, 150),
                                     (F, -9, 150), (F, -8.8, 150), (F, -10, 150), (R, 2, None)]


def test_205_from_a_pilot_hole_starts_counting_below_the_surface():
    # Q379 = 5: down at Q253 = 750 to 2 above -5, then plunges of 10, 8, 6 and 1 from -5.
    m = run_205(Q379="5")
    assert m[:4] == [(R, 2, None), (F, -3, 750), (F, -15, 150), (R, 2, None)]
    assert [z for k, z, f in m if f == 150] == [-15, -23, -29, -30]


BORE = """CYCL DEF 208 BORE MILLING ~
    Q200=+2   ;SET-UP CLEARANCE ~
    Q201=-10  ;DEPTH ~
    Q206=+150 ;FEED RATE FOR PLNGNG ~
    Q334=+2   ;PLUNGING DEPTH ~
    Q203=+0   ;SURFACE COORDINATE ~
    Q204=+50  ;2ND SET-UP CLEARANCE ~
    Q335=+20  ;NOMINAL DIAMETER ~
    Q342=+0   ;ROUGHING DIAMETER ~
    Q351=+1   ;CLIMB OR UP-CUT"""


def test_208_mills_a_helix_of_the_hole_radius_less_the_tool_radius():
    # Tool R6, hole D20: the tool centre on a circle of radius 4 about (50, 50). From Z+2 a
    # 12 mm helix at 2 mm a turn: 6 turns, counter-clockwise (climb with M3), ending where it
    # began; a full circle at -10; back to the centre; out at FMAX to Z+50.
    text = program("L X+50 Y+50 Z+50 R0 FMAX M3", BORE, "L X+50 Y+50 R0 FMAX M99")
    p = run(text).nominal
    sel = np.flatnonzero(p.line == line_of(text, "M99"))
    kinds = [int(k) for k in p.kind[sel]]
    assert kinds == [R, tc.ARC_CCW, tc.ARC_CCW, tc.ARC_CCW, F, R]
    ends = [tuple(np.round(p.end[i], 6)) for i in sel]
    assert ends == [(50, 50, 2), (54, 50, 2), (54, 50, -10), (54, 50, -10), (50, 50, -10), (50, 50, 50)]
    approach, helix, circle = sel[1], sel[2], sel[3]
    assert tuple(p.center[approach, :2]) == (52, 50) and tuple(p.center[helix, :2]) == (50, 50)
    assert p.turns[helix] == 5 and p.turns[circle] == 0  # 6 turns: start == end and 5 more
    assert np.all(p.feed[sel[1:5]] == 150)


def test_208_a_part_turn_ends_the_helix_at_its_angle():
    # Q334 = 5: 12 / 5 = 2.4 turns, the helix ends at 0.4 * 360 = 144 degrees.
    text = program("L X+50 Y+50 Z+50 R0 FMAX M3", BORE.replace("Q334=+2 ", "Q334=+5 "), "L X+50 Y+50 R0 FMAX M99")
    p = run(text).nominal
    sel = np.flatnonzero(p.line == line_of(text, "M99"))
    helix = sel[2]
    a = math.radians(144)
    np.testing.assert_allclose(p.end[helix], [50 + 4 * math.cos(a), 50 + 4 * math.sin(a), -10], atol=1e-9)
    assert p.turns[helix] == 2


@pytest.mark.parametrize("change, what", [("Q335=+20 ", "Q335=+10 "), ("Q335=+20 ", "Q335=+30 ")])
def test_208_refuses_a_hole_smaller_than_the_tool_or_over_twice_its_diameter(change, what):
    with pytest.raises(tc.ProgramError) as e:
        run(program("L X+50 Y+50 Z+50 R0 FMAX M3", BORE.replace(change, what), "L X+50 Y+50 R0 FMAX M99"))
    assert e.value.code == "cycle_bad_value" and "Q335" in e.value.message


def test_old_cycle_1_pecks_from_the_start_and_returns_to_it():
    # From Z+2, SET UP 2 (surface 0), DEPTH -15, PECKG 5, F80: the advanced stop distance is
    # 0.6 (depth up to 30).
    text = program("L X+50 Y+50 Z+2 R0 FMAX", "CYCL DEF 1.0 PECKING", "CYCL DEF 1.1 SET UP 2",
                   "CYCL DEF 1.2 DEPTH -15", "CYCL DEF 1.3 PECKG 5", "CYCL DEF 1.4 DWELL 0.5", "CYCL DEF 1.5 F80",
                   "CYCL CALL M3")
    assert axis_moves(run(text).nominal, line_of(text, "CYCL CALL")) == [(F, -5, 80), (R, 2, None), (R, -4.4, None), (F, -10, 80),
                                                 (R, 2, None), (R, -9.4, None), (F, -15, 80), (R, 2, None)]


def test_old_cycle_17_taps_from_the_start_a_pitch_a_revolution():
    text = program("L X+0 Y+0 Z+2 R0 FMAX", "CYCL DEF 17.0 RIGID TAPPING", "CYCL DEF 17.1 SET UP 2",
                   "CYCL DEF 17.2 DEPTH -12", "CYCL DEF 17.3 PITCH +1.5", "CYCL CALL", tool="1 TOOL DEF 5 L+0 R+3\n2 TOOL CALL 5 Z S400\n")
    assert axis_moves(run(text).nominal, line_of(text, "CYCL CALL")) == [(F, -12, 600), (F, 2, 600)]


def test_an_old_cycle_line_without_its_start_is_refused():
    with pytest.raises(tc.ProgramError) as e:
        run(program("CYCL DEF 1.2 DEPTH -15"))
    assert e.value.code == "unsupported_block" and "CYCL DEF 1.0" in e.value.message


CYCLE_200 = """CYCL DEF 200 DRILLING ~
    Q200=+2    ;SET-UP CLEARANCE ~
    Q201=-5    ;DEPTH ~
    Q206=+250  ;FEED RATE FOR PLNGNG ~
    Q202=+5    ;PLUNGING DEPTH ~
    Q210=+0    ;DWELL TIME AT TOP ~
    Q203=+0    ;SURFACE COORDINATE ~
    Q204=+20   ;2ND SET-UP CLEARANCE ~
    Q211=+0    ;DWELL TIME AT DEPTH"""


def test_cycl_call_pos_moves_in_the_plane_and_shifts_the_surface_by_its_z():
    # From Z+50 (above the surface): to (30, 40) at F1000, then the cycle on the surface Z-4:
    # +2 above it, 5 deep, out to 20 above it.
    text = program("L X+0 Y+0 Z+50 R0 FMAX", CYCLE_200, "CYCL CALL POS X+30 Y+40 Z-4 F1000 M3")
    p = run(text).nominal
    sel = np.flatnonzero(p.line == line_of(text, "CYCL CALL"))
    assert [tuple(np.round(p.end[i], 6)) for i in sel] == [(30, 40, 50), (30, 40, -2), (30, 40, -9), (30, 40, 16)]
    assert list(p.kind[sel]) == [F, R, F, R] and p.feed[sel[0]] == 1000


def test_cycl_call_pos_from_below_the_surface_goes_up_to_the_2nd_clearance_first():
    text = program("L X+0 Y+0 Z-3 R0 FMAX", CYCLE_200, "CYCL CALL POS X+30 Y+40 Z+0 FMAX")
    p = run(text).nominal
    sel = np.flatnonzero(p.line == line_of(text, "CYCL CALL"))
    assert [tuple(np.round(p.end[i], 6)) for i in sel][:2] == [(0, 0, 20), (30, 40, 20)]


def test_pattern_def_circ_with_cycl_call_pat_lifts_to_the_safe_height_between_points():
    # CIRC1 about (50, 50), D60, from 30 degrees, 6 points; safe height max(100, 0 + 20).
    text = program("L X+0 Y+0 Z+100 R0 FMAX", "PATTERN DEF ~\n   CIRC1 ( X+50 Y+50 D60 START+30 NUM6 Z+0 )",
                   CYCLE_200, "CYCL CALL PAT FMAX M3")
    p = run(text).nominal
    holes = [(round(float(e[0]), 4), round(float(e[1]), 4)) for e, k in zip(p.end, p.kind) if k == F]
    expected = [(round(50 + 30 * math.cos(math.radians(a)), 4), round(50 + 30 * math.sin(math.radians(a)), 4))
                for a in (30, 90, 150, 210, 270, 330)]
    assert holes == expected
    z = [round(float(v), 4) for v in p.end[p.line == line_of(text, "CYCL CALL"), 2]]
    assert z[:6] == [100, 2, -5, 20, 100, 100]  # to the point, drill, out, up to 100, over
    assert z[-3:] == [2, -5, 20]  # no lift after the last point


def test_pattern_def_points_rows_grids_and_pitch_circles():
    text = program("L X+0 Y+0 Z+30 R0 FMAX",
                   "PATTERN DEF ~\n POS1 ( X+10 Y+10 Z+0 ) ~\n POS2 ( IX+5 Y+20 Z+0 ) ~\n"
                   " ROW1 ( X+0 Y+0 D+10 NUM3 ROT+90 Z+0 ) ~\n"
                   " PAT1 ( X+100 Y+0 DX+10 DY+20 NUMX3 NUMY2 ROT+0 ROTX+0 ROTY+0 Z+0 ) ~\n"
                   " PITCHCIRC1 ( X+0 Y+0 D20 START+0 STEP+90 NUM2 Z+0 )",
                   CYCLE_200, "CYCL CALL PAT FMAX")
    holes = [(round(float(e[0]), 4), round(float(e[1]), 4)) for e, k in zip(run(text).nominal.end, run(text).nominal.kind)
             if k == F]
    assert holes == [(10, 10), (15, 20), (0, 0), (0, 10), (0, 20), (100, 0), (110, 0), (120, 0), (120, 20), (110, 20),
                     (100, 20), (10, 0), (0, 10)]


def test_pattern_def_frame_and_sheared_grids_are_refused_by_name():
    for item, word in [("FRAME1 ( X+0 Y+0 DX+5 DY+5 NUMX3 NUMY3 ROT+0 ROTX+0 ROTY+0 Z+0 )", "FRAME"),
                       ("PAT1 ( X+0 Y+0 DX+5 DY+5 NUMX3 NUMY3 ROT+0 ROTX+10 ROTY+0 Z+0 )", "ROTX")]:
        with pytest.raises(tc.ProgramError) as e:
            run(program(f"PATTERN DEF ~\n {item}"))
        assert word in e.value.message


POLAR = """CYCL DEF 220 POLAR PATTERN ~
  Q216=+50 ;CENTER IN 1ST AXIS ~
  Q217=+50 ;CENTER IN 2ND AXIS ~
  Q244=+60 ;PITCH CIRCLE DIAMETR ~
  Q245=+0 ;STARTING ANGLE ~
  Q246=+360 ;STOPPING ANGLE ~
  Q247=+0 ;STEPPING ANGLE ~
  Q241=+4 ;NR OF REPETITIONS ~
  Q200=+2 ;SET-UP CLEARANCE ~
  Q203=+0 ;SURFACE COORDINATE ~
  Q204=+30 ;2ND SET-UP CLEARANCE ~
  Q301=+1 ;MOVE TO CLEARANCE ~
  Q365=+0 ;TYPE OF TRAVERSE"""


def test_220_drills_on_the_pitch_circle_with_its_own_clearances():
    # 4 points at 0, 90, 180, 270 degrees on R30 about (50, 50); Q204 = 30 of 220 overrides
    # the 20 of cycle 200; the tool stays at Z100 (above 30) to the first point.
    text = program("L X+0 Y+0 Z+100 R0 FMAX", CYCLE_200, POLAR)
    p = run(text).nominal
    sel = p.line == line_of(text, "CYCL DEF 220")
    assert plane_points(p, F) == [(80, 50), (50, 80), (20, 50), (50, 20)]
    z = [round(float(v), 4) for v in p.end[sel, 2]]
    assert z == [100, 2, -5, 30] + [30, 2, -5, 30] * 3


def test_220_partial_arc_steps_from_start_to_stop_and_q301_0_travels_at_the_clearance():
    text = program("L X+0 Y+0 Z+100 R0 FMAX", CYCLE_200,
                   POLAR.replace("Q246=+360", "Q246=+90").replace("Q241=+4", "Q241=+3").replace("Q301=+1", "Q301=+0"))
    p = run(text).nominal
    c = math.sqrt(0.5) * 30
    assert plane_points(p, F) == [(80, 50), (round(50 + c, 4), round(50 + c, 4)), (50, 80)]
    assert [round(float(v), 4) for v in p.end[p.line == line_of(text, "CYCL DEF 220"), 2]][-4:] == [2, 2, -5, 2]


CARTESIAN = """CYCL DEF 221 CARTESIAN PATTERN ~
  Q225=+10 ;STARTNG PNT 1ST AXIS ~
  Q226=+10 ;STARTNG PNT 2ND AXIS ~
  Q237=+20 ;SPACING IN 1ST AXIS ~
  Q238=+15 ;SPACING IN 2ND AXIS ~
  Q242=+3 ;NUMBER OF COLUMNS ~
  Q243=+2 ;NUMBER OF LINES ~
  Q224=+0 ;ANGLE OF ROTATION ~
  Q200=+2 ;SET-UP CLEARANCE ~
  Q203=+0 ;SURFACE COORDINATE ~
  Q204=+20 ;2ND SET-UP CLEARANCE ~
  Q301=+1 ;MOVE TO CLEARANCE"""


def test_221_runs_its_lines_back_and_forth():
    text = program("L X+0 Y+0 Z+10 R0 FMAX", CYCLE_200, CARTESIAN)
    p = run(text).nominal
    assert plane_points(p, F) == [(10, 10), (30, 10), (50, 10), (50, 25), (30, 25), (10, 25)]
    assert float(p.end[p.line == line_of(text, "CYCL DEF 221")][0, 2]) == 20  # up to the 2nd set-up clearance first


def test_221_rotated_about_its_start_point():
    p = run(program("L X+0 Y+0 Z+10 R0 FMAX", CYCLE_200, CARTESIAN.replace("Q224=+0", "Q224=+30"))).nominal
    holes = plane_points(p, F)
    assert holes[1] == (27.3205, 20) and holes[5] == (2.5, 22.9904) and holes[3] == (37.141, 42.9904)


def test_a_pattern_cycle_needs_a_machining_cycle_before_it():
    with pytest.raises(tc.ProgramError) as e:
        run(program(CARTESIAN))
    assert e.value.code == "unsupported_block" and "CYCL DEF 221" in e.value.message


def test_m89_calls_the_cycle_after_every_positioning_block_until_m99():
    text = program("L X+0 Y+0 Z+50 R0 FMAX", CYCLE_200, "L X+10 Y+0 R0 FMAX M89", "L X+20 FMAX",
                   "L X+30 FMAX M99", "L X+40 FMAX")
    p = run(text).nominal
    assert plane_points(p, F) == [(10, 0), (20, 0), (30, 0)]
    profile = tc.ControlProfile("heidenhain")
    profile.m89_modal_cycle_call = False  # a free M function: only M99 calls
    assert plane_points(run(text, profile=profile).nominal, F) == [(30, 0)]


def test_cycl_call_ends_m89():
    text = program("L X+0 Y+0 Z+50 R0 FMAX", CYCLE_200, "L X+10 Y+0 R0 FMAX M89", "CYCL CALL", "L X+40 FMAX")
    assert plane_points(run(text).nominal, F) == [(10, 0), (10, 0)]


@pytest.mark.parametrize("block", ["PLANE SPATIAL SPA+0 SPB+0 SPC+0 STAY SEQ+ TABLE ROT", "CYCL DEF 19.1 A+0 B+0 C+0",
                                   "PLANE AXIAL A+0 C+0 STAY",
                                   "PLANE VECTOR BX+1 BY+0 BZ+0 NX+0 NY+0 NZ+1 STAY", "PLANE RESET STAY"])
def test_an_untilted_plane_sets_the_rotary_positions_q120_to_q122_to_zero(block):
    p = run(program("L A+10 C+20 X+5 R0 FMAX", block, "L A+Q120 C+Q122 X+10 R0 FMAX")).nominal
    assert tuple(p.abc[-1]) == (0, 0, 0)
    with pytest.raises(tc.ProgramError) as e:  # before the plane is set, the control's Q120 is not known
        run(program("L A+Q120 C+Q122 X+10 R0 FMAX"))
    assert e.value.code == "q_system"


def test_plane_turn_is_taken_where_the_rotary_axes_stand_at_zero_only():
    assert tuple(run(program("PLANE RESET TURN FMAX", "L A+Q120 X+10 R0 FMAX")).nominal.abc[-1]) == (0, 0, 0)
    with pytest.raises(tc.ProgramError) as e:
        run(program("L A+10 X+5 R0 FMAX", "PLANE RESET TURN FMAX"))
    assert e.value.code == "unsupported_block" and "TURN" in e.value.message


@pytest.mark.parametrize("block, word", [("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX", "SPB45"),
                                         ("CYCL DEF 19.1 A+0 B-30 C+0", "B-30"),
                                         ("PLANE POINTS", "PLANE POINTS")])
def test_a_tilted_plane_is_refused_naming_it(block, word):
    with pytest.raises(tc.ProgramError) as e:
        run(program(block))
    assert e.value.code == "unsupported_block" and word in e.value.message


def test_function_tcpm_is_m128_and_refuses_spatial_angles():
    ok = program("FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS", "L X+10 Y+0 Z+5 R0 FMAX", "FUNCTION RESET TCPM")
    assert run(ok).nominal.end[-1, 0] == 10
    for block, word in [("FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS", "AXIS SPAT"),
                        ("FUNCTION MODE TURN", "FUNCTION MODE")]:
        with pytest.raises(tc.ProgramError) as e:
            run(program(block))
        assert word in e.value.message


def test_m126_turns_a_rotary_axis_the_shorter_way():
    # C from 350 to 10: with M126 +20 degrees (the axis reads 370), without it -340.
    text = program("L C+350 X+1 R0 FMAX", "L C+10 X+2 R0 FMAX M126", "L C+350 X+3 FMAX M127", "L C+10 X+4 FMAX")
    c = [float(v) for v in run(text).nominal.abc[:, 2]]
    assert c[-4:] == [350, 370, 350, 10]


@pytest.mark.parametrize("cycle, marker", [
    (CYCLE_200.replace("Q202=+5 ", "Q202=+0.001 ").replace("Q201=-5 ", "Q201=-100 ") + "\n%LINE CYCL CALL",
     "CYCL CALL"),
    (CYCLE_200 + "\n%LINE " + POLAR.replace("Q241=+4", "Q241=+5000"), "CYCL DEF 220"),
])
def test_cycle_moves_count_against_the_block_limit(cycle, marker):
    # 100 000 pecks, or 5000 holes: stopped at the limit of 2000 blocks, at the calling block.
    profile = tc.ControlProfile("heidenhain")
    profile.block_limit = 2000
    first, second = cycle.split("\n%LINE ")
    text = program("L X+0 Y+0 Z+50 R0 FMAX", first, second)
    with pytest.raises(tc.ProgramError) as e:
        run(text, profile=profile)
    assert e.value.code == "block_limit" and e.value.line == line_of(text, marker)


def test_an_inch_program_drills_in_inches_with_feeds_in_tenths_of_an_inch():
    # BEGIN PGM ... INCH: Q values in inches (the path in mm), Q206=+50 is 5 in/min = 127 mm/min.
    # From Z+2: 0.1 above the surface, pecks of 0.25 to -0.25 and -0.5, back to 0.1 above -0.25.
    text = ("0 BEGIN PGM I INCH\n1 TOOL DEF 1 L+0 R+0.125\n2 TOOL CALL 1 Z S2000\n3 L X+0 Y+0 Z+2 R0 FMAX\n"
            + CYCLE_200.replace("Q200=+2 ", "Q200=+0.1 ").replace("Q201=-5 ", "Q201=-0.5 ").replace("Q206=+250", "Q206=+50")
            .replace("Q202=+5 ", "Q202=+0.25 ").replace("Q204=+20 ", "Q204=+1 ").replace("CYCL DEF", "4 CYCL DEF")
            + "\n5 L X+1 Y+0.5 R0 FMAX M99\n6 END PGM I INCH\n")
    moves = axis_moves(run(text).nominal, line_of(text, "M99"))
    assert moves == [(R, 50.8, None), (R, 2.54, None), (F, -6.35, 127.0), (R, 2.54, None), (R, -3.81, None),
                     (F, -12.7, 127.0), (R, 25.4, None)]
