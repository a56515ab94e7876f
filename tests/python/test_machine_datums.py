"""Machine positions and travel on the Sinumerik and the Heidenhain: the work origin, G53 /
SUPA and M91 / M92 moves in machine coordinates, the tool change position, the axis travel.
Every expected number is worked by hand from the machine file and the tool length."""
import numpy as np
import pytest

import toolcomp as tc


def _tools(*lengths):
    t = tc.ToolTable()
    for n, length in enumerate(lengths, start=1):
        t.set(tc.Tool(n, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, length])]))
    return t


def _machine(control, kind="mill", **fields):
    m = tc.Machine(control, kind, "test")
    for k, v in fields.items():
        setattr(m, k, v)
    return m


# ---- Heidenhain: M91, M92 -------------------------------------------------------------------

# The preset (program zero) at machine (-300, -200, -400); the additional machine datum at
# machine (-50, -10, -20); tool 1 100 mm long, tool 2 50 mm.
KLARTEXT = """\
0 BEGIN PGM DATUMS MM
1 TOOL DEF 1 L+100 R+5
2 TOOL DEF 2 L+50 R+3
3 TOOL CALL 1 Z S3000
4 L Z+5 R0 FMAX
5 L X+10 Y+20 R0 FMAX
6 L Z-1 R0 FMAX M91
7 L X-50 Y-10 R0 FMAX M92
8 L IX+5 R0 FMAX M91
9 END PGM DATUMS MM
"""


def _tnc(**fields):
    return _machine("heidenhain", work_origin=(-300.0, -200.0, -400.0), m92=(-50.0, -10.0, -20.0), **fields)


def test_m91_and_m92_positions_are_the_spindles_from_the_machine_datums():
    res = tc.run(tc.Program.parse(KLARTEXT, dialect="heidenhain"), machine=_tnc())
    assert res.ok
    # The run starts with the spindle at the machine's zero, program (300, 200, 400); TOOL CALL
    # 1 keeps the spindle there, so the tip of the 100 mm tool starts at program Z 300.
    np.testing.assert_allclose(res.nominal.start[0], [300, 200, 300])
    # (Block n is line n + 1 of the file.)
    np.testing.assert_allclose(res.nominal.end, [
        [300, 200, 5],
        [10, 20, 5],
        # M91 Z-1: the spindle at machine Z-1, the tool length not compensated: the tip at
        # -1 - (-400) - 100 = 299.
        [10, 20, 299],
        # M92 X-50 Y-10 from the datum at machine (-50, -10): machine X-100 Y-20, program
        # X -100 + 300 = 200, Y -20 + 200 = 180.
        [200, 180, 299],
        # IX+5 moves by 5 whatever the datum.
        [205, 180, 299],
    ], atol=1e-12)
    assert list(res.nominal.line) == [5, 6, 7, 8, 9]


def test_without_a_machine_m91_is_measured_from_program_zero():
    res = tc.run(tc.Program.parse(KLARTEXT, dialect="heidenhain"), start="machine_zero")
    # Machine zero at program zero: M91 Z-1 puts the tip at -1 - 100 = -101; M92's datum is
    # the machine's zero too.
    np.testing.assert_allclose(res.nominal.end[2], [10, 20, -101])
    np.testing.assert_allclose(res.nominal.end[3], [-50, -10, -101])


def test_m91_acts_in_l_blocks_only():
    text = KLARTEXT.replace("6 L Z-1 R0 FMAX M91", "6 STOP M91")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="heidenhain"), machine=_tnc())
    assert (e.value.code, e.value.line) == ("bad_word", 7)
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(KLARTEXT.replace("M92", "M91 M92"), dialect="heidenhain"), machine=_tnc())
    assert (e.value.code, e.value.line) == ("bad_word", 8)


def test_tool_call_goes_to_the_tool_change_position_first():
    # Tool change position: machine Z0. At TOOL CALL 2 the spindle goes to machine Z0 with tool
    # 1 in it: the tip at 0 - (-400) - 100 = 300; then L Z+10 with tool 2.
    text = KLARTEXT.replace("9 END PGM", "9 TOOL CALL 2 Z\n10 L Z+10 R0 FMAX\n11 END PGM")
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"), machine=_tnc(tool_change=(None, None, 0.0)))
    np.testing.assert_allclose(res.nominal.end[-2:], [[205, 180, 300], [205, 180, 10]], atol=1e-12)
    assert list(res.nominal.line[-2:]) == [10, 11] and res.nominal.kind[-2] == tc.RAPID


def test_a_klartext_move_beyond_the_travel_is_an_error_at_its_block():
    # X travel [-500, 0]: program X+300 is machine X0 (allowed), X+301 is machine X1.
    m = _tnc(travel=((-500.0, 0.0), (-400.0, 0.0), (-450.0, 0.0)))
    ok = KLARTEXT.replace("9 END PGM", "9 L X+300 R0 FMAX\n10 END PGM")
    assert tc.run(tc.Program.parse(ok, dialect="heidenhain"), machine=m).ok
    bad = KLARTEXT.replace("9 END PGM", "9 L X+301 R0 FMAX\n10 END PGM")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(bad, dialect="heidenhain"), machine=m)
    assert (e.value.code, e.value.line) == ("travel_limit", 10)
    assert "X 1.0000 mm" in e.value.message
    # The tool length counts: L Z+5 with the 100 mm tool puts the spindle at machine
    # 5 + 100 - 400 = -295; Z-60 at -360, inside -450; Z-151 at -451, beyond.
    deep = KLARTEXT.replace("9 END PGM", "9 L Z-151 R0 F500\n10 END PGM")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(deep, dialect="heidenhain"), machine=m)
    assert (e.value.code, e.value.line) == ("travel_limit", 10)


def test_a_klartext_arc_that_bulges_beyond_the_travel_is_caught_as_a_warning():
    # CC X+290 Y+20, C from (290, 0) to (290, 40) DR+: counter-clockwise through X+310
    # (machine X10) while its ends lie at machine X-10.
    m = _tnc(travel=((-500.0, 0.0), (-400.0, 0.0), (-450.0, 0.0)), travel_limit_warning=True)
    text = KLARTEXT.replace("9 END PGM", "9 L X+290 Y+0 R0 FMAX\n10 CC X+290 Y+20\n11 C X+290 Y+40 DR+ F500\n12 END PGM")
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"), machine=m)
    assert [(d.code, d.line, d.severity) for d in res.diagnostics] == [("travel_limit", 12, "warning")]
    clockwise = text.replace("DR+", "DR-")
    assert tc.run(tc.Program.parse(clockwise, dialect="heidenhain"), machine=m).diagnostics == []


def test_m92_round_trips_in_a_machine_file(tmp_path):
    m = _tnc()
    m.write(tmp_path / "tnc.toml")
    back = tc.Machine.read(tmp_path / "tnc.toml")
    assert back.m92 == [-50.0, -10.0, -20.0] and back.work_origin == [-300.0, -200.0, -400.0]
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse('control = "heidenhain"\nkind = "mill"\n[positions]\nm92 = [0, 0]\n')
    assert (e.value.code, e.value.line) == ("machine_file", 4)


# ---- Sinumerik: G53 / SUPA, tool change position, travel ------------------------------------

# The work origin at machine (-400, -200, -500); T1 100 mm long, T2 50 mm.
MPF = """\
G54 G90 G0 X10 Y10
T1 M6
D1 Z5
G1 Z-1 F100
G53 G0 Z0
SUPA G0 Z0 D0
M30
"""


def _sinumerik(**fields):
    return _machine("sinumerik", work_origin=(-400.0, -200.0, -500.0), **fields)


def test_sinumerik_g53_keeps_the_tool_offset_and_d0_takes_it_away():
    res = tc.run(tc.Program.parse(MPF, dialect="sinumerik"), tools=_tools(100, 50), machine=_sinumerik())
    assert res.ok
    np.testing.assert_allclose(res.nominal.start[0], [400, 200, 500])  # the machine's zero
    # G53 Z0: the tool tip (the offset stays active) at machine Z0: program Z 0 - (-500) = 500,
    # the spindle 100 mm above. SUPA Z0 D0: no tool offset, the spindle at machine Z0: the
    # same program Z, the tool offset gone (a move of the spindle alone).
    np.testing.assert_allclose(res.nominal.end, [[10, 10, 500], [10, 10, 5], [10, 10, -1], [10, 10, 500],
                                                 [10, 10, 500]], atol=1e-12)
    np.testing.assert_allclose(res.nominal.tool_offset[-1], [0, 0, 0])
    np.testing.assert_allclose(res.nominal.tool_offset[-2], [0, 0, 100])


def test_sinumerik_m6_goes_to_the_tool_change_position_with_the_old_tool():
    # At T2 M6 the tip is at Z-1 with T1: the spindle goes to machine Z0, the tip to
    # 0 - 100 - (-500) = 400.
    text = MPF.replace("G53 G0 Z0\n", "T2 M6\nD1 Z20\n")
    res = tc.run(tc.Program.parse(text, dialect="sinumerik"), tools=_tools(100, 50),
                 machine=_sinumerik(tool_change=(None, None, 0.0)))
    np.testing.assert_allclose(res.nominal.end[3:5], [[10, 10, 400], [10, 10, 20]], atol=1e-12)
    assert list(res.nominal.line[3:5]) == [5, 6]


def test_sinumerik_travel_counts_the_tool_offset():
    # Z travel [-600, 0]: G53 Z0 with D1 puts the spindle at machine Z+100: beyond; with D0 not.
    m = _sinumerik(travel=((-800.0, 0.0), (-500.0, 0.0), (-600.0, 0.0)))
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(MPF, dialect="sinumerik"), tools=_tools(100, 50), machine=m)
    assert (e.value.code, e.value.line) == ("travel_limit", 5)
    assert "Z 100.0000 mm" in e.value.message
    ok = MPF.replace("G53 G0 Z0\n", "")
    assert tc.run(tc.Program.parse(ok, dialect="sinumerik"), tools=_tools(100, 50), machine=m).ok


def test_sinumerik_lathe_travel_is_a_diameter():
    # X travel [0, 300] as a diameter: DIAMON X290 is diameter 290 (inside), X310 beyond.
    m = _machine("sinumerik", "lathe", travel=((0.0, 300.0), (-1.0, 1.0), (-800.0, 800.0)))
    ok = "DIAMON G18 G90 G0 X290 Z10\nM30\n"
    assert tc.run(tc.Program.parse(ok, dialect="sinumerik"), machine=m).ok
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(ok.replace("X290", "X310"), dialect="sinumerik"), machine=m)
    assert (e.value.code, e.value.line) == ("travel_limit", 1)
    assert "X 310.0000 mm" in e.value.message


def test_without_a_machine_m91_and_m92_are_measured_from_the_preset():
    # The plain machine: its zero and the M92 datum at the preset. The spindle at Z+0 puts the
    # tip of the 100 mm tool at Z-100; M92 X+10 at X+10.
    res = tc.run(tc.Program.parse(KLARTEXT.replace("6 L Z-1", "6 L Z+0").replace("7 L X-50 Y-10", "7 L X+10 Y-10"),
                                  dialect="heidenhain"), start="machine_zero")
    np.testing.assert_allclose(res.nominal.end[2:4], [[10, 20, -100], [10, -10, -100]])


def test_builder_cycles_declared_in_the_machine_file_run_without_moving():
    # DMG's CYCL DEF 392 ATC (a dynamics setting): refused on the plain TNC, accepted where
    # the machine declares it; its Q parameters become the program's.
    text = ("0 BEGIN PGM A MM\n1 CYCL DEF 392 ATC ~\n    Q240=+1 ;MODE ~\n    Q241=+2 ;LEVEL\n"
            "2 L X+Q241 Y+0 Z+0 R0 FMAX\n3 END PGM A MM\n")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="heidenhain"), start="machine_zero")
    assert e.value.code == "unsupported_block" and "CYCL DEF 392 ATC" in e.value.message
    m = tc.Machine.parse('control = "heidenhain"\nkind = "mill"\n[cycles]\n392 = { action = "nothing", name = "ATC" }\n')
    assert m.cycles[392].name == "ATC"
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"), machine=m)
    np.testing.assert_allclose(res.nominal.end, [[2, 0, 0]])
    again = tc.Machine.parse(m.dumps())
    assert again.cycles[392].name == "ATC"


@pytest.mark.parametrize("text, what", [
    ('control = "fanuc"\nkind = "mill"\n[cycles]\n392 = "nothing"\n', "Heidenhain"),
    ('control = "heidenhain"\nkind = "mill"\n[cycles]\n200 = "nothing"\n', "TNC itself"),
    ('control = "heidenhain"\nkind = "mill"\n[cycles]\n392 = "coolant_on"\n', "nothing"),
])
def test_builder_cycles_that_a_machine_file_cannot_declare(text, what):
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse(text)
    assert e.value.code == "machine_file" and what in e.value.message


def test_sysread_240_reads_the_machine_position_an_m91_block_programs():
    # Program Z+5 with the 100 mm tool, the preset at machine Z-400: the spindle at machine
    # Z 5 - 400 + 100 = -295; X 10 - 300 = -290 under a datum shift of X+10 (program X0).
    text = ("0 BEGIN PGM S MM\n1 TOOL DEF 1 L+100 R+5\n2 TOOL CALL 1 Z S3000\n3 CYCL DEF 7.0 DATUM SHIFT\n"
            "4 CYCL DEF 7.1 X+10\n5 L X+0 Y+0 Z+5 R0 FMAX\n6 FN 18: SYSREAD Q1 = ID240 NR1 IDX3\n"
            "7 FN 18: SYSREAD Q2 = ID240 NR1 IDX1\n8 L X+Q2 Z+Q1 R0 FMAX M91\n9 L X+Q2 Y+Q1 R0 FMAX\n"
            "10 END PGM S MM\n")
    res = tc.run(tc.Program.parse(text, dialect="heidenhain"), machine=_tnc())
    assert len(res.nominal) == 2  # the M91 block (line 9) stays where it is
    assert 9 not in res.nominal.line
    # The values themselves, as program coordinates: X -290 (+10 shift), Y -295.
    np.testing.assert_allclose(res.nominal.end[-1], [-280, -295, 5])
