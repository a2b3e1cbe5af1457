#!/usr/bin/python3
# plot_results.py — plots and tables of docs/results from the CSV files of ample_bench
#
# Reads docs/results/<suite>.csv (written by build/release/ample_bench) and writes
# PNG plots and a markdown file of tables, docs/results/tables.md, next to them.
# Needs Debian's python3-matplotlib (run with /usr/bin/python3).
#   /usr/bin/python3 plotting/plot_results.py [docs/results]
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from bench_csv import param  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else "docs/results"
NAMES = {1: "MPM", 2: "GIMP", 3: "CPDI1", 4: "CPDI2"}


def rows(name):
    path = os.path.join(OUT, name + ".csv")
    if not os.path.exists(path):
        return []
    return list(csv.DictReader(open(path)))




def num(r, key):
    try:
        return float(r[key])
    except (KeyError, ValueError):
        return float("nan")


def slope(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def elastica(alpha):
    """Tip of an inextensible cantilever under a vertical tip load: theta'' = -alpha cos(theta),
    theta(0) = 0, theta'(1) = 0; returns (u/L, w/L), u inwards negative, w downwards positive."""
    def shoot(k0, n=400):
        h, th, dth, x, y = 1.0 / n, 0.0, k0, 0.0, 0.0
        f = lambda t, d: (d, -alpha * math.cos(t))
        for _ in range(n):  # RK4 on (theta, theta'), trapezoid-like on x, y
            k1 = f(th, dth); k2 = f(th + h / 2 * k1[0], dth + h / 2 * k1[1])
            k3 = f(th + h / 2 * k2[0], dth + h / 2 * k2[1]); k4 = f(th + h * k3[0], dth + h * k3[1])
            th2 = th + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            dth2 = dth + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
            x += h * (math.cos(th) + 4 * math.cos((th + th2) / 2) + math.cos(th2)) / 6
            y += h * (math.sin(th) + 4 * math.sin((th + th2) / 2) + math.sin(th2)) / 6
            th, dth = th2, dth2
        return dth, x, y
    lo, hi = 0.0, alpha  # theta'(1) grows with theta'(0): negative at 0, >= 0 at alpha
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        (lo, hi) = (lo, mid) if shoot(mid)[0] > 0 else (mid, hi)
    _, x, y = shoot(0.5 * (lo + hi))
    return x - 1.0, y


tables = ["# Benchmark tables\n", "Written by plotting/plot_results.py from the CSV files of ample_bench.\n"]

# 1. compaction: error against h and against wall time --------------------------------------
comp = rows("compaction")
if comp:
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    tables.append("\n## Compaction ([AMPLE] fig 9): error of eq 37, 2x2 points per cell\n")
    tables.append("| method | nelsy | points | error | wall s | NR its |\n|---|---|---|---|---|---|\n")
    for t in range(1, 5):
        rs = [r for r in comp if param(r, "mpType") == str(t) and r["converged"] == "1"]
        if not rs:
            continue
        h = [50.0 / int(param(r, "nelsy")) for r in rs]
        e = [num(r, "error") for r in rs]
        w = [num(r, "wall_s") for r in rs]
        fine = [i for i in range(len(h)) if h[i] <= 50.0 / 64]
        rate = slope([h[i] for i in fine], [e[i] for i in fine]) if len(fine) > 1 else float("nan")
        ax[0].loglog(h, e, "o-", label="%s (rate %.2f for h <= 0.78 m)" % (NAMES[t], rate))
        ax[1].loglog(w, e, "o-", label=NAMES[t])
        for r, hh, ee, ww in zip(rs, h, e, w):
            tables.append("| %s | %s | %s | %.3e | %.3f | %s |\n" % (NAMES[t], param(r, "nelsy"), r["nmp"], ee, ww, r["NR_iterations"]))
    ax[0].set_xlabel("cell size h (m)"); ax[0].set_ylabel("error (eq 37)"); ax[0].legend(); ax[0].grid(True, which="both", alpha=.3)
    ax[1].set_xlabel("wall time (s)"); ax[1].set_ylabel("error (eq 37)"); ax[1].legend(); ax[1].grid(True, which="both", alpha=.3)
    ax[0].set_title("convergence with refinement"); ax[1].set_title("work-precision")
    fig.tight_layout(); fig.savefig(os.path.join(OUT, "compaction.png"), dpi=110); plt.close(fig)

# 2. scaling -----------------------------------------------------------------------------------
# curves: the compaction column and the collapse with each solver= (LU, LDLT, MUMPS: a build with
# -DAMPLE_MUMPS=ON; PETSC, one process: -DAMPLE_PETSC=ON; the collapse at a = 32 with the remedies it needs, not with LU); a solver
# without rows is left out, and rows of other solvers (older runs) are not drawn; the collapse
# before the performance work of 2026-12-01/02 (scaling2d_before.csv: main at 8eb7125, SparseLU, run the same day), dashed
scal = rows("scaling") + rows("scaling2d")
before = rows("scaling2d_before")
if scal:
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    tables.append("\n## Scaling: run time and memory against the number of points\n")
    tables.append("| setup | parameters | points | NR its | wall s | detMPs s | linSolve s | us per point-iteration (detMPs) | peak kB | kB per point |\n|---|---|---|---|---|---|---|---|---|---|\n")
    curves = [("compaction", sv, m, scal, "compaction solver=" + sv)
              for sv, m in (("LU", "o-"), ("LDLT", "D-"), ("MUMPS", "P-"))]
    curves += [("collapse", sv, m, scal, "collapse solver=" + sv)
               for sv, m in (("LU", "s-"), ("LDLT", "^-"), ("MUMPS", "*-"), ("PETSC", "x-"))]
    curves += [("collapse", "LU", "s--", before, "collapse at 8eb7125 (LU)")]
    for setup, solver, mark, src, label in curves:
        rs = [r for r in src if r["setup"] == setup and r["converged"] == "1" and
              (solver is None or param(r, "solver", "LU") == solver)]
        if not rs:
            continue
        n = [num(r, "nmp") for r in rs]
        w = [num(r, "wall_s") for r in rs]
        ax[0].loglog(n, w, mark, label="%s (slope %.2f)" % (label, slope(n, w) if len(n) > 1 else float("nan")))
        ax[1].semilogx(n, [num(r, "t_linSolve") / num(r, "wall_s") for r in rs], mark, label=label)
        for r in rs if src is scal else []:
            us = 1e6 * num(r, "t_detMPs") / (num(r, "nmp") * num(r, "NR_iterations"))
            tables.append("| %s | %s | %d | %s | %.2f | %.2f | %.2f | %.2f | %s | %.2f |\n" % (
                setup, r["parameters"], num(r, "nmp"), r["NR_iterations"], num(r, "wall_s"), num(r, "t_detMPs"),
                num(r, "t_linSolve"), us, r["peak_kB"], num(r, "peak_kB") / num(r, "nmp")))
    ax[0].set_xlabel("material points"); ax[0].set_ylabel("wall time (s)"); ax[0].legend(fontsize=8); ax[0].grid(True, which="both", alpha=.3)
    ax[1].set_xlabel("material points"); ax[1].set_ylabel("share of linSolve"); ax[1].legend(fontsize=8); ax[1].grid(True, alpha=.3)
    fig.tight_layout(); fig.savefig(os.path.join(OUT, "scaling.png"), dpi=110); plt.close(fig)

# 2b. threads: the point loop on 1 and 2 OpenMP threads -----------------------------------------
thr = rows("threads")
if thr:
    tables.append("\n## Threads: the point loop on one and two OpenMP threads\n")
    tables.append("| setup | parameters | points | wall s | detMPs s | elemMPinfo s | linSolve s | run speed-up | detMPs speed-up |\n|---|---|---|---|---|---|---|---|---|\n")
    one = {(r["setup"], " ".join(kv for kv in r["parameters"].split() if not kv.startswith("threads="))): r
           for r in thr if param(r, "threads") == "1"}
    for r in thr:
        key = (r["setup"], " ".join(kv for kv in r["parameters"].split() if not kv.startswith("threads=")))
        base = one.get(key)
        sw = num(base, "wall_s") / num(r, "wall_s") if base else float("nan")
        sd = num(base, "t_detMPs") / num(r, "t_detMPs") if base else float("nan")
        tables.append("| %s | %s | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n" % (
            r["setup"], r["parameters"], num(r, "nmp"), num(r, "wall_s"), num(r, "t_detMPs"),
            num(r, "t_elemMPinfo"), num(r, "t_linSolve"), sw, sd))

# 3. beam: load against tip displacement, elastica -------------------------------------------
beam = rows("beam")
if beam:
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    lam = [i / 50 for i in range(1, 51)]
    el = [elastica(9.6 * l) for l in lam]
    ax.plot([-u for u, w in el], lam, "k-", lw=2, label="elastica u/l")
    ax.plot([w for u, w in el], lam, "k--", lw=2, label="elastica v/l")
    u96, w96 = elastica(9.6)
    tables.append("\n## Beam: tip displacement at full load (elastica alpha = 9.6: u/l = %.4f, v/l = %.4f)\n" % (u96, -w96))
    tables.append("| a | points per cell | converged | last step | u/l | v/l | diff u/l | diff v/l | wall s |\n|---|---|---|---|---|---|---|---|---|\n")
    for c, r in enumerate(beam):
        path = os.path.join(OUT, "beam_%d_history.csv" % c)
        if os.path.exists(path):
            hs = list(csv.DictReader(open(path)))
            lf = [float(x["load_factor"]) for x in hs]
            ax.plot([-float(x["tip_u_over_l"]) for x in hs], lf, ".", ms=4, label="u/l a=%s mp=%s" % (param(r, "a"), param(r, "mp")))
            ax.plot([-float(x["tip_v_over_l"]) for x in hs], lf, ".", ms=4, label="v/l a=%s mp=%s" % (param(r, "a"), param(r, "mp")))
        ok = r["converged"] == "1"
        tables.append("| %s | %s | %s | %s | %s | %s | %s | %s | %.2f |\n" % (
            param(r, "a"), param(r, "mp"), "yes" if ok else "no", r["last_step"],
            "%.4f" % num(r, "tip_u_over_l") if ok else "-", "%.4f" % num(r, "tip_v_over_l") if ok else "-",
            "%.4f" % (num(r, "tip_u_over_l") - u96) if ok else "-", "%.4f" % (num(r, "tip_v_over_l") + w96) if ok else "-",
            num(r, "wall_s")))
    ax.set_xlabel("tip displacement / l"); ax.set_ylabel("load factor (alpha / 9.6)"); ax.legend(fontsize=7); ax.grid(True, alpha=.3)
    fig.tight_layout(); fig.savefig(os.path.join(OUT, "beam.png"), dpi=110); plt.close(fig)

# 4. collapse: tables 5 and 6 ------------------------------------------------------------------
PUB5 = {(3, 1.0): (13.781, 6.194), (3, 0.5): (13.841, 6.215), (3, 0.25): (13.896, 6.190),
        (6, 1.0): (13.773, 6.256), (6, 0.5): (13.832, 6.240), (6, 0.25): (13.882, 6.213)}
PUB6 = {(3, 2.0): (13.343, 6.357), (3, 1.0): (13.662, 6.245), (3, 0.5): (13.731, 6.245), (3, 0.25): (13.787, 6.234),
        (6, 2.0): (13.359, 6.437), (6, 1.0): (13.735, 6.277), (6, 0.5): (13.797, 6.251), (6, 0.25): (13.847, 6.231),
        (9, 2.0): (13.380, 6.452), (9, 1.0): (13.750, 6.289), (9, 0.5): (13.812, 6.255), (9, 0.25): (13.863, 6.226)}
col = rows("collapse")
if col:
    tables.append("\n## Collapse: extent / height (m) against [AMPLE] table 5 (GIMP) and [Lagrangian] table 6 (MPM)\n")
    tables.append("| method | points per cell | h (m) | ours | published | difference | wall s |\n|---|---|---|---|---|---|---|\n")
    for r in col:
        t, mp, h = int(param(r, "mpType")), int(param(r, "mp")), 2.0 / int(param(r, "a"))
        pub = (PUB5 if t == 2 else PUB6).get((mp, h))
        ours = (num(r, "extent"), num(r, "height"))
        tables.append("| %s | %dx%d | %g | %s | %s | %s | %.2f |\n" % (
            NAMES[t], mp, mp, h, "%.3f / %.3f" % ours if r["converged"] == "1" else "stopped at step %s" % r["last_step"],
            "%.3f / %.3f" % pub if pub else "-",
            "%+.3f / %+.3f" % (ours[0] - pub[0], ours[1] - pub[1]) if pub and r["converged"] == "1" else "-", num(r, "wall_s")))

# 5. Newton tables -------------------------------------------------------------------------------
for c, steps, pub in ((0, (10, 20, 30, 40), "[Lagrangian] table 8 (collapse, GIMP h = 1 m, 6x6)"),
                      (1, (10, 20, 40, 49, 50), "[Lagrangian] table 3 (beam, GIMP h = 0.125 m, 6x6)")):
    path = os.path.join(OUT, "newton_%d_residuals.csv" % c)
    if not os.path.exists(path):
        continue
    res = {}
    for x in csv.DictReader(open(path)):
        res.setdefault(int(x["lstp"]), []).append(float(x["fErr"]))
    tables.append("\n## Newton-Raphson residuals, compare %s\n" % pub)
    tables.append("| NR it | " + " | ".join("step %d" % s for s in steps) + " |\n|" + "---|" * (len(steps) + 1) + "\n")
    for k in range(max(len(res.get(s, [])) for s in steps)):
        tables.append("| %d | " % k + " | ".join("%.3e" % res[s][k] if k < len(res.get(s, [])) else "-" for s in steps) + " |\n")
    orders = []
    for s in steps:
        v = [x for x in res.get(s, [])[1:] if x > 1e-13]
        if len(v) >= 3:
            orders.append(math.log(v[-1] / v[-2]) / math.log(v[-2] / v[-3]))
    tables.append("\nobserved order (last three residuals above 1e-13): " + ", ".join("%.2f" % o for o in orders) + "\n")

# 6. where the time goes, and the methods ---------------------------------------------------------
TIMES = ["elemMPinfo", "detExtForce", "detFDoFs", "detMPs", "linSolve", "updateMPs", "postPro"]
split = [r for r in scal if r["setup"] == "compaction" and param(r, "nelsy") == "4096"] + beam[:1]
if split:
    tables.append("\n## Where the time goes (compare [Lagrangian] table 5)\n")
    tables.append("| run | " + " | ".join(TIMES) + " | other |\n|" + "---|" * (len(TIMES) + 2) + "\n")
    for r in split:
        w = num(r, "wall_s")
        parts = [num(r, "t_" + t) / w for t in TIMES]
        tables.append("| %s %s | " % (r["setup"], r["parameters"]) + " | ".join("%.1f %%" % (100 * p) for p in parts) + " | %.1f %% |\n" % (100 * (1 - sum(parts))))
met = rows("methods")
if met:
    PUB7 = {"detF": (13.645, 6.316), "Fii": (14.415, 5.546), "Uii": (13.425, 6.441), "corner": (13.769, 6.392),
            "FiiVol": (13.769, 6.257), "FiiVolInc": (13.769, 6.257), "CPDI2": (13.780, 6.292)}
    tables.append("\n## Methods: formulations, GIMP domain updates ([Lagrangian] table 7, as printed), CPDI\n")
    tables.append("| run | converged | extent / height or error | published | NR its | wall s | detMPs s |\n|---|---|---|---|---|---|---|\n")
    for r in met:
        key = param(r, "domainUpdate") or param(r, "mpType")
        val = {"compaction": "%.3e" % num(r, "error"),
               "beam": "tip u/l %.5f, v/l %.5f" % (num(r, "tip_u_over_l"), num(r, "tip_v_over_l"))}.get(
                   r["setup"], "%.3f / %.3f" % (num(r, "extent"), num(r, "height")))
        pub = PUB7.get(key) if r["setup"] == "collapse" else None
        tables.append("| %s %s | %s | %s | %s | %s | %.2f | %.2f |\n" % (
            r["setup"], r["parameters"], "yes" if r["converged"] == "1" else "no (step %s)" % r["last_step"], val,
            "%.3f / %.3f" % pub if pub else "-", r["NR_iterations"], num(r, "wall_s"), num(r, "t_detMPs")))

rem = rows("remedies")
if rem:
    tables.append("\n## Remedies (off by default): ghost penalty and load-step sub-division\n")
    tables.append("| run | completed | last step | result | load-step attempts / NR its | wall s |\n|---|---|---|---|---|---|\n")
    for r in rem:
        res = {"beam": "tip u/l %.4f, v/l %.4f" % (num(r, "tip_u_over_l"), num(r, "tip_v_over_l")),
               "compaction": "error %.3e" % num(r, "error")}.get(r["setup"], "%.3f / %.3f" % (num(r, "extent"), num(r, "height")))
        tables.append("| %s %s | %s | %s | %s | %s | %.2f |\n" % (r["setup"], r["parameters"], "yes" if r["converged"] == "1" else "no",
                                                          r["last_step"], res if r["converged"] == "1" else "-", r["NR_iterations"], num(r, "wall_s")))

sav = rows("savings")
if sav:
    tables.append("\n## What skipping unused work saves (compaction)\n")
    tables.append("| run | wall s | detMPs s | updateMPs s | postPro s |\n|---|---|---|---|---|\n")
    for r in sav:
        tables.append("| %s | %.3f | %.3f | %.3f | %.3f |\n" % (r["parameters"], num(r, "wall_s"), num(r, "t_detMPs"),
                                                        num(r, "t_updateMPs"), num(r, "t_postPro")))

open(os.path.join(OUT, "tables.md"), "w").write("".join(tables))
print("wrote", os.path.join(OUT, "tables.md"))
