#!/usr/bin/env python3
"""plot_history.py — one column of history.csv against another, for several runs.

usage: plot_history.py X Y OUT.png LABEL=OUTDIR [LABEL=OUTDIR ...] [--title TEXT]
e.g.   plot_history.py settlement load_kN docs/results/footing_load.png SS=/tmp/ftSS UL=/tmp/ftUL
draw_history() is also the history panel of plot_run.py.
"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from run_output import read_csv


def draw_history(ax, runs, x, ys):
    """columns ys against column x of each (label, rows) in runs, from the unloaded state 0"""
    for label, rows in runs:
        for y in ys:
            name = " ".join(s for s in (label, y if len(ys) > 1 else "") if s)
            ax.plot([0] + [r[x] for r in rows], [0] + [r[y] for r in rows], "o-", ms=3,
                    label=name or None)
    ax.set_xlabel(x)
    ax.set_ylabel(", ".join(ys))
    ax.grid(True, alpha=0.3)
    if any(label for label, _ in runs) or len(ys) > 1:
        ax.legend(fontsize=8)


def main(args):
    title = ""
    if "--title" in args:
        i = args.index("--title")
        title = args[i + 1]
        del args[i:i + 2]
    if len(args) < 4:
        sys.exit(__doc__)
    x, y, out = args[0], args[1], args[2]
    runs = [(run.split("=", 1)[0], read_csv(run.split("=", 1)[1] + "/history.csv")) for run in args[3:]]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    draw_history(ax, runs, x, [y])
    if title:
        ax.set_title(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:])
