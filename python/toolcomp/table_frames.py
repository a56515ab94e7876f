"""Tool tables as pandas DataFrames, and differences between two tables.

``table.to_pandas()`` gives one row per cutting edge with the common tool model's fields;
``ToolTable.from_pandas(df, base=table)`` writes edited values back into a copy of ``base``
(comments, unknown columns and untouched tools stay as they were, so a save changes only
the edited lines); ``table.diff(other)`` lists what differs, field by field.
pandas is an optional dependency (``pip install 'toolcomp[pandas]'``), imported on use.
"""
from __future__ import annotations

import math
from typing import List, NamedTuple, Optional

import numpy as np

from . import _core
from ._optional import require

_VEC = {"length": ("x", "y", "z"), "rotary": ("a", "b", "c"), "uvw": ("u", "v", "w"),
        "length_wear": ("x_wear", "y_wear", "z_wear")}
_SCALAR = ("radius", "corner_radius", "radius_wear", "corner_radius_wear", "orientation",
           "front_angle", "back_angle")
COLUMNS = ("tool", "edge", "pocket", "name", "comment", *sum(_VEC.values(), ()), *_SCALAR)


def _rows(table):
    for t in table:
        for e in t.edges:
            row = {"tool": t.number, "edge": e.number, "pocket": t.pocket, "name": t.name, "comment": t.comment}
            for field, cols in _VEC.items():
                row.update(zip(cols, (float(v) for v in getattr(e, field))))
            for field in _SCALAR:
                row[field] = getattr(e, field)
            yield row


def to_pandas(table: "_core.ToolTable"):
    """One row per cutting edge: tool, edge, pocket, name, comment, x..w, wear, radii, tip."""
    pd = require("pandas", "pandas", "ToolTable.to_pandas")
    return pd.DataFrame(list(_rows(table)), columns=list(COLUMNS))


def _copy(table: "_core.ToolTable") -> "_core.ToolTable":
    fmt = table.format or "json"
    return _core.ToolTable.parse(table.dumps(fmt), fmt, units=table.units)


def from_pandas(df, base: Optional["_core.ToolTable"] = None, units: str = "mm") -> "_core.ToolTable":
    """A table from a DataFrame shaped like :func:`to_pandas`'s; with ``base``, a copy of it
    with the rows' values written over (tools not in ``df`` are kept). Missing columns keep
    the base's values (or the defaults). A missing value (NaN, None, pd.NA) in a number
    column keeps the base's value; where no base value exists (no ``base``, or a tool or edge
    that is not in it) it is refused with ValueError naming the tool and the column, rather
    than becoming 0 (a 6 mm cutter whose radius was lost in column arithmetic would be
    taken as radius 0)."""
    table = _copy(base) if base is not None else _core.ToolTable(units)
    missing = {"tool"} - set(df.columns)
    if missing:
        raise ValueError("from_pandas needs a 'tool' column")
    for rec in df.to_dict("records"):
        if _isnan(rec["tool"]):
            raise ValueError("from_pandas: a row without a tool number")
        number = _whole(rec, "tool")
        tool = table.get(number) or _core.Tool(number)
        for field in ("pocket", "name", "comment"):
            if field in rec and not _isnan(rec[field]):
                setattr(tool, field, _whole(rec, field, number) if field == "pocket" else str(rec[field]))
        d = _whole(rec, "edge", number) if "edge" in rec and not _isnan(rec["edge"]) else 1
        given = base.get(number) if base is not None else None
        known = given is not None and given.has_edge(d)  # the base gives this edge's values
        edge = tool.edge(d) if tool.has_edge(d) else _core.CuttingEdge(number=d)
        for field, cols in _VEC.items():
            if any(c in rec for c in cols):
                v = np.array(getattr(edge, field), dtype=float)
                for i, c in enumerate(cols):
                    if c in rec and not _missing(rec, c, number, d, known):
                        v[i] = _number(rec, c, number)
                setattr(edge, field, v)
        for field in _SCALAR:
            if field in rec and not _missing(rec, field, number, d, known):
                setattr(edge, field, _whole(rec, field, number) if field == "orientation" else _number(rec, field, number))
        tool.set_edge(edge)
        table.set(tool)
    return table


def _missing(rec, field, tool, edge, known) -> bool:
    """Whether a number cell is missing, which only a base value may fill."""
    if not _isnan(rec[field]):
        return False
    if not known:
        raise ValueError(f"from_pandas: {field} of tool {tool} (edge {edge}) is missing (NaN) and no base table "
                         "gives it; fill it in (0 where 0 is meant)")
    return True


def _isnan(v) -> bool:
    """A missing value: NaN, None or pandas' NA."""
    if v is None:
        return True
    try:
        return bool(v != v)  # NaN; pd.NA compares as NA, which bool() refuses
    except TypeError:
        return True


def _number(rec, field, tool=None) -> float:
    try:
        v = float(rec[field])
    except (TypeError, ValueError):
        where = f" (tool {tool})" if tool is not None else ""
        raise ValueError(f"from_pandas: {field}{where} is not a number: {rec[field]!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"from_pandas: {field} (tool {tool}) is not a finite number: {v}")
    return v


def _whole(rec, field, tool=None) -> int:
    """A tool, pocket, edge or orientation number: a whole number, never cut down."""
    v = _number(rec, field, tool)
    if not v.is_integer():
        raise ValueError(f"from_pandas: {field} must be a whole number, not {rec[field]!r}")
    return int(v)


class Change(NamedTuple):
    tool: int
    edge: int      # 0 for tool-level fields and for added or removed tools
    field: str     # a column of to_pandas, or "added" / "removed"
    old: object
    new: object


def diff(a: "_core.ToolTable", b: "_core.ToolTable", tol: float = 0.0) -> List[Change]:
    """What changes from ``a`` to ``b``: tools added and removed, then every differing
    field (numbers compared with ``tol``), sorted by tool, edge and column order."""
    ra = {(r["tool"], r["edge"]): r for r in _rows(a)}
    rb = {(r["tool"], r["edge"]): r for r in _rows(b)}
    out: List[Change] = []
    ta, tb = set(a.numbers), set(b.numbers)
    out += [Change(n, 0, "removed", n, None) for n in sorted(ta - tb)]
    out += [Change(n, 0, "added", None, n) for n in sorted(tb - ta)]
    for key in sorted(set(ra) & set(rb)):
        for col in COLUMNS[2:]:
            x, y = ra[key][col], rb[key][col]
            same = (abs(x - y) <= tol) if isinstance(x, (int, float)) and isinstance(y, (int, float)) else x == y
            if not same:
                out.append(Change(key[0], key[1], col, x, y))
    for key in sorted(set(ra) ^ set(rb)):
        if key[0] in ta and key[0] in tb:
            out.append(Change(key[0], key[1], "removed" if key in ra else "added",
                              key[1] if key in ra else None, key[1] if key in rb else None))
    return out


__all__ = ["to_pandas", "from_pandas", "diff", "Change", "COLUMNS"]
