"""G-code export of a path with its compensation already applied.

``to_gcode(res.path)`` writes the compensated path as a plain program for controls that have
no cutter or nose radius compensation (Grbl-class controllers among them): G40 throughout,
lines as G0/G1, arcs as G2/G3 with incremental centres (I J K), helices as arcs with the
third axis, millimetres (G21), absolute coordinates (G90), feed per minute (G94). Run again
without compensation, the program reproduces the path to the printed precision.

Coordinates are the path's program coordinates (``Path.start``/``end``, radius X on lathes)
plus the active tool length offset (``Path.tool_offset``), so the program needs no tool
table: re-run, its path is the compensated path shifted by the offsets
(``tool_length=False`` leaves them out). A path that still jumps (a work coordinate system
changed between two moves) cannot be written as one program and is refused.

The text is written by the engine (``cpp/src/path_gcode.cpp``), a few million segments a
second, with the GIL released.
"""
from __future__ import annotations

from typing import Iterable

from . import _core

DIALECTS = ("linuxcnc", "fanuc", "grbl")  # what the engine writes (it refuses any other, naming these)


def to_gcode(path: "_core.Path", dialect: str = "linuxcnc", *, digits: int = 6,
             comments: bool = True, tool_length: bool = True) -> str:
    """The path as a G-code program of ``dialect`` (``linuxcnc``, ``fanuc`` or ``grbl``).

    ``digits`` decimals (0 to 30) are written (6: 1e-6 mm); a Y or Z word whose value, so
    written, is the segment's start is left out, F and the rotary axes are modal. With
    ``comments``, the blocks of each source line of the original program are preceded by
    ``(line N)``. ``linuxcnc`` writes an arc of several turns as one block with P; ``fanuc``
    and ``grbl`` write its full circles first. Raises ValueError for a path that jumps, a
    feed move without a known feed rate, or (fanuc, grbl) an arc of more than a million turns.
    """
    return _core._gcode_text(path, dialect, int(digits), bool(comments), bool(tool_length))


def write_gcode(path: "_core.Path", filename: str, dialect: str = "linuxcnc", **kw) -> None:
    """Write :func:`to_gcode` to ``filename``."""
    text = to_gcode(path, dialect, **kw)
    with open(filename, "w", encoding="ascii", newline="\n") as fh:
        fh.write(text)


__all__: Iterable[str] = ("to_gcode", "write_gcode", "DIALECTS")
