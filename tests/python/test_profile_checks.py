"""A ControlProfile setting that cannot describe a control is refused when the run starts,
naming the field: a NaN tolerance would make every comparison false (corners taken as
tangent, a wrong path without a word)."""
import math

import pytest

import toolcomp as tc

# A square under G41: every corner is an outside corner with a transition arc.
TEXT = "G21 G17 G90\nG0 X-10 Y0\nG41.1 D2\nG1 X0 Y0 F100\nX10\nY10\nX0\nY0\nG40 G1 X-10\nM2\n"

BAD = [
    ("radius.corner_tolerance", math.nan), ("radius.corner_tolerance", -0.1), ("radius.corner_tolerance", 2.0),
    ("radius.corner_limit", math.nan), ("radius.corner_limit", 4.0),
    ("radius.disc", 101.0), ("radius.disc", -1.0), ("radius.disc", math.nan),
    ("radius.overcut_tolerance", math.inf), ("radius.extension_min_length", -1.0),
    ("radius.max_non_plane_moves", -2), ("radius.overcut_neighbours", -1), ("radius.lookahead", -1),
    ("radius.arc_sweep_tolerance", (math.nan, 0.001)),
    ("inverse_time_min_rate", math.nan), ("wear_sign", math.inf),
    ("t_format", 7), ("tool_length_type", 3), ("tool_length_const", 16),
]


def profile_with(field, value):
    p = tc.ControlProfile("linuxcnc")
    obj, name = (p.radius, field.split(".")[1]) if field.startswith("radius.") else (p, field)
    setattr(obj, name, value)
    return p


@pytest.mark.parametrize("field, value", BAD)
def test_a_bad_setting_is_refused_by_run_and_iter_run(field, value):
    p = profile_with(field, value)
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        tc.run(tc.Program.parse(TEXT), profile=p)
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        tc.run(tc.Program.parse(TEXT), profile=p, strict=False)  # a caller's error, not the program's
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        tc.iter_run(tc.Program.parse(TEXT), profile=p)


def test_the_file_reader_checks_too(tmp_path):
    f = tmp_path / "square.ngc"
    f.write_text(TEXT)
    with pytest.raises(ValueError, match="corner_tolerance"):
        tc.run(f, profile=profile_with("radius.corner_tolerance", math.nan))


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc", "sinumerik", "heidenhain", "rockwell"])
@pytest.mark.parametrize("machine", ["mill", "lathe"])
def test_the_built_in_profiles_pass(dialect, machine):
    res = tc.run(tc.Program.parse(TEXT), profile=tc.ControlProfile(dialect, machine), strict=False)
    assert not any("ControlProfile" in d.message for d in res.diagnostics)


def test_edge_values_are_accepted():
    p = tc.ControlProfile("linuxcnc")
    p.radius.disc = 100
    p.radius.corner_tolerance = 0
    p.radius.max_non_plane_moves = -1
    p.tool_length_const = -19
    res = tc.run(tc.Program.parse(TEXT), profile=p)
    assert res.ok
