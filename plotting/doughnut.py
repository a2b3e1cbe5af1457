#!/usr/bin/python3
"""Doughnut twist ([CPDI] sec 3.2): runs the setup for each method and plots
fig 6 (displacement along theta = 0 at alpha = 10 degrees, and the difference to FE)
and figs 7-8 (f / (C E) against alpha). Usage:
  plotting/doughnut.py BUILD/ample OUTDIR [steps] [nr nc] [hole]
Writes docs/results/doughnut_*.csv and .png (names carry the mesh and the hole).
REF=path/summary.json:NR (environment): fig 6's differences against that fine FE run
(nr = NR, e.g. the paper's 160 x 1152) instead of FE on the same mesh.
EXTRA="dalpha=2.5 refine=0.5": more setup parameters for every run."""
import csv, json, os, subprocess, sys, time
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

exe, out = sys.argv[1], sys.argv[2]
steps = int(sys.argv[3]) if len(sys.argv) > 3 else 16
nr, nc = (int(sys.argv[4]), int(sys.argv[5])) if len(sys.argv) > 5 else (10, 72)
hole = int(sys.argv[6]) if len(sys.argv) > 6 else 0
methods = [("FE", ["mpType=1", "fem=1"]), ("MPM", ["mpType=1"]), ("CPDI1", ["mpType=3"]),
           ("CPDI2", ["mpType=4"])]
tag = f"{nr}x{nc}" + ("_ellipse" if hole else "") + os.environ.get("TAG", "")
res = "docs/results"

def run(name, args, lstps):
    d = os.path.join(out, f"doughnut_{tag}_{name}_{lstps}")
    t = time.time()
    rc = subprocess.run([exe, "doughnut", f"nr={nr}", f"nc={nc}", f"hole={hole}", f"lstps={lstps}",
                         "--vtk", "0", "--quiet", "--out", d] + args + os.environ.get("EXTRA", "").split(),
                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    summ = json.load(open(os.path.join(d, "summary.json")))
    hist = list(csv.DictReader(open(os.path.join(d, "history.csv")))) if os.path.exists(
        os.path.join(d, "history.csv")) else []
    return rc.returncode, rc.stderr.strip(), summ, hist, time.time() - t

rows, fig6 = [], {}
yField = "torqueNorm" if hole else "fNorm"  # fig 11 (ellipse): the torque; figs 7-8: f
plt.figure(figsize=(6, 4))
for name, args in methods:
    rc, err, summ, hist, wall = run(name, args, steps)
    a = [float(h["alpha"]) for h in hist]
    f = [float(h[yField]) for h in hist]
    plt.plot(a, f, "o-", ms=3, label=name)
    for h in hist: rows.append([name, h["alpha"], h["f"], h["fNorm"], h["torque"], h["torqueNorm"]])
    print(name, "rc", rc, "last alpha", a[-1] if a else None, "wall", round(wall, 1), "s", err[-300:])
    if hole: continue  # fig 6 is the circle's
    rc2, err2, summ2, hist2, wall2 = run(name, args, 2)
    if rc2 == 0: fig6[name] = summ2.get("results", {})
    else: print(name, "did not reach alpha = 10 degrees:", err2[-200:])
with open(f"{res}/doughnut_{tag}_reaction.csv", "w") as fh:
    w = csv.writer(fh); w.writerow(["method", "alpha_deg", "f", "f_over_CE", "torque", "torque_over_ChE"]); w.writerows(rows)
plt.xlabel("alpha (degrees)"); plt.ylabel("torque / (C_h E)" if hole else "f / (C E)"); plt.legend(); plt.grid(alpha=0.3)
plt.title(f"doughnut {tag}: " + ("torque" if hole else "reaction") + " on the inner boundary")
plt.tight_layout(); plt.savefig(f"{res}/doughnut_{tag}_reaction.png", dpi=120)

if hole: sys.exit(0)
# fig 6: displacement along theta = 0 at alpha = 10 degrees (the 2-step runs) and Pdiff (eq 2)
fe = fig6["FE"]
n = len([k for k in fe if k.startswith("uy_")])
refName = "FE"
if os.environ.get("REF"):  # the fine FE run: its node i (n - 1) / NR ... sampled at ours
    path, rnr = os.environ["REF"].rsplit(":", 1)
    rs, k = json.load(open(path))["results"], int(rnr) // (n - 1)
    fe = {f"u{c}_{i}": rs[f"u{c}_{i * k}"] for c in "xy" for i in range(n)}
    refName = f"FE {rnr} x {int(rnr) * nc // nr}"
r = [5 + (10 - 5) * i / (n - 1) for i in range(n)]
fig, ax = plt.subplots(1, 2, figsize=(10, 4))
with open(f"{res}/doughnut_{tag}_fig6.csv", "w") as fh:
    w = csv.writer(fh); w.writerow(["method", "i", "r", "ux", "uy", "Pdiff_uy", "Pdiff_u"])
    for name in fig6:
        s = fig6[name]
        uy = [s.get(f"uy_{i}", float("nan")) for i in range(n)]
        ux = [s.get(f"ux_{i}", float("nan")) for i in range(n)]
        um = [(a * a + b * b) ** 0.5 for a, b in zip(ux, uy)]
        uf = [(fe[f"ux_{i}"] ** 2 + fe[f"uy_{i}"] ** 2) ** 0.5 for i in range(n)]
        pd = [(uy[i] - fe[f"uy_{i}"]) / fe[f"uy_{i}"] if abs(fe[f"uy_{i}"]) > 0 else float("nan") for i in range(n)]
        pm = [(um[i] - uf[i]) / uf[i] if uf[i] > 0 else float("nan") for i in range(n)]
        for i in range(n): w.writerow([name, i, r[i], ux[i], uy[i], pd[i], pm[i]])
        ax[0].plot(r, um, "o-", ms=3, label=name)
        if name != "FE" or refName != "FE": ax[1].plot(r[1:-1], [100 * abs(p) for p in pm[1:-1]], "o-", ms=3, label=name)
        print(name, "max |Pdiff| of |u| to", refName, "over interior samples (%):", max(100 * abs(p) for p in pm[1:-1]),
              "of uy:", max(100 * abs(p) for p in pd[1:-1]))
ax[0].set_xlabel("r at theta = 0"); ax[0].set_ylabel("|u| at alpha = 10 deg"); ax[0].legend()
ax[1].set_xlabel("r"); ax[1].set_ylabel(f"|Pdiff| of |u| to {refName} (%)"); ax[1].set_yscale("log"); ax[1].legend()
plt.tight_layout(); plt.savefig(f"{res}/doughnut_{tag}_fig6.png", dpi=120)
