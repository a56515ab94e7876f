"""LinuxCNC's user M codes and REMAPs, declared in a machine file: M100-M199 do nothing to the
path (they run a program on the machine), a remapped M code runs its o-word sub with the
argspec's words as locals. The expected values are those rs274 gives with the same REMAP=
lines in an INI ([RS274NGC] REMAP=M400 modalgroup=10 argspec=Pq ngc=m400, ...): M400 P1.5
sees #<p> = 1.5 and no #<q>; M410 P10 Q20 with '@PQr' sees #1 = 10, #2 = 20, #3 = 0;
a missing required word is "user-defined M400: missing: P"."""
import numpy as np
import pytest

import toolcomp as tc

MACHINE = """name = "mill with user codes"
control = "linuxcnc"
kind = "mill"
[m_codes]
101 = { action = "nothing", name = "air blast", words = "PQ" }
400 = { action = "subprogram", program = "m400", argspec = "Pq" }
410 = { action = "subprogram", program = "m410", argspec = "@PQr" }
420 = { action = "subprogram", program = "m400", argspec = "P>" }
"""
M400 = "o<m400> sub\nG0 X#<p>\no<m400> if [EXISTS[#<q>]]\nG0 Y#<q>\no<m400> endif\no<m400> endsub\nM2\n"
M410 = "o<m410> sub\nG0 X#1 Y#2 Z#3\no<m410> endsub\nM2\n"


@pytest.fixture
def machine(tmp_path):
    (tmp_path / "m.toml").write_text(MACHINE)
    (tmp_path / "m400.ngc").write_text(M400)
    (tmp_path / "m410.ngc").write_text(M410)
    return tmp_path


def _run(text, where):
    return tc.run(tc.Program.parse(text), machine=str(where / "m.toml"), search_path=[str(where)])


def test_user_m_codes_and_remaps_with_their_words(machine):
    res = _run("G21 G90\nM101 P1 Q2\nG0 X1\nM400 P2.5\nM400 P3 Q4\nM410 P10 Q20\nM2\n", machine)
    assert np.round(res.nominal.end, 9).tolist() == [[1, 0, 0], [2.5, 0, 0], [3, 0, 0], [3, 4, 0], [10, 20, 0]]


@pytest.mark.parametrize("block, message", [
    ("M400", "user-defined M400: missing: P"),
    ("M420 P1", "user-defined M420:F>0,"),
    ("M420", "user-defined M420: missing: PF>0,"),
])
def test_the_argspec_requires_its_upper_case_words(machine, block, message):
    with pytest.raises(tc.ProgramError) as e:
        _run(f"G21\n{block}\nM2\n", machine)
    assert (e.value.code, str(e.value.message), e.value.line) == ("remap_words", message, 2)


def test_without_the_machine_the_codes_stay_errors():
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21\nM101\nM2\n"))
    assert str(e.value.message) == "Unknown m code used: M101"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse("G21\nM400\nM2\n"))
    assert e.value.code == "m_code_out_of_range"


def test_the_rest_of_the_block_runs_when_the_sub_returns(machine):
    # LinuxCNC runs a remapped M code after the block's M codes and before its G codes: the
    # sub's G0 X2.5 first, then the block's G1 X1 (F100 of the block already in force).
    res = _run("G21 G90\nG1 X1 F100 M400 P2.5\nM2\n", machine)
    assert np.round(res.nominal.end, 9).tolist() == [[2.5, 0, 0], [1, 0, 0]]
    assert res.nominal.feed.tolist()[1] == 100.0
    # axis words alone move in the mode read with the block (G1), not the sub's G0 (rs274 with
    # the same REMAP: STRAIGHT_TRAVERSE(2, 0, 0) then STRAIGHT_FEED(2, 5, 0))
    res = _run("G21 G90 F100\nG1 X0.5\nM400 P2 Y5\nM2\n", machine)
    assert res.nominal.kind.tolist() == [1, 0, 1] and res.nominal.end[-1].tolist() == [2, 5, 0]
    # a program end in the block ends it after the sub
    res = _run("G21 G90\nM400 P2 M2\nG0 X9\nM2\n", machine)
    assert res.nominal.end.tolist() == [[2, 0, 0]]


def test_machine_file_rules(tmp_path):
    for body, what in [
        ('150 = { action = "subprogram", program = "m150" }', "M100-M199"),
        ('400 = { action = "nothing", argspec = "P" }', "argspec"),
        ('400 = { action = "subprogram", program = "m400", argspec = "P%" }', "argspec"),
        ('1000 = { action = "subprogram", program = "m1000" }', "up to M999"),
    ]:
        (tmp_path / "bad.toml").write_text('control = "linuxcnc"\nkind = "mill"\n[m_codes]\n' + body + "\n")
        with pytest.raises(tc.ParseError) as e:
            tc.Machine.read(str(tmp_path / "bad.toml"))
        assert e.value.code == "machine_file" and what in str(e.value), body


def test_the_argspec_reads_back(machine):
    m = tc.Machine.read(str(machine / "m.toml"))
    m.write(str(machine / "again.toml"))
    assert tc.Machine.read(str(machine / "again.toml")).m_codes[410].argspec == "@PQr"


G886 = ("o<g886> sub\n#<pe> = EXISTS[#<p>]\n(debug, g886: x=#<x> y=#<y> z=#<z> p=#<pe> mode=#<_motion_mode>)\n"
        "G1 X#<x> Y#<y> F10\nG1 Z#<z>\no<g886> endsub\nM2\n")


def test_a_remapped_g_code_runs_its_sub_as_the_block_s_motion(tmp_path):
    # rs274 with REMAP=G88.6 modalgroup=1 argspec=XYZp ngc=g886 (inch): the sub sees x=1 y=2
    # z=-0.5 p=7 and the motion mode before the block (G0), feeds to (1, 2, 0) and (1, 2, -0.5);
    # the next bare line feeds in the sub's G1 (STRAIGHT_FEED(3, 4, -1)): the code is not modal.
    (tmp_path / "m.toml").write_text('control = "linuxcnc"\nkind = "mill"\n[g_codes]\n'
                                     '"88.6" = { program = "g886", argspec = "XYZp" }\n')
    (tmp_path / "g886.ngc").write_text(G886)
    text = "G20 G90 G94\nG0 X0.5\nG88.6 X1 Y2 Z-0.5 P7\nX3 Y4 Z-1\nG0 Z1\nM2\n"
    res = _run(text, tmp_path)
    ends = (np.asarray(res.nominal.end) / 25.4).round(9).tolist()
    assert ends == [[0.5, 0, 0], [1, 2, 0], [1, 2, -0.5], [3, 4, -1], [3, 4, 1]]
    assert res.nominal.kind.tolist() == [0, 1, 1, 1, 0]
    msg = [d.message for d in res.diagnostics if d.code == "message"]
    assert msg == [" g886: x=1.000000 y=2.000000 z=-0.500000 p=1.000000 mode=0.000000"]
    res = _run("G20 G90 G94\nG88.6 X1 Y2 Z-0.5 P7 M2\nG0 X9\nM2\n", tmp_path)  # M2 after the sub
    assert len(res.nominal.kind) == 2
    m = tc.Machine.read(str(tmp_path / "m.toml"))
    assert tc.Machine.parse(m.dumps()).g_codes[88.6].argspec == "XYZp"


def test_remapped_g_codes_are_linuxcnc_s(tmp_path):
    with pytest.raises(tc.ParseError):
        tc.Machine.parse('control = "fanuc"\nkind = "mill"\n[g_codes]\n"88.6" = { program = "x" }\n')
