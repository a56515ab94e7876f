"""A LinuxCNC .var file carries the machine's state as well as the program's parameters:
the G28/G30 positions (#5161-, #5181-), the G92 offsets (#5210, #5211-), the system in use
(#5220) and the G54-G59.3 origins (#5221 + 20 n, rotation at +9). LinuxCNC takes them back at
start (the machine at its zero), and so does a run given them as parameters."""
import math
import os

import numpy as np
import pytest

import toolcomp as tc
from toolcomp.params import read_var, write_var


def run(text, parameters):
    # The machine stands at its zero (the .var file's state), as LinuxCNC's run starts.
    return tc.run(tc.Program.parse(text), parameters=parameters, start="machine_zero").path


def test_g54_origin_and_the_machine_at_zero():
    p = run("G21 G0 X1 Y0\nG53 G0 X0\nM2\n", {5221: 100.0})
    np.testing.assert_allclose(p.start[0, :2], [-100, 0])  # machine 0 in G54 = program X-100
    np.testing.assert_allclose(p.end[1, :2], [-100, 0])    # G53 X0: back at machine 0


def test_g28_position_and_system_in_use():
    assert run("G21 G0 X1\nG28\nM2\n", {5161: 50.0}).end[-1, 0] == 50
    p = run("G21 G0 X5\nM2\n", {5220: 2.0, 5241: 10.0})  # G55 in use, its origin X10
    assert p.start[0, 0] == -10


def test_g92_offsets_in_force_only_with_5210():
    assert run("G21 G0 X5\nM2\n", {5210: 1.0, 5211: 3.0}).start[0, 0] == -3
    assert run("G21 G0 X5\nM2\n", {5210: 0.0, 5211: 3.0}).start[0, 0] == 0


@pytest.mark.parametrize("params, what", [
    ({1: math.nan}, "not a finite number"), ({1: math.inf}, "not a finite number"),
    ({0: 1.0}, "not a parameter"), ({99999: 1.0}, "not a parameter"),
    ({5220: 10.0}, "5220"), ({5227: 1.0}, "U, V or W"),
])
def test_bad_parameters_are_refused(params, what):
    with pytest.raises(ValueError, match=what):
        run("G21 G0 X5\nM2\n", params)


def test_var_files_read_and_written_faithfully(tmp_path):
    f = tmp_path / "sim.var"
    f.write_bytes("\ufeff31\t1.5\n40\t2\n".encode())  # a byte order mark before the first line
    assert read_var(f) == {31: 1.5, 40: 2.0}
    f.write_text("31\t1e999\n")
    with pytest.raises(tc.ParseError, match="finite"):
        read_var(f)
    f.write_text("31\t\u0661\n40\t2\n")  # an Arabic-Indic digit is not a number here: skipped
    assert read_var(f) == {40: 2.0}
    with pytest.raises(ValueError, match="finite"):
        write_var(f, {31: math.nan})
    os.chmod(f, 0o640)
    link = tmp_path / "link.var"
    link.symlink_to(f)
    write_var(link, {31: 4.0})
    assert link.is_symlink() and read_var(f) == {31: 4.0, 40: 2.0}
    assert (os.stat(f).st_mode & 0o777) == 0o640


@pytest.mark.parametrize("value", ["nan", "NaN", "-inf", "inf", "Infinity", "+INF", "nan(0x1)", "0x1p3", "-0X10"])
def test_values_strtod_reads_but_no_decimal_number_are_refused_with_their_line(tmp_path, value):
    # LinuxCNC reads the value column with C's strtod, which takes these: skipping the line
    # would leave #40 at 0 where LinuxCNC has a value (or NaN).
    f = tmp_path / "sim.var"
    f.write_text(f"31\t1.5\n40\t{value}\n5220\t1\n")
    with pytest.raises(tc.ParseError) as e:
        read_var(f)
    assert (e.value.code, e.value.line) == ("parameter_bad_value", 2)
    assert "#40" in e.value.message
    with pytest.raises(tc.ParseError):
        tc.run(tc.Program.parse("G21 G0 X5\nM2\n"), parameters=f)


@pytest.mark.parametrize("params", [[1, 2], (3.0,), 5])
def test_parameters_that_are_no_mapping_are_a_type_error(params):
    with pytest.raises(TypeError, match="parameters must be a"):
        tc.run(tc.Program.parse("G21 G0 X5\nM2\n"), parameters=params)
