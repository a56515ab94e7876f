"""Canned cycle words as LinuxCNC reads them: P and Q of -1 are its "no word", other negative
values are taken as given, and its checks come in its order (feed, feed mode, compensation,
R, L, depth, R against depth, then each cycle's own words). Checked against LinuxCNC 2.9's
gcode module; the same refusals are in tests/programs/errors/cycle_*.ngc for the oracle suite."""
import numpy as np
import pytest

import toolcomp as tc

HEAD = "G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z5\n"


def run(text, dialect="linuxcnc"):
    return tc.run(tc.Program.parse(text, dialect=dialect))


def test_g82_with_a_negative_dwell_drills():
    p = run(HEAD + "G82 X1 Z-1 R2 P-2 F100\nM2\n").path
    # to the hole at Z5, down to R, feed to the bottom, out to R (G99, the start-up mode)
    np.testing.assert_allclose(p.end[1:], [[1, 0, 5], [1, 0, 2], [1, 0, -1], [1, 0, 2]])
    assert p.kind[1:].tolist() == [0, 0, 1, 0]


def test_g4_with_a_negative_dwell_is_accepted():
    assert len(run(HEAD + "G4 P-2\nM2\n").path) == 1


def test_g83_with_a_negative_q_refuses_after_the_approach():
    res = tc.run(tc.Program.parse(HEAD + "G83 X1 Z-1 R2 Q-2 F100\nM2\n"), strict=False)
    assert [(d.message, d.line) for d in res.diagnostics if d.severity == "error"] == [
        ("Negative or zero q value used", 3)]
    np.testing.assert_allclose(res.path.end[1:], [[1, 0, 5], [1, 0, 2]])


@pytest.mark.parametrize("text, message, line", [
    (HEAD + "G82 X1 Z-1 R2 P-1 F100\nM2\n", "Dwell time p word missing with g82", 3),
    (HEAD + "G83 X1 Z-1 R2 Q-1 F100\nM2\n", "Q word missing with g83", 3),
    (HEAD + "G4 P-1\nM2\n", "Dwell time missing with g4", 3),
    ("G21 G17 G90 G94\nG0 X0 Y0 Z5\nG81 X1 Z-1 L0\nM2\n", "Cannot feed with zero feed rate", 3),
    (HEAD + "G81 X1 Z-1 L0 F100\nM2\n", "R clearance plane unspecified in cycle", 3),
    (HEAD + "G81 X1 R2 L0 F100\nM2\n", "Cannot do zero repeats of cycle", 3),
    (HEAD + "G82 X1 Z-1 R-2 F100\nM2\n", "R less than z in cycle in xy plane", 3),
    (HEAD + "G83 X1 Z-1 R-2 F100\nM2\n", "R less than z in cycle in xy plane", 3),
    (HEAD + "M3 S100\nG87 X1 Z-1 R-2 F100\nM2\n", "R less than z in cycle in xy plane", 4),
    ("G21 G17 G90 G94\nG0 X0 Y0 Z5\nG93\nG81 X1 Z-1 R2 F100\nM2\n", "Cannot feed with zero feed rate", 4),
    ("G21 G17 G90 G94\nG0 X0 Y0 Z5\nG93 G1 X1 F2\nG81 X1 Z-1 R2 F5\nM2\n",
     "Cannot use inverse time feed with canned cycles", 4),
    ("G21 G17 G90 G94\nF100\nG0 X0 Y0 Z5\nG93\nG81 X1 Z-1 R2 F5\nM2\n",
     "Cannot use inverse time feed with canned cycles", 5),
])
def test_refusals_in_linuxcnc_order(text, message, line):
    with pytest.raises(tc.ProgramError) as e:
        run(text)
    assert (e.value.message, e.value.line) == (message, line)


def test_fanuc_still_refuses_a_negative_dwell():
    with pytest.raises(tc.ProgramError) as e:
        run(HEAD + "G4 P-2\nM2\n", dialect="fanuc")
    assert e.value.line == 3
