"""Writes doc/diagnostics.md from the engine's catalogue of diagnostic codes
(cpp/include/toolcomp/program/codes.inc, read through toolcomp._core.diagnostic_codes).

    python doc/gen_diagnostics.py          # rewrite doc/diagnostics.md
    python doc/gen_diagnostics.py --check  # exit 1 when it is out of date (the tests do this)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def render(rows):
    out = [
        "# Diagnostic codes",
        "",
        "Every code toolcomp raises (as `tc.Error` and its subclasses, `.code`) or reports (as",
        "`Diagnostic.code`), from the engine's catalogue",
        "(`cpp/include/toolcomp/program/codes.inc`; this page is generated from it by",
        "`doc/gen_diagnostics.py`). Codes are stable: a code keeps its meaning once it is here.",
        "A number is the control's own alarm (Sinumerik). *Text*: the message, with what the block",
        "gives in &lt;angle brackets&gt;, or where a code's messages vary, what they say.",
        "",
        "| code | raised as | severity | text |",
        "|---|---|---|---|",
    ]
    for r in rows:
        text = r["text"].replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;")
        code = f"`{r['code']}`" + (" (alarm)" if r["alarm"] else "")
        out.append(f"| {code} | {r['kind']} | {r['severity']} | {text} |")
    return "\n".join(out) + "\n"


def main(argv):
    import toolcomp._core as core

    text = render(core.diagnostic_codes())
    path = os.path.join(HERE, "diagnostics.md")
    if "--check" in argv:
        with open(path, encoding="utf-8") as f:
            if f.read() != text:
                print("doc/diagnostics.md is out of date: run python doc/gen_diagnostics.py", file=sys.stderr)
                return 1
        return 0
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
