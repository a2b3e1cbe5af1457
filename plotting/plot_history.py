#!/usr/bin/env python3
"""plot_history.py — one column of history.csv against another, for several runs.

usage: plot_history.py X Y OUT.png LABEL=OUTDIR [LABEL=OUTDIR ...] [--title TEXT]
e.g.   plot_history.py settlement load_kN docs/results/footing_load.png SS=/tmp/ftSS UL=/tmp/ftUL
"""
import csv
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

args = sys.argv[1:]
title = ""
if "--title" in args:
    i = args.index("--title")
    title = args[i + 1]
    del args[i:i + 2]
if len(args) < 4:
    sys.exit(__doc__)
x, y, out = args[0], args[1], args[2]
fig, ax = plt.subplots(figsize=(5.5, 4))
for run in args[3:]:
    label, path = run.split("=", 1)
    rows = list(csv.DictReader(open(path + "/history.csv")))
    ax.plot([0] + [float(r[x]) for r in rows], [0] + [float(r[y]) for r in rows], "o-", ms=3,
            label=label)
ax.set_xlabel(x)
ax.set_ylabel(y)
ax.grid(True, alpha=0.3)
ax.legend()
if title:
    ax.set_title(title)
fig.tight_layout()
fig.savefig(out, dpi=110)
