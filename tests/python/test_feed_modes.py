"""Feed modes: LinuxCNC sets the feed rate to 0 at every G93/G94/G95 (an F in the same block
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
