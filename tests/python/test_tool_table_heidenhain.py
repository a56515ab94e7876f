"""Heidenhain TOOL.T tables from Python: mapped values, lossless write-back, conversion."""
import pathlib

import pytest

import toolcomp as tc

TABLES = pathlib.Path(__file__).resolve().parent.parent / "programs" / "tables"


def test_read_tnc426_table_maps_values():
    table = tc.ToolTable.read(TABLES / "tnc426.t")
    assert table.format == "heidenhain"
    assert table.units == "mm"
    assert table.numbers == [0, 1, 2, 3, 5, 7, 12]

    t1 = table[1]
    assert (t1.name, t1.comment) == ("SCHAFTFRAESER_10", "SCHRUPPEN Z4")
    e = t1.edge()
    assert e.length[2] == 95.25 and e.length[0] == 0 and e.length[1] == 0
    assert (e.radius, e.corner_radius, e.radius_wear) == (5, 0, -0.02)
    assert e.effective_radius == pytest.approx(4.98)

    ball = table[2].edge()
    assert ball.radius == ball.corner_radius == 3
    assert ball.corner_radius_wear == 0.01

    torus = table[3].edge()
    assert (torus.radius, torus.corner_radius) == (8, 1.5)
    assert torus.length_wear[2] == 0.05 and torus.radius_wear == -0.015

    assert table[5].name == "BOHRER D8,5" and table[5].comment == ""
    assert table[7].edge().radius == 0 and table[7].comment == "GESPERRT"  # empty fields
    assert table[12].name == "FRÄSER_D20" and table[12].comment == "Ø20 HM"


@pytest.mark.parametrize("name", ["tnc426.t", "tnc426_inch.t"])
def test_write_back_is_byte_identical(tmp_path, name):
    src = TABLES / name
    table = tc.ToolTable.read(src)
    out = tmp_path / "TOOL.T"  # upper-case suffix
    table.write(out)
    assert out.read_bytes() == src.read_bytes()
    assert table.dumps("heidenhain").encode("utf-8") == src.read_bytes()


def test_inch_table_from_its_begin_line():
    table = tc.ToolTable.read(TABLES / "tnc426_inch.t", units="mm")  # the file's INCH wins
    assert table.units == "inch"
    e = table[1].edge()
    assert e.length[2] == pytest.approx(3.75 * 25.4)
    assert e.radius == pytest.approx(6.35)
    assert e.radius_wear == pytest.approx(-0.0005 * 25.4)


def test_changed_tool_rewrites_only_its_row(tmp_path):
    path = tmp_path / "tool.t"
    path.write_bytes((TABLES / "tnc426.t").read_bytes())
    table = tc.ToolTable.read(path, format="t")
    tool = table[2]
    e = tool.edge()
    e.radius_wear = -0.01
    tool.set_edge(e)
    table.set(tool)
    table.write(path)
    before = (TABLES / "tnc426.t").read_text(encoding="utf-8").splitlines()
    after = path.read_text(encoding="utf-8").splitlines()
    assert len(after) == len(before)
    assert [i for i in range(len(before)) if before[i] != after[i]] == [4]
    assert after[4] == before[4][:66] + "-0.01 " + before[4][72:]
    assert tc.ToolTable.read(path)[2] == tool


def test_write_heidenhain_from_tbl(tmp_path):
    tbl = tmp_path / "mill.tbl"
    tbl.write_text("T1 P1 Z+25.000000 D+10.000000 ;10 mm end mill\nT2 P2 Z30.5 D6\n")
    table = tc.ToolTable.read(tbl)
    out = tmp_path / "y.t"
    table.write(out, format="heidenhain")
    text = out.read_bytes().decode("utf-8")
    lines = text.split("\r\n")
    assert lines[0] == "BEGIN TOOL .T MM"
    assert lines[1].split()[:8] == ["T", "NAME", "L", "R", "R2", "DL", "DR", "DR2"]
    assert lines[2].startswith("1                     +25         +5          +0")
    assert lines[-2:] == ["[END]", ""]
    back = tc.ToolTable.read(out)
    assert back.format == "heidenhain"
    assert back[1].edge().length[2] == 25 and back[1].edge().radius == 5
    assert back[1].comment == "10 mm end mill"
    assert back[1].pocket == 0  # TOOL.T has no pocket column
    assert back[2].edge().radius == 3

    # mill.tbl's tool 3 has X/Y offsets a TOOL.T cannot hold: refused, nothing written.
    with pytest.raises(tc.ToolTableError) as err:
        tc.ToolTable.read(TABLES / "mill.tbl").write(tmp_path / "z.t")
    assert err.value.code == "heidenhain_unrepresentable"
    assert not (tmp_path / "z.t").exists()


def test_csv_round_trip_keeps_mapped_data():
    table = tc.ToolTable.read(TABLES / "tnc426.t")
    via_csv = tc.ToolTable.parse(table.dumps("csv"), "csv")
    back = tc.ToolTable.parse(via_csv.dumps("heidenhain"), "heidenhain")
    assert list(back) == list(table)


def test_errors_have_code_and_position():
    text = "BEGIN TOOL .T MM\nT    NAME        L\n1    A           +5x\n[END]\n"
    with pytest.raises(tc.ToolTableError) as err:
        tc.ToolTable.parse(text, "heidenhain")
    assert err.value.code == "heidenhain_bad_number"
    assert (err.value.line, err.value.column) == (3, 18)
    with pytest.raises(tc.ToolTableError) as err:
        tc.ToolTable.parse("BEGIN TOOL .T MM\nT    NAME\n1    A\n", "heidenhain")
    assert err.value.code == "heidenhain_missing_end"
    with pytest.raises(tc.ToolTableError) as err:
        tc.ToolTable.parse("BEGIN TOOL .T MM\nT    NAME\n5.1  A\n[END]\n", "t")
    assert err.value.code == "heidenhain_tool_index_unsupported"


def locked_table(tl, rt):
    """tnc426.t with tool 1's TL and RT fields set (written at their columns)."""
    lines = (TABLES / "tnc426.t").read_text().split("\n")
    header = lines[1]
    row = next(i for i, line in enumerate(lines) if line.startswith("1 "))
    text = list(lines[row])
    for title, value in (("TL", tl), ("RT", rt)):
        col = header.index(" " + title + " ") + 1
        text[col:col + len(value)] = value
    lines[row] = "".join(text)
    return tc.ToolTable.parse("\n".join(lines), "heidenhain")


@pytest.mark.parametrize("rt, tail", [("2", "replacement tool 2 (RT) is not modelled"), ("", "no replacement tool")])
def test_a_locked_tool_is_refused(rt, tail):
    # TL = L: the control does not use the tool; toolcomp never cuts with its data.
    table = locked_table("L", rt)
    prog = "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z\n2 L X+0 Y+0 Z+10 R0 FMAX\n3 END PGM T MM\n"
    with pytest.raises(tc.ProgramError) as e:
        tc.run(tc.Program.parse(prog, "heidenhain"), tools=table, start="machine_zero")
    assert e.value.code == "tool_locked" and e.value.line == 2 and tail in e.value.message  # file line 2
    ok = tc.run(tc.Program.parse(prog.replace("CALL 1", "CALL 2"), "heidenhain"), tools=table, start="machine_zero")
    assert ok.path.tool[-1] == 2
    unlocked = tc.run(tc.Program.parse(prog, "heidenhain"), tools=locked_table(" ", rt), start="machine_zero")
    assert unlocked.path.tool[-1] == 1
