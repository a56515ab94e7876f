"""LinuxCNC's straight probe G38.2-G38.5. Where a probe stops depends on the part: the run is
given the contact points (probes=[...]); without them a probe touches at its target, as
LinuxCNC's preview draws it. Paths are compared with rs274 and the gcode module in
tests/programs/oracle/probing_g38*.ngc, the errors in tests/programs/errors/probe_*.ngc."""
import numpy as np
import pytest

import toolcomp as tc

TOUCH_OFF = "G21 G90 G94\nG10 L2 P1 Z0\nG0 X0 Y0 Z10\nF100\nG38.2 Z-5\n#<top> = #5063\nG0 Z[#<top> + 2]\nM2\n"


def _run(text, **kw):
    return tc.run(tc.Program.parse(text), **kw)


def test_without_results_the_probe_touches_at_its_target_and_warns():
    res = _run(TOUCH_OFF)
    assert np.round(res.nominal.end, 9).tolist() == [[0, 0, 10], [0, 0, -5], [0, 0, -3]]
    assert res.nominal.feed.tolist()[1] == 100.0
    warn = [d for d in res.diagnostics if d.code == "probe_move"]
    assert [(d.line, d.severity) for d in warn] == [(5, "warning")]
    assert "at the target" in warn[0].message


def test_the_contact_point_given_ends_the_move_and_is_read_back():
    res = _run(TOUCH_OFF, probes=[(0.0, 0.0, -2.5)])
    assert np.round(res.nominal.end, 9).tolist() == [[0, 0, 10], [0, 0, -2.5], [0, 0, -0.5]]


def test_results_are_in_mm_also_in_an_inch_program():
    res = _run(TOUCH_OFF.replace("G21", "G20"), probes=[(0.0, 0.0, -25.4)])
    assert res.nominal.end[1].tolist() == pytest.approx([0, 0, -25.4])
    assert res.nominal.end[2].tolist() == pytest.approx([0, 0, -25.4 + 2 * 25.4])  # Z[-1 + 2] inch


def test_tripped_flag_and_no_contact():
    text = "G21 G90 F100\nG38.3 Z-5\n#1 = #5070\nG0 X#1\nM2\n"
    assert _run(text).nominal.end[-1][0] == 1.0                    # touched (at the target)
    res = _run(text, probes=[None])                                 # G38.3: no error without contact
    assert res.nominal.end[-2].tolist() == [0, 0, -5]               # the whole way to the target
    assert res.nominal.end[-1][0] == 0.0
    with pytest.raises(tc.ProgramError) as e:                       # G38.2: the machine's error
        _run(text.replace("G38.3", "G38.2"), probes=[None])
    assert (e.value.code, str(e.value.message)) == ("probe_no_contact", "G38.2 move finished without making contact")


def test_results_are_taken_in_order_one_per_probe_move():
    text = "G21 G90 F100\nG38.2 Z-5\nG0 Z5\nG38.2 Z-5\nG0 Z5\nG38.2 Z-5\nM2\n"
    res = _run(text, probes=[(0, 0, -1), (0, 0, -2)])
    probes = [e[2] for k, e in zip(res.nominal.kind, res.nominal.end) if k == 1]
    assert probes == [-1.0, -2.0, -5.0]


def test_a_probe_result_is_three_or_six_numbers():
    with pytest.raises(ValueError):
        _run(TOUCH_OFF, probes=[(1.0, 2.0)])


def test_probe_results_before_any_probe_are_refused():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G90 F100\nG0 Z#5063\nM2\n")
    assert e.value.code == "probe_parameter_unset"
