"""Feed modes: LinuxCNC sets the feed rate to 0 at every G94/G95 (an F in the same block
is read after it), feed per revolution needs a spindle speed; the profile switch, and Fanuc
keeping its F (tests/programs/errors/feed_* hold the same cases checked against rs274)."""
import pytest

import toolcomp as tc

HEAD = "G21 G90 G94 F300\nG0 X0 Y0 Z0\n"


def run(text, dialect="linuxcnc", profile=None):
    return tc.run(tc.Program.parse(HEAD + text + "M2\n", dialect=dialect), profile=profile)


@pytest.mark.parametrize("text, line", [("G94\nG1 X1\n", 4), ("G93\nG1 X1 F1\nG94\nG1 X2\n", 6),
                                        ("S100 M3\nG95\nG1 X2\n", 5)])
def test_a_feed_mode_word_clears_the_feed(text, line):
    with pytest.raises(tc.ProgramError) as e:
        run(text)
    assert (e.value.code, e.value.message, e.value.line) == ("zero_feed", "Cannot do g1 with zero feed rate", line)


def test_an_f_word_in_the_same_block_is_read_after_it():
    assert run("G94 F200\nG1 X1\n").path.feed[-1] == 200
    # per revolution: 0.1 mm/rev at 1000 rev/min
    assert run("S1000 M3\nG95 F0.1\nG1 X10\n").path.feed[-1] == pytest.approx(100)


def test_the_profile_switch_and_fanuc():
    prof = tc.ControlProfile("linuxcnc")
    prof.feed_mode_clears_feed = False
    assert run("G94\nG1 X1\n", profile=prof).path.feed[-1] == 300
    assert tc.ControlProfile("fanuc").feed_mode_clears_feed is False
    assert run("G94\nG1 X1\n", dialect="fanuc").path.feed[-1] == 300


@pytest.mark.parametrize("move", ["G1 X10", "G2 X10 Y0 R5"])
def test_feed_per_revolution_needs_a_spindle_speed(move):
    for speed in ("", "S0 M3 "):
        with pytest.raises(tc.ProgramError) as e:
            run(f"{speed}G95 F0.1\n{move}\n")
        assert (e.value.code, e.value.line) == ("zero_spindle_speed", 4)
        assert e.value.message == "Cannot feed with zero spindle speed in feed per rev mode"


def test_feed_per_revolution_at_constant_surface_speed():
    # G96 S200 (m/min) D2000 (rev/min at most), G95 F0.2 mm/rev, lathe radius mode: at the
    # end of each move the spindle turns 200 000 / (2 pi r) rev/min, r the X radius in mm.
    text = ("G21 G18 G8 G0 X60 Z5\nG96 D2000 S200 M3\nG95 F0.2\nG1 X50 Z0\nG1 X10\nG1 X0\n"
            "G7 G1 X40\nG97 S1000\nG1 Z-5\nM2\n")
    feed = tc.run(tc.Program.parse(text)).path.feed
    import math
    assert feed[1] == pytest.approx(0.2 * 200_000 / (2 * math.pi * 50))  # 127.32 mm/min
    assert feed[2] == pytest.approx(0.2 * 2000)  # r = 10: 3183 rev/min, held to 2000
    assert feed[3] == pytest.approx(0.2 * 2000)  # at the axis
    assert feed[4] == pytest.approx(0.2 * 200_000 / (2 * math.pi * 20))  # G7: X40 is a radius of 20
    assert feed[5] == pytest.approx(0.2 * 1000)  # G97: S is rev/min again
    # in inch: S in ft/min (304.8 mm), F in inch/rev
    inch = tc.run(tc.Program.parse("G20 G18 G8 G0 X3 Z1\nG96 S500 M3\nG95 F0.01\nG1 X2\nG1 X0\nM2\n")).path.feed
    assert inch[1] == pytest.approx(0.01 * 25.4 * 500 * 304.8 / (2 * math.pi * 2 * 25.4))
    assert math.isnan(inch[2])  # at the axis without D the spindle speed is not known


def test_g96_without_d_has_no_speed_limit():
    import math
    text = "G21 G18 G8 G0 X60 Z5\nG96 D500 S200 M3\nG95 F0.2\nG1 X10\nG97 S1000\nG96 S200\nG1 X10 Z0\nM2\n"
    feed = tc.run(tc.Program.parse(text)).path.feed
    assert feed[1] == pytest.approx(0.2 * 500)  # held to D500
    assert feed[2] == pytest.approx(0.2 * 200_000 / (2 * math.pi * 10))  # the later G96 has no D


def test_g96_cycle_feeds_follow_the_hole():
    # G96 S100 without D, G95 F0.1: drilling at X10 turns at 100 000 / (2 pi 10) rev/min
    # wherever the tool came from (X0 before the cycle: no speed there).
    text = "G21 G17 G90 G0 X0 Y0 Z5\nG96 S100 M3\nG95 F0.1\nG81 X10 Y0 Z-1 R2\nG80\nM2\n"
    p = tc.run(tc.Program.parse(text)).path
    fed = p.kind == tc.LINE
    assert fed.sum() == 1
    assert p.feed[fed][0] == pytest.approx(0.1 * 100_000 / (2 * 3.141592653589793 * 10))
