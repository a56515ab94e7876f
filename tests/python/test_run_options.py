"""run(), iter_run() and run_many() take one set of keywords: run() defines and documents
them, iter_run() writes the ones it shares out again (for help(), IDEs and type checkers),
run_many() passes them on to run(); one function checks and converts them for the engine."""
import inspect
import re

import pytest

import toolcomp as tc


def keywords(fn):
    return {name: p for name, p in inspect.signature(fn).parameters.items() if p.kind is p.KEYWORD_ONLY}


def engine_parameters(fn):
    """The parameter names of a _core function, from the signature pybind11 writes first in its doc."""
    first = fn.__doc__.strip().splitlines()[0]
    return re.findall(r"(\w+): ", first[first.index("(") + 1:])


def test_iter_run_shares_runs_keywords_with_their_defaults_and_types():
    run, it = keywords(tc.run), keywords(tc.iter_run)
    assert set(run) - set(it) == set(tc._ONLY["run"])
    assert set(it) - set(run) == set(tc._ONLY["iter_run"])
    for name in set(run) & set(it):
        assert (it[name].default, it[name].annotation) == (run[name].default, run[name].annotation), name
    assert [p.name for p in inspect.signature(tc.iter_run).parameters.values()][:2] == ["program", "tools"]


def test_run_many_shows_runs_keywords():
    many = inspect.signature(tc.run_many).parameters
    assert list(many)[:4] == ["programs", "tools", "workers", "return_exceptions"]
    run = keywords(tc.run)
    assert list(many)[4:] == list(run)
    for name, p in run.items():
        assert many[name].default == (None if name == "threads" else p.default), name  # threads: chosen unless given


def test_the_docstrings_name_what_iter_run_does_not_take():
    for name in tc._ONLY["run"]:
        assert f"``{name}``" in tc.iter_run.__doc__.split("The keywords are")[1].split("Memory:")[0], name
    assert "iter_run" in tc.run.__doc__ and "run_many" in tc.run.__doc__


def test_every_count_is_a_keyword_with_a_valid_default():
    params = {**keywords(tc.run), **keywords(tc.iter_run)}
    for name, (least, most) in tc._COUNTS.items():
        default = params[name].default
        assert isinstance(default, int) and default >= least and (most is None or default <= most), name


@pytest.mark.parametrize("entry, engine_file, engine_program", [
    ("run", "run_file", "run"),
    ("iter_run", "iter_run_file", "iter_run_program"),
])
def test_the_engine_takes_every_keyword_as_converted(entry, engine_file, engine_program):
    fn = getattr(tc, entry)
    defaults = {name: p.default for name, p in keywords(fn).items()}
    for program, engine in (("part.ngc", engine_file), (tc.Program.parse("G0 X1\nM2\n"), engine_program)):
        dialect, tools, options = tc._engine_options(program, None, **defaults)
        takes = set(engine_parameters(getattr(tc._core, engine)))
        if engine == "iter_run_program":
            options.pop("piece_bytes")  # as iter_run does: a Program is not read in pieces
        assert set(options) <= takes, set(options) - takes
        assert {"dialect", "units"}.isdisjoint(options)


def test_counts_are_checked_alike():
    prog = tc.Program.parse("G0 X1\nM2\n")
    for fn in (tc.run, tc.iter_run):
        for name in set(tc._COUNTS) & set(keywords(fn)):
            with pytest.raises(TypeError, match=name):
                fn(prog, **{name: 1.5})
            with pytest.raises(ValueError, match=name):
                fn(prog, **{name: 0})
    with pytest.raises(ValueError, match="piece_bytes must be from 1 to 1073741824"):
        tc.iter_run(prog, piece_bytes=2**30 + 1)


def test_run_many_reads_a_table_and_a_machine_once(tmp_path, monkeypatch):
    table = tmp_path / "tools.tbl"
    table.write_text("T1 P1 Z10 D6\n")
    seen = []

    def fake_run(program, tools=None, **kwargs):
        seen.append((tools, kwargs))
        return program

    monkeypatch.setattr(tc, "run", fake_run)
    tc.run_many(["a.ngc", "b.ngc"], table, units="inch", machine="haas-mill", workers=1)
    (t1, k1), (t2, k2) = seen
    assert isinstance(t1, tc.ToolTable) and t1 is t2 and t1.units == "inch" and "units" not in k1
    assert isinstance(k1["machine"], tc.Machine) and k1["machine"] is k2["machine"]
    seen.clear()
    tc.run_many(["a.ngc"], machine="lathe")
    assert seen[0][1]["machine"] == "lathe"  # run() makes the profile: it depends on the program's control
