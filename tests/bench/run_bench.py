"""Benchmarks: print figures, assert nothing. Run with `make bench`.

Measures parse and run of generated CAM-like programs (lines and arcs, G17, tool length
offset) through the Python API, LinuxCNC's rs274 on the same program when it is installed,
and tc.compensate_3d on CAM points. Sections, in order (each prints its elapsed time):

  iso        the LinuxCNC contour with G42.1 and without compensation: parse, run, export,
             tc.run(file), rs274
  dialects   the same contour with radius compensation as ISO (LinuxCNC), Sinumerik 840D and
             Heidenhain Klartext: parse, run, total and tc.run(file) ns/block, peak memory of
             tc.run(file) in a fresh process, each over ISO's
  loop       a LinuxCNC program that computes the contour in an o-while loop
  batch      8 programs one by one and with run_many
  memory     peak RSS of one ISO tc.run(file) against its Path columns
  plot       res.plot() and savefig of the G42 program's paths
  linearity  tc.run(file) of a program TOOLCOMP_BENCH_LINEAR times as long against the 1x one,
             each dialect with compensation and ISO without, interleaved rounds in fresh processes
  stream     tc.iter_run over a long program file of each dialect: time and peak RSS
  3d         tc.compensate_3d of CAM points

Environment (sizes in blocks):
  TOOLCOMP_BENCH_BLOCKS        programs' size (default 1,000,000)
  TOOLCOMP_BENCH_LINEAR        the linearity factor (default 10; 0 or 1 to skip)
  TOOLCOMP_BENCH_ROUNDS        rounds of the fresh-process runs, dialects and linearity (default 3)
  TOOLCOMP_BENCH_STREAM_BLOCKS the streamed file's size (default 50,000,000, about 0.9 GB of
                               ISO, written to the temporary directory; 0 to skip)
  TOOLCOMP_BENCH_STREAM_OTHER_BLOCKS  the same for Sinumerik and Heidenhain (default: as
                               TOOLCOMP_BENCH_STREAM_BLOCKS; 0 to skip). iter_run reads their
                               files whole: the run is skipped, with the reason, when its
                               memory, estimated from a TOOLCOMP_BENCH_BLOCKS-block stream,
                               would exceed 80 % of MemAvailable
  TOOLCOMP_BENCH_PLOT_SEGMENTS compensated segments plotted (default 1,000,000; 0 to skip)
  TOOLCOMP_BENCH_POINTS        compensate_3d points (default 10,000,000)
  TOOLCOMP_BENCH_SECTIONS      the sections to run, comma-separated (default all)
Peak memory is measured in a fresh interpreter for each run (VmHWM).
"""
import contextlib
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from typing import Callable, NamedTuple, Optional, Tuple

import toolcomp as tc


# Rows of 6 moves: long line, two corners, a CCW semicircle, a line back, a CW semicircle;
# each row 1 um above the one before. The blocks' Y values are the row's y plus these.
_ROW_Y = (0, 2, 2, 7, 7, 0)
_ISO_ROW = ("G1 X100 Y%.3f", "G1 X100 Y%.3f", "G1 X95 Y%.3f", "G3 X95 Y%.3f I0 J2.5", "G1 X5 Y%.3f",
            "G2 X5 Y%.3f I0 J-3.5")
_KLARTEXT_ROW = ("L X+100 Y%+.3f", "L X+100 Y%+.3f", "L X+95 Y%+.3f", "CR X+95 Y%+.3f R+2.5 DR+", "L X+5 Y%+.3f",
                 "CR X+5 Y%+.3f R+3.5 DR-")


# The lines before and after the rows: tool (r = 1 mm), approach, compensation on and off.
_KLARTEXT_HEAD = ("BEGIN PGM BENCH MM", "TOOL DEF 1 L+0 R+1", "TOOL CALL 1 Z S1000", "L X+0 Y+0 Z+5 R0 FMAX",
                  "L Z-1 F600", "L X+0 Y+0 RR F600")
_KLARTEXT_FOOT = ("L X-10 Y-10 R0", "END PGM BENCH MM")
_SINUMERIK_HEAD = ("$TC_DP1[1,1]=120", "$TC_DP3[1,1]=50", "$TC_DP6[1,1]=1", "T1 D1 M6", "G17 G90 G71",
                   "G0 X0 Y0 Z5", "G1 Z-1 F600", "G42")
_SINUMERIK_FOOT = ("G40 G1 X-10 Y-10", "M30")


def contour_rows(n_blocks, row):
    """The blocks of n_blocks // 6 rows, each of the six formats of `row`."""
    out = []
    for i in range(n_blocks // 6):
        y = i * 0.001
        out += [f % (y + dy) for f, dy in zip(row, _ROW_Y)]
    return out


def generate(n_blocks, comp):
    """The contour rows as a LinuxCNC program; with ``comp``, cutter radius compensation
    G42 (r = 1 mm) on for all of them."""
    out = ["G21 G17 G90 G94 G40 G49", "T1 M6", "G43 H1", "G0 X0 Y0 Z5", "G1 Z-1 F600"]
    if comp:
        out.append("G42.1 D2")
    out += contour_rows(n_blocks, _ISO_ROW)
    if comp:
        out.append("G40 G1 X-10 Y-10")
    out.append("M2")
    return "\n".join(out) + "\n", n_blocks // 6 * 6


def generate_heidenhain(n_blocks):
    """The same contour in Klartext: L and CR blocks, RR with a tool of R1 (1 mm)."""
    out = list(_KLARTEXT_HEAD) + contour_rows(n_blocks, _KLARTEXT_ROW) + list(_KLARTEXT_FOOT)
    return "".join(f"{i} {b}\n" for i, b in enumerate(out)), n_blocks // 6 * 6


def generate_sinumerik(n_blocks):
    """The same contour for a Sinumerik 840D: tool data in $TC_DP, G42 with a tool of r = 1 mm."""
    out = list(_SINUMERIK_HEAD) + contour_rows(n_blocks, _ISO_ROW) + list(_SINUMERIK_FOOT)
    return "\n".join(out) + "\n", n_blocks // 6 * 6


def generate_loops(n_blocks):
    """A LinuxCNC program that computes the same contour in an o-while loop (parameters,
    expressions, 7 statements a pass): what computing costs per executed block."""
    rows = n_blocks // 6
    return (f"G21 G17 G90 G94 G40 G49\nT1 M6\nG43 H1\nG0 X0 Y0 Z5\nG1 Z-1 F600\nG42.1 D2\n"
            f"#1=0\n#2=0\no1 while [#1 LT {rows}]\n"
            f"  G1 X100 Y#2\n  G1 X100 Y[#2+2]\n  G1 X95 Y[#2+2]\n  G3 X95 Y[#2+7] I0 J2.5\n"
            f"  G1 X5 Y[#2+7]\n  G2 X5 Y#2 I0 J-3.5\n  #2=[#2+0.001]\n  #1=[#1+1]\no1 endwhile\n"
            f"G40 G1 X-10 Y-10\nM2\n"), rows * 6


def write_program(path, n_blocks, comp=True):
    """generate(n_blocks, comp) written straight to a file, for programs too large to hold."""
    rows = n_blocks // 6
    with open(path, "w", buffering=1 << 22) as f:
        f.write("G21 G17 G90 G94 G40 G49\nT1 M6\nG43 H1\nG0 X0 Y0 Z5\nG1 Z-1 F600\n" + ("G42.1 D2\n" if comp else ""))
        buf = []
        for i in range(rows):
            y = i * 0.001
            buf.append("G1 X100 Y%.3f\nG1 X100 Y%.3f\nG1 X95 Y%.3f\nG3 X95 Y%.3f I0 J2.5\nG1 X5 Y%.3f\n"
                       "G2 X5 Y%.3f I0 J-3.5\n" % (y, y + 2, y + 2, y + 7, y + 7, y))
            if len(buf) == 10000:
                f.write("".join(buf))
                buf.clear()
        f.write("".join(buf) + ("G40 G1 X-10 Y-10\n" if comp else "") + "M2\n")
    return rows * 6


def write_rows(path, head, row, foot, n_blocks, numbered=False):
    """Lines `head`, the contour rows of n_blocks // 6 rows in the six formats of `row`
    (as contour_rows), lines `foot`, written straight to a file 10,000 rows at a time; with
    ``numbered`` every line starts with its number from 0 (Klartext). Returns the rows' blocks."""
    rows = n_blocks // 6
    fmt = "".join(("%d " if numbered else "") + f + "\n" for f in row)
    with open(path, "w", buffering=1 << 22) as f:
        f.write("".join((f"{i} " if numbered else "") + line + "\n" for i, line in enumerate(head)))
        k = len(head)  # the number of the row's first line
        buf = []
        for i in range(rows):
            y = i * 0.001
            if numbered:  # (line number, y) for each block
                args = tuple(v for j, dy in enumerate(_ROW_Y) for v in (k + j, y + dy))
            else:
                args = tuple(y + dy for dy in _ROW_Y)
            buf.append(fmt % args)
            k += 6
            if len(buf) == 10000:
                f.write("".join(buf))
                buf.clear()
        f.write("".join(buf) + "".join((f"{k + i} " if numbered else "") + line + "\n" for i, line in enumerate(foot)))
    return rows * 6


def write_heidenhain(path, n_blocks):
    """generate_heidenhain(n_blocks) written straight to a file."""
    return write_rows(path, _KLARTEXT_HEAD, _KLARTEXT_ROW, _KLARTEXT_FOOT, n_blocks, numbered=True)


def write_sinumerik(path, n_blocks):
    """generate_sinumerik(n_blocks) written straight to a file."""
    return write_rows(path, _SINUMERIK_HEAD, _ISO_ROW, _SINUMERIK_FOOT, n_blocks)


def check_writers():
    """The file writers write what the generators return (small programs, compared byte for
    byte): the dialects' figures are of the same geometry. Raises if they do not."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "check")
        for n in (0, 5, 6, 61, 120_000):
            for name, write, text in (("ISO", lambda p, n: write_program(p, n), generate(n, True)[0]),
                                      ("Heidenhain", write_heidenhain, generate_heidenhain(n)[0]),
                                      ("Sinumerik", write_sinumerik, generate_sinumerik(n)[0])):
                write(path, n)
                with open(path) as f:
                    if f.read() != text:
                        raise RuntimeError(f"bench: the {name} file writer and its generator differ at {n} blocks")


# Run in a fresh interpreter so that its peak RSS is that of one run: tc.run on a file (both
# Paths kept) or tc.iter_run over it (chunks dropped as they come). The peak is the kernel's
# VmHWM of the child's own address space (getrusage's ru_maxrss would carry the parent's
# over the exec); `base` is VmHWM after the imports and the tool table, before the run.
# argv: the directory to import from, the program file, "run" or "stream", and a JSON object
# of options: "dialect" (None: from the suffix), "tools" ([table text, format], or None when
# the program defines its tools), "max_bytes" and "max_segments" (run()'s limits, raised for
# large programs).
_CHILD = r"""
import json, sys, time
sys.path.insert(0, sys.argv[1])
import toolcomp as tc

def hwm():
    with open("/proc/self/status") as f:
        return next(int(l.split()[1]) for l in f if l.startswith("VmHWM")) / 1024

opts = json.loads(sys.argv[4])
tools = tc.ToolTable.parse(*opts["tools"]) if opts["tools"] else None
limits = dict(dialect=opts["dialect"], max_bytes=opts["max_bytes"])
base = hwm()
t = time.perf_counter()
if sys.argv[3] == "run":
    res = tc.run(sys.argv[2], tools, max_segments=opts["max_segments"], **limits)
    segments, blocks, columns = len(res.path), res.blocks, res.path.nbytes + res.nominal.nbytes
else:
    stream = tc.iter_run(sys.argv[2], tools, chunk=1_000_000, **limits)
    segments = sum(len(c) for c in stream)
    blocks, columns = stream.blocks, 0
seconds = time.perf_counter() - t
print(json.dumps(dict(seconds=seconds, segments=segments, blocks=blocks, columns=columns, base=base,
                      peak=hwm())))
"""

ISO_TOOLS = ("T1 P1 Z50 D6\n", "linuxcnc")  # the ISO programs' tool table: T1, 6 mm, 50 mm long


def child(path, mode, dialect=None, tools=ISO_TOOLS):
    """_CHILD on the program file `path` in a fresh interpreter: its figures as a dict
    (seconds, segments, blocks, columns in bytes, base and peak VmHWM in MB). `tools` is
    (table text, format) or None."""
    import json

    size = os.path.getsize(path)
    opts = dict(dialect=dialect, tools=tools, max_bytes=max(2**31, size + 1),
                max_segments=max(20_000_000, size // 4))  # a segment per 4 bytes: more than any bench program makes
    out = subprocess.run([sys.executable, "-c", _CHILD, os.path.dirname(os.path.abspath(__file__)), path, mode,
                          json.dumps(opts)], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def bench_memory(n):
    """Peak RSS of one tc.run on the G42 program file against its Paths' columns."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "g42.ngc")
        write_program(path, n)
        r = child(path, "run")
    cols = r["columns"] / 2**20
    target = 1.5 * cols + 64
    print(f"memory         : tc.run(file) of {r['blocks']:,} blocks: peak RSS {r['peak']:.0f} MB "
          f"(interpreter and numpy {r['base']:.0f} MB) for {cols:.0f} MB of Path columns; "
          f"target 1.5 x columns + 64 MB = {target:.0f} MB ({r['peak'] / target:.2f} of it); "
          f"{r['seconds']:.2f} s, {r['seconds'] / r['blocks'] * 1e9:.0f} ns/block read + parse + run")


# res.plot() and savefig in a fresh interpreter: pyplot imported first (a notebook has it),
# then the first res.plot() as a user meets it (the columns it reads written out on the way),
# a second one, and the PNG. Peak RSS as for _CHILD.
_PLOT_CHILD = r"""
import json, sys, time
import matplotlib
matplotlib.use("Agg")
import toolcomp as tc

def hwm():
    with open("/proc/self/status") as f:
        return next(int(l.split()[1]) for l in f if l.startswith("VmHWM")) / 1024

res = tc.run(sys.argv[1], tc.ToolTable.parse("T1 P1 Z50 D6\n", "linuxcnc"))
t = time.perf_counter()
import matplotlib.pyplot as plt
pyplot = time.perf_counter() - t
base = hwm()
t = time.perf_counter()
ax = res.plot()
first = time.perf_counter() - t
vertices = sum(len(line.get_xdata()) for line in ax.get_lines())
t = time.perf_counter()
ax.figure.savefig(sys.argv[2], dpi=150)
save = time.perf_counter() - t
peak = hwm()
plt.close(ax.figure)
t = time.perf_counter()
plt.close(res.plot().figure)
again = time.perf_counter() - t
print(json.dumps(dict(segments=len(res.path), nominal=len(res.nominal), blocks=res.blocks, pyplot=pyplot,
                      first=first, again=again, save=save, vertices=vertices, base=base, peak=peak,
                      columns=(res.path.nbytes + res.nominal.nbytes) / 2**20)))
"""


def bench_plot(segments):
    """res.plot() of the G42 program with about `segments` compensated segments (5 for every
    3 blocks) and savefig of it to a PNG at 150 dpi, in a fresh interpreter."""
    import json

    with tempfile.TemporaryDirectory() as d:
        path, png = os.path.join(d, "plot.ngc"), os.path.join(d, "plot.png")
        write_program(path, segments * 3 // 5)
        out = subprocess.run([sys.executable, "-c", _PLOT_CHILD, path, png], check=True, capture_output=True,
                             text=True)
        r = json.loads(out.stdout)
        size = os.path.getsize(png)
    print(f"plot           : res.plot() of {r['segments']:,} compensated + {r['nominal']:,} programmed segments "
          f"({r['blocks']:,} blocks): {r['first']:.2f} s (again {r['again']:.2f} s; pyplot imported before, "
          f"{r['pyplot']:.2f} s), {r['vertices']:,} points drawn; savefig 150 dpi {r['save']:.2f} s "
          f"({size / 1024:.0f} KB); peak RSS {r['peak']:.0f} MB, {r['peak'] - r['base']:.0f} MB over the run's "
          f"{r['base']:.0f} MB ({r['columns']:.0f} MB of Path columns)")


def best_of(fn, repeat=3):
    best = float("inf")
    value = None
    for _ in range(repeat):
        value = None  # the last result goes before the next run starts (peak memory)
        t = time.perf_counter()
        value = fn()
        best = min(best, time.perf_counter() - t)
    return best, value


def best_interleaved(fns, rounds=4):
    """Best time of each of `fns` (name -> callable), run in turn `rounds` times: a slow spell
    of the machine falls on all of them alike instead of on whichever ran during it."""
    best = dict.fromkeys(fns, float("inf"))
    for _ in range(rounds):
        for name, fn in fns.items():
            t = time.perf_counter()
            fn()
            best[name] = min(best[name], time.perf_counter() - t)
    return best


def rs274_run(d, text):
    """A callable that runs LinuxCNC's rs274 on `text` in the directory `d` (a tool table for
    T1, an empty parameter file), output to /dev/null."""
    with open(os.path.join(d, "big.ngc"), "w") as f:
        f.write(text)
    with open(os.path.join(d, "t.tbl"), "w") as f:
        f.write("T1 P1 Z%.6f D%.6f\n" % (50 / 25.4, 6 / 25.4))  # this rs274 reads tables in inch
    open(os.path.join(d, "v.var"), "w").close()
    env = dict(os.environ, HOME=d)
    return lambda: subprocess.run(["rs274", "-g", "-t", "t.tbl", "-v", "v.var", "big.ngc", os.devnull], cwd=d,
                                  env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)


def bench_text(path):
    """What users wait for after a run: the G-code export and the CLI's CSV rows."""
    from toolcomp import _core
    from toolcomp.export import to_gcode

    n = len(path)
    path.start, path.center, path.feed  # written out once, as any first use does
    t_gcode, text = best_of(lambda: to_gcode(path, "grbl"))
    t_csv, _ = best_of(lambda: _core._csv_rows(path, 0, n, 0))
    print(f"  export, CSV    : {n:,} segments: G-code {t_gcode:.3f} s ({t_gcode / n * 1e9:.0f} ns/segment, "
          f"{len(text) / 2**20:.0f} MB), CSV rows {t_csv:.3f} s ({t_csv / n * 1e9:.0f} ns/segment)")


def bench_program(n, comp, tools):
    text, blocks = generate(n, comp)
    print(f"program {'with G42' if comp else 'without compensation'}: {blocks:,} motion blocks, "
          f"{len(text) / 1e6:.1f} MB")
    t_parse, prog = best_of(lambda: tc.Program.parse(text))
    t_run, res = best_of(lambda: tc.run(prog, tools=tools))
    compensated = int((res.path.side != 0).sum())
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"  toolcomp parse : {t_parse:7.3f} s  {blocks / t_parse / 1e6:6.2f} M blocks/s  "
          f"{t_parse / blocks * 1e9:5.0f} ns/block")
    print(f"  toolcomp run   : {t_run:7.3f} s  {blocks / t_run / 1e6:6.2f} M blocks/s  "
          f"{t_run / blocks * 1e9:5.0f} ns/block  ({len(res.path):,} segments, {compensated:,} compensated)")
    print(f"  toolcomp total : {t_parse + t_run:7.3f} s  peak RSS of the bench so far {rss:.0f} MB; the two Paths' "
          f"columns {(res.path.nbytes + res.nominal.nbytes) / 2**20:.0f} MB")
    if comp:
        bench_text(res.path)
    del res, prog
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "bench.ngc")
        with open(path, "w") as f:
            f.write(text)
        runs = {"file": lambda: tc.run(path, tools)}
        if shutil.which("rs274"):
            runs["rs274"] = rs274_run(d, text)
        # In turn, best of three each: a slow spell of the machine falls on both alike.
        t = best_interleaved(runs, rounds=3)
    t_file = t["file"]
    print(f"  tc.run(file)   : {t_file:7.3f} s  {blocks / t_file / 1e6:6.2f} M blocks/s  "
          f"{t_file / blocks * 1e9:5.0f} ns/block  (read and parsed piece by piece on the other core)")
    if "rs274" in t:
        t_rs = t["rs274"]
        print(f"  LinuxCNC rs274 : {t_rs:7.3f} s  {blocks / t_rs / 1e6:6.2f} M blocks/s  (output to /dev/null; "
              f"best of 3, in turn with tc.run(file))")
        print(f"  speed-up       : {t_rs / (t_parse + t_run):7.1f} x (parse + run), {t_rs / t_file:.1f} x (tc.run(file))")
    else:
        print("  LinuxCNC rs274 : not installed (make oracle installs it)")


def bench_other(label, text, blocks, dialect, tools):
    """toolcomp only (no rs274 counterpart): parse and run, ns per block."""
    print(f"program {label}: {blocks:,} motion blocks, {len(text) / 1e6:.1f} MB")
    t_parse, prog = best_of(lambda: tc.Program.parse(text, dialect=dialect), repeat=2)
    t_run, res = best_of(lambda: tc.run(prog, tools=tools), repeat=2)
    print(f"  toolcomp parse : {t_parse:7.3f} s  {t_parse / blocks * 1e9:5.0f} ns/block")
    print(f"  toolcomp run   : {t_run:7.3f} s  {blocks / t_run / 1e6:6.2f} M blocks/s  "
          f"{t_run / blocks * 1e9:5.0f} ns/block  ({len(res.path):,} segments, "
          f"{int((res.path.side != 0).sum()):,} compensated, {len(res.diagnostics):,} warnings)")
    del res, prog


# ---- the three dialects side by side ------------------------------------------------------

class Dialect(NamedTuple):
    """A dialect's version of the contour program with radius compensation (r = 1 mm)."""
    name: str
    program: str  # what the program is
    dialect: str  # tc's dialect name
    suffix: str
    write: Callable[[str, int], int]  # write(path, n_blocks) -> motion blocks written
    tools: Optional[Tuple[str, str]]  # (table text, format) given to the run; None: the program's own
    read_whole: bool  # iter_run reads the file whole (not piece by piece)


DIALECTS = (
    Dialect("ISO", "LinuxCNC, G42.1 D2, tool table T1", "linuxcnc", ".ngc", write_program, ISO_TOOLS, False),
    Dialect("Sinumerik", "840D, G42, $TC_DP tool data", "sinumerik", ".mpf", write_sinumerik, None, False),
    Dialect("Heidenhain", "Klartext L/CR, RR, TOOL DEF", "heidenhain", ".h", write_heidenhain, None, False),
)
ISO_NO_COMP = Dialect("ISO no comp", "LinuxCNC, no compensation", "linuxcnc", ".ngc",
                      lambda path, n: write_program(path, n, comp=False), ISO_TOOLS, False)


def run_child(d, path, mode="run"):
    """child() with the dialect's name and tool table."""
    return child(path, mode, d.dialect, d.tools)


def mem_available_mb():
    """MemAvailable of /proc/meminfo, MB."""
    with open("/proc/meminfo") as f:
        return next(int(l.split()[1]) for l in f if l.startswith("MemAvailable")) / 1024


def fits(peak_mb, what):
    """None if `peak_mb` of memory is at most 80 % of MemAvailable now (the rest for the
    machine's other work), else the reason to skip `what`."""
    avail = mem_available_mb()
    if peak_mb <= 0.8 * avail:
        return None
    return (f"skipped {what}: it would need about {peak_mb / 1024:.1f} GB, more than 80 % of the "
            f"{avail / 1024:.1f} GB available (MemAvailable)")


def bench_dialects(n, rounds):
    """ISO, Sinumerik and Heidenhain on the same contour of n blocks with radius compensation.
    Each program file is written by its streaming writer; in this process, Program.parse of
    its text and tc.run of the Program (best of 2 each); then tc.run(file) of each in a fresh
    interpreter, `rounds` rounds with the dialects in turn: the median time, and the median
    peak memory of the run (VmHWM after the run less VmHWM before it, as _CHILD measures) with
    the size of its two Paths' columns. The ratios are each dialect's figure over ISO's."""
    check_writers()
    rows = {}
    with tempfile.TemporaryDirectory() as td:
        paths = {}
        for d in DIALECTS:
            paths[d.name] = os.path.join(td, "bench" + d.suffix)
            blocks = d.write(paths[d.name], n)
        for d in DIALECTS:
            with open(paths[d.name]) as f:
                text = f.read()
            tools = tc.ToolTable.parse(*d.tools) if d.tools else None
            t_parse, prog = best_of(lambda: tc.Program.parse(text, dialect=d.dialect), repeat=2)
            t_run, res = best_of(lambda: tc.run(prog, tools=tools), repeat=2)
            rows[d.name] = dict(parse=t_parse, run=t_run, mb=len(text) / 2**20, segments=len(res.path),
                                compensated=int((res.path.side != 0).sum()), warnings=len(res.diagnostics),
                                file=[], peak=[], base=[], columns=(res.path.nbytes + res.nominal.nbytes) / 2**20)
            del text, prog, res
        for _ in range(rounds):
            for d in DIALECTS:
                r = run_child(d, paths[d.name])
                rows[d.name]["file"].append(r["seconds"])
                rows[d.name]["peak"].append(r["peak"] - r["base"])
                rows[d.name]["base"].append(r["base"])
    ns = lambda t: t / blocks * 1e9  # noqa: E731
    for r in rows.values():
        r["file"], r["peak"] = statistics.median(r["file"]), statistics.median(r["peak"])
    iso = rows["ISO"]
    print(f"dialects       : the contour with radius compensation (r = 1 mm), {blocks:,} motion blocks each; "
          f"parse and run in this process (best of 2), tc.run(file) and its peak memory in a fresh process "
          f"(median of {rounds}, dialects in turn; peak = VmHWM over the "
          f"{statistics.median(iso['base']):.0f} MB of interpreter and numpy)")
    print(f"  {'':<11}{'file':>6}{'parse':>10}{'run':>10}{'total':>10}{'x ISO':>7}{'run(file)':>11}{'x ISO':>7}"
          f"{'peak':>8}{'x ISO':>7}{'columns':>9}  program")
    print(f"  {'':<11}{'MB':>6}{'ns/block':>10}{'ns/block':>10}{'ns/block':>10}{'':>7}{'ns/block':>11}{'':>7}"
          f"{'MB':>8}{'':>7}{'MB':>9}")
    for d in DIALECTS:
        r = rows[d.name]
        total = r["parse"] + r["run"]
        print(f"  {d.name:<11}{r['mb']:6.1f}{ns(r['parse']):10.0f}{ns(r['run']):10.0f}{ns(total):10.0f}"
              f"{total / (iso['parse'] + iso['run']):7.2f}{ns(r['file']):11.0f}{r['file'] / iso['file']:7.2f}"
              f"{r['peak']:8.0f}{r['peak'] / iso['peak']:7.2f}{r['columns']:9.0f}  {d.program}")
    print("  " + "; ".join(f"{d.name} {rows[d.name]['segments']:,} segments, {rows[d.name]['compensated']:,} "
                           f"compensated, {rows[d.name]['warnings']:,} warnings" for d in DIALECTS))


def short(n):
    """1M for 1,000,000; other counts with thousands separators."""
    return f"{n // 10**6}M" if n and n % 10**6 == 0 else f"{n:,}"


def bench_linearity(n, factor, rounds):
    """tc.run on a program file of n * factor blocks against one of n blocks, each dialect with
    radius compensation (and ISO without it): every run in a fresh interpreter, as a user's
    script meets it (in one process the column cache would keep the small run's columns warm),
    in interleaved rounds (n, n * factor, n, n * factor, ...) so that a slow spell of the
    machine falls on both sizes. Prints the median of the per-round ratios with their range,
    the median times and the large run's peak memory. The large run is skipped when the small
    run's memory over the interpreter's, times `factor`, would not fit (fits())."""
    big_n = n * factor
    print(f"linearity      : tc.run(file) of {big_n:,} against {n:,} blocks, each run in a fresh process, "
          f"{rounds} interleaved rounds ({short(n)}, {short(big_n)}, {short(n)}, ...); ratio of the times: "
          f"median of the rounds' (min..max); times: medians; peak MB: the large run's, over the interpreter")
    print(f"  {'':<13}{'ratio':>7}{'range':>14}{'small s':>9}{'large s':>9}{'ns/block':>15}{'peak MB':>9}")
    for d in DIALECTS + (ISO_NO_COMP,):
        with tempfile.TemporaryDirectory() as td:
            small, big = os.path.join(td, "small" + d.suffix), os.path.join(td, "big" + d.suffix)
            blocks = d.write(small, n)
            first = run_child(d, small)
            skip = fits(first["base"] + (first["peak"] - first["base"]) * factor, f"{big_n:,} blocks")
            if skip:
                print(f"  {d.name:<13}{skip}")
                continue
            big_blocks = d.write(big, big_n)
            t_small, t_big, peak = [], [], []
            for i in range(rounds):
                r = first if i == 0 else run_child(d, small)
                t_small.append(r["seconds"])
                r = run_child(d, big)
                t_big.append(r["seconds"])
                peak.append(r["peak"] - r["base"])
        ratios = [b / s for s, b in zip(t_small, t_big)]
        m_small, m_big = statistics.median(t_small), statistics.median(t_big)
        per_block = f"{m_small / blocks * 1e9:.0f} / {m_big / big_blocks * 1e9:.0f}"
        print(f"  {d.name:<13}{statistics.median(ratios):7.2f}{f'{min(ratios):.2f}..{max(ratios):.2f}':>14}"
              f"{m_small:9.2f}{m_big:9.2f}{per_block:>15}{statistics.median(peak):9.0f}")


def bench_stream(n, d=DIALECTS[0], probe=1_000_000):
    """tc.iter_run over a file of n blocks of dialect `d` (chunks of 1M segments) in a fresh
    interpreter: time and peak RSS. A dialect whose file iter_run reads whole is first
    streamed at `probe` blocks; its peak memory over the interpreter's, scaled to n blocks,
    says whether the n-block run fits (fits()); if not it is skipped with the reason."""
    with tempfile.TemporaryDirectory() as td:
        path = os.path.join(td, "stream" + d.suffix)
        note = ""
        if d.read_whole and n > probe:
            d.write(path, probe)
            r = run_child(d, path, "stream")
            estimate = r["base"] + (r["peak"] - r["base"]) * n / probe
            note = (f" (read whole; estimated {estimate:.0f} MB from {probe:,} blocks: {r['peak']:.0f} MB, "
                    f"{r['seconds'] / r['blocks'] * 1e9:.0f} ns/block)")
            skip = fits(estimate, f"{n:,} blocks")
            size = os.path.getsize(path) * n / probe
            if not skip and size > 0.9 * shutil.disk_usage(td).free:
                skip = f"skipped {n:,} blocks: the file, about {size / 2**30:.1f} GiB, would not fit on {td}'s disk"
            if skip:
                print(f"streaming {d.name:<11}: tc.iter_run over {probe:,} blocks: {r['seconds']:.1f} s, "
                      f"{r['seconds'] / r['blocks'] * 1e9:.0f} ns/block, peak RSS {r['peak']:.0f} MB "
                      f"(the file is read whole); {skip}")
                return
        t = time.perf_counter()
        d.write(path, n)
        size = os.path.getsize(path)
        gen = time.perf_counter() - t
        r = run_child(d, path, "stream")
    print(f"streaming {d.name:<11}: tc.iter_run over {r['blocks']:,} blocks ({size / 2**20:,.0f} MB file, written in "
          f"{gen:.0f} s): {r['segments']:,} segments in {r['seconds']:.1f} s, "
          f"{r['seconds'] / r['blocks'] * 1e9:.0f} ns/block, peak RSS {r['peak']:.0f} MB{note}")


def bench_batch(n, tools):
    """8 programs of n/8 blocks each (with compensation), one after the other and with run_many."""
    text, blocks = generate(max(6, n // 8), True)
    with tempfile.TemporaryDirectory() as d:
        paths = []
        for i in range(8):
            p = os.path.join(d, f"p{i}.ngc")
            with open(p, "w") as f:
                f.write(text)
            paths.append(p)
        cores = os.cpu_count() or 1
        one_by_one = lambda: [tc.run(p, tools) for p in paths]  # noqa: E731
        fns = {"seq": one_by_one, "many": lambda: tc.run_many(paths, tools, workers=cores)}
        # A single run already puts its overcut watch and the reading of its file on the
        # other core; one by one on one core is the run without a second core to use.
        allowed = os.sched_getaffinity(0) if hasattr(os, "sched_setaffinity") else None
        if allowed:
            def one_core():
                os.sched_setaffinity(0, {min(allowed)})
                try:
                    one_by_one()
                finally:
                    os.sched_setaffinity(0, allowed)
            fns["one"] = one_core
        t = best_interleaved(fns)
        t_seq, t_many, t_one = t["seq"], t["many"], t.get("one")
    one = f"one by one on 1 core {t_one:.3f} s, " if t_one else ""
    print(f"batch          : 8 programs of {blocks:,} blocks: {one}one by one {t_seq:.3f} s, "
          f"run_many on {cores} threads {t_many:.3f} s: {t_seq / t_many:.2f} x over one by one"
          + (f", {t_one / t_many:.2f} x over 1 core" if t_one else "") + " (best of 4, in turn)")


def bench_3d(m):
    """tc.compensate_3d of m random CAM points and normals (one core), ball and toroid, best of 3."""
    import numpy as np

    rng = np.random.default_rng(1)
    pts = rng.normal(size=(m, 3))
    nrm = rng.normal(size=(m, 3))
    out = np.empty_like(pts)
    t_ball, _ = best_of(lambda: tc.compensate_3d(pts, nrm, R=3, R2=3, DR=-0.1, DR2=-0.1, out=out))
    t_torus, _ = best_of(lambda: tc.compensate_3d(pts, nrm, R=3, R2=1, DR=-0.1, DR2=-0.05, out=out))
    print(f"compensate_3d  : {m:,} points: ball {t_ball:.3f} s ({m / t_ball / 1e6:.0f} M/s), "
          f"toroid {t_torus:.3f} s ({m / t_torus / 1e6:.0f} M/s)")


SECTIONS = ("iso", "dialects", "loop", "batch", "memory", "plot", "linearity", "stream", "3d")


@contextlib.contextmanager
def section(name, chosen):
    """Runs the body if `name` is among the chosen sections, then prints its elapsed time."""
    if name not in chosen:
        yield False
        return
    t = time.perf_counter()
    yield True
    print(f"  [{name}: {time.perf_counter() - t:.0f} s]")


def env_int(name, default):
    return int(os.environ.get(name, str(default)))


def main():
    sys.stdout.reconfigure(line_buffering=True)  # each figure as it comes, under make too
    n = env_int("TOOLCOMP_BENCH_BLOCKS", 1_000_000)
    rounds = max(1, env_int("TOOLCOMP_BENCH_ROUNDS", 3))
    chosen = os.environ.get("TOOLCOMP_BENCH_SECTIONS", ",".join(SECTIONS)).replace(" ", "").split(",")
    unknown = set(chosen) - set(SECTIONS)
    if unknown:
        sys.exit(f"TOOLCOMP_BENCH_SECTIONS: unknown {', '.join(sorted(unknown))} (sections: {', '.join(SECTIONS)})")
    tools = tc.ToolTable.parse(*ISO_TOOLS)
    start = time.perf_counter()
    with section("iso", chosen) as on:
        if on:
            bench_program(n, True, tools)
            bench_program(n, False, tools)
    with section("dialects", chosen) as on:
        if on:
            bench_dialects(n, rounds)
    with section("loop", chosen) as on:
        if on:
            bench_other("LinuxCNC o-while loop with G42.1", *generate_loops(n), "linuxcnc", tools)
    with section("batch", chosen) as on:
        if on:
            bench_batch(n, tools)
    with section("memory", chosen) as on:
        if on:
            bench_memory(n)
    plotted = env_int("TOOLCOMP_BENCH_PLOT_SEGMENTS", 1_000_000)
    with section("plot", chosen if plotted > 0 else ()) as on:
        if on:
            bench_plot(plotted)
    factor = env_int("TOOLCOMP_BENCH_LINEAR", 10)
    with section("linearity", chosen if factor > 1 else ()) as on:
        if on:
            bench_linearity(n, factor, rounds)
    streamed = env_int("TOOLCOMP_BENCH_STREAM_BLOCKS", 50_000_000)
    streamed_other = env_int("TOOLCOMP_BENCH_STREAM_OTHER_BLOCKS", streamed)
    with section("stream", chosen) as on:
        if on:
            for d in DIALECTS:
                blocks = streamed if d.name == "ISO" else streamed_other
                if blocks > 0:
                    bench_stream(blocks, d, probe=min(n, blocks))
    with section("3d", chosen) as on:
        if on:
            bench_3d(env_int("TOOLCOMP_BENCH_POINTS", 10_000_000))
    print(f"  [total: {time.perf_counter() - start:.0f} s]")
    return 0


if __name__ == "__main__":
    sys.exit(main())
