"""pytest plugin: NC program files become test items.

Configure the folder in ``pyproject.toml``::

    [tool.toolcomp]
    programs = "nc/"          # folder (relative to the rootdir) whose programs are tests
    tools = "nc/tools.tbl"    # default tool table (optional)
    dialect = "linuxcnc"      # default dialect (optional; otherwise from each suffix)
    machine = "haas-mill"     # the machine (optional): a preset or a machine file (.toml)
    start = "machine_zero"    # where the axes stand (optional): "machine_zero" or [x, y, z] mm
    fail_on_warnings = false

(or the ini options ``toolcomp_programs``, ``toolcomp_tools``, ``toolcomp_dialect``). A
``toolcomp.toml`` in a sub-folder overrides ``tools``, ``dialect``, ``machine``, ``start`` and
``fail_on_warnings`` for the programs in it (paths relative to that file), and a program's
own header line ``(toolcomp: tools=lathe.tbl dialect=fanuc machine=haas-lathe start=0,0,50)``
(or with ``;``) overrides both. ``start`` is :func:`toolcomp.run`'s: without it, the machine's
start, else where the program first sends each axis. Each program runs once; it fails with its diagnostics as
``file:line:column: severity code message``.
"""
from __future__ import annotations

import os
import pathlib
import re
from typing import Dict, Optional

import pytest

from .cli import SUFFIX_DIALECTS as SUFFIXES
_HEADER = re.compile(r"toolcomp:\s*(.*?)\s*\)?\s*$", re.IGNORECASE)


def _toml(path: pathlib.Path) -> dict:
    from .machine import tomllib  # the standard library's, or tomli before Python 3.11

    with open(path, "rb") as f:
        return tomllib.load(f)


def pytest_addoption(parser):
    parser.addini("toolcomp_programs", "folder of NC programs collected as tests", default="")
    parser.addini("toolcomp_tools", "default tool table for collected NC programs", default="")
    parser.addini("toolcomp_dialect", "default dialect for collected NC programs", default="")


def _settings(config) -> Optional[dict]:
    cached = getattr(config, "_toolcomp_settings", False)
    if cached is not False:
        return cached
    root = pathlib.Path(str(config.rootpath))
    s: dict = {}
    pp = root / "pyproject.toml"
    if pp.is_file():
        s = dict(_toml(pp).get("tool", {}).get("toolcomp", {}))
    for key in ("programs", "tools", "dialect"):
        v = config.getini(f"toolcomp_{key}")
        if v:
            s[key] = v
    result = None
    if s.get("programs"):
        result = {"programs": (root / s["programs"]).resolve(),
                  "tools": str((root / s["tools"]).resolve()) if s.get("tools") else None,
                  "dialect": s.get("dialect"),
                  "machine": str((root / s["machine"]).resolve()) if _is_file_option("machine", s.get("machine", ""))
                  else s.get("machine"),
                  "start": s.get("start"),
                  "fail_on_warnings": bool(s.get("fail_on_warnings", False))}
    config._toolcomp_settings = result
    return result


def _header(path: pathlib.Path) -> Dict[str, str]:
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for _ in range(5):
                m = _HEADER.search(f.readline())
                if m:
                    return dict(kv.split("=", 1) for kv in m.group(1).split() if "=" in kv)
    except OSError:
        pass
    return {}


def _is_file_option(key, value) -> bool:
    """A setting that names a file, relative to where it is given: the tool table, and a
    machine file (a machine may also be a preset name)."""
    return key == "tools" or (key == "machine" and str(value).endswith(".toml"))


def _options(path: pathlib.Path, base: dict) -> dict:
    opts = dict(base)
    folders = []
    d = path.parent
    while True:
        folders.append(d)
        if d == base["programs"] or d.parent == d:
            break
        d = d.parent
    for folder in reversed(folders):  # outermost first, the nearest wins
        f = folder / "toolcomp.toml"
        if f.is_file():
            for k, v in _toml(f).items():
                opts[k] = str((folder / v).resolve()) if _is_file_option(k, v) else v
    for k, v in _header(path).items():
        opts[k] = str((path.parent / v).resolve()) if _is_file_option(k, v) else v
    if isinstance(opts.get("start"), str) and opts["start"] != "machine_zero":  # a header's "x,y,z"
        opts["start"] = [float(v) for v in opts["start"].split(",")]
    if isinstance(opts.get("fail_on_warnings"), str):
        opts["fail_on_warnings"] = opts["fail_on_warnings"].lower() in ("1", "true", "yes")
    return opts


def pytest_collect_file(file_path, parent):
    s = _settings(parent.config)
    if s is None or file_path.suffix.lower() not in SUFFIXES:
        return None
    p = pathlib.Path(file_path).resolve()
    if s["programs"] != p and s["programs"] not in p.parents:
        return None
    return NCProgramFile.from_parent(parent, path=file_path)


class NCProgramFailure(Exception):
    pass


class NCProgramFile(pytest.File):
    def collect(self):
        yield NCProgramItem.from_parent(self, name="run")


class NCProgramItem(pytest.Item):
    def runtest(self):
        import toolcomp as tc

        path = pathlib.Path(self.path)
        opts = _options(path.resolve(), _settings(self.config))
        dialect = opts.get("dialect") or SUFFIXES[path.suffix.lower()]
        res = tc.run(str(path), tools=opts.get("tools"), dialect=dialect, strict=False, machine=opts.get("machine"),
                     start=opts.get("start"))
        bad = [d for d in res.diagnostics
               if d.severity == "error" or (opts.get("fail_on_warnings") and d.severity == "warning")]
        if bad:
            rel = os.path.relpath(str(path), str(self.config.rootpath))
            raise NCProgramFailure("\n".join(f"{rel}:{d.line}:{d.column}: {d.severity} {d.code} {d.message}"
                                             for d in bad))

    def repr_failure(self, excinfo):
        if isinstance(excinfo.value, NCProgramFailure):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.path, 0, f"NC program {self.path.name}"
