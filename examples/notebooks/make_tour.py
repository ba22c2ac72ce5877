"""Writes tour.ipynb (its cells are here, so a change is reviewed as text):
    /usr/bin/python3 examples/notebooks/make_tour.py
The test Python.Notebook runs the notebook with nbclient."""
import pathlib

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# A tour of stickslip in a notebook\n\n"
        "The seed branch with its stability and labelled special points, a stability chart "
        "with its regions, and an orbit diagram of the forced Stribeck oscillator, drawn "
        "with Matplotlib (`stickslip.plot`). Install: `scripts/setup.sh`, then "
        "`pip install --no-build-isolation .` (README)."),
    new_code_cell(
        "import matplotlib.pyplot as plt\n"
        "import stickslip\n"
        "stickslip.__version__"),
    new_markdown_cell(
        "## The seed branch in the belt speed v\n\n"
        "A result shows itself: status, counts and the special points with their labels "
        "(`lab`) and rows (`pt`), as `ss_continue` writes them."),
    new_code_cell(
        "p = stickslip.Params()  # the seed set; Params(beta=-1) raises ValueError\n"
        "b = stickslip.continue_branch(p, 'v', from_=0.05, to=0.5)\n"
        "b"),
    new_code_cell(
        "fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))\n"
        "b.plot(y='x_max', ax=ax1)   # stable solid, unstable dashed\n"
        "b.plot(y='xdot_min', ax=ax2, legend=False)\n"
        "fig.tight_layout()"),
    new_code_cell("b.to_pandas().head()"),
    new_markdown_cell(
        "Restart from a labelled point: the Hopf point HB1 continued in beta "
        "(AUTO's IRS; `b.save(dir)` writes the run as `ss_continue` does)."),
    new_code_cell(
        "hb1 = b.restart('HB1')\n"
        "in_beta = stickslip.continue_branch(hb1.params, options=hb1.options('beta'))\n"
        "in_beta"),
    new_markdown_cell("## A stability chart in (v, beta), with its regions"),
    new_code_cell(
        "c = stickslip.chart(p, 'v', 0.05, 0.6, 'beta', 0.0, 0.25, regions=(24, 20))\n"
        "c.plot()\n"
        "c"),
    new_markdown_cell(
        "## A forced orbit diagram\n\n"
        "The Stribeck oscillator forced by A cos(Omega t) (`studies/forced_stribeck_orbit_diagram.ini`, "
        "fewer values): the section points against Omega, swept up and down."),
    new_code_cell(
        "st = stickslip.Params(law='stribeck', beta=0.01, v=0.1, mu_s=0.4, mu_k=0.25, v_s=0.5)\n"
        "fp = stickslip.ForcedBeltParams(st, force=0.5)\n"
        "d = stickslip.orbit_diagram(fp, stickslip.Parameter.omega, 0.2, 1.2, n=100)\n"
        "stickslip.plot.orbit_diagram(d, axis='omega', y='x');"),
]
nb = new_notebook(cells=cells, metadata={
    "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
    "language_info": {"name": "python"}})
nbformat.write(nb, str(pathlib.Path(__file__).with_name("tour.ipynb")))
