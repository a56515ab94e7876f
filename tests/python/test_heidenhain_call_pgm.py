"""Heidenhain CALL PGM through the Python API: ``tc.run(..., search_path=...)`` looks for the
called program (``name`` or ``name.h``) in the given directories only; the called program
runs inline with shared Q parameters, its segments carry the line numbers of its own file."""
import pathlib

import numpy as np
import pytest

import toolcomp as tc

DATA = pathlib.Path(__file__).resolve().parents[1] / "programs" / "heidenhain"
TABLES = pathlib.Path(__file__).resolve().parents[1] / "programs" / "tables"  # no programs there


def test_call_pgm_runs_the_called_program_with_shared_q_parameters():
    # call_main.h: Q1 = 10, CALL PGM SUB1, L X+Q2 Y+0, CALL PGM SUB1; sub1.h: L X+Q1 IY+5,
    # Q2 = Q1 + 7, Q1 = Q1 + 1. First call (10,5), main (17,0), second call (11,5).
    res = tc.run(DATA / "call_main.h", search_path=[DATA])
    np.testing.assert_allclose(res.path.end[:, :2], [[10, 5], [17, 0], [11, 5]])
    assert list(res.path.line) == [2, 7, 2]  # sub1.h line 2, call_main.h line 7, sub1.h line 2
    assert list(res.path.file) == [1, 0, 1]
    assert [pathlib.Path(f).name.lower() for f in res.path.files] == ["call_main.h", "sub1.h"]
    assert res.ok


@pytest.mark.parametrize("search_path", [str(DATA), DATA, [str(TABLES), str(DATA)], (TABLES, DATA)])
def test_search_path_spellings(search_path):
    res = tc.run(DATA / "call_main.h", search_path=search_path)
    assert len(res.path) == 3


def test_call_pgm_not_found_is_an_error_at_the_call_block():
    with pytest.raises(tc.ProgramError, match="SUB1.*not found") as e:
        tc.run(DATA / "call_main.h", search_path=[TABLES])  # the program's own directory is not searched
    assert (e.value.line, e.value.column) == (6, 3)
    with pytest.raises(tc.ProgramError, match="no search path"):
        tc.run(DATA / "call_main.h")
    res = tc.run(DATA / "call_main.h", strict=False)
    (d,) = res.diagnostics
    assert (d.code, d.line, d.column) == ("call_pgm_not_found", 6, 3)


def test_call_pgm_recursion_is_bounded(tmp_path):
    (tmp_path / "REC.h").write_text("0 BEGIN PGM REC MM\n1 CALL PGM REC\n2 END PGM REC MM\n")
    prog = tc.Program.parse("0 BEGIN PGM M MM\n1 CALL PGM REC\n2 END PGM M MM\n", dialect="heidenhain")
    with pytest.raises(tc.ProgramError, match="100") as e:
        tc.run(prog, search_path=[tmp_path])
    assert e.value.line == 2


@pytest.mark.parametrize("sub, error, line", [
    ("1 FN 4: Q1 = +1 DIV +0\n2 END PGM SUB MM\n", tc.ProgramError, 2),       # when it runs
    ("1 L X+5 R0 FMAX\n2 L X+10 ZZ+5\n3 END PGM SUB MM\n", tc.ParseError, 3),  # when it is read
])
def test_an_error_in_a_called_program_names_that_file(tmp_path, sub, error, line):
    (tmp_path / "SUB.h").write_text("0 BEGIN PGM SUB MM\n" + sub)
    prog = tc.Program.parse("0 BEGIN PGM M MM\n1 CALL PGM SUB\n2 END PGM M MM\n", dialect="heidenhain")
    with pytest.raises(error) as e:
        tc.run(prog, search_path=[tmp_path])
    assert e.value.line == line and pathlib.Path(e.value.file).name == "SUB.h"
