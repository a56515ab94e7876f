"""Checks of a tool table before it goes to a machine.

``check_table(table, lathe=False)`` returns findings as :class:`toolcomp.Diagnostic` objects
(line 0: the table readers do not keep a tool's source line):

* ``pocket_conflict`` (error): two tools in the same pocket (pocket 0 means none);
* ``missing_orientation`` (error, lathes only): a tool with a nose radius and no tip
  orientation 1-9, so nose radius compensation cannot know where the tip is;
* ``negative_radius`` (warning): LinuxCNC runs G41 as G42 (and back) with it, other
  controls refuse or do the same; rarely what was meant;
* ``zero_radius`` (warning): a milling tool with no radius: G41/G42 do nothing with it;
* ``radius_wear_exceeds_radius`` (error): geometry plus wear is negative.

Duplicate tool numbers are refused by the readers themselves (``ToolTableError`` with the
line of the second definition).
"""
from __future__ import annotations

from typing import List

from . import _core


def check_table(table: "_core.ToolTable", lathe: bool = False) -> List["_core.Diagnostic"]:
    found: List[_core.Diagnostic] = []

    def add(code: str, severity: str, message: str) -> None:
        found.append(_core.Diagnostic(code, severity, message, 0, 0))

    pockets: dict = {}
    for tool in table:
        if tool.pocket:
            if tool.pocket in pockets:
                add("pocket_conflict", "error",
                    f"tools T{pockets[tool.pocket]} and T{tool.number} are both in pocket P{tool.pocket}")
            else:
                pockets[tool.pocket] = tool.number
        for e in tool.edges:
            name = f"T{tool.number}" + (f" D{e.number}" if len(tool.edges) > 1 else "")
            if e.radius < 0:
                add("negative_radius", "warning",
                    f"{name} has a negative radius {e.radius:g}: G41 and G42 swap sides with it")
            elif e.radius == 0 and not lathe:
                add("zero_radius", "warning", f"{name} has radius 0: cutter radius compensation has no effect")
            if e.radius > 0 and e.radius + e.radius_wear < 0:
                add("radius_wear_exceeds_radius", "error",
                    f"{name}: radius {e.radius:g} with wear {e.radius_wear:g} is negative")
            if lathe and e.radius > 0 and not 1 <= e.orientation <= 9:
                add("missing_orientation", "error",
                    f"{name} has a nose radius {e.radius:g} and no tip orientation (1-9)")
    return found


__all__ = ["check_table"]
