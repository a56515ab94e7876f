"""Optional dependencies: a function that needs one that is missing names the extra that
installs it (the module is hidden by putting None in sys.modules, as a missing one is)."""
import sys

import pytest

import toolcomp as tc


@pytest.fixture
def without(monkeypatch):
    def hide(*modules):
        for m in modules:
            for name in [n for n in sys.modules if n == m or n.startswith(m + ".")]:
                monkeypatch.delitem(sys.modules, name)
            monkeypatch.setitem(sys.modules, m, None)
    return hide


def _table():
    t = tc.ToolTable()
    t.set(tc.Tool(1, edges=[tc.CuttingEdge(radius=3.0)]))
    return t


def test_to_pandas_without_pandas_names_the_extra(without):
    without("pandas")
    with pytest.raises(ImportError, match=r"ToolTable.to_pandas needs pandas.*toolcomp\[pandas\]"):
        _table().to_pandas()
