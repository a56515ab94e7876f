"""LinuxCNC's G33, G33.1, G76 and the $ word. Paths are compared with rs274 and the gcode
module in tests/programs/oracle/threading_*.ngc and the errors in tests/programs/errors/g33_*,
g76_*, dollar_*; here the numbers worked by hand from LinuxCNC's convert_threading_cycle and
threading_pass (the pass depths of its manual's example and of rs274 runs)."""
import math

import numpy as np
import pytest

import toolcomp as tc


def _run(text, **kw):
    return tc.run(tc.Program.parse(text), **kw)


def test_g33_feeds_its_lead_per_revolution_and_leaves_f_alone():
    res = _run("G21 G18 S300 M3\nG0 X5 Z3\nG1 F200 X5.1\nG33 Z-20 K1.5\nG1 X8\nM2\n")
    assert res.nominal.feed.tolist()[2:] == [450.0, 200.0]  # 1.5 mm/rev x 300 rev/min; F200 after


def test_g33_1_taps_in_and_back_out_faster_by_i():
    res = _run("G21 G17 S500 M3\nG0 X10 Y10 Z2\nG33.1 Z-8 K1.25 I2\nG0 X20\nM2\n")
    ends = np.round(res.nominal.end, 9).tolist()
    assert ends[1:] == [[10, 10, -8], [10, 10, 2], [20, 10, 2]]  # back where it began, and on from there
    assert res.nominal.feed.tolist()[1:3] == [625.0, 1250.0]     # out with the spindle twice as fast


def _pass_depths(res, start_x):
    # each pass's cutting move: a line parallel to Z at X = start_x - depth
    n = res.nominal
    cuts = [i for i in range(len(n.kind)) if n.kind[i] == 1 and n.start[i][0] == n.end[i][0]]
    return [round(start_x - n.end[i][0], 9) for i in cuts]


def test_g76_pass_depths():
    # I-1 J0.3 K0.92 from X10: depths J*n beyond the crest while below K (0.3, 0.6, 0.9), then K
    res = _run("G21 G18 S300 M3\nG0 X10 Z2\nG76 P1.5 Z-20 I-1 J0.3 K0.92\nM2\n")
    assert _pass_depths(res, 10) == [1.3, 1.6, 1.9, 1.92]
    assert res.nominal.end[-1].tolist() == [10, 0, -20]
    # R2: J sqrt(n); H2: two spring passes at full depth
    res = _run("G21 G18 S300 M3\nG0 X10 Z2\nG76 P1.5 Z-20 I-1 J0.3 K0.92 R2 H2\nM2\n")
    want = [round(1 + 0.3 * np.sqrt(n), 9) for n in range(1, 10) if 0.3 * np.sqrt(n) < 0.92] + [1.92] * 3
    assert _pass_depths(res, 10) == want


def test_g76_compound_angle_moves_each_pass_along_z():
    # Q30: a pass at depth d beyond the crest starts (d - |I| ... ) * tan 30 further back in Z
    res = _run("G21 G18 S300 M3\nG0 X10 Z2\nG76 P1.5 Z-20 I-1 J0.3 K0.92 Q30\nM2\n")
    n = res.nominal
    first_back = n.end[1]  # the first move after the approach: back to the pass's start
    assert first_back[2] == pytest.approx(2 - 0.3 * np.tan(np.radians(30)), abs=1e-12)
    last_cut = [i for i in range(len(n.kind)) if n.kind[i] == 1][-1]
    assert n.end[last_cut][2] == pytest.approx(-20.0, abs=1e-12)  # full depth ends at Z


def test_g76_in_diameter_mode_takes_diameters():
    a = _run("G21 G18 S300 M3\nG0 X10 Z2\nG76 P1.5 Z-20 I-1 J0.3 K0.92\nM2\n")
    b = _run("G21 G18 G7 S300 M3\nG0 X20 Z2\nG76 P1.5 Z-20 I-2 J0.6 K1.84\nM2\n")
    assert np.allclose(a.nominal.end, b.nominal.end, atol=1e-12)


def test_g7_in_the_g76_block_scales_twice_as_linuxcnc_does():
    res = _run("G21 G18 G8 S300 M3\nG0 X10 Z2\nG7 G76 P1.5 Z-20 I-2 J0.6 K1.84\nM2\n")
    assert _pass_depths(res, 10)[0] == pytest.approx(0.5 + 0.15)  # I/4 + J/4
    assert [d.code for d in res.diagnostics if d.severity == "warning"] == ["g76_diameter_block"]


def test_g76_modal_repeat_needs_its_words_again():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G18 S300 M3\nG0 X10 Z2\nG76 P1.5 Z-20 I-1 J0.3 K0.92\nZ-10\nM2\n")
    assert (str(e.value.message), e.value.line) == ("P word missing with G76", 4)


@pytest.mark.parametrize("block, message", [
    ("M3 $1", "Spindle ($) number out of range in M3 Command"),
    ("S100 $1 M3", "Invalid spindle ($) number in Spindle speed command"),
    ("G97 S100 $1", "Invalid spindle ($) number in Spindle Mode command"),
    ("M3 S100 $0\nG33 Z-1 K1 $-1", "Invalid spindle ($) number in G33 move"),
])
def test_a_machine_with_one_spindle(block, message):
    with pytest.raises(tc.ProgramError) as e:
        _run(f"G21 G18\n{block}\nM2\n")
    assert (str(e.value.message), e.value.code) == (message, "spindle_choice")


def test_dollar_zero_and_all_spindles_are_the_one_spindle():
    res = _run("G21 G18\nS300 M3 $-1\nG0 X5 Z2\nG33 Z-10 K2 $0.9\nM5 $-1\nM2\n")
    assert res.nominal.feed.tolist()[-1] == 600.0


def test_other_dialects_have_no_dollar_word():
    with pytest.raises(tc.ParseError):
        tc.Program.parse("G21 M3 $0\nM30\n", "fanuc")


def _two_spindles():
    m = tc.Machine("linuxcnc", "lathe", "two spindles")
    m.spindles = 2  # LinuxCNC [TRAJ]SPINDLES = 2
    return m


def test_a_machine_with_two_spindles_feeds_by_the_one_chosen():
    # The canonical calls of rs274 with SPINDLES = 2 for this program: spindle 0 at 800 rev/min
    # clockwise, spindle 1 at 1500 counter-clockwise, then G96 S200 D3000 on spindle 1, G95
    # feeding by spindle 1 (SET_FEED_MODE(1, 1)), G95 again without $: by spindle 0.
    text = """G21 G18 G90 G94
S800 M3
S1500 M4 $1
G96 S200 D3000 $1
G95 F0.2 S200 $1
G0 X20 Z2
G1 Z-10
G1 X30
G95 F0.1
G1 Z-20
M5 $1
(DEBUG, rpm=#<_rpm> on=#<_spindle_on>)
G33 Z-30 K1 $0
M5
(DEBUG, on=#<_spindle_on>)
M3 $-1
S300 $-1
G33 Z-40 K2 $1
M2
"""
    res = tc.run(tc.Program.parse(text), machine=_two_spindles())
    css = lambda v, x: v * 1000 / (2 * math.pi * x)  # rev/min at radius x (mm) for v m/min
    np.testing.assert_allclose(res.nominal.feed[1:], [
        0.2 * css(200, 20),   # spindle 1 under G96, at X20
        0.2 * css(200, 30),   # at X30
        0.1 * 800,            # G95 without $: spindle 0, 800 rev/min
        1 * 800,              # G33 K1 $0
        2 * css(300, 30),     # G33 K2 $1: S300 $-1 is spindle 1's surface speed (G96 on it)
    ], rtol=1e-12)
    # #<_rpm> and #<_spindle_on> read spindle 0 (rs274: " rpm=800.000000 on=1.000000", then
    # " on=0.000000": M5 without $ stops spindle 0 on LinuxCNC 2.9.0)
    assert [d.message for d in res.diagnostics if d.code == "message"] == [" rpm=800.000000 on=1.000000",
                                                                          " on=0.000000"]


def test_two_spindles_and_the_dollar_limits():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21 G18\nM3 $2\nM2\n"), machine=_two_spindles())
    assert str(e.value.message) == "Spindle ($) number out of range in M3 Command"
    with pytest.raises(tc.ProgramError) as e:  # spindle 1 stopped: G33 on it cannot start
        tc.run(tc.Program.parse("G21 G18\nS500 M3\nG0 X5 Z2\nG33 Z-5 K1 $1\nM2\n"), machine=_two_spindles())
    assert str(e.value.message) == "Spindle not turning in G33"
    m = _two_spindles()
    assert tc.Machine.parse(m.dumps()).spindles == 2 and "spindles = 2" in m.dumps()
    with pytest.raises(tc.ParseError, match="spindles must be a whole number from 1 to 8") as e:
        tc.Machine.parse('control = "linuxcnc"\nspindles = 9\n')
    assert e.value.line == 2
