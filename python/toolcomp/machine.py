"""Machine files: a control plus what its builder configured, as TOML (doc/machines.md).

    m = tc.Machine.read("haas_vf2.toml")      # or tc.Machine.preset("haas-mill")
    res = tc.run("part.nc", tools=tools, machine=m)
    m.write("copy.toml")                      # reads back to the same machine

A machine file names the control and the kind of machine, overrides fields of the control's
:class:`ControlProfile`, declares the builder's M codes, places program zero and the G28 /
G30 / tool change positions in machine coordinates, and gives the axis travel and rates::

    name = "Haas VF-2"
    control = "fanuc"            # linuxcnc | fanuc | sinumerik | heidenhain | rockwell
    kind = "mill"                # mill | lathe
    units = "mm"                 # of the lengths and rates below: mm | inch

    [profile]                    # ControlProfile fields that differ from the control's
    call_depth_limit = 10

    [m_codes]                    # number = action, or { action = ..., name = ... }
    31 = { action = "nothing", name = "chip conveyor forward" }
    59 = { action = "nothing", name = "set output relay", words = "P" }   # reads P
    88 = "coolant_on"

    [positions]                  # machine coordinates
    work_origin = [-400.0, -200.0, -500.0]   # where program zero (G54) is
    g28 = [0, 0, 0]
    start = [0, 0, 0]            # where the axes stand when a program starts
    tool_change = { z = 0 }      # M6 sends Z there first

    [travel]                     # [min, max] of each axis, machine coordinates
    x = [-762, 0]
    y = [-406, 0]
    z = [-508, 0]
    limit = "error"              # a move beyond: error (stops the run) | warning

    [rates]                      # mm/min (in/min with units = "inch")
    rapid = [25400, 25400, 25400]
    max_feed = [16510, 16510, 16510]
    tool_change = 4.2            # seconds, chip to chip

Every mistake in a file is a :class:`ParseError` with code ``machine_file`` and the line of
the key it is about.
"""
from __future__ import annotations

import enum
import math
import os
import re
import sys
from typing import Any, Dict, List, Optional, Tuple, Union

from . import _core
from ._errors import ParseError
from ._files import replace_text

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = ["read", "parse", "dumps", "write", "preset", "presets", "resolve"]

_PRESETS = os.path.join(os.path.dirname(__file__), "machines")
_CONTROLS = tuple(row["name"] for row in _core.dialect_table())
_AXES = ("x", "y", "z")
_TOP = {"name", "control", "kind", "units", "spindles", "profile", "m_codes", "g_codes", "cycles", "machine_data",
        "positions", "travel", "rates"}
_MM_PER_INCH = 25.4


class _Source:
    """The file's text, to say on which line a key stands."""

    def __init__(self, text: str, path: Optional[str]):
        self.lines = text.splitlines()
        self.path = path

    def line_of(self, section: Optional[str], key: Optional[str] = None, exact: bool = False) -> int:
        """The line of `key` in `section` ([section] or section.key), or of the section header
        (0 with `exact`)."""
        current = None
        header_line = 0
        for n, raw in enumerate(self.lines, 1):
            line = raw.strip()
            m = re.match(r"^\[\s*([^\]]+?)\s*\]", line)
            if m:
                current = m.group(1).replace('"', "")
                if current == section:
                    header_line = n
                continue
            if key is None:
                continue
            m = re.match(r'^"?([^"=\s]+)"?\s*=', line)
            if not m:
                continue
            name = m.group(1)
            if section is None and current is None and name == key:
                return n
            if current == section and name == key:
                return n
            if current is None and name == f"{section}.{key}":
                return n
        return 0 if exact else header_line

    def error(self, message: str, section: Optional[str] = None, key: Optional[str] = None, line: int = 0):
        line = line or self.line_of(section, key)
        where = f"{self.path}: " if self.path else ""
        return ParseError(where + message, "machine_file", line, 0)


def _number(src, section, key, v, what="a number", infinite=False) -> float:
    """A finite number (or with `infinite`, also inf / -inf: a travel without that bound)."""
    ok = not isinstance(v, bool) and isinstance(v, (int, float))
    try:
        f = float(v) if ok else math.nan
    except OverflowError:
        f = math.nan
    if not (math.isfinite(f) or (infinite and math.isinf(f))):
        raise src.error(f"{section + '.' if section else ''}{key} must be {what}, not {v!r}", section, key)
    return f


def _table(src, doc, name) -> Dict[str, Any]:
    value = doc.get(name, {})
    if not isinstance(value, dict):
        raise src.error(f"{name} must be a table ([{name}])", None, name)
    return value


def _triple(src, section, key, v, scale) -> Tuple[float, float, float]:
    if not isinstance(v, list) or len(v) != 3:
        raise src.error(f"{section}.{key} must be [x, y, z], not {v!r}", section, key)
    return tuple(_number(src, section, key, x, "a list of three numbers") * scale for x in v)


def _m_code_line(src, number: str) -> int:
    """The line of an M code's key, written 30 or M30."""
    return (src.line_of("m_codes", number, exact=True) or src.line_of("m_codes", "M" + number, exact=True)
            or src.line_of("m_codes", "m" + number))


# ---- profile fields ----------------------------------------------------------------------

def _fields(obj) -> List[str]:
    """The settable fields (properties) of a bound object, in name order."""
    cls = type(obj)
    return sorted(a for a in dir(cls) if not a.startswith("_") and isinstance(getattr(cls, a), property)
                  and getattr(cls, a).fset is not None)


def _is_record(v) -> bool:
    """A nested bound object with fields of its own (RadiusRules, its messages)."""
    return type(v).__module__.startswith("toolcomp") and not isinstance(v, enum.Enum) and bool(_fields(v)) \
        and not hasattr(type(v), "__members__")


def _set_fields(src, target, table: Dict[str, Any], section: str) -> None:
    for key, value in table.items():
        if key not in _fields(target):
            raise src.error(f"{section} has no field '{key}'", section, key)
        current = getattr(target, key)
        if _is_record(current):
            if not isinstance(value, dict):
                raise src.error(f"{section}.{key} is a table of fields", section, key)
            _set_fields(src, current, value, f"{section}.{key}")
            setattr(target, key, current)
            continue
        try:
            if hasattr(type(current), "__members__"):  # a pybind enum: by name
                members = type(current).__members__
                if value not in members:
                    raise ValueError(f"one of {', '.join(members)}")
                value = members[value]
            elif isinstance(current, tuple):
                value = tuple(value)
            elif isinstance(current, bool) and not isinstance(value, bool):
                raise ValueError("true or false")
            setattr(target, key, value)
        except (ValueError, TypeError) as e:
            raise src.error(f"{section}.{key} = {value!r} is refused: {e}", section, key) from None


def _profile_diff(profile, default) -> Dict[str, Any]:
    """The fields of `profile` that differ from `default`, as TOML values."""
    out: Dict[str, Any] = {}
    for key in _fields(profile):
        a, b = getattr(profile, key), getattr(default, key)
        if _is_record(a):
            sub = _profile_diff(a, b)
            if sub:
                out[key] = sub
        elif a != b:
            out[key] = a.name if hasattr(type(a), "__members__") else (list(a) if isinstance(a, tuple) else a)
    return out


# ---- reading -------------------------------------------------------------------------------

def parse(text: str, path: Optional[str] = None) -> "_core.Machine":
    """A Machine from the text of a machine file (`path` names it in messages)."""
    src = _Source(text, path)
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        m = re.search(r"line (\d+)", str(e))
        raise src.error(f"not TOML: {e}", line=int(m.group(1)) if m else 0) from None
    for key in doc:
        if key not in _TOP:
            raise src.error(f"unknown key '{key}' (known: {', '.join(sorted(_TOP))})",
                            line=src.line_of(None, key) or src.line_of(key))
    control = doc.get("control")
    if control not in _CONTROLS:
        raise src.error(f"control must be one of {', '.join(_CONTROLS)}, not {control!r}", None, "control")
    kind = doc.get("kind", "mill")
    if kind not in ("mill", "lathe"):
        raise src.error(f"kind must be 'mill' or 'lathe', not {kind!r}", None, "kind")
    units = doc.get("units", "mm")
    if units not in ("mm", "inch"):
        raise src.error(f"units must be 'mm' or 'inch', not {units!r}", None, "units")
    scale = _MM_PER_INCH if units == "inch" else 1.0
    name = doc.get("name", f"{control}-{kind}")
    if not isinstance(name, str):
        raise src.error("name must be text", None, "name")
    m = _core.Machine(control, kind, name)
    spindles = doc.get("spindles", 1)
    if not isinstance(spindles, int) or isinstance(spindles, bool) or not 1 <= spindles <= 8:
        raise src.error("spindles must be a whole number from 1 to 8", None, "spindles")
    m.spindles = spindles

    profile = m.profile
    table = _table(src, doc, "profile")
    _set_fields(src, profile, table, "profile")
    m.profile = profile  # its values are checked with the machine's, below

    codes = {}
    for key, value in _table(src, doc, "m_codes").items():
        number_text = key[1:] if key[:1] in ("M", "m") else key
        if not number_text.isdigit():
            raise src.error(f"m_codes: '{key}' is no M code number", "m_codes", key)
        number = int(number_text)
        if isinstance(value, str):
            value = {"action": value}
        if (not isinstance(value, dict) or set(value) - {"action", "name", "words", "program", "argspec"}
                or "action" not in value):
            raise src.error(f"m_codes.{key} must be an action or {{ action = ..., name = ..., words = ..., "
                            "program = ..., argspec = ... }}", "m_codes", key)
        try:
            codes[number] = _core.MachineCode(value["action"], str(value.get("name", "")),
                                              str(value.get("words", "")).upper(), str(value.get("program", "")),
                                              str(value.get("argspec", "")))
        except ValueError as e:
            raise src.error(f"m_codes.{key}: {e}", "m_codes", key) from None
    try:
        m.m_codes = codes
    except ValueError as e:
        bad = re.search(r"M(\d+)", str(e))
        raise src.error(f"m_codes: {e}", line=_m_code_line(src, bad.group(1)) if bad else src.line_of("m_codes")) from None

    gcodes = {}  # LinuxCNC's remapped G codes: "88.6" = { program = ..., argspec = ... }
    for key, value in _table(src, doc, "g_codes").items():
        text = key[1:] if key[:1] in ("G", "g") else key
        try:
            number = float(text)
        except ValueError:
            raise src.error(f"g_codes: '{key}' is no G code number", "g_codes", key) from None
        if not isinstance(value, dict) or set(value) - {"name", "program", "argspec"} or "program" not in value:
            raise src.error(f"g_codes.{key} must be {{ program = ..., argspec = ..., name = ... }}", "g_codes", key)
        gcodes[number] = _core.MachineCode("subprogram", str(value.get("name", "")), "", str(value["program"]),
                                           str(value.get("argspec", "")))
    try:
        m.g_codes = gcodes
    except ValueError as e:
        raise src.error(f"g_codes: {e}", "g_codes") from None

    cycles = {}  # Heidenhain builder cycles: 392 = { action = "nothing", name = "ATC" }
    for key, value in _table(src, doc, "cycles").items():
        if not key.isdigit():
            raise src.error(f"cycles: '{key}' is no cycle number", "cycles", key)
        if isinstance(value, str):
            value = {"action": value}
        if not isinstance(value, dict) or set(value) - {"action", "name"} or "action" not in value:
            raise src.error(f"cycles.{key} must be an action or {{ action = ..., name = ... }}", "cycles", key)
        try:
            cycles[int(key)] = _core.MachineCode(value["action"], str(value.get("name", "")))
        except ValueError as e:
            raise src.error(f"cycles.{key}: {e}", "cycles", key) from None
    m.cycles = cycles

    data = {}  # Sinumerik machine and setting data: "$MN_SCALING_VALUE_INCH" = 25.4
    for key, value in _table(src, doc, "machine_data").items():
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise src.error(f"machine_data.{key} must be a number", "machine_data", key)
        data[key] = float(value)
    m.machine_data = data

    positions = _table(src, doc, "positions")
    for key, value in positions.items():
        if key in ("work_origin", "g28", "g30", "m92", "start"):
            setattr(m, key, _triple(src, "positions", key, value, scale))
        elif key == "tool_change":
            if not isinstance(value, dict) or set(value) - set(_AXES):
                raise src.error("positions.tool_change must be { x = .., y = .., z = .. } (any of them)",
                                "positions", key)
            m.tool_change = tuple(None if a not in value else _number(src, "positions", key, value[a]) * scale
                                  for a in _AXES)
        else:
            raise src.error(f"positions has no '{key}' (work_origin, g28, g30, m92, start, tool_change)", "positions",
                            key)

    travel = _table(src, doc, "travel")
    limits = [(-math.inf, math.inf)] * 3
    for key, value in travel.items():
        if key == "limit":
            if value not in ("error", "warning"):
                raise src.error("travel.limit must be 'error' or 'warning'", "travel", key)
            m.travel_limit_warning = value == "warning"
        elif key in _AXES:
            if not isinstance(value, list) or len(value) != 2:
                raise src.error(f"travel.{key} must be [min, max]", "travel", key)
            lo, hi = (_number(src, "travel", key, v, "a number (or inf)", infinite=True) * scale for v in value)
            if lo > hi:
                raise src.error(f"travel.{key}: min {value[0]} is above max {value[1]}", "travel", key)
            limits[_AXES.index(key)] = (lo, hi)
        else:
            raise src.error(f"travel has no '{key}' (x, y, z, limit)", "travel", key)
    m.travel = limits

    for key, value in _table(src, doc, "rates").items():
        if key == "tool_change":
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 <= value < math.inf:
                raise src.error("rates.tool_change must be the seconds a tool change takes (a number >= 0)",
                                "rates", key)
            m.tool_change_time = float(value)
            continue
        if key not in ("rapid", "max_feed"):
            raise src.error(f"rates has no '{key}' (rapid, max_feed, tool_change)", "rates", key)
        v = _triple(src, "rates", key, value, scale)
        if min(v) < 0:
            raise src.error(f"rates.{key} must not be negative", "rates", key)
        setattr(m, "rapid_rate" if key == "rapid" else "max_feed", v)
    try:
        m.check()
    except ValueError as e:
        bad = re.search(r"M(\d+) ", str(e))
        if bad:
            raise src.error(str(e), line=_m_code_line(src, bad.group(1))) from None
        field = re.search(r"ControlProfile\.([\w.]+)", str(e))
        path = field.group(1).split(".") if field else []
        raise src.error(str(e), ".".join(["profile"] + path[:-1]) if path else None,
                        path[-1] if path else None) from None
    return m


def read(path: str | os.PathLike[str]) -> "_core.Machine":
    """A Machine from a machine file (TOML)."""
    path = os.fspath(path)
    if os.path.exists(path) and not os.path.isfile(path):
        raise ParseError(f"Cannot read machine file '{path}': not a regular file", "not_a_regular_file")
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except FileNotFoundError:
        raise ParseError(f"Cannot read machine file '{path}': no such file", "file_not_found") from None
    except UnicodeDecodeError as e:
        raise ParseError(f"Cannot read machine file '{path}': not UTF-8 text ({e.reason})", "machine_file") from None
    return parse(text, path)


# ---- writing -------------------------------------------------------------------------------

def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        if isinstance(v, float) and math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        out = []
        for ch in v:  # TOML basic strings: escape the quote, the backslash and control characters
            if ch in ('"', "\\"):
                out.append("\\" + ch)
            elif ord(ch) < 0x20 or ord(ch) == 0x7F:
                out.append(f"\\u{ord(ch):04X}")
            else:
                out.append(ch)
        return '"' + "".join(out) + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {v!r} to TOML")


def _write_table(lines: List[str], name: str, table: Dict[str, Any]) -> None:
    plain = {k: v for k, v in table.items() if not isinstance(v, dict)}
    nested = {k: v for k, v in table.items() if isinstance(v, dict)}
    if plain or not nested:
        lines.append(f"\n[{name}]")
        lines += [f"{k} = {_toml_value(v)}" for k, v in plain.items()]
    for k, v in nested.items():
        _write_table(lines, f"{name}.{k}", v)


def dumps(m: "_core.Machine") -> str:
    """The machine as the text of a machine file (mm); parse() of it gives the same machine."""
    control, kind = m.control, m.kind.name
    lines = [f"name = {_toml_value(m.name)}", f"control = {_toml_value(control)}", f"kind = {_toml_value(kind)}",
             'units = "mm"']
    if m.spindles != 1:
        lines.append(f"spindles = {m.spindles}")
    diff = _profile_diff(m.profile, _core.ControlProfile(control, kind))
    if diff:
        _write_table(lines, "profile", diff)
    def code_line(key, code, fields):  # a code as an inline table of its fields that are set
        value = {f: getattr(code, f) for f in fields if getattr(code, f)}
        return f"{key} = {{ " + ", ".join(f"{k} = {_toml_value(v)}" for k, v in value.items()) + " }"

    if m.m_codes:
        lines.append("\n[m_codes]")
        lines += [code_line(n, c, ("action", "name", "words", "program", "argspec")) for n, c in sorted(m.m_codes.items())]
    if m.g_codes:
        lines.append("\n[g_codes]")
        lines += [code_line(f'"{n:g}"', c, ("program", "argspec", "name")) for n, c in sorted(m.g_codes.items())]
    if m.machine_data:
        lines.append("\n[machine_data]")
        lines += [f"{_toml_value(n)} = {_toml_value(v)}" for n, v in sorted(m.machine_data.items())]
    if m.cycles:
        lines.append("\n[cycles]")
        lines += [code_line(n, c, ("action", "name")) for n, c in sorted(m.cycles.items())]
    lines.append("\n[positions]")
    lines.append(f"work_origin = {_toml_value(list(m.work_origin))}")
    lines.append(f"g28 = {_toml_value(list(m.g28))}")
    lines.append(f"g30 = {_toml_value(list(m.g30))}")
    if any(m.start):
        lines.append(f"start = {_toml_value(list(m.start))}")
    if m.control == "heidenhain" or any(m.m92):
        lines.append(f"m92 = {_toml_value(list(m.m92))}")
    given = {a: v for a, v in zip(_AXES, m.tool_change) if v is not None}
    if given:
        lines.append("tool_change = { " + ", ".join(f"{a} = {_toml_value(v)}" for a, v in given.items()) + " }")
    travel = [(a, t) for a, t in zip(_AXES, m.travel) if math.isfinite(t[0]) or math.isfinite(t[1])]
    if travel or m.travel_limit_warning:
        lines.append("\n[travel]")
        lines += [f"{a} = {_toml_value(list(t))}" for a, t in travel]
        lines.append(f"limit = {_toml_value('warning' if m.travel_limit_warning else 'error')}")
    if any(m.rapid_rate) or any(m.max_feed) or m.tool_change_time:
        lines.append("\n[rates]")
        lines.append(f"rapid = {_toml_value(list(m.rapid_rate))}")
        lines.append(f"max_feed = {_toml_value(list(m.max_feed))}")
        lines.append(f"tool_change = {_toml_value(m.tool_change_time)}")
    return "\n".join(lines) + "\n"


def write(m: "_core.Machine", path: str | os.PathLike[str]) -> None:
    """Write the machine file, replaced atomically (never half written; a link and the
    file's permissions are kept)."""
    replace_text(path, dumps(m), suffix=".toml")


# ---- presets and what run() takes ----------------------------------------------------------

def presets() -> List[str]:
    """The names of the built-in machines."""
    return sorted(n[:-5] for n in os.listdir(_PRESETS) if n.endswith(".toml"))


def preset(name: str) -> "_core.Machine":
    """A built-in machine: 'haas-mill', 'haas-lathe', or a control's plain machine
    ('linuxcnc', 'fanuc-mill', 'fanuc-lathe', 'sinumerik-mill', 'sinumerik-lathe', 'heidenhain',
    'rockwell'); see presets()."""
    if name not in presets():
        raise ValueError(f"no machine preset '{name}' (presets: {', '.join(presets())})")
    return read(os.path.join(_PRESETS, name + ".toml"))


def resolve(machine) -> Union["_core.Machine", str, None]:
    """What run(), iter_run() and run_many() take as machine=, as they give it to the engine:
    a Machine (as it is, or read from a preset name or the path of a machine file, .toml),
    None, or 'mill' / 'lathe' as they are (the control's plain profile of that kind, the
    former shorthand: it depends on the program's control, so run() makes it)."""
    if machine is None or isinstance(machine, _core.Machine) or machine in ("mill", "lathe"):
        return machine
    if isinstance(machine, os.PathLike) or (isinstance(machine, str) and machine.endswith(".toml")):
        return read(machine)
    if isinstance(machine, str):
        return preset(machine)
    raise TypeError(f"machine must be a Machine, a preset name or a .toml path, not {type(machine).__name__}")
