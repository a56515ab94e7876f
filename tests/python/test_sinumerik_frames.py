"""840D frames: the settable frames ($P_UIFR[n], active at G500 / G54 ... G599), $P_IFRAME,
$P_BFRAME and $P_PFRAME assigned with CTRANS / CFINE / CROT / CSCALE / CMIRROR chained with
':', frame components ($P_UIFR[1, X, TR]) and G58 / G59. The numbers are worked by hand from
v = R · S · M · v' + (TR + FI), chained basic : settable : programmable."""
import math

import numpy as np
import pytest

import toolcomp as tc


def run(text, **kw):
    return tc.run(tc.Program.parse(text, "sinumerik"), **kw)


def ends(text, **kw):
    return np.round(run(text, **kw).nominal.end, 6).tolist()


C30, S30 = math.cos(math.radians(30)), math.sin(math.radians(30))


def test_a_settable_frame_written_acts_when_its_g_function_is_selected_again():
    got = ends("""N10 G17 G90 G54
N20 G0 X0 Y0 Z10
N30 $P_UIFR[1]=CTRANS(X,10,Y,20)
N40 G0 X1 Y0
N50 G54
N60 G0 X1 Y0
N70 $P_UIFR[1,X,TR]=15
N80 G0 X2
N90 G55
N95 G0 X2 Y0
N100 G54
N105 G0 X0 Y0
N110 $P_IFRAME=CTRANS(X,10,Y,20):CROT(Z,30)
N120 G0 X10 Y0
N130 TRANS X5
N140 G0 X10 Y0
N150 G54
N160 G0 X0 Y0
M30
""")
    assert got == [[0, 0, 10],
                   [1, 0, 10],                                   # the write is in the data only
                   [11, 20, 10],                                 # G54 again: X10 Y20
                   [12, 20, 10],                                 # the component write waits too
                   [2, 0, 10],                                   # G55: neutral
                   [15, 20, 10],                                 # G54: X15 Y20
                   [round(10 + 10 * C30, 6), round(20 + 10 * S30, 6), 10],  # $P_IFRAME at once
                   [round(10 + 15 * C30, 6), round(20 + 15 * S30, 6), 10],  # TRANS X5 in the turned system
                   [20, 20, 10]]                                 # G54: the data again, TRANS kept


def test_g58_and_g59_replace_the_coarse_and_the_additive_translation():
    got = ends("G0 X0 Y0 Z0\nTRANS X10 Y10 Z10\nATRANS X5 Y5\nG0 X0 Y0 Z0\nG58 X20\nG0 X0 Y0 Z0\nG59 X10 Y10\n"
               "G0 X0 Y0 Z0\nM30\n")
    assert got == [[0, 0, 0], [15, 15, 10], [25, 15, 10], [30, 20, 10]]


def test_programmable_frame_assigned_and_its_components_read():
    # $P_PFRAME = CTRANS(X,10) : CROT(Z,90): X1 Y0 goes to (10, 1); its components read back
    # (translations in the program's unit); a component written acts at once.
    got = ends("G0 X0 Y0 Z0\n$P_PFRAME=CTRANS(X,10):CROT(Z,90)\nG0 X1 Y0\nR1=$P_PFRAME[X,TR] R2=$P_PFRAME[Z,RT]\n"
               "$P_PFRAME[Z,RT]=0\nG0 X=R1 Y=R2\n$P_PFRAME=CTRANS()\nG0 X1 Y2\nM30\n")
    assert got == [[0, 0, 0], [10, 1, 0], [20, 90, 0], [1, 2, 0]]


def test_a_basic_frame_and_a_settable_frame_chain_under_the_programmable_one():
    # $P_BFRAME X100; G54 data: mirror X and scale 2; TRANS X1: X1 -> programmable 2 -> settable
    # -4 -> basic 96.
    got = ends("G0 X0 Y0 Z0\n$P_BFRAME=CTRANS(X,100)\n$P_UIFR[1]=CMIRROR(X):CSCALE(X,2,Y,2,Z,2)\nG54\nTRANS X1\n"
               "G0 X1 Y1\nM30\n")
    assert got == [[0, 0, 0], [96, 2, 0]]


def test_frames_in_an_inch_program_take_inches():
    assert ends("G70 G0 X0 Y0 Z0\n$P_UIFR[2]=CTRANS(X,1)\nG55\nG0 X1\nR1=$P_UIFR[2,X,TR]\nG0 X=R1+1\nM30\n") == [
        [0, 0, 0], [50.8, 0, 0], [76.2, 0, 0]]


def test_a_save_subprogram_gives_back_the_callers_settable_frame(tmp_path):
    (tmp_path / "OTHER.SPF").write_text("PROC OTHER SAVE\nG55\nG0 X0 Y0\nM17\n")
    got = ends("G0 X0 Y0 Z0\n$P_UIFR[1]=CTRANS(X,100)\nG54\nOTHER\nG0 X0 Y0\nM30\n", search_path=[tmp_path])
    assert got == [[0, 0, 0], [0, 0, 0], [100, 0, 0]]


@pytest.mark.parametrize("line, code", [
    ("$P_ACTFRAME=CTRANS(X,1)", "17070"),
    ("$P_UIFR[100]=CTRANS(X,1)", "17020"),
    ("$P_PFRAME=CSCALE(X,2):CROT(Z,30)", "unsupported_word"),  # would shear
    ("$P_PFRAME=CTRANS(A,10)", "unsupported_word"),
    ("$P_PFRAME=CSCALE(X,0)", "scale_zero"),
    ("$P_PFRAME=MEAFRAME(X,1)", "unsupported_word"),
    ("R1=$P_UIFR[1]", "12550"),                                # a whole frame is not a number
    ("G58 X10 G1 Y5", "12190"),
])
def test_frame_errors(line, code):
    with pytest.raises((tc.ProgramError, tc.ParseError)) as e:
        run(f"G0 X0 Y0 Z0 F100\n{line}\nM30\n")
    assert e.value.code == code


def test_the_active_frame_reads_the_whole_chain():
    got = ends("G0 X0 Y0 Z0\n$P_IFRAME=CTRANS(Y,7)\nTRANS X3\nR1=$P_ACTFRAME[X,TR] R2=$P_ACTFRAME[Y,TR]\n"
               "TRANS\nG0 X=R1 Y=R2\nM30\n")
    assert got == [[0, 0, 0], [3, 14, 0]]
