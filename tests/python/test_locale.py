"""Programs read the same whatever the process's locale. Python sets LC_CTYPE from the
environment; a C library's letter tests (isalpha, toupper) follow it, so in a Latin-1 locale
the bytes of a UTF-8 'é' (0xC3 0xA9) are letters. toolcomp's readers use ASCII tests only:
an 'é' after an axis letter is a bad number in every locale (it was read as the start of an
expression, "Unexpected 'Ã' in expression", under de_DE.ISO-8859-1)."""
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

SCRIPT = textwrap.dedent("""
    import locale, sys
    import toolcomp as tc
    if sys.argv[1] != "C":
        locale.setlocale(locale.LC_CTYPE, sys.argv[1])
    def outcome(text, dialect):
        try:
            res = tc.run(tc.Program.parse(text, dialect=dialect))
            return ("ok", len(res.path))
        except tc.Error as e:
            return (e.code, e.line, e.column)
    print(repr([outcome("G21 G1 X\\u00e91 F100\\nM2\\n", "linuxcnc"),
                outcome("G21 G1 X1 F100\\n#<\\u00e9t\\u00e9> = 2\\nG1 X#<\\u00e9t\\u00e9>\\nM2\\n", "linuxcnc"),
                outcome("G21 G1 X1 F100\\nG1 Y\\u00e41\\nM2\\n", "fanuc")]))
""")


def outcomes(env, loc):
    out = subprocess.run([sys.executable, "-c", SCRIPT, loc], env=env, capture_output=True, text=True, check=True)
    return out.stdout.strip()


def test_the_same_reading_in_a_latin1_locale(tmp_path):
    if shutil.which("localedef") is None:
        pytest.skip("no localedef to build a Latin-1 locale with")
    made = subprocess.run(["localedef", "-i", "de_DE", "-f", "ISO-8859-1", str(tmp_path / "de_DE.ISO-8859-1")],
                          capture_output=True)
    if not (tmp_path / "de_DE.ISO-8859-1").exists():
        pytest.skip(f"localedef could not build de_DE.ISO-8859-1: {made.stderr[-200:]!r}")
    env = dict(os.environ, LOCPATH=str(tmp_path), LC_ALL="")
    env.pop("LC_ALL")
    want = outcomes(env, "C")
    assert want.startswith("[('bad_number_format', 1, 9), ('ok', 2), ('bad_number_format', 2, 5)")
    assert outcomes(env, "de_DE.ISO-8859-1") == want
