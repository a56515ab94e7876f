"""Words of Heidenhain path blocks: a word the function does not take, an axis given twice
(X twice, or X with IX), a TNC word toolcomp does not model, a Q number out of range, and a
circle of radius 0 are errors at their line, never ignored or silently resolved."""
import numpy as np
import pytest

import toolcomp as tc


def pgm(body):
    """BEGIN PGM on line 1: the body's k-th line is source line k + 1."""
    lines = ["BEGIN PGM T MM", "TOOL DEF 1 L+0 R+2", "TOOL CALL 1 Z S3000", "L X+0 Y+0 Z-1 R0 F100"]
    lines += body.strip().splitlines() + ["END PGM T MM"]
    return "\n".join(f"{i} {l.strip()}" for i, l in enumerate(lines)) + "\n"


def error_of(body):
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(pgm(body), dialect="heidenhain"))
    return e.value.code, e.value.line, e.value.column


@pytest.mark.parametrize("body, code, column", [
    ("L X+10 X+20 Y+0", "bad_word", 8),           # the second X
    ("L X+10 IX+5", "bad_word", 8),               # X absolute and incremental
    ("CC X+1 Y+2 Y+3", "bad_word", 12),
    ("L X+10 F100 F200", "bad_word", 13),
    ("L X+10 ZZ+5", "bad_word", 8),               # no such word
    ("L X+10 DR+", "bad_word", 8),                # DR belongs to arcs
    ("L X+10 R+5", "bad_word", 8),                # a radius in a straight line
    ("CC X+5 Y+0 F100", "bad_word", 12),          # CC moves nothing
    ("L X+10 W+5", "unsupported_word", 8),        # parallel axis
    ("L X+10 IB+5", "unsupported_word", 8),
    ("L X+10 FZ0.1", "unsupported_word", 8),
])
def test_word_errors_at_their_column(body, code, column):
    # column: in the body line; the program line starts with its block number "4 ".
    assert error_of(body) == (code, 5, column + 2)


def test_long_line_of_repeated_axis_words_fails_at_the_second():
    assert error_of("L " + "X+1 " * 25_000) == ("bad_word", 5, 2 + 7)


@pytest.mark.parametrize("body", [
    "L X+10 Y+5 RL F200 M3 M8\nL X+20 R0",    # two M functions in one block
    "L Z+1 R+ F100",                          # paraxial R+ (R0 off)
    "CC X+5 Y+0\nC X+10 Y+0 DR+ F100",         # arc about CC
    "CR X+10 Y+0 R+5 DR- F100",
    "CC X+0 Y+0\nLP PR+5 PA+90 F100",
    "CC X+5 Y+0\nCP IPA+360 IZ-1 DR+ F100",    # helix
    "L X+10 Y+0 F100\nRND R2\nL Y+10\nCHF 1\nL X+20",
    "L X+10 A+90 C+45 F100",                  # rotary axes
])
def test_valid_words_are_accepted(body):
    tc.run(tc.Program.parse(pgm(body), dialect="heidenhain"))


def test_q_parameter_numbers_have_at_most_five_digits():
    res = tc.run(tc.Program.parse(pgm("Q1999 = 7\nL X+Q1999 F100"), dialect="heidenhain"))
    assert res.path.end[-1, 0] == 7
    # Q0 to Q1999 exist: a higher number is refused where it is used
    assert error_of("Q12345 = 7")[:2] == ("q_out_of_range", 5)
    assert error_of("Q1 = Q2000 + 1")[:2] == ("q_out_of_range", 5)
    assert error_of("L X+Q2000 F100")[:2] == ("q_out_of_range", 5)
    assert error_of("Q123456 = 5")[:2] == ("q_syntax", 5)
    assert error_of("Q1 = Q123456 + 1")[:2] == ("q_syntax", 5)
    assert error_of("FN 0: Q123456 = +5")[:2] == ("q_syntax", 5)
    assert error_of("L X+Q123456")[:2] == ("bad_word", 5)


@pytest.mark.parametrize("body", ["CC X+0 Y+0\nC X+0 Y+0 DR+",    # start and end on the centre
                                  "CC X+0 Y+0.01\nC X+0 Y+0.01 DR+"])  # end on the centre
def test_circle_of_radius_zero_is_arc_end_incorrect(body):
    code, line, _ = error_of(body)
    assert (code, line) == ("arc_end_incorrect", 6)


def test_numbers_with_a_decimal_comma_or_a_leading_point():
    # The TNC takes a comma for the point, and a number may start with either.
    path = tc.run(tc.Program.parse(pgm("L X+1,5 Y+,25\nL X-.75 Y+2."), dialect="heidenhain")).nominal
    assert [tuple(e[:2]) for e in path.end[-2:]] == [(1.5, 0.25), (-0.75, 2.0)]


@pytest.mark.parametrize("body, shown", [("L X+1.2.3", "1.2.3"), ("L X+1,2,3", "1.2.3"), ("L X+.1.", "0.1.")])
def test_bad_number_is_an_error_with_its_text(body, shown):
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(pgm(body), dialect="heidenhain"))
    assert (e.value.code, e.value.line) == ("bad_number_format", 5)
    assert f"Bad number '{shown}'" in e.value.message


def test_q0_is_a_parameter_like_any_other():
    # X+Q0 was read as X+1 (the sign alone).
    res = tc.run(tc.Program.parse(pgm("Q0 = 5\nQ1 = 7\nL X+Q0 Y-Q1 F100"), dialect="heidenhain"))
    np.testing.assert_allclose(res.path.end[-1, :2], [5, -7])


@pytest.mark.parametrize("body", ["L X+Q108 F100", "Q1 = Q114 + 1", "FN 0: Q1 = +Q109"])
def test_the_controls_own_q_parameters_are_not_read_as_zero(body):
    # Q100-Q199 are set by the control (Q108 the tool radius, Q109 the tool axis, ...).
    with pytest.raises(tc.ProgramError, match="set by the control") as e:
        tc.run(tc.Program.parse(pgm(body), dialect="heidenhain"))
    assert (e.value.code, e.value.line) == ("q_system", 5)


def test_tool_call_without_a_number_keeps_the_tool():
    # TOOL CALL Z S2000 changes the speed only: the tool (R2 here, DR-0.5 from its call) and
    # its length stay. With DR given, the new delta replaces the old one.
    head = "0 BEGIN PGM T MM\n1 TOOL DEF 1 L+10 R+2\n2 TOOL CALL 1 Z S1000 DR-0.5\n3 L X+0 Y-10 Z+0 R0 F100\n"
    tail = "5 L X+0 Y+0 RL\n6 L X+10\n7 L X+20 Y+10 R0\n8 END PGM T MM\n"

    def y_along(call):
        p = tc.run(tc.Program.parse(head + f"4 {call}\n" + tail, dialect="heidenhain")).path
        k = np.flatnonzero(p.line == 6)[-1]
        return p.end[k, 1], p.tool_offset[k, 2]

    assert y_along("TOOL CALL Z S2000") == (pytest.approx(1.5), 10)  # RL along +X: y = R + DR
    assert y_along("TOOL CALL Z DR-0.2") == (pytest.approx(1.8), 10)
    assert y_along("TOOL CALL Z DL+1") == (pytest.approx(1.5), 11)


HEAD = "0 BEGIN PGM A MM\n1 TOOL DEF 1 L+0 R+5\n2 TOOL CALL 1 Z\n3 L X+40 Y+10 Z+0 R0 F100\n4 CC X+0 Y+0\n"


@pytest.mark.parametrize("block, word, column", [
    ("LP PR5 PA90 X3", "X", 15),               # polar end point: PR, PA (and the tool axis)
    ("CTP PA90 X5", "X", 12),
    ("CP PR15 PA0 DR+", "PR", 6),              # CP's radius is the distance from the pole
    ("CP PA180 Y5 DR+", "Y", 12),
    ("APPR LT PR5 PA0 X+20 Y+20 LEN15 RR F100", "PR", 11),     # polar words need APPR PLT
    ("APPR LT X+20 Y+20 Z-10 LEN15 CCA90 RR F100", "CCA", 32),  # LT has no arc
    ("APPR LT X+20 Y+20 Z-10 LEN15 R5 RR F100", "R", 32),
    ("APPR CT X+10 Y+20 Z-10 CCA180 R+10 LEN5 RR F100", "LEN", 38),
    ("TOOL CALL 1 Z S1000 X10", "X", 23),     # the tool axis has no value
])
def test_words_a_block_would_drop_are_refused(block, word, column):
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(HEAD + f"5 {block}\n6 END PGM A MM\n", dialect="heidenhain"))
    assert (e.value.code, e.value.line, e.value.column) == ("bad_word", 6, column)
    assert e.value.message.startswith(word + " is not read") or "TOOL CALL" in e.value.message


def test_polar_blocks_with_their_own_words_run():
    # LP PR+5 PA+90 about (0,0): X0 Y5; CP PA180: from there around the pole to X-5 Y0.
    res = tc.run(tc.Program.parse(HEAD + "5 LP PR+5 PA+90\n6 CP PA180 DR+\n7 END PGM A MM\n", dialect="heidenhain"))
    np.testing.assert_allclose(res.nominal.end[-2, :2], [0, 5], atol=1e-12)
    np.testing.assert_allclose(res.nominal.end[-1, :2], [-5, 0], atol=1e-12)
