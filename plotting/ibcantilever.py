#!/usr/bin/python3
# ibcantilever.py — the runs and plots of the slender cantilever ([Boundaries] sec 5.4, figs 18, 19, 21)
#
# --run: runs build/release/ample ibcantilever (one run at a time, < 1 min each on the shared
# machine) and writes to docs/results:
#   ibcantilever_runs.csv     one row per run: h, theta, ibK2, mp, lstps, steps reached, message,
#                             full-load (or last) figures, the program's wall seconds
#   ibcantilever_history.csv  every load step of every run (the setup's history.csv rows)
#   ibcantilever_fig21.csv    the points within 20 mm of the support of h = 1 mm, 5 x 5 points,
#                             90 degrees, full load in 1 and in 4 load steps: lstps, X0, Y0 (mm),
#                             sigma_xx, sigma_yy, sigma_xy (MPa)
# then (always) plots from those files:
#   ibcantilever_fig18.png    free-end v' against the total body force, 0/45/90 (h = 2 mm, 10 x 10)
#   ibcantilever_fig19.png    percentage difference |v'45 - v'90| / |v'90| of the free-end
#                             deflection against d / h, the mean over the load steps that both
#                             reached (annotated: steps reached / lstps), 1 and 10 load steps
#   ibcantilever_fig21.png    the three stresses near the support
# Needs Debian's python3-matplotlib.
#   /usr/bin/python3 plotting/ibcantilever.py [--run]
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

OUT = "docs/results"
AMPLE = "build/release/ample"
D = 0.02  # beam depth (m)

# (h, theta, ibK2, mp, lstps): fig 18 (h = 2 mm, both K2), fig 19 (one linear step and
# ten steps, h = 4 .. 0.5 mm), the 0 degree beam-theory check, fig 21
RUNS = ([(0.002, t, k, 10, 10) for t in (0, 45, 90) for k in (0, 1)] +
        [(h, t, 0, 10, l) for l in (1, 10) for h in (0.004, 0.002, 0.001, 0.0005) for t in (0, 45, 90)] +
        [(0.001, t, 1, 10, 1) for t in (45, 90)] +
        [(0.001, 90, 0, 5, 1), (0.001, 90, 0, 5, 4)])
FIG21 = [(0.001, 90, 0, 5, 1), (0.001, 90, 0, 5, 4)]  # one linear step; 4 steps (10 fail, docs)


def run_all():
    runs, hist = [], []
    f21 = open(os.path.join(OUT, "ibcantilever_fig21.csv"), "w")
    f21.write("lstps,X0_mm,Y0_mm,sxx_MPa,syy_MPa,sxy_MPa\n")
    for key in dict.fromkeys(RUNS):  # each once, in order
        h, t, k, mp, l = key
        out = "/tmp/ibcantilever_%g_%g_%d_%d_%d" % key
        cmd = [AMPLE, "ibcantilever", "h=%g" % h, "theta=%g" % t, "ibK2=%d" % k, "mp=%d" % mp,
               "lstps=%d" % l, "--vtk", "0", "--quiet", "--out", out]
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        s = json.load(open(out + "/summary.json"))
        rows = list(csv.DictReader(open(out + "/history.csv"))) if os.path.exists(out + "/history.csv") else []
        last = rows[-1] if rows else {}
        runs.append({"h": h, "theta": t, "ibK2": k, "mp": mp, "lstps": l, "points": s["nmp"],
                     "steps": s["last_converged_step"], "tip_v": last.get("tip_v", ""),
                     "tip_v_beam": last.get("tip_v_beam", ""), "R_y": last.get("R_y", ""),
                     "F_y": last.get("F_y", ""), "seconds": s["wall_seconds"],
                     "message": s["message"].replace(",", ";")})
        for r in rows:
            hist.append(dict({"h": h, "theta": t, "ibK2": k, "mp": mp, "lstps": l}, **r))
        print(runs[-1])
        if key in FIG21:
            pts = list(csv.DictReader(open(out + "/mp_final.csv")))
            ymax = max(float(p["Y0"]) for p in pts)  # 90 degrees: the support is the top end
            for p in pts:
                if float(p["Y0"]) > ymax - 0.02:
                    f21.write("%d,%.4f,%.4f,%.4g,%.4g,%.4g\n" % (
                        l, 1e3 * float(p["X0"]), 1e3 * float(p["Y0"]), 1e-6 * float(p["sxx"]),
                        1e-6 * float(p["syy"]), 1e-6 * float(p["sxy"])))
    f21.close()
    for name, rows in (("runs", runs), ("history", hist)):
        with open(os.path.join(OUT, "ibcantilever_%s.csv" % name), "w") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


def history():
    rows = list(csv.DictReader(open(os.path.join(OUT, "ibcantilever_history.csv"))))
    out = {}
    for r in rows:
        key = (float(r["h"]), float(r["theta"]), int(r["ibK2"]), int(r["mp"]), int(r["lstps"]))
        out.setdefault(key, []).append(r)
    return out


def fig18(H):
    plt.figure(figsize=(6, 4.5))
    for t, style in ((0, "o-"), (45, "s--"), (90, "x:")):
        r = H.get((0.002, t, 0, 10, 10), [])
        plt.plot([0] + [-float(x["F_y"]) / 1e3 for x in r], [0] + [-1e3 * float(x["tip_v"]) for x in r],
                 style, label="%d degrees" % t)
    r = H[(0.002, 0, 0, 10, 10)]
    plt.plot([0] + [-float(x["F_y"]) / 1e3 for x in r], [0] + [-1e3 * float(x["tip_v_beam"]) for x in r],
             "k-", lw=0.8, label="Timoshenko (linear)")
    plt.xlabel("total body force b d L (N/mm; 400 = the paper's 0.2 N/mm2)")  # N/m / 1e3
    plt.ylabel("free-end deflection -v' (mm)")
    plt.title("ibcantilever: h = 2 mm, 10 x 10 points per cell, 10 load steps")
    plt.legend()
    plt.grid(alpha=0.3)
    plt.tight_layout()
    plt.savefig(os.path.join(OUT, "ibcantilever_fig18.png"), dpi=120)


def fig19(H):
    plt.figure(figsize=(6, 4.5))
    for l, style in ((1, "o-"), (10, "s--")):
        x, y = [], []
        for h in (0.004, 0.002, 0.001, 0.0005):
            a, b = H.get((h, 45, 0, 10, l), []), H.get((h, 90, 0, 10, l), [])
            n = min(len(a), len(b))
            if n == 0:
                continue
            diff = [100 * abs(float(a[i]["tip_v"]) - float(b[i]["tip_v"])) / abs(float(b[i]["tip_v"]))
                    for i in range(n)]
            x.append(D / h)
            y.append(sum(diff) / n)
            plt.annotate("%d/%d" % (n, l), (D / h, y[-1]), fontsize=7,
                         textcoords="offset points", xytext=(4, 6 if l == 1 else -10))
        plt.plot(x, y, style, label="%d load step%s (mean over the steps reached)" % (l, "s" if l > 1 else ""))
    plt.xscale("log")
    plt.yscale("log")
    plt.xlabel("d / h")
    plt.ylabel("|v'45 - v'90| / |v'90| (%)")
    plt.title("ibcantilever: 45 against 90 degrees, 10 x 10 points per cell")
    plt.legend(fontsize=8)
    plt.grid(alpha=0.3, which="both")
    plt.tight_layout()
    plt.savefig(os.path.join(OUT, "ibcantilever_fig19.png"), dpi=120)


def fig21():
    allRows = list(csv.DictReader(open(os.path.join(OUT, "ibcantilever_fig21.csv"))))
    fig, ax = plt.subplots(2, 3, figsize=(11, 8))
    for row, l in enumerate((1, 4)):
        rows = [r for r in allRows if int(r["lstps"]) == l]
        X = [float(r["X0_mm"]) for r in rows]
        Y = [float(r["Y0_mm"]) for r in rows]
        for a, (k, name) in zip(ax[row], (("sxx_MPa", "sigma_xx"), ("syy_MPa", "sigma_yy"),
                                          ("sxy_MPa", "sigma_xy"))):
            sc = a.scatter(X, Y, c=[float(r[k]) for r in rows], s=5, cmap="jet", marker="s", linewidths=0)
            a.set_aspect("equal")
            a.set_title("%s (MPa), %d load step%s" % (name, l, "s" if l > 1 else ""), fontsize=9)
            a.set_xlabel("x (mm)")
            fig.colorbar(sc, ax=a, shrink=0.8)
        ax[row][0].set_ylabel("y (mm)")
    fig.suptitle("ibcantilever 90 degrees, h = 1 mm, 5 x 5 points, full load, the 20 mm at the support "
                 "(top edge; original positions)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ibcantilever_fig21.png"), dpi=120)


if __name__ == "__main__":
    if "--run" in sys.argv:
        run_all()
    H = history()
    fig18(H)
    fig19(H)
    fig21()
