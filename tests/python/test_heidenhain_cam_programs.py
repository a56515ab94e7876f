"""Whole programs as CAM posts write them for the TNC (tests/programs/heidenhain): a Fusion 360
style drill-and-bore job (TOOL CALL Z for M140, M140 MB MAX, CYCL DEF 247, 32, 200 with M99,
208) and a hyperMILL style job (a name of letters and digits, M91 safe positions, M126/M127,
FUNCTION RESET TCPM, PLANE ... STAY with L A+Q120 C+Q122, a datum shift in X, Y and Z, cycle
203 with `~` continuation and a Q parameter feed, FN 18 and a jump to a named label, `/` block
skip). The machine: preset at machine (-300, -200, -450), Z travel up to machine 0.
Numbers worked by hand from the cycles' runs (doc/heidenhain.md)."""
import pathlib

import numpy as np

import toolcomp as tc

HERE = pathlib.Path(__file__).resolve().parents[1] / "programs" / "heidenhain"
MACHINE = ('control = "heidenhain"\nkind = "mill"\n[positions]\nwork_origin = [-300.0, -200.0, -450.0]\n'
           '[travel]\nx = [-600, 0]\ny = [-400, 0]\nz = [-500, 0]\n')


def run(name, tools):
    return tc.run(tc.Program.read(HERE / name), tools=tc.ToolTable.read(HERE / tools), machine=tc.Machine.parse(MACHINE))


def test_fusion_drill_and_bore_job():
    res = run("fusion_drill_bore.h", "fusion_tools.t")
    p = res.nominal
    assert sorted(d.code for d in res.diagnostics) == ["blending_not_modelled", "preset_not_modelled"]
    # M140 MB MAX puts the spindle at machine Z0: the 80 mm centre drill's tip at 450 - 80.
    assert p.start[0, 2] == 370
    # Four holes at (+-25, +-15), each from 5 above the surface 8 deep in one plunge (Q202 = 8)
    # at F300, out to the 2nd set-up clearance 15.
    bottoms = p.end[(p.kind == tc.LINE) & (p.end[:, 2] == -8)]
    assert [tuple(b[:2]) for b in bottoms] == [(25, -15), (-25, -15), (-25, 15), (25, 15)]
    assert np.all(p.feed[(p.kind == tc.LINE) & (p.end[:, 2] == -8)] == 300)
    # The 8 mm end mill (L90) after M140 MB MAX: its tip at 450 - 90 = 360.
    assert 360 in p.end[:, 2] and 360 in p.start[:, 2]
    # 208: tool R4 in a 12 mm hole: the centre on radius 2; from +5 to -10 at 1.5 a turn: 10
    # turns, ending where it began (start == end and 9 more).
    helix = np.flatnonzero((p.kind == tc.ARC_CCW) & (p.end[:, 2] == -10))[0]
    assert tuple(p.end[helix]) == (2, 0, -10) and p.turns[helix] == 9 and tuple(p.center[helix, :2]) == (0, 0)


def test_hypermill_plate_job():
    res = run("hypermill_plate.h", "hypermill_tools.t")
    p = res.nominal
    assert [d.code for d in res.diagnostics] == ["blending_not_modelled"]
    assert np.all(p.abc == 0)  # A+Q120 C+Q122 of the untilted plane
    # L Z0 M91: the spindle at machine Z0, the 75 mm tool's tip at program 450 - 75.
    assert p.start[0, 2] == 375 and p.end[-1, 2] == 375
    # The datum shifted by (186.5, 0, -25): holes at (147.5, 7) and (222.5, 155.1); cycle 203
    # without decrement or breaks: plunges of 5, 5 and 2 from 3 above the surface -25, out of
    # the hole after each at Q208 = 25000 and back at FMAX to 3 above the depth reached.
    lines = (HERE / "hypermill_plate.h").read_text().splitlines()
    line_of = {l.split()[0]: i + 1 for i, l in enumerate(lines) if l[:1].isdigit()}
    for block, (x, y) in [("26", (147.5, 7)), ("27", (222.5, 155.1))]:
        at = np.flatnonzero(p.line == line_of[block])[-10:]  # the cycle's moves (after the block's own)
        np.testing.assert_allclose(p.end[at, :2], [(x, y)] * 10, atol=1e-9)
        assert list(p.end[at, 2]) == [-22, -30, -22, -27, -35, -22, -32, -37, -22, -15]
        assert list(p.feed[at][p.kind[at] == tc.LINE]) == [95, 25000, 95, 25000, 95, 25000]
    # FN 18 ID270 read Z 10 in the shifted system: the jump skipped block 30.
    assert line_of["30"] not in p.line
