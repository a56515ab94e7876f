"""Words that must be whole numbers: LinuxCNC's slack (M, T, H, L within 0.0001 of an
integer, rounding up from 0.9999 above the one below; G41/G42 D within 0.0001; G2/G3 P
within 0.001; G codes ten times within 0.001; M61 Q rounded) and Fanuc taking words as
written. The refusals are in tests/programs/errors/whole_*.ngc, checked against rs274; the
cases here were checked against LinuxCNC's gcode module too."""
import pytest

import toolcomp as tc

TOOLS = tc.ToolTable.parse("T1 P1 D10\nT2 P2 D6\n", "linuxcnc")
HEAD = "G21 G90 G94 F300\nG0 X0 Y0 Z0\n"


def run(text, dialect="linuxcnc"):
    return tc.run(tc.Program.parse(HEAD + text + "M2\n", dialect=dialect), tools=TOOLS)


@pytest.mark.parametrize("d, r", [("1.00009", 5), ("0.99991", 5), ("1.9999", 3)])
def test_g41_d_within_a_ten_thousandth(d, r):
    # G41 along +X: the tool centre runs r to the left, at y = r
    p = run(f"G41 D{d}\nG1 X10 Y0\nG1 X20\nG40 G1 X30\n").path
    assert p.end[2, 1] == pytest.approx(r)


def test_g41_d_further_off_is_refused():
    with pytest.raises(tc.ProgramError, match="G41 requires D word to be a whole number"):
        run("G41 D1.0002\nG1 X10 Y0\n")


def test_tool_and_m_words_round_to_the_integer_they_are_near():
    assert run("T1.99991 M6\nG1 X1\n").path.tool[-1] == 2
    assert run("T2\nM5.9999\nG1 X1\n").path.tool[-1] == 2  # M5.9999 is M6
    assert run("T2\nM5.00009\nG1 X1\n").path.tool[-1] == 0  # M5: no change
    assert run("M61 Q1.4\nG1 X1\n").path.tool[-1] == 1
    assert run("M61 Q-0.3\nG1 X1\n").path.tool[-1] == 0


def test_g_codes_and_arc_turns():
    assert run("G1.0001 X5\n").path.kind[-1] == tc.LINE
    assert run("G0.99999 X5\n").path.kind[-1] == tc.LINE  # 9.9999 rounds up to G1
    arc = run("G2 X0 Y0 I5 J0 P1.001\n").path
    assert (arc.kind[-1], arc.turns[-1]) == (tc.ARC_CW, 0)


def test_fanuc_takes_the_words_as_written():
    with pytest.raises(tc.ProgramError, match="Non integer value for integer"):
        run("M5.00009\nG1 X1\n", dialect="fanuc")
    with pytest.raises(tc.ProgramError, match="Unknown g code used"):
        run("G1.0001 X5\n", dialect="fanuc")


def test_an_l_word_beside_g41_or_g42_is_let_be():
    # LinuxCNC accepts L with G41/G42 (it only reads it with G41.1/G42.1 in G18)
    assert run("G41 D1 L3\nG1 X10 Y0\nG1 X20\nG40 G1 X30\n").path.end[2, 1] == pytest.approx(5)



def test_negative_values_that_read_as_zero():
    # LinuxCNC reads the integer first and tests its sign: -0.00005 is 0, -0.99995 is -1.
    assert run("T2 M6\nT-0.00005\nG1 X1\n").path.tool[-1] == 2        # T0 selects, no change
    assert len(run("M-0.00005\nG1 X1\n").path) == 2                    # M0, a stop
    with pytest.raises(tc.ProgramError) as e:
        run("G0 Z5\nG81 X1 Z-1 R2 L-0.00005\n")
    assert (e.value.message, e.value.line) == ("Cannot do zero repeats of cycle", 4)
    with pytest.raises(tc.ProgramError) as e:
        run("G0 Z5\nG81 X1 Z-1 R2 L-0.99995\n")
    assert (e.value.message, e.value.line) == ("Negative l word used", 4)
    with pytest.raises(tc.ProgramError) as e:
        run("M-0.5\n")
    assert e.value.message == "Non integer value for integer"
