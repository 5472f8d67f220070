"""The example notebook runs from top to bottom on the installed wheel, as Jupyter runs
it (nbclient, the venv's own Python kernel, in `examples/`), with no error: a run of the
shipped drum, its energy and heights plotted, and the 3D movie shown inline."""

import nbformat
from nbclient import NotebookClient

from conftest import REPO

NOTEBOOK = REPO / "examples" / "drum.ipynb"


def test_the_drum_notebook_runs_and_shows_its_plots_and_movie():
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    # Nothing run is committed: the notebook shows what the package does when it is run.
    code = [c for c in notebook.cells if c.cell_type == "code"]
    assert all(not c.outputs and c.execution_count is None for c in code)
    client = NotebookClient(
        notebook,
        timeout=600,
        kernel_name="python3",
        resources={"metadata": {"path": str(NOTEBOOK.parent)}},
    )
    client.execute()
    outputs = [o for c in code for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    shown = [o.get("data", {}) for o in outputs if o.output_type in ("display_data", "execute_result")]
    assert any("image/png" in d for d in shown), "no plot"
    movie = code[-1].outputs
    assert len(movie) == 1 and "<iframe" in movie[0]["data"]["text/html"], movie
