"""Bad input gets a clear error, never a crash, a hang, NaN coordinates or an exception that
is not a toolcomp error. Random programs from a small G-code grammar, with and without
radius compensation (hypothesis, deterministic seed)."""
import numpy as np
from hypothesis import given, settings, HealthCheck, strategies as st

import toolcomp as tc

TOOLS = tc.ToolTable.parse("T1 P1 Z25 D6\nT2 P2 D-4 Q3\nT3 P3 D0\n", "linuxcnc")

letters = st.sampled_from(list("XYZIJKRFPQLDHT"))
numbers = st.one_of(st.integers(-50, 50).map(str), st.floats(-60, 60, allow_nan=False).map(lambda f: f"{f:.3f}"))
gcodes = st.sampled_from(["G0", "G1", "G2", "G3", "G17", "G18", "G19", "G20", "G21", "G40", "G41", "G42", "G41.1",
                          "G42.1", "G43", "G49", "G54", "G55", "G80", "G81", "G83", "G90", "G91", "G92", "G98",
                          "G99", "M3", "M5", "M6", "G4", "G10 L2 P1", "G28", "G53"])
word = st.one_of(gcodes, st.tuples(letters, numbers).map("".join))
block = st.lists(word, min_size=0, max_size=5).map(" ".join)
program = st.lists(block, min_size=1, max_size=25).map(lambda b: "G21 F100\n" + "\n".join(b) + "\nM2\n")


def check(res):
    for path in (res.nominal, res.path):
        assert np.isfinite(path.end).all()
        assert np.isfinite(path.start).all()
        arcs = path.kind >= tc.ARC_CW
        assert np.isfinite(path.center[arcs][:, :2]).all() or not arcs.any()


@settings(max_examples=400, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(program, st.sampled_from(["linuxcnc", "fanuc"]))
def test_random_programs_fail_cleanly_or_give_finite_paths(text, dialect):
    try:
        prog = tc.Program.parse(text, dialect=dialect)
    except tc.ParseError:
        return
    for strict in (True, False):
        try:
            res = tc.run(prog, tools=TOOLS, strict=strict)
        except tc.Error as e:
            assert strict and e.line >= 0 and e.code
            continue
        check(res)
