"""Bad input corpus (tests/programs/bad/, written by make_bad.py): truncated files, binary
garbage, huge and tiny numbers, NaN/inf spellings, 100,000-character lines, deep nesting,
unbalanced comments and brackets, unknown words, duplicate modal codes, bad arcs, missing
tools, negative radii, CRLF / CR-only line ends, BOMs and non-ASCII text, for every dialect
and tool table format.

expected.json gives each file's outcome: a tc.Error with its ``code`` (or, with "message",
the alarm number the message starts with) at its ``line``, or ``ok``. Whatever the outcome,
nothing but a tc.Error may escape and no path may hold NaN/inf coordinates. Known defects
are marked ``xfail`` (strict) with the reason; ``crash`` cases run in a subprocess because
they take the interpreter down."""
import json
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import toolcomp as tc

HERE = pathlib.Path(__file__).resolve().parent
BAD = HERE.parent / "programs" / "bad"
MANIFEST = json.loads((BAD / "expected.json").read_text(encoding="utf-8"))

# Tools 1-4 for every dialect (T4 has a negative diameter); Heidenhain and Sinumerik programs
# find them as tool 1..4 edge 1, Fanuc lathe / 9/Series programs as offsets 1..4.
TOOLS_TEXT = "T1 P1 Z25 D6\nT2 P2 Z30 D10\nT3 P3 Z20 D4\nT4 P4 Z10 D-4\n"


def _finite_path(res):
    """None when the programmed and compensated paths hold only finite coordinates (arc
    centres included; a line's centre may be NaN), else what is wrong."""
    for label, p in (("nominal", res.nominal), ("path", res.path)):
        for col in ("start", "end"):
            bad = ~np.isfinite(getattr(p, col)).all(axis=1)
            if bad.any():
                return f"{label}.{col} not finite at source line(s) {sorted(set(p.line[bad].tolist()))[:5]}"
        arcs = p.kind >= tc.ARC_CW
        bad = arcs & ~np.isfinite(p.center).all(axis=1)
        if bad.any():
            return f"{label}.center of an arc not finite at line(s) {sorted(set(p.line[bad].tolist()))[:5]}"
    return None


def outcome(name, exp):
    """Runs one case; returns a plain dict (so a subprocess can send it back as JSON)."""
    path = str(BAD / name)
    try:
        if "table_format" in exp:
            table = tc.ToolTable.read(path)
            return {"kind": "ok", "tools": len(table)}
        tools = tc.ToolTable.parse(TOOLS_TEXT, "linuxcnc")
        profile = None
        if "block_limit" in exp:
            profile = tc.ControlProfile(exp["dialect"])
            profile.block_limit = exp["block_limit"]
        prog = tc.Program.read(path, dialect=exp["dialect"])
        res = tc.run(prog, tools, profile=profile, start="machine_zero")
        return {"kind": "ok", "segments": len(res.path), "nonfinite": _finite_path(res)}
    except tc.Error as e:
        return {"kind": "error", "type": type(e).__name__, "code": e.code, "message": e.message, "line": e.line}
    except Exception as e:  # noqa: BLE001 - any other exception is the finding
        return {"kind": "exception", "type": type(e).__name__, "message": str(e)[:200]}


def lenient_outcome(name, exp):
    """The same program read and run with strict=False: the path up to the first error must
    be finite too, and still nothing but a tc.Error may escape."""
    tools = tc.ToolTable.parse(TOOLS_TEXT, "linuxcnc")
    profile = None
    if "block_limit" in exp:
        profile = tc.ControlProfile(exp["dialect"])
        profile.block_limit = exp["block_limit"]
    try:
        prog = tc.Program.read(str(BAD / name), dialect=exp["dialect"], strict=False)
        res = tc.run(prog, tools, profile=profile, strict=False, start="machine_zero")
    except tc.Error:
        return None
    except Exception as e:  # noqa: BLE001
        return f"{type(e).__name__} escaped with strict=False: {str(e)[:200]}"
    return _finite_path(res)


def outcome_in_subprocess(name, exp):
    code = ("import json, sys; sys.path.insert(0, sys.argv[1]); import test_bad_inputs as t; "
            "print(json.dumps(t.outcome(sys.argv[2], json.loads(sys.argv[3]))))")
    p = subprocess.run([sys.executable, "-c", code, str(HERE), name, json.dumps(exp)],
                       capture_output=True, text=True, timeout=60)
    if p.returncode != 0:
        return {"kind": "crash", "returncode": p.returncode, "stderr": p.stderr[-500:]}
    return json.loads(p.stdout.strip().splitlines()[-1])


def _params():
    for name, exp in MANIFEST.items():
        marks = [pytest.mark.xfail(strict=True, reason=exp["xfail"])] if "xfail" in exp else []
        yield pytest.param(name, exp, id=name, marks=marks)


def test_manifest_matches_the_corpus():
    files = {p.name for p in BAD.iterdir() if p.name not in ("make_bad.py", "expected.json")}
    assert files == set(MANIFEST), (sorted(files - set(MANIFEST)), sorted(set(MANIFEST) - files))
    for name, exp in MANIFEST.items():
        assert (BAD / name).stat().st_size < 200_000, name
        assert ("dialect" in exp) != ("table_format" in exp), name
        assert exp.get("ok") or ("code" in exp and "line" in exp), name


@pytest.mark.parametrize("name,exp", list(_params()))
def test_bad_input(name, exp):
    got = outcome_in_subprocess(name, exp) if exp.get("crash") else outcome(name, exp)
    assert got["kind"] != "crash", f"the process died (return code {got.get('returncode')}): {got.get('stderr')}"
    assert got["kind"] != "exception", f"{got['type']} escaped instead of a tc.Error: {got['message']}"
    if got["kind"] == "ok":
        assert not got.get("nonfinite"), got["nonfinite"]
    if exp.get("ok"):
        assert got["kind"] == "ok", f"expected success, got {got['type']} {got['code']} line {got['line']}: {got['message']}"
        if "tools" in exp:
            assert got["tools"] == exp["tools"]
        if "min_segments" in exp:
            assert got["segments"] >= exp["min_segments"]
    else:
        assert got["kind"] == "error", f"expected {exp['code']} at line {exp['line']}, but it was accepted ({got})"
        if "table_format" in exp:
            assert got["type"] == "ToolTableError"
        assert (got["code"], got["line"]) == (exp["code"], exp["line"]), got["message"]
        if "message" in exp:
            assert got["message"].startswith(exp["message"]), got["message"]
    if "dialect" in exp and not exp.get("crash"):
        problem = lenient_outcome(name, exp)
        assert problem is None, problem


@pytest.mark.parametrize("dialect, text", [
    ("linuxcnc", "G0 X1\nG1 X2 \x00 F10\nM2\n"),
    ("linuxcnc", "G0 X1\no<a\x00b> call\nM2\n"),
    ("heidenhain", "0 BEGIN PGM A MM\n1 L X+1\x00 R0 FMAX\n2 END PGM A MM\n"),
])
def test_a_nul_byte_is_shown_escaped_in_the_message(dialect, text):
    # A C string ends at a NUL: the message was cut there ("Bad character '").
    with pytest.raises(tc.Error) as e:
        tc.run(tc.Program.parse(text, dialect=dialect))
    assert "\x00" not in e.value.message
    before, after = e.value.message.split("\\x00", 1)
    assert after  # the message goes on past the byte
