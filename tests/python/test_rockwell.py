"""Allen-Bradley 9/Series lathe (dialect "rockwell"): T-word formats, geometry + wear offset
tables, tool tip radius compensation (TTRC) started in one, two or three blocks, and the
TTRC errors, each at its line. Facts from the 9/Series lathe manual (spec §5, seed 003)."""
import numpy as np
import pytest

import toolcomp as tc

# Offset tables: geometry X/Z (radius mm), nose radius, tip (orientation); wear columns.
TABLE = """tool,x,z,radius,orientation,x_wear,z_wear,radius_wear,comment
2,-1.0,2.0,0.4,3,0,0,0,geometry 2
13,0,0,0,0,0.05,-0.02,0.01,wear 13
16,-0.5,1.5,0.8,3,0.1,0.2,0.02,geometry and wear 16
"""


def rw(text, t_format=None, strict=True):
    prof = tc.ControlProfile("rockwell")
    if t_format is not None:
        prof.t_format = t_format
    return tc.run(tc.Program.parse(text, dialect="rockwell"), tools=tc.ToolTable.parse(TABLE, "csv"),
                  profile=prof, strict=strict)


def test_t_word_format_5_tool_geometry_wear():
    # Format 5 (2 DGT WEAR): T213 is tool 2, geometry 2, wear 13 (the manual's example).
    res = rw("G21 G18\nT213\nG0 X20 Z5\nM30\n", t_format=5)
    assert res.path.tool[0] == 2
    np.testing.assert_allclose(res.path.tool_offset[0], [-1.0 + 0.05, 0, 2.0 - 0.02])


def test_t_word_format_2_geometry_and_wear_from_the_same_number():
    res = rw("G21 G18\nT0016\nG0 X20 Z5\nM30\n")
    assert res.path.tool[0] == 0
    np.testing.assert_allclose(res.path.tool_offset[0], [-0.5 + 0.1, 0, 1.5 + 0.2])


START_FORMS = {
    "one block": "G42 T0016 X1 Z1;\n",
    "two blocks": "T0016;\nG42 X1 Z1;\n",
    "three blocks": "T0016;\nG42;\nX1 Z1;\n",
}
BODY = "G1 Z-10 F100;\nG1 X12 Z-15;\nG1 X14;\nG40 G0 X20 Z5;\nM30;\n"


def test_the_three_ways_to_start_ttrc_give_the_same_path():
    paths = {}
    for name, start in START_FORMS.items():
        res = rw("G20 G18 G0 X0 Z3;\n" + start + BODY)
        p = res.path
        on = p.side != 0
        assert on.any(), name
        paths[name] = (p.kind[on], p.end[on], p.side[on])
    ref = paths["one block"]
    for name, got in paths.items():
        assert (got[0] == ref[0]).all() and (got[2] == ref[2]).all(), name
        np.testing.assert_allclose(got[1], ref[1], atol=1e-12, err_msg=name)


def error_of(text):
    with pytest.raises(tc.Error) as e:
        rw(text)
    return e.value


def test_ttrc_entry_and_exit_must_be_linear():
    e = error_of("G21 G18 G0 X20 Z5\nT0016\nG42 G2 X20 Z-5 R10 F100\nM30\n")
    assert (e.message, e.line) == ("Block format error: TTRC entry in a circular block", 3)
    e = error_of("G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nZ-10\nG40 G2 X30 Z-15 R5\nM30\n")
    assert (e.message, e.line) == ("Block format error: TTRC exit in a circular block", 5)


# A groove 0.5 mm wide and 0.5 mm deep (radius) under a nose of radius 0.82: its bottom's
# compensated move would run backwards.
NARROW_STEP = "G21 G18 G0 X40 Z5\nT0016\nG42 G1 X40 Z0 F100\nG1 Z-10\nG1 X39\nG1 Z-10.5\nG1 X40\nG1 Z-20\n{m}G40 G0 X60 Z5\nM30\n"


def test_backwards_motion_is_an_error_unless_m800():
    e = error_of(NARROW_STEP.format(m=""))
    assert (e.message, e.line) == ("Backwards motion: the compensated move runs against the programmed move", 7)
    # M800 switches the check off: the control runs the path and toolcomp warns.
    res = rw("M800\n" + NARROW_STEP.format(m=""))
    assert res.ok and any(d.code == "comp_gouge" and d.severity == "warning" for d in res.diagnostics)
    # M801 switches it on again.
    with pytest.raises(tc.CompensationError):
        rw("M800\nM801\n" + NARROW_STEP.format(m=""))


def test_circular_departure_too_small_is_never_switchable():
    text = "M800\nG21 G18 G0 X40 Z5\nT0016\nG42 G1 X40 Z0 F100\nG1 Z-10\nG2 X40 Z-10.6 R0.3\nG1 Z-20\nM30\n"
    e = error_of(text)
    assert (e.message, e.line) == ("Circular departure too small: the tool radius does not fit the arc", 6)


def test_g10_during_ttrc():
    e = error_of("G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nG10 L2 P2 X1\nM30\n")
    assert (e.message, e.line) == ("G10 is not allowed while TTRC is active", 4)


def test_t00_continues_with_radius_zero():
    res = rw("G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nG1 Z-10\nT0000\nG1 Z-20\nG1 X30\nM30\n")
    assert res.ok
    p = res.path
    last = np.flatnonzero(p.line == 7)[-1]
    np.testing.assert_allclose(p.end[last][[0, 2]], [15, -20])  # uncompensated again
    assert p.side[last] == 1 or p.side[last] == -1  # still in TTRC, with radius 0


def test_exit_modified_with_i_k():
    # Along -Z at radius 10 (X20) under G42 (nose radius 0.82), then G40 towards (X30, Z-12).
    # Plain exit: the last move ends perpendicular at (x 10.82, z -10). With I1 K-1 (the
    # contour taken to go on towards +X -Z, an inside corner for G42) the Z move is pulled
    # back to that direction's equidistant: z = -10 + 0.82 tan(22.5 deg).
    base = "G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nZ-10\nG40 X30 Z-12{ik}\nM30\n"
    plain = rw(base.format(ik=""))
    mod = rw(base.format(ik=" I1 K-1"))
    r = 0.82
    z_move = np.flatnonzero(plain.path.line == 4)[-1]
    # the tip (tip 3, Fanuc) is the nose centre shifted by (-r, -r) in (X, Z)
    np.testing.assert_allclose(plain.path.end[z_move][[0, 2]], [10 + r - r, -10 - r])
    k = np.flatnonzero(mod.path.line == 4)[-1]
    np.testing.assert_allclose(mod.path.end[k][[0, 2]], [10, -10 + r * np.tan(np.pi / 8) - r])
    np.testing.assert_allclose(mod.path.end[-1][[0, 2]], [15, -12])


def test_exit_direction_words_are_a_setting():
    # Without the setting I/K in a G40 block have no code to use them, as on LinuxCNC.
    text = "G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nZ-10\nG40 X30 Z-12 I1 K-1\nM30\n"
    prof = tc.ControlProfile("rockwell")
    assert prof.radius.exit_direction_words
    prof.radius.exit_direction_words = False
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text, dialect="rockwell"), tools=tc.ToolTable.parse(TABLE, "csv"), profile=prof)
    assert e.value.code == "unused_word" and e.value.line == 5


@pytest.mark.parametrize("change", ["G55", "G92 Z-10"])
def test_a_work_offset_change_exits_and_enters_again(change):
    # spec 5.3: a change of the work coordinate system under TTRC uses the last move as an
    # exit and the first move in the new system as an entry. Along -Z at radius 20 under G42
    # with a nose radius of 1 (tip 3: the centre shifted by (-1, -1)), then out along +X at
    # Z-20. Z-10 ends perpendicular: centre (21, -10). Z-20 is a type A entry: it ends
    # perpendicular to the X move at its start, centre (20, -19), where the tool would
    # otherwise have run on at radius 21 to the inside corner (21, -19).
    text = f"G21 G18 G54 G0 X50 Z5\nT0001\nG42 G1 X40 Z0 F0.2\nZ-10\n{change}\nZ-20\nX50\nG40 G0 X80 Z5\nM30\n"
    table = tc.ToolTable.parse("tool,edge,x,z,radius,orientation\n1,1,0,0,1,3\n", "csv")
    p = tc.run(tc.Program.parse(text, "rockwell"), tools=table, profile=tc.ControlProfile("rockwell")).path
    tip = p.end[:, [0, 2]]
    np.testing.assert_allclose(tip[np.flatnonzero(p.line == 4)[-1]], [21 - 1, -10 - 1], atol=1e-9)
    np.testing.assert_allclose(tip[np.flatnonzero(p.line == 6)[-1]], [20 - 1, -19 - 1], atol=1e-9)
    np.testing.assert_allclose(tip[np.flatnonzero(p.line == 7)[-1]], [25 - 1, -19 - 1], atol=1e-9)
    # LinuxCNC and Fanuc refuse the change instead.
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(text.replace("T0001", "T1 M6\nG43 H1"), "fanuc"),
               tools=tc.ToolTable.parse("T1 P1 D2 Z0\n", "linuxcnc"))
    assert e.value.code in ("comp_coord_system", "comp_axis_offsets") and e.value.line == 6


def test_extension_blocks_and_the_minimum_length_rule():
    # An acute outside corner for G42: along -Z, then back out towards +Z and smaller X (a
    # left turn of 167.5 degrees): three extension blocks.
    text = "G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nG1 Z-10\nG1 X16 Z-1\nG40 G0 X40 Z5\nM30\n"
    full = rw(text)
    gen = full.path.generated
    assert gen.sum() == 3
    prof = tc.ControlProfile("rockwell")
    prof.radius.extension_min_length = 5.0
    short = tc.run(tc.Program.parse(text, dialect="rockwell"), tools=tc.ToolTable.parse(TABLE, "csv"), profile=prof)
    assert short.path.generated.sum() == 2  # the middle block is dropped, the last re-aimed
    np.testing.assert_allclose(short.path.end[short.path.generated][-1], full.path.end[gen][-1])


@pytest.mark.parametrize("fmt, word, tool, geometry, wear", [
    (1, 213, 21, 3, 3), (2, 213, 2, 13, 13), (3, 2013, 2, 13, 13),
    (4, 213, 21, 21, 3), (5, 213, 2, 2, 13), (6, 2013, 2, 2, 13),
])
def test_all_six_t_word_formats(fmt, word, tool, geometry, wear):
    # Offsets n carry geometry X = -n/10 and wear Z = n/100, so the sums show which were used.
    rows = "tool,x,z,radius,orientation,x_wear,z_wear,radius_wear\n" + "".join(
        f"{n},{-n / 10},0,0.4,3,0,{n / 100},0\n" for n in sorted({3, 13, 21, 2}))
    prof = tc.ControlProfile("rockwell")
    prof.t_format = fmt
    res = tc.run(tc.Program.parse(f"G21 G18\nT{word}\nG0 X20 Z5\nM30\n", dialect="rockwell"),
                 tools=tc.ToolTable.parse(rows, "csv"), profile=prof)
    assert res.path.tool[0] == tool
    np.testing.assert_allclose(res.path.tool_offset[0], [-geometry / 10, 0, wear / 100])


def test_side_and_radius_change_in_a_circular_block():
    base = "G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\nG1 Z-10\n{arc}\nG1 Z-30\nG40 G0 X40 Z5\nM30\n"
    res = rw(base.format(arc="G41 G2 X20 Z-20 R5"))  # G41 in a circular block: side changes
    arc = np.flatnonzero((res.path.line == 5) & ~res.path.generated)
    assert (res.path.side[arc] == 1).all()
    res = rw(base.format(arc="T0002 G2 X20 Z-20 R5"))  # T word in a circular block: radius 0.4
    assert res.ok


def test_interference_is_switchable():
    # A small arc (R 0.9 against a nose of 0.82, tool outside) and a line going straight back:
    # the compensated elements do not meet (interference), unless M800 switches the check off.
    text = "{m}G21 G18 G0 X40 Z5\nT0016\nG42 G1 X40 Z0 F100\nG1 Z-10\nG2 U1 W-0.5 R0.9\nG1 U-1 W0.5\nG1 W-20\nM30\n"
    with pytest.raises(tc.CompensationError) as e:
        rw(text.format(m=""))
    assert (e.value.message, e.value.line) == ("Interference: the compensation vectors cross", 6)
    res = rw(text.format(m="M800\n"))
    assert res.ok and any(d.code == "comp_gouge" and d.severity == "warning" for d in res.diagnostics)


def test_threading_during_ttrc_is_refused_at_its_line():
    for cycle in ("G33 Z-20 K1.5", "G76 Z-20 K1.5"):
        e = error_of(f"G21 G18 G0 X20 Z5\nT0016\nG42 G1 X20 Z0 F100\n{cycle}\nM30\n")
        assert e.line == 4 and e.code == "unsupported_g_code"
