"""Write the Python docstrings of toolcomp._core into a C++ header, from `///` comments.

Every docstring of the bindings is written once, as a `///` comment block:

* in a header of cpp/include/toolcomp, directly above the declaration it documents (a struct,
  class, enum, enumerator, data member or function). Its name is the declaration's, qualified
  by the enclosing structs and namespaces (without `toolcomp`): `///` above the member
  `overcut_tolerance` of `struct RadiusRules` becomes `pydoc::RadiusRules_overcut_tolerance`.
* in python/bindings (a Python-only name: a lambda, a property computed in the binding), where
  its first line names it: `/// @pydoc Result.cycle_time` becomes `pydoc::Result_cycle_time`.
  The same line also names a block in a header whose declaration has no usable name.

The text is the block's lines without `/// `, joined by spaces; an empty `///` line starts a
new paragraph (a blank line in the docstring). Usage:

    gen_docstrings.py OUTPUT FILE...

OUTPUT (a header declaring `pydoc::NAME` constants) is rewritten only when its text changes.
A block not followed by a declaration, or two blocks of one name, are errors.
"""
import os
import re
import sys

OPENER = re.compile(r"\b(?:struct|class|union|enum(?:\s+class|\s+struct)?|namespace)\s+([\w:]*)")
EXPLICIT = re.compile(r"^@pydoc\s+([\w.]+)\s*$")
# The text of string and character literals and of comments: no braces or semicolons of the code.
LITERALS = re.compile(r'"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])\'|//.*$')


def code_of(line):
    return LITERALS.sub(lambda m: "" if m.group(0).startswith("//") else '""', line)


def without_templates(text):
    text = re.sub(r"\btemplate\s*<.*?>\s*", "", text)
    while True:
        shorter = re.sub(r"<[^<>;{}()]*>", "", text)
        if shorter == text:
            return text
        text = shorter


def declared_name(lines):
    """The name a declaration (one or more lines of code) declares, or None."""
    text = without_templates(" ".join(code_of(line).strip() for line in lines))
    text = re.sub(r"\[\[.*?\]\]", "", text)
    opener = OPENER.match(text.strip())
    if opener:
        return opener.group(1) or None
    text = re.sub(r"\b\w+::", "", text)  # std::string name; -> string name;
    m = re.search(r"~?\b(\w+)\s*[(=;\[{,:]", text)
    if m and not m.group(1) in ("operator", "public", "private", "protected"):
        return m.group(1)
    return None


def read_blocks(path):
    """(name, text, path:line) of every /// block in a file."""
    lines = open(path, encoding="utf-8").read().splitlines()
    out, stack, pending = [], [], None
    i = 0
    while i < len(lines):
        stripped = lines[i].strip()
        if stripped.startswith("///"):
            start = i
            body = []
            while i < len(lines) and lines[i].strip().startswith("///"):
                s = lines[i].strip()[3:]
                body.append(s[1:] if s.startswith(" ") else s)
                i += 1
            where = f"{os.path.relpath(path)}:{start + 1}"
            m = EXPLICIT.match(body[0])
            if m:
                name, body = m.group(1).replace(".", "_"), body[1:]
            else:
                if any(entry is None for entry in stack):
                    sys.exit(f"{where}: a /// block inside a function needs a first line '@pydoc NAME'")
                decl = [line for line in lines[i:i + 4] if line.strip() and not line.strip().startswith("//")]
                member = None
                for n in range(1, len(decl) + 1):
                    member = declared_name(decl[:n])
                    if member:
                        break
                if not member:
                    sys.exit(f"{where}: no declaration after this /// block (or name it: '/// @pydoc NAME')")
                scopes = [s for entry in stack for s in entry.split("::") if s and s != "toolcomp"]
                name = "_".join(scopes + [member])
            paragraphs = " ".join(line if line else "\n\n" for line in body)
            text = re.sub(r" ?\n\n ?", "\n\n", paragraphs).strip()
            if not text:
                sys.exit(f"{where}: an empty /// block")
            out.append((name, text, where))
            continue
        code = code_of(lines[i])
        for m in OPENER.finditer(without_templates(code)):
            pending = m.group(1)
        for ch in code:
            if ch == "{":
                stack.append(pending)  # None: a function body, an initializer
                pending = None
            elif ch == "}" and stack:
                stack.pop()
            elif ch == ";":
                pending = None
        i += 1
    return out


def literal(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def main(output, *files):
    seen, entries = {}, []
    for path in files:
        for name, text, where in read_blocks(path):
            if name in seen:
                sys.exit(f"{where}: pydoc::{name} is documented twice (also at {seen[name]})")
            seen[name] = where
            entries.append(f"// {where}\ninline constexpr const char {name}[] = {literal(text)};")
    text = ("// Generated by python/tools/gen_docstrings.py from the /// comments of the headers and\n"
            "// bindings: edit those, not this file.\n#pragma once\n\nnamespace pydoc {\n"
            + "\n".join(entries) + "\n}  // namespace pydoc\n")
    try:
        unchanged = open(output, encoding="utf-8").read() == text
    except OSError:
        unchanged = False
    if not unchanged:  # unchanged: no recompilation of the bindings
        with open(output, "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(*sys.argv[1:])
