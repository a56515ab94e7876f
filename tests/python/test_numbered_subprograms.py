"""LinuxCNC 2.9's Fanuc-style numbered subprograms (O<n> ... M99, M98 P L). Paths are compared
with rs274 and the gcode module in tests/programs/oracle/m98_numbered_subprograms.ngc and the
errors in tests/programs/errors/m98_*.ngc and tests/programs/macros/error_m9*.ngc; here the
readings worked by hand from LinuxCNC's interp_o_word.cc and rs274 runs."""
import numpy as np
import pytest

import toolcomp as tc


def _run(text, **kw):
    # The points below count the first move from machine zero, where the run is told to start.
    kw.setdefault("start", "machine_zero")
    return tc.run(tc.Program.parse(text), **kw)


def _x(res):
    return list(np.round(res.nominal.end[:, 0], 9))


def test_parameters_are_shared_and_named_locals_are_the_calls_own():
    res = _run("G21\n#1 = 5\nM98 P300\nG0 X#1\nM30\nO300\n#1 = [#1 + 1]\n#<y> = 2\nM99\n")
    assert _x(res) == [6.0]
    with pytest.raises(tc.ProgramError):  # the sub's #<y> is gone after M99
        _run("G21\nM98 P300\nG0 X#<y>\nM30\nO300\n#<y> = 2\nM99\n")


def test_l_runs_the_m98_line_again_and_reads_its_p_each_time():
    # O100 sets #10 to 200: the second pass of "M98 P#10 L2" calls O200.
    text = "G21\n#10 = 100\nM98 P#10 L2\nM30\nO100\nG0 X1\n#10 = 200\nM99\nO200\nG0 X2\nM99\n"
    assert _x(_run(text)) == [1.0, 2.0]
    assert _x(_run("G21\nM98 P100 L3\nG0 X9\nM30\nO100\nG91 G0 X1\nG90\nM99\n")) == [1.0, 2.0, 3.0, 9.0]


def test_l0_calls_nothing():
    assert _x(_run("G21\nM98 P100 L0\nG0 X9\nM30\nO100\nG0 X1\nM99\n")) == [9.0]


def test_m99_in_the_main_program_ends_it_as_m2():
    assert _x(_run("G21\nG0 X1 M99\nG0 X2\n")) == [1.0]


def test_a_file_on_the_search_path_comes_before_the_program_s_own(tmp_path):
    (tmp_path / "100.ngc").write_text("O100\nG0 X7\nM99\n")
    res = _run("G21\nM98 P100\nM30\nO100\nG0 X1\nM99\n", search_path=[str(tmp_path)])
    assert _x(res) == [7.0]


def test_a_call_with_no_numbered_sub_after_it():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21\nM98 P100\nM2\n")
    assert e.value.code == "unknown_o_word" and "seeking o-word: o<100>" in str(e.value)


def test_ten_nested_calls_are_too_many():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21\nM98 P1\nM30\nO1\nM98 P1\nM99\n")
    assert str(e.value.message) == "Too many subroutine levels"
