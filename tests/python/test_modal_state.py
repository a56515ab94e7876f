"""LinuxCNC's M70-M73: the modal state saved, forgotten and restored. Paths are compared with
rs274 and the gcode module in tests/programs/oracle/modal_state_m70_m73.ngc, the errors in
tests/programs/errors/m72_*.ngc and tests/programs/macros/error_m7*.ngc; here the readings
worked by hand from LinuxCNC's interp_convert.cc (save_settings, restore_settings,
gen_settings: the restore is G-code text, F as %.1f, S as %.0f)."""
import numpy as np
import pytest

import toolcomp as tc


def _run(text, **kw):
    return tc.run(tc.Program.parse(text), **kw)


def _ends(res):
    return np.round(res.nominal.end, 9).tolist()


def test_restored_feed_is_printed_with_one_decimal():
    # " F%.1f" of 100.25 is "F100.2" (printf rounds the binary value 100.25 half to even).
    res = _run("G21 F100.25\nM70\nF50\nM72\nG1 X1\nM2\n")
    assert res.nominal.feed.tolist() == [100.2]


def test_units_come_back_first_and_positions_are_read_in_them():
    # saved in mm; the program switches to inch; after M72, X10 is 10 mm again
    res = _run("G21 G90\nM70\nG20\nG0 X1\nM72\nG0 X10\nM2\n")
    assert _ends(res) == [[25.4, 0, 0], [10, 0, 0]]


def test_the_rest_of_an_m72_block_is_not_run_once_something_was_restored():
    res = _run("G21 G90 F100\nM70\nG91\nG1 X5 M72\nG1 X7\nM2\n")
    assert _ends(res) == [[7, 0, 0]]  # no move on line 4; line 5 is absolute again
    warn = [d for d in res.diagnostics if d.code == "modal_restore_rest_lost"]
    assert [(d.line, d.severity) for d in warn] == [(4, "warning")]
    assert "G codes, axis words" in warn[0].message


def test_an_m72_with_nothing_to_restore_leaves_its_block_alone():
    res = _run("G21 G90 F100\nM70\nG1 X5 M72\nM2\n")
    assert _ends(res) == [[5, 0, 0]]
    assert not [d for d in res.diagnostics if d.code == "modal_restore_rest_lost"]


def test_feed_and_speed_always_restored_makes_every_m72_end_its_block():
    prof = tc.ControlProfile("linuxcnc")
    prof.restore_feed_speed_always = True  # LinuxCNC 2.9.1 on
    res = _run("G21 G90 F100\nM70\nG1 X5 M72\nG1 X6\nM2\n", profile=prof)
    assert _ends(res) == [[6, 0, 0]]


def test_m73_restores_when_the_subroutine_returns_and_m71_forgets():
    subs = ("o<a> sub\nM73\nG91 F7\no<a> endsub\n"
            "o<b> sub\nM73\nG91 F9\nM71\no<b> endsub\n")
    res = _run(subs + "G21 G90 F100\no<a> call\nG1 X3\no<b> call\nG1 X3\nM2\n")
    # after o<a>: G90 F100 again; after o<b>: G91 F9 leak (M71 cancelled the restore)
    assert _ends(res) == [[3, 0, 0], [6, 0, 0]]
    assert res.nominal.feed.tolist() == [100, 9]


def test_m73_then_m71_then_m70_still_restores_on_return_to_the_m70_state():
    # the restore-on-return flag stays with the level; M70 gave it G91 F7 to restore
    subs = "o<s> sub\nM73\nG91 F7\nM71\nM70\nG90 F9\no<s> endsub\n"
    res = _run(subs + "G21 G90 F100\no<s> call\nG1 X2\nG1 X2\nM2\n")
    assert _ends(res) == [[2, 0, 0], [4, 0, 0]]
    assert res.nominal.feed.tolist() == [7, 7]


def test_a_restored_g43_takes_the_tool_in_the_spindle():
    tools = tc.ToolTable()
    tools.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=1.0, length=[0, 0, 10.0])]))
    tools.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=1.0, length=[0, 0, 30.0])]))
    res = _run("G21 T1 M6\nG43\nM70\nT2 M6\nG49\nM72\nG0 X1\nM2\n", tools=tools)
    assert res.nominal.tool_offset.tolist() == [[0, 0, 30.0]]  # T2's, not T1's saved one


def test_m72_needs_a_saved_state_of_its_own_level():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21\nM70\nM71\nM72\nM2\n")
    assert (e.value.code, e.value.line) == ("modal_state_invalid", 4)
    assert str(e.value).startswith("Cannot restore context from invalid stack frame - missing M70/M73?")


def test_a_failing_restore_names_its_text():
    # the restored G41 comes before the G64 (block order): G64 is refused under compensation;
    # flood on and mist off make the mist slot M9 and leave the flood slot alone
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G17 G90 G64 P0.01 F100.25 S1000.5\nG41\nG1 X20 Y20\nM70\nG40 G1 X40 Y0\n"
             "G18 G91 G61 F7 S7 M8\nM72\nM2\n")
    assert (e.value.code, e.value.line) == ("modal_restore_failed", 7)
    assert str(e.value).startswith(
        "M7x: restore_settings failed executing: ' F100.2 S1000 G17 G41 G90 G64 P0.010000 Q0.010000M9': "
        "Cannot change control mode with cutter radius compensation on")


def test_other_controls_do_not_know_m70():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21\nM70\nM30\n", "fanuc"))
    assert e.value.code == "unsupported_m_code"
