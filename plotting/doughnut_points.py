#!/usr/bin/env python3
"""doughnut_points.py — the deformed material points of doughnut runs ([CPDI] figs 9-10).

One row per run, one column per twist angle; each point a dot coloured by the field
(default rho_vonMises), one colour scale for the figure. A panel whose load step the run
did not reach says so. Runs need `--vtk 1` (mpData_<lstp>.vtk, lstp = alpha / dalpha).

usage: doughnut_points.py OUT.png FIELD ALPHAS DALPHA LABEL=OUTDIR [LABEL=OUTDIR ...]
       VMAX=v (environment): the top of the colour scale (larger values drawn in its colour)
       e.g. doughnut_points.py fig10.png rho_vonMises 20,30,60 2.5 FE=/tmp/fe MPM=/tmp/mpm
"""
import os
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from plot_points import read_vtk


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__)
    out, field, alphas, dalpha = argv[0], argv[1], [float(a) for a in argv[2].split(",")], float(argv[3])
    runs = [a.split("=", 1) for a in argv[4:]]
    data = {}
    for label, d in runs:
        for a in alphas:
            f = f"{d}/mpData_{round(a / dalpha)}.vtk"
            if os.path.exists(f):
                data[label, a] = read_vtk(f, field)
    lo = min(min(v) for _, v in data.values())
    hi = float(os.environ["VMAX"]) if "VMAX" in os.environ else max(max(v) for _, v in data.values())
    fig, axes = plt.subplots(len(runs), len(alphas), figsize=(3.0 * len(alphas), 3.0 * len(runs)), squeeze=False)
    sc = None
    for r, (label, _) in enumerate(runs):
        for c, a in enumerate(alphas):
            ax = axes[r][c]
            ax.set_aspect("equal")
            ax.set_xlim(-10.5, 10.5), ax.set_ylim(-10.5, 10.5)
            ax.set_xticks([]), ax.set_yticks([])
            ax.set_title(f"{label}, alpha = {a:g} deg", fontsize=9)
            if (label, a) not in data:
                ax.text(0, 0, "stopped before", ha="center", va="center")
                continue
            xy, v = data[label, a]
            sc = ax.scatter([p[0] for p in xy], [p[1] for p in xy], c=v, s=1, cmap="jet", vmin=lo, vmax=hi)
    if sc is not None:
        fig.colorbar(sc, ax=axes.ravel().tolist(), label=field, shrink=0.8)
    fig.savefig(out, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main(sys.argv[1:])
