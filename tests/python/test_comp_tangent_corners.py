"""A line that ends exactly tangent to the inner equidistant of the arc after it (a concave
corner the tool of radius r just reaches): LinuxCNC decides on the last bit of its corner angle,
worked out with long-double constants, and accepts six of the eight orientations below and
refuses two (verdicts of LinuxCNC 2.9's gcode module; the programs are in tests/programs/comp,
where the oracle suite checks them against LinuxCNC itself). Tool 4: D4, r = 2 mm."""

from pathlib import Path

import pytest

import toolcomp as tc

ROOT = Path(__file__).resolve().parents[2]
COMP = ROOT / "tests" / "programs" / "comp"
TABLE = COMP / "tools.tbl"

# orientation of the line -> None (refused at line 5) or the arc's compensated end (mm): the
# programmed end moved r = 2 towards the centre (the tool is inside the arc in every case).
EXPECTED = {
    "px_g41": (36, 2), "px_g42": None,
    "py_g41": None, "py_g42": (2, 36),
    "nx_g41": (-36, -2), "nx_g42": (-36, 2),
    "ny_g41": (2, -36), "ny_g42": (-2, -36),
}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_exactly_tangent_concave_line_to_arc(name):
    prog = COMP / f"tangent_concave_line_arc_{name}.ngc"
    want = EXPECTED[name]
    if want is None:
        with pytest.raises(tc.CompensationError) as e:
            tc.run(str(prog), tools=str(TABLE))
        assert e.value.line == 5
        assert e.value.message == "Arc move in concave corner cannot be reached by the tool without gouging"
        return
    path = tc.run(str(prog), tools=str(TABLE)).path
    assert list(path.kind) == [tc.LINE, tc.ARC_CW if name.endswith("g42") else tc.ARC_CCW]
    # The held line is pulled to where its equidistant touches the arc's inner equidistant
    # (radius 4 - 2 about the centre): the arc's compensated end itself (to 1e-7: asin near 1
    # turns the last bit of l into 3e-8 mm). The arc runs from there to its end.
    assert path.end[0][:2] == pytest.approx(want, abs=1e-7)
    assert path.end[0][:2] == pytest.approx(path.start[1][:2], abs=1e-12)
    assert path.end[1].tolist() == pytest.approx([*want, 0], abs=1e-12)



@pytest.mark.parametrize("n", range(8))
def test_a_tangent_corner_at_a_slant_is_decided_in_long_double(n):
    # 3-4-5 slants, tool radius half the arc's: l = 1 in exact arithmetic. LinuxCNC takes the
    # sine of the long double beta - M_PI_2l and refuses the first six (l = 1 + 2e-16; with a
    # double sine toolcomp ran them) and runs the last two (verdicts of LinuxCNC's gcode module).
    prog = COMP / f"tangent_concave_line_arc_slant_{n}.ngc"
    if n <= 5:
        with pytest.raises(tc.CompensationError) as e:
            tc.run(str(prog))
        assert (e.value.line, e.value.message) == (
            6, "Arc move in concave corner cannot be reached by the tool without gouging")
    else:
        assert list(tc.run(str(prog)).path.kind) == [tc.LINE, tc.ARC_CCW if "G3" in prog.read_text() else tc.ARC_CW]
