"""One table of dialects in the engine: the command line, the pytest plugin and reading a
file by its suffix all take it from there."""
import toolcomp as tc
from toolcomp import cli, pytest_plugin


def test_the_table():
    rows = tc._core.dialect_table()
    assert [r["name"] for r in rows] == ["linuxcnc", "fanuc", "sinumerik", "heidenhain", "rockwell"]
    assert {s: r["name"] for r in rows for s in r["suffixes"]} == {
        ".ngc": "linuxcnc", ".nc": "fanuc", ".tap": "fanuc", ".mpf": "sinumerik", ".spf": "sinumerik",
        ".h": "heidenhain"}


def test_everyone_reads_it():
    rows = tc._core.dialect_table()
    assert cli.DIALECTS == tuple(r["name"] for r in rows)
    assert pytest_plugin.SUFFIXES is cli.SUFFIX_DIALECTS
    for r in rows:
        for suffix in r["suffixes"]:
            assert tc._core.dialect_of_file("part" + suffix.upper()) == r["name"]
        assert tc._core.dialect_of_file("part.txt", r["name"]) == r["name"]
