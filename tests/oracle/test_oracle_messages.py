"""Messages of comments, against rs274: (MSG, ...) and (DEBUG, ...) in every position on a
line, with several comments, ';' comments, blanks and parameters. LinuxCNC keeps one comment
per block (the last in parentheses); toolcomp's info diagnostics "message" must be rs274's
MESSAGE(...) calls, text for text, in order. (PRINT goes to rs274's standard output, not to
MESSAGE: not compared here.)"""
import re

import pytest

import lcnc

tc = pytest.importorskip("toolcomp")

PROGRAMS = {
    "two_msgs": "G21 (MSG, first) (MSG, second)\nM2\n",
    "msg_then_note": "G21 G0 X1 (MSG, only) (plain note)\nM2\n",
    "note_then_msg": "G21 (plain note) G0 X1 (MSG, last)\nM2\n",
    "semicolon_msg": "G21\n;MSG, semi\nG0 X1\nM2\n",
    "paren_then_semicolon": "G21 G0 X2 (MSG, par) ;(MSG, semi2)\nM2\n",
    "debug_values": "G21\n#1=2.5\n(DEBUG, a=#1) (DEBUG, b=#1 c=#2)\n#<x>=3 (DEBUG,x=#<x>)\nM2\n",
    "case_and_blanks": "G21\n(msg,lower)\n( MSG, leading blank)\n(Msg ,no)\nM2\n",
    "on_motion_lines": "G21 G1 X1 F100 (MSG, one)\nG1 X2 (DEBUG, two) (MSG, three)\nG1 X3\nM2\n",
    # #5599 switches (DEBUG, ...) off and on; #5061-#5070 may be set by a program
    "debug_flag_and_probe_results": "G21\n(debug, a=#5599)\n#5599=0\n(DEBUG, hidden)\n(MSG, msg)\n#5599=1\n"
                                    "(DEBUG, shown)\n#5070=1\n(debug, p=#5070 #5063)\nM2\n",
    "predefined_values": "G21 G91 F150 S1200\n(debug, feed=#<_feed> rpm=#<_rpm> abs=#<_absolute> x=#<_x>)\nM2\n",
}


def rs274_messages(path):
    run = lcnc.run(path)
    assert run.returncode == 0, run.stderr
    return re.findall(r'MESSAGE\("(.*)"\)', run.canon)


@pytest.mark.skipif(not lcnc.available(), reason="LinuxCNC rs274 not installed")
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_messages_match_rs274(name, tmp_path):
    path = tmp_path / f"{name}.ngc"
    path.write_text(PROGRAMS[name])
    want = rs274_messages(path)
    res = tc.run(tc.Program.read(str(path)), start="machine_zero")
    got = [d.message for d in res.diagnostics if d.code == "message"]
    assert got == want
