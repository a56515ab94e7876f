"""Lathes: Fanuc-style T offsets, diameter X, U/W increments, and the nose radius worked
example of the spec (§1.10): a 45 degree chamfer turned without nose radius compensation
leaves r(sqrt 2 - 1) = 0.331 mm for r = 0.8; with it, none."""
import math

import numpy as np
import pytest

import toolcomp as tc

# Offset table (X, Z of the offset in radius mm, nose radius, Fanuc tip number in Q).
OFFSETS = "T1 P1 X-2.5 Z1.25 D1.6 Q3 ;OD finishing, r 0.8, tip 3\nT2 P2 Z-3 D0.8 Q2\n"


def lathe_run(text, **kw):
    prof = tc.ControlProfile("fanuc", machine="lathe")
    return tc.run(tc.Program.parse(text, dialect="fanuc"), tools=tc.ToolTable.parse(OFFSETS, "linuxcnc"),
                  profile=prof, **kw)


def test_t_word_offsets_diameter_x_and_uw_increments():
    res = lathe_run("G21 G18 G98\nT0101\nG0 X50 Z5\nG1 U-10 F100\nW-10\nT0202\nG0 X60\nM30\n")
    p = res.path
    np.testing.assert_allclose(p.end[:3], [[25, 0, 5], [20, 0, 5], [20, 0, -5]])  # X is a diameter
    np.testing.assert_allclose(p.tool_offset[:3], [[-2.5, 0, 1.25]] * 3)
    assert list(p.tool[:3]) == [1, 1, 1]
    np.testing.assert_allclose(p.tool_offset[3], [0, 0, -3])  # T0202: tool 2, offset 2
    assert p.tool[3] == 2
    assert p.feed[1] == 100


def test_offset_must_exist():
    with pytest.raises(tc.ProgramError, match="Offset 7 not found"):
        lathe_run("G21 G18\nT0107\nM30\n")


CHAMFER = """G21 G18 G98
T0101
G0 X0 Z2
{on}G1 X0 Z0 F100
G1 X20
G1 X30 Z-5
G1 Z-20
G1 X40
{off}G0 X50 Z5
M30
"""


def chamfer_form_error(compensate):
    text = CHAMFER.format(on="G42 " if compensate else "", off="G40 " if compensate else "")
    res = lathe_run(text)
    p = res.path
    r = 0.8
    # The controlled point is the imaginary tip P; tip 3 (Fanuc) lies at -X, -Z from the
    # nose centre, so the centre is C = P + r (1, 1) in (X, Z).
    centre = p.end[:, [0, 2]] + r
    chamfer = np.flatnonzero(p.line == 6)
    # Chamfer from (x 10, z 0) to (x 15, z -5) in radius: the line x - 10 = -(z - 0).
    n = np.array([1, 1]) / math.sqrt(2)
    ends = np.vstack([p.start[chamfer][:, [0, 2]] + r, centre[chamfer]])
    dist = (ends - np.array([10.0, 0.0])) @ n
    return dist.min() - r


def test_chamfer_form_error_without_and_with_nose_radius_compensation():
    assert chamfer_form_error(False) == pytest.approx(0.8 * (math.sqrt(2) - 1), abs=1e-9)  # 0.331
    assert chamfer_form_error(True) == pytest.approx(0.0, abs=1e-9)


def test_tip_convention_is_a_setting():
    text = CHAMFER.format(on="G42 ", off="G40 ")
    fanuc = lathe_run(text)
    prof = tc.ControlProfile("fanuc", machine="lathe")
    prof.radius.tip_convention = tc.TipConvention.linuxcnc  # tip 3 read as LinuxCNC's (+X, -Z)
    other = tc.run(tc.Program.parse(text, dialect="fanuc"), tools=tc.ToolTable.parse(OFFSETS, "linuxcnc"),
                   profile=prof)
    d = other.path.end - fanuc.path.end
    comp = fanuc.path.side != 0
    np.testing.assert_allclose(d[comp][:, 0], 2 * 0.8)  # the X shift flips sign
    np.testing.assert_allclose(d[comp][:, 2], 0, atol=1e-12)


def test_lathe_offset_table_csv_round_trip_and_use(tmp_path):
    import pathlib
    src = pathlib.Path(__file__).resolve().parents[1] / "programs" / "tables" / "lathe_offsets.csv"
    table = tc.ToolTable.read(src)
    out = tmp_path / "offsets.csv"
    table.write(out)
    assert out.read_bytes() == src.read_bytes()  # lossless
    e = table[1].edge()
    assert (e.radius, e.orientation, e.radius_wear) == (0.8, 3, 0.005)
    np.testing.assert_allclose(e.length_wear, [0.02, 0, -0.01])
    res = tc.run(tc.Program.parse("G21 G18\nT0101\nG0 X50 Z5\nM30\n", dialect="fanuc"), tools=table,
                 profile=tc.ControlProfile("fanuc", machine="lathe"))
    np.testing.assert_allclose(res.path.tool_offset[0], [-2.5 + 0.02, 0, 1.25 - 0.01])


def test_g7_x_words_are_diameters_in_g43_1_and_cycle_depths():
    # LinuxCNC halves every X word in G7: G43.1 X4 is a 2 mm offset, a G19 cycle's depth X-2
    # is -1 (both checked against LinuxCNC's gcode module)
    p = tc.run(tc.Program.parse("G21 G90 G94 F300\nG0 X0 Y0 Z0\nG18 G7\nG43.1 X4\nG1 X20 Z1\nM2\n")).path
    assert p.tool_offset[-1, 0] == 2
    p = tc.run(tc.Program.parse("G21 G90 G94 F300\nG0 X0 Y0 Z0\nG19 G7\nG0 X5\nM3 S100\n"
                                "G81 Y10 Z0 X-2 R1\nG80\nM2\n")).path
    assert p.end[:, 0].min() == -1


FANUC_LATHE_START = "O1\nG21 G18 G99\nG0 X50 Z5\n"


@pytest.mark.parametrize("block, mid, home", [
    ("G28 U0 W0", (25, 5), (0, 0)),   # home from where the tool is, both axes
    ("G28 U0", (25, 5), (0, 5)),      # X only
    ("G28 U10 W0", (30, 5), (0, 0)),  # through X60 (radius 30), U a diameter increment
])
def test_g28_with_u_and_w_sends_x_and_z_home(block, mid, home):
    prof = tc.ControlProfile("fanuc", machine="lathe")
    p = tc.run(tc.Program.parse(FANUC_LATHE_START + block + "\nM30\n", "fanuc"), profile=prof).path
    np.testing.assert_allclose(p.end[-2][[0, 2]], mid, atol=1e-12)
    np.testing.assert_allclose(p.end[-1][[0, 2]], home, atol=1e-12)


@pytest.mark.parametrize("block, code, what", [
    ("G90 X45 Z-10 F0.2", "unsupported_g_code", "turning cycle"),
    ("G92 X45 Z-10 F1.5", "unsupported_g_code", "threading cycle"),
    ("G94 X20 Z-2 F0.2", "unsupported_g_code", "facing cycle"),
    ("G91 G0 U-2", "unknown_g_code", "does not exist"),
])
def test_fanuc_lathe_g_code_system_a(block, code, what):
    # G90/G92/G94 are box cycles on a system-A lathe, not distance mode, coordinate setting
    # and feed per minute: without the lathe cycles (test_lathe_single_cycles.py) refused,
    # never read as the mill's codes.
    prof = tc.ControlProfile("fanuc", machine="lathe")
    assert prof.g_code_system_a and not tc.ControlProfile("fanuc").g_code_system_a
    prof.turning_cycles = False
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(FANUC_LATHE_START + block + "\nM30\n", "fanuc"), profile=prof)
    assert e.value.code == code and e.value.line == 4 and what in e.value.message


@pytest.mark.parametrize("dialect", ["fanuc", "rockwell"])
def test_a_lathe_starts_in_the_zx_plane(dialect):
    # No G18 in the program: an R arc from (X50 Z-10) to (X60 Z-15), X in diameter, is cut in
    # ZX as the lathe powers up in G18. G2 seen from +Y, R5 on the 7.07 mm chord: the centre
    # lies 3.54 mm right of the chord's middle (Z-12.5, X radius 27.5) in (Z, X): Z-10, X30.
    profile = tc.ControlProfile(dialect, machine="lathe")
    assert profile.startup_plane == 18
    text = "G21 G0 X50 Z0 T0101 S500 M3\nG1 Z-10 F0.2\nG2 X60 Z-15 R5\nM30\n"
    res = tc.run(tc.Program.parse(text, dialect=dialect), profile=profile)
    np.testing.assert_allclose(res.nominal.center[-1], [30, 0, -10], atol=1e-12)
    np.testing.assert_allclose(res.nominal.end[-1], [30, 0, -15])
    assert tc.ControlProfile(dialect, machine="mill").startup_plane == 17 or dialect == "rockwell"


def test_a_fanuc_lathe_feeds_per_revolution_at_power_on():
    # G99 is the T series' power-on state: F0.2 at S500 is 100 mm/min.
    profile = tc.ControlProfile("fanuc", machine="lathe")
    assert profile.startup_feed_per_rev
    text = "G21 G18 G0 X50 Z0 T0101 S500 M3\nG1 Z-10 F0.2\nG98 G1 Z-20 F80\nM30\n"
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), profile=profile)
    np.testing.assert_allclose(res.nominal.feed[1:], [100, 80])
    assert not tc.ControlProfile("fanuc").startup_feed_per_rev


@pytest.mark.parametrize("code", ["G73", "G74", "G81", "G83", "G84", "G87"])
def test_mill_cycle_codes_are_not_read_as_mill_cycles_on_a_fanuc_lathe(code):
    # G74 on a Fanuc lathe is end face peck drilling, G73 pattern repeating, G83-G89 live
    # tool drilling: run as the mill's cycles they gave another path without a word.
    # (G73 and G74 run as those lathe cycles: test_turning_cycles.py; without them, refused.)
    text = f"G21 G18 G0 X0 Z10 T0101 S500 M3\n{code} R1\n{code} Z-20 Q5 F0.1\nM30\n"
    profile = tc.ControlProfile("fanuc", machine="lathe")
    profile.turning_cycles = code not in ("G73", "G74")
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), profile=profile)
    assert (e.value.code, e.value.line) == ("unsupported_g_code", 2)


def test_a_fanuc_lathe_chamfer_c_is_refused_not_read_as_a_c_axis():
    text = "G21 G18 G98 G0 X40 Z2 T0101\nG1 Z0 F100\nG1 X50 Z-20 C2\nM30\n"
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), profile=tc.ControlProfile("fanuc", kind="lathe"))
    assert (e.value.code, e.value.line, e.value.column) == ("unsupported_word", 3, 13)
    # A C axis move on its own (live tooling) stays a C move.
    res = tc.run(tc.Program.parse("G21 G18 G98 G0 X40 Z2\nG0 C90\nM30\n", dialect="fanuc"),
                 profile=tc.ControlProfile("fanuc", kind="lathe"))
    assert res.nominal.abc[-1, 2] == 90
