"""The command line's run of a large program as a stream: ``check``, and ``run`` without
``--plot``, need the diagnostics, the summary's totals and at most the CSV of the compensated
path, not the paths. A program file of ``STREAM_MIN_BYTES`` or more is read through once as a
syntax check (``Program.check_file``, every syntax error wherever it is, as ``Program.read``
finds them) and run with ``iter_run``: the compensated path is summed up (and written to the
CSV) chunk by chunk and dropped, the programmed path only counted. Memory stays that of a
chunk or two whatever the program's length, and ``max_segments`` does not apply. The
records, the summary and the CSV are those of a whole run (tests/python/test_cli_stream.py
runs both ways).
"""

from __future__ import annotations

import os

import numpy as np

import toolcomp as tc

STREAM_MIN_BYTES = 64 * 2**20  # about 3.5 million CAM blocks: Paths of about 800 MB
STREAM_CHUNK = 250_000         # segments summed at a time (about 30 MB)


def streams(program_file) -> bool:
    """Whether the command line runs `program_file` as a stream (a regular file that large)."""
    try:
        return os.path.isfile(program_file) and os.path.getsize(program_file) >= STREAM_MIN_BYTES
    except OSError:
        return False


class PathTotals:
    """What the summary tells of the paths: segment counts, tools, feed and rapid lengths."""

    def __init__(self):
        self.nominal = self.compensated = self.generated = 0
        self.tools: set[int] = set()
        self.feed = self.total = 0.0

    def add(self, path) -> None:
        """One chunk of the compensated path (its segments are not kept)."""
        n = len(path)
        if not n:
            return
        self.compensated += n
        self.generated += int(np.count_nonzero(path.generated))
        self.tools.update(int(t) for t in np.unique(path.tool))
        self.total += float(path.length(True))
        self.feed += float(path.length(False))

    def segments(self) -> dict:
        return {"nominal": self.nominal, "compensated": self.compensated, "generated": self.generated}

    def lengths(self) -> dict:
        return {"feed": self.feed, "rapid": max(0.0, self.total - self.feed)}


def execute_streamed(out, program_file, dialect, run_kwargs, progress_bar, csv=None):
    """``cli.execute`` for a large program: fills ``out`` (records, dialect, blocks, totals;
    blocks stay None for a program with a syntax error: the summary counts its lines, as for
    a whole run). `progress_bar(total)` makes a bar (or None) for a program of `total` blocks.
    ``csv`` (a cli.CsvWriter or None) gets every chunk of the compensated path; a run that
    stops with an error takes its rows back (a whole run has no path then)."""
    from toolcomp.cli import Record

    try:
        out.blocks = tc.Program.check_file(program_file, dialect=dialect)
        parse_error = None
    except tc.Error as exc:
        # A program that does not parse as a whole may still run up to the bad block, as
        # the control reads it; the run says how far it gets.
        out.blocks, parse_error = None, exc
    totals = PathTotals()
    bar = progress_bar(out.blocks)
    try:
        with tc.iter_run(program_file, strict=False, chunk=STREAM_CHUNK, dialect=dialect, **run_kwargs) as stream:
            out.dialect = stream.dialect
            for chunk in stream:
                totals.add(chunk)
                if csv is not None:
                    csv.add(chunk)
                if bar is not None:
                    bar.update(stream.blocks_read - bar.n)
            totals.nominal = stream.programmed_segments
            diagnostics = stream.diagnostics
    except tc.Error as exc:
        out.records.append(Record.of(parse_error or exc, program_file, "error"))
        if csv is not None:
            csv.discard()
        return out
    finally:
        out.streamed = True
        if bar is not None:
            bar.close()
    out.totals = totals
    out.records.extend(Record.of(d, program_file) for d in diagnostics)
    if parse_error is not None and not any(r.is_error for r in out.records):
        out.records.append(Record.of(parse_error, program_file, "error"))
    return out
