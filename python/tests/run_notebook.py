"""ctest Python.Notebook: runs a notebook top to bottom with nbclient (Debian
python3-nbclient, python3-ipykernel) in its own directory; any cell's error
fails the test (exit 1). Also requires the figures: at least MIN_FIGURES PNG
outputs. Exit 77 (skipped) without nbclient or an ipykernel.
Usage: run_notebook.py NOTEBOOK MIN_FIGURES"""
import os
import sys


def main(path, min_figures):
    try:
        import nbclient
        import nbformat
        from jupyter_client.kernelspec import KernelSpecManager
    except ImportError as e:
        print("run_notebook: needs python3-nbclient and python3-ipykernel (%s)" % e)
        return 77
    if "python3" not in KernelSpecManager().find_kernel_specs():
        print("run_notebook: no python3 kernel (python3-ipykernel)")
        return 77
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                                     resources={"metadata": {"path": os.path.dirname(path)}})
    try:
        client.execute()
    except nbclient.exceptions.CellExecutionError as e:
        print("run_notebook: a cell failed:\n%s" % e)
        return 1
    figures = sum(1 for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
                  if "image/png" in o.get("data", {}))
    print("run_notebook: %d cells ran, %d figures" % (len(nb.cells), figures))
    out = os.environ.get("STICKSLIP_NOTEBOOK_OUT")  # keep the executed notebook to look at
    if out:
        nbformat.write(nb, out)
    if figures < min_figures:
        print("run_notebook: expected at least %d figures" % min_figures)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(os.path.abspath(sys.argv[1]), int(sys.argv[2])))
