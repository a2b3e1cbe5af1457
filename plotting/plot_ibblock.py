#!/usr/bin/env python3
"""plot_ibblock.py — [Boundaries] figs 10-13 from docs/results/ibblock_sweep.csv.

Top row (figs 10-12): ru against 1/h (1/mm) for each delta/h, at 30, 45 and 90 degrees;
bottom row left (fig 13): ru against delta/h for each h at 90 degrees. Solid lines: the
paper's K2 coupling (ibK2=0); dashed: the consistent coupling (ibK2=1).
usage: plot_ibblock.py docs/results/ibblock_sweep.csv docs/results/ibblock_convergence.png
"""
import csv
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    for k in ("theta", "h_m", "delta_over_h", "ibK2", "ru", "r_sxx"):
        r[k] = float(r[k])


def curves(a, select, x, y, groups, label):
    """one line per group value g and coupling: (x, y) of the rows where select(r, g)"""
    for i, g in enumerate(groups):
        for k, style in ((0, "-"), (1, "--")):
            pts = sorted((x(r), max(r[y], 1e-17)) for r in rows if select(r, g) and r["ibK2"] == k)
            a.loglog(*zip(*pts), style, color=f"C{i}", marker="o", ms=3,
                     label=label(g) if k == 0 else None)
    a.grid(True, which="both", alpha=0.3)


fig, ax = plt.subplots(2, 3, figsize=(14, 8.5))
deltas = sorted({r["delta_over_h"] for r in rows}, reverse=True)
hs = sorted({r["h_m"] for r in rows}, reverse=True)
for col, th in enumerate((30, 45, 90)):
    a = ax[0][col]
    curves(a, lambda r, d: r["theta"] == th and r["delta_over_h"] == d, lambda r: 1e-3 / r["h_m"],
           "ru", deltas, lambda d: f"delta/h = {d:g}")
    a.set_title(f"{th} degrees ([Boundaries] fig {10 if th == 30 else 11 if th == 45 else 12})")
    a.set(xlabel="1/h (1/mm)", ylabel="ru (eq 29)")
ax[0][0].legend(fontsize=7)
curves(ax[1][0], lambda r, h: r["theta"] == 90 and r["h_m"] == h, lambda r: r["delta_over_h"],
       "ru", hs, lambda h: f"h = {h * 1e3:g} mm")
ax[1][0].set(title="90 degrees: ru against delta/h ([Boundaries] fig 13)", xlabel="delta/h",
             ylabel="ru (eq 29)")
ax[1][0].legend(fontsize=7)
curves(ax[1][1], lambda r, th: r["theta"] == th and r["h_m"] == 0.01, lambda r: r["delta_over_h"],
       "r_sxx", (30, 45, 90), lambda th: f"{th} degrees")
ax[1][1].set(title="h = 10 mm: r_sxx (eq 30) against delta/h", xlabel="delta/h", ylabel="r_sxx")
ax[1][1].legend(fontsize=7)
ax[1][2].axis("off")
ax[1][2].text(0, 0.5, "solid: ibK2 = paper (int d d' = 1/2)\ndashed: ibK2 = consistent (1)\n"
              "one standard MPM point per cell, SS,\nE = 1000 MPa, nu = 0.3", fontsize=11)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
