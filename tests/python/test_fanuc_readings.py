"""How a Fanuc (and the Fanuc-compatible Haas) control reads the blocks real programs are
made of: the safe-start block with G80, G53 parking, G43 H with D, G00 at power on, G98,
the Macro B abbreviations. Each reading is a ControlProfile field; LinuxCNC keeps its own."""
import numpy as np
import pytest

import toolcomp as tc


def _run(text, dialect="fanuc", **kw):
    return tc.run(tc.Program.parse(text, dialect=dialect), **kw)


def _tools():
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=3.0, length=[0.0, 0.0, 100.0])]))
    t.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, 80.0])]))
    return t


def test_the_safe_start_block_then_g53_parks_the_spindle():
    # Haas and Fusion 360 posts: G80 beside G00 in one block, then G53 Z0. alone: G80 is
    # group 09, the motion mode stays G00, and G53 moves at rapid to machine Z0 (work origin
    # at machine Z-500: program Z500).
    m = tc.Machine("fanuc")
    m.work_origin = (0.0, 0.0, -500.0)
    res = _run("%\nO1000\nG00 G17 G40 G49 G80 G90\nG53 Z0.\nM30\n%\n", machine=m)
    np.testing.assert_allclose(res.nominal.end[-1], [0, 0, 500])
    assert res.nominal.kind[-1] == tc.RAPID and res.nominal.line[-1] == 4


def test_g53_moves_at_rapid_in_g01_mode():
    res = _run("G21 G90 G00 X0 Y0 Z10\nG01 X5 F100\nG53 Z0\nX8\nM30\n")
    assert list(res.nominal.kind) == [tc.RAPID, tc.LINE, tc.RAPID, tc.LINE]  # G01 stays modal
    # LinuxCNC: G53 takes the motion mode (G0 or G1).
    lin = _run("G21 G90 G0 X0 Y0 Z10\nG1 X5 F100\nG53 Z0\nM2\n", "linuxcnc")
    assert lin.nominal.kind[-1] == tc.LINE


def test_g80_brings_back_the_motion_mode_before_the_cycle():
    # G81 from Z10 (the initial level; G98 at power on) to R2, Z-5; G80; X20 moves at G00,
    # the mode before the cycle.
    res = _run("G21 G90 G00 X0 Y0 Z10\nG81 X10 Y0 Z-5 R2 F100\nG80\nX20\nM30\n")
    np.testing.assert_allclose(res.nominal.end, [[0, 0, 10], [10, 0, 10], [10, 0, 2], [10, 0, -5], [10, 0, 10],
                                                 [20, 0, 10]])
    assert res.nominal.kind[-1] == tc.RAPID
    # In G01 before the cycle: G80 X30 in one block feeds to X30.
    res = _run("G21 G90 G00 X0 Y0 Z10\nG01 X1 F100\nG81 X10 Y0 Z-5 R2 F100\nG80 X30\nM30\n")
    assert res.nominal.kind[-1] == tc.LINE and res.nominal.end[-1, 0] == 30


def test_g99_returns_to_the_r_point():
    res = _run("G21 G90 G00 X0 Y0 Z10\nG99 G81 X10 Y0 Z-5 R2 F100\nG80\nM30\n")
    np.testing.assert_allclose(res.nominal.end[-1], [10, 0, 2])


def test_fanuc_starts_in_g00_and_linuxcnc_in_g80():
    res = _run("G21 G90\nX10 Y5\nM30\n")
    assert res.nominal.kind[0] == tc.RAPID and list(res.nominal.end[0]) == [10, 5, 0]
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G90\nX10 Y5\nM2\n", "linuxcnc")
    assert (e.value.code, e.value.line) == ("axis_without_motion", 2)
    with pytest.raises(tc.ProgramError) as e:  # G80 a motion mode of its own on LinuxCNC
        _run("G21 G90 G0 X0\nG80\nX10\nM2\n", "linuxcnc")
    assert (e.value.code, e.value.line) == ("axis_without_motion", 3)


def test_g43_h_with_d_sets_the_d_number_for_g41():
    # D1 (radius 3) given at the tool change; G41 without D takes it. Type A start-up on the
    # line along +X: the centre 3 mm to the left, at Y3.
    text = "G21 G90 G00 X0 Y-10\nG43 H1 D1 Z5.\nG41 G01 X0 Y0 F100.\nX50.\nG40 G00 X60. Y-10.\nM30\n"
    res = _run(text, tools=_tools())
    np.testing.assert_allclose(res.path.end[res.path.line == 4][-1], [50, 3, 5], atol=1e-9)
    # A D changing the offset under compensation is refused, never ignored.
    with pytest.raises(tc.ProgramError) as e:
        _run(text.replace("X50.", "D2 X50."), tools=_tools())
    assert (e.value.code, e.value.line) == ("unsupported_word", 4)
    with pytest.raises(tc.ProgramError) as e:  # LinuxCNC: a D without G41/G42 is unused
        _run("G21 G0 X0\nG43 H1 D1 Z5\nM2\n", "linuxcnc", tools=_tools())
    assert (e.value.code, e.value.line) == ("unused_word", 2)


def test_macro_b_words_take_their_two_letter_abbreviations():
    # WH for WHILE, EN for END, IF [..] GO n for GOTO, TH for THEN (the first two letters).
    text = ("G21 G90 G00 X0 Y0\n#1=0\nWH[#1LT3]DO1\n#1=#1+1\nG91 X1.\nEN1\nG90\n"
            "IF[#1EQ3]GO10\nX99.\nN10 IF[#1EQ3]TH#2=5\nY#2\nM30\n")
    res = _run(text)
    np.testing.assert_allclose(res.nominal.end[1:], [[1, 0, 0], [2, 0, 0], [3, 0, 0], [3, 5, 0]])


@pytest.mark.parametrize("field, text, code, line", [
    ("cycles_own_group", "G21 G00 G80\nX10.\nM30\n", "axis_without_motion", 2),
    ("g53_rapid", "G21 G90 G00 X0 Y0\nG02 X10. Y0 R5. F100.\nG53 Z0\nM30\n", "g53_motion", 3),
    ("d_word_alone", "G21 G00 X0\nG43 H1 D1 Z5.\nM30\n", "unused_word", 2),
    ("motion_beside_data_axes", "G21 G90 G01 X10. Y10. F100.\nG00 G28 X0 Y0\nX5.\nM30\n", "two_axis_codes", 2),
])
def test_each_reading_is_a_profile_field(field, text, code, line):
    assert tc.run(tc.Program.parse(text, dialect="fanuc"), tools=_tools()).ok
    p = tc.ControlProfile("fanuc")
    setattr(p, field, False)
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="fanuc"), profile=p, tools=_tools())
    assert (e.value.code, e.value.line) == (code, line)


# ---- lathe (G-code system A) ------------------------------------------------------------------

def test_g50_s_clamps_the_spindle_under_constant_surface_speed():
    # G96 S200 (m/min), G99 F0.2 (mm/rev): at diameter 50 the spindle turns
    # 1000 * 200 / (pi * 50) = 1273.24 rev/min, the feed 254.648 mm/min; at diameter 10 it
    # would turn 6366 rev/min, G50 S2000 holds it at 2000: 400 mm/min.
    text = "G21 G18 G50 S2000\nG96 S200 M3\nG99\nG0 X50 Z1\nG1 Z-10 F0.2\nX10\nM30\n"
    res = _run(text, machine="lathe")
    np.testing.assert_allclose(res.nominal.feed[1:], [0.2 * 1000 * 200 / (np.pi * 50), 400.0])
    # Without the clamp the speed at diameter 10 stands.
    res = _run(text.replace("G50 S2000", ""), machine="lathe")
    np.testing.assert_allclose(res.nominal.feed[-1], 0.2 * 1000 * 200 / (np.pi * 10))


def test_g50_x_z_sets_the_coordinate_system():
    # At X10 (diameter) Z-10, G50 X0 Z0 makes that point program zero; X20 is then diameter
    # 20 from it: radius 10 further out, 10 along Z.
    res = _run("G21 G18 G0 X10 Z-10\nG50 X0 Z0\nG1 X20 F0.2 S500 M3\nM30\n", machine="lathe")
    np.testing.assert_allclose(res.nominal.end[-1], [10, 0, 0])
    np.testing.assert_allclose(res.nominal.start[-1], [0, 0, 0])
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G18 G0 X10 Z-10\nG50 U2\nM30\n", machine="lathe")
    assert (e.value.code, e.value.line) == ("unsupported_word", 2)
    with pytest.raises(tc.ProgramError) as e:  # G50 is no code of a Fanuc mill here
        _run("G21 G50 S2000\nM30\n")
    assert (e.value.code, e.value.line) == ("unknown_g_code", 1)


@pytest.mark.parametrize("r", [1.0, 5.0])
def test_g40_right_after_a_lead_out_arc(r):
    # Fusion 360 / Mastercam lead-out: the contour along +X, a G03 arc of radius 10 about
    # (50, 10) turning towards the tool's side (G41), then G01 G40 off it. Type C: the arc's
    # compensated end lies r towards its centre, (60 - r, 10); the G40 block ends at its
    # programmed point.
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=r, length=[0.0, 0.0, 50.0])]))
    text = ("G21 G90 G17 G00 X-20. Y-20.\nG43 H1 Z5.\nG01 Z-2. F100.\nG41 D1 X-10. Y-10.\nG01 X0 Y0\nX50.\n"
            "G03 X60. Y10. R10.\nG01 G40 X70. Y-10.\nM30\n")
    res = _run(text, tools=tools)
    assert res.ok
    np.testing.assert_allclose(res.path.end[res.path.line == 7][-1], [60 - r, 10, -2], atol=1e-9)
    np.testing.assert_allclose(res.path.end[-1], [70, -10, -2], atol=1e-9)


def test_g0_beside_g28_sets_the_mode_and_g28_takes_the_axes():
    # "G0 G28 U0. W0." (Mastercam's lathe posts), here on a mill: G28 through X0 Y0 to the G28
    # position (machine zero), and G00 is the mode after it.
    res = _run("G21 G90 G01 X10. Y10. F100.\nG00 G28 X0 Y0\nX5.\nM30\n")
    np.testing.assert_allclose(res.nominal.end[1:], [[0, 0, 0], [0, 0, 0], [5, 0, 0]])
    assert res.nominal.kind[-1] == tc.RAPID

