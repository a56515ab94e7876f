"""Fanuc Macro B: variables (vacant, local, common), IF / WHILE / GOTO, M98 / M99, G65.

Expected numbers are worked out by hand from the program text (Fanuc's rules: a vacant
variable leaves its address out, counts as 0 in arithmetic, equals only vacant in EQ / NE;
G65 argument specification I: A #1, B #2, C #3, I #4, J #5, K #6, ..., X #24, Y #25, Z #26).
"""
import textwrap

import numpy as np
import pytest

import toolcomp as tc


def run(text, **kw):
    prog = tc.Program.parse(textwrap.dedent(text), dialect="fanuc")
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(prog, **kw)


def ends(res):
    return np.round(res.path.end, 9).tolist()


def test_nested_while_do_runs_like_its_unrolled_program():
    loops = run("""\
        O0001 (GRID OF HOLES)
        G21 G90 G17 G0 X0 Y0 Z5
        #1=0
        WHILE [#1 LT 3] DO1
          #2=0
          WHILE [#2 LT 4] DO2
            G0 X[#2*10] Y[#1*15]
            G1 Z-2 F100
            G0 Z5
            #2=#2+1
          END2
          #1=#1+1
        END1
        M30
        """)
    unrolled = "G21 G90 G17 G0 X0 Y0 Z5\n" + "".join(
        f"G0 X{j * 10} Y{i * 15}\nG1 Z-2 F100\nG0 Z5\n" for i in range(3) for j in range(4)) + "M30\n"
    ref = run(unrolled)
    assert len(loops.path) == len(ref.path) == 1 + 3 * 4 * 3
    np.testing.assert_allclose(loops.path.end, ref.path.end, atol=1e-12)
    np.testing.assert_array_equal(loops.path.kind, ref.path.kind)
    assert ends(loops)[-1] == [30, 30, 5]


def test_vacant_variables():
    res = run("""\
        G21 G0 X7 Y7
        G0 X#1 Y5
        #2=#1
        #3=#1*5
        #4=[#1 EQ #0]*10+[#1 EQ 0]
        #5=#2+1
        G0 X#3 Y#4 Z#5
        M30
        """)
    # X#1 with #1 vacant: X is left out (stays 7). #2 vacant, #3 = 0, #4 = 10 + 0, #5 = 1.
    assert ends(res) == [[7, 7, 0], [7, 5, 0], [0, 10, 1]]
    assert res.parameters == {3: 0.0, 4: 10.0, 5: 1.0}


def test_if_goto_goto_and_if_then():
    res = run("""\
        G21 G0 X0
        #1=1
        N10 G0 X#1
        #1=#1+1
        IF [#1 LE 3] GOTO10
        IF [#1 EQ 4] THEN #5=2
        IF [#1 EQ 5] THEN #5=9
        GOTO 30
        G0 X99
        N30 G0 Y#5
        M30
        """)
    assert ends(res) == [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0], [3, 2, 0]]


def test_m98_subprogram_in_the_same_file_with_repeats():
    res = run("""\
        O1 (MAIN)
        G21 G91 G0 X0
        M98 P1000 L3
        G90 G0 Y50
        M98 P22000 (two passes of O2000)
        M30
        O1000 (STEP X)
        G91 G1 X10 F100
        M99
        O2000
        G91 G0 Y1
        M99
        """)
    assert ends(res) == [[0, 0, 0], [10, 0, 0], [20, 0, 0], [30, 0, 0], [30, 50, 0], [30, 51, 0], [30, 52, 0]]
    assert res.path.line.tolist() == [2, 8, 8, 8, 4, 11, 11]


def test_g65_arguments_are_locals_of_the_macro():
    res = run("""\
        G21 G90
        #1=111 #100=0
        G65 P9010 A2 B3 X40 Z-5
        G0 X#1 Y#100
        M30
        O9010 (MACRO)
        G0 X#24 Y[#1*#2]
        G1 Z#26 F100
        #100=#4+1
        #1=999
        M99
        """)
    # In the macro: #24 = 40, #1 = 2, #2 = 3, #26 = -5, #4 (I) vacant -> #100 = 1.
    # After it: the caller's #1 (111) is back; #100 is common.
    assert ends(res) == [[40, 6, 0], [40, 6, -5], [111, 1, -5]]


def test_subprogram_file_on_the_search_path(tmp_path):
    (tmp_path / "O1234.nc").write_text("O1234\nG91 G1 X5 F100\nM99\n")
    main = tmp_path / "main.nc"
    main.write_text("G21 G0 X0\nM98 P1234 L2\nG90 G0 Y1\nM30\n")
    res = tc.run(tc.Program.read(str(main)), search_path=[str(tmp_path)], start="machine_zero")
    assert ends(res) == [[0, 0, 0], [5, 0, 0], [10, 0, 0], [10, 1, 0]]
    assert res.path.file.tolist() == [0, 1, 1, 0]
    assert res.path.line.tolist() == [1, 2, 2, 3]
    assert res.path.files[1] == str(tmp_path / "O1234.nc")
    with pytest.raises(tc.ProgramError, match="Program O1234 not found") as e:
        tc.run(tc.Program.read(str(main)))
    assert e.value.line == 2


def test_macro_alarm_stops_with_its_message():
    with pytest.raises(tc.ProgramError) as e:
        run("G21 G0 X1\nIF [#1 EQ #0] THEN #3000=5 (NO DEPTH GIVEN)\nG0 X2\nM30\n")
    assert e.value.code == "macro_alarm" and e.value.line == 2
    assert str(e.value).startswith("Alarm 3005 NO DEPTH GIVEN")


@pytest.mark.parametrize("text, code, line", [
    ("G21\nGOTO 50\nM30\n", "sequence_number_not_found", 2),
    ("G21\nEND1\nM30\n", "o_word_structure", 2),
    ("G21\nWHILE [1 LT 2] DO1\nG0 X1\nM30\n", "macro_loop", 2),
    ("G21\n#1=1/0\nM30\n", "math_error", 2),
    ("G21\n#0=1\nM30\n", "vacant_assignment", 2),
    ("G21\nG65 P1 G1\nM30\n", "g65_other_codes", 2),
    ("G21\nM98 P77\nM30\n", "program_not_found", 2),
])
def test_errors_with_their_lines(text, code, line):
    with pytest.raises(tc.Error) as e:
        run(text)
    assert (e.value.code, e.value.line) == (code, line)


def test_m99_in_the_main_program_repeats_it_until_the_block_limit():
    profile = tc.ControlProfile("fanuc")
    profile.block_limit = 10_000
    with pytest.raises(tc.ProgramError) as e:
        run("G21 G91 G0 X1\nM99\n", profile=profile)
    assert e.value.code == "block_limit"


def test_last_g_code_of_a_modal_group_wins():
    res = run("G21 G0 G1 X5 F100\nM30\n")
    assert res.path.kind.tolist() == [tc.LINE]


def test_an_error_in_a_subprogram_file_names_that_file(tmp_path):
    # Fanuc reports the block of the subprogram: line 3 of O2000.nc (#1 is vacant there, so
    # #2=1/#1 divides by zero).
    (tmp_path / "O2000.nc").write_text("O2000\nG91 G1 X5 F100\n#2=1/#1\nM99\n")
    main = tmp_path / "main.nc"
    main.write_text("G21 G0 X0\nM98 P2000\nM30\n")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.read(str(main)), search_path=[str(tmp_path)])
    assert (e.value.code, e.value.line, e.value.file) == ("math_error", 3, str(tmp_path / "O2000.nc"))
    assert f"line 3 of {tmp_path / 'O2000.nc'}" in str(e.value)
    res = tc.run(tc.Program.read(str(main)), search_path=[str(tmp_path)], strict=False)
    d = res.diagnostics[-1]
    assert (d.code, d.line, d.file) == ("math_error", 3, str(tmp_path / "O2000.nc"))
    assert ends(res) == [[0, 0, 0], [5, 0, 0]]
    with pytest.raises(tc.ProgramError) as e:
        run("G21\n#1=1/0\nM30\n")
    assert e.value.file is None  # the main program


def test_a_compensation_error_in_a_subprogram_file_names_that_file(tmp_path):
    # G41 with r = 5 (D10) onto a CCW arc of R2 in O3000.nc: the tool does not fit inside
    # it. Fanuc's alarm comes at the arc's block: line 3 of O3000.nc.
    (tmp_path / "O3000.nc").write_text("O3000\nG1 X20 Y0\nG3 X24 Y0 R2\nG1 X40\nM99\n")
    main = tmp_path / "main.nc"
    main.write_text("G21 G90 G40 G17\nT1 M6\nG0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nM98 P3000\nG40 G0 X50 Y-10\nM30\n")
    tools = tc.ToolTable.parse("T1 P1 D10\n", "linuxcnc")
    sub = str(tmp_path / "O3000.nc")
    with pytest.raises(tc.CompensationError) as e:
        tc.run(str(main), tools, search_path=[str(tmp_path)])
    assert (e.value.code, e.value.line, e.value.file) == ("comp_arc_too_small", 3, sub)
    assert f"line 3 of {sub}" in str(e.value)
    res = tc.run(str(main), tools, search_path=[str(tmp_path)], strict=False)
    assert [(d.code, d.line, d.file) for d in res.diagnostics] == [("comp_arc_too_small", 3, sub)]


def test_a_compensation_error_names_the_file_when_both_files_have_that_line(tmp_path):
    # The same arc as above, now at line 2 of O3000.nc while the entry move of line 2 of the
    # main program is still held: the error is the arc's, in O3000.nc.
    (tmp_path / "O3000.nc").write_text("O3000\nG3 X4 Y0 R2\nG1 X40\nM99\n")
    main = tmp_path / "main.nc"
    main.write_text("G21 G90 G40 G17 T1 M6 G0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nM98 P3000\nG40 G0 X50 Y-10\nM30\n")
    tools = tc.ToolTable.parse("T1 P1 D10\n", "linuxcnc")
    with pytest.raises(tc.CompensationError) as e:
        tc.run(str(main), tools, search_path=[str(tmp_path)])
    assert (e.value.code, e.value.line, e.value.file) == ("comp_arc_too_small", 2, str(tmp_path / "O3000.nc"))
