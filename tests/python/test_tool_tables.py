"""Tool tables from Python: LinuxCNC .tbl, CSV and JSON, read/write losslessly."""
import copy
import os
import pathlib
import stat

import numpy as np
import pytest

import toolcomp as tc

TABLES = pathlib.Path(__file__).resolve().parent.parent / "programs" / "tables"


def test_read_stock_lathe_table_in_inch():
    table = tc.ToolTable.read(TABLES / "lathe.tbl", units="inch")
    assert len(table) == 10
    assert table.units == "inch"
    assert table.format == "linuxcnc"
    t1 = table[1]
    assert t1.pocket == 1
    e = t1.edge()
    assert e.radius == pytest.approx(1.27)  # D0.1 inch is the diameter
    assert isinstance(e.length, np.ndarray) and e.length.dtype == np.float64 and e.length.shape == (3,)
    np.testing.assert_allclose(e.length, [0, 0, 2.54])
    assert (e.front_angle, e.back_angle, e.orientation) == (95, 155, 1)
    assert table[10].comment == "demo zero diameter"
    assert [t.number for t in table] == list(range(1, 11))
    assert 6 in table and 11 not in table
    assert table.get(11) is None


@pytest.mark.parametrize("name, fmt", [("lathe.tbl", "linuxcnc"), ("mill.tbl", "tbl"),
                                       ("tools.csv", "csv"), ("tools_edges.csv", "csv"),
                                       ("tools.json", "json")])
def test_round_trip_is_byte_identical(tmp_path, name, fmt):
    src = TABLES / name
    table = tc.ToolTable.read(src)
    out = tmp_path / name
    table.write(out)
    assert out.read_bytes() == src.read_bytes()
    assert table.dumps(fmt) == src.read_bytes().decode("utf-8")
    crlf = src.read_bytes().decode("utf-8").replace("\n", "\r\n")
    assert tc.ToolTable.parse(crlf, fmt).dumps(fmt) == crlf


def test_changed_tool_rewrites_only_its_line(tmp_path):
    path = tmp_path / "lathe.tbl"
    path.write_bytes((TABLES / "lathe.tbl").read_bytes())
    table = tc.ToolTable.read(path, units="inch")
    tool = table[6]
    e = tool.edge()
    e.length = (0.5 * 25.4, 0, 0.6 * 25.4)
    tool.set_edge(e)
    table.set(tool)
    table.write(path)
    before = (TABLES / "lathe.tbl").read_text().splitlines()
    after = path.read_text().splitlines()
    assert after[5] == "T6 P6 D+0.100000 X+0.500000 Z+0.600000 I+120.000000 J+60.000000 Q6 ;"
    assert after[:5] == before[:5] and after[6:] == before[6:]


def test_values_are_copies_until_set():
    table = tc.ToolTable.parse("T1 P1 D6 ;x\n", "linuxcnc")
    table[1].comment = "lost"  # a copy: the table is unchanged
    assert table[1].comment == "x"
    with pytest.raises(ValueError):
        table[1].edge().length[2] = 5.0  # read-only view, no silent loss
    tool = table[1]
    tool.comment = "kept"
    table.set(tool)
    assert table.dumps("linuxcnc") == "T1 P1 D+6.000000 ;kept\n"  # changed: canonical spelling


def test_new_tool_and_remove():
    table = tc.ToolTable.parse("T1 P1 D6\nT2 P2 D8\n", "tbl")
    edge = tc.CuttingEdge(radius=2.5, length=(0, 0, 42), orientation=0)
    table.set(tc.Tool(7, pocket=3, comment="drill", edges=[edge]))
    assert table.remove(1) is True
    assert table.remove(1) is False
    assert table.dumps("tbl") == "T2 P2 D8\nT7 P3 D+5.000000 Z+42.000000 ;drill\n"


def test_multi_edge_tools_and_wear():
    table = tc.ToolTable.read(TABLES / "tools_edges.csv")
    t = table[10]
    assert len(t.edges) == 2
    assert t.edge(2).effective_radius == pytest.approx(2.51)
    np.testing.assert_allclose(t.edge(2).effective_length, [0, 0, 95.48])
    with pytest.raises(tc.ToolTableError) as err:
        t.edge(5)
    assert err.value.code == "tool_no_such_edge"
    # LinuxCNC tables have one edge and no wear: converting refuses instead of dropping data.
    with pytest.raises(tc.ToolTableError) as err:
        table.dumps("linuxcnc")
    assert err.value.code == "tbl_unrepresentable"


def test_conversion_keeps_all_data(tmp_path):
    lathe = tc.ToolTable.read(TABLES / "lathe.tbl", units="inch")
    lathe.write(tmp_path / "lathe.csv")
    lathe.write(tmp_path / "lathe.json")
    from_csv = tc.ToolTable.read(tmp_path / "lathe.csv", units="inch")
    from_json = tc.ToolTable.read(tmp_path / "lathe.json")  # "units": "inch" in the file
    assert from_json.units == "inch"
    for a, b, c in zip(lathe, from_csv, from_json):
        assert a == b == c
    back = tmp_path / "back.tbl"
    from_json.write(back)
    assert list(tc.ToolTable.read(back, units="inch")) == list(lathe)

    multi = tc.ToolTable.read(TABLES / "tools.json")
    assert list(tc.ToolTable.parse(multi.dumps("csv"), "csv")) == list(multi)


@pytest.mark.parametrize("text, fmt, code, line, column", [
    ("T1 P1 D6\nT2 P2 K5 ;x\n", "tbl", "tbl_bad_word", 2, 7),
    ("T1 P1 Xabc\n", "tbl", "tbl_bad_number", 1, 7),
    ("T1 P1\n\nT1 P9\n", "tbl", "tbl_duplicate_tool", 3, 1),
    ("T1 P1 Q10\n", "tbl", "tbl_bad_orientation", 1, 7),
    ("tool,z\n1,2\n2,x\n", "csv", "csv_bad_number", 3, 3),
    ("tool,z\n1,2\n1,3\n", "csv", "csv_duplicate_tool", 3, 1),
    ('{"tools": [\n {"tool": 1,}\n]}', "json", "json_syntax", 2, 13),
    ('{"tools": [{"tool": 1}, {"tool": 1}]}', "json", "json_duplicate_tool", 1, 34),
])
def test_errors_have_code_and_position(text, fmt, code, line, column):
    with pytest.raises(tc.ToolTableError) as err:
        tc.ToolTable.parse(text, fmt)
    assert isinstance(err.value, tc.Error)
    assert (err.value.code, err.value.line, err.value.column) == (code, line, column)


def test_format_and_unit_arguments(tmp_path):
    with pytest.raises(tc.ToolTableError):
        tc.ToolTable.read(tmp_path / "tools.xyz")
    with pytest.raises(tc.ToolTableError):
        tc.ToolTable.parse("T1", "linuxcnc", units="cm")
    p = tmp_path / "tools.txt"
    p.write_text("T1 P1 D0.1\n")
    t = tc.ToolTable.read(str(p), format="tbl", units="inch")
    assert t[1].edge().radius == pytest.approx(1.27)
    t.units = "mm"  # a new unit rewrites every tool
    assert t.dumps("tbl") == "T1 P1 D+2.540000\n"


def test_write_replaces_the_file_and_keeps_its_mode(tmp_path):
    path = tmp_path / "tools.tbl"
    path.write_text("T1 P1 D6\n")
    os.chmod(path, 0o640)
    table = tc.ToolTable.read(path)
    tool = table[1]
    tool.pocket = 2
    table.set(tool)
    table.write(path)
    assert path.read_text() == "T1 P2 D+6.000000\n"
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tools.tbl"]


def test_copies():
    table = tc.ToolTable.read(TABLES / "mill.tbl")
    other = copy.deepcopy(table)
    other.remove(1)
    assert len(table) == 8 and len(other) == 7
    assert table.dumps("tbl") == (TABLES / "mill.tbl").read_text()
