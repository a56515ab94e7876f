"""LinuxCNC parameter files (``.var``): the numbered parameters a program starts from and
leaves behind.

The format is LinuxCNC's: one parameter a line, its number, a tab and its value, numbers
ascending. LinuxCNC itself skips lines it cannot read and refuses a file whose numbers are
out of order or repeated ("Parameter file out of order"); :func:`read_var` does the same, and
:func:`write_var` keeps every line it was not asked to change (comments, unreadable lines,
the order), so a file users own is never rewritten differently than asked.

    values = tc.params.read_var("sim.var")
    res = tc.run("probe.ngc", parameters=values)
    tc.params.write_var("sim.var", res.parameters)    # only the numbers given change
"""
from __future__ import annotations

import math
import os
import re

from ._errors import ParseError
from ._files import replace_text

__all__ = ["read_var", "write_var"]

_LINE = re.compile(r"^\s*(\d+)\s+([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*$", re.ASCII)
# Values LinuxCNC's reader (C's strtod) takes that are no decimal number: nan, inf, infinity
# and hexadecimal floats. Refused with their line, never skipped as unreadable (the parameter
# would stay 0 where LinuxCNC has a value).
_NOT_DECIMAL = re.compile(r"^\s*(\d+)\s+([-+]?(?:nan|inf|0x)\S*)", re.ASCII | re.IGNORECASE)


def _parse(text: str, path: str) -> list[tuple[int | None, str]]:
    rows: list[tuple[int | None, str]] = []
    last = 0
    for lineno, line in enumerate(text.splitlines(), 1):
        text_line = line.lstrip("\ufeff") if lineno == 1 else line  # a UTF-8 byte order mark
        m = _LINE.match(text_line)
        if not m:
            odd = _NOT_DECIMAL.match(text_line)
            if odd:
                raise ParseError(f"Parameter #{int(odd.group(1))} is not a finite decimal number ({odd.group(2)}) "
                                 f"in {path}", "parameter_bad_value", lineno, 1)
            rows.append((None, line))
            continue
        n = int(m.group(1))
        if not math.isfinite(float(m.group(2))):
            raise ParseError(f"Parameter #{n} is not a finite number ({m.group(2)}) in {path}", "parameter_bad_value",
                             lineno, 1)
        if n < 1 or n > 5601:
            raise ParseError(f"Parameter number out of range: {n} in {path}", "parameter_out_of_range", lineno, 1)
        if n <= last:
            raise ParseError(f"Parameter file out of order: #{n} after #{last} in {path}", "parameter_file_order",
                             lineno, 1)
        last = n
        rows.append((n, line))
    return rows


MAX_VAR_BYTES = 64 * 2**20  # a full LinuxCNC .var file (5601 parameters) is about 100 KB


def read_var(path, max_bytes=MAX_VAR_BYTES) -> dict[int, float]:
    """The parameters of a ``.var`` file as ``{number: value}`` (unreadable lines skipped).
    Only a regular file of at most ``max_bytes`` bytes is read: ParseError
    ``not_a_regular_file`` or ``input_too_large`` otherwise."""
    path = os.fspath(path)
    if os.path.exists(path) and not os.path.isfile(path):
        raise ParseError(f"Cannot read parameter file '{path}': not a regular file", "not_a_regular_file")
    if os.path.isfile(path) and os.path.getsize(path) > max_bytes:
        raise ParseError(f"Cannot read parameter file '{path}': it is {os.path.getsize(path)} bytes, more than "
                         f"the limit of {max_bytes} bytes (max_bytes)", "input_too_large")
    with open(path, encoding="utf-8", errors="replace", newline="") as f:
        text = f.read()
    out = {}
    for n, line in _parse(text, path):
        if n is not None:
            out[n] = float(_LINE.match(line.lstrip("\ufeff")).group(2))
    return out


def write_var(path, values: dict[int, float]) -> None:
    """Set the given parameters in ``path`` (created if missing) and keep every other line.

    Values are written as LinuxCNC writes them (``%f``); new numbers go in at their place in
    the ascending order. The file is replaced atomically (a temporary file in the same
    folder, flushed to disk, renamed over the old one), so it is never left half written.
    """
    path = os.fspath(path)
    try:
        with open(path, encoding="utf-8", errors="surrogateescape", newline="") as f:
            text = f.read()
    except FileNotFoundError:
        text = ""
    newline = "\r\n" if "\r\n" in text else "\n"
    rows = _parse(text, path)
    todo = {int(k): float(v) for k, v in values.items()}
    for n, v in todo.items():
        if not 1 <= n <= 5601:
            raise ValueError(f"parameter number out of range: {n}")
        if not math.isfinite(v):
            raise ValueError(f"parameter #{n} is not a finite number: {v}")
    out: list[str] = []
    for n, line in rows:
        if n is not None:
            for m in sorted(k for k in todo if k < n):
                out.append(f"{m}\t{todo.pop(m):f}")
            if n in todo:
                line = f"{n}\t{todo.pop(n):f}"
        out.append(line)
    for m in sorted(todo):
        out.append(f"{m}\t{todo[m]:f}")
    body = newline.join(out) + (newline if out else "")
    replace_text(path, body, suffix=".var", errors="surrogateescape")
