"""The Sinumerik tool data file ($TC_DP...=, suffix .ini) as a tool table of the common model:
mapping, lossless writing, and its use by Sinumerik programs. Numbers from spec 3.2."""
import numpy as np
import pytest

import toolcomp as tc

INI = (
    "; tool data\r\n"
    "$TC_DP1[1,1]=120\r\n$TC_DP3[1,1]=120\r\n$TC_DP12[1,1]=-0.15\r\n$TC_DP21[1,1]=10\r\n"
    "$TC_DP6[1,1]=6\r\n$TC_DP15[1,1]=-0.02\r\n"
    "$TC_DP1[1,2]=120\r\n$TC_DP3[1,2]=80\r\n$TC_DP6[1,2]=4\r\n"
    "\r\n"
    "$TC_DP1[2,1]=500\r\n$TC_DP2[2,1]=3\r\n$TC_DP3[2,1]=50\r\n$TC_DP4[2,1]=100\r\n$TC_DP13[2,1]=0.1\r\n"
    "$TC_DP6[2,1]=0.8\r\n"
    "M17\r\n"
)


@pytest.fixture
def ini(tmp_path):
    p = tmp_path / "TO_INI.INI"
    p.write_bytes(INI.encode())
    return p


def test_mapping_to_the_common_model(ini):
    t = tc.ToolTable.read(ini)
    assert t.format == "sinumerik"
    e1 = t.get(1).edge(1)
    # L1 = 120 + 10 (adapter) on z, wear -0.15; R = 6 - 0.02
    np.testing.assert_allclose(e1.length, [0, 0, 130])
    np.testing.assert_allclose(e1.length_wear, [0, 0, -0.15])
    assert e1.radius == 6 and e1.radius_wear == pytest.approx(-0.02)
    assert t.get(1).edge(2).radius == 4
    lathe = t.get(2).edge(1)
    # turning type 500: L1 on X, L2 on Z (G18), tip 3
    np.testing.assert_allclose(lathe.length, [50, 0, 100])
    np.testing.assert_allclose(lathe.length_wear, [0, 0, 0.1])
    assert lathe.orientation == 3


def test_unchanged_table_writes_back_byte_identical(ini, tmp_path):
    t = tc.ToolTable.read(ini)
    out = tmp_path / "copy.ini"
    t.write(out)
    assert out.read_bytes() == ini.read_bytes()


def test_changed_tool_rewritten_in_place_keeping_what_the_model_does_not_carry(ini, tmp_path):
    t = tc.ToolTable.read(ini)
    tool = t.get(1)
    e = tool.edge(1)
    e.radius = 6.5
    tool.set_edge(e)
    t.set(tool)
    t.remove(2)
    new = tc.Tool(number=9)
    ne = new.edges[0]
    ne.radius = 2
    ne.length = [0, 0, 55]
    new.edges = [ne]
    t.set(new)
    out = tmp_path / "out.ini"
    t.write(out)
    text = out.read_bytes().decode()
    assert text.startswith("; tool data\r\n")
    assert "$TC_DP1[2,1]" not in text and "M17\r\n" in text
    edges = tc.sinumerik.parse_tool_data(text)
    assert edges[(1, 1)].get_dp(6) == 6.5
    assert edges[(1, 1)].get_dp(21) == 10 and edges[(1, 1)].get_dp(3) == 120  # adapter split kept
    assert edges[(1, 2)].get_dp(6) == 4
    assert edges[(9, 1)].get_dp(1) == 120 and edges[(9, 1)].get_dp(3) == 55


def test_programs_use_the_file_by_plane_and_tool_type(ini):
    # Spec 3.2: the milling tool's L1 = 129.85 on Z in G17, Y in G18; the turning tool in
    # G18: X 50, Z 100.1.
    t = tc.ToolTable.read(ini)
    prog = "T1 M6\nG17 G0 X0\nG18 X1\nT2 M6\nX2\nM30\n"
    res = tc.run(tc.Program.parse(prog, dialect="sinumerik"), t)
    off = res.nominal.tool_offset
    np.testing.assert_allclose(off[0], [0, 0, 129.85], atol=1e-12)
    np.testing.assert_allclose(off[1], [0, 129.85, 0], atol=1e-12)
    np.testing.assert_allclose(off[2], [50, 0, 100.1], atol=1e-12)
