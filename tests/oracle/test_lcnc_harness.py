"""Self-test of the rs274 side of the oracle (tests/oracle/lcnc.py), independent of toolcomp.

Every expected number here is worked out by hand from the program text, so a wrong plane
remap, unit conversion, tool-table conversion or offset bookkeeping in the parser shows up
here and not as a mysterious toolcomp mismatch.
"""
import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import lcnc  # noqa: E402

pytestmark = pytest.mark.skipif(not lcnc.available(), reason="LinuxCNC rs274 not installed")

TOL_MM = lcnc.PRINT_TOL
NAN = float("nan")


def _run(tmp_path, text, table=None):
    prog = tmp_path / "p.ngc"
    prog.write_text(text)
    tbl = None
    if table is not None:
        tbl = tmp_path / "t.tbl"
        tbl.write_text(table)
    return lcnc.nominal(prog, tbl)


def _close(a, b, tol):
    a, b = np.asarray(a, float), np.asarray(b, float)
    both_nan = np.isnan(a) & np.isnan(b)
    return bool(np.all(both_nan | (np.abs(a - b) <= tol)))


def test_mm_table_conversion():
    out = lcnc.mm_table_to_inch("T1 P1 X2.54 Z25.4 D12.7 I95 J155 Q2 ;c\n\n")
    toks = out.split(";")[0].split()
    assert toks[0] == "T1" and toks[1] == "P1"
    assert float(toks[2][1:]) == pytest.approx(0.1)
    assert float(toks[3][1:]) == pytest.approx(1.0)
    assert float(toks[4][1:]) == pytest.approx(0.5)
    assert toks[5:] == ["I95", "J155", "Q2"]
    assert out.rstrip().endswith(";c")


def test_metric_program_planes_and_tlo(tmp_path):
    d = _run(tmp_path, "\n".join([
        "G21 G17 G90 F250",
        "G0 X10 Y0 Z5",          # rapid
        "T1 M6",
        "G43 H1",                # TLO z 25 (table in mm, converted for rs274's inch bug)
        "G1 Z-1",                # feed 250
        "G3 X0 Y10 I-10 J0",     # ccw quarter, centre (0,0)
        "G18",
        "G2 X-10 Z-1 Y3 I-5 K0",  # XZ plane: start (0,10,-1), centre x=-5 z=-1, helix in Y
        "G19",
        "G3 Y3 Z-1 J0 K2 X-10 P2",  # YZ full circle (start==end), 2 turns, centre y=3 z=1
        "G49",
        "G0 Z10",
        "M2", ""]), "T1 P1 Z25 D10\n")
    assert d["kind"].tolist() == [0, 1, 3, 2, 3, 0]
    assert _close(d["end"], [[10, 0, 5], [10, 0, -1], [0, 10, -1], [-10, 3, -1],
                             [-10, 3, -1], [-10, 3, 10]], TOL_MM)
    # centres: in-plane from rs274, normal-axis component = the start's
    assert _close(d["center"], [[NAN] * 3, [NAN] * 3, [0, 0, -1], [-5, 10, -1],
                                [-10, 3, 1], [NAN] * 3], TOL_MM)
    assert d["turns"].tolist() == [0, 0, 1, -1, 2, 0]
    assert d["plane"].tolist() == [17, 17, 17, 18, 19, 19]
    assert _close(d["tool_offset"][:, 2], [0, 25, 25, 25, 25, 0], TOL_MM)
    assert _close(d["feed"], [NAN, 250, 250, 250, 250, NAN], 0)
    # program position is re-expressed when the TLO changes (machine does not move):
    # after G43 H1 at Z5 the current program Z is 5 - 25 = -20
    assert _close(d["start"][1], [10, 0, -20], TOL_MM)
    # and after G49 at Z-1 (machine 24) it is 24
    assert _close(d["start"][5], [-10, 3, 24], TOL_MM)
    # sweep: quarter ccw, half cw, two full turns
    assert lcnc.sweep(d["start"][2], d["end"][2], d["center"][2], False, 17) == pytest.approx(math.pi / 2)
    assert lcnc.sweep(d["start"][3], d["end"][3], d["center"][3], True, 18) == pytest.approx(math.pi)
    assert lcnc.sweep(d["start"][4], d["end"][4], d["center"][4], False, 19, 2) == pytest.approx(4 * math.pi)


def test_inch_program_converted_to_mm(tmp_path):
    d = _run(tmp_path, "\n".join([
        "G20 G17 G90",
        "F10",                      # (F in the G20 block would be read in the old units: mm)
        "G0 X1 Y0.5",
        "T2 M6",                    # (G43 in the M6 block hits an rs274 resync quirk, see lcnc.py)
        "G43 H2",                   # table (mm): X1 Z30.5 -> rs274 sees inches, we report mm
        "G1 X2 Y0.5 A45",           # feed 10 in/min = 254 mm/min, A in degrees unscaled
        "G2 X3 Y0.5 R0.5",          # semicircle cw, centre (2.5, 0.5) in
        "M2", ""]), "T2 P2 X1 Z30.5 D6\n")
    assert d["kind"].tolist() == [0, 1, 2]
    assert _close(d["end"], [[25.4, 12.7, 0], [50.8, 12.7, -30.5], [76.2, 12.7, -30.5]],
                  TOL_MM * 25.4 * 1.01)
    assert _close(d["center"][2], [63.5, 12.7, -30.5], TOL_MM * 25.4)
    assert _close(d["feed"][1:], [254.0, 254.0], 1e-9)
    assert _close(d["abc"][1], [45, 0, 0], 1e-9)
    # 1 mm = 0.0394 in printed -> 1.00076 mm; 30.5 mm = 1.2008 in -> 30.50032 mm
    assert _close(d["tool_offset"][1], [1, 0, 30.5], TOL_MM * 25.4)
    assert d["units"].tolist() == [25.4] * 3


def test_offsets_bookkeeping(tmp_path):
    d = _run(tmp_path, "\n".join([
        "G21 F100",
        "G0 X10 Y10",
        "G92 X0 Y0",            # G92 offset (10,10): current point becomes (0,0)
        "G1 X5",
        "G10 L2 P1 X100",       # active system moves: program X = 15 - 100 - 10 = -95
        "G1 Y1",
        "G92.1",                # program X = 15 - 100 = -85, Y = 11
        "G0 X0",
        "M2", ""]))
    assert _close(d["start"], [[0, 0, 0], [0, 0, 0], [-95, 0, 0], [-85, 11, 0]], TOL_MM)
    assert _close(d["end"], [[10, 10, 0], [5, 0, 0], [-95, 1, 0], [0, 11, 0]], TOL_MM)


def test_error_message_and_line(tmp_path):
    prog = tmp_path / "e.ngc"
    prog.write_text("G21 F100\nG0 X0 Y0\nG2 X10 Y0 R4\nM2\n")
    e = lcnc.run_error(prog)
    assert e.message == "Arc radius too small to reach end point"
    assert e.source == "G2 X10 Y0 R4"
    assert e.line == 3
    prog.write_text("G21 F100\nG1 X1\nM2\n")
    assert lcnc.run_error(prog) is None


def test_generated_programs_are_valid_for_rs274(tmp_path):
    import generate
    assert generate.generate(7) == generate.generate(7)          # deterministic
    for seed in range(10):
        prog = tmp_path / ("g%d.ngc" % seed)
        prog.write_text(generate.generate(seed))
        e = lcnc.run_error(prog, Path(__file__).resolve().parents[2] / "tests/programs/oracle/tools.tbl")
        assert e is None, (seed, e)


def test_compare_accepts_split_full_turns():
    """compare.py matches one rs274 ARC_FEED with turn=2 against two 360-degree toolcomp segments."""
    import compare
    rs = {"kind": np.array([3]), "start": np.array([[10.0, 0, 0]]), "end": np.array([[10.0, 0, -2]]),
          "center": np.array([[0.0, 0, 0]]), "turns": np.array([2]), "abc": np.zeros((1, 3)),
          "tool_offset": np.zeros((1, 3)), "feed": np.array([100.0]), "plane": np.array([17]),
          "units": np.array([1.0])}
    tc = {"kind": np.array([3, 3]), "start": np.array([[10.0, 0, 0], [10.0, 0, -1]]),
          "end": np.array([[10.0, 0, -1], [10.0, 0, -2]]), "center": np.array([[0.0, 0, 0], [0.0, 0, -1]]),
          "abc": np.zeros((2, 3)), "tool_offset": np.zeros((2, 3)), "feed": np.array([100.0, 100.0])}
    compare.compare(rs, tc)
    tc_one = {k: v[:1].copy() for k, v in tc.items()}
    tc_one["end"] = np.array([[10.0, 0, -2]])
    with pytest.raises(compare.Mismatch):           # one revolution is not two
        compare.compare(rs, tc_one)


def test_long_block_numbers_and_feed_per_revolution(tmp_path):
    # rs274 pads N to six characters: "N1006941SET_FEED_RATE(...)" runs into the name. G95:
    # F0.2 mm/rev at S1000 is 200 mm/min, toolcomp's column; under G96 the speed follows X
    # and the feed is not compared (NaN).
    p = tmp_path / "n.ngc"
    p.write_text("G21 G90 G95 S1000 M3\nN1006941 G1 X10 F0.2\nN5 G94 X20 F100\nG95 G96 S100 D2000 X30 F0.1\nM2\n")
    rs = lcnc.nominal(str(p))
    np.testing.assert_allclose(rs["end"][:, 0], [10, 20, 30])
    np.testing.assert_allclose(rs["feed"][:2], [200, 100])
    assert np.isnan(rs["feed"][2])


@pytest.mark.parametrize("plane, block", [("G18", "G99 G84 X5 Z20 Y-8 R2 F100"), ("G19", "G99 G84 Y5 Z7 X-8 R2 F100")])
def test_g84_off_the_xy_plane_is_reported_where_linuxcnc_feeds(plane, block, tmp_path):
    # LinuxCNC 2.9 feeds G84 in G18/G19 to the plane's coordinates in another axis order; toolcomp
    # keeps the tap on the hole's axis and its warning names the point rs274 feeds to.
    import toolcomp as tc
    p = tmp_path / "g84.ngc"
    p.write_text(f"G21 {plane} G90 G94 S500 M3\nG0 X0 Y0 Z0\n{block}\nG80\nM2\n")
    rs = lcnc.nominal(str(p))
    feed_to = rs["end"][rs["kind"] == lcnc.LINE][0]
    res = tc.run(tc.Program.read(str(p)), start="machine_zero")
    (w,) = [d for d in res.diagnostics if d.code == "g84_off_axis"]
    assert w.line == 3
    assert "X%.4f Y%.4f Z%.4f" % tuple(feed_to) in w.message
