"""toolcomp: run CNC part programs the way the control does, apply its tool compensation,
and get the programmed and compensated paths as numpy arrays.

    import toolcomp as tc
    res = tc.run("part.ngc", tools="tools.tbl")
    res.nominal.end, res.path.end        # (N, 3) float64, millimetres
"""
from __future__ import annotations

import collections.abc as _abc
import numbers as _numbers
import os as _os
import sys as _sys
from typing import Any as _Any
from typing import Callable as _Callable
from typing import Dict as _Dict
from typing import Iterable as _Iterable
from typing import Mapping as _Mapping
from typing import Optional as _Optional
from typing import Sequence as _Sequence
from typing import Tuple as _Tuple
from typing import Union as _Union

from . import _core
from ._core import (
    ARC_CCW,
    ARC_CW,
    LINE,
    RAPID,
    ControlProfile,
    CuttingEdge,
    Diagnostic,
    EntryStyle,
    ExitStyle,
    GougeReaction,
    LengthAxes,
    Machine,
    MachineCode,
    MachineKind,
    NonPlaneReaction,
    OutsideCorner,
    Path,
    PathStream,
    Program,
    RadiusRules,
    Result,
    TipConvention,
    Tool,
    ToolTable,
    __version__,
    compensate_3d,
    sinumerik,
)
from ._errors import CompensationError, Error, ParseError, ProgramError, ToolTableError

__all__ = [
    "ARC_CCW", "ARC_CW", "LINE", "RAPID",
    "CompensationError", "ControlProfile", "CuttingEdge", "Diagnostic", "EntryStyle", "Error", "ExitStyle",
    "GougeReaction", "LengthAxes", "Machine", "MachineCode", "MachineKind", "NonPlaneReaction", "OutsideCorner", "ParseError", "Path", "PathStream",
    "Program", "ProgramError", "RadiusRules", "Result", "TipConvention", "Tool", "ToolTable",
    "ToolTableError", "compensate_3d", "iter_run", "params", "run", "run_many", "sinumerik", "__version__",
]

_sys.modules[__name__ + ".sinumerik"] = sinumerik  # type: ignore[assignment]  # `import toolcomp.sinumerik`

# ---------------------------------------------------------------------------------------
# The options of a run
#
# run(), iter_run() and run_many() take one set of keywords: run()'s signature and docstring
# are where each is defined and documented; iter_run() writes the ones it shares out again
# (help(), IDEs and type checkers see them), tests/python/test_run_options.py checks that
# they agree with run()'s, and run_many() passes its keywords on to run(). Every keyword is
# checked and converted into what the engine takes in one place, _engine_options().
# ---------------------------------------------------------------------------------------

# What run() and iter_run() take: a file name is a str or an os.PathLike.
_FileName = _Union[str, "_os.PathLike[str]"]
_SearchPath = _Union[_FileName, _Iterable[_FileName]]
_Parameters = _Union[_Mapping[int, float], _FileName, None]
_Start = _Union[None, str, _Sequence[float]]

# The keywords only one of the two takes; every other keyword of run(), iter_run() takes too,
# with the same default and meaning. (The engine's stream has no progress callback and no
# total to limit, keeps its look-ahead on its own thread and does not probe.)
_ONLY = {"run": ("progress", "progress_every", "max_segments", "threads", "probes"),
         "iter_run": ("chunk", "piece_bytes")}

# Counts and sizes: (least, most or None). A whole number in that range, or TypeError/ValueError.
_COUNTS = {"progress_every": (1, None), "max_segments": (1, None), "max_bytes": (1, None),
           "max_line_length": (1, None), "chunk": (1, None), "piece_bytes": (1, 2**30)}


def run(program: _Union[Program, _FileName], tools: _Union[ToolTable, _FileName, None] = None, *,
        dialect: _Optional[str] = None, strict: bool = True, block_delete: bool = False,
        profile: _Optional[ControlProfile] = None, units: str = "mm",
        progress: _Optional[_Callable[[int], object]] = None, progress_every: int = 65536,
        search_path: _SearchPath = (), parameters: _Parameters = None, max_segments: int = 20_000_000,
        max_bytes: int = 2**31, max_line_length: int = 2**20, threads: bool = True, follow_links: bool = False,
        machine: _Union[Machine, _FileName, None] = None,
        probes: _Iterable[_Optional[_Sequence[float]]] = (), start: _Start = None) -> Result:
    """Interpret ``program`` and apply tool compensation.

    ``program`` is a :class:`Program` or a path to a program file (dialect from the suffix
    unless ``dialect`` is given); ``tools`` is a :class:`ToolTable`, a path to a table
    (read with ``units``), or None. With ``strict=True`` the first error is raised; with
    ``strict=False`` the path up to the error is returned and the error is in
    ``result.diagnostics``. ``profile`` (a :class:`ControlProfile`) overrides the
    dialect's control behaviour. ``machine`` is the machine the program runs on: a
    :class:`Machine`, a preset name (``"haas-mill"``, see ``Machine.presets()``) or the path of
    a machine file (``.toml``); its control must be the program's dialect, its profile is the
    run's unless ``profile`` is given, and its builder M codes, work origin, G28/G30 and tool
    change positions and travel limits act (``"mill"`` / ``"lathe"``: the control's plain
    profile of that kind). ``progress(blocks_read)`` is called every ``progress_every``
    blocks (blocks executed, loops counted, in Heidenhain programs); an exception it raises
    stops the run. ``search_path`` (a directory or a sequence of directories) is where
    called programs are looked for, in order, and nowhere else: Heidenhain ``CALL PGM name``
    (``name`` or ``name.h``), Sinumerik ``L10`` / ``NAME`` (``L10.spf``, ``NAME.spf``,
    ``.mpf``, any case); segments of a called program carry line numbers of that program's
    file. LinuxCNC ``o<name> call`` looks for ``name.ngc`` there (before the program's own
    definitions, as LinuxCNC does), Fanuc ``M98 P1000`` / ``G65 P1000`` for ``O1000.nc``,
    ``O1000`` or ``1000.nc`` when the program file holds no ``O1000``; every segment's
    ``file`` column indexes ``path.files``. A called file found through a symbolic link whose
    real path lies outside its search directory is refused (``outside_search_path``) unless
    ``follow_links=True``; an entry of the name that is a FIFO, device or directory is refused
    (``not_a_regular_file``); an empty directory name is refused (ValueError). ``parameters`` gives numbered parameters their
    start values: a ``{number: value}`` dict, or the path of a LinuxCNC ``.var`` file (read
    with :func:`toolcomp.params.read_var`); ``result.parameters`` holds the values at the
    end. ``probes`` says what the probe moves (LinuxCNC G38.2-G38.5) meet, one entry per
    probe move in order: ``None`` (no contact: G38.2/G38.4 then fail as the machine would) or
    the contact point ``(x, y, z[, a, b, c])`` in the program's coordinates of the active
    system, mm; the probe move ends there and #5061-#5070 read it. A probe move beyond the list
    touches at its target (warning ``probe_move``). The GIL is released while the program runs.

    ``start`` is where the axes stand when the program starts, in machine coordinates:
    ``(x, y, z)`` in mm, or ``"machine_zero"`` (LinuxCNC's interpreter run on its own, rs274,
    starts there). None: the machine's ``start`` when a ``machine`` is given (its zero unless
    its file says otherwise); without a machine, each axis where the program first sends it,
    so the path begins at the program's first position (doc/python.md, "Where a path starts").

    Limits (each raises a :class:`Error` subclass with a stable ``code``): a program file
    larger than ``max_bytes`` is refused before it is read (``input_too_large``, as is every
    file it calls; a FIFO, device or directory: ``not_a_regular_file``), a line longer than
    ``max_line_length`` bytes, in it or in a called file, is refused with its line (``line_too_long``),
    and a run whose programmed or compensated path would hold more than ``max_segments``
    segments (about 120 bytes each) stops at the block that crossed it (``memory_limit``;
    with ``strict=False`` the path up to it is returned). ``ControlProfile.block_limit`` and
    ``call_depth_limit`` bound executed blocks and nested calls. A run that exhausts the
    memory anyway raises ``ProgramError`` ``out_of_memory``. A count or size that is no
    whole number raises TypeError, one below 1 ValueError.

    ``threads``: a run puts its overcut watch, and the reading of the next piece of a program
    file, on threads of their own (the other core). ``threads=False`` keeps everything on the
    calling thread, for batches whose runs keep every core busy anyway (:func:`run_many` does
    this when its workers and programs are at least as many as the cores). The result is the same either way.

    These keywords are also those of :func:`iter_run` (but ``progress``, ``progress_every``,
    ``max_segments``, ``threads`` and ``probes``) and of :func:`run_many`.
    """
    dialect, tools, options = _engine_options(**locals())
    if isinstance(program, (str, _os.PathLike)):
        # Read leniently: a syntax error is raised (or reported) when the run reaches its
        # line, as the control does, and never after M2/M30. A file without control flow
        # (LinuxCNC, Fanuc, Sinumerik, Heidenhain) is read piece by piece as it runs.
        return _core.run_file(_os.fspath(program), dialect, tools, **options)
    return _core.run(program, tools, **options)


def iter_run(program: _Union[Program, _FileName], tools: _Union[ToolTable, _FileName, None] = None, *,
             chunk: int = 1_000_000, dialect: _Optional[str] = None, strict: bool = True, block_delete: bool = False,
             profile: _Optional[ControlProfile] = None, units: str = "mm", search_path: _SearchPath = (),
             parameters: _Parameters = None, max_bytes: int = 2**31, max_line_length: int = 2**20,
             piece_bytes: int = 1 << 20, follow_links: bool = False,
             machine: _Union[Machine, _FileName, None] = None, start: _Start = None) -> PathStream:
    """Run ``program`` like :func:`run` and yield its compensated path in chunks of ``chunk``
    segments (:class:`Path` objects; the last may be shorter). The chunks joined are the
    ``path`` that :func:`run` returns, segment for segment: the compensation look-ahead runs
    on across chunk boundaries. The programmed path is not kept.

    The keywords are :func:`run`'s, with their defaults and meaning, but ``progress`` (read
    ``stream.blocks_read`` while it runs), ``progress_every``, ``max_segments`` (a stream has
    no total), ``threads`` and ``probes``; and ``chunk`` and ``piece_bytes``.

    Memory: the run goes on in a thread of its own, at most one chunk ahead of the loop. A
    program file without control flow (CAM output: no O-words, GOTO, loops, program numbers or
    M99; no labels, jumps, control structures, PROC or DEFINE; no LBL, FN 9-12 jumps or CYCL
    DEF 14) is read ``piece_bytes`` at a time (1 to 2**30), so memory does not grow with its
    length; other programs are read whole, up to ``max_bytes``, their path still streamed.

    Errors: with ``strict=True`` the run's error is raised by the loop after the chunk that
    holds the segments before it; with ``strict=False`` it ends the stream and is in
    ``stream.diagnostics``. The returned :class:`PathStream` also gives ``blocks`` and
    ``files`` once it has ended; ``close()`` (or leaving a ``with`` block) stops the run."""
    dialect, tools, options = _engine_options(**locals())
    if isinstance(program, (str, _os.PathLike)):
        return _core.iter_run_file(_os.fspath(program), dialect, tools, **options)
    del options["piece_bytes"]  # a parsed Program is not read in pieces
    return _core.iter_run_program(program, tools, **options)


def _engine_options(program, tools, *, dialect, units,
                    **options) -> _Tuple[_Optional[str], _Optional[ToolTable], _Dict[str, _Any]]:
    """The arguments of :func:`run` or :func:`iter_run` (their ``locals()`` on entry) as the
    engine takes them: ``(dialect, tools, options)``, the tool table read, the keywords
    checked and converted."""
    for name, (least, most) in _COUNTS.items():
        if name in options:
            _whole_in(name, options[name], least, most)
    tools = _tools_input(tools, units)
    options["search_path"] = _search_path_input(options["search_path"])
    options["parameters"] = _parameters_input(options["parameters"])
    machine = _machine.resolve(options["machine"])
    if isinstance(machine, str):  # "mill" / "lathe": the plain profile of that kind for the program's control
        if options["profile"] is None:
            d = program.dialect if isinstance(program, Program) else _core.dialect_of_file(_os.fspath(program), dialect)
            options["profile"] = ControlProfile(d, kind=machine)
        machine = None
    options["machine"] = machine
    options["start"] = _start_input(options["start"])
    if "probes" in options:
        options["probes"] = list(options["probes"])
    return dialect, tools, options


def _tools_input(tools, units):
    """run()'s tools as the engine takes them: a ToolTable (a path read with ``units``) or None.
    A table comes back as it is: :func:`run_many` reads a path once for all its programs."""
    if isinstance(tools, (str, _os.PathLike)):
        tools = ToolTable.read(_os.fspath(tools), units=units)
    return tools


def _search_path_input(search_path):
    """run()'s search_path as the engine takes it: a list of directory names (str)."""
    if isinstance(search_path, (str, bytes, _os.PathLike)):
        search_path = [search_path]
    search_path = [_os.fsdecode(d) for d in search_path]
    if any(d == "" for d in search_path):
        raise ValueError("search_path: an empty directory name would mean the working directory, which a run "
                         "never searches; name the directory (e.g. '.')")
    return search_path


def _parameters_input(parameters):
    """run()'s parameters as the engine takes them: {int: float} (a .var file read)."""
    if isinstance(parameters, (str, _os.PathLike)):
        from .params import read_var

        parameters = read_var(parameters)
    if parameters is not None and not isinstance(parameters, _abc.Mapping):
        raise TypeError("parameters must be a {number: value} mapping or the path of a .var file, not "
                        f"{type(parameters).__name__}")
    return {int(k): float(v) for k, v in (parameters or {}).items()}


def _start_input(start):
    """run()'s start as the engine takes it: None or (x, y, z) mm."""
    if start is None:
        return None
    if isinstance(start, str):
        if start != "machine_zero":
            raise ValueError(f"start must be None, 'machine_zero' or (x, y, z), not {start!r}")
        return (0.0, 0.0, 0.0)
    xyz = tuple(float(v) for v in start)
    if len(xyz) != 3:
        raise ValueError(f"start must be (x, y, z), not {start!r}")
    return xyz


def _whole_in(name, value, least, most=None):
    """A count or size argument: a whole number (not a bool, not 1.5), at least ``least``
    (and at most ``most``)."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Integral):
        raise TypeError(f"{name} must be a whole number, not {value!r}")
    if value < least:
        raise ValueError(f"{name} must be at least {least}, not {value}")
    if most is not None and value > most:
        raise ValueError(f"{name} must be from {least} to {most}, not {value}")


from . import plot as _plot  # noqa: E402  (cheap: matplotlib is imported when something is drawn)


def _result_plot(self: Result, ax: object = None, plane: str = "xy", show_nominal: bool = True,
                 tolerance: float | None = None, title: str | None = None, legend: bool = True,
                 color_by: str = "tool") -> object:
    return _plot.plot_result(self, ax=ax, plane=plane, show_nominal=show_nominal, tolerance=tolerance,
                             title=title, legend=legend, color_by=color_by)


_result_plot.__doc__ = _plot.plot_result.__doc__  # written once, in plot.py
Result.plot = _result_plot

from . import display as _display  # noqa: E402  (Jupyter's rich display)

Result._repr_html_ = _display.result_html
Result.__repr__ = _display.result_repr
Path._repr_html_ = _display.path_html
ToolTable._repr_html_ = _display.table_html
Diagnostic._repr_html_ = _display.diagnostic_html


def _table_to_pandas(self: ToolTable) -> object:
    """One row per cutting edge (pandas DataFrame); see :mod:`toolcomp.table_frames`."""
    from .table_frames import to_pandas

    return to_pandas(self)


def _table_from_pandas(df: object, base: ToolTable | None = None, units: str = "mm") -> ToolTable:
    """A ToolTable from a DataFrame (edits written over a copy of ``base`` if given)."""
    from .table_frames import from_pandas

    return from_pandas(df, base=base, units=units)


def _table_diff(self: ToolTable, other: ToolTable, tol: float = 0.0) -> list:
    """What changes from this table to ``other``: a list of (tool, edge, field, old, new)."""
    from .table_frames import diff

    return diff(self, other, tol=tol)


ToolTable.to_pandas = _table_to_pandas
ToolTable.from_pandas = staticmethod(_table_from_pandas)
ToolTable.diff = _table_diff


from . import machine as _machine  # noqa: E402  (machine files; Machine.read & co. below)

Machine.read = staticmethod(_machine.read)
Machine.parse = staticmethod(_machine.parse)
Machine.preset = staticmethod(_machine.preset)
Machine.presets = staticmethod(_machine.presets)
Machine.write = _machine.write
Machine.dumps = _machine.dumps

from .batch import run_many  # noqa: E402  (needs run above)
from . import params  # noqa: E402  (LinuxCNC .var parameter files)
