#!/usr/bin/env python3
"""plot_points.py — the material points of chosen load steps, coloured by a field.

Reads the legacy VTK files mpData_<lstp>.vtk that `ample <setup> --vtk 1` writes
(points and their scalars) and draws one panel per load step, each point a dot
coloured by the field (e.g. uy for the footing of [Boundaries] fig 22, ux for the
funnel of fig 23), with one colour scale for all panels.

usage: plot_points.py OUTDIR FIELD OUT.png LSTP [LSTP ...] [--mm] [--title TEXT]
       --mm: axes and field in mm (the paper's units) instead of m
"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from run_output import read_vtk


def main(argv):
    flags = [a for a in argv if a.startswith("--")]
    args = [a for a in argv if not a.startswith("--")]
    title = ""
    if "--title" in argv:
        title = argv[argv.index("--title") + 1]
        args.remove(title)
    if len(args) < 4:
        sys.exit(__doc__)
    outdir, field, out, steps = args[0], args[1], args[2], [int(s) for s in args[3:]]
    scale = 1e3 if "--mm" in flags else 1.0
    data = [read_vtk(f"{outdir}/mpData_{s}.vtk", field) for s in steps]
    lo = min(min(v) for _, v in data) * scale
    hi = max(max(v) for _, v in data) * scale
    fig, axes = plt.subplots(1, len(steps), figsize=(3.2 * len(steps), 3.4), squeeze=False)
    for ax, s, (xy, v) in zip(axes[0], steps, data):
        sc = ax.scatter([p[0] * scale for p in xy], [p[1] * scale for p in xy],
                        c=[x * scale for x in v], s=2, cmap="jet", vmin=lo, vmax=hi)
        ax.set_aspect("equal")
        ax.set_title(f"load step {s}")
    fig.colorbar(sc, ax=axes[0].tolist(), label=field + (" (mm)" if scale == 1e3 else " (m)"))
    if title:
        fig.suptitle(title)
    fig.savefig(out, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main(sys.argv[1:])
