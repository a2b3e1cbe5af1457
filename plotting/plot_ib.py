#!/usr/bin/python3
# plot_ib.py — plots and tables of [Boundaries] secs 5.2 and 5.3 from the CSV files of ample_bench
#
# Reads docs/results/deepbeam.csv and ibshear.csv (ample_bench deepbeam ibshear) and writes
# deepbeam.png (tables II and III, figs 15a-b: ours with both K2 couplings beside the paper's)
# and ibshear.png (fig 16: the shear stress error against the position xA of the fixed
# implicit boundary), and prints the tables in markdown for docs/implicitBoundaries.md.
# Needs Debian's python3-matplotlib (run with /usr/bin/python3).
#   /usr/bin/python3 plotting/plot_ib.py [docs/results]
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from bench_csv import param  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else "docs/results"
PAPER_II = {3: 1.6653e-3, 5: 5.9450e-4, 10: 1.4812e-4, 15: 6.5788e-5, 20: 3.6998e-5,
            25: 2.3676e-5, 40: 1.0277e-5}                          # [Boundaries] table II
PAPER_III = {0.01: (242, 9.313e-4), 0.005: (882, 3.110e-4), 0.002: (5202, 7.558e-5),
             0.001: (20402, 2.670e-5)}                              # table III (dofs, rA)
COUPLING = {"0": "paper K2 (ibK2=0)", "1": "consistent K2 (ibK2=1)"}


def rows(name):
    path = os.path.join(OUT, name + ".csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []




def finish(fig, axes, name, legend_size):
    """grid and legend on every panel, then docs/results/<name>"""
    for a in axes:
        a.grid(True, which="both", alpha=0.3)
        a.legend(fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, name), dpi=110)
    plt.close(fig)


def deepbeam(db):
    series = {}  # (table, coupling) -> [(x, rA, row)]
    for r in db:
        k, mp, h = param(r, "ibK2"), int(param(r, "mp")), float(param(r, "h", "0.01"))
        if mp == 4:
            series.setdefault(("III", k), []).append((h, float(r["rA"]), r))
        if h == 0.01 and mp != 4:
            series.setdefault(("II", k), []).append((mp, float(r["rA"]), r))
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for k, mark in (("0", "o-"), ("1", "x--")):
        pts = sorted(series.get(("II", k), []))
        ax[0].loglog([p[0] ** 2 for p in pts], [p[1] for p in pts], mark, label="ours, " + COUPLING[k])
        pts = sorted(series.get(("III", k), []), reverse=True)
        ax[1].loglog([float(p[2]["dofs"]) ** 0.5 for p in pts], [p[1] for p in pts], mark,
                     label="ours, " + COUPLING[k])
    ax[0].loglog([m * m for m in PAPER_II], list(PAPER_II.values()), "s", mfc="none", ms=9,
                 label="paper, table II")
    ax[1].loglog([d ** 0.5 for d, _ in PAPER_III.values()], [e for _, e in PAPER_III.values()], "s",
                 mfc="none", ms=9, label="paper, table III")
    ax[0].set(xlabel="material points per cell", ylabel="rA = |v(A) - v_FE(A)| / |v_FE(A)|",
              title="deep beam, h = 10 mm (table II, fig 15a)")
    ax[1].set(xlabel="(dofs)^0.5", ylabel="rA", title="deep beam, 4^2 points per cell (table III, fig 15b)")
    finish(fig, ax, "deepbeam.png", 8)
    print("| points per cell | paper | ours ibK2=0 | ours ibK2=1 | run (s) 0 / 1 |\n|---|---|---|---|---|")
    two = {k: {p[0]: p for p in series.get(("II", k), [])} for k in ("0", "1")}
    for mp in sorted(two["0"]):
        a, b = two["0"][mp], two["1"].get(mp)
        paper = "%.4e" % PAPER_II[mp] if mp in PAPER_II else "-"
        print("| %d^2 | %s | %.4e | %.4e | %.3f / %.3f |" % (mp, paper, a[1], b[1],
              float(a[2]["wall_seconds"]), float(b[2]["wall_seconds"])))
    print("\n| h (mm) | dofs ours | dofs paper | paper | ours ibK2=0 | ours ibK2=1 | run (s) 0 / 1 |")
    print("|---|---|---|---|---|---|---|")
    three = {k: {p[0]: p for p in series.get(("III", k), [])} for k in ("0", "1")}
    for h in sorted(three["0"], reverse=True):
        a, b = three["0"][h], three["1"][h]
        d, e = PAPER_III[h]
        print("| %g | %d | %d | %.3e | %.4e | %.4e | %.3f / %.3f |" % (h * 1e3, float(a[2]["dofs"]), d, e,
              a[1], b[1], float(a[2]["wall_seconds"]), float(b[2]["wall_seconds"])))


def ibshear(sh):
    fig, ax = plt.subplots(figsize=(6, 4))
    table = {}
    for k, mark, colour in (("0", "o", "C0"), ("1", "x", "C1")):
        pts = sorted((1e3 * float(param(r, "xA")), r) for r in sh if param(r, "ibK2") == k)
        for x, r in pts:
            table.setdefault(x, {})[k] = r
        xs = [p[0] for p in pts]
        for col, style, what in (("r_sxy", "-", "domain (eq 30)"), ("r_sxy_max", ":", "largest point")):
            ys = [max(float(p[1][col]), 1e-17) for p in pts]
            ax.semilogy(xs, ys, mark + style, color=colour, label="%s, %s" % (COUPLING[k], what))
    ax.axhline(2e-8, color="k", lw=0.8, ls="--", label="paper: below 2e-8 at every xA")
    ax.set(xlabel="xA: position of the fixed implicit boundary (mm)", ylabel="r_sxy",
           title="simple shear, 2 cells of 100 mm, 20 x 20 points (fig 16)")
    finish(fig, [ax], "ibshear.png", 7)
    print("\n| xA (mm) | r_sxy ibK2=0 | max ibK2=0 | r_sxy ibK2=1 | max ibK2=1 | run (s) 0 / 1 |")
    print("|---|---|---|---|---|---|")
    for x in sorted(table):
        a, b = table[x]["0"], table[x]["1"]
        print("| %g | %.4e | %.4e | %.2e | %.2e | %.3f / %.3f |" % (x, float(a["r_sxy"]), float(a["r_sxy_max"]),
              float(b["r_sxy"]), float(b["r_sxy_max"]), float(a["wall_seconds"]), float(b["wall_seconds"])))


if rows("deepbeam"):
    deepbeam(rows("deepbeam"))
if rows("ibshear"):
    ibshear(rows("ibshear"))
