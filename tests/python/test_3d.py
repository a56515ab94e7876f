"""3D tool compensation: Heidenhain LN blocks and tc.compensate_3d for CAM data."""
import numpy as np
import pytest

import toolcomp as tc

N_EX = (0.2637581, 0.0078922, -0.8764339)  # the TNC manuals' example normal (|N| = 0.9153)


def ln_program(lines, tool="TOOL DEF 1 L+0 R+3 R2+3\nTOOL CALL 1 Z DR-0.1 DR2-0.1", extra=""):
    body = [tool, "L X+0 Y+0 Z+50 R0 FMAX" + extra] + lines
    text = "\n".join(f"{i} {l}" for i, l in enumerate(["BEGIN PGM S MM"] + body + ["END PGM S MM"]))
    return tc.run(tc.Program.parse(text, dialect="heidenhain"), start="machine_zero")


def test_ln_ball_cutter_moves_along_the_normal():
    res = ln_program([f"LN X+31.737 Y+21.954 Z+33.165 NX+{N_EX[0]} NY+{N_EX[1]} NZ{N_EX[2]} F1000"])
    ln = res.path.end[-1] - res.nominal.end[-1]
    np.testing.assert_allclose(ln, [-0.02882, -0.00086, 0.09575], atol=1e-5)
    n = np.array(N_EX) / np.linalg.norm(N_EX)
    np.testing.assert_allclose(res.path.normal[-1], n)
    assert np.isnan(res.path.normal[0]).all()
    assert [d.code for d in res.diagnostics] == ["ln_normal_not_unit"]  # warned once


def test_positive_deltas_need_m107():
    lines = ["LN X+1 Y+0 Z+0 NX+0 NY+0 NZ+1 F100"]
    tool = "TOOL DEF 1 L+0 R+3 R2+3\nTOOL CALL 1 Z DR2+0.1"
    with pytest.raises(tc.ProgramError, match="M107") as e:
        ln_program(lines, tool=tool)
    assert e.value.line == 5
    res = ln_program(lines, tool=tool, extra=" M107")
    np.testing.assert_allclose(res.path.end[-1], [1, 0, 0.1])


@pytest.mark.parametrize("block", [
    "LN X+1 Y+0 Z+0 NX+0 NZ+1 F100",            # NY missing
    "LN X+1 Z+0 Y+0 NX+0 NY+0 NZ+1 F100",       # order
    "LN X+1 Y+0 Z+0 NX+0 NY+0 NZ+1 TX+0 TZ+1",  # TY missing
])
def test_ln_block_format_errors(block):
    with pytest.raises(tc.ProgramError) as e:
        ln_program([block])
    assert e.value.code == "ln_block_format" and e.value.line == 5


@pytest.mark.parametrize("word", ["TX+Q1 TY+0 TZ+1", "TX+0 TY-Q1 TZ+1", "TX+0 TY+0 TZ+Q1"])
def test_ln_tool_orientation_must_be_numbers(word):
    # spec 2.6: TX/TY/TZ are numbers, a Q parameter there is a block format error; in X..NZ
    # a Q parameter is a value like any other.
    q = ["Q1 = 0.5"]
    with pytest.raises(tc.ProgramError) as e:
        ln_program(q + [f"LN X+1 Y+0 Z+0 NX+0 NY+0 NZ+1 {word} F100"], extra=" M128")
    assert e.value.code == "ln_block_format" and e.value.line == 6 and "Q parameters" in e.value.message
    res = ln_program(q + ["LN X+Q1 Y+0 Z+0 NX+0 NY+0 NZ+1 TX+0 TY+0 TZ+1 F100"], extra=" M128")
    assert res.nominal.end[-1, 0] == 0.5


def test_m128_tool_axis_and_contact_points():
    # Toroid R 4, R2 1 tilted along T with M128; the contact point of the nominal tool at PT and
    # of the actual tool at the compensated point are the same surface point.
    tool = "TOOL DEF 1 L+0 R+4 R2+1\nTOOL CALL 1 Z DR-0.2 DR2-0.05"
    res = ln_program(["LN X+10 Y+5 Z+2 NX+0.6 NY+0 NZ+0.8 TX+0 TY+0.6 TZ+0.8 F500 M128"], tool=tool)
    np.testing.assert_allclose(res.path.tool_axis[-1], [0, 0.6, 0.8])
    nominal = res.nominal.contact_points(4, 1)[-1]
    actual = res.path.contact_points(4 - 0.2, 1 - 0.05)[-1]
    np.testing.assert_allclose(nominal, actual, atol=1e-12)
    # without M128 the T vector is ignored: the tool axis is Z
    res = ln_program(["LN X+10 Y+5 Z+2 NX+0.6 NY+0 NZ+0.8 TX+0 TY+0.6 TZ+0.8 F500"], tool=tool)
    np.testing.assert_allclose(res.path.tool_axis[-1], [0, 0, 1])


def test_compensate_3d_zero_copy_and_same_code_as_ln():
    rng = np.random.default_rng(3)
    pts = rng.normal(size=(1000, 3))
    nrm = rng.normal(size=(1000, 3))
    out = tc.compensate_3d(pts, nrm, R=3, R2=1, DR=-0.2, DR2=-0.05)
    assert out.shape == (1000, 3) and not np.shares_memory(out, pts)
    # ball: along the normal
    ball = tc.compensate_3d(pts, nrm, R=3, R2=3, DR=-0.1, DR2=-0.1)
    np.testing.assert_allclose(ball - pts, -0.1 * nrm / np.linalg.norm(nrm, axis=1)[:, None])
    # in place
    again = pts.copy()
    res = tc.compensate_3d(again, nrm, R=3, R2=1, DR=-0.2, DR2=-0.05, out=again)
    assert res is again
    np.testing.assert_allclose(again, out)
    with pytest.raises(ValueError):
        tc.compensate_3d(pts, nrm, R=3, R2=1, out=np.zeros((1000, 3), dtype=np.float32))
    with pytest.raises(ValueError):
        tc.compensate_3d(pts, nrm[:5], R=3, R2=1)


@pytest.mark.parametrize("bad", [(0, 0, 0), (np.nan, 0, 1), (0, np.inf, 1), (1e-200, 0, 0)])
@pytest.mark.parametrize("where", ["normals", "tool_axes"])
def test_compensate_3d_refuses_a_normal_or_axis_that_is_not_a_direction(bad, where):
    # A zero normal would leave its point uncompensated without a word; nothing is written,
    # not even into `out` when it is `points`.
    pts = np.arange(12.0).reshape(4, 3)
    arrays = {"normals": np.tile([0.0, 0.0, 1.0], (4, 1)), "tool_axes": np.tile([0.0, 0.0, 1.0], (4, 1))}
    arrays[where][2] = bad
    before = pts.copy()
    with pytest.raises(ValueError, match="row 2"):
        tc.compensate_3d(pts, arrays["normals"], arrays["tool_axes"], R=3, R2=1, DR=-0.2, DR2=-0.05, out=pts)
    np.testing.assert_array_equal(pts, before)
    with pytest.raises(ValueError, match="finite"):
        tc.compensate_3d(pts, np.ones((4, 3)), R=3, R2=1, DR=np.nan)


def test_peripheral_milling_with_m128_uses_the_deltas_only():
    # CAM wrote the tool-centre path for the nominal tool; with RL and M128 the TNC displaces
    # it by sum DR only: an undersize of 0.2 moves the tool 0.2 towards the contour (right of +X).
    text = "\n".join(f"{i} {b}" for i, b in enumerate([
        "BEGIN PGM P MM", "TOOL DEF 1 L+0 R+5", "TOOL CALL 1 Z DR-0.2", "L X-10 Y+0 Z+0 R0 F500 M128",
        "L X+0 Y+0 RL", "L X+50 Y+0", "L X+60 Y+10 R0", "END PGM P MM"]))
    p = tc.run(tc.Program.parse(text, dialect="heidenhain"), start="machine_zero").path
    along = np.flatnonzero(p.line == 6)[-1]
    np.testing.assert_allclose(p.end[along, :2], [50, -0.2])


def test_tool_shape_from_the_radii():
    t = tc.ToolTable.parse("tool,radius,corner_radius,corner_radius_wear\n1,5,5,0\n2,5,1,0\n3,5,0,0\n4,5,4.9,0.1\n", "csv")
    assert [x.edge().shape for x in t] == ["ball", "toroid", "end_mill", "ball"]


def test_ln_tool_axis_of_zero_length():
    # TX TY TZ of zero length under M128 is refused (the tool axis came out as (0, 0, 0)).
    with pytest.raises(tc.ProgramError) as e:
        ln_program(["LN X+1 Y+0 Z+0 NX+0 NY+0 NZ+1 TX+0 TY+0 TZ+0 F100"], extra=" M128")
    assert e.value.code == "ln_tool_axis_zero" and e.value.line == 5


def test_tool_def_r2_at_most_r_and_contact_point_radii():
    with pytest.raises(tc.ProgramError) as e:
        ln_program([], tool="TOOL DEF 1 L+0 R+4 R2+5\nTOOL CALL 1 Z")
    assert e.value.code == "tool_def"
    res = ln_program(["LN X+1 Y+0 Z+0 NX+0 NY+0 NZ+1 F100"])
    for r, r2 in ((-4, 1), (1, 4), (np.nan, 1)):
        with pytest.raises(ValueError):
            res.path.contact_points(r, r2)
