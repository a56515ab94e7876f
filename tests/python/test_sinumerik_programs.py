"""Whole 840D programs as an 840D programmer and a CAM post write them (tests/programs/sinumerik):
macros, machine data and strings in conditions, a settable frame the program sets, a PROC
with VAR and SAVE, MCALL CYCLE83 on a HOLES2 bolt circle, an inch job with CYCLE81 and
CYCLE84. The numbers are worked by hand (doc/sinumerik.md has the cycles' rules)."""
import math
from pathlib import Path

import numpy as np

import toolcomp as tc

HERE = Path(__file__).resolve().parents[1] / "programs" / "sinumerik"


def tools():
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=5.0, length=[0.0, 0.0, 100.0])]))
    t.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=2.0, length=[0.0, 0.0, 80.0])]))
    return t


def run(name):
    # The points below count the first move from machine zero, where the run is told to start.
    return tc.run(tc.Program.read(HERE / name), tools=tools(), search_path=[HERE], start="machine_zero")


def test_flange_bolt_circle_and_ring_groove():
    res = run("FLANGE.MPF")
    p = res.nominal
    kind, end, feed = p.kind, np.round(p.end, 4), p.feed
    # G54 = CTRANS(X80, Y80): the six holes at 55 mm from the centre, from 30 degrees on.
    bottoms = [tuple(e[:2]) for k, e in zip(kind, end) if k == tc.LINE and e[2] == -18]
    expect = [(round(80 + 55 * math.cos(math.radians(a)), 4), round(80 + 55 * math.sin(math.radians(a)), 4))
              for a in (30, 90, 150, 210, 270, 330)]
    assert bottoms == expect
    # CYCLE83 at the first hole, chip breaking (VARI 0, _VRT 1 mm), FDEP -6, DAM 2: strokes to
    # -6, then 4 (6 - 2), 2, 2, and the last 4 mm in two halves: -16, -18; F250 (MAT "ALU").
    first = [i for i, e in enumerate(end) if tuple(e[:2]) == expect[0]]
    zs = [(int(kind[i]), end[i][2]) for i in first]
    assert zs == [(tc.RAPID, 50), (tc.RAPID, 2), (tc.LINE, -6), (tc.RAPID, -5), (tc.LINE, -10), (tc.RAPID, -9),
                  (tc.LINE, -12), (tc.RAPID, -11), (tc.LINE, -14), (tc.RAPID, -13), (tc.LINE, -16),
                  (tc.RAPID, -15), (tc.LINE, -18), (tc.RAPID, 10)]
    assert {float(feed[i]) for i in first if kind[i] == tc.LINE} == {250.0}
    # RING(30, 5, R10): its circle about (80, 80) at Z-5, the cutter (radius 5) inside on 25;
    # R10 counts the lap in the caller.
    path = res.path
    on_ring = [tuple(np.round(e, 4)) for e, z in zip(path.end, path.end[:, 2]) if z == -5]
    assert (105.0, 80.0, -5.0) in on_ring
    assert [d.message for d in res.diagnostics if d.code == "message"] == ["Ring laps 1"]


def test_plate_in_inches_drills_and_taps_modally():
    res = run("PLATE_INCH.MPF")
    p = res.nominal
    moves = [(int(k), tuple(np.round(e / 25.4, 4)), None if k == tc.RAPID else round(float(f), 4))
             for k, e, f in zip(p.kind, p.end, p.feed)]
    drill = lambda x, y: [(tc.RAPID, (x, y, 0.1), None), (tc.LINE, (x, y, -0.4), 304.8), (tc.RAPID, (x, y, 0.5), None)]
    # CYCLE84: pitch 0.05 in x 600 rev/min = 30 in/min = 762 mm/min in and out.
    tap = [(tc.RAPID, (1.0, 2.0, 0.1), None), (tc.LINE, (1.0, 2.0, -0.5), 762.0), (tc.LINE, (1.0, 2.0, 0.1), 762.0),
           (tc.RAPID, (1.0, 2.0, 0.5), None)]
    assert moves[:-1] == ([(tc.RAPID, (1.0, 1.0, 1.0), None), (tc.RAPID, (1.0, 1.0, 1.0), None)] + drill(1.0, 1.0)
                          + [(tc.RAPID, (2.5, 1.0, 0.5), None)] + drill(2.5, 1.0) + [(tc.RAPID, (1.0, 2.0, 0.5), None)]
                          + tap)
    assert "blending_not_modelled" in [d.code for d in res.diagnostics]
