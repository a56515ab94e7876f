"""840D STRING variables and parameters: "<<" joins values as text, strings compare in
conditions, and the string functions STRLEN, INDEX, RINDEX, SUBSTR, TOUPPER, TOLOWER, NUMBER,
ISNUMBER give what the 840D's programming manual describes (positions count from 0)."""
import pytest

import toolcomp as tc


def run(text, **kw):
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text, "sinumerik"), **kw)


def xs(text, **kw):
    return [float(x) for x in run(text, **kw).nominal.end[:, 0]]


def test_string_variables_compare_in_conditions():
    text = """DEF STRING[20] TOOL="DRILL"
DEF STRING[20] OTHER
OTHER="DRILL"
IF TOOL=="DRILL"
G1 X1 F100
ENDIF
IF TOOL<>OTHER
G1 X99
ENDIF
IF "ABC"<"ABD"
G1 X2
ENDIF
M30
"""
    assert xs(text) == [1, 2]


@pytest.mark.parametrize("expr, value", [
    ('STRLEN("DRILL")', 5),
    ('INDEX("T3_1.5", "_")', 2),
    ('RINDEX("A.B.C", ".")', 3),
    ('INDEX("ABC", "X")', -1),
    ('NUMBER(SUBSTR("T12_R", 1, 2))', 12),
    ('NUMBER(SUBSTR("XY7", 2))', 7),
    ('ISNUMBER("1.5")', 1),
    ('ISNUMBER("1.5A")', 0),
    ('STRLEN(TOUPPER("abc") << TOLOWER("D"))', 4),
    ('("abc" << 1) == "abc1"', 1),
    ('("X" << 2.5 << "/" << 3) == "X2.5/3"', 1),
    ('TOUPPER("mill") == "MILL"', 1),
])
def test_string_functions(expr, value):
    assert xs(f"R1={expr}\nG1 X=R1 F100\nM30\n") == [value]


def test_strings_join_into_variables_and_messages():
    res = run('DEF STRING[32] NAME\nDEF INT N=3\nNAME="PART_" << N\nMSG("Running " << NAME)\n'
              'IF NAME=="PART_3"\nG1 X1 F100\nENDIF\nM30\n')
    assert [float(x) for x in res.nominal.end[:, 0]] == [1]
    assert [(d.code, d.message) for d in res.diagnostics] == [("message", "Running PART_3")]


def test_string_arrays():
    text = 'DEF STRING[8] NAMES[3]\nNAMES[1]="B"\nNAMES[2]=NAMES[1] << "C"\nIF NAMES[2]=="BC"\nG1 X=STRLEN(NAMES[0]) F100\nENDIF\nM30\n'
    assert xs(text) == [0]


def test_string_parameters_by_value_and_by_reference(tmp_path):
    (tmp_path / "LABEL.SPF").write_text(
        'PROC LABEL(STRING[10] KIND, VAR STRING[20] OUT, REAL N)\nOUT=KIND << "-" << N\nG1 X=STRLEN(OUT)\nM17\n')
    res = run('DEF STRING[20] RESULT\nG1 X0 F100\nLABEL("HOLE", RESULT, 12)\nIF RESULT=="HOLE-12"\nG1 Y1\nENDIF\n'
              'LABEL(, RESULT)\nIF RESULT=="-0"\nG1 Z1\nENDIF\nM30\n', search_path=[tmp_path])
    assert res.nominal.end[1:].tolist() == [[7, 0, 0], [7, 1, 0], [2, 1, 0], [2, 1, 1]]


@pytest.mark.parametrize("text, code", [
    ('DEF STRING[3] TXT="ABCD"\nM30\n', "string_too_long"),
    ('DEF STRING[3] TXT\nTXT="AB" << "CD"\nM30\n', "string_too_long"),
    ('DEF STRING[5] TXT="AB"\nR1=TXT+1\nM30\n', "math_error"),      # a string in arithmetic
    ('DEF STRING[5] TXT="AB"\nIF TXT==1\nENDIF\nM30\n', "math_error"),  # a string compared with a number
    ('R1=NUMBER("X1")\nM30\n', "math_error"),
    ('DEF REAL VAL\nVAL="X"\nM30\n', "math_error"),
    ('R1="X"\nM30\n', "math_error"),
])
def test_string_errors(text, code):
    with pytest.raises(tc.ProgramError) as e:
        run(text)
    assert e.value.code == code


def test_a_var_string_parameter_needs_a_string_variable(tmp_path):
    (tmp_path / "SUB.SPF").write_text("PROC SUB(VAR STRING[10] S)\nM17\n")
    for call, code in [("SUB(R1)", "12330"), ("SUB(N)", "12330"), ('SUB("A")', "12320")]:
        with pytest.raises(tc.ProgramError) as e:
            run(f"DEF INT N\nG0 X0\n{call}\nM30\n", search_path=[tmp_path])
        assert e.value.code == code, call


def test_strings_in_an_assignments_indices_are_errors_not_crashes():
    for text in ['DEF STRING[5] TXT="A"\nDEF REAL A[3]\nA[TXT]=1\nM30\n', 'DEF REAL A[3]\nA[STRLEN("AB")]=1\nM30\n']:
        with pytest.raises(tc.ProgramError) as e:
            run(text)
        assert e.value.code == "math_error"
