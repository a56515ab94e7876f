"""Line ends of tool tables: LF, CRLF, a lone CR (classic Mac OS) and CR CR LF (a file
converted to CRLF twice) all end a line. A table read and written back unchanged keeps its
own line ends byte for byte; a changed tool rewrites only its own line, and a new tool is
written with the file's line end."""
import pathlib

import pytest

import toolcomp as tc

TABLES = pathlib.Path(__file__).resolve().parent.parent / "programs" / "tables"
FILES = [("mill.tbl", "linuxcnc"), ("tools.csv", "csv"), ("tools_edges.csv", "csv"), ("tnc426.t", "heidenhain")]
ENDS = ["\r", "\r\r\n"]


def _text(name):
    return (TABLES / name).read_bytes().decode("utf-8")


@pytest.mark.parametrize("eol", ENDS, ids=["cr", "cr-cr-lf"])
@pytest.mark.parametrize("name, fmt", FILES)
def test_same_tools_and_byte_identical_round_trip(name, fmt, eol):
    lf = _text(name)
    assert "\r" not in lf
    text = lf.replace("\n", eol)
    reference = tc.ToolTable.parse(lf, fmt)
    table = tc.ToolTable.parse(text, fmt)
    assert [t.number for t in table] == [t.number for t in reference]
    for t in reference:
        assert table[t.number] == t
    assert table.dumps(fmt) == text


@pytest.mark.parametrize("eol", ENDS, ids=["cr", "cr-cr-lf"])
@pytest.mark.parametrize("name, fmt", FILES)
def test_changed_and_new_tools_keep_the_line_end(name, fmt, eol):
    text = _text(name).replace("\n", eol)
    table = tc.ToolTable.parse(text, fmt)
    number = next(iter(table)).number
    tool = table[number]
    e = tool.edge()
    e.radius = e.radius + 0.5
    tool.set_edge(e)
    table.set(tool)
    table.set(tc.Tool(99, edges=[tc.CuttingEdge(radius=2.0)]))
    out = table.dumps(fmt)
    assert out.endswith(eol)
    if eol == "\r":
        assert "\n" not in out
    else:
        assert out.count("\n") == out.count(eol)
    lines_in = text.split(eol)
    lines_out = [l for l in out.split(eol) if not l.lstrip("T").startswith("99")]
    assert len(lines_out) == len(lines_in)
    changed = [i for i, (a, b) in enumerate(zip(lines_in, lines_out)) if a != b]
    assert len(changed) == 1, changed
    back = tc.ToolTable.parse(out, fmt)
    assert back[number].edge().radius == pytest.approx(e.radius)
    assert back[99].edge().radius == pytest.approx(2.0)


def test_cr_only_tbl_comment_does_not_swallow_the_next_tool():
    # Read as one line, T2 would sit inside T1's ';' comment and be lost.
    table = tc.ToolTable.parse("T1 P1 Z+25 D10 ;end mill\rT2 P2 Z30 D6 ;drill\r", "linuxcnc")
    assert [t.number for t in table] == [1, 2]
    assert table[1].comment == "end mill"
    assert table[2].edge().radius == pytest.approx(3.0)


def test_cr_only_csv_error_positions_count_cr_lines():
    with pytest.raises(tc.ToolTableError) as e:
        tc.ToolTable.parse("tool,diameter\r1,10\r2,x\r", "csv")
    assert (e.value.code, e.value.line, e.value.column) == ("csv_bad_number", 3, 3)


def test_a_tbl_comment_with_a_cr_cannot_be_written():
    table = tc.ToolTable.parse("T1 P1 D10\n", "linuxcnc")
    t = table[1]
    t.comment = "a\rb"
    table.set(t)
    with pytest.raises(tc.ToolTableError):
        table.dumps("linuxcnc")
