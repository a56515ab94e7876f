"""G-code system A's single cycles and threading on Fanuc and Haas lathes: G90 turning, G92
threading, G94 facing (modal: a block with only X or Z repeats them), G32 thread cutting.
Numbers by hand: X words are diameters (radius = X / 2); feeds per revolution times S."""
import numpy as np
import pytest

import toolcomp as tc

PROGRAM = """\
G21 G18 G97 S500 M3
G99
G0 X32 Z5
G92 X29.3 Z-20 F1.5
X28.9
X28.6
G0 X40
G90 X25 Z-30 F0.2
X20
G94 X10 Z-2 F0.1
Z-4
G32 Z-10 F1.0
M30
"""


def _run(text, **kw):
    return tc.run(tc.Program.parse(text, dialect="fanuc"), machine=kw.pop("machine", "lathe"), **kw)


def _rows(res, line):
    sel = res.nominal.line == line
    return res.nominal.end[sel][:, [0, 2]], res.nominal.kind[sel], res.nominal.feed[sel]


def test_g92_threads_pass_by_pass_from_its_start_point():
    res = _run(PROGRAM)
    # From A (radius 16, Z5): rapid to the pass's X, the thread at 1.5 mm/rev x 500 rev/min
    # = 750 mm/min, rapid out to A's X, rapid back to A's Z. X28.9, X28.6 repeat it.
    for line, x in [(4, 14.65), (5, 14.45), (6, 14.3)]:
        ends, kinds, feeds = _rows(res, line)
        np.testing.assert_allclose(ends, [(x, 5), (x, -20), (16, -20), (16, 5)])
        assert list(kinds) == [tc.RAPID, tc.LINE, tc.RAPID, tc.RAPID]
        assert feeds[1] == 750


def test_g90_turns_and_g94_faces():
    res = _run(PROGRAM)
    ends, kinds, feeds = _rows(res, 8)  # from A (20, 5): 0.2 mm/rev x 500 = 100 mm/min
    np.testing.assert_allclose(ends, [(12.5, 5), (12.5, -30), (20, -30), (20, 5)])
    assert list(kinds) == [tc.RAPID, tc.LINE, tc.LINE, tc.RAPID] and feeds[1] == feeds[2] == 100
    np.testing.assert_allclose(_rows(res, 9)[0], [(10, 5), (10, -30), (20, -30), (20, 5)])  # X20 repeats, Z kept
    ends, kinds, feeds = _rows(res, 10)  # G94: Z first, feed along X, back along Z
    np.testing.assert_allclose(ends, [(20, -2), (5, -2), (5, 5), (20, 5)])
    assert list(kinds) == [tc.RAPID, tc.LINE, tc.LINE, tc.RAPID] and feeds[1] == 50
    np.testing.assert_allclose(_rows(res, 11)[0], [(20, -4), (5, -4), (5, 5), (20, 5)])  # Z-4 repeats, X kept


def test_g32_cuts_a_thread_at_lead_times_speed():
    ends, kinds, feeds = _rows(_run(PROGRAM), 12)
    np.testing.assert_allclose(ends, [(20, -10)])
    assert kinds[0] == tc.LINE and feeds[0] == 500  # F1.0 is the lead: 1 mm x 500 rev/min


def test_a_taper_r_moves_the_start_of_the_cut():
    # G90 R-2 (radius): the cut starts 2 mm below its end's radius 12.5.
    res = _run("G21 G18 G97 S500 M3\nG99\nG0 X40 Z5\nG90 X25 Z-30 R-2 F0.2\nM30\n")
    np.testing.assert_allclose(_rows(res, 4)[0], [(10.5, 5), (12.5, -30), (20, -30), (20, 5)])


def test_inch_on_haas_lathe():
    # G20: X1.0 diameter = radius 12.7 mm; G92 F0.0625 (16 TPI) at S400: 25 in/min. Haas
    # ends the thread with a chamfer of one lead (setting 95) at 45 degrees (setting 96): the
    # thread stops 0.0625 short of Z-1 and pulls out 0.0625 (radius) to Z-1; M24 turns it off.
    text = "G20 G18 G97 S400 M3\nG99\nG0 X1.2 Z0.2\nG92 X0.95 Z-1. F0.0625\nX0.93\nG0 X3.\nM30\n"
    res = _run(text, machine="haas-lathe")
    ends, kinds, feeds = _rows(res, 4)
    np.testing.assert_allclose(ends / 25.4, [(0.475, 0.2), (0.475, -0.9375), (0.5375, -1), (0.6, -1), (0.6, 0.2)])
    assert list(kinds) == [tc.RAPID, tc.LINE, tc.LINE, tc.RAPID, tc.RAPID]
    assert feeds[1] == pytest.approx(0.0625 * 400 * 25.4)
    res = _run(text.replace("G99", "G99 M24"), machine="haas-lathe")
    np.testing.assert_allclose(_rows(res, 4)[0] / 25.4, [(0.475, 0.2), (0.475, -1), (0.6, -1), (0.6, 0.2)])
    res = _run(text, machine="fanuc-lathe")  # parameter 5130 at 0: no chamfer
    np.testing.assert_allclose(_rows(res, 4)[0] / 25.4, [(0.475, 0.2), (0.475, -1), (0.6, -1), (0.6, 0.2)])


def test_haas_one_block_g76():
    # G76 X27.546 Z-20 K1.227 D0.4 A60 F2 from A (X34 Z5, radius 17): passes at 0.4 sqrt(n)
    # while short of K (n = 1 ... 9: 0.4 ... 1.2), then one at K = 1.227. Pass at depth d: X
    # (radius) 13.773 + 1.227 - d = 15 - d, Z moved by -d tan 30; the thread to Z-20 (moved
    # alike) less the chamfer of one lead (2 mm), out 2 mm at 45 degrees, rapid to A's X, to A.
    res = _run("G21 G18 G97 S500 M3\nG0 X34 Z5\nG76 X27.546 Z-20 K1.227 D0.4 A60 F2\nM30\n", machine="haas-lathe")
    ends, kinds, _ = _rows(res, 3)
    t = np.tan(np.radians(30))
    depths = [0.4 * np.sqrt(n) for n in range(1, 10)] + [1.227]
    expected = []
    for d in depths:
        x, s = 15 - d, -d * t
        expected += [(x, 5 + s), (x, -20 + s + 2), (x + 2, -20 + s), (17, -20 + s), (17, 5)]
    np.testing.assert_allclose(ends, expected, atol=1e-9)
    assert list(kinds[:5]) == [tc.RAPID, tc.LINE, tc.LINE, tc.RAPID, tc.RAPID]
    # Settings 86 (finishing allowance) and 99 (least cut), in mm, from the machine: with
    # 0.05 and 0.2 the passes are 0.4, 0.6, 0.8, 1.0 (each at least 0.2 deeper), then
    # 1.177 (K less the allowance) and 1.227.
    m = tc.Machine.preset("haas-lathe")
    profile = m.profile
    profile.thread_finish_allowance, profile.thread_min_cut = 0.05, 0.2
    m.profile = profile
    res = _run("G21 G18 G97 S500 M3\nG0 X34 Z5\nG76 X27.546 Z-20 K1.227 D0.4 A60 F2 M24\nM30\n", machine=m)
    ends, kinds, _ = _rows(res, 3)
    np.testing.assert_allclose(ends[1::4, 0], [15 - d for d in (0.4, 0.6, 0.8, 1.0, 1.177, 1.227)], atol=1e-9)


@pytest.mark.parametrize("text, code, line", [
    ("G21 G18 G97 S500 M3\nG0 X30 Z5\nG92 X28 F1.5\nM30\n", "cycle_bad_value", 3),  # no Z
    ("G21 G18 G97 M3\nG0 X30 Z5\nG92 X28 Z-10 F1.5\nM30\n", "zero_spindle_speed", 3),

    ("G21 G18 G97 S500 M3\nG0 X30 Z5\nG76 X28 Z-10 K1 D0.3 F1.5 P2\nM30\n", "unsupported_word", 3),  # Haas P2
    ("G21 G18 G97 S500 M3\nG0 X30 Z5\nG76 X28 Z-10 K1 D0.3 F1.5 A60.5\nM30\n", "cycle_bad_value", 3),
    ("G21 G18 G97 S500 M3\nG0 X30 Z5\nG76 X28 Z-10 K1 F1.5\nM30\n", "cycle_bad_value", 3),  # no D
])
def test_what_is_refused(text, code, line):
    with pytest.raises(tc.ProgramError) as e:
        _run(text)
    assert (e.value.code, e.value.line) == (code, line), str(e.value)


def test_a_fanuc_mill_keeps_g90_g92_g94():
    res = tc.run(tc.Program.parse("G21 G17 G90 G94 G0 X10 Y10\nG92 X0 Y0\nG1 X5 F100\nM30\n", dialect="fanuc"))
    np.testing.assert_allclose(res.nominal.end[-1], [5, 0, 0])


# ---- G76 ----------------------------------------------------------------------------------------

G76 = """\
G21 G18 G97 S600 M3
G0 X32 Z5
G76 P020060 Q100 R0.05
G76 X28.16 Z-20 P920 Q300 F1.5
M30
"""


def test_g76_threads_in_passes_of_falling_depth():
    # Height P920 = 0.92 mm, first depth Q300 = 0.3, least Q100 = 0.1, allowance R0.05, two
    # finishing passes (P02..), 60 degrees. Depths 0.3*sqrt(n), at least 0.1 more each time:
    # 0.3, 0.424264, 0.524264, 0.624264, 0.724264, 0.824264, then 0.87 (= 0.92 - 0.05), then
    # 0.92 twice. Each pass: rapid to X (radius) = root 14.08 + 0.92 - depth, its Z moved by
    # -depth * tan(30 deg) along the flank, the thread at 1.5 x 600 = 900 mm/min, rapid out to
    # X16, rapid back to Z5.
    res = tc.run(tc.Program.parse(G76, dialect="fanuc"), machine="lathe")
    depths = [0.3, 0.3 * 2 ** 0.5, 0.3 * 2 ** 0.5 + 0.1, 0.3 * 2 ** 0.5 + 0.2, 0.3 * 2 ** 0.5 + 0.3,
              0.3 * 2 ** 0.5 + 0.4, 0.87, 0.92, 0.92]
    expected = []
    for d in depths:
        x, s = 14.08 + 0.92 - d, -d * np.tan(np.radians(30))
        expected += [(x, 5 + s), (x, -20 + s), (16, -20 + s), (16, 5)]
    sel = res.nominal.line == 4
    np.testing.assert_allclose(res.nominal.end[sel][:, [0, 2]], expected, atol=1e-9)
    feeds = res.nominal.feed[sel]
    assert list(feeds[1::4]) == [900.0] * len(depths)


def test_g76_chamfer_pulls_out_at_45_degrees():
    # P011060: one finishing pass, chamfer 10 tenths of the lead (1.5 mm): the thread ends
    # 1.5 mm early and pulls out 1.5 mm (radius) at 45 degrees to the end Z.
    res = tc.run(tc.Program.parse(G76.replace("P020060", "P011060"), dialect="fanuc"), machine="lathe")
    sel = res.nominal.line == 4
    ends = res.nominal.end[sel][:, [0, 2]]
    x, s = 14.7, -0.3 * np.tan(np.radians(30))
    np.testing.assert_allclose(ends[:5], [(x, 5 + s), (x, -18.5 + s), (x + 1.5, -20 + s), (16, -20 + s), (16, 5)],
                               atol=1e-9)


@pytest.mark.parametrize("change", [("Q300", "Q0"), ("P920 Q300", "P920.5 Q300"), ("P020060", "P020061"),
                                    ("R0.05", "R1.0")])
def test_g76_refuses_what_the_control_refuses(change):
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(G76.replace(*change), dialect="fanuc"), machine="lathe")
    assert e.value.code == "cycle_bad_value" and e.value.line in (3, 4)
