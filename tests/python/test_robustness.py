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
@given(program, st.sampled_from(["linuxcnc", "fanuc"]), st.sampled_from([None, "sinumerik", "heidenhain", "rockwell"]))
def test_random_programs_fail_cleanly_or_give_finite_paths(text, dialect, profile):
    try:
        prog = tc.Program.parse(text, dialect=dialect)
    except tc.ParseError:
        return
    prof = tc.ControlProfile(profile) if profile else None
    for strict in (True, False):
        try:
            res = tc.run(prog, tools=TOOLS, strict=strict, profile=prof)
        except tc.Error as e:
            assert strict and e.line >= 0 and e.code
            continue
        check(res)


kl_words = st.sampled_from(["X+10", "Y-5", "Z+2", "IX+3", "IY-1", "R0", "RL", "RR", "F100", "FMAX", "M3", "M97",
                            "M98", "M120 LA2", "DR+", "DR-", "R+5", "R-3", "PA+30", "PR+10", "IPA+90", "CCA90",
                            "LEN5", "Q1", "X+Q1", "R+", "M2"])
kl_heads = st.sampled_from(["L", "C", "CC", "CR", "CT", "LP", "CP", "RND R2", "CHF 1", "APPR LT", "APPR LN",
                            "APPR CT", "APPR LCT", "DEP LT", "DEP LN", "DEP CT", "DEP LCT", "FN 0: Q1 = +3",
                            "FN 9: IF +Q1 EQU +3 GOTO LBL 1", "LBL 1", "Q2 = Q1 * 2", "TOOL CALL 1 Z DR-0.1",
                            "LN X+1 Y+1 Z+1 NX+0 NY+0 NZ+1"])
kl_block = st.tuples(kl_heads, st.lists(kl_words, max_size=4)).map(lambda t: " ".join([t[0], *t[1]]))
kl_program = st.lists(kl_block, min_size=1, max_size=20).map(
    lambda bs: "\n".join(f"{i} {b}" for i, b in enumerate(
        ["BEGIN PGM R MM", "TOOL DEF 1 L+0 R+2 R2+1", "TOOL CALL 1 Z", "L X+0 Y+0 Z+0 R0 F100"] + bs + ["END PGM R MM"])))


@settings(max_examples=400, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(kl_program)
def test_random_klartext_fails_cleanly_or_gives_finite_paths(text):
    prof = tc.ControlProfile("heidenhain")
    prof.block_limit = 10000
    try:
        prog = tc.Program.parse(text, dialect="heidenhain")
        res = tc.run(prog, profile=prof)
    except tc.Error as e:
        assert e.code
        return
    check(res)
