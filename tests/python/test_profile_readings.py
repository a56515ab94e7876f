"""A control's readings are ControlProfile fields, not branches on the dialect: each can be
set on any profile and acts, and each control's profile says what it reads."""
import pytest

import toolcomp as tc


def _run(text, dialect="linuxcnc", **fields):
    p = tc.ControlProfile(dialect)
    for k, v in fields.items():
        setattr(p, k, v)
    return tc.run(tc.Program.parse(text, dialect=dialect), profile=p)


def test_the_readings_of_each_control():
    lin, fan, rock = (tc.ControlProfile(d) for d in ("linuxcnc", "fanuc", "rockwell"))
    assert (lin.integer_word_slack, lin.linuxcnc_g_numbers, lin.max_m_code, lin.program_end_required,
            lin.errors_at_outermost_call, lin.abort_comment, lin.call_depth_message) == (
        True, True, 199, True, True, True, "Too many subroutine levels")
    assert (fan.last_g_code_wins, fan.fanuc_g10, fan.dwell_x_seconds, fan.integer_word_slack) == (True, True, True, False)
    assert (rock.last_g_code_wins, rock.fanuc_g10, rock.program_end_required) == (False, False, False)


def test_program_end_required():
    with pytest.raises(tc.ProgramError) as e:
        _run("G0 X1\n")
    assert e.value.code == "no_program_end"
    assert _run("G0 X1\n", program_end_required=False).ok


def test_last_g_code_wins():
    with pytest.raises(tc.ProgramError) as e:
        _run("G21 G0 G1 X1 F100\nM30\n", "rockwell")
    assert e.value.code == "modal_group_conflict"
    res = _run("G21 G0 G1 X1 F100\nM30\n", "rockwell", last_g_code_wins=True)
    assert res.nominal.kind[-1] == tc.LINE


def test_integer_word_slack():
    assert _run("T1.00005 M6\nM2\n").ok  # LinuxCNC: within 0.0001
    with pytest.raises(tc.ProgramError) as e:
        _run("T1.00005 M6\nM2\n", integer_word_slack=False)
    assert e.value.code == "non_integer_value"


def test_max_m_code_and_the_call_depth_message():
    with pytest.raises(tc.ProgramError) as e:
        _run("M300\nM2\n", max_m_code=299)
    assert e.value.message == "M-code greater than 299: M300"
    text = "o<r> sub\no<r> call\no<r> endsub\no<r> call\nM2\n"
    with pytest.raises(tc.ProgramError) as e:
        _run(text, call_depth_message="")
    assert e.value.message.startswith("More than 9 nested subprogram calls")


def _fields(profile, prefix=""):
    """Every bound field of a profile, nested RadiusRules included, by dotted name."""
    out = {}
    for name in dir(profile):
        if name.startswith("_") or name in ("machine",):
            continue
        value = getattr(profile, name)
        if callable(value):
            continue
        if type(value).__name__ == "RadiusRules":
            out.update(_fields(value, prefix + name + "."))
        else:
            out[prefix + name] = value
    return out


def test_the_9_series_is_the_fanuc_lathe_with_its_differences():
    fanuc, rockwell = _fields(tc.ControlProfile("fanuc", kind="lathe")), _fields(tc.ControlProfile("rockwell"))
    differ = {k for k in fanuc if fanuc[k] != rockwell[k]}
    assert differ == {
        "name", "t_format", "ttrc_check_codes", "radius.exit_direction_words", "radius.offset_change_reenters",
        # the Fanuc readings the 9/Series excerpt does not confirm
        "call_depth_limit", "last_g_code_wins", "fanuc_g10", "dwell_x_seconds", "length_subtract_word",
        "modal_offset_numbers", "startup_feed_per_rev", "c_word_is_chamfer", "g_code_system_a", "macro_calls",
        "m98_subprograms", "startup_motion", "cycles_own_group", "g53_rapid", "d_word_alone", "turning_cycles",
        "motion_beside_data_axes"}
    assert rockwell["t_format"] == 2 and rockwell["ttrc_check_codes"] and not rockwell["m98_subprograms"]


@pytest.mark.parametrize("text, dialect, field, code", [
    ("G21 G0 X0\nG52 X10\nM2\n", "linuxcnc", "g52_offset", "unsupported_g_code"),
    ("G21 G0 X0\nG65 P9010 A1\nM30\n", "fanuc", "macro_calls", "unknown_g_code"),
    ("G21 G0 X0\nM98 P100\nM30\n", "fanuc", "m98_subprograms", "unknown_m_code"),
    ("G21 G0 X0\nG44 H1 Z1\nM30\n", "fanuc", "length_subtract_word", "unknown_g_code"),
])
def test_the_codes_beyond_the_shared_iso_set_are_profile_fields(text, dialect, field, code):
    with pytest.raises(tc.ProgramError) as e:
        _run(text, dialect, **{field: False})
    assert (e.value.code, e.value.line) == (code, 2)


def test_m800_is_read_where_the_profile_says():
    text = "G21 G18 G0 X10 Z0\nM800\nM30\n"
    assert _run(text, "fanuc", ttrc_check_codes=True).ok
    with pytest.raises(tc.ProgramError) as e:
        _run(text, "fanuc")
    assert (e.value.code, e.value.line) == ("unknown_m_code", 2)
