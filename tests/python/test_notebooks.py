"""The notebooks are executed by the test suite, so they never rot; a notebook that draws
must show its pictures (no backend forced off: Jupyter's inline display)."""
import pathlib

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

NOTEBOOKS = sorted((pathlib.Path(__file__).resolve().parents[2] / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_runs(path):
    nb = nbformat.read(path, as_version=4)
    nbclient.NotebookClient(nb, timeout=120, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}}).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.output_type == "error"]
    draws = any(".plot(" in c.source or "plt." in c.source for c in nb.cells if c.cell_type == "code")
    images = [o for o in outputs if o.output_type in ("display_data", "execute_result")
              and ("image/png" in o.get("data", {}) or "image/svg+xml" in o.get("data", {}))]
    assert images or not draws, f"{path.name} draws but shows no picture"
