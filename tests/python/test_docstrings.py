"""Every public name reached through ``toolcomp`` and ``toolcomp.sinumerik`` has a docstring."""
import inspect
import re

import toolcomp as tc
import toolcomp.sinumerik as sinumerik

_METHOD_TYPES = ("instancemethod", "builtin_function_or_method", "staticmethod", "function", "classmethod")


def _auto_only(name, doc):
    """True when ``doc`` is empty or only the signature line pybind11 generates."""
    doc = (doc or "").strip()
    if not doc:
        return True
    lines = [line for line in doc.splitlines() if line.strip()]
    # pybind11 overloads: "name(*args, **kwargs)\nOverloaded function.\n\n1. name(...) -> ...\n..."
    if all(line.startswith(name + "(") or line.strip() == "Overloaded function."
           or re.match(r"^\d+\. " + re.escape(name) + r"\(", line) for line in lines):
        return True
    return False


def _missing(module, names, prefix=""):
    missing = []
    for n in names:
        if n.startswith("__"):
            continue
        o = getattr(module, n)
        if isinstance(o, (int, float, str)) or inspect.ismodule(o):
            continue
        if inspect.isclass(o):
            if not (o.__doc__ or "").strip():
                missing.append(prefix + n)
            for a, v in vars(o).items():
                if a.startswith("_") or a in ("name", "value"):
                    continue
                if isinstance(v, property) or type(v).__name__ in _METHOD_TYPES:
                    if _auto_only(a, getattr(v, "__doc__", None)):
                        missing.append(f"{prefix}{n}.{a}")
            members = getattr(o, "__members__", None)
            if members and "Members:" in (o.__doc__ or ""):  # pybind11 enum: every value documented
                for m in members:
                    if not re.search(r"^\s*" + re.escape(m) + r" : \S", o.__doc__, re.M):
                        missing.append(f"{prefix}{n}.{m}")
        elif callable(o):
            if _auto_only(n, o.__doc__):
                missing.append(prefix + n)
    return missing


def test_toolcomp_public_names_have_docstrings():
    assert _missing(tc, tc.__all__) == []


def test_sinumerik_public_names_have_docstrings():
    assert (sinumerik.__doc__ or "").strip()
    names = [n for n in dir(sinumerik) if not n.startswith("_")]
    assert _missing(sinumerik, names, "sinumerik.") == []


def test_checker_detects_missing_docstrings():
    class Bare:
        @property
        def prop(self):
            return 1

        def meth(self):
            pass

    class Ns:
        pass

    ns = Ns()
    ns.Bare = Bare
    assert sorted(_missing(ns, ["Bare"])) == ["Bare", "Bare.meth", "Bare.prop"]
    assert _auto_only("f", "f(x: int) -> int\n")
    assert not _auto_only("f", "f(x: int) -> int\n\nDoubles x.")
