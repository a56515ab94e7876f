"""Programs a run calls by name, in every dialect: found only inside the search directories
(a symbolic link out of one is refused unless follow_links=True), read only when they are
regular files, and within the limits the caller set for the run (max_bytes,
max_line_length), whether the main program is a file or a parsed Program."""
import os

import numpy as np
import pytest

import toolcomp as tc

# Per dialect: the main program (its call on line 2), the called file's name and its text
# (one feed move to X1).
CASES = {
    "linuxcnc": ("G21 G0 X0 Y0\no<sub> call\nM2\n", "sub.ngc",
                 "o<sub> sub\nG1 X1 F100\no<sub> endsub\nM2\n"),
    "fanuc": ("G21 G0 X0 Y0\nM98 P1000\nM30\n", "O1000.nc", "O1000\nG1 X1 F100\nM99\n"),
    "heidenhain": ("0 BEGIN PGM MAIN MM\n1 CALL PGM SUB\n2 END PGM MAIN MM\n", "SUB.h",
                   "0 BEGIN PGM SUB MM\n1 L X+1 Y+0 R0 F100\n2 END PGM SUB MM\n"),
    "sinumerik": ("G0 X0 Y0\nL10\nM30\n", "L10.spf", "G1 X1 F100\nM17\n"),
}
DIALECTS = sorted(CASES)


def _main(dialect):
    return tc.Program.parse(CASES[dialect][0], dialect=dialect)


def _error(dialect, search, **kwargs):
    with pytest.raises(tc.Error) as e:
        tc.run(_main(dialect), search_path=[search], **kwargs, start="machine_zero")
    assert e.value.line == 2, e.value
    return e.value


@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_called_file_runs(dialect, tmp_path):
    _, name, text = CASES[dialect]
    (tmp_path / name).write_text(text)
    res = tc.run(_main(dialect), search_path=[tmp_path], start="machine_zero")
    assert res.nominal.end[-1, 0] == 1.0


# ---- limits ------------------------------------------------------------------------------

@pytest.mark.parametrize("dialect", DIALECTS)
def test_max_bytes_holds_for_called_files(dialect, tmp_path):
    _, name, text = CASES[dialect]
    (tmp_path / name).write_text(text)
    size = len(text.encode())
    e = _error(dialect, tmp_path, max_bytes=size - 1)
    assert e.code == "input_too_large"
    assert f"it is {size} bytes, more than the limit of {size - 1} bytes" in e.message
    tc.run(_main(dialect), search_path=[tmp_path], max_bytes=size, start="machine_zero")  # at the limit: read


@pytest.mark.parametrize("dialect", DIALECTS)
def test_max_bytes_holds_for_files_called_by_a_program_file(dialect, tmp_path):
    main, name, text = CASES[dialect]
    first, rest = text.split("\n", 1)
    pad = ("(" + "x" * 60 + ")") if dialect in ("linuxcnc", "fanuc") else ";" + "x" * 60
    text = first + "\n" + pad + "\n" + rest  # larger than the main program
    (tmp_path / "subs").mkdir()
    (tmp_path / "subs" / name).write_text(text)
    suffix = {"linuxcnc": ".ngc", "fanuc": ".nc", "heidenhain": ".h", "sinumerik": ".mpf"}[dialect]
    (tmp_path / ("main" + suffix)).write_text(main)
    with pytest.raises(tc.Error) as e:
        tc.run(tmp_path / ("main" + suffix), search_path=[tmp_path / "subs"], max_bytes=len(main) + 1, start="machine_zero")
    assert (e.value.code, e.value.line) == ("input_too_large", 2)
    with pytest.raises(tc.Error) as e:
        list(tc.iter_run(tmp_path / ("main" + suffix), search_path=[tmp_path / "subs"], max_bytes=len(main) + 1))
    assert (e.value.code, e.value.line) == ("input_too_large", 2)


@pytest.mark.parametrize("dialect", DIALECTS)
def test_max_line_length_holds_for_called_files(dialect, tmp_path):
    _, name, text = CASES[dialect]
    (tmp_path / name).write_text(text)
    longest = max(len(line) for line in text.splitlines())
    e = _error(dialect, tmp_path, max_line_length=longest - 1)
    assert e.code == "line_too_long"
    tc.run(_main(dialect), search_path=[tmp_path], max_line_length=longest, start="machine_zero")


def test_iter_run_of_a_program_holds_the_limits_too(tmp_path):
    _, name, text = CASES["linuxcnc"]
    (tmp_path / name).write_text(text)
    with pytest.raises(tc.Error) as e:
        list(tc.iter_run(_main("linuxcnc"), search_path=[tmp_path], max_bytes=10))
    assert e.value.code == "input_too_large"


# ---- links -------------------------------------------------------------------------------

@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_link_out_of_the_search_directory_is_refused(dialect, tmp_path):
    _, name, text = CASES[dialect]
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "elsewhere" / name).write_text(text)
    (tmp_path / "subs").mkdir()
    os.symlink(tmp_path / "elsewhere" / name, tmp_path / "subs" / name)
    e = _error(dialect, tmp_path / "subs")
    assert e.code == "outside_search_path"
    assert "follow_links=True" in e.message
    res = tc.run(_main(dialect), search_path=[tmp_path / "subs"], follow_links=True, start="machine_zero")
    assert res.nominal.end[-1, 0] == 1.0


@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_link_within_the_search_directory_runs(dialect, tmp_path):
    _, name, text = CASES[dialect]
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "real_file").write_text(text)
    os.symlink("lib/real_file", tmp_path / name)  # relative, inside the search directory
    res = tc.run(_main(dialect), search_path=[tmp_path], start="machine_zero")
    assert res.nominal.end[-1, 0] == 1.0


def test_a_search_directory_that_is_a_link_is_its_own_place(tmp_path):
    _, name, text = CASES["linuxcnc"]
    (tmp_path / "real").mkdir()
    (tmp_path / "real" / name).write_text(text)
    os.symlink(tmp_path / "real", tmp_path / "alias")
    res = tc.run(_main("linuxcnc"), search_path=[tmp_path / "alias"], start="machine_zero")
    assert res.nominal.end[-1, 0] == 1.0


def test_heidenhain_cannot_reach_the_root_through_a_link(tmp_path):
    os.symlink("/", tmp_path / "root")
    prog = tc.Program.parse("0 BEGIN PGM MAIN MM\n1 CALL PGM TNC:\\root\\etc\\hostname\n2 END PGM MAIN MM\n",
                            dialect="heidenhain")
    with pytest.raises(tc.Error) as e:
        tc.run(prog, search_path=[tmp_path], start="machine_zero")
    assert (e.value.code, e.value.line) == ("outside_search_path", 2)


@pytest.mark.parametrize("dialect", DIALECTS)
def test_a_dangling_link_is_no_entry_and_the_search_goes_on(dialect, tmp_path):
    _, name, text = CASES[dialect]
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    os.symlink(tmp_path / "nothing", tmp_path / "a" / name)
    (tmp_path / "b" / name).write_text(text)
    for follow in (False, True):
        res = tc.run(_main(dialect), search_path=[tmp_path / "a", tmp_path / "b"], follow_links=follow, start="machine_zero")
        assert res.nominal.end[-1, 0] == 1.0
        assert res.nominal.files[1].startswith(str(tmp_path / "b"))


# ---- what is not a regular file ----------------------------------------------------------

@pytest.mark.parametrize("dialect", DIALECTS)
@pytest.mark.parametrize("kind", ["fifo", "directory"])
def test_a_fifo_or_directory_of_the_name_is_refused_as_such(dialect, kind, tmp_path):
    _, name, _ = CASES[dialect]
    if kind == "fifo":
        os.mkfifo(tmp_path / name)
    else:
        (tmp_path / name).mkdir()
    e = _error(dialect, tmp_path)
    assert e.code == "not_a_regular_file"
    assert ("a FIFO (named pipe)" if kind == "fifo" else "a directory") in e.message


def test_a_device_linked_into_the_search_directory(tmp_path):
    os.symlink("/dev/zero", tmp_path / "sub.ngc")
    assert _error("linuxcnc", tmp_path).code == "outside_search_path"
    e = _error("linuxcnc", tmp_path, follow_links=True)
    assert e.code == "not_a_regular_file" and "a character device" in e.message


# ---- the search path itself --------------------------------------------------------------

@pytest.mark.parametrize("search", [[""], ["subs", ""]])
def test_an_empty_search_directory_is_refused(search):
    with pytest.raises(ValueError, match="empty directory name"):
        tc.run(_main("linuxcnc"), search_path=search, start="machine_zero")
    with pytest.raises(ValueError, match="empty directory name"):
        tc.iter_run(_main("linuxcnc"), search_path=search)


def test_the_engine_refuses_an_empty_search_directory_too():
    with pytest.raises(tc.Error) as e:
        tc._core.run(_main("linuxcnc"), search_path=[""])
    assert e.value.code == "search_path_empty"


def test_sinumerik_picks_the_same_file_whatever_the_directory_order(tmp_path):
    # L10.SPF before L10.MPF before L10, and among spellings the first in byte order.
    (tmp_path / "L10").write_text("G1 X3 F100\nM17\n")
    (tmp_path / "l10.mpf").write_text("G1 X2 F100\nM17\n")
    (tmp_path / "l10.spf").write_text("G1 X1 F100\nM17\n")
    (tmp_path / "L10.Spf").write_text("G1 X4 F100\nM17\n")
    res = tc.run(_main("sinumerik"), search_path=[tmp_path], start="machine_zero")
    assert os.path.basename(res.nominal.files[1]) == "L10.Spf"
    np.testing.assert_array_equal(res.nominal.end[-1], [4, 0, 0])


def test_the_command_line_refuses_an_empty_search_directory_as_a_usage_error(tmp_path):
    import subprocess
    import sys

    (tmp_path / "p.ngc").write_text("G0 X1\nM2\n")
    r = subprocess.run([sys.executable, "-m", "toolcomp", "run", str(tmp_path / "p.ngc"), "--search-path", ""],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "empty directory name" in r.stderr
