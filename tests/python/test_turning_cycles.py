"""Fanuc lathe cycles G71 / G72 (stock removal, type I) and G70 (finishing), as the Fanuc T
series and Haas lathes run them. Every pass below is worked by hand from the contour, the
allowances, the depth of cut and the escape (radius values; X words are diameters):

    levels   start X (radius) - k * depth, while short of the shifted contour's first point
    pass     infeed to the level (rapid: the P block is G00), feed along Z to the contour
             shifted by (U/2, W), escape 45 degrees by R, rapid back to the start Z
    last     to the shifted contour's first point, along the contour, rapid to the start
"""
import math

import numpy as np
import pytest

import toolcomp as tc

OD = """\
G21 G18 G40
T0101
G97 S1000 M3
G98
G0 X52 Z2
G71 U2 R0.5
G71 P10 Q20 U0.4 W0.1 F200
N10 G0 X20
G1 Z-20
X40 Z-30
Z-50
N20 X52
G70 P10 Q20
G0 X100 Z100
M30
"""


def _lathe(text, **kw):
    kw.setdefault("machine", "lathe")
    return tc.run(tc.Program.parse(text, dialect="fanuc"), **kw)


def _xz(path):
    """(X radius, Z) of each segment's end."""
    return path.end[:, [0, 2]]


def _pass(level, end, start_z=2.0, e=0.5, du=-1, dv=-1):
    """One roughing pass at X `level` (radius) ending at Z `end`: infeed, cut, escape, back."""
    return [(level, start_z), (level, end), (level - dv * e, end - du * e), (level - dv * e, start_z)]


def test_g71_roughs_an_od_contour_pass_by_pass():
    res = _lathe(OD)
    assert res.ok
    g71 = res.nominal.line == 7
    # Shifted contour (radius, Z): (10.2, 2.1) (10.2, -19.9) (20.2, -29.9) (20.2, -49.9)
    # (26.2, -49.9). Levels 24 ... 12 (10 lies beyond 10.2: the contour pass takes it). At 24
    # and 22 the pass meets the shoulder at Z-49.9; at 20 ... 12 the taper, where
    # Z = -19.9 - (X - 10.2).
    expected = []
    for level, end in [(24, -49.9), (22, -49.9), (20, -29.7), (18, -27.7), (16, -25.7), (14, -23.7), (12, -21.7)]:
        expected += _pass(level, end)
    expected += [(10.2, 2.1), (10.2, -19.9), (20.2, -29.9), (20.2, -49.9), (26.2, -49.9), (26, 2)]
    np.testing.assert_allclose(_xz(res.nominal)[g71], expected, atol=1e-9)
    kinds = res.nominal.kind[g71]
    assert list(kinds[:4]) == [tc.RAPID, tc.LINE, tc.RAPID, tc.RAPID]  # N10 is G00: rapid infeeds
    assert list(kinds[-6:]) == [tc.RAPID, tc.LINE, tc.LINE, tc.LINE, tc.LINE, tc.RAPID]
    np.testing.assert_allclose(res.nominal.feed[g71][kinds == tc.LINE], 200)


def test_the_contour_after_g71_is_skipped_and_g70_runs_it():
    res = _lathe(OD)
    lines = list(res.nominal.line)
    # After G71 (line 7) comes G70 (the contour, lines 8-12, then the rapid back: line 13),
    # never the contour's blocks on their own.
    after = lines[lines.index(8):]
    assert after == [8, 9, 10, 11, 12, 13, 14]
    g70 = np.isin(res.nominal.line, [8, 9, 10, 11, 12, 13])
    np.testing.assert_allclose(_xz(res.nominal)[g70], [(10, 2), (10, -20), (20, -30), (20, -50), (26, -50), (26, 2)])


def test_g71_with_a_feed_in_the_p_block_infeeds_at_feed():
    res = _lathe(OD.replace("N10 G0 X20", "N10 G1 X20"))
    g71 = res.nominal.line == 7
    assert list(res.nominal.kind[g71][:2]) == [tc.LINE, tc.LINE]


def test_g71_cuts_to_an_arc_of_the_contour():
    # A rounded shoulder: from (10, -10) G3 to (20, -20), radius 10 about (X10, Z-20) (radius
    # values). No allowance, depth 3 from X26: levels 23, 20, 17, 14, 11. At 17, 14, 11 the
    # pass ends on the arc, at Z = -20 + sqrt(100 - (level - 10)^2).
    text = ("G21 G18 G98 G97 S800 M3\nG0 X52 Z2\nG71 U3 R0.5\nG71 P1 Q2 F150\nN1 G0 X20\nG1 Z-10\n"
            "G3 X40 Z-20 R10\nG1 Z-30\nN2 X52\nM30\n")
    res = _lathe(text)
    g71 = res.nominal.line == 4
    expected = []
    for level, end in [(23, -30), (20, -30)] + [(v, -20 + math.sqrt(100 - (v - 10) ** 2)) for v in (17, 14, 11)]:
        expected += _pass(level, end)
    expected += [(10, 2), (10, -10), (20, -20), (20, -30), (26, -30), (26, 2)]
    np.testing.assert_allclose(_xz(res.nominal)[g71], expected, atol=1e-9)
    arc = np.flatnonzero(g71)[-4]
    assert res.nominal.kind[arc] == tc.ARC_CCW
    np.testing.assert_allclose(res.nominal.center[arc][[0, 2]], [10, -20], atol=1e-9)


def test_g71_bores_an_id_contour():
    # Boring from X18 (radius 9) out to the contour: the passes step outwards, U is negative.
    # Shifted contour: (19.8, 2.1) (19.8, -9.9) (14.8, -19.9) (14.8, -39.9) (8.8, -39.9).
    text = ("G21 G18 G98 G97 S800 M3\nG0 X18 Z2\nG71 U2 R0.5\nG71 P10 Q20 U-0.4 W0.1 F120\nN10 G0 X40\nG1 Z-10\n"
            "X30 Z-20\nZ-40\nN20 X18\nM30\n")
    res = _lathe(text)
    g71 = res.nominal.line == 4
    expected = []
    for level, end in [(11, -39.9), (13, -39.9), (15, -19.5), (17, -15.5), (19, -11.5)]:
        expected += _pass(level, end, dv=1)
    expected += [(19.8, 2.1), (19.8, -9.9), (14.8, -19.9), (14.8, -39.9), (8.8, -39.9), (9, 2)]
    np.testing.assert_allclose(_xz(res.nominal)[g71], expected, atol=1e-9)


def test_g72_faces_pass_by_pass():
    # Facing from X82 Z2: passes along X, stepping in Z by W2. Contour (radius, Z): (41, -12)
    # (30, -12) (20, -4) (0, -4), shifted by U0.4 (0.2 in X) and W0.2: (41.2, -11.8)
    # (30.2, -11.8) (20.2, -3.8) (0.2, -3.8). Levels Z0 ... Z-10. At Z0 and Z-2 the pass runs
    # to X0.2; below, it meets the taper, where X = 30.2 - (Z + 11.8) * 10 / 8.
    text = ("G21 G18 G98 G97 S800 M3\nG0 X82 Z2\nG72 W2 R0.5\nG72 P10 Q20 U0.4 W0.2 F150\nN10 G0 Z-12\nG1 X60\n"
            "X40 Z-4\nN20 X0\nG70 P10 Q20\nM30\n")
    res = _lathe(text)
    g72 = res.nominal.line == 4
    expected = []
    for z, x in [(0, 0.2), (-2, 0.2)] + [(z, 30.2 - (z + 11.8) * 10 / 8) for z in (-4, -6, -8, -10)]:
        expected += [(41, z), (x, z), (x + 0.5, z + 0.5), (41, z + 0.5)]
    expected += [(41.2, -11.8), (30.2, -11.8), (20.2, -3.8), (0.2, -3.8), (41, 2)]
    np.testing.assert_allclose(_xz(res.nominal)[g72], expected, atol=1e-9)


def test_the_haas_one_block_form_in_inch_on_haas_lathe():
    # G71 P Q U W D F: D the depth of cut; no R: the escape is ControlProfile.turning_escape
    # (1 mm = 0.03937 in). From X1.1 (radius 0.55) by 0.1: levels 0.45 and 0.35; the shifted
    # contour starts at radius 0.26.
    text = """%
O00010 (HAAS LATHE G71 INCH)
G20 G18 G40 G99
T101
G50 S3000
G96 S500 M03
G00 X1.1 Z0.1 M08
G71 P10 Q20 U0.02 W0.005 D0.1 F0.012
N10 G00 X0.5
G01 Z-0.5
X0.8 Z-0.8
Z-1.5
N20 X1.1
G70 P10 Q20
G00 X3. Z3. M09
M30
%
"""
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), machine="haas-lathe")
    assert res.ok
    g71 = res.nominal.line == 8
    e = 1 / 25.4
    expected = _pass(0.45, -1.495, 0.1, e) + _pass(0.35, -0.495 - (0.35 - 0.26) * 2, 0.1, e)
    expected += [(0.26, 0.105), (0.26, -0.495), (0.41, -0.795), (0.41, -1.495), (0.56, -1.495), (0.55, 0.1)]
    np.testing.assert_allclose(_xz(res.nominal)[g71] / 25.4, expected, atol=1e-9)


def test_g70_with_nose_radius_compensation_cuts_as_the_contour_written_out():
    # G42 in the P block, G40 after: the finishing pass is compensated as the same blocks
    # would be on their own.
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=0.8, orientation=3)]))
    contour = "G0 G42 X20\nG1 Z-20\nX40 Z-30\nZ-50\nX52\nG40 G0 X60\n"
    cycle = "G21 G18 G98 G97 S800 M3\nT0101\nG0 X52 Z2\nG71 U2 R0.5\nG71 P10 Q20 U0.4 W0.1 F200\n"
    numbered = contour.replace("G0 G42 X20", "N10 G0 G42 X20").replace("G40 G0 X60", "N20 G40 G0 X60")
    res = _lathe(cycle + numbered + "G70 P10 Q20\nM30\n", tools=tools)
    direct = _lathe("G21 G18 G98 G97 S800 M3\nT0101\nG0 X52 Z2\nF200\n" + contour + "G0 X52 Z2\nM30\n", tools=tools)
    g70 = res.path.line >= 6  # the G71 passes are line 5's
    np.testing.assert_allclose(res.path.end[g70], direct.path.end[direct.path.line >= 5], atol=1e-9)
    assert not np.allclose(res.path.end[g70], res.nominal.end[res.nominal.line >= 6])  # compensated


@pytest.mark.parametrize("change, code, line", [
    (("X40 Z-30\n", "X40 Z-30\nX36 Z-35\n"), "cycle_not_monotonic", 11),  # X turns back
    (("G71 P10 Q20", "G71 P10"), "cycle_p_q_missing", 7),
    (("G71 P10 Q20", "G71 P10 Q30"), "cycle_sequence_not_found", 7),
    (("N10 G0 X20", "N10 G2 X20 R5"), "cycle_first_block", 7),
    (("G1 Z-20\n", "G1 Z-20 M8\n"), "cycle_improper_block", 9),
    (("G71 U2 R0.5", "G71 U0 R0.5"), "cycle_bad_value", 6),
    (("G0 X52 Z2\n", "G0 X20 Z2\n"), "cycle_bad_value", 7),  # the contour starts at the start's X
])
def test_what_the_control_refuses(change, code, line):
    with pytest.raises(tc.ProgramError) as e:
        _lathe(OD.replace(*change))
    assert (e.value.code, e.value.line) == (code, line), str(e.value)
    if code.startswith("cycle_") and code != "cycle_bad_value":
        assert str(e.value).startswith("PS00")


def test_g71_under_nose_radius_compensation_is_refused():
    with pytest.raises(tc.ProgramError) as e:
        _lathe(OD.replace("G0 X52 Z2", "G42 G0 X52 Z2"), tools=_tools())
    assert (e.value.code, e.value.line) == ("unsupported_g_code", 7)


def _tools():
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=0.8, orientation=3)]))
    return t


def test_lathe_cycles_run_from_a_file_read_in_pieces(tmp_path):
    # Thousands of blocks before the cycle: the file is read whole (a G71 reads blocks
    # N10 .. N20 ahead of it), and the passes come out as from the text.
    body = "".join(f"G1 Z{2 + (k % 2) * 0.5:.1f} F200\n" for k in range(20000))
    text = OD.replace("G0 X52 Z2\n", "G0 X52 Z2\n" + body + "G0 X52 Z2\n")
    (tmp_path / "part.nc").write_text(text)
    from_file = tc.run(str(tmp_path / "part.nc"), dialect="fanuc", machine="lathe")
    from_text = _lathe(text)
    np.testing.assert_array_equal(from_file.nominal.end, from_text.nominal.end)


def test_linuxcnc_reads_g71_as_its_own_cycle():
    # LinuxCNC's G71 takes its profile from O<Q>: Fanuc's P (first block) is a word it refuses.
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G18 G0 X10 Z2\nG71 P10 Q20 D1\nM2\n"), machine="lathe")
    assert e.value.code == "unused_word" and str(e.value).startswith("P word with no G2 G3 G4")


# ---- G73 pattern repeating, G74 / G75 pecking --------------------------------------------------

def test_g73_repeats_the_contour_shifted_ever_closer():
    # Relief U3 (radius) W1 in 3 passes, allowance U0.4 (0.2 radius) W0.1: the contour
    # (5, 0) (5, -10) (10, -15) (15, -15) (radius, Z) shifted by (3.2, 1.1), (1.7, 0.6),
    # (0.2, 0.1); each pass from A (15, 2) at rapid (the P block is G00) and back.
    text = ("G21 G18 G97 S600 M3\nG99\nG0 X30 Z2\nG73 U3 W1 R3\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X10 Z0\nG1 Z-10\n"
            "X20 Z-15\nN20 X30\nM30\n")
    res = _lathe(text)
    sel = res.nominal.line == 5
    expected = []
    for dx, dz in [(3.2, 1.1), (1.7, 0.6), (0.2, 0.1)]:
        expected += [(5 + dx, dz), (5 + dx, -10 + dz), (10 + dx, -15 + dz), (15 + dx, -15 + dz), (15, 2)]
    np.testing.assert_allclose(_xz(res.nominal)[sel], expected, atol=1e-9)
    assert np.all(res.nominal.feed[sel][res.nominal.kind[sel] == tc.LINE] == 0.2 * 600)


def test_haas_one_block_g73_returns_to_the_start_shifted_as_the_next_pass():
    # The same cycle in Haas's one block: I3 (radius) K1 the distance from the first pass to
    # the last, D3 passes. Haas: "when block Q is reached a rapid departure move is executed to
    # the Start position plus the offset for the second roughing pass": after the first pass
    # to A + (1.7, 0.6) (the second pass's shift), after the second to A + (0.2, 0.1), after
    # the last to A.
    text = ("G21 G18 G97 S600 M3\nG99\nG0 X30 Z2\nG73 P10 Q20 U0.4 W0.1 I3 K1 D3 F0.2\nN10 G0 X10 Z0\nG1 Z-10\n"
            "X20 Z-15\nN20 X30\nM30\n")
    res = tc.run(tc.Program.parse(text, dialect="fanuc"), machine="haas-lathe")
    sel = res.nominal.line == 4
    expected = []
    for (dx, dz), back in [((3.2, 1.1), (15 + 1.7, 2 + 0.6)), ((1.7, 0.6), (15 + 0.2, 2 + 0.1)), ((0.2, 0.1), (15, 2))]:
        expected += [(5 + dx, dz), (5 + dx, -10 + dz), (10 + dx, -15 + dz), (15 + dx, -15 + dz), back]
    np.testing.assert_allclose(_xz(res.nominal)[sel], expected, atol=1e-9)
    # On a Fanuc lathe each pass goes back to A itself.
    res = _lathe(text)
    np.testing.assert_allclose(_xz(res.nominal)[res.nominal.line == 4][[4, 9, 14]], [(15, 2)] * 3, atol=1e-9)


def test_g75_grooves_in_pecks():
    # From X42 Z-20 (radius 21): grooves at Z-20, -23, -26 (Q3000: 3 mm), each pecked 2 mm
    # (P2000) deep to radius 15, 0.5 back after each peck (R0.5), out to 21 at rapid.
    text = "G21 G18 G97 S600 M3\nG99\nG0 X42 Z-20\nG75 R0.5\nG75 X30 Z-26 P2000 Q3000 F0.05\nM30\n"
    res = _lathe(text)
    sel = res.nominal.line == 5
    expected = []
    for z in (-20, -23, -26):
        if z != -20:
            expected.append((21, z))
        expected += [(19, z), (19.5, z), (17, z), (17.5, z), (15, z), (21, z)]
    expected.append((21, -20))
    np.testing.assert_allclose(_xz(res.nominal)[sel], expected, atol=1e-9)
    assert set(res.nominal.feed[sel][res.nominal.kind[sel] == tc.LINE]) == {0.05 * 600}


def test_g74_pecks_along_z():
    # Peck drilling on the axis from Z5: 3 mm pecks (Q3000), 1 mm back (R1), to Z-8.
    text = "G21 G18 G97 S600 M3\nG99\nG0 X0 Z5\nG74 R1\nG74 Z-8 Q3000 F0.1\nM30\n"
    res = _lathe(text)
    sel = res.nominal.line == 5
    np.testing.assert_allclose(_xz(res.nominal)[sel], [(0, 2), (0, 3), (0, -1), (0, 0), (0, -4), (0, -3), (0, -7),
                                                         (0, -6), (0, -8), (0, 5)], atol=1e-9)


@pytest.mark.parametrize("text, code", [
    ("G75 X30 Z-26 P2000 F0.05", "cycle_bad_value"),  # a second groove without a shift
    ("G75 X30 Z-20 P2000.5 F0.05", "cycle_bad_value"),
    ("G75 X30 Z-20 P2000 R0.2 F0.05", "unsupported_word"),  # the relief at the bottom
])
def test_g75_refusals(text, code):
    with pytest.raises(tc.ProgramError) as e:
        _lathe("G21 G18 G97 S600 M3\nG99\nG0 X42 Z-20\n" + text + "\nM30\n")
    assert (e.value.code, e.value.line) == (code, 4)


# ---- programs as CAM posts write them ------------------------------------------------------------

PROGRAMS = __import__("pathlib").Path(__file__).resolve().parents[1] / "programs" / "lathe"


def _line_of(path, text):
    """The 1-based line of the file that holds `text`."""
    return next(i for i, l in enumerate(path.read_text().splitlines(), 1) if text in l)


def _cam_tools():
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=0.8, orientation=3)]))
    t.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=0.4, orientation=3)]))
    return t


@pytest.mark.parametrize("machine", ["haas-lathe", "fanuc-lathe"])
def test_a_mastercam_fanuc_lathe_program_runs(machine):
    # G0 T0101, G50 S3000, G96, G99 G1 Z1., the two-block G71 with G42 in the contour, G70
    # with the finishing tool, G0 G28 U0. W0. M05 (G0 beside G28: the axis words are G28's).
    res = tc.run(str(PROGRAMS / "spacer_mastercam_fanuc_metric.nc"), dialect="fanuc", machine=machine,
                 tools=_cam_tools())
    assert res.ok
    at = _line_of(PROGRAMS / "spacer_mastercam_fanuc_metric.nc", "G71 P100")
    g71 = res.nominal.line == at
    # From A (radius 24, Z1), depth 2: levels 22 ... 12. The shifted contour: (10.2, 1.1),
    # (10.2, 0.1), (12.2, -1.9), (12.2, -19.9), (18.2, -19.9), (20.2, -21.9), (20.2, -34.9),
    # (24.2, -34.9), and on Haas (G42 in the contour: the rough allowance grows by tool 1's
    # nose radius n = 0.8 in X and Z, tip 3) n further in both. Level 22 meets the last face
    # at Z-34.9 + n; level 20 the chamfer at Z = -19.9 + n - (20 - 18.2 - n) = -21.7 + 2n;
    # levels 18 ... 14 the face at Z-19.9 + n; 12 the chamfer at Z = -1.7 + 2n.
    n = 0.8 if machine == "haas-lathe" else 0.0
    cuts = res.nominal.end[g71 & (res.nominal.kind == tc.LINE)][:, [0, 2]]
    np.testing.assert_allclose(cuts[:7], [(22, -34.9 + n), (20, -21.7 + 2 * n), (18, -19.9 + n), (16, -19.9 + n),
                                           (14, -19.9 + n), (12, -1.7 + 2 * n), (10.2 + n, 0.1 + n)], atol=1e-9)
    # The G70 pass is compensated (G42 in the contour, tool 2's 0.4 mm nose).
    contour = (res.path.line > at) & (res.path.line <= at + 8)
    assert not np.allclose(res.path.end[contour], res.nominal.end[(res.nominal.line > at) & (res.nominal.line <= at + 8)])


def test_a_fusion_360_haas_lathe_program_runs_in_inch():
    # G20, G28 U0. / G28 W0., G50 S2500, T101, G54, G99, G96 S656, the one-block G71 with D.
    res = tc.run(str(PROGRAMS / "flange_fusion_haas_inch.nc"), dialect="fanuc", machine="haas-lathe",
                 tools=_cam_tools())
    assert res.ok
    g71 = res.nominal.line == _line_of(PROGRAMS / "flange_fusion_haas_inch.nc", "G71 P27")
    cuts = res.nominal.end[g71 & (res.nominal.kind == tc.LINE)][:, [0, 2]] / 25.4
    # From A (radius 1.03, Z0.1) by D0.05: levels 0.98 ... 0.48 (11 of them); 0.98 meets the
    # last face at Z-0.795 (-0.8 + W0.005), as do 0.93 ... 0.73 (the face from radius 0.71 to
    # 0.96); 0.68 ... 0.53 the R0.2 fillet; 0.48 the chamfer.
    levels = 1.03 - 0.05 * np.arange(1, 12)
    np.testing.assert_allclose(cuts[:11, 0], levels, atol=1e-9)
    np.testing.assert_allclose(cuts[:5, 1], -0.795, atol=1e-9)


def test_the_contours_feed_acts_in_g70_only():
    # F50 in the contour: the roughing keeps the cycle's F200; G70 cuts the contour at F50
    # from the block that gives it (the P block's rapid has none).
    res = _lathe(OD.replace("G1 Z-20\n", "G1 Z-20 F50\n"))
    g71 = (res.nominal.line == 7) & (res.nominal.kind == tc.LINE)
    assert set(res.nominal.feed[g71]) == {200.0}
    g70 = np.isin(res.nominal.line, [9, 10, 11, 12])
    assert set(res.nominal.feed[g70]) == {50.0}
