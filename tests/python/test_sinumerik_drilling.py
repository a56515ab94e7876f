"""The 840D's drilling cycles CYCLE83-CYCLE89, CYCLE840 and the grid CYCLE801: the moves the
840D's cycles make, worked by hand from their parameters (doc/sinumerik.md, "Drilling cycles")."""
import pytest

import toolcomp as tc


def run(text, **kw):
    return tc.run(tc.Program.parse(text, "sinumerik"), **kw)


R_, L_ = tc.RAPID, tc.LINE


def moves(res, start=0):
    p = res.nominal
    return [(int(k), tuple(round(float(v), 6) for v in e), None if k == tc.RAPID else round(float(f), 6))
            for k, e, f in list(zip(p.kind, p.end, p.feed))[start:]]


def zs(res, start=1):
    """The tool-axis positions and kinds after the positioning moves."""
    return [(k, e[2], f) for k, e, f in moves(res, start)]


def test_cycle83_swarf_removal_with_degression():
    # RTP 10, RFP 0, SDIS 2, DP -30, FDEP -8, DAM 3, FRF 0.5, VARI 1. Strokes 8, 5, 3, 3, 3, 3
    # (DAM off each, not below DAM), then 5 remain: under 2 DAM and over DAM: halved, 2.5 + 2.5.
    # After each stroke G0 to the safety plane Z2 and down again to 0.6 above the depth reached
    # (depths up to 30 mm). The first stroke at F100 x FRF 0.5.
    res = run("N10 G17 G90 G54 G0 X0 Y0 Z50\nN20 F100 S1000 M3\nN30 MCALL CYCLE83(10, 0, 2, -30, , -8, , 3, 0, 0, 0.5, 1)\n"
              "N40 X20 Y10\nN50 MCALL\nM30\n")
    depths = [-8, -13, -16, -19, -22, -25, -27.5, -30]
    expect = [(R_, 50, None), (R_, 2, None), (L_, -8, 50.0)]
    for prev, d in zip(depths, depths[1:]):
        expect += [(R_, 2, None), (R_, prev + 0.6, None), (L_, d, 100.0)]
    expect.append((R_, 10, None))
    assert zs(res) == expect
    assert {e[:2] for k, e, f in moves(res, 1)} == {(20, 10)}


def test_cycle83_chip_breaking_with_constant_strokes():
    # DAM 0: strokes of the first one (5), no stroke leaving less than 5: the last 5 halved;
    # after each stroke G0 back by _VRT 0.5.
    res = run("G0 X0 Y0 Z50 F100\nCYCLE83(10, 0, 2, -20, , -5, , 0, 0, 0, 1, 0, , , 0.5)\nM30\n")
    assert zs(res) == [(R_, 2, None), (L_, -5, 100.0), (R_, -4.5, None), (L_, -10, 100.0), (R_, -9.5, None),
                       (L_, -15, 100.0), (R_, -14.5, None), (L_, -17.5, 100.0), (R_, -17, None), (L_, -20, 100.0),
                       (R_, 10, None)]


def test_cycle83_as_fusion_writes_it_extended_and_in_strokes_of_degressing_factor():
    # Fusion's deep drilling: FDEP = RFP - peck, DAM 0, FRF 1, VARI 1, _MDEP peck, _DIS1 0,
    # AMODE 1001110. Pecks of 5 from Z0 to -12: after the first, a full one would leave 2, under
    # the minimum (DAM 0: the first stroke, 5): the 7 left are halved, 3.5 + 3.5.
    res = run("G0 X0 Y0 Z50\nF200\nMCALL CYCLE83(10, 0, 2, -12, , -5, , 0, , , 1, 1, , 5, 0, 0, 0, 0, 0, 1001110)\n"
              "X10 Y10\nMCALL\nM30\n")
    strokes = [(k, z) for k, z, f in zs(res, 2) if k == L_]
    assert strokes == [(L_, -5), (L_, -8.5), (L_, -12)]
    # DAM -0.5: each stroke half the last, not below _MDEP 1: 8, 4, 2, 1, 1, 1, 1, 1; then a full
    # one would leave 0, under 1: the last 1 halved.
    res = run("G0 X0 Y0 Z50 F100\nCYCLE83(10, 0, 2, -20, , -8, , -0.5, 0, 0, 1, 0, , 1)\nM30\n")
    assert [z for k, z, f in zs(res) if k == L_] == [-8, -12, -14, -15, -16, -17, -18, -19, -19.5, -20]


def test_cycle83_depth_rules_in_inches():
    # A G700 program (lengths and feeds in inches): the chip-breaking back-off _VRT omitted is
    # 1 mm = 1/25.4 in; F10 = 254 mm/min; FDPR 0.25 below RFP 0.1 gives FDEP -0.15; a full stroke
    # would end on DP leaving 0, under the stroke 0.25: the 0.25 left are halved.
    res = run("G700 G0 X0 Y0 Z2 F10\nCYCLE83(1, 0.1, 0.1, -0.4, , , 0.25, 0, 0, 0, 1, 0)\nM30\n")
    back = 1 / 25.4
    got = [(k, round(z / 25.4, 6), f) for k, z, f in zs(res)]
    assert got == [(R_, 0.2, None), (L_, -0.15, 254.0), (R_, round(-0.15 + back, 6), None), (L_, -0.275, 254.0),
                   (R_, round(-0.275 + back, 6), None), (L_, -0.4, 254.0), (R_, 1.0, None)]
    # G70: lengths in inches, feeds stay mm/min (CYCLE85's FFR 8 and RFF 16 too).
    res = run("G70 G0 X0 Y0 Z2 F10\nCYCLE85(1, 0, 0.1, -0.5, , 0, 8, 16)\nM30\n")
    assert [(k, round(z / 25.4, 6), f) for k, z, f in zs(res)] == [
        (R_, 0.1, None), (L_, -0.5, 8.0), (L_, 0.1, 16.0), (R_, 1.0, None)]


def test_cycle83_without_a_feed_factor_feeds_its_first_stroke_at_a_thousandth_with_a_warning():
    res = run("G0 X0 Y0 Z50 F100\nCYCLE83(10, 0, 2, -10, , -5, , 0, 0, 0, , 0)\nM30\n")
    assert [(z, f) for k, z, f in zs(res) if k == L_] == [(-5, 0.1), (-7.5, 100.0), (-10, 100.0)]
    assert [d.code for d in res.diagnostics] == ["cycle_feed_factor"]


@pytest.mark.parametrize("call, code", [
    ("CYCLE83(10,0,2,-20,,5)", "61107"),             # the first depth above RFP
    ("CYCLE83(10,0,2,-20,,-5,,0,0,0,1,2)", "61002"),  # VARI 2
    ("CYCLE83(10,0,2,-20,,0,,0,0,0,1,0)", "cycle_bad_value"),  # first stroke 0: no stroke ever advances
    ("CYCLE83(10,0,2,-20,,-5,,0,0,0,1,0,,,,,,0,0,10)", "unsupported_word"),  # AMODE 10 not CYCLE83's
])
def test_cycle83_errors(call, code):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0 Y0 Z50 F100\n{call}\nM30\n")
    assert e.value.code == code


def test_cycle84_rigid_tapping_feeds_pitch_times_speed():
    # M10 (MPIT 10: pitch 1.5), SST 800 in, SST1 1600 out: in at 1200 mm/min to -20, out at
    # 2400 mm/min to the safety plane, G0 to RTP. Fusion writes PIT and leaves MPIT out.
    for call in ["CYCLE84(10, 0, 2, -20, , , 3, 10, , 0, 800, 1600)", "CYCLE84(10, 0, 2, -20, , , 3, , 1.5, 0, 800, 1600)"]:
        res = run(f"G0 X5 Y5 Z50 F100\n{call}\nM30\n")
        assert zs(res) == [(R_, 2, None), (L_, -20, 1200.0), (L_, 2, 2400.0), (R_, 10, None)]
    # _PTAB 2: 20 threads per inch (pitch 1.27 mm) in a metric program, SST1 0 = SST.
    res = run("G0 X5 Y5 Z50 F100\nCYCLE84(10, 0, 2, -20, , , 3, , 20, 0, 500, 0, 0, 2)\nM30\n")
    assert zs(res) == [(R_, 2, None), (L_, -20, 635.0), (L_, 2, 635.0), (R_, 10, None)]


def test_cycle84_tapping_in_strokes_breaking_or_removing_chips():
    # _VARI 1, _DAM 5, _VRT 1 to -12: a first stroke of 5; 7 left, under two strokes: halved,
    # 3.5 + 3.5; backs off 1 at the retraction speed between strokes (pitch 1 x 600).
    res = run("G0 X0 Y0 Z50 F100\nCYCLE84(10, 0, 2, -12, , 0, 3, , 1, 0, 600, 600, 0, 0, 0, 1, 5, 1)\nM30\n")
    assert zs(res) == [(R_, 2, None), (L_, -5, 600.0), (L_, -4, 600.0), (L_, -8.5, 600.0), (L_, -7.5, 600.0),
                       (L_, -12, 600.0), (L_, 2, 600.0), (R_, 10, None)]
    # _VARI 2: out to the safety plane and in again to _VRT above the depth reached.
    res = run("G0 X0 Y0 Z50 F100\nCYCLE84(10, 0, 2, -12, , 0, 3, , 1, 0, 600, 600, 0, 0, 0, 2, 5, 1)\nM30\n")
    assert [z for k, z, f in zs(res)] == [2, -5, 2, -4, -8.5, 2, -7.5, -12, 2, 10]


@pytest.mark.parametrize("call, code", [
    ("CYCLE84(10,0,2,-20,,,3,,,0,800)", "61001"),      # no pitch
    ("CYCLE84(10,0,2,-20,,,3,7,,0,800)", "61001"),     # M7 is not a metric coarse size
    ("CYCLE84(10,0,2,-20,,,3,10,1.25,0,800)", "61001"),  # PIT differs from M10's 1.5
    ("CYCLE84(10,0,2,-20,,,3,,1.5,0,800,800,0,0,0,3)", "61002"),
    ("CYCLE84(10,0,2,-20,,,3,,1.5,0,800,800,0,0,0,1,30)", "61809"),  # first stroke beyond DP
    ("CYCLE84(10,0,2,-20,,,3,,1.5,0,0)", "cycle_bad_value"),  # SST 0
])
def test_cycle84_errors(call, code):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0 Y0 Z50 F100\n{call}\nM30\n")
    assert e.value.code == code


def test_cycle840_tapping_with_a_compensating_chuck():
    # With a pitch (PIT 1.25) the feed is pitch x S 400 = 500 mm/min; without one the caller's F.
    res = run("G0 X0 Y0 Z50 F80 S400 M3\nCYCLE840(10, 0, 2, -15, , 0, 4, 3, 0, , 1.25)\nM30\n")
    assert zs(res) == [(R_, 2, None), (L_, -15, 500.0), (L_, 2, 500.0), (R_, 10, None)]
    res = run("G0 X0 Y0 Z50 F80 S400 M3\nCYCLE840(10, 0, 2, -15, , 0, 4, 3, 1)\nM30\n")
    assert zs(res) == [(R_, 2, None), (L_, -15, 80.0), (L_, 2, 80.0), (R_, 10, None)]


def test_boring_cycles_85_to_89():
    start = "G0 X10 Y10 Z50 F150 S900 M3\n"
    # CYCLE85: in at FFR 200, out to the safety plane at RFF 400.
    assert zs(run(start + "CYCLE85(10, 0, 2, -20, , 0.5, 200, 400)\nM30\n")) == [
        (R_, 2, None), (L_, -20, 200.0), (L_, 2, 400.0), (R_, 10, None)]
    # CYCLE86: lift-off by RPA -0.1, RPO 0.2 and RPAP 0.5, up to the safety plane still off the
    # centre, then to RTP back on the centre.
    assert moves(run(start + "CYCLE86(10, 0, 2, -20, , 0.5, 3, -0.1, 0.2, 0.5, 30)\nM30\n"), 1) == [
        (R_, (10, 10, 2), None), (L_, (10, 10, -20), 150.0), (R_, (9.9, 10.2, -19.5), None),
        (R_, (9.9, 10.2, 2), None), (R_, (10, 10, 10), None)]
    # CYCLE87 / CYCLE88: spindle and program stop at the depth, G0 out to RTP.
    for call in ["CYCLE87(10, 0, 2, -20, , 3)", "CYCLE88(10, 0, 2, -20, , 0.5, 4)"]:
        assert zs(run(start + call + "\nM30\n")) == [(R_, 2, None), (L_, -20, 150.0), (R_, 10, None)]
    # CYCLE89: out at the feed it went in.
    assert zs(run(start + "CYCLE89(10, 0, 2, -20, , 0.5)\nM30\n")) == [
        (R_, 2, None), (L_, -20, 150.0), (L_, 2, 150.0), (R_, 10, None)]


@pytest.mark.parametrize("call", ["CYCLE86(10,0,2,-20,,0,5,0,0,0,0)", "CYCLE87(10,0,2,-20,,0)", "CYCLE88(10,0,2,-20,,0,2)"])
def test_boring_without_a_spindle_direction_is_61102(call):
    with pytest.raises(tc.ProgramError) as e:
        run(f"G0 X0 Y0 Z50 F100\n{call}\nM30\n")
    assert e.value.code == "61102"


def test_cycle801_grid_meanders_from_the_corner_nearer_the_tool():
    # 3 columns 10 apart, 2 lines 20 apart from (100, 50), unturned: lines along X (the smaller
    # spacing). The tool at X0 Y0 stands before the middle in both: start at (100, 50).
    res = run("G0 X0 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nCYCLE801(100, 50, 0, 10, 20, 3, 2)\nMCALL\nM30\n")
    assert [(x, y) for k, (x, y, z), f in moves(res) if k == L_] == [
        (100, 50), (110, 50), (120, 50), (120, 70), (110, 70), (100, 70)]
    # The tool beyond the middle in X (X500): each first line runs from the far end.
    res = run("G0 X500 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nCYCLE801(100, 50, 0, 10, 20, 3, 2)\nMCALL\nM30\n")
    assert [(x, y) for k, (x, y, z), f in moves(res) if k == L_][:3] == [(120, 50), (110, 50), (100, 50)]
    # Turned by 90 degrees: the columns run along +Y from (0, 0), the lines along -X.
    res = run("G0 X0 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nCYCLE801(0, 0, 90, 10, 20, 2, 2)\nMCALL\nM30\n")
    assert [(x, y) for k, (x, y, z), f in moves(res) if k == L_] == [(0, 0), (0, 10), (-20, 10), (-20, 0)]


def test_cycle801_with_a_count_of_zero_warns_and_takes_one():
    res = run("G0 X0 Y0 Z50 F100\nMCALL CYCLE81(10,0,2,-5)\nCYCLE801(0, 0, 0, 10, 20, 3, 0)\nMCALL\nM30\n")
    assert [(x, y) for k, (x, y, z), f in moves(res) if k == L_] == [(0, 0), (10, 0), (20, 0)]
    assert "62105" in [d.code for d in res.diagnostics]


def test_a_fusion_style_drilling_job_runs_every_cycle_modally():
    # As the 840D post writes a job: F before each cycle, MCALL, bare positions, MCALL alone.
    text = """; %_N_PLATE_MPF
N10 G90 G94 G17 G71
N11 T1 D1
N12 M6
N13 S1200 M3
N14 G0 X10 Y10
N15 G0 Z10
N16 F200
N17 MCALL CYCLE83(10, 0, 2, -20, , -5, , 0, , , 1, 1, , 5, 0, 0, 0)
N18 X10 Y10
N19 X30
N20 MCALL
N21 F120
N22 MCALL CYCLE85(10, 0, 2, -20, , 0.5, 120, 240)
N23 X10 Y30
N24 MCALL
N25 MCALL CYCLE84(10, 0, 2, -20, , , 3, , 1.5, 0, 800, 800)
N26 X30 Y30
N27 MCALL
N28 G0 SUPA Z0 D0
N29 M30
"""
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=4.0, length=[0.0, 0.0, 100.0])]))
    res = run(text, tools=t)
    feeds = sorted({round(float(f), 6) for k, f in zip(res.nominal.kind, res.nominal.feed) if k == tc.LINE})
    assert feeds == [120.0, 200.0, 240.0, 1200.0]
    bottoms = [(round(float(e[0]), 6), round(float(e[1]), 6)) for k, e in zip(res.nominal.kind, res.nominal.end)
               if k == tc.LINE and round(float(e[2]), 6) == -20]
    assert bottoms == [(10, 10), (30, 10), (10, 30), (30, 30)]
