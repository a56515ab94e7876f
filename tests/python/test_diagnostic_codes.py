"""The catalogue of diagnostic codes (cpp/include/toolcomp/program/codes.inc) is complete:
call sites name codes from it instead of spelling them, every code a run of the test
programs reports is in it, the Python package raises only catalogued codes, and
doc/diagnostics.md is generated from it."""
import pathlib
import re
import subprocess
import sys

import pytest

import toolcomp as tc

ROOT = pathlib.Path(__file__).resolve().parents[2]
CATALOGUE = {row["code"]: row for row in tc._core.diagnostic_codes()}


def test_the_catalogue_is_well_formed():
    assert len(CATALOGUE) == len(tc._core.diagnostic_codes())  # no code twice
    for code, row in CATALOGUE.items():
        assert re.fullmatch(r"[a-z][a-z0-9_]*|[0-9]{4,5}", code), code
        assert row["kind"] in ("Error", "ParseError", "ProgramError", "CompensationError", "ToolTableError")
        assert row["severity"] in ("error", "warning", "info")
        assert row["alarm"] in ("", code)  # a control's alarm number is its own code
    for code in ("arc_too_many_turns", "travel_limit", "machine_file", "14040", "no_progress"):
        assert code in CATALOGUE


def test_no_call_site_spells_a_code_out():
    literal = re.compile(r'"([a-z0-9_]+)"')
    found = []
    for path in sorted((ROOT / "cpp" / "src").rglob("*.[ch]pp")):
        for n, line in enumerate(path.read_text().splitlines(), 1):
            code_part = line.split("//")[0]
            if 'bad("' in code_part:  # ControlProfile / Machine field names in check messages
                continue
            for m in literal.finditer(code_part):
                if m.group(1) in CATALOGUE:
                    found.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert not found, "use code::<name> from toolcomp/program/codes.hpp:\n" + "\n".join(found)


def test_the_python_package_raises_catalogued_codes():
    raised = re.compile(r'Error\(\s*f?"[^"]*"(?:\s*f?"[^"]*")*\s*,\s*"([a-z0-9_]+)"')
    for path in sorted((ROOT / "python" / "toolcomp").glob("*.py")):
        text = path.read_text()
        for m in raised.finditer(text):
            assert m.group(1) in CATALOGUE, f"{path.name}: {m.group(1)}"
    assert "machine_file" in CATALOGUE and "parameter_bad_value" in CATALOGUE


SUFFIX = {".ngc": "linuxcnc", ".nc": "fanuc", ".mpf": "sinumerik", ".spf": "sinumerik", ".h": "heidenhain"}


def _codes_of(path):
    dialect = SUFFIX.get(path.suffix.lower())
    if dialect is None:
        return set()
    try:
        res = tc.run(tc.Program.parse(path.read_text(errors="replace"), dialect=dialect, strict=False), strict=False)
    except tc.Error as e:
        return {e.code}
    return {d.code for d in res.diagnostics}


@pytest.mark.parametrize("folder", ["bad", "errors", "heidenhain", "comp", "macros"])
def test_every_code_a_run_reports_is_catalogued(folder):
    seen = set()
    for path in sorted((ROOT / "tests" / "programs" / folder).iterdir()):
        if path.is_file():
            seen |= _codes_of(path)
    assert seen, folder
    assert seen <= set(CATALOGUE), sorted(seen - set(CATALOGUE))


def test_the_documentation_is_generated_from_the_catalogue():
    r = subprocess.run([sys.executable, str(ROOT / "doc" / "gen_diagnostics.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    text = (ROOT / "doc" / "diagnostics.md").read_text()
    for code in CATALOGUE:
        assert f"`{code}`" in text
