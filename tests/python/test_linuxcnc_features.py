"""LinuxCNC features: polar coordinates (@ radius, ^ angle), whose paths are compared with rs274
and the gcode module in tests/programs/oracle/polar_coordinates.ngc and its errors in
tests/programs/errors/polar_*.ngc (here what toolcomp refuses on its own, and one path worked
by hand)."""
import numpy as np
import pytest

import toolcomp as tc


def test_a_bolt_circle_of_holes_with_g91_polar_repeats():
    # G81 at @30 ^0, then G91 ^90 L3: holes at 90, 180, 270 degrees on radius 30.
    res = tc.run(tc.Program.parse("G21 G17 G0 X0 Y0 Z5\nG81 @30 ^0 R1 Z-2 F100\nG91 G81 ^90 R-4 Z-3 L3\nG80\nM2\n"))
    holes = res.nominal.end[(res.nominal.kind == tc.LINE)][:, :2]
    np.testing.assert_allclose(holes, [(30, 0), (0, 30), (-30, 0), (0, -30)], atol=1e-12)


def test_linuxcnc_polar_coordinates_with_codes_that_read_axis_words_are_refused():
    # LinuxCNC reads @/^ with G28/G30 as the intermediate point and ignores them with G10/G52;
    # toolcomp refuses them there rather than guess, naming the feature.
    for code in ("G28", "G30", "G52", "G10 L2 P1"):
        with pytest.raises(tc.ProgramError) as e:
            tc.run(tc.Program.parse(f"G21 G0 X1 Y1\n{code} @5 ^30\nM2\n"))
        assert e.value.code == "unsupported_word" and "Polar coordinates" in str(e.value), code
    # Fanuc has no polar words.
    with pytest.raises(tc.ParseError) as e:
        tc.Program.parse("G0 @5\n", dialect="fanuc")
    assert e.value.code == "bad_character"


def test_a_syntax_error_in_a_sub_is_named_not_a_missing_end(tmp_path):
    # Read leniently, a file stops at its first syntax error: the sub whose endsub lies beyond it
    # is refused for that error (rs274 runs the file: the body is never called; toolcomp checks
    # every block), not with "File ended with no percent sign or program end".
    prog = tmp_path / "u.ngc"
    prog.write_text("G21\no100 sub\nG0 V2\no100 endsub\nG0 X1\nM2\n")
    with pytest.raises(tc.ParseError) as e:
        tc.run(str(prog))
    assert (e.value.code, e.value.line) == ("bad_character", 3)
    # U and W are words the reader takes (in a lathe cycle's profile): a sub nothing calls runs
    prog.write_text("G21\no100 sub\nG0 U2\no100 endsub\nG0 X1\nM2\n")
    assert len(tc.run(str(prog)).nominal.kind) == 1


def test_m19_orients_a_stopped_spindle_and_moves_nothing():
    # LinuxCNC: M19 is in M3-M5's group; the spindle stops (#<_spindle_on> 0) and turns to R.
    res = tc.run(tc.Program.parse("G21\nS500 M3\nM19 R90 Q2 P1\n(DEBUG, #<_spindle_on>)\nG0 X1\nM2\n"))
    assert len(res.nominal.kind) == 1
    assert [d.message.strip() for d in res.diagnostics if d.code == "message"] == ["0.000000"]
    profile = tc.ControlProfile("linuxcnc")
    profile.spindle_orient = False
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21\nM19 R90\nM2\n"), profile=profile)
    assert e.value.code == "unsupported_m_code"
