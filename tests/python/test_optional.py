"""Optional dependencies: a function that needs one that is missing names the extra that
installs it (the module is hidden by putting None in sys.modules, as a missing one is)."""
import sys

import pytest

import toolcomp as tc
from toolcomp.plot import save_plot


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


def test_plot_without_matplotlib_names_the_extra(without, tmp_path):
    res = tc.run(tc.Program.parse("G21 G90\nG1 X10 F100\nM2\n", dialect="linuxcnc"))
    without("matplotlib")
    with pytest.raises(ImportError, match=r"Result.plot needs matplotlib.*toolcomp\[plot\]"):
        res.plot()
    with pytest.raises(ImportError, match=r"save_plot needs matplotlib.*toolcomp\[plot\]"):
        save_plot(res, tmp_path / "p.png")
