"""The type stub _core.pyi declares what the compiled module has, no more and no less: every
public name of the module and of each of its classes (enum members too). It is generated from
the module, and mypy reads it without an error."""
import ast
import pathlib
import subprocess
import sys

import pytest

import toolcomp._core as core

STUB = pathlib.Path(core.__file__).with_name("_core.pyi")
if not STUB.exists():  # an installed module beside the source tree's stub
    STUB = pathlib.Path(__file__).resolve().parents[2] / "python" / "toolcomp" / "_core.pyi"


def declared(body):
    names = {}
    for node in body:
        if isinstance(node, ast.ClassDef):
            names[node.name] = declared(node.body)
        elif isinstance(node, ast.FunctionDef):
            names[node.name] = None
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names[node.target.id] = None
        elif isinstance(node, ast.Assign):
            names.update({t.id: None for t in node.targets if isinstance(t, ast.Name)})
    return names


def public(obj):
    names = {n for n in dir(obj) if not n.startswith("_")}
    if isinstance(obj, type) and hasattr(obj, "__members__"):  # an enum: its members, not name / value
        names -= {"name", "value"}
    return names


def compare(obj, stub, where, out):
    have, said = public(obj), {n for n in stub if not n.startswith("_")}
    if isinstance(obj, type) and hasattr(obj, "__members__"):  # the stub may declare them or not
        said -= {"name", "value"}
    out += [f"{where}.{n} is not in the stub" for n in sorted(have - said)]
    out += [f"{where}.{n} is in the stub, not in the module" for n in sorted(said - have)]
    for n in sorted(have & said):
        if isinstance(stub[n], dict):
            compare(getattr(obj, n), stub[n], f"{where}.{n}", out)


def test_the_stub_matches_the_module():
    out = []
    compare(core, declared(ast.parse(STUB.read_text()).body), "_core", out)
    assert not out, "\n".join(out)


ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_the_stub_is_what_the_generator_writes():
    """_core.pyi is generated (python/tools/gen_stub.py, `make stub`): the committed file is
    what the current module gives, signatures and docstrings alike."""
    pytest.importorskip("pybind11_stubgen")
    run = subprocess.run([sys.executable, str(ROOT / "python" / "tools" / "gen_stub.py"), "--check"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-20000:] + run.stderr[-5000:]


def test_mypy_accepts_the_stub(tmp_path):
    mypy_api = pytest.importorskip("mypy.api")
    out, err, status = mypy_api.run([str(ROOT / "python" / "toolcomp" / "_core.pyi"), "--no-incremental",
                                     "--cache-dir", str(tmp_path / "cache")])
    assert status == 0, out + err
