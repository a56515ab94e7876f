"""Words whose meaning differs between controls, each read as its own control reads it.

* Fanuc G65 argument specification II: the n-th I, J, K go to #(4+3(n-1)), #(5+3(n-1)),
  #(6+3(n-1)) (Fanuc Macro B); a letter other than I, J, K given twice is refused.
* Fanuc G10 L2 in G91 adds to the offset (LinuxCNC sets it in G90 and G91 alike); Fanuc's
  L20 (G54.1 systems) and L2 P0 (external offset) are refused, not read as LinuxCNC's.
* Fanuc G04 X / U (lathes) give the dwell in seconds, not a move.
* LinuxCNC (ABORT, text) stops the program with the text, parameters substituted, before the
  block's motion: numbers from LinuxCNC 2.9's gcode module (' wrong setup 7.000000', line 4;
  the comment beside G0 X1 stops before that move).
"""
import numpy as np
import pytest

import toolcomp as tc


def run(text, dialect="fanuc", profile=None):
    return tc.run(tc.Program.parse(text, dialect), profile=profile)


@pytest.mark.parametrize("args, body, end", [
    ("I3 J4 I5", "G0 X#4 Y#5 Z#7", [3, 4, 5]),
    ("I3 I5", "G0 X#4 Y#7", [3, 5, 0]),
    ("I1 J2 I3 D4", "G0 X#4 Y#5 Z#7", [1, 2, 4]),  # #7 named by the second I and by D: D, later, wins
    ("K1 K2 K3", "G0 X#6 Y#9 Z#12", [1, 2, 3]),
])
def test_g65_argument_specification_two(args, body, end):
    p = run(f"O1\nG21 G90\nG65 P2 {args}\nM30\nO2\n{body}\nM99\n").path
    np.testing.assert_allclose(p.end[-1], end)


def test_g65_other_letters_once():
    with pytest.raises(tc.ProgramError) as e:
        run("O1\nG21 G90\nG65 P2 A1 A2\nM30\nO2\nG0 X#1\nM99\n")
    assert e.value.code == "multiple_words" and e.value.line == 3


@pytest.mark.parametrize("mode, start", [("G91 ", 2.0), ("", 3.0)])
def test_fanuc_g10_l2_adds_in_g91(mode, start):
    # Offset 1, tool to X5 (machine 6); then X3 more (G91: offset 4, the tool at X2) or X3.
    text = f"O1\nG21 G90 G54\nG10 L2 P1 X1\nG0 X5 Y0\n{mode}G10 L2 P1 X3\nG90 G1 X10 F100\nM30\n"
    assert run(text).path.start[-1, 0] == start
    lcnc = run(text.replace("O1\n", "").replace("M30", "M2"), "linuxcnc").path
    assert lcnc.start[-1, 0] == 3.0  # LinuxCNC: the value itself in G91 too


@pytest.mark.parametrize("block, code", [
    ("G10 L20 P1 X1", "unsupported_g10"), ("G10 L2 P0 X1", "unsupported_g10"),
    ("G10 L2 P7 X1", "g10_bad_p"), ("G10 L2 P1 X1 R30", "unused_word"),
])
def test_fanuc_g10_forms_that_are_not_linuxcncs(block, code):
    with pytest.raises(tc.ProgramError) as e:
        run(f"O1\nG21 G90\n{block}\nM30\n")
    assert e.value.code == code and e.value.line == 3


def test_fanuc_g04_x_and_u_are_dwell_times():
    p = run("O1\nG21 G90\nG0 X1\nG04 X1.5\nG0 X5\nM30\n").path
    np.testing.assert_allclose(p.end[:, 0], [1, 5])  # no move to X1.5
    lathe = tc.ControlProfile("fanuc", machine="lathe")
    p = run("O1\nG21 G18 G99\nG0 X50 Z5\nG04 U1.5\nG0 X5\nM30\n", profile=lathe).path
    np.testing.assert_allclose(p.end[:, 0], [25, 2.5])  # U not an increment of X here
    with pytest.raises(tc.ProgramError) as e:
        run("O1\nG21 G90\nG04 X1.5 P2\nM30\n")
    assert e.value.code == "dwell_twice"


def test_linuxcnc_abort_comment():
    with pytest.raises(tc.ProgramError) as e:
        run("G21 G90\n#1=7\nG0 X1\n(ABORT, wrong setup #1)\nG0 X5\nM2\n", "linuxcnc")
    assert e.value.code == "abort" and e.value.line == 4 and e.value.message == " wrong setup 7.000000"
    res = tc.run(tc.Program.parse("G21 G90\nG0 X1 (abort,x)\nG0 X5\nM2\n", "linuxcnc"), strict=False)
    assert len(res.path) == 0 and res.diagnostics[-1].message == "x"
    # Fanuc has no such comment: a comment like any other.
    assert len(run("O1\nG21 G90\nG0 X1\n(ABORT, no)\nG0 X5\nM30\n").path) == 2


TOOLS = tc.ToolTable.parse("T1 P1 Z25 D10\nT2 P2 Z40 D6\n", "linuxcnc")


@pytest.mark.parametrize("blocks, z_offset", [
    ("T1 M6\nG43 G0 Z5", 0),            # no H yet: H0, no offset (LinuxCNC: the tool's 25)
    ("T1 M6\nG43 H1 G0 Z5", 25),
    ("G43 H2 G0 Z5\nG49\nG43 G0 Z5", 40),  # the last H stays
    ("T1 M6\nG43 H0 G0 Z5", 0),          # H0 is no offset (LinuxCNC: the tool in the spindle)
])
def test_fanuc_h_numbers_are_modal(blocks, z_offset):
    p = tc.run(tc.Program.parse(f"O1\nG21 G90\n{blocks}\nM30\n", "fanuc"), tools=TOOLS).path
    assert p.tool_offset[-1, 2] == z_offset


def test_linuxcnc_takes_the_spindle_tool_without_h():
    p = tc.run(tc.Program.parse("G21 G90\nT1 M6\nG43 G0 Z5\nM2\n", "linuxcnc"), tools=TOOLS).path
    assert p.tool_offset[-1, 2] == 25


@pytest.mark.parametrize("first, y", [("G41 D2 G1 X0 Y0 F100", 3.0), ("G41 G1 X0 Y0 F100", 0.0)])
def test_fanuc_d_numbers_are_modal(first, y):
    # Along +X under G41 the tool centre is r to the left (+Y): D2 gives r 3; without any D
    # the radius is D0's, none. After G40 a G41 without D takes the last D again.
    text = f"O1\nG21 G90\nT1 M6\nG0 X-10 Y-10\n{first}\nX50\nG40 G1 X60 Y-10\nG41 G1 X70 Y0\nX100\nG40 X110 Y-10\nM30\n"
    p = tc.run(tc.Program.parse(text, "fanuc"), tools=TOOLS).path
    assert p.end[np.flatnonzero(p.line == 6)[-1], 1] == pytest.approx(y)
    assert p.end[np.flatnonzero(p.line == 9)[-1], 1] == pytest.approx(y)


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_g64_blending_is_said_once(dialect):
    text = "O1\nG21 G90\nG64 P0.01\nG1 X1 F100\nG64\nG1 X2\nG61\nM30\n"
    if dialect == "linuxcnc":
        text = text.replace("O1\n", "").replace("M30", "M2")
    res = run(text, dialect)
    infos = [(d.code, d.severity, d.line) for d in res.diagnostics]
    assert infos == [("blending_not_modelled", "info", 3 if dialect == "fanuc" else 2)]
