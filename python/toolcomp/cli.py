"""Command line: run or check NC programs the way the control would.

    python -m toolcomp run PROGRAM [--tools TABLE] [--dialect D] [--plot FILE.png] [--progress]
                                   [--csv FILE] [--json FILE] [--units-table mm|inch]
    python -m toolcomp check PROGRAM... [--tools TABLE] [--dialect D] [--format text|json]

Diagnostics are printed as ``file:line:column: severity code message`` so editors and CI
log parsers can jump to the block. Exit status: 0 when no diagnostic is an error, 1 when
one is, 2 on usage errors (bad options, a program or table that cannot be read).
"""

from __future__ import annotations

import argparse
import inspect
import json
import os
import sys

import numpy as np

import toolcomp as tc
from toolcomp import cli_stream, export

EXIT_OK, EXIT_ERRORS, EXIT_USAGE = 0, 1, 2

_DIALECT_TABLE = tc._core.dialect_table()  # the dialects and their suffixes
DIALECTS = tuple(row["name"] for row in _DIALECT_TABLE)
SUFFIX_DIALECTS = {s: row["name"] for row in _DIALECT_TABLE for s in row["suffixes"]}
ERROR_SEVERITIES = ("error", "fatal")
MAX_COUNTED_BYTES = inspect.signature(tc.run).parameters["max_bytes"].default  # a run's size limit


class UsageError(Exception):
    """Bad input from the command line: reported as ``toolcomp: error: …``, exit 2."""


class Record:
    """A diagnostic as the command line reports it (engine Diagnostic or raised Error)."""

    __slots__ = ("file", "line", "column", "severity", "code", "message")

    def __init__(self, file, line, column, severity, code, message):
        self.file, self.line, self.column = file, line, column
        self.severity, self.code, self.message = severity, code, message

    @classmethod
    def of(cls, diag, file, severity=None):
        """A tc.Diagnostic, or a raised tc.Error (give its ``severity``: errors carry none)."""
        return cls(diag.file or file, diag.line, diag.column, severity or diag.severity, diag.code, diag.message)

    @property
    def is_error(self):
        return self.severity in ERROR_SEVERITIES

    def format(self):
        # Always file:line:column (0 = unknown / whole line) so every line parses alike.
        return (f"{self.file}:{self.line or 0}:{self.column or 0}: "
                f"{self.severity} {self.code} {self.message}")

    def as_dict(self):
        return {k: getattr(self, k) for k in self.__slots__}


def _start_position(v):
    """A --start value: machine_zero, or X,Y,Z in mm."""
    if v == "machine_zero":
        return v
    try:
        xyz = tuple(float(c) for c in v.split(","))
    except ValueError:
        xyz = ()
    if len(xyz) != 3:
        raise argparse.ArgumentTypeError(f"expected machine_zero or X,Y,Z (mm), not {v!r}")
    return xyz


def _directory_name(v):
    """A --search-path value: a directory's name (an empty one would mean the working directory)."""
    if not v:
        raise argparse.ArgumentTypeError("an empty directory name; name the directory (e.g. '.')")
    return v


# ---------------------------------------------------------------------------------------
# running a program
# ---------------------------------------------------------------------------------------

class Outcome:
    """Everything one command-line run produced."""

    def __init__(self, program_file, dialect):
        self.program_file = program_file
        self.dialect = dialect
        self.program = None
        self.result = None
        self.records: list[Record] = []
        self.blocks = None  # a streamed run: blocks of the program, and
        self.totals = None  # its paths summed up (cli_stream.PathTotals)
        self.streamed = False  # run as a stream (no result: the path went chunk by chunk)

    @property
    def has_errors(self):
        return any(r.is_error for r in self.records)


def _check_readable(path, what):
    if not os.path.exists(path):
        raise UsageError(f"{what} '{path}' does not exist")
    if os.path.isdir(path):
        raise UsageError(f"{what} '{path}' is a directory")
    if not os.access(path, os.R_OK):
        raise UsageError(f"{what} '{path}' is not readable")


def _read_tools(path, units):
    """The table at ``path``, its lengths in ``units`` (None: ToolTable.read's default)."""
    return tc.ToolTable.read(path) if units is None else tc.ToolTable.read(path, units=units)


PROGRESS_MIN_BLOCKS = 1_000_000  # on a terminal, a bar for runs (blocks) and plots (segments) this long


def _shows_progress(size, force, stream) -> bool:
    """Whether to show progress: ``force`` True (--progress) always, False (--no-progress)
    never, None when ``stream`` is a terminal and ``size`` is a million or more."""
    if force is not None:
        return bool(force)
    return size is not None and size >= PROGRESS_MIN_BLOCKS and stream.isatty()


class _ProgressLines:
    """What the command line shows without tqdm: plain lines on the stream, at every tenth
    of the way (the part of tqdm's interface it uses: n, total, update, close)."""

    def __init__(self, total, unit, desc, file):
        self.n, self.total, self.unit, self.desc, self.file = 0, total, unit, desc, file
        self._tenths = -1

    def update(self, k=1):
        self.n += k
        tenths = 10 * self.n // self.total if self.total else 10
        if tenths > self._tenths:
            self._tenths = tenths
            print(f"toolcomp: {self.desc}: {self.n:,} of {self.total:,} {self.unit}s ({10 * tenths}%)",
                  file=self.file, flush=True)

    def close(self):
        pass


def _progress_bar(program, stream=None, force=None):
    """A bar on stderr of the blocks run (``program``: a Program or a block count): a tqdm
    bar, or plain lines without tqdm; when :func:`_shows_progress` (for a million blocks or
    more on a terminal, or ``force``), else None."""
    stream = stream or sys.stderr
    blocks = program if isinstance(program, int) or program is None else len(program)
    if blocks is None or not _shows_progress(blocks, force, stream):
        return None
    try:
        from tqdm import tqdm
    except ImportError:
        bar = _ProgressLines(blocks, "block", "run", stream)
        bar.update(0)
        return bar
    return tqdm(total=blocks, desc="run", unit="block", unit_scale=True, file=stream, leave=False)


class _PlotProgress:
    """``save_plot``'s progress(done, total, what) as a bar of the drawing's steps on the
    stream (tqdm's, or a plain line a step without tqdm)."""

    def __init__(self, stream):
        self.stream = stream
        self.bar = None
        try:
            from tqdm import tqdm
        except ImportError:
            tqdm = None
        self._tqdm = tqdm

    def __call__(self, done, total, what):
        if self._tqdm is None:
            print(f"toolcomp: plot: {what} ({done} of {total} steps)", file=self.stream, flush=True)
            return
        if self.bar is None:
            self.bar = self._tqdm(total=total, desc="plot", unit="step", file=self.stream, leave=False)
        self.bar.total = total
        self.bar.set_postfix_str(what, refresh=False)
        self.bar.update(done - self.bar.n)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _plot_progress(segments, stream=None, force=None):
    """A :class:`_PlotProgress` for a plot of ``segments`` segments when
    :func:`_shows_progress`, else None."""
    stream = stream or sys.stderr
    return _PlotProgress(stream) if _shows_progress(segments, force, stream) else None


def execute(program_file, tools_file=None, dialect=None, units_table=None, search_path=(),
            parameters=None, whole_path=True, csv=None, machine=None, progress=None, start=None) -> Outcome:
    """Read the program and tool table and run it with ``strict=False``; every problem
    becomes a diagnostic record. Raises UsageError for unreadable inputs. ``whole_path=False``
    (the caller needs the records, the summary and at most ``csv``, a CsvWriter): a large
    program file is run as a stream (cli_stream.py), in bounded memory, and ``out.streamed``
    is set (the compensated path went to ``csv`` chunk by chunk; ``out.result`` is None).
    ``progress``: a bar of the blocks run on stderr; None: for a million blocks or more on
    a terminal, True: always, False: never."""
    _check_readable(program_file, "program")
    if tools_file is not None:
        _check_readable(tools_file, "tool table")
    if parameters is not None:
        _check_readable(parameters, "parameter file")
    dialect = dialect or SUFFIX_DIALECTS.get(os.path.splitext(program_file)[1].lower())
    out = Outcome(program_file, dialect)

    tools = None
    if tools_file is not None:
        try:
            tools = _read_tools(tools_file, units_table)
        except tc.Error as exc:
            out.records.append(Record.of(exc, tools_file, "error"))
            return out

    kwargs = {"dialect": dialect} if dialect else {}
    run_kwargs = {} if tools is None else {"tools": tools}
    if search_path:
        run_kwargs["search_path"] = list(search_path)
    if start is not None:
        run_kwargs["start"] = start
    if machine is not None:
        try:
            run_kwargs["machine"] = tc.machine.resolve(machine)
        except tc.Error as exc:
            out.records.append(Record.of(exc, machine, "error"))
            return out
        except ValueError as exc:
            raise UsageError(str(exc)) from None
    if parameters is not None:
        try:
            run_kwargs["parameters"] = tc.params.read_var(parameters)
        except tc.Error as exc:
            out.records.append(Record.of(exc, parameters, "error"))
            return out
    if not whole_path and cli_stream.streams(program_file):
        return cli_stream.execute_streamed(out, program_file, dialect, run_kwargs,
                                           lambda blocks: _progress_bar(blocks, force=progress), csv)

    try:
        out.program = tc.Program.read(program_file, **kwargs)
        out.dialect = out.program.dialect
        source = out.program
    except tc.Error as exc:
        # A program that does not parse as a whole may still run up to the bad block
        # when the engine parses as it goes; let run() say how far it gets.
        source = program_file
        parse_error = exc
    else:
        parse_error = None

    if source is program_file:
        run_kwargs.update(kwargs)
    bar = _progress_bar(out.program, force=progress)
    if bar is not None:
        run_kwargs["progress"] = lambda n: bar.update(n - bar.n)
    try:
        out.result = tc.run(source, strict=False, **run_kwargs)
        if bar is not None:
            bar.update(bar.total - bar.n)
    except tc.Error as exc:
        out.records.append(Record.of(parse_error or exc, program_file, "error"))
        return out
    finally:
        if bar is not None:
            bar.close()
    out.records.extend(Record.of(d, program_file) for d in out.result.diagnostics)
    if parse_error is not None and not any(r.is_error for r in out.records):
        out.records.append(Record.of(parse_error, program_file, "error"))
    return out


# ---------------------------------------------------------------------------------------
# summary
# ---------------------------------------------------------------------------------------

def _block_count(program, program_file, blocks=None):
    if blocks is not None:
        return int(blocks)
    if program is not None:
        return len(program)
    # No program object (it could not be read): lines with content, read in
    # chunks (a file refused as too large or with a huge line is never held whole); 0 for
    # what is no regular file or over the engine's default size limit.
    try:
        if not os.path.isfile(program_file) or os.path.getsize(program_file) > MAX_COUNTED_BYTES:
            return 0
        count, content = 0, False
        with open(program_file, "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                *ended, last = chunk.split(b"\n")
                for line in ended:
                    count += content or bool(line.strip())
                    content = False
                content = content or bool(last.strip())
        return count + content
    except OSError:
        return 0


def summarize(out: Outcome) -> dict:
    """The run summary as plain data (what --json writes)."""
    res = out.result
    summary = {
        "program": out.program_file,
        "dialect": out.dialect,
        "blocks": _block_count(out.program, out.program_file, out.blocks),
        "ok": not out.has_errors,
    }
    segs = {"nominal": 0, "compensated": 0, "generated": 0}
    tools, length = [], {"feed": 0.0, "rapid": 0.0}
    if out.totals is not None:
        segs, tools, length = out.totals.segments(), sorted(out.totals.tools), out.totals.lengths()
    elif res is not None:
        path = res.path
        segs["nominal"] = len(res.nominal)
        segs["compensated"] = len(path)
        if segs["compensated"]:
            segs["generated"] = int(np.count_nonzero(path.generated))
            tools = sorted(int(t) for t in np.unique(path.tool))
            total, feed = path.length(True), path.length(False)  # arcs and helices exact
            length = {"feed": float(feed), "rapid": max(0.0, float(total - feed))}
    summary["segments"] = segs
    summary["tools"] = tools
    summary["length_mm"] = length
    counts = {}
    for r in out.records:
        counts[r.severity] = counts.get(r.severity, 0) + 1
    summary["diagnostic_counts"] = counts
    summary["diagnostics"] = [r.as_dict() for r in out.records]
    return summary


def _plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def format_summary(s: dict) -> str:
    segs, length = s["segments"], s["length_mm"]
    counts = s["diagnostic_counts"]
    seg_text = f"{segs['nominal']} programmed, {segs['compensated']} compensated"
    if segs["generated"]:
        seg_text += f" ({segs['generated']} inserted by compensation)"
    order = ["error", "fatal", "warning", "note", "info"]
    sev = sorted(counts, key=lambda k: (order.index(k) if k in order else len(order), k))
    diag_text = ", ".join(_plural(counts[k], k) for k in sev) if counts else "none"
    rows = [
        ("program", s["program"]),
        ("dialect", s["dialect"] or "?"),
        ("blocks", str(s["blocks"])),
        ("segments", seg_text),
        ("tools", ", ".join(f"T{t}" for t in s["tools"]) or "none"),
        ("path length", f"feed {length['feed']:.3f} mm, rapid {length['rapid']:.3f} mm"),
        ("diagnostics", diag_text),
    ]
    lines = [f"{k + ':':<13}{v}" for k, v in rows]
    lines += [Record(**d).format() for d in s["diagnostics"]]
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------
# exports
# ---------------------------------------------------------------------------------------

CSV_HEADER = (["index", "kind", "line", "tool",
               "start_x", "start_y", "start_z", "end_x", "end_y", "end_z",
               "center_x", "center_y", "center_z", "feed", "side", "generated",
               "tool_offset_x", "tool_offset_y", "tool_offset_z", "a", "b", "c"])
CSV_ROWS_AT_ONCE = 65536


class CsvWriter:
    """The CSV of a compensated path, written as its segments come: ``add`` a Path (a whole
    one, or the chunks of a stream in order; rows are numbered on across them), then
    ``close``. The file is made at the first ``add`` or at ``close`` (header only for no
    segments). ``discard`` takes back what was written (a streamed run that stopped with an
    error has no path, as a whole run has none). The rows are written by the engine
    (``cpp/src/path_csv.cpp``): numbers with 6 decimals, an empty field for a line's centre
    and a rapid's feed, RFC 4180 line ends."""

    def __init__(self, filename):
        self.filename = filename
        self.rows = 0
        self._file = None

    def _open(self):
        if self._file is None:
            self._file = open(self.filename, "w", newline="", encoding="ascii")
            self._file.write(self._header())

    @staticmethod
    def _header():
        return tc._core._csv_header

    def add(self, path) -> None:
        self._open()
        n = len(path) if path is not None else 0
        core = tc._core
        # A block of rows at a time: the text of a whole path would take many times its memory.
        for a in range(0, n, CSV_ROWS_AT_ONCE):
            self._file.write(core._csv_rows(path, a, min(n, a + CSV_ROWS_AT_ONCE), self.rows + a))
        self.rows += n

    def discard(self) -> None:
        if self._file is not None:
            self._file.seek(0)
            self._file.truncate()
            self._file.write(self._header())
        self.rows = 0

    def close(self, make=True) -> int:
        """Closes the file (made now if nothing was added, unless ``make`` is false); returns
        the number of rows."""
        if make:
            self._open()
        if self._file is not None:
            self._file.close()
        return self.rows


def write_csv(path, filename):
    """One row per segment of ``path``; returns the number of rows."""
    w = CsvWriter(filename)
    try:
        w.add(path)
    except BaseException:
        w.close(make=False)
        raise
    return w.close()


# ---------------------------------------------------------------------------------------
# commands
# ---------------------------------------------------------------------------------------

def cmd_run(args) -> int:
    # Without --plot the whole path is not needed: a large program runs as a stream, its
    # CSV written chunk by chunk.
    writer = CsvWriter(args.csv) if args.csv else None
    try:
        out = execute(args.program, args.tools, args.dialect, args.units_table, args.search_path,
                      args.parameters, whole_path=bool(args.plot), csv=writer, machine=args.machine,
                      progress=args.progress, start=args.start)
        if writer is not None and not out.streamed:
            writer.add(out.result.path if out.result is not None else None)
    except BaseException:
        if writer is not None:
            writer.close(make=False)  # a file begun is closed, none is made
        raise
    if writer is not None:
        writer.close()
    summary = summarize(out)
    print(format_summary(summary))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(summary, f, indent=2)
            f.write("\n")
    if args.plot:
        if out.result is None:
            print(f"toolcomp: no path to plot for {args.program}", file=sys.stderr)
        else:
            progress = _plot_progress(len(out.result.path), force=args.progress)
            try:
                from toolcomp.plot import save_plot
                save_plot(out.result, args.plot, title=os.path.basename(args.program), progress=progress)
            except ImportError:
                raise UsageError("--plot needs matplotlib: pip install 'toolcomp[plot]'")
            finally:
                if progress is not None:
                    progress.close()
    return EXIT_ERRORS if out.has_errors else EXIT_OK


def cmd_check(args) -> int:
    # Unreadable files are usage errors: check them all before running any.
    for p in args.programs:
        _check_readable(p, "program")
    outcomes = [execute(p, args.tools, args.dialect, args.units_table, args.search_path, args.parameters,
                        machine=args.machine, start=args.start,
                        whole_path=False) for p in args.programs]
    if args.format == "json":
        doc = [{"program": o.program_file, "ok": not o.has_errors,
                "diagnostics": [r.as_dict() for r in o.records]} for o in outcomes]
        print(json.dumps(doc[0] if len(doc) == 1 else doc, indent=2))
    else:
        for o in outcomes:
            for r in o.records:
                print(r.format())
    return EXIT_ERRORS if any(o.has_errors for o in outcomes) else EXIT_OK


def cmd_export(args) -> int:
    out = execute(args.program, args.tools, args.dialect, args.units_table, args.search_path, args.parameters,
                  machine=args.machine, start=args.start)
    if out.has_errors or out.result is None:
        # A program the control refuses has no compensated path to export.
        for r in out.records:
            print(r.format(), file=sys.stderr)
        return EXIT_ERRORS
    try:
        text = export.to_gcode(out.result.path, args.to, comments=not args.no_comments,
                        tool_length=not args.no_tool_length)
    except ValueError as exc:
        raise UsageError(str(exc))
    if args.output in (None, "-"):
        sys.stdout.write(text)
    else:
        with open(args.output, "w", encoding="ascii", newline="\n") as f:
            f.write(text)
    return EXIT_OK


def _version():
    try:
        from importlib.metadata import version
        return version("toolcomp")
    except Exception:  # not installed (running from a source tree)
        return "unknown"


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="toolcomp",
        description="Run CNC part programs the way the control does and report the "
                    "programmed and tool-compensated paths.")
    p.add_argument("--version", action="version", version=f"%(prog)s {_version()}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    def common(sp):
        sp.add_argument("--tools", metavar="TABLE",
                        help="tool table (.tbl, .t, .ini, .csv, .json; format from suffix)")
        sp.add_argument("--dialect", choices=DIALECTS,
                        help="control dialect (default: from the program's suffix)")
        sp.add_argument("--units-table", choices=("mm", "inch"), dest="units_table",
                        help="units of the tool table's lengths (default: the table's own)")
        sp.add_argument("--search-path", metavar="DIR", action="append", default=[], dest="search_path",
                        type=_directory_name,
                        help="directory where called programs are looked for (Heidenhain CALL PGM, "
                             "Sinumerik L10 / named subprograms, LinuxCNC o<name> call, Fanuc M98/G65); "
                             "repeatable, searched in order")
        sp.add_argument("--machine", metavar="NAME|FILE.toml",
                        help="the machine the program runs on: a preset (haas-mill, haas-lathe, fanuc-lathe, ...) "
                             "or a machine file; builder M codes, positions and travel limits act")
        sp.add_argument("--start", metavar="machine_zero|X,Y,Z", type=_start_position,
                        help="where the axes stand when the program starts, machine coordinates in mm "
                             "(default: the machine's start, or without --machine where the program first "
                             "sends each axis)")
        sp.add_argument("--parameters", metavar="FILE.var",
                        help="LinuxCNC parameter file: the numbered parameters the program starts from")

    r = sub.add_parser("run", help="run a program and print a summary of its paths",
                       description="Run a program (errors do not stop the report: the path "
                                   "up to the first error is summarised).")
    r.add_argument("program", metavar="PROGRAM")
    common(r)
    r.add_argument("--plot", metavar="FILE.png", help="write a plot of the paths")
    r.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="show the progress of the run and of the plot on stderr (default: on a terminal, "
                        "for a million blocks or segments or more)")
    r.add_argument("--csv", metavar="FILE", help="write the compensated segments as CSV")
    r.add_argument("--json", metavar="FILE", help="write the summary as JSON")
    r.set_defaults(func=cmd_run)

    c = sub.add_parser("check", help="print only the diagnostics of programs",
                       description="Print diagnostics as file:line:column: severity code "
                                   "message; exit 1 if any is an error.")
    c.add_argument("programs", metavar="PROGRAM", nargs="+")
    common(c)
    c.add_argument("--format", choices=("text", "json"), default="text")
    c.set_defaults(func=cmd_check)

    e = sub.add_parser("export", help="write the compensated path as G-code without compensation",
                       description="Write the compensated path as a plain program (G40 "
                                   "throughout, arcs as arcs, tool length offsets applied) for "
                                   "controls without cutter compensation.")
    e.add_argument("program", metavar="PROGRAM")
    common(e)
    e.add_argument("--to", choices=export.DIALECTS, default="linuxcnc",
                   help="dialect of the written program (default: linuxcnc)")
    e.add_argument("-o", "--output", metavar="FILE", help="output file (default: stdout)")
    e.add_argument("--no-comments", action="store_true", help="leave out the (line N) comments")
    e.add_argument("--no-tool-length", action="store_true",
                   help="do not add the tool length offsets to the coordinates")
    e.set_defaults(func=cmd_export)

    from toolcomp import cli_tools
    cli_tools.add_parser(sub)
    return p


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)  # exits 2 on bad usage
    try:
        return args.func(args)
    except UsageError as exc:
        print(f"toolcomp {args.command}: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except OSError as exc:  # output files that cannot be written
        print(f"toolcomp {args.command}: error: {exc}", file=sys.stderr)
        return EXIT_USAGE


if __name__ == "__main__":
    sys.exit(main())
