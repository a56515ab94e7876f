"""ToolTable.to_pandas / from_pandas / diff: bulk edits keep comments and unknown columns, and
a save changes only the edited lines."""
import math
import pathlib

import numpy as np
import pytest

import toolcomp as tc

pd = pytest.importorskip("pandas")
ROOT = pathlib.Path(__file__).resolve().parents[2]
TBL = "T1 P1 D10 Z50 ;end mill 10\nT2 P2 D6.8 Z75 ;drill 6.8\nT3 P3 D12 Z62.5 ;spot drill\n"


def test_to_pandas_has_one_row_per_edge_with_the_table_values():
    df = tc.ToolTable.parse(TBL, "linuxcnc").to_pandas()
    assert list(df.tool) == [1, 2, 3]
    assert list(df.z) == [50.0, 75.0, 62.5]
    assert list(df.radius) == [5.0, 3.4, 6.0]  # D is the diameter in .tbl
    assert list(df.comment) == ["end mill 10", "drill 6.8", "spot drill"]


def test_bulk_edit_through_pandas_changes_only_the_edited_lines(tmp_path):
    path = tmp_path / "tool.tbl"
    path.write_text(TBL)
    table = tc.ToolTable.read(path)
    df = table.to_pandas()
    df.loc[df.tool == 2, "z"] += 0.25      # measured 0.25 longer
    df.loc[df.tool == 3, "radius"] = 5.99  # reground
    edited = tc.ToolTable.from_pandas(df[df.tool != 1], base=table)
    changes = table.diff(edited)
    assert [(c.tool, c.field, c.old, c.new) for c in changes] == [(2, "z", 75.0, 75.25), (3, "radius", 6.0, 5.99)]
    edited.write(path)
    lines = path.read_text().splitlines()
    assert lines[0] == "T1 P1 D10 Z50 ;end mill 10"  # untouched tool: byte-identical line
    assert "Z+75.25" in lines[1] and lines[1].endswith(";drill 6.8")
    assert "D+11.98" in lines[2]
    assert table.diff(table) == []
    # .tbl has no wear columns: such an edit is refused at the save, the file is untouched.
    df.loc[df.tool == 3, "radius_wear"] = -0.01
    before = path.read_bytes()
    with pytest.raises(tc.ToolTableError):
        tc.ToolTable.from_pandas(df, base=table).write(path)
    assert path.read_bytes() == before


def test_from_pandas_without_base_builds_a_table_and_diff_sees_added_and_removed():
    df = pd.DataFrame({"tool": [7, 8], "pocket": [7, 8], "z": [40.0, 30.0], "radius": [2.0, 0.4],
                       "orientation": [0, 3], "comment": ["drill", "insert"]})
    t = tc.ToolTable.from_pandas(df)
    assert t[8].edge().orientation == 3 and t[7].edge().length[2] == 40.0 and t[8].comment == "insert"
    base = tc.ToolTable.parse(TBL, "linuxcnc")
    changes = base.diff(t)
    assert [(c.tool, c.field) for c in changes] == [(1, "removed"), (2, "removed"), (3, "removed"),
                                                    (7, "added"), (8, "added")]
    with pytest.raises(ValueError, match="'tool' column"):
        tc.ToolTable.from_pandas(pd.DataFrame({"z": [1.0]}))


@pytest.mark.parametrize("col, val, what", [
    ("tool", 1.7, "whole number"), ("orientation", 2.7, "whole number"), ("edge", 2.9, "whole number"),
    ("pocket", 2.5, "whole number"), ("z", math.inf, "finite"), ("radius", "abc", "not a number"),
])
def test_from_pandas_refuses_values_it_would_have_cut_down(col, val, what):
    base = tc.ToolTable.parse("T1 P1 Z25 D10\n", "linuxcnc")
    df = base.to_pandas()
    df[col] = df[col].astype(object)
    df.loc[0, col] = val
    with pytest.raises(ValueError, match=what):
        tc.ToolTable.from_pandas(df, base=base)


def test_from_pandas_missing_values_keep_the_base():
    base = tc.ToolTable.parse("T1 P1 Z25 D10 ;mill\n", "linuxcnc")
    df = base.to_pandas().astype(object)
    df.loc[0, "comment"] = None
    df.loc[0, "radius"] = pd.NA
    new = tc.ToolTable.from_pandas(df, base=base)
    assert new.get(1).comment == "mill" and new.get(1).edge(1).radius == 5


def test_a_missing_number_without_a_base_value_is_refused():
    # Column arithmetic lost tool 2's radius (NaN): without a base it would become radius 0.
    df = pd.DataFrame({"tool": [1, 2], "radius": [3.0, np.nan], "z": [40.0, 50.0]})
    with pytest.raises(ValueError, match="radius of tool 2 .* missing"):
        tc.ToolTable.from_pandas(df)
    df = pd.DataFrame({"tool": [1, 2], "radius": [3.0, 5.0], "z": [40.0, None]})
    with pytest.raises(ValueError, match="z of tool 2"):
        tc.ToolTable.from_pandas(df)


def test_a_missing_number_keeps_the_base_value():
    base = tc.ToolTable()
    base.set(tc.Tool(2, edges=[tc.CuttingEdge(radius=3.0, length=[0.0, 0.0, 40.0])]))
    df = pd.DataFrame({"tool": [2, 7], "radius": [np.nan, 1.5], "z": [45.0, 30.0]})
    table = tc.ToolTable.from_pandas(df, base=base)
    assert table[2].edges[0].radius == 3.0 and table[2].edges[0].length[2] == 45.0
    assert table[7].edges[0].radius == 1.5
    df.loc[1, "radius"] = np.nan  # tool 7 is not in the base
    with pytest.raises(ValueError, match="radius of tool 7"):
        tc.ToolTable.from_pandas(df, base=base)
