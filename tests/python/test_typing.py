"""The public API is typed: a script that calls tc.run / tc.iter_run wrongly fails mypy, a
right one passes (the package's annotations and its _core.pyi)."""
import pathlib

import pytest

mypy_api = pytest.importorskip("mypy.api")

PACKAGE_ROOT = pathlib.Path(__file__).resolve().parents[2] / "python"

GOOD = """
import pathlib
import toolcomp as tc

res: tc.Result = tc.run("part.ngc", tools="tools.tbl", strict=False, search_path=["subs", pathlib.Path("more")],
                        parameters={5220: 1.0}, machine="haas-mill", progress=print)
ends = res.path.end
for chunk in tc.iter_run(pathlib.Path("part.ngc"), chunk=1000):
    n: int = len(chunk)
"""

BAD = """
import toolcomp as tc

tc.run("part.ngc", strict="yes")
res: int = tc.run("part.ngc")
tc.iter_run("part.ngc", chunk="many")
"""


def check(tmp_path, text, monkeypatch):
    script = tmp_path / "script.py"
    script.write_text(text)
    monkeypatch.setenv("MYPYPATH", str(PACKAGE_ROOT))
    out, err, status = mypy_api.run([str(script), "--follow-imports=silent", "--no-incremental",
                                     "--cache-dir", str(tmp_path / "cache")])
    return out, status


def test_a_right_script_passes_mypy(tmp_path, monkeypatch):
    out, status = check(tmp_path, GOOD, monkeypatch)
    assert status == 0, out


def test_a_wrong_script_fails_mypy_at_each_mistake(tmp_path, monkeypatch):
    out, status = check(tmp_path, BAD, monkeypatch)
    assert status == 1
    assert [line.split(":")[1] for line in out.splitlines() if ": error:" in line] == ["4", "5", "6"]
