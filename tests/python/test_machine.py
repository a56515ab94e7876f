"""Machines as data (tc.Machine): builder M codes, work origin, G53, tool change position,
travel limits, machine files (TOML) read, written and refused with their line, presets."""
import math
import pathlib

import numpy as np
import pytest

import toolcomp as tc

HAAS = """%
O1001 (HAAS MILL, AS A CAM POST WRITES IT)
G20 G17 G40 G49 G80 G90
T1 M06
G00 G90 G54 X0. Y0. S1000 M03
G43 H01 Z1.0 M08
M31
G01 Z-0.1 F10.
X1.0
M59 P1133
G00 Z1.0 M09
M33
G53 G49 Z0.
M30
%
"""


def _tools(length=100.0):
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=3.0, length=[0.0, 0.0, length])]))
    return t


def _machine(**fields):
    m = tc.Machine("fanuc", "mill", "test")
    for k, v in fields.items():
        setattr(m, k, v)
    return m


# ---- builder M codes ---------------------------------------------------------------------

def test_a_haas_program_runs_on_haas_mill_and_is_refused_on_plain_fanuc():
    prog = tc.Program.parse(HAAS, dialect="fanuc")
    with pytest.raises(tc.ProgramError) as e:
        tc.run(prog, tools=_tools())
    assert (e.value.code, e.value.line) == ("unknown_m_code", 7)  # M31, the chip conveyor
    res = tc.run(prog, tools=_tools(), machine="haas-mill")
    assert res.ok, res.diagnostics
    # inch program: Z1.0 = 25.4 mm, Z-0.1 = -2.54 mm, X1.0 = 25.4 mm; G53 Z0 with G49 and the
    # work origin at machine zero: program Z0.
    np.testing.assert_allclose(res.nominal.end, [[0, 0, 0], [0, 0, 25.4], [0, 0, -2.54], [25.4, 0, -2.54],
                                                 [25.4, 0, 25.4], [25.4, 0, 0]], atol=1e-12)


def test_a_code_the_machine_does_not_declare_stays_an_error():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G0 X0\nM97 P100\nM30\n", dialect="fanuc"), machine="haas-mill")
    assert (e.value.code, e.value.line) == ("unknown_m_code", 2)


def test_a_builder_code_acts_like_the_standard_code_of_its_action():
    # M88 (through-spindle coolant) declared coolant_on stands for M8: M8 in the same block
    # is two codes of one group, as M8 M8 would be.
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G0 X0\nM88 M8\nM30\n", dialect="fanuc"), machine="haas-mill")
    assert e.value.code == "modal_group_conflict"
    # M16 declared tool_change is M6: the prepared tool goes into the spindle.
    res = tc.run(tc.Program.parse("G21 T1 M16\nG43 H1 G0 Z5\nM30\n", dialect="fanuc"), tools=_tools(40),
                 machine="haas-mill")
    assert res.nominal.tool[-1] == 1 and res.nominal.tool_offset[-1, 2] == 40


def test_words_a_builder_code_reads_leave_the_block():
    # M59 P1133 (Haas: set output relay 1133): without the machine P is an unused word.
    text = "G21 G0 X0\nM59 P1133\nM30\n"
    with pytest.raises(tc.Error):
        tc.run(tc.Program.parse(text, dialect="fanuc"), machine=_machine(m_codes={59: tc.MachineCode("nothing")}))
    tc.run(tc.Program.parse(text, dialect="fanuc"), machine="haas-mill")


def test_codes_the_control_fixes_cannot_be_declared():
    m = tc.Machine("fanuc")
    for n in (0, 1, 2, 30, 98, 99):
        with pytest.raises(ValueError, match=f"M{n} cannot be declared"):
            m.m_codes = {n: tc.MachineCode("nothing")}
    with pytest.raises(ValueError, match="unknown M code action"):
        tc.MachineCode("coffee")


def test_sinumerik_and_heidenhain_take_builder_codes_too():
    m = tc.Machine("sinumerik", "mill", "dmg")
    m.m_codes = {206: tc.MachineCode("tool_change", "tool change")}
    t = _tools(50)
    res = tc.run(tc.Program.parse("T1 M206\nD1 G0 Z10\nM30\n", dialect="sinumerik"), tools=t, machine=m)
    assert res.nominal.tool[-1] == 1 and res.nominal.tool_offset[-1, 2] == 50
    h = tc.Machine("heidenhain", "mill", "dmu")
    h.m_codes = {25: tc.MachineCode("nothing")}  # a code the TNC itself does not run in toolcomp
    text = "0 BEGIN PGM A MM\n1 L X+10 R0 FMAX M25\n2 END PGM A MM\n"
    with pytest.raises(tc.Error):
        tc.run(tc.Program.parse(text, dialect="heidenhain"))
    assert tc.run(tc.Program.parse(text, dialect="heidenhain"), machine=h).ok


def test_the_machine_control_must_be_the_programs():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G0 X1\nM2\n", dialect="linuxcnc"), machine="haas-mill")
    assert e.value.code == "machine_control"


# ---- positions -----------------------------------------------------------------------------

def test_g53_z0_lands_at_machine_z0_in_program_coordinates():
    # Program zero (G54) at machine (-400, -200, -500); tool length 100: G53 Z0 puts the spindle
    # at machine Z0, the tool tip at program Z = 0 - (-500) - 100 = 400.
    m = _machine(work_origin=(-400.0, -200.0, -500.0))
    text = "G21 G90 G54 G0 X10 Y10\nG43 H1 Z5\nG1 Z-1 F100\nG53 G0 Z0\nM30\n"
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), tools=_tools(100), machine=m)
    np.testing.assert_allclose(res.nominal.end[-1], [10, 10, 400])
    # The run starts with the machine at its zero: program (400, 200, 500).
    np.testing.assert_allclose(res.nominal.start[0], [400, 200, 500])


def test_a_var_file_wins_over_the_machine_origin():
    m = _machine(work_origin=(-400.0, -200.0, -500.0))
    text = "G21 G90 G54 G53 G0 Z0\nM2\n"
    res = tc.run(tc.Program.parse(text, dialect="linuxcnc"), machine=tc.Machine("linuxcnc"),
                 parameters={5223: -300.0})
    assert res.nominal.end[-1, 2] == 300
    lin = tc.Machine("linuxcnc")
    lin.work_origin = (-400.0, -200.0, -500.0)
    res = tc.run(tc.Program.parse(text, dialect="linuxcnc"), machine=lin, parameters={5223: -300.0})
    assert res.nominal.end[-1, 2] == 300
    res = tc.run(tc.Program.parse(text, dialect="linuxcnc"), machine=lin)
    assert res.nominal.end[-1, 2] == 500


def test_g28_goes_to_the_machines_position():
    m = _machine(g28=(-100.0, -50.0, 0.0), work_origin=(-400.0, -200.0, -500.0))
    res = tc.run(tc.Program.parse("G21 G90 G0 X0 Y0 Z10\nG28\nM30\n", dialect="fanuc"), machine=m)
    np.testing.assert_allclose(res.nominal.end[-1], [300, 150, 500])  # machine - origin


def test_m6_goes_to_the_tool_change_position_first():
    # Tool change at machine Z0 (work origin Z -500): from program Z5 with tool 1 (length 100)
    # the spindle rises to Z = 0 + 500 - 100 = 400 before the change; X and Y stay.
    m = _machine(work_origin=(0.0, 0.0, -500.0), tool_change=(None, None, 0.0))
    text = "G21 G90 T1 M6\nG43 H1 G0 X10 Y20 Z5\nT1 M6\nM30\n"
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), tools=_tools(100), machine=m)
    np.testing.assert_allclose(res.nominal.end[-1], [10, 20, 400])
    assert res.nominal.kind[-1] == tc.RAPID and res.nominal.line[-1] == 3


# ---- travel limits -------------------------------------------------------------------------

def _travel_machine(warning=False):
    # A VF-2's travel: X 762, Y 406, Z 508 below the machine zero; program zero at
    # machine (-600, -300, -400).
    return _machine(work_origin=(-600.0, -300.0, -400.0), travel=((-762.0, 0.0), (-406.0, 0.0), (-508.0, 0.0)),
                    travel_limit_warning=warning)


def test_a_move_beyond_the_travel_is_an_error_at_its_line():
    text = "G21 G90 G0 X0 Y0 Z10\nG1 Z-50 F100\nX600\nX601\nM30\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), machine=_travel_machine())
    # X600 is machine X0 (the limit, allowed); X601 is machine X1.
    assert (e.value.code, e.value.line) == ("travel_limit", 4)
    assert "X 1.0000 mm" in e.value.message
    with pytest.raises(tc.ProgramError) as e:  # Z-150 is machine Z-550, below -508
        tc.run(tc.Program.parse("G21 G90 G0 X0 Y0 Z10\nG1 Z-150 F100\nM30\n", dialect="fanuc"),
               machine=_travel_machine())
    assert (e.value.code, e.value.line) == ("travel_limit", 2)


def test_an_arc_that_bulges_beyond_the_travel_is_caught():
    # From (590, 0) G3 to (590, 40) about (590, 20): the arc reaches program X610 (machine
    # X10, beyond 0) at its middle while both ends (machine X-10) are inside.
    text = "G21 G90 G0 X590 Y0 Z10\nG3 X590 Y40 I0 J20 F100\nM30\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), machine=_travel_machine())
    assert (e.value.code, e.value.line) == ("travel_limit", 2)
    ok = "G21 G90 G0 X590 Y0 Z10\nG2 X590 Y40 I0 J20 F100\nM30\n"  # the other way round: inside
    assert tc.run(tc.Program.parse(ok, dialect="fanuc"), machine=_travel_machine()).ok


def test_the_tool_length_counts_in_the_travel():
    # Tool 100 long at program Z10: the spindle at machine Z = 10 - 400 + 100 = -290;
    # G1 Z-250: machine Z -540, beyond -508.
    text = "G21 G90 T1 M6\nG43 H1 G0 X0 Y0 Z10\nG1 Z-200 F100\nZ-250\nM30\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), tools=_tools(100), machine=_travel_machine())
    assert (e.value.code, e.value.line) == ("travel_limit", 4)


def test_travel_warnings_let_the_run_go_on():
    text = "G21 G90 G0 X0 Y0 Z10\nX601\nX0\nM30\n"
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), machine=_travel_machine(warning=True))
    warnings = [d for d in res.diagnostics if d.code == "travel_limit"]
    assert [w.line for w in warnings] == [2] and warnings[0].severity == "warning"
    assert len(res.nominal) == 3


# ---- files ----------------------------------------------------------------------------------

FILE = """\
name = "VF-2 cell 3"
control = "fanuc"
kind = "mill"
units = "inch"

[profile]
call_depth_limit = 4
[profile.radius]
corner_limit = 1.0

[m_codes]
31 = { action = "nothing", name = "chip conveyor forward" }
M59 = { action = "nothing", words = "p" }
88 = "coolant_on"

[positions]
work_origin = [-10.0, -5.0, -20.0]
tool_change = { z = 0 }

[travel]
x = [-30, 0]
z = [-20, 0]
limit = "warning"

[rates]
rapid = [1000, 1000, 1000]
max_feed = [650, 650, 650]
"""


def test_a_machine_file_is_read_in_its_units(tmp_path):
    (tmp_path / "vf2.toml").write_text(FILE)
    m = tc.Machine.read(tmp_path / "vf2.toml")
    assert (m.name, m.control, m.kind) == ("VF-2 cell 3", "fanuc", tc.MachineKind.mill)
    assert m.profile.call_depth_limit == 4 and m.profile.radius.corner_limit == 1.0
    assert m.m_codes[59] == tc.MachineCode("nothing", "", "P")
    assert m.m_codes[88].action == "coolant_on"
    assert m.work_origin == pytest.approx((-254.0, -127.0, -508.0))
    assert list(m.tool_change) == [None, None, 0.0]
    assert m.travel[0] == pytest.approx((-762.0, 0.0)) and m.travel[1] == (-math.inf, math.inf)
    assert m.travel_limit_warning
    assert m.rapid_rate == pytest.approx((25400.0,) * 3) and m.max_feed == pytest.approx((16510.0,) * 3)


def test_machine_files_round_trip(tmp_path):
    (tmp_path / "vf2.toml").write_text(FILE)
    m = tc.Machine.read(tmp_path / "vf2.toml")
    m.write(tmp_path / "copy.toml")
    back = tc.Machine.read(tmp_path / "copy.toml")
    assert back.dumps() == m.dumps()
    for field in ("name", "control", "kind", "m_codes", "work_origin", "g28", "g30", "tool_change", "travel",
                  "travel_limit_warning", "rapid_rate", "max_feed"):
        assert getattr(back, field) == getattr(m, field), field
    assert back.profile.call_depth_limit == 4 and back.profile.radius.corner_limit == 1.0
    for name in tc.Machine.presets():
        p = tc.Machine.preset(name)
        assert tc.Machine.parse(p.dumps()).dumps() == p.dumps(), name


@pytest.mark.parametrize("change, line, what", [
    (('control = "fanuc"', 'control = "haas"'), 2, "control must be one of"),
    (('kind = "mill"', 'kind = "router"'), 3, "kind must be"),
    (("call_depth_limit = 4", "call_depth_limt = 4"), 7, "no field 'call_depth_limt'"),
    (("call_depth_limit = 4", "call_depth_limit = 100000"), 7, "at most 10000"),
    (("corner_limit = 1.0", "corner_limit = \"wide\""), 9, "corner_limit"),
    (('88 = "coolant_on"', '88 = "coolant_please"'), 14, "unknown M code action"),
    (('88 = "coolant_on"', '30 = "nothing"'), 14, "M30"),
    (('88 = "coolant_on"', 'M8x = "nothing"'), 14, "no M code number"),
    (("work_origin = [-10.0, -5.0, -20.0]", "work_origin = [-10.0, -5.0]"), 17, "[x, y, z]"),
    (("x = [-30, 0]", "x = [0, -30]"), 21, "min 0 is above max -30"),
    (('limit = "warning"', 'limit = "maybe"'), 23, "'error' or 'warning'"),
    (("rapid = [1000, 1000, 1000]", "rapid = [1000, -1, 1000]"), 26, "must not be negative"),
    (("[rates]", "[rate]"), 25, "unknown key 'rate'"),
    (("units = \"inch\"", "units = inch"), 4, "not TOML"),
])
def test_bad_machine_files_name_their_line(tmp_path, change, line, what):
    text = FILE.replace(*change)
    assert text != FILE
    (tmp_path / "bad.toml").write_text(text)
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.read(tmp_path / "bad.toml")
    assert e.value.code == "machine_file" and e.value.line == line, (e.value, e.value.line)
    assert what in e.value.message and "bad.toml" in e.value.message


def test_presets():
    names = tc.Machine.presets()
    for n in ("haas-mill", "haas-lathe", "linuxcnc", "fanuc-mill", "fanuc-lathe", "sinumerik-mill", "heidenhain",
              "rockwell"):
        assert n in names
    lathe = tc.Machine.preset("haas-lathe")
    assert lathe.kind == tc.MachineKind.lathe and lathe.profile.x_diameter and 21 in lathe.m_codes
    mill = tc.Machine.preset("haas-mill")
    assert list(mill.tool_change) == [None, None, 0.0] and mill.m_codes[13].action == "nothing"  # a brake, not M3+M8
    with pytest.raises(ValueError, match="no machine preset"):
        tc.Machine.preset("haas")


def test_a_haas_lathe_program_with_the_tailstock():
    text = ("G20 G18 G40 G99\nT0101 M21\nG50 S3000\nG97 S1000 M03\nG00 X1.0 Z0.1 M08\nG01 Z-1.0 F0.01\n"
            "G00 X1.2 M09\nM22\nM31\nM30\n").replace("G50 S3000\n", "")
    tools = tc.ToolTable.parse("offset,x,z,nose_radius,tip\n1,0,0,0.4,3\n", "csv")
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), tools=tools, machine="haas-lathe")
    assert res.ok
    np.testing.assert_allclose(res.nominal.end[-1, [0, 2]], [0.6 * 25.4, -25.4])  # X1.2 diameter
    with pytest.raises(tc.ProgramError):
        tc.run(tc.Program.parse(text, dialect="fanuc"), tools=tools, machine="fanuc-lathe")


def test_run_iter_run_and_run_many_take_a_machine_by_name_or_file(tmp_path):
    (tmp_path / "vf2.toml").write_text(FILE)
    prog = tc.Program.parse(HAAS.replace("M33\n", ""), dialect="fanuc")  # vf2.toml has no M33
    for machine in ("haas-mill", tmp_path / "vf2.toml", str(tmp_path / "vf2.toml"), tc.Machine.preset("haas-mill")):
        chunks = list(tc.iter_run(prog, tools=_tools(), machine=machine))
        assert sum(len(c) for c in chunks) >= 6
    results = tc.run_many([prog, prog], tools=_tools(), machine="haas-mill")
    assert all(r.ok for r in results)
    with pytest.raises(TypeError):
        tc.run(prog, machine=42)


def test_the_mill_lathe_shorthand_still_works():
    text = "G21 G18 G98 G0 X50 Z0\nG1 X40 F100\nM30\n"
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), machine="lathe")
    assert res.nominal.end[-1, 0] == 20  # X diameter on the lathe
    assert tc.ControlProfile("fanuc", machine="lathe").kind == tc.MachineKind.lathe
    assert tc.ControlProfile("fanuc", kind="lathe").machine == tc.MachineKind.lathe


def test_a_builder_code_that_runs_a_subprogram(tmp_path):
    # LinuxCNC: a remap of M250 to the O-word sub probe_tip (probe_tip.ngc on the search path);
    # Fanuc: a macro M code running O9020. Both lift Z by 5 (G91) after their block.
    (tmp_path / "probe_tip.ngc").write_text("o<probe_tip> sub\nG91 G0 Z5\nG90\no<probe_tip> endsub\nM2\n")
    (tmp_path / "O9020.nc").write_text("O9020\nG91 G0 Z5\nG90\nM99\n")
    lin = tc.Machine.parse('control = "linuxcnc"\n[m_codes]\n250 = { action = "subprogram", program = "probe_tip" }\n')
    fan = tc.Machine.parse('control = "fanuc"\n[m_codes]\nM80 = { action = "subprogram", program = "O9020" }\n')
    for machine, dialect, text in ((lin, "linuxcnc", "G21 G0 X1 Z0\nM250\nG0 X2\nM2\n"),
                                   (fan, "fanuc", "G21 G0 X1 Z0\nM80\nG0 X2\nM30\n")):
        res = tc.run(tc.Program.parse(text, dialect=dialect), machine=machine, search_path=[tmp_path])
        np.testing.assert_array_equal(res.nominal.end, [[1, 0, 0], [1, 0, 5], [2, 0, 5]])
        assert list(res.nominal.file) == [0, 1, 0]
        assert tc.Machine.parse(machine.dumps()).m_codes == machine.m_codes


@pytest.mark.parametrize("text, what", [
    ('control = "sinumerik"\n[m_codes]\n150 = { action = "subprogram", program = "PROBE" }\n', "LinuxCNC and Fanuc"),
    ('control = "fanuc"\n[m_codes]\n150 = { action = "subprogram", program = "probe" }\n', "O number"),
    ('control = "linuxcnc"\n[m_codes]\n150 = { action = "subprogram" }\n', "program is missing"),
    ('control = "linuxcnc"\n[m_codes]\n150 = { action = "subprogram", program = "../x" }\n', "no subroutine name"),
])
def test_subprogram_codes_that_cannot_run_are_refused_at_their_line(text, what):
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse(text)
    assert what in e.value.message and e.value.line == 3


@pytest.mark.parametrize("rotation", [0.0, 45.0, 30.0])
def test_arc_extremes_count_in_a_rotated_system(rotation):
    # A full circle of radius 10 about program (0, 0): whatever the rotation of G54, it reaches
    # machine X 10, beyond the travel's 9.
    m = tc.Machine("linuxcnc")
    m.travel = ((-math.inf, 9.0), (-math.inf, math.inf), (-math.inf, math.inf))
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G17 G0 X-10 Y0\nG2 X-10 Y0 I10 J0 F100\nM2\n"), machine=m,
               parameters={5230: rotation})
    assert (e.value.code, e.value.line) == ("travel_limit", 2)
    assert "X 10.0000 mm" in e.value.message


def test_a_lathes_machine_x_is_a_diameter():
    # Travel X up to 60 (diameter, as the control shows it): X50 is inside, X100 beyond.
    lathe = tc.Machine.preset("fanuc-lathe")
    lathe.travel = ((-math.inf, 60.0), (-math.inf, math.inf), (-math.inf, math.inf))
    tc.run(tc.Program.parse("G21 G18 G98 G0 X50 Z0\nM30\n", dialect="fanuc"), machine=lathe)
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G18 G98 G0 X100 Z0\nM30\n", dialect="fanuc"), machine=lathe)
    assert e.value.code == "travel_limit" and "X 100.0000 mm" in e.value.message
    # A work origin of X10 (diameter): G53 X0 is program diameter -10.
    lathe.work_origin = (10.0, 0.0, 0.0)
    res = tc.run(tc.Program.parse("G21 G18 G98 G53 G0 X0\nM30\n", dialect="fanuc"), machine=lathe)
    assert res.nominal.end[-1, 0] == -5.0  # the path holds radii


def test_one_sided_travel_round_trips():
    m = tc.Machine.parse('control = "fanuc"\n[travel]\nx = [-inf, 100]\n')
    assert m.travel[0] == (-math.inf, 100.0)
    assert tc.Machine.parse(m.dumps()).travel == m.travel


@pytest.mark.parametrize("text, line", [
    ('control = "fanuc"\nm_codes = 5\n', 2),                      # a section that is no table
    ('control = "fanuc"\n[profile]\nblock_limit = 0\n', 3),       # refused by the engine's check
    ('control = "fanuc"\n[m_codes]\nM30 = "nothing"\n', 3),       # the key written M30
    ('control = "fanuc"\n[travel]\nx = [0, "far"]\n', 3),
])
def test_more_bad_machine_files_name_their_line(text, line):
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse(text)
    assert (e.value.code, e.value.line) == ("machine_file", line), e.value


def test_names_with_control_characters_round_trip():
    m = tc.Machine("fanuc", "mill", "cell\r3\x7f \"A\" \\ B")
    assert tc.Machine.parse(m.dumps()).name == m.name


def test_a_linuxcnc_builder_subprogram_name_is_folded_to_lower_case(tmp_path):
    (tmp_path / "mysub.ngc").write_text("o<mysub> sub\nG91 G0 Z5\nG90\no<mysub> endsub\nM2\n")
    m = tc.Machine("linuxcnc")
    m.m_codes = {250: tc.MachineCode("subprogram", program="MySub")}
    res = tc.run(tc.Program.parse("G21 G0 X1 Z0\nM250\nM2\n"), machine=m, search_path=[tmp_path])
    assert res.nominal.end[-1, 2] == 5


def test_a_fusion_style_haas_program_on_its_machine():
    # A metric Haas program as a CAM post writes it: % frame, O number, safe start, G28 G91 Z0,
    # T1 M06, M08, the chip conveyor M31/M33, G41 D01 on a contour with an arc, G53 G49 Z0 and
    # G53 X0 Y0 to park. Program zero at machine (-400, -200, -500).
    shapely = pytest.importorskip("shapely.geometry")
    m = tc.Machine.preset("haas-mill")
    m.work_origin = (-400.0, -200.0, -500.0)
    m.travel = ((-762.0, 0.0), (-406.0, 0.0), (-508.0, 0.0))
    tools = tc.ToolTable.parse("tool,z,diameter\n1,120,10\n", "csv")
    path = pathlib.Path(__file__).resolve().parents[1] / "programs" / "machines" / "haas_bracket_metric.nc"
    res = tc.run(path, tools=tools, machine=m)
    assert res.ok and not res.diagnostics
    p = res.path
    # Parking: G53 G49 Z0 is program Z 500, G53 X0 Y0 program (400, 200).
    np.testing.assert_allclose(p.end[-2], [-20, -20, 500])
    np.testing.assert_allclose(p.end[-1], [400, 200, 500])
    # The contour (0,0)-(0,50)-(80,50), G2 about (80,30) to (100,30), (100,0), (0,0): the tool
    # centre runs 5 mm outside it (Shapely's distance; the 400-point polygon of the arc is
    # within 4e-5 of it), meeting at the outside corners 5*sqrt(2) off (Fanuc's intersection
    # of the two offset lines), the arc about (80,30) at radius 25.
    arc = np.flatnonzero(p.kind == tc.ARC_CW)
    np.testing.assert_allclose(p.center[arc[0], :2], [80, 30])
    np.testing.assert_allclose(p.end[arc[0], :2], [105, 30])
    contour = [(0, 0), (0, 50), (80, 50)] + [(80 + 20 * math.cos(a), 30 + 20 * math.sin(a))
                                               for a in np.linspace(math.pi / 2, 0, 400)] + [(100, 0), (0, 0)]
    ring = shapely.Polygon(contour).exterior
    on_contour = (p.side != 0) & (p.line >= 20)
    pts, seg = p.sample(0.0005)
    pts = pts[np.isin(seg, np.flatnonzero(on_contour))]
    d = np.array([ring.distance(shapely.Point(x, y)) for x, y, _ in pts])
    assert d.min() > 5 - 1e-4 and d.max() < math.sqrt(50) + 1e-9
    assert np.median(d) == pytest.approx(5, abs=1e-4)
    assert np.count_nonzero(np.abs(d - math.sqrt(50)) < 1e-9) == 2  # (0,50) at (-5,55), (100,0) at (105,-5)
    with pytest.raises(tc.ProgramError) as e:  # the plain Fanuc mill does not know the conveyor
        tc.run(path, tools=tools, machine="fanuc-mill")
    assert (e.value.code, e.value.line) == ("unknown_m_code", 14)


def test_a_builder_code_beyond_the_controls_m_codes_is_refused_at_its_line():
    # LinuxCNC reads M codes up to M199 in programs (ControlProfile.max_m_code) and remaps
    # M200-M999.
    with pytest.raises(tc.ParseError) as e:
        tc.Machine.parse('control = "linuxcnc"\nkind = "mill"\n[m_codes]\n150 = "nothing"\n1000 = "nothing"\n')
    assert (e.value.code, e.value.line) == ("machine_file", 5) and "up to M999" in e.value.message
    assert 200 in tc.Machine.parse('control = "fanuc"\nkind = "mill"\n[m_codes]\n200 = "nothing"\n').m_codes


def test_an_inch_fusion_360_haas_program_runs_on_haas_mill():
    # Fusion 360's Haas post: G53 G0 Z0. parking, T1 M6, G43 Z0.6 H1, a G42 contour with an
    # arc, G98 G83 pecking at two holes, G80 then Z0.6 (in G00), G53 G0 Z0. Program zero at
    # machine (-15, -8, -20) in: the tool change position Z0 and the parking put the spindle at
    # machine Z0, the tip a tool length below: program Z = 20 in - length.
    m = tc.Machine.preset("haas-mill")
    m.work_origin = (-15 * 25.4, -8 * 25.4, -20 * 25.4)
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=0.25 * 25.4, length=[0.0, 0.0, 4 * 25.4])]))
    tools.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=0.125 * 25.4, length=[0.0, 0.0, 3.5 * 25.4])]))
    path = pathlib.Path(__file__).resolve().parents[1] / "programs" / "machines" / "bracket_fusion_haas_inch.nc"
    res = tc.run(path, tools=tools, machine=m)
    assert res.ok and not res.diagnostics
    inch = res.path.end / 25.4
    lines = res.path.line
    # The contour (0,0) (2,0), G3 about (2,0.25) to (2.25,0.25), (2.25,1.5), (0,1.5), (0,0)
    # with G42 and r 0.25: the centre 0.25 outside, the arc at radius 0.5, the corners at the
    # offset lines' intersections, the start-up and the last block perpendicular at their ends.
    contour = (lines >= 19) & (lines <= 24)
    np.testing.assert_allclose(inch[contour][:, :2], [(0, -0.25), (2, -0.25), (2.5, 0.25), (2.5, 1.75),
                                                       (-0.25, 1.75), (-0.25, 0)], atol=1e-9)
    # G83 down to Z-0.35 at both holes, back to the initial level Z0.2 (G98).
    drill = (lines >= 38) & (lines <= 39)
    assert inch[drill][:, 2].min() == pytest.approx(-0.35)
    assert inch[lines == 38][-1, 2] == pytest.approx(0.2) and inch[lines == 39][-1, 2] == pytest.approx(0.2)
    # G80 (line 40), then Z0.6 at rapid; G53 G0 Z0. with tool 2 (3.5 in): program Z 20 - 3.5.
    assert res.path.kind[lines == 41][0] == tc.RAPID and inch[lines == 41][0, 2] == pytest.approx(0.6)
    np.testing.assert_allclose(inch[-1], [1.5, 0.5, 16.5], atol=1e-9)
