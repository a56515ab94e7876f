"""LinuxCNC programs that compute: parameters, expressions, O-word subroutines and loops.

Expected numbers are worked out by hand from the program text; where LinuxCNC's own
behaviour decides (precedence, MOD's sign, EQ's tolerance, messages), the value is the one
LinuxCNC 2.9's rs274 printed for the same text (noted per test).
"""
import math
import textwrap

import numpy as np
import pytest

import toolcomp as tc


def run(text, **kw):
    prog = tc.Program.parse(textwrap.dedent(text), dialect="linuxcnc")
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(prog, **kw)


def ends(res):
    return np.round(res.path.end, 9)


def x_of(expr):
    """X of a rapid to the expression (one program per expression)."""
    res = run(f"G21 G0 X{expr}\nM2\n")
    return res.path.end[-1][0]


@pytest.mark.parametrize("expr, value", [
    ("[2+3*4]", 14),
    ("[2**3**2]", 64),          # left to right: (2**3)**2 (rs274: 64)
    ("[2*3**2]", 18),
    ("[-2**2]", 4),             # unary minus binds tighter than ** (rs274: 4)
    ("[1+2 EQ 3]", 1),
    ("[1 OR 0 AND 0]", 0),      # AND OR XOR share one level, left to right (rs274: 0)
    ("[3 GT 2 GT 1]", 0),
    ("[7 MOD 3]", 1),
    ("[-7 MOD 3]", 2),          # never negative (rs274: 2)
    ("[5 MOD -3]", 2),          # (rs274: 2)
    ("[1 EQ 1.0000001]", 1),    # EQ within 0.0001
    ("[0 EQ 0.0001]", 0),
    ("[1 LT 1.00001]", 1),      # the other comparisons exact
    ("ROUND[2.5]", 3), ("ROUND[-2.5]", -3), ("FIX[-2.5]", -3), ("FUP[-2.5]", -2),
    ("[SIN[30]*2]", 1), ("[COS[60]*4]", 2), ("TAN[45]", 1), ("ASIN[1]", 90), ("ACOS[0]", 90),
    ("ATAN[1]/[1]", 45), ("ATAN[1]/[0]", 90), ("ATAN[-1]/[-1]", -135),
    ("SQRT[16]", 4), ("ABS[-3]", 3), ("EXP[0]", 1), ("LN[1]", 0),
    ("[1 2 + 1]", 13),          # blanks are dropped: "1 2" is 12
    ("s i n[90]", 1),
    ("-[1+2]", -3), ("--1", 1), ("+[1]", 1),
])
def test_expression_values(expr, value):
    assert x_of(expr) == pytest.approx(value, abs=1e-12)


@pytest.mark.parametrize("expr, message", [
    ("[1/0]", "Attempt to divide by zero"),
    ("SQRT[-1]", "Negative argument to sqrt"),
    ("LN[0]", "Zero or negative argument to ln"),
    ("ASIN[2]", "Argument to asin out of range"),
    ("ACOS[-1.5]", "Argument to acos out of range"),
    ("[1 MOD 0]", "Calculation resulted in 'not a number'"),
    ("EXP[1000]", "Calculation resulted in 'infinity'"),
])
def test_math_errors_name_the_line(expr, message):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G21 G0 X1\nG0 X{expr}\nM2\n")
    assert str(e.value).startswith(message)
    assert e.value.line == 2


def test_atan_needs_its_slash():
    with pytest.raises(tc.ParseError, match="Slash missing after first atan argument"):
        run("G0 X[ATAN[1]]\nM2\n")


def test_words_read_the_values_before_the_line_assignments_after():
    # rs274: "#1=1 #2=#1 #1=9" leaves #2 = 0 (the old #1) and #1 = 9.
    res = run("""\
        #1=1 #2=#1 #1=9
        G21 G0 X#1 Y#2
        #3=5 G0 Z#3
        M2
        """)
    assert ends(res)[0].tolist() == [9, 0, 0]
    assert ends(res)[1].tolist() == [9, 0, 0]  # Z#3 read before #3=5 is set
    assert res.parameters == {1: 9.0, 3: 5.0}


def test_indirect_and_computed_parameter_numbers():
    res = run("""\
        #1=7 #7=3.5
        #[10+2]=2
        G21 G0 X##1 Y#12 Z#[#12*6]
        M2
        """)
    assert ends(res)[0].tolist() == [3.5, 2, 2]  # ##1 = #7; #[#12*6] = #[12]


def test_named_parameters_are_local_to_a_call_and_globals_are_global():
    # rs274: a caller's #<loc> is not visible in the callee; what the sub sets locally is gone
    # after the return; #<_g> set in the sub survives.
    res = run("""\
        #<loc>=1
        o100 sub
          #<inside>=5
          #<_g>=6
          G0 X[EXISTS[#<loc>]] Y[EXISTS[#<inside>]]
        o100 endsub
        G21
        o100 call
        G0 Z[EXISTS[#<inside>]*10 + #<_g>]
        M2
        """)
    assert ends(res).tolist() == [[0, 1, 0], [0, 1, 6]]
    with pytest.raises(tc.ProgramError, match=r"Named parameter #<nope> not defined") as e:
        run("G21\nG0 X1\nG0 X#<nope>\nM2\n")
    assert e.value.line == 3


def test_call_arguments_fill_1_to_30_and_the_callers_come_back():
    res = run("""\
        G21
        #1=100 #2=200 #31=1
        o1 sub
          G0 X#1 Y#2 Z#3
          #1=99 #31=77
        o1 endsub
        o1 call [5] [6]
        G0 X#1 Y#2 Z#31
        M2
        """)
    assert ends(res).tolist() == [[5, 6, 0], [100, 200, 77]]  # #3 of the call is 0; #31 is global


def test_return_values_and_value_returned():
    res = run("""\
        G21
        o<sq> sub
          o<sq> return [#1*#1]
          G0 Z99
        o<sq> endsub
        o<nv> sub
        o<nv> endsub
        o<sq> call [3]
        G0 X#<_value> Y#<_value_returned>
        o<nv> call
        G0 X#<_value> Y#<_value_returned>
        M2
        """)
    assert ends(res).tolist() == [[9, 1, 0], [0, 0, 0]]


def test_loops_emit_their_moves():
    res = run("""\
        G21 F100
        #1=0
        o10 while [#1 LT 4]
          #1=[#1+1]
          o11 if [#1 EQ 2]
            o10 continue
          o11 endif
          G1 X#1
        o10 endwhile
        #2=0
        o20 do
          #2=[#2+1]
          G1 Y#2
          o21 if [#2 GE 3]
            o20 break
          o21 endif
        o20 while [1]
        o30 repeat [2.5]
          G91 G1 Z-1
        o30 endrepeat
        G90
        M2
        """)
    # X 1, 3, 4 (2 is skipped); Y 1, 2, 3 (break at 3); repeat [2.5] runs twice (half to even)
    assert ends(res).tolist() == [[1, 0, 0], [3, 0, 0], [4, 0, 0], [4, 1, 0], [4, 2, 0], [4, 3, 0],
                                  [4, 3, -1], [4, 3, -2]]
    assert res.path.line.tolist() == [8, 8, 8, 13, 13, 13, 19, 19]


def test_if_elseif_else():
    def pick(v):
        res = run(f"""\
            G21 #1={v}
            o1 if [#1 LT 0]
              G0 X1
            o1 elseif [#1 EQ 0]
              G0 X2
            o1 elseif [#1 LT 10]
              G0 X3
            o1 else
              G0 X4
            o1 endif
            M2
            """)
        return ends(res)[0][0]
    assert [pick(v) for v in (-1, 0, 5, 50)] == [1, 2, 3, 4]


def test_every_elseif_reached_is_evaluated():
    # rs274 evaluates an elseif after a taken branch too: [1/0] there is an error.
    with pytest.raises(tc.ProgramError, match="Attempt to divide by zero") as e:
        run("G21\no1 if [1]\nG0 X1\no1 elseif [1/0]\nG0 X2\no1 endif\nM2\n")
    assert e.value.line == 4


def test_skipped_text_is_not_evaluated():
    res = run("G21\no1 if [0]\nG0 X[1/0] Y#<undefined>\no1 endif\nG0 X1\nM2\n")
    assert ends(res).tolist() == [[1, 0, 0]]


def test_forward_call_and_a_definition_the_flow_must_not_reach():
    ok = run("G21\no200 call [5]\nM2\no200 sub\nG0 X#1\no200 endsub\n")
    assert ends(ok).tolist() == [[5, 0, 0]]
    with pytest.raises(tc.ProgramError, match=r"sub: o\|200\| found in illegal location") as e:
        run("G21\no200 call [5]\nG0 Y1\no200 sub\nG0 X#1\no200 endsub\nM2\n")
    assert e.value.line == 4


@pytest.mark.parametrize("text, code, message, line", [
    ("G21\no300 call\nG0 X1\nM2\n", "unknown_o_word", "EOF in file:<string> seeking o-word: o<300> from line: 2", 2),
    ("G21\no1 endwhile\nM2\n", "o_word_structure", "2: undefined O-word label: 'o1 endwhile'", 2),
    ("G21\no1 while [1]\no1 endif\nM2\n", "o_word_structure",
     "3: no matching label: '#1' (found 'while' in line 2): 'o1 endif'", 3),
    ("G21\n  o1 return\nM2\n", "return_outside_sub", "2: not in a subroutine definition: '  o1 return'", 2),
    ("G21\no1 while [0]\nG0 X1\nM2\n", "o_word_structure", "File ended with no percent sign or program end", 4),
    ("G21\no6 repeat [2]\n  o6 break\no6 endrepeat\nM2\n", "o_word_structure",
     "3: no matching while/do label: '  o6 break' (found 'repeat' in line 2)", 3),
    ("G21\n#0=1\nM2\n", "parameter_out_of_range", "Parameter number out of range", 2),
    ("G21\nG0 X#5602\nM2\n", "parameter_out_of_range", "Parameter number out of range", 2),
    ("G21\n#5400=3\nM2\n", "read_only_parameter", "Parameter is readonly", 2),
    ("G21\nG0 X#5061\nM2\n", "probe_parameter_unset", "Probe result #5061 read", 2),
    ("G21\n#<_x>=1\nM2\n", "read_only_parameter", "Cannot assign to read-only parameter #<_x>", 2),
])
def test_errors_with_their_lines(text, code, message, line):
    with pytest.raises(tc.Error) as e:
        run(text)
    assert e.value.code == code
    assert str(e.value).startswith(message)
    assert e.value.line == line


def test_recursion_stops_at_linuxcncs_nine_levels():
    text = "G21\no<rec> sub\no<rec> call\no<rec> endsub\no<rec> call\nM2\n"
    with pytest.raises(tc.ProgramError, match="Too many subroutine levels") as e:
        run(text)
    assert e.value.code == "call_depth" and e.value.line == 5  # LinuxCNC: the outermost call
    deeper = tc.ControlProfile("linuxcnc")
    deeper.call_depth_limit = 50
    with pytest.raises(tc.ProgramError, match="Too many subroutine levels"):
        run(text, profile=deeper)


def test_nine_nested_calls_are_allowed():
    # #1 counts the level down from 9: nine nested calls, each leaving a move.
    res = run("""\
        G21
        o<n> sub
          G0 X#1
          o1 if [#1 GT 1]
            o<n> call [#1-1]
          o1 endif
        o<n> endsub
        o<n> call [9]
        M2
        """)
    assert ends(res)[:, 0].tolist() == [9, 8, 7, 6, 5, 4, 3, 2, 1]


def test_an_endless_loop_stops_at_the_block_limit():
    profile = tc.ControlProfile("linuxcnc")
    profile.block_limit = 200_000
    with pytest.raises(tc.ProgramError) as e:
        run("G21\no1 while [1]\nG0 X1\no1 endwhile\nM2\n", profile=profile)
    assert e.value.code == "block_limit" and e.value.line in (2, 3, 4)
    assert tc.ControlProfile("linuxcnc").block_limit == 100_000_000


def test_debug_and_print_show_values_msg_does_not():
    res = run("G21\n#1=1.5 (DEBUG, x=#1 y=#<_nope>)\n(MSG, #1)\n(PRINT,#2)\nM2\n")
    assert [d.message for d in res.diagnostics] == [" x=1.500000 y=######", " #1", "0.000000"]
    assert all(d.severity == "info" for d in res.diagnostics)


COMMENTS = ("G21 (MSG, first) (MSG, second)\nG0 X1 (MSG, only) (plain note)\n;MSG, semi\n"
            "G0 X2 (MSG, par) ;(MSG, semi2)\n(DEBUG, one) (debug, two)\nM2\n")


def test_only_the_last_comment_in_parentheses_of_a_line_speaks():
    # LinuxCNC keeps one comment per block, each overwriting the one before, and does not
    # read ';' comments for MSG. rs274 (2.9) on this program prints MESSAGE(" second"),
    # COMMENT("plain note"), MESSAGE(" par") and MESSAGE(" two"), nothing for line 3.
    res = run(COMMENTS)
    assert [(d.line, d.message) for d in res.diagnostics] == [(1, " second"), (4, " par"), (5, " two")]


def test_every_comment_speaks_when_the_profile_says_so():
    every = tc.ControlProfile("linuxcnc")
    assert every.last_comment_only and not tc.ControlProfile("fanuc").last_comment_only
    every.last_comment_only = False
    res = run(COMMENTS, profile=every)
    assert [(d.line, d.message) for d in res.diagnostics] == [
        (1, " first"), (1, " second"), (2, " only"), (3, " semi"), (4, " par"), (5, " one"), (5, " two")]


def test_system_parameters_show_the_interpreter_state():
    res = run("""\
        G21 G10 L2 P1 X5 Y6
        G54 G0 X1 Y2 Z3
        #1=#5221 #2=#5222 #3=#5220 #4=#5420 #5=#5421 #6=#5422
        G0 X#1 Y#2 Z[#3*100+#4*10+#5]
        M2
        """)
    assert ends(res)[-1].tolist() == [5, 6, 100 + 10 + 2]


def test_subroutine_files_on_the_search_path_carry_their_file_and_lines(tmp_path):
    (tmp_path / "pocket.ngc").write_text("(a sub file)\no<pocket> sub\n  G1 X#1 F100\n  G1 Y#2\no<pocket> endsub\nM2\n")
    main = tmp_path / "main.ngc"
    main.write_text("G21\nG0 X0 Y0\no<Pocket> call [3] [4]\nG0 Z5\nM2\n")
    res = tc.run(tc.Program.read(str(main)), search_path=[str(tmp_path)], start="machine_zero")
    p = res.path
    assert ends(res).tolist() == [[0, 0, 0], [3, 0, 0], [3, 4, 0], [3, 4, 5]]
    assert p.line.tolist() == [2, 3, 4, 4]
    assert p.file.tolist() == [0, 1, 1, 0]
    assert p.files == [str(main), str(tmp_path / "pocket.ngc")]
    with pytest.raises(tc.ProgramError, match="EOF in file"):
        tc.run(tc.Program.read(str(main)))  # no search path: nowhere to look


def test_parameters_from_a_var_file_and_back(tmp_path):
    var = tmp_path / "sim.var"
    var.write_text("31\t2.500000\n5161\t0.000000\n5220\t1.000000\n")
    res = run("G21\nG0 X#31\n#31=[#31*2] #40=7\nM2\n", parameters=str(var))
    assert ends(res).tolist() == [[2.5, 0, 0]]
    assert res.parameters[31] == 5.0 and res.parameters[40] == 7.0
    tc.params.write_var(var, {31: res.parameters[31]})
    assert var.read_text() == "31\t5.000000\n5161\t0.000000\n5220\t1.000000\n"  # only #31 changed
    tc.params.write_var(var, {40: 7})
    assert var.read_text().splitlines()[1] == "40\t7.000000"  # inserted in order
    assert tc.params.read_var(var) == {31: 5.0, 40: 7.0, 5161: 0.0, 5220: 1.0}
    var.write_text("40\t1\n31\t2\n")
    with pytest.raises(tc.ParseError, match="Parameter file out of order") as e:
        tc.params.read_var(var)
    assert e.value.line == 2


def test_unrolled_loop_gives_the_same_path():
    n, step = 12, 2.5
    loop = run(f"""\
        G21 G1 F200
        #1=0
        o1 while [#1 LT {n}]
          G1 X[#1*{step}] Y[SIN[#1*30]*10]
          #1=[#1+1]
        o1 endwhile
        M2
        """)
    unrolled = "G21 G1 F200\n" + "".join(
        f"G1 X{i * step:.10f} Y{math.sin(math.radians(i * 30)) * 10:.10f}\n" for i in range(n)) + "M2\n"
    ref = run(unrolled)
    np.testing.assert_allclose(loop.path.end, ref.path.end, atol=1e-9)


def test_a_syntax_error_in_a_subroutine_file_is_reported_at_the_call(tmp_path):
    # LinuxCNC reports errors inside calls at the main program's line of the outermost call.
    (tmp_path / "bad.ngc").write_text("o<bad> sub\nG1 X1..2\no<bad> endsub\n")
    main = tmp_path / "main.ngc"
    main.write_text("G21\nG0 X0\no<bad> call\nM2\n")
    with pytest.raises(tc.ParseError) as e:
        tc.run(tc.Program.read(str(main)), search_path=[str(tmp_path)])
    assert (e.value.line, e.value.file) == (3, None)
    assert str(e.value).startswith("bad number format (trailing characters) parsing '1..2'")


def test_compensation_warnings_in_a_subroutine_file_name_that_file(tmp_path):
    # The inside corner onto a 2 mm step (r = 5) cuts into the contour: LinuxCNC cuts it,
    # toolcomp warns at the step's block, line 4 of cut.ngc. The gouge error that follows is
    # LinuxCNC's, at the main program's line of the call (3).
    (tmp_path / "cut.ngc").write_text("o<cut> sub\nG1 X0 Y0 F100\nX30\nY-2\nX60\no<cut> endsub\nM2\n")
    main = tmp_path / "main.ngc"
    main.write_text("G21 G0 X-10 Y5\nG41.1 D10\no<cut> call\nG40 G0 X70 Y10\nM2\n")
    res = tc.run(str(main), search_path=[str(tmp_path)], strict=False)
    cut = str(tmp_path / "cut.ngc")
    assert [(d.code, d.line, d.file) for d in res.diagnostics] == [
        ("comp_overcut", 4, cut), ("comp_overcut", 4, cut), ("comp_gouge", 3, None)]


@pytest.mark.parametrize("arg, value", [("#1", 1), ("#0", 0), ("#5601", 1), ("#5602", 0), ("##2", 1),
                                        ("#[2+3]", 1), ("#[0-3]", 0), ("#<a>", 0), ("#<_x>", 1)])
def test_exists_takes_numbered_parameters_too(arg, value):
    # LinuxCNC 2.9 (gcode module): a number of 1-5601 is a parameter; #2 = 7 names #7
    assert ends(run(f"G21\n#2=7\nG0 X[EXISTS[{arg}]]\nM2\n"))[-1][0] == value


def test_named_parameters_are_declared_as_the_line_is_read():
    # LinuxCNC 2.9 (gcode module): an assignment declares its name (value 0) where it stands
    # in the line; what is read before it finds nothing, what is read after it finds 0.
    with pytest.raises(tc.ProgramError) as e:
        run("G21\nG0 X#<n2> #<n2>=4\nM2\n")
    assert (e.value.message, e.value.line) == ("Named parameter #<n2> not defined", 2)
    assert ends(run("G21\n#1=EXISTS[#<n>] #<n>=2\nG0 X[#1+1]\nM2\n"))[-1][0] == 1
    assert ends(run("G21\n#<n>=4 G0 X#<n>\nG0 Y#<n>\nM2\n")).tolist()[-2:] == [[0, 0, 0], [0, 4, 0]]
