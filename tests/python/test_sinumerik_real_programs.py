"""What real 840D programs carry besides the path: subprogram names ending in digits, keywords
that set up the control without a path of their own, ShopMill/ShopTurn step programs (refused
with their own code), and T.. D.. before M6 (MD20270 $MC_CUTTING_EDGE_DEFAULT)."""
import numpy as np
import pytest

import toolcomp as tc


def run(text, **kw):
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text, "sinumerik"), **kw)


def tools():
    t = tc.ToolTable()
    for n, length in [(1, 50.0), (2, 80.0)]:
        t.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=3.0, length=[0.0, 0.0, length])]))
    return t


@pytest.mark.parametrize("call", ["PART12", "L_39", "PART12()", "L_39 P2"])
def test_subprogram_names_ending_in_digits_are_calls(tmp_path, call):
    name = call.split()[0].rstrip("()")
    (tmp_path / f"{name}.SPF").write_text("G91 G1 X10 F100\nG90\nM17\n")
    res = run(f"G0 X0 Y0\n{call}\nM30\n", search_path=[tmp_path])
    passes = 2 if "P2" in call else 1
    assert res.nominal.end[-1, 0] == 10 * passes


def test_a_name_ending_in_digits_that_is_nowhere_is_a_missing_program():
    with pytest.raises(tc.ProgramError) as e:
        run("G0 X0\nPART12\nM30\n")
    assert e.value.code == "14011" and "PART12" in e.value.message


@pytest.mark.parametrize("block", ["F_HEAD(1,101,0,\"\",\"\",0,1,0,1,\"\",0)", "E_HEAD(1,\"\",0)", "F_DRILL(1,2)"])
def test_shopturn_and_shopmill_step_programs_are_refused_with_their_own_code(block):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0\n{block}\nM30\n")
    assert e.value.code == "shopturn_program" and e.value.line == 2 and "ShopMill/ShopTurn" in e.value.message


def test_a_subprogram_of_that_shape_on_the_search_path_is_still_called(tmp_path):
    (tmp_path / "F_PART.SPF").write_text("G1 X7 F100\nM17\n")
    assert run("G0 X0\nF_PART\nM30\n", search_path=[tmp_path]).nominal.end[-1, 0] == 7


@pytest.mark.parametrize("word", ["FNORM", "FLIN", "FCUB", "BRISK", "SOFT", "FFWON", "FFWOF", "UPATH", "SPATH", "COMPOF"])
def test_control_settings_without_a_path_are_taken(word):
    res = run(f"G0 X0 Y0\n{word} G1 X10 F100\nM30\n")
    assert res.nominal.end[-1, 0] == 10 and not res.diagnostics


@pytest.mark.parametrize("block, code", [
    ("COMPCAD", "blending_not_modelled"),
    ("CYCLE832(0.01,112001)", "blending_not_modelled"),
    ("WORKPIECE(,\"\",,\"BOX\",112,0,-50,-80,-50,-50,50,50)", "no_path_effect"),
    ("CYCLE800()", "no_path_effect"),
    ("CYCLE800(1,\"TABLE\",200000,57,0,0,0,0,0,0,0,0,0,-1,100,1)", "no_path_effect"),
])
def test_setup_calls_without_a_path_are_noted(block, code):
    res = run(f"G0 X0 Y0\n{block}\nG1 X10 F100\nM30\n")
    assert res.nominal.end[-1, 0] == 10 and [d.code for d in res.diagnostics] == [code]


@pytest.mark.parametrize("block, word", [
    ("CYCLE800(1,\"TABLE\",200000,57,0,0,0,0,30,0,0,0,0,-1,100,1)", "CYCLE800 with a swivel (B = 30)"),
    ("CYCLE800(0,\"\",0,57,0,0,0,45,0,0,0,0,0,1)", "CYCLE800 with a swivel (A = 45)"),
    ("BSPLINE", "BSPLINE"), ("TRAORI", "TRAORI"), ("ORIWKS", "ORIWKS"), ("CYCLE90(10,0,2,-5)", "CYCLE90"),
    ("POCKET3(10,0,2,-5)", "POCKET3"),
])
def test_keywords_toolcomp_does_not_run_are_refused_by_name_never_as_missing_programs(block, word):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0\n{block}\nM30\n")
    assert e.value.code == "unsupported_word" and word in e.value.message


def test_t_and_d_before_m6_select_the_new_tools_edge_at_the_change():
    # D1 in the T block refers to the tool in the spindle (none yet); M6 selects the edge
    # MD20270 names: 1 (the default) -> T1 D1, 50 mm.
    res = run("G0 X0 Y0\nT1 D1\nM6\nG0 Z10\nT2 D1\nM6\nG0 Z20\nM30\n", tools=tools())
    assert list(res.nominal.tool_offset[:, 2]) == [0, 50, 80]
    profile = tc.ControlProfile("sinumerik")
    profile.cutting_edge_default = 0  # no edge after M6 until a D
    res = run("G0 X0 Y0\nT1 D1\nM6\nG0 Z10\nD1\nG0 Z20\nM30\n", tools=tools(), profile=profile)
    assert list(res.nominal.tool_offset[:, 2]) == [0, 0, 50]
    with pytest.raises(ValueError):
        profile.cutting_edge_default = -2
        run("M30\n", profile=profile)


def xs(text):
    return [round(float(x), 6) for x in run(text).nominal.end[:, 0]]


def test_repeat_a_section_up_to_endlabel():
    # The 840D manual's example: the section from BEGIN to ENDLABEL runs once in the flow and
    # three times more at REPEAT BEGIN P=3; the block between ENDLABEL and REPEAT once only.
    text = "G0 X0\nR10=0\nBEGIN: R10=R10+1\nG1 X=R10 F100\nENDLABEL:\nG1 X100\nREPEAT BEGIN P=3\nM30\n"
    assert xs(text) == [0, 1, 100, 2, 3, 4]


def test_repeat_from_a_label_to_the_block_before_and_between_two_labels():
    assert xs("G0 X0\nR1=0\nSTA: R1=R1+1\nG1 X=R1 F100\nREPEAT STA\nM30\n") == [0, 1, 2]  # P omitted: once
    text = "G0 X0\nR1=0\nSTA: R1=R1+1\nG1 X=R1 F100\nSTO: G1 X=-R1\nG1 X50\nREPEAT STA STO P=2\nM30\n"
    assert xs(text) == [0, 1, -1, 50, 2, -2, 3, -3]


def test_repeatb_repeats_one_block():
    assert xs("G0 X0\nMARK: G91 G1 X1 F100\nG90\nREPEATB MARK P=2\nG90 G1 X0\nM30\n") == [0, 1, 2, 3, 0]


@pytest.mark.parametrize("text, code", [
    ("REPEAT NOWHERE P=2\nM30\n", "14080"),
    ("MARK: G0 X1\nREPEATB MARK P=0\nM30\n", "14770"),
    ("MARK: G0 X1\nREPEATB MARK OTHER\nM30\n", "syntax_error"),
])
def test_repeat_errors(text, code):
    with pytest.raises(tc.ProgramError) as e:
        run(text)
    assert e.value.code == code


def test_a_syntax_error_in_a_called_file_names_that_file(tmp_path):
    (tmp_path / "BAD.SPF").write_text("G1 X10 F100\nFOO 1 2 (\nM17\n")
    with pytest.raises(tc.ParseError) as e:
        run("G0 X0\nBAD\nM30\n", search_path=[tmp_path])
    assert e.value.line == 2 and e.value.file == str(tmp_path / "BAD.SPF")


MYSUB = """PROC MYSUB(REAL XP, INT N, VAR REAL OUT, BOOL FLAG) SAVE DISPLOF
DEF REAL KK
KK=XP*2
G1 X=KK Y=N F100
OUT=OUT+XP
IF FLAG
  G1 Z=-1
ENDIF
M17
"""


def run_proc(tmp_path, main):
    (tmp_path / "MYSUB.SPF").write_text(MYSUB)
    return run(main, search_path=[tmp_path])


def test_proc_parameters_by_value_and_by_reference(tmp_path):
    # XP 1.5 -> X 3; N 2.6 -> INT 3 (rounded); OUT is R5 itself: 10 + 1.5; FLAG 1: Z-1.
    res = run_proc(tmp_path, "G0 X0 Y0 Z0\nR5=10\nMYSUB(1.5, 2.6, R5, 1)\nG1 X=R5\nM30\n")
    np.testing.assert_allclose(res.nominal.end, [[0, 0, 0], [3, 3, 0], [3, 3, -1], [11.5, 3, -1]])


def test_omitted_value_parameters_are_zero_and_var_reaches_user_variables(tmp_path):
    res = run_proc(tmp_path, "DEF REAL TOT=3\nDEF REAL AA[3]\nG0 X0 Y0 Z0\nAA[2]=1\nMYSUB(1.5, , TOT)\nMYSUB(1, 2, AA[2])\n"
                             "G1 X=TOT Y=AA[2]\nM30\n")
    np.testing.assert_allclose(res.nominal.end, [[0, 0, 0], [3, 0, 0], [2, 2, 0], [4.5, 2, 0]])


def test_p_subpar_tells_a_given_parameter_from_an_omitted_one(tmp_path):
    # A cycle's idiom: an omitted DEPTH (0) takes 5, a DEPTH given as 0 stays 0.
    (tmp_path / "PECK.SPF").write_text("PROC PECK(REAL TOP, REAL DEPTH) SAVE\nIF NOT $P_SUBPAR[2]\nDEPTH=5\nENDIF\n"
                                       "G1 Z=TOP-DEPTH\nM17\n")
    res = run("G0 X0 Y0 Z10 F100\nPECK(2)\nPECK(2, 0)\nPECK(2, 1)\nM30\n", search_path=[tmp_path])
    assert [float(z) for z in res.nominal.end[1:, 2]] == [-3.0, 2.0, 1.0]
    for bad in ["R1=$P_SUBPAR[3]", "R1=$P_SUBPAR[0]"]:
        (tmp_path / "BAD.SPF").write_text(f"PROC BAD(REAL A, REAL B)\n{bad}\nM17\n")
        with pytest.raises(tc.ProgramError) as e:
            run("G0 X0\nBAD(1)\nM30\n", search_path=[tmp_path])
        assert e.value.code == "17020"


@pytest.mark.parametrize("call, code", [
    ("MYSUB(1.5, 2)", "14010"),            # VAR without its argument
    ("MYSUB(1.5, 2, 7)", "12320"),         # a constant for VAR
    ("MYSUB(1.5, 2, R1, 0, 9)", "12340"),  # five arguments for four parameters
    ("MYSUB(1.5, 2, II)", "12330"),        # an INT for VAR REAL
])
def test_proc_argument_alarms(tmp_path, call, code):
    with pytest.raises(tc.ProgramError) as e:
        run_proc(tmp_path, f"DEF INT II\nG0 X0\n{call}\nM30\n")
    assert e.value.code == code and e.value.line == 3


def test_proc_parameters_of_other_types_are_refused_by_name(tmp_path):
    (tmp_path / "FRSUB.SPF").write_text("PROC FRSUB(FRAME _F, REAL V)\nM17\n")
    with pytest.raises(tc.ProgramError) as e:
        run("G0 X0\nFRSUB(X, 1)\nM30\n", search_path=[tmp_path])
    assert e.value.code == "unsupported_word" and "FRAME _F" in e.value.message


def test_arrays_are_passed_whole_to_var_parameters(tmp_path):
    # SUMUP adds VALS[0..N-1] of the caller's A (1 + 2 + 3) and writes VALS[0]; INNER gets the
    # same array on, and BUMP one element of it.
    (tmp_path / "SUMUP.SPF").write_text("PROC SUMUP(VAR REAL VALS[3], VAR REAL TOTAL, INT N)\nDEF INT I\nTOTAL=0\n"
                                        "FOR I=0 TO N-1\nTOTAL=TOTAL+VALS[I]\nENDFOR\nVALS[0]=99\nINNER(VALS)\nM17\n")
    (tmp_path / "INNER.SPF").write_text("PROC INNER(VAR REAL W[,3])\nW[2]=W[0]+1\nBUMP(W[1])\nM17\n")
    (tmp_path / "BUMP.SPF").write_text("PROC BUMP(VAR REAL X1)\nX1=X1*10\nM17\n")
    res = run("DEF REAL A[3]\nDEF REAL T\nA[0]=1\nA[1]=2\nA[2]=3\nSUMUP(A, T, 3)\nG1 X=T Y=A[0] Z=A[2] F100\n"
              "G1 X=A[1]\nM30\n", search_path=[tmp_path])
    assert res.nominal.end.tolist() == [[6, 99, 100], [20, 99, 100]]
    for call, code in [("SUMUP(T, T, 1)", "12330"), ("SUMUP(A[1], T, 1)", "12320"), ("SUMUP(AI, T, 1)", "12330")]:
        with pytest.raises(tc.ProgramError) as e:
            run(f"DEF REAL A[3]\nDEF INT AI[3]\nDEF REAL T\n{call}\nM30\n", search_path=[tmp_path])
        assert e.value.code == code, call
    (tmp_path / "BAD.SPF").write_text("PROC BAD(REAL V[3])\nM17\n")
    with pytest.raises(tc.ProgramError) as e:
        run("DEF REAL A[3]\nBAD(A)\nM30\n", search_path=[tmp_path])
    assert e.value.code == "syntax_error" and "VAR" in e.value.message


def test_axis_variables_and_parameters_move_the_axis_they_name(tmp_path):
    # DRL(_AX, DEPTH): down the applicate of the plane ($P_AXN3: Z in G17, Y in G18) and to 5
    # on _AX; AX[Y]=IC(1) after a comparison with the axis X.
    (tmp_path / "DRL.SPF").write_text("PROC DRL(AXIS _AX, REAL DEPTH)\nDEF AXIS _Z\n_Z=$P_AXN3\n"
                                      "G1 AX[_Z]=-DEPTH AX[_AX]=5 F100\nIF _AX==X\nG1 AX[Y]=IC(1)\nENDIF\nM17\n")
    res = run('DEF AXIS Q1=AXNAME("Z")\nG0 X0 Y0 Z10\nDRL(X, 3)\nG18\nDRL(Z, 2)\nG1 AX[Q1]=7\nM30\n',
              search_path=[tmp_path])
    assert res.nominal.end.tolist() == [[0, 0, 10], [5, 0, -3], [5, 1, -3], [5, -2, 5], [5, -2, 7]]
    with pytest.raises(tc.ProgramError) as e:
        run("G0 X0\nDRL(, 3)\nM30\n", search_path=[tmp_path])
    assert e.value.code == "14010"
    with pytest.raises(tc.ProgramError) as e:
        run("G0 X0\nDRL(R1, 3)\nM30\n", search_path=[tmp_path])
    assert e.value.code == "12330"


@pytest.mark.parametrize("expr, value", [
    ("'B0101' B_AND 'B0011'", 1), ("'B0101' B_OR 'B0011'", 7), ("'B0101' B_XOR 'B0011'", 6), ("'H1F'", 31),
    ("'hff' B_AND 'B1111'", 15), ("B_NOT 'B0'", -1), ("'HFFFFFFFF'", -1),
])
def test_binary_and_hexadecimal_constants_with_bit_operations(expr, value):
    # 840D INT: 32-bit two's complement ('HFFFFFFFF' and B_NOT 0 are -1).
    assert xs(f"R1={expr}\nG1 X=R1 F100\nM30\n") == [value]


@pytest.mark.parametrize("expr", ["'B0102'", "'B" + "1" * 33 + "'", "'HG'", "'Q01'"])
def test_bad_constants_are_syntax_errors(expr):
    with pytest.raises(tc.ParseError) as e:
        run(f"R1={expr}\nM30\n")
    assert e.value.code == "syntax_error"


def test_define_as_macros_replace_their_names_in_the_lines_after_them():
    text = ("DEFINE DEPTH AS 5 ; the depth\nDEFINE DOWN AS G1 Z=-DEPTH\nG0 X0 Y0 Z0\nDOWN F100\n"
            "G1 X=DEPTH ; DEPTH in a comment stays\nMSG(\"DEPTH\")\nM30\n")
    res = run(text)
    np.testing.assert_allclose(res.nominal.end, [[0, 0, 0], [0, 0, -5], [5, 0, -5]])
    assert [d.message for d in res.diagnostics] == ["DEPTH"]  # nor in a string
    with pytest.raises(tc.ParseError) as e:
        run("DEFINE A1 AS 5\nDEFINE A1 AS 6\nM30\n")
    assert "12270" in e.value.message


def test_machine_data_read_from_the_machine_file_or_the_plain_840d():
    # Read: the plain 840D's inch scaling 25.4, metric system 1; a builder's datum from the
    # machine file; unknown: 12550 naming the machine file.
    text = "IF $MN_SCALING_SYSTEM_IS_METRIC == 1\nG1 X=$MN_SCALING_VALUE_INCH F100\nENDIF\nM30\n"
    assert xs(text) == [25.4]
    with pytest.raises(tc.ProgramError) as e:
        run("G1 X=$MC_MY_FLAG F100\nM30\n")
    assert e.value.code == "12550" and "[machine_data]" in e.value.message
    m = tc.Machine.parse('control = "sinumerik"\nkind = "mill"\n[machine_data]\n"$MC_MY_FLAG" = 7\n')
    assert run("G1 X=$MC_MY_FLAG F100\nM30\n", machine=m).nominal.end[-1, 0] == 7
    assert tc.Machine.parse(m.dumps()).machine_data == {"$MC_MY_FLAG": 7.0}


def test_indexed_machine_data_by_axis_name_or_number():
    # An axis index is written as the machine file keys it: "$MA_AX_VELO_LIMIT[X]"; a numeric
    # index from an expression reads the same key as the number written out.
    m = tc.Machine.parse('control = "sinumerik"\nkind = "mill"\n[machine_data]\n"$MA_POS_LIMIT_PLUS[Z]" = 5\n'
                         '"$MN_USER_DATA_INT[3]" = 7\n"$MA_POS_LIMIT_MINUS[1,X]" = -40\n')
    res = run("DEF INT N=3\nG1 X=$MN_USER_DATA_INT[N] Y=$MA_POS_LIMIT_MINUS[1, X] Z=$MA_POS_LIMIT_PLUS[Z] F100\n"
              "$SA_WORKAREA_PLUS[Y]=12\nG1 Y=$SA_WORKAREA_PLUS[Y]\nM30\n", machine=m)
    np.testing.assert_allclose(res.nominal.end, [[7, -40, 5], [7, 12, 5]])
    with pytest.raises(tc.ProgramError) as e:
        run("G1 X=$MA_POS_LIMIT_PLUS[Y] F100\nM30\n", machine=m)
    assert e.value.code == "12550" and "$MA_POS_LIMIT_PLUS[Y]" in e.value.message
    assert tc.Machine.parse(m.dumps()).machine_data == m.machine_data
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse('control = "sinumerik"\nkind = "mill"\n[machine_data]\n"$MA_A[x]" = 1\n')
    assert e.value.code == "machine_file" and "an index as [3], [X] or [1,Z]" in e.value.message


def test_machine_data_writes_are_not_made_and_setting_data_writes_are():
    # The 840D: "4075 machine data not changed due to missing permission level", the program
    # goes on with the old value; setting data are written.
    res = run("$MN_SCALING_VALUE_INCH=3\n$SC_THREAD_START_ANGLE=45\n"
              "G1 X=$SC_THREAD_START_ANGLE Y=$MN_SCALING_VALUE_INCH F100\nM30\n")
    np.testing.assert_allclose(res.nominal.end, [[45, 25.4, 0]])
    assert [(d.code, d.line) for d in res.diagnostics] == [("4075", 1)]


@pytest.mark.parametrize("text, what", [
    ('control = "fanuc"\nkind = "mill"\n[machine_data]\n"$MC_A" = 1\n', "Sinumerik"),
    ('control = "sinumerik"\nkind = "mill"\n[machine_data]\n"MC_A" = 1\n', "no machine or setting data name"),
    ('control = "sinumerik"\nkind = "mill"\n[machine_data]\n"$MC_A" = "x"\n', "must be a number"),
])
def test_machine_data_a_machine_file_cannot_declare(text, what):
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse(text)
    assert e.value.code == "machine_file" and what in e.value.message


@pytest.mark.parametrize("call", ['CALL "/_N_WKS_DIR/_N_PART_WPD/_N_SUBX_SPF"', 'CALL "SUBX"', "PCALL SUBX",
                                  'EXTCALL "SUBX"', 'CALL "../../elsewhere/subx.spf"'])
def test_call_by_path_finds_the_program_on_the_search_path(tmp_path, call):
    # The NC file system's name _N_SUBX_SPF is SUBX.SPF; only the search path is looked in.
    (tmp_path / "SUBX.SPF").write_text("G1 Y5 F100\nM17\n")
    assert run(f"G0 X0 Y0\n{call}\nM30\n", search_path=[tmp_path]).nominal.end[-1, 1] == 5


def moves(res):
    p = res.nominal
    return [(int(k), tuple(round(float(v), 6) for v in e), None if k == tc.RAPID else float(f))
            for k, e, f in zip(p.kind, p.end, p.feed)]


R_, L_ = tc.RAPID, tc.LINE


def test_mcall_cycle82_after_every_positioning_block_until_mcall_alone():
    # The SW6 cycle: G0 to RFP + SDIS = 2, G1 to DP = -12 at the caller's F150, dwell, G0 to
    # RTP = 10; N70 after MCALL alone moves without a cycle.
    res = run("N10 G17 G90 G54 G0 X0 Y0 Z50\nN20 F150 S1200 M3\nN30 MCALL CYCLE82(10, 0, 2, -12, , 0.5)\n"
              "N40 X10 Y10\nN50 X30\nN60 MCALL\nN70 X50 Y50\nM30\n")
    hole = lambda x, y: [(R_, (x, y, 2), None), (L_, (x, y, -12), 150.0), (R_, (x, y, 10), None)]
    assert moves(res) == ([(R_, (0, 0, 50), None), (R_, (10, 10, 50), None)] + hole(10, 10) + [(R_, (30, 10, 10), None)]
                          + hole(30, 10) + [(R_, (50, 50, 10), None)])


def test_cycle81_with_the_depth_relative_to_the_reference_plane():
    # DPR 12 below RFP 0 (RTP above it): DP = 0 - 12; in G18 the tool axis is Y.
    assert moves(run("G0 X0 Y0 Z50 F100\nCYCLE81(10,0,2,,12)\nM30\n"))[1:] == [
        (R_, (0, 0, 2), None), (L_, (0, 0, -12), 100.0), (R_, (0, 0, 10), None)]
    assert moves(run("G18 G0 X0 Y50 Z0 F100\nCYCLE81(10,0,2,-5)\nM30\n"))[1:] == [
        (R_, (0, 2, 0), None), (L_, (0, -5, 0), 100.0), (R_, (0, 10, 0), None)]


@pytest.mark.parametrize("call, code", [
    ("CYCLE81(10,0,2,5)", "61101"),       # the depth on the retraction side
    ("CYCLE81(0,0,2,,5)", "61101"),       # DPR with RTP = RFP
    ("MCALL MYSUB(1)", "unsupported_word"),
    ("CYCLE81(10,0,2,-5,0,1)", "unsupported_word"),  # GMODE 1
    ("CYCLE81(10,0,2,-5,0,0,0,10,4)", "12340"),
])
def test_drilling_cycle_errors(call, code):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0 Y0 Z50 F100\n{call}\nM30\n")
    assert e.value.code == code


def test_a_drilling_cycle_with_no_depth_makes_no_move():
    assert len(run("G0 X0 Y0 Z50 F100\nCYCLE81(10,0,2,0)\nM30\n").nominal) == 1


def test_holes1_runs_the_modal_cycle_along_a_row():
    # HOLES1(0,0,0,10,15,3): holes at X10, X25, X40 on Y0 (nearer end first), each: G0 there at
    # the tool's height, then CYCLE81(10,0,2,-5).
    res = run("G0 X0 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nHOLES1(0,0,0,10,15,3)\nMCALL\nM30\n")
    at = [(x, y) for k, (x, y, z), f in moves(res) if k == L_]
    assert at == [(10, 0), (25, 0), (40, 0)]
    # From the far end when it is nearer the workpiece zero: HOLES1(60,0,180,10,15,3).
    res = run("G0 X0 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nHOLES1(60,0,180,10,15,3)\nM30\n")
    assert [x for k, (x, y, z), f in moves(res) if k == L_] == [20, 35, 50]


def test_holes2_runs_the_modal_cycle_on_a_circle():
    res = run("G0 X0 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nHOLES2(50,50,20,0,0,4)\nMCALL\nM30\n")
    assert [(x, y) for k, (x, y, z), f in moves(res) if k == L_] == [(70, 50), (50, 70), (30, 50), (50, 30)]


def test_a_pattern_without_a_modal_call_only_positions_with_a_warning():
    res = run("G0 X0 Y0 Z50 F100\nHOLES1(0,0,0,10,15,2)\nM30\n")
    assert [e for k, e, f in moves(res)] == [(0, 0, 50), (10, 0, 50), (25, 0, 50)]
    assert [d.code for d in res.diagnostics] == ["62100"]
    with pytest.raises(tc.ProgramError) as e:
        run("G0 X0 Y0 Z50 F100\nHOLES1(0,0,0,10,15,0)\nM30\n")
    assert e.value.code == "61103"


def test_macros_of_macros_cannot_grow_without_bound():
    text = "DEFINE A0 AS XXXXXXXXXX\n" + "".join(f"DEFINE A{i} AS " + " ".join([f"A{i - 1}"] * 10) + "\n"
                                            for i in range(1, 8)) + "A7\nM30\n"
    with pytest.raises(tc.ParseError) as e:
        run(text)
    assert "longer than 65536 characters" in e.value.message


# ---- what real 840D programs carry (found running public programs) ---------------------------

def test_names_are_not_case_sensitive_in_proc_parameters_and_var_arguments(tmp_path):
    (tmp_path / "SUBV.SPF").write_text("PROC SUBV(real rStart, VAR REAL outV)\noutv = RSTART*2\nRET\n")
    res = run("DEF REAL Ypos\nSUBV(2, Ypos)\nG1 X=YPOS F100\nM30\n", search_path=[tmp_path])
    assert res.nominal.end[-1, 0] == 4


def test_a_call_whose_first_argument_is_a_string(tmp_path):
    (tmp_path / "SSUB.SPF").write_text("PROC SSUB(STRING[20] TXT, REAL A)\nG1 X=A+STRLEN(TXT) F100\nM17\n")
    assert run('SSUB("abc", 5)\nM30\n', search_path=[tmp_path]).nominal.end[-1, 0] == 8


def test_standard_cycles_are_refused_by_name_unless_a_program_of_that_name_is_given(tmp_path):
    for call in ['CYCLE95("CONT", 1, 0.2)', "CYCLE97(1,,0,-20)", "POCKET3(10,0,1,-5)", "LONGHOLE(1)"]:
        with pytest.raises(tc.ProgramError) as e:
            run(f"G0 X0\n{call}\nM30\n")
        assert e.value.code == "unsupported_word" and "standard cycle" in e.value.message
    (tmp_path / "CYCLE97.SPF").write_text("PROC CYCLE97(REAL A)\nG1 X=A F100\nM17\n")
    assert run("CYCLE97(7)\nM30\n", search_path=[tmp_path]).nominal.end[-1, 0] == 7


def test_editor_grouping_master_spindle_and_extern_declarations_run_without_motion():
    res = run('EXTERN SUBV(REAL, VAR REAL)\nGROUP_BEGIN(0,"ROUGH",0,0)\nSETMS(1)\nG1 X10 F100\nGROUP_END(0,0)\nM30\n')
    assert res.nominal.end.tolist() == [[10, 0, 0]]
    assert [d.code for d in res.diagnostics] == ["no_path_effect"] * 3


def test_lims_caps_the_spindle_speed_of_g96():
    # S200 m/min at radius 10: 200000 / (2 pi 10) = 3183.1 rev/min, capped at 2500: F0.1 mm/rev
    # is 250 mm/min; at radius 20 the speed 1591.5 is under the cap: 159.15 mm/min.
    res = run("G0 X10 Y0\nG96 S200 LIMS=2500 F0.1 M3\nG1 Y5\nG1 X20\nM30\n")
    np.testing.assert_allclose(res.nominal.feed[1:], [250.0, 0.1 * 200000 / (2 * np.pi * 20)])
    res = run("G0 X10 Y0\nG96 S200 F0.1 M3\nG1 Y5\nM30\n")
    np.testing.assert_allclose(res.nominal.feed[1:], [0.1 * 200000 / (2 * np.pi * 10)])


@pytest.mark.parametrize("line, word", [
    ("G1 X10 Y0 F100 RNDM=2", "RNDM"), ("G1 X20 ANG=45 F100", "ANG"),
    ("WHENEVER $A_IN[1]==1 DO $R1=0", "Synchronized actions"), ("WHEN $AA_IM[X]>5 DO M120", "Synchronized actions"),
])
def test_contour_definitions_and_synchronized_actions_are_refused_by_name(line, word):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0 Y0\n{line}\nM30\n")
    assert e.value.code == "unsupported_word" and word in e.value.message


@pytest.mark.parametrize("value, x", [(1, 1), (2, 2), (-3, 3), (7, 9)])
def test_case_jumps_to_the_branch_of_the_value_else_default(value, x):
    text = (f"R1={value}\nCASE R1 OF 1 GOTOF ONE 2 GOTOF TWO -3 GOTOF THREE DEFAULT GOTOF OTHER\n"
            "ONE:\nG1 X1 F100\nGOTOF END\nTWO:\nG1 X2 F100\nGOTOF END\nTHREE:\nG1 X3 F100\nGOTOF END\n"
            "OTHER:\nG1 X9 F100\nEND:\nM30\n")
    assert xs(text) == [x]
    # no branch and no DEFAULT: on with the next block
    assert xs("R1=5\nCASE R1 OF 1 GOTOF ONE\nG1 X4 F100\nONE:\nM30\n") == [4]


def test_g40_alone_after_a_circle_takes_effect_with_the_next_move():
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=2.0, length=[0.0, 0.0, 0.0])]))
    src = "G17 G90 T1 M6 D1\nG0 X-10 Y-10\nG41 G1 X0 Y0 F100\nG3 X10 Y10 CR=10\nG40\n{}\nM30\n"
    assert run(src.format("G1 X20 Y20"), tools=t).path.end[-1].tolist() == [20, 20, 0]
    with pytest.raises(tc.CompensationError) as e:  # the next move a circle: still 10754
        run(src.format("G2 X20 Y0 CR=10"), tools=t)
    assert e.value.code == "comp_exit_arc"


def test_rotary_axes_dc_acp_acn_reach_a_modulo_position():
    # From C350: DC(10) the short way +20 (370); DC(200) from 10: -170 (200); ACP(190) from 200
    # turning positively: +350 (550); ACN(200) from 190: -350 (200); half a turn: the positive way.
    res = run("G0 X0 C350\nG0 C=DC(10)\nG0 C=DC(200)\nG0 C=ACP(190)\nG0 C=ACN(200)\nG0 A=DC(180)\nM30\n")
    assert res.nominal.abc[:, 2].tolist() == [350, 370, 200, 550, 200, 200]
    assert res.nominal.abc[-1, 0] == 180
    with pytest.raises(tc.ProgramError) as e:
        run("G0 C=DC(360)\nM30\n")
    assert e.value.code == "16830"
    with pytest.raises(tc.ParseError) as e:
        run("G0 X=DC(10)\nM30\n")
    assert e.value.code == "unsupported_word" and "rotary axes" in e.value.message


def test_a_proc_run_as_the_main_program_takes_its_parameters_as_omitted():
    # Selected on its own (not called), a PROC's parameters hold 0 / "" (VAR ones as locals).
    res = run('PROC CHAMF(REAL rStart, VAR REAL OUT, STRING[5] S)\nG1 X=rStart+1 F100\nOUT=2\nG1 Y=OUT Z=STRLEN(S)\nM17\n')
    assert res.nominal.end.tolist() == [[1, 0, 0], [1, 2, 0]]
