"""O-word labels as LinuxCNC 2.9 keeps them (messages and lines from its gcode module for
the same text): an if, while or repeat label opened on two lines of one call is refused (do
labels may repeat; labels of other subs and of the main program are their own); a sub
defined twice, a sub defined inside another sub's definition; a definition ends at its
endsub; the blocks of the same label that LinuxCNC reads while it skips a structure."""
import pytest

import toolcomp as tc

H = "G21 G17 G90 G94 G40 G49\nG0 X0 Y0 Z0\n"


def run(text):
    return tc.run(tc.Program.parse(H + text, dialect="linuxcnc"))


@pytest.mark.parametrize("body, message, line", [
    ("o1 while [0]\no1 endwhile\no1 while [0]\no1 endwhile\nG0 X1\nM2",
     "5: duplicate O-word label: 'o1 while [0]' - defined in line 3", 5),
    ("o1 if [1]\no1 if [1]\no1 endif\no1 endif\nG0 X1\nM2",
     "4: duplicate O-word label - already defined in line 3: 'o1 if [1]'", 4),
    ("o1 repeat [1]\no1 endrepeat\no1 repeat [1]\no1 endrepeat\nG0 X1\nM2",
     "5: duplicate O-word label: 'o1 repeat [1]' - defined in line 3", 5),
    ("o100 sub\nG0 X1\no100 endsub\no100 sub\nG0 X2\no100 endsub\nG0 X3\nM2",
     "File:<string> line:6 redefining sub: o|100| already defined in file:<string>", 6),
    ("o100 sub\no101 sub\no101 endsub\no100 endsub\nG0 X1\nM2", "Nested subroutine definition", 4),
    ("o1 while [0]\nG0 X1\no1 else\no1 endwhile\nM2",
     "5: no matching 'if' label: 'o1 else' (found 'while' in line 3)", 5),
    ("o100 sub\no1 if [0]\no100 endsub\no1 endif\nG0 X1\no100 endsub\no100 call\nM2",
     "6: undefined O-word label: 'o1 endif'", 6),
    ("o1 repeat [1]\nG0 X1\no1 endwhile\nM2", "5: no matching label: 'o1 endwhile' (found 'repeat' in line 3)", 5),
    ("o1 if [1]\nG0 X1\no1 endsub\nM2", "5: not in a subroutine definition: 'o1 endsub'", 5),
    ("o1 if [1]\no1 break\no1 endif\nM2", "4: no matching while/do label: 'o1 break' (found 'if' in line 3)", 4),
])
def test_refused(body, message, line):
    with pytest.raises(tc.ProgramError) as e:
        run(body)
    assert (e.value.message, e.value.line) == (message, line)


@pytest.mark.parametrize("body, x", [
    # the same label in two subs, in a sub and the main program, inside a branch not taken
    ("o100 sub\no1 if [1]\no1 endif\no100 endsub\no200 sub\no1 if [1]\no1 endif\no200 endsub\n"
     "o100 call\no200 call\nG0 X1\nM2", 1),
    ("o100 sub\no1 if [1]\no1 endif\no100 endsub\no100 call\no1 if [1]\no1 endif\nG0 X1\nM2", 1),
    ("o2 if [0]\no1 while [0]\no1 endwhile\no1 while [0]\no1 endwhile\no2 endif\nG0 X1\nM2", 1),
    # a loop passing its if again; do labels repeat; a sub defined inside an if
    ("#1=0\no1 while [#1 LT 2]\no2 if [1]\no2 endif\n#1=[#1+1]\no1 endwhile\nG0 X1\nM2", 1),
    ("o1 do\nG0 X1\no1 while [0]\no1 do\nG0 X2\no1 while [0]\nM2", 2),
    ("o1 if [1]\no100 sub\nG0 X1\no100 endsub\no1 endif\no100 call\nM2", 1),
])
def test_accepted(body, x):
    assert run(body).path.end[-1][0] == x


@pytest.mark.parametrize("call, end", [("#1=100\no#1 call [4]", [5, 0, 0]), ("o[100+1] call", [0, 5, 0]),
                                       ("#1=100.00005\no#1 call [2]", [3, 0, 0])])
def test_a_call_may_compute_its_number(call, end):
    # LinuxCNC (gcode module): the number is read as an integer word when the call runs
    subs = "o100 sub\nG0 X[#1+1]\no100 endsub\no101 sub\nG0 Y5\no101 endsub\n"
    assert run(subs + call + "\nM2").path.end[-1].tolist() == end


def test_a_computed_number_elsewhere_is_refused_explicitly():
    with pytest.raises(tc.ParseError, match="computed O-word number is supported by toolcomp with call only"):
        run("o[1+1] if [1]\no2 endif\nM2")
