"""Sinumerik 840D tool data from Python: $TC_DP edges, tool lengths by plane, the $TC_DP file
form, GETTCOR, toolholders ($TC_CARR) and TRAFO5 (spec section 3; the C++ tests are
tests/cpp/test_sinumerik_lengths.cpp and test_sinumerik_toolholder.cpp)."""
import copy
import math

import numpy as np
import pytest

import toolcomp as tc
from toolcomp import sinumerik as sn


def milling_example():
    """Spec 3.2 worked example, T1 D1."""
    return sn.Edge({1: 120, 3: 120.0, 12: -0.15, 21: 10.0, 6: 6.0, 15: -0.02})


def is_vec3(v):
    return isinstance(v, np.ndarray) and v.dtype == np.float64 and v.shape == (3,)


def test_submodule_is_reexported():
    import toolcomp.sinumerik

    assert toolcomp.sinumerik is tc.sinumerik is tc._core.sinumerik
    assert "sinumerik" in tc.__all__


def test_spec_3_2_milling_example():
    e = milling_example()
    assert e.tool_type == 120
    assert e.length(1) == pytest.approx(129.85)
    assert e.radius() == pytest.approx(5.98)
    assert e.radius(0.5) == pytest.approx(6.48)  # OFFN allowance
    g17 = sn.tool_length(e, 17)
    assert is_vec3(g17)
    np.testing.assert_allclose(g17, [0, 0, 129.85], atol=1e-9)
    np.testing.assert_allclose(sn.tool_length(e, "G18"), [0, 129.85, 0], atol=1e-9)
    np.testing.assert_allclose(sn.tool_length(e, "g19"), [129.85, 0, 0], atol=1e-9)
    # SD42930 WEAR_SIGN inverts the wear: 120 + 0.15 + 10, 6 + 0.02.
    inv = sn.LengthSettings(wear_sign_inverted=True)
    assert inv.wear_sign == -1.0
    assert sn.tool_length(e, 17, inv)[2] == pytest.approx(130.15)
    assert e.radius(wear_sign=inv.wear_sign) == pytest.approx(6.02)


def test_turning_example_and_length_settings():
    e = sn.Edge({1: 500, 2: 3, 3: 50, 4: 100, 13: 0.1})
    assert e.cutting_edge_position == 3
    assert sn.is_turning_type(e.tool_type)
    np.testing.assert_allclose(sn.tool_length(e, 18), [50, 0, 100.1], atol=1e-9)  # X 50, Z 100.1
    assert sn.length_axes(500, 18) == (0, 2, 1)  # L1 -> X, L2 -> Z, L3 -> Y
    assert sn.length_axes(120, 17) == (2, 1, 0)
    assert sn.length_axes(120, 17, sn.LengthSettings(tool_length_const=18)) == (1, 0, 2)
    assert sn.length_axes(500, 18, sn.LengthSettings(tool_length_type=1)) == (1, 0, 2)
    np.testing.assert_allclose(sn.place_lengths([1, 2, 3], 120, "G17"), [3, 2, 1])
    with pytest.raises(tc.ToolTableError) as err:
        sn.length_axes(120, 17, sn.LengthSettings(tool_length_const=20))
    assert err.value.code == "sinumerik_bad_setting"
    with pytest.raises(ValueError):
        sn.tool_length(e, 20)
    with pytest.raises(ValueError):
        sn.tool_length(e, "G20")


def test_edge_values_and_views():
    e = milling_example()
    assert e.dp.shape == (25,) and e.dp.dtype == np.float64
    assert e.dp[2] == 120.0 and e.get_dp(3) == 120.0
    e.set_dp(3, 100.0)
    assert e.dp[2] == 100.0
    e.dp[11] = -0.25  # writable view: $TC_DP12
    assert e.get_dp(12) == -0.25
    e.scp[11] = 2.0  # $TC_SCP12 enters the total length
    assert e.get_scp(12) == 2.0
    assert e.length(1) == pytest.approx(100 - 0.25 + 2.0 + 10)
    c = copy.deepcopy(e)
    assert c == e
    c.dp[0] = 110
    assert c != e and e.tool_type == 120
    with pytest.raises(tc.ToolTableError) as err:
        e.get_dp(26)
    assert err.value.code == "sinumerik_bad_dp"
    with pytest.raises(tc.ToolTableError):
        sn.Edge({0: 1.0})
    with pytest.raises(tc.ToolTableError):
        e.length(4)


def test_gettcor_seed_example():
    # W1 manual: turning tool G18, MD20360 TOOL_PARAMETER_DEF_MASK = 3 (X as diameter):
    # _LEN[2] = Z = 4 + 13 = 17, [3] = X = (3 + 12) / 2 = 7.5, [4] = Y = 5 + 14 = 19.
    e = sn.Edge({1: 500, 2: 3, 3: 3, 4: 4, 5: 5, 12: 12, 13: 13, 14: 14})
    s = sn.GettcorSettings(plane=18, parameter_def_mask=3)
    assert s.plane == 18 and s.geometry_diameter and s.wear_diameter
    status, length = sn.gettcor(e, "GW", s)
    assert status == sn.GETTCOR_OK == 0
    assert isinstance(length, np.ndarray) and length.dtype == np.float64 and length.shape == (11,)
    assert (length[0], length[1]) == (500, 3)
    np.testing.assert_allclose(length[2:5], [17.0, 7.5, 19.0])
    # Case, blanks and a coordinate system change nothing here.
    status2, length2 = sn.gettcor(e, " g w : m ", s)
    assert status2 == 0 and np.array_equal(length2, length)
    # Without the diameter setting X is 3 + 12; plane= overrides the settings' plane.
    status, length = sn.gettcor(e, "GW", plane="G18")
    assert status == 0 and length[3] == pytest.approx(15.0)


def test_gettcor_components_status_and_table():
    e = milling_example()
    status, length = sn.gettcor(e, "G")
    assert status == 0 and length[4] == pytest.approx(120.0) and length[5] == pytest.approx(6.0)
    status, length = sn.gettcor(e, "GWC")
    assert status == 0 and length[4] == pytest.approx(129.85)
    status, length = sn.gettcor(e, "GG")
    assert status == sn.GETTCOR_BAD_COMP and not length.any()
    assert sn.gettcor(e, "G:X")[0] == sn.GETTCOR_BAD_COORD
    assert sn.gettcor(e, "G", stat="ENV1")[0] == sn.GETTCOR_NO_ENV_MEMORY
    assert sn.gettcor(e, "G", dl=2)[0] == sn.GETTCOR_BAD_DL
    table = {(1, 1): e, (1, 2): sn.Edge({1: 120, 3: 50})}
    status, length = sn.gettcor(table, 1, 2, "G")
    assert status == 0 and length[4] == pytest.approx(50.0)
    assert sn.gettcor(table, 1, 3, "G")[0] == sn.GETTCOR_BAD_D
    assert sn.gettcor(table, 2, 1, "G")[0] == sn.GETTCOR_BAD_T


TC_DP_TEXT = (
    "; tool data T1 D1\r\n"
    "N10 $TC_DP1[1,1]=120\r\n"
    "\r\n"
    "$TC_DP3[1,1]=120.0   ; geometry length 1\n"
    "$tc_dp12[1,1] = -0.15\n"
    "N20$TC_DP21[ 1 , 1 ]=10\n"
    "$TC_DP6[1,1]=6\n"
    "$TC_DP15[1,1]=-.02\n"
    "$TC_SCP13[1,1]=0.5\n"
    "$TC_DP1[2,3]=500\n"
    "M17\n"
)


def test_tc_dp_file_round_trip(tmp_path):
    edges = sn.parse_tool_data(TC_DP_TEXT)
    assert sorted(edges) == [(1, 1), (2, 3)]
    np.testing.assert_array_equal(edges[(1, 1)].dp, milling_example().dp)
    assert edges[(1, 1)].get_scp(13) == 0.5
    assert edges[(2, 3)].tool_type == 500
    assert edges[(1, 1)].length(1) == pytest.approx(129.85)
    text = sn.format_tool_data(edges)
    assert "$TC_DP12[1,1]=-0.15\n" in text
    assert "$TC_SCP13[1,1]=0.5\n" in text
    assert sn.parse_tool_data(text) == edges
    assert sn.format_tool_data(sn.parse_tool_data(text)) == text
    f = tmp_path / "tools.spf"
    f.write_text(text)
    assert sn.read_tool_data(f) == edges
    assert sn.read_tool_data(str(f)) == edges


@pytest.mark.parametrize(
    "text, code, line",
    [
        ("; x\n$TC_DP26[1,1]=1\n", "sinumerik_bad_dp", 2),
        ("$TC_DP1[1,1]=1\n$TC_DP3[1,1]=abc\n", "sinumerik_bad_line", 2),
        ("\n\n$TC_DP3[0,1]=1\n", "sinumerik_bad_tool", 3),
    ],
)
def test_tc_dp_file_errors(text, code, line):
    with pytest.raises(tc.ToolTableError) as err:
        sn.parse_tool_data(text)
    assert isinstance(err.value, tc.Error)
    assert (err.value.code, err.value.line) == (code, line)


def test_tc_dp_file_limits_and_missing_file(tmp_path):
    with pytest.raises(tc.ToolTableError) as err:
        sn.parse_tool_data("$TC_DP3[1,10]=1", max_t=99, max_d=9)
    assert (err.value.code, err.value.line, err.value.column) == ("sinumerik_bad_edge", 1, 11)
    with pytest.raises(tc.ToolTableError) as err:
        sn.read_tool_data(tmp_path / "missing.spf")
    assert err.value.code == "file_not_found"


def test_toolholder_type_p_zero_offset():
    # Spec 3.6 (W1 manual): type P, l4 = (0, 0, 15), B45 -> offset (10.607, 0, -4.393).
    h = sn.Toolholder("P", l4=(0, 0, 15), v1=(0, 1, 0), alpha1=45)
    assert h.kinematic_type == "P"
    off = h.table_zero_offset()
    assert is_vec3(off)
    np.testing.assert_allclose(off, [10.607, 0, -4.393], atol=1e-3)
    np.testing.assert_allclose(off, [15 * math.sin(math.radians(45)), 0, -15 * (1 - math.cos(math.radians(45)))],
                               atol=1e-12)
    # The manual's setting via $TC_CARRn: v1 = A (X) at 0, v2 = B (Y) at 45.
    ab = sn.Toolholder()
    ab.set_carr(23, "p")
    for n, v in zip(range(7, 15), [1, 0, 0, 0, 1, 0, 0, 45]):
        ab.set_carr(n, v)
    ab.set_carr(20, 15)
    ab.set_carr(21, "A")
    ab.set_carr(22, "B")
    assert (ab.kinematic_type, ab.axis1, ab.axis2, ab.alpha2) == ("P", "A", "B", 45.0)
    np.testing.assert_allclose(ab.table_zero_offset(), off, atol=1e-12)
    # A type P holder does not influence the tool length.
    np.testing.assert_allclose(h.resulting_tool_length([0, 0, 250]), [0, 0, 250])


def test_toolholder_type_t_lengths():
    # Spec 3.6 worked example type T: l1 = (-200,0,0), l3 = (-100,0,0), v1 = X, v2 = (-1,0,1)/sqrt2.
    h = sn.Toolholder(l1=(-200, 0, 0), l3=(-100, 0, 0), v1=(1, 0, 0), v2=np.array([-1, 0, 1]) / math.sqrt(2))
    assert h.kinematic_type == "T"
    res = h.resulting_tool_length([0, 0, 250])
    assert is_vec3(res)
    np.testing.assert_allclose(res, [-300, 0, 250], atol=1e-9)
    np.testing.assert_allclose(h.table_zero_offset(), [0, 0, 0], atol=1e-12)
    h.alpha1 = 90
    np.testing.assert_allclose(h.resulting_tool_length([0, 0, 250]), [-300, -250, 0], atol=1e-9)
    h.alpha1 = 0
    h.set_carr(25, 180)  # rotary axis offset adds to alpha2
    assert h.angle2 == 180
    np.testing.assert_allclose(h.resulting_tool_length([0, 0, 250]), [-450, 0, 100], atol=1e-9)
    # The edge's length vector feeds the holder.
    edge = sn.Edge({1: 120, 3: 250})
    h2 = copy.copy(h)
    h2.offset2 = 0
    np.testing.assert_allclose(h2.resulting_tool_length(sn.tool_length(edge, 17)), [-300, 0, 250], atol=1e-9)


def test_toolholder_errors():
    with pytest.raises(tc.CompensationError) as err:
        sn.Toolholder("X")
    assert err.value.code == "toolholder_bad_kinematic_type" and "14153" in str(err.value)
    h = sn.Toolholder()
    with pytest.raises(tc.CompensationError):
        h.kinematic_type = "Q"
    with pytest.raises(tc.CompensationError) as err:
        h.set_carr(41, 1.0)
    assert err.value.code == "toolholder_bad_field"
    with pytest.raises(tc.CompensationError):
        h.set_carr(23, 1.0)  # a text field


def test_trafo5_equals_toolholder():
    t = sn.Trafo5(24, base_tool=(0, 0, 40), joint_offset=(-200, 0, 0), joint_offset_part=(-100, 0, 0),
                  part_offset=(0, 0, 15), axis1=(1, 0, 0), axis2=np.array([-1, 0, 1]) / math.sqrt(2))
    tool = [0, 0, 250]
    np.testing.assert_allclose(t.tool_length(0, 0, tool), [-300, 0, 290], atol=1e-9)
    for typ, kind in ((24, "T"), (56, "M")):
        t.type = typ
        for a1 in (0.0, 30.0, -75.0):
            for a2 in (0.0, 45.0, 180.0):
                h = t.to_toolholder(a1, a2)
                assert isinstance(h, sn.Toolholder) and h.kinematic_type == kind
                np.testing.assert_allclose(h.resulting_tool_length(tool), t.tool_length(a1, a2, tool), atol=1e-9)
    t.type = 40
    with pytest.raises(tc.CompensationError) as err:
        t.to_toolholder(0, 0)
    assert err.value.code == "trafo5_bad_type"


@pytest.mark.parametrize("axes, what", [
    (((0, 0, 0), (0, 1, 0)), "TRAFO5_AXIS1 is zero"),
    (((1, 0, 0), (0, 0, 0)), "TRAFO5_AXIS2 is zero"),
    (((1, 0, 0), (2, 0, 0)), "parallel"),
    (((0, 0, 1), (0, 0, -3)), "parallel"),
    (((1, 0, 0), (0, math.nan, 1)), "not a number"),
])
def test_trafo5_machine_data_alarm_4342(axes, what):
    # spec 3.7: alarm 4342 for invalid transformation data (an axis vector zero, parallel axes).
    for typ in (24, 56):
        t = sn.Trafo5(typ, base_tool=(0, 0, 40), axis1=axes[0], axis2=axes[1])
        for call in (lambda: t.to_toolholder(0, 30), lambda: t.tool_length(30, 45, (0, 0, 100))):
            with pytest.raises(tc.CompensationError, match=what) as err:
                call()
            assert err.value.code == "4342"


def test_lentoax_gives_the_axes_of_the_length_components():
    # spec 3.2: standard milling in G17: _AXIND = (3, 2, 1), L1 -> Z, L2 -> Y, L3 -> X.
    status, axind, matrix = sn.lentoax(120, 17)
    assert status == 0 and axind == (3, 2, 1)
    np.testing.assert_array_equal(matrix, [[0, 0, 1], [0, 1, 0], [1, 0, 0]])
    # Turning tool in G18: L1 -> X, L2 -> Z, L3 -> Y (the turning table of 3.2).
    assert sn.lentoax(500, 18, coord="mcs")[1] == (1, 3, 2)
    # Milling in G19: L1 -> X, L2 -> Z, L3 -> Y.
    assert sn.lentoax(120, "G19")[1] == (1, 3, 2)
    # SD42940 = -17 for milling: Z X Y.
    assert sn.lentoax(120, 18, sn.LengthSettings(tool_length_const=-17))[1] == (3, 1, 2)
    assert sn.lentoax(120, 17, coord="XYZ")[0] == -1
