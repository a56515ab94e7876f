"""How real TNC programs are written (hand-written, Fusion 360, hyperMILL, NX posts): program
names of any letters, digits, '.', '_' and '-'; blanks between an address and its value;
F MAX; feeds in Q parameters (F Q58, FQ58); the block skip '/'; cycle definitions continued
over lines with '~'."""
import numpy as np
import pytest

import toolcomp as tc


def run(text, **kw):
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text, "heidenhain"), **kw)


def ends(res):
    return [tuple(float(v) for v in e) for e in np.round(res.nominal.end, 6)]


@pytest.mark.parametrize("name", ["0TREF", "11setup", "contour-cut", "W5246NS01007A1", "spot-drill", "PART-1",
                                  "A.B_C-1"])
def test_program_names(name):
    res = run(f"0 BEGIN PGM {name} MM\n1 L X+1 Y+2 R0 FMAX\n2 END PGM {name} MM\n")
    assert ends(res) == [(1, 2, 0)]


def test_spaced_words_f_max_and_q_feeds():
    text = """0 BEGIN PGM SPACED MM
1 TOOL DEF 1 L+0 R+5
2 TOOL CALL 1 Z S2000
3 L X+0 Y+0 Z+10 R0 F MAX
4 Q58 = 250
5 L Z - 2.5 FQ58
6 L X + 20 F Q58
7 L IX - 5 Y + Q58 F 300
8 L  Z 25.000 FMAX
9 END PGM SPACED MM
"""
    res = run(text)
    assert ends(res) == [(0, 0, 10), (0, 0, -2.5), (20, 0, -2.5), (15, 250, -2.5), (15, 250, 25)]
    f = res.nominal.feed
    assert np.isnan(f[0]) and list(f[1:4]) == [250, 250, 300] and np.isnan(f[4])


def test_the_block_skip():
    text = "0 BEGIN PGM S MM\n1 L X+10 R0 FMAX\n2 /L X+20 F100\n/3 L Y+5 F100\n4 L Z+1 F100\n5 END PGM S MM\n"
    assert ends(run(text)) == [(10, 0, 0), (20, 0, 0), (20, 5, 0), (20, 5, 1)]
    assert ends(run(text, block_delete=True)) == [(10, 0, 0), (10, 0, 1)]


def test_a_cycle_definition_over_continued_lines_is_one_block():
    text = """0 BEGIN PGM CYC MM
1 TOOL DEF 1 L+0 R+3
2 TOOL CALL 1 Z S2000
3 CYCL DEF 251 RECTANGULAR POCKET ~
    Q215=0     ;MACHINING OPERATION ~
    Q218=80    ;FIRST SIDE LENGTH ~
    Q219=60    ;2ND SIDE LENGTH
4 L X+10 Y+10 R0 FMAX
5 END PGM CYC MM
"""
    prog = tc.Program.parse(text, "heidenhain")
    with pytest.raises(tc.ProgramError) as e:  # the definition is read whole; the cycle is refused
        tc.run(prog)
    assert e.value.code == "unsupported_block" and e.value.line == 4
    assert "CYCL DEF 251 RECTANGULAR POCKET" in e.value.message



def test_labels_by_name():
    text = """0 BEGIN PGM L MM
1 L X+0 Y+0 R0 FMAX
2 CALL LBL "CORNER"
3 L X+5 FMAX
4 M30
5 LBL "CORNER"
6 L Y+7 FMAX
7 LBL 0
8 END PGM L MM
"""
    assert ends(run(text)) == [(0, 7, 0), (5, 7, 0)]
    with pytest.raises(tc.ProgramError) as e:
        run(text.replace('CALL LBL "CORNER"', 'CALL LBL "EDGE"'))
    assert (e.value.code, str(e.value.message), e.value.line) == ("label_not_found", 'LBL "EDGE" not found', 3)


def test_sgn_in_q_formulas():
    text = "0 BEGIN PGM Q MM\n1 Q1 = SGN -5\n2 Q2 = SGN(0) + SGN 3 * 2\n3 L X+Q1 Y+Q2 R0 FMAX\n4 END PGM Q MM\n"
    assert ends(run(text)) == [(-1, 2, 0)]


def test_a_long_comment_wrapped_with_a_tilde():
    # Fusion 360 wraps long comment lines with '~'; the next line is more of the comment.
    text = """0  BEGIN PGM m8_tap_up MM
1  ;  description: This machine has YX axis on the Table and Z axis on the~
 Head
2  * - a structure block that goes on~
 over two lines
3  L X+1 Y+2 R0 FMAX
4  END PGM m8_tap_up MM
"""
    assert ends(run(text)) == [(1, 2, 0)]


def test_the_tolerance_cycle_is_noted_and_other_cycles_are_refused_by_number():
    text = """0  BEGIN PGM T MM
1  TOOL DEF 23 L+0 R+4
2  TOOL CALL 23 Z S5000
3  L  X+49  Y-15 R0 FMAX
4  CYCL DEF 32.0 TOLERANCE
5  CYCL DEF 32.1 T0.05
6  CYCL DEF 32.2 HSC-MODE:0 TA0.5
7  L  Z+19 FMAX
8  END PGM T MM
"""
    res = run(text)
    assert ends(res) == [(49, -15, 0), (49, -15, 19)]
    notes = [(d.code, d.line) for d in res.diagnostics]
    assert notes == [("blending_not_modelled", 5)]
    with pytest.raises(tc.ProgramError) as e:
        run(text.replace("7  L  Z+19 FMAX", "7  CYCL DEF 252 CIRCULAR POCKET ~\n Q215=+0 ;MACHINING OPERATION"))
    assert str(e.value.message) == "CYCL DEF 252 CIRCULAR POCKET is not supported by toolcomp yet" and e.value.line == 8


def test_m140_retracts_along_the_tool_axis():
    # The machine's Z travel ends at machine Z+100; program zero lies at machine (-300, -200, -400);
    # tool 2 is 50 long. MB MAX: the spindle to machine Z+100, the tip (program) at
    # 100 + 400 - 50 = 450. MB 30: 30 up from where the block starts, before its own move.
    text = """0  BEGIN PGM M140 MM
1  TOOL DEF 2 L+50 R+3.5
2  TOOL CALL 2 Z S1247
3  L M140 MB MAX
4  L  X+13  Y-13.5 R0 FMAX
5  L  Z+15 R0 FMAX
6  L Z+5 F100 M140 MB 30
7  L M140 MB MAX
8  END PGM M140 MM
"""
    m = tc.Machine("heidenhain", "mill", "vmc")
    m.work_origin = (-300, -200, -400)
    m.travel = [(-600, 0), (-400, 0), (-500, 100)]
    res = run(text, machine=m)
    p = res.nominal
    assert [int(l) for l in p.line] == [4, 5, 6, 7, 7, 8]
    np.testing.assert_allclose(p.end, [[300, 200, 450], [13, -13.5, 450], [13, -13.5, 15], [13, -13.5, 45],
                                       [13, -13.5, 5], [13, -13.5, 450]], atol=1e-12)
    assert list(p.kind) == [tc.RAPID, tc.RAPID, tc.RAPID, tc.RAPID, tc.LINE, tc.RAPID]
    with pytest.raises(tc.ProgramError) as e:  # no machine: no travel to retract to
        run(text)
    assert e.value.code == "travel_limit" and "M140 MB MAX" in str(e.value.message) and e.value.line == 4


def test_conditional_jumps_to_named_labels():
    # FN 9: IF Q1 EQU 0 GOTO LBL "SKIP": the move to X+5 is jumped over while Q1 is 0.
    text = """0 BEGIN PGM J MM
1 Q1 = 0
2 L X+1 R0 FMAX
3 FN 9: IF +Q1 EQU +0 GOTO LBL "SKIP"
4 L X+5 FMAX
5 LBL "SKIP"
6 L Y+2 FMAX
7 END PGM J MM
"""
    assert ends(run(text)) == [(1, 0, 0), (1, 2, 0)]
    assert ends(run(text.replace("Q1 = 0", "Q1 = 1"))) == [(1, 0, 0), (5, 0, 0), (5, 2, 0)]


def test_fn18_sysread_reads_the_controls_data():
    # TNC groups: ID10 NR1 units; ID20 NR1 tool, NR3 axis (2 = Z); ID50 NR1/2/5 table L, R, DR of
    # tool IDX; ID60 NR4 the TOOL CALL's DL; ID200 NR1/NR2 the active radius and length with
    # the oversizes (3 + 0.1 - 0.05, 50 + 0.2); ID210 NR4 scale 1; ID270 NR1 IDX3 the position.
    text = """0 BEGIN PGM S MM
1 TOOL CALL 2 Z S2000 DL+0.2 DR+0.1
2 L X+10 Y+5 Z+7 R0 FMAX
3 FN 18: SYSREAD Q1 = ID10 NR1
4 FN 18: SYSREAD Q2 = ID20 NR1
5 FN18: SYSREAD Q3 = ID20 NR3
6 FN 18: SYSREAD Q4 = ID50 NR1 IDX2
7 FN 18: SYSREAD Q5 = ID50 NR2 IDX2
8 FN 18: SYSREAD Q6 = ID50 NR5 IDX2
9 FN 18: SYSREAD Q7 = ID60 NR4
10 FN 18: SYSREAD Q8 = ID200 NR1
11 FN 18: SYSREAD Q9 = ID200 NR2
12 FN 18: SYSREAD Q10 = ID210 NR4 IDX1
13 FN 18: SYSREAD Q11 = ID270 NR1 IDX3 ;the tool's Z
14 L X+Q1 Y+Q2 Z+Q3 FMAX
15 L X+Q4 Y+Q5 Z+Q6 FMAX
16 L X+Q7 Y+Q8 Z+Q9 FMAX
17 L X+Q10 Y+Q11 FMAX
18 END PGM S MM
"""
    tools = tc.ToolTable()
    tools.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=3.0, radius_wear=-0.05, length=[0.0, 0.0, 50.0])]))
    res = run(text, tools=tools)
    np.testing.assert_allclose(res.nominal.end[1:], [[0, 2, 2], [50, 3, -0.05], [0.2, 3.05, 50.2], [1, 7, 50.2]],
                               atol=1e-12)
    with pytest.raises(tc.ProgramError) as e:
        run(text.replace("ID210 NR4 IDX1", "ID320 NR1 IDX0"), tools=tools)
    assert e.value.code == "unsupported_parameter" and "ID320 NR1" in str(e.value.message)


def test_cycle_7_shifts_the_datum():
    # The datum to X+50 Y+20: L X+10 Y+0 ends at (60, 20) from the preset; a pole CC X+0 Y+0 is
    # at (50, 20); IX+5 moves the datum 5 further; X+0 Y+0 takes it back. The path stays
    # measured from the preset; FN 18 ID270 reads the position from the shifted datum.
    text = """0 BEGIN PGM D MM
1 L X+0 Y+0 Z+0 R0 FMAX
2 CYCL DEF 7.0 DATUM SHIFT
3 CYCL DEF 7.1 X+50
4 CYCL DEF 7.2 Y+20
5 L X+10 Y+0 FMAX
6 CC X+0 Y+0
7 C X+0 Y+10 DR+ F100
8 FN 18: SYSREAD Q1 = ID270 NR1 IDX2
9 CYCL DEF 7.0 DATUM SHIFT
10 CYCL DEF 7.1 IX+5
11 L X+0 Y+Q1 FMAX
12 CYCL DEF 7.0 DATUM SHIFT
13 CYCL DEF 7.1 X+0
14 CYCL DEF 7.2 Y+0
15 L X+1 Y+1 FMAX
16 END PGM D MM
"""
    res = run(text)
    assert ends(res) == [(60, 20, 0), (50, 30, 0), (55, 30, 0), (1, 1, 0)]
    np.testing.assert_allclose(res.nominal.center[1], [50, 20, 0])


def test_cycle_200_drilling_with_m99():
    # Two holes: Q200=2 set-up clearance, Q201=-15 depth, Q202=6 pecks (6, 12, then 15),
    # Q203=0 surface, Q204=50: rapid to Z2, feed to -6, out to Z2, down to -4 (2 above the last
    # depth), feed to -12, out, down to -10, feed to -15, out to Z50 (the higher clearance).
    text = """0  BEGIN PGM E200 MM
1  TOOL DEF 5 L+0 R+3
2  TOOL CALL 5 Z S2000
3  L Z+100 R0 FMAX M3
4  CYCL DEF 200 DRILLING ~
    Q200=+2    ;SET-UP CLEARANCE ~
    Q201=-15   ;DEPTH ~
    Q206=+250  ;FEED RATE FOR PLNGNG ~
    Q202=+6    ;PLUNGING DEPTH ~
    Q210=+0.5  ;DWELL TIME AT TOP ~
    Q203=+0    ;SURFACE COORDINATE ~
    Q204=+50   ;2ND SET-UP CLEARANCE ~
    Q211=+0.2  ;DWELL TIME AT DEPTH
5  L X+30 Y+20 R0 FMAX M99
6  L X+60 R0 FMAX M99
7  L Z+100 R0 FMAX
8  END PGM E200 MM
"""
    p = run(text).nominal
    z_of_hole = [2, -6, 2, -4, -12, 2, -10, -15, 50]
    kinds = [tc.RAPID, tc.LINE, tc.RAPID, tc.RAPID, tc.LINE, tc.RAPID, tc.RAPID, tc.LINE, tc.RAPID]
    first = list(np.flatnonzero(p.line == 14))  # source lines: the blocks after the definition
    assert list(p.end[first, 2]) == [100] + z_of_hole and list(p.kind[first[1:]]) == kinds
    second = list(np.flatnonzero(p.line == 15))
    assert list(p.end[second, 2]) == [50] + z_of_hole and np.all(p.end[second, 0] == 60)
    assert np.all(p.feed[first[1:]][np.array(kinds) == tc.LINE] == 250)


def test_cycle_207_taps_at_the_pitch_and_201_reams():
    text = """0  BEGIN PGM T MM
1  TOOL DEF 2 L+0 R+4
2  TOOL CALL 2 Z S500
3  L X+10 Y+10 Z+15 R0 FMAX
4  CYCL DEF 207 RIGID TAPPING ~
    Q200=+5    ;SET-UP CLEARANCE ~
    Q201=-25   ;DEPTH OF THREAD ~
    Q239=+1.25 ;THREAD PITCH ~
    Q203=+0    ;SURFACE COORDINATE ~
    Q204=+5    ;2ND SET-UP CLEARANCE
5  L FMAX M99
6  CYCL DEF 201 REAMING ~
    Q200=+2 ;SET-UP CLEARANCE ~
    Q201=-10 ;DEPTH ~
    Q206=+100 ;FEED RATE FOR PLNGNG ~
    Q211=+0 ;DWELL TIME AT DEPTH ~
    Q208=MAX ;RETRACTION FEED RATE ~
    Q203=-1 ;SURFACE COORDINATE ~
    Q204=+20 ;2ND SET-UP CLEARANCE
7  CYCL CALL
8  END PGM T MM
"""
    p = run(text).nominal
    tap = np.flatnonzero(p.line == 11)
    assert list(p.end[tap, 2]) == [5, -25, 5] and list(p.feed[tap[1:]]) == [1.25 * 500] * 2  # 625 mm/min
    ream = np.flatnonzero(p.line == 20)
    assert list(p.end[ream, 2]) == [1, -11, 1, 19] and list(p.kind[ream]) == [tc.RAPID, tc.LINE, tc.RAPID, tc.RAPID]
    with pytest.raises(tc.ProgramError) as e:
        run(text.replace("Q201=-25", "Q201=+25"))
    assert e.value.code == "cycle_bad_value" and e.value.line == 11
