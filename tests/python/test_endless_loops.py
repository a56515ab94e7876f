"""Endless loops end in seconds: a run that executes ControlProfile.no_motion_limit blocks in
a row without a move stops with 'no_progress' at the block it reached (inside the loop), in
every dialect; loops that cut run on to block_limit. Call nesting is bounded too."""
import pytest

import toolcomp as tc

# A loop that never moves the tool, its blocks on lines 2-4 (Heidenhain 2-4, the jump on 4).
IDLE = {
    "linuxcnc": ("G0 X0\no1 while [1]\n#1=[#1+1]\no1 endwhile\nM2\n", {2, 3, 4}),
    "fanuc": ("G0 X0\nN10 #1=#1+1\nGOTO10\nM30\n", {2, 3}),
    "sinumerik": ("G0 X0\nLOOP\nR1=R1+1\nENDLOOP\nM30\n", {2, 3, 4}),
    "heidenhain": ("0 BEGIN PGM A MM\n1 L X+0 R0 FMAX\n2 LBL 1\n3 Q1 = Q1 + 1\n"
                   "4 FN 9: IF +0 EQU +0 GOTO LBL 1\n5 END PGM A MM\n", {3, 4, 5}),
}
# A loop that moves on every pass, with the same shape.
CUTTING = {
    "linuxcnc": "G0 X0\no1 while [1]\nG1 X[#1] F100\n#1=[1-#1]\no1 endwhile\nM2\n",
    "fanuc": "G0 X0\nN10 G1 X#1 F100\n#1=1-#1\nGOTO10\nM30\n",
    "sinumerik": "G0 X0\nLOOP\nG1 X=R1 F100\nR1=1-R1\nENDLOOP\nM30\n",
    "heidenhain": "0 BEGIN PGM A MM\n1 L X+5 R0 FMAX\n2 LBL 1\n3 L X+Q1 F100\n4 Q1 = 1 - Q1\n"
                  "5 FN 9: IF +0 EQU +0 GOTO LBL 1\n6 END PGM A MM\n",
}


def _profile(dialect, **fields):
    p = tc.ControlProfile(dialect)
    for k, v in fields.items():
        setattr(p, k, v)
    return p


@pytest.mark.parametrize("dialect", sorted(IDLE))
def test_a_loop_without_motion_stops_with_no_progress(dialect):
    text, loop_lines = IDLE[dialect]
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect=dialect), profile=_profile(dialect, no_motion_limit=1000))
    assert e.value.code == "no_progress" and e.value.line in loop_lines
    assert "1000 blocks executed in a row without a move" in e.value.message


def test_the_default_limit_is_ten_million_blocks():
    assert tc.ControlProfile("fanuc").no_motion_limit == 10_000_000
    text, loop_lines = IDLE["linuxcnc"]
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text))
    assert e.value.code == "no_progress" and e.value.line in loop_lines
    assert "10000000 blocks" in e.value.message


@pytest.mark.parametrize("dialect", sorted(CUTTING))
def test_a_loop_that_cuts_runs_on_to_the_block_limit(dialect):
    profile = _profile(dialect, no_motion_limit=5, block_limit=20_000)
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(CUTTING[dialect], dialect=dialect), profile=profile)
    assert e.value.code == "block_limit"
    res = tc.run(tc.Program.parse(CUTTING[dialect], dialect=dialect), profile=profile, strict=False)
    assert len(res.nominal) >= 4999  # 20 000 blocks, a move every three or four


def test_blocks_without_motion_between_moves_do_not_add_up():
    # 3 idle blocks between moves, 10 000 times over, with a limit of 3: never 4 in a row.
    text = "G0 X0\no1 repeat [10000]\nG1 X1 F100\n#1=1\n#2=2\n(comment)\no1 endrepeat\nM2\n"
    res = tc.run(tc.Program.parse(text), profile=_profile("linuxcnc", no_motion_limit=4))
    assert len(res.nominal) == 10_001


@pytest.mark.parametrize("bad", [0, -1])
def test_no_motion_limit_must_be_a_count(bad):
    p = tc.ControlProfile("linuxcnc")
    with pytest.raises((ValueError, TypeError)):
        p.no_motion_limit = bad


def test_call_depth_limit_is_bounded():
    p = tc.ControlProfile("linuxcnc")
    p.call_depth_limit = 10_000
    with pytest.raises(ValueError, match="at most 10000"):
        p.call_depth_limit = 10**8
    assert p.call_depth_limit == 10_000


def test_a_self_calling_sub_stops_at_the_limit():
    text = "o<r> sub\no<r> call\no<r> endsub\no<r> call\nM2\n"
    p = _profile("linuxcnc", call_depth_limit=10_000)
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text), profile=p)
    assert e.value.code == "call_depth"


# Cycles that would make more moves than the blocks left: (dialect, program, cycle line).
BIG_CYCLES = {
    "linuxcnc G71, 1.2 million levels": ("linuxcnc", (
        "G21 G18 G7 G90 F100\no100 sub\nG1 X10 Z0\nG1 X24 Z-10\no100 endsub\nG0 X30 Z2\n"
        "G71 Q100 X24 Z2 D0 I0.00001 R0.5\nM2\n"), 7),
    "fanuc G71 type I, 160 000 levels": ("fanuc", (
        "G21 G18 G98\nG0 X52 Z2\nG71 U0.0001 R0.5\nG71 P10 Q20 F200\nN10 G0 X20\nG1 Z-20\nN20 X52\nM30\n"), 4),
    "fanuc G71 type II, 160 000 levels": ("fanuc", (
        "G21 G18 G98\nG0 X52 Z2\nG71 U0.0001 R0.5\nG71 P10 Q20 F200\nN10 G0 X20 Z0\nG1 Z-20\nN20 X52\nM30\n"), 4),
    "fanuc G73, 100 000 passes": ("fanuc", (
        "G21 G18 G98\nG0 X52 Z2\nG73 U3 W1 R100000\nG73 P10 Q20 F200\nN10 G0 X20 Z0\nG1 Z-20\nN20 X52\nM30\n"), 4),
}


@pytest.mark.parametrize("case", sorted(BIG_CYCLES))
def test_a_cycle_beyond_the_blocks_left_stops_at_the_block_limit_before_making_its_moves(case):
    dialect, text, line = BIG_CYCLES[case]
    profile = tc.ControlProfile(dialect, machine="lathe")
    profile.block_limit = 20_000
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect=dialect), profile=profile)
    assert e.value.code == "block_limit" and e.value.line == line
