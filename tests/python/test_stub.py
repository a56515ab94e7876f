"""The type stub _core.pyi declares what the compiled module has, no more and no less: every
public name of the module and of each of its classes (enum members too)."""
import ast
import pathlib

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
    out += [f"{where}.{n} is not in the stub" for n in sorted(have - said)]
    out += [f"{where}.{n} is in the stub, not in the module" for n in sorted(said - have)]
    for n in sorted(have & said):
        if isinstance(stub[n], dict):
            compare(getattr(obj, n), stub[n], f"{where}.{n}", out)


def test_the_stub_matches_the_module():
    out = []
    compare(core, declared(ast.parse(STUB.read_text()).body), "_core", out)
    assert not out, "\n".join(out)
