#!/usr/bin/env bash
#--------------------------------------------------------------------------
# plot_run_test.sh — plotting/plot_run.py draws a small run's output (CTest plot.run)
#--------------------------------------------------------------------------
# Runs two small setups (compaction: points and grid; stretch: also history.csv),
# draws each with plotting/plot_run.py (default field, and --original
# --deformed-grid --field uy --history), reads every PNG back with matplotlib and checks
# that it is not blank: at least 64 distinct colours, coloured pixels (the
# viridis points) on at least 2 % of the left panel and the coloured
# convergence lines on at least 0.2 % of the right one. The points' panel is to scale (one
# metre as many pixels in x as in y, the column of compaction too), and a run that stopped
# (collapse on a grid too narrow) has its whole message in the title, inside the picture.
# --step N draws load step N's points (mpData_N.vtk): the left panel's title names step N
# and the program says so; a step with no mpData_N.vtk is refused naming --step and the
# steps written. The history panel puts columns of two units on two y axes (footing:
# settlement against load_kN and imbalance, kN/m and N/m), each labelled with its unit.
# A folder that is not a run's output must give a clear error and a non-zero exit.
# Skips (exit 77) when no python3 with matplotlib is found (/usr/bin/python3 first).
# Usage: tests/plot_run_test.sh AMPLE_BINARY WORKDIR
#--------------------------------------------------------------------------
set -euo pipefail
ample="$1" work="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
py=""
for p in /usr/bin/python3 python3; do
  if command -v "$p" > /dev/null && "$p" -c "import matplotlib" 2> /dev/null; then py="$p"; break; fi
done
[ -n "$py" ] || { echo "SKIPPED: no python3 with matplotlib (apt-get install python3-matplotlib)"; exit 77; }

rm -rf "$work" && mkdir -p "$work"
"$ample" compaction nelsy=8 lstps=5 --vtk 5 --quiet --out "$work/compaction"
"$ample" stretch lstps=5 --vtk 5 --quiet --out "$work/stretch"
"$py" "$root/plotting/plot_run.py" "$work/compaction"
"$py" "$root/plotting/plot_run.py" "$work/stretch" --original --deformed-grid --field uy \
  --history lstp reaction --out "$work/stretch_uy.png"

"$py" - "$work/compaction/run.png" "$work/stretch_uy.png" <<'PY'
import sys
import matplotlib.image as im
import numpy as np
bad = 0
for path in sys.argv[1:]:
    a = im.imread(path)[:, :, :3]
    colours = len(np.unique((a * 255).astype(np.uint8).reshape(-1, 3), axis=0))
    chroma = a.max(axis=2) - a.min(axis=2) > 0.15          # not white, grey or black
    w = a.shape[1]
    left, right = chroma[:, : int(0.6 * w)].mean(), chroma[:, int(0.6 * w):].mean()
    ok = colours >= 64 and left >= 0.02 and right >= 0.002
    print("%s: %dx%d, %d colours, coloured %.3f left / %.4f right: %s"
          % (path, a.shape[1], a.shape[0], colours, left, right, "ok" if ok else "BLANK?"))
    bad += not ok
sys.exit(bad)
PY

# equal axes, and a stopped run's title whole and inside the figure
"$ample" collapse a=1 mp=2 lstps=10 width=9 --vtk 2 --quiet --out "$work/stopped" 2> /dev/null &&
  { echo "collapse width=9 was expected to stop (a point leaves the grid)"; exit 1; }
"$py" - "$root/plotting" "$work" <<'PY'
import json, os, sys
sys.path.insert(0, sys.argv[1])
import matplotlib.pyplot as plt
import plot_run
bad = 0
for run in ("compaction", "stretch", "stopped"):
    outdir = os.path.join(sys.argv[2], run)
    plot_run.main([outdir, "--out", os.path.join(sys.argv[2], run + "_check.png")])
    fig = plt.gcf()
    renderer = fig.canvas.get_renderer()
    (x0, y0), (x1, y1) = fig.axes[0].transData.transform([(0, 0), (1, 1)])
    sx, sy = abs(x1 - x0), abs(y1 - y0)                 # pixels per metre
    equal = abs(sx - sy) <= 1e-6 * max(sx, sy)
    title = fig._suptitle
    box, page = title.get_window_extent(renderer), fig.bbox
    inside = box.x0 >= page.x0 and box.x1 <= page.x1 and box.y0 >= page.y0 and box.y1 <= page.y1
    summary = json.load(open(os.path.join(outdir, "summary.json")))
    whole = " ".join(summary["message"].split()) in " ".join(title.get_text().split())
    ok = equal and inside and whole and (run != "stopped" or not summary["converged"])
    print("%s: %.1f x %.1f pixels per metre, title %s, %s: %s"
          % (run, sx, sy, "inside" if inside else "CUT OFF", "message whole" if whole
             else "MESSAGE CUT", "ok" if ok else "BAD"))
    bad += not ok
    plt.close(fig)
sys.exit(bad)
PY

# --step: the drawn step named in the panel and on stdout; a step not written is refused
out=$("$py" "$root/plotting/plot_run.py" "$work/stopped" --step 2 --out "$work/step2.png")
grep -q "the points of load step 2 (mpData_2.vtk)" <<< "$out" || { echo "--step 2 not said: $out"; exit 1; }
"$py" - "$root/plotting" "$work" <<'PY'
import os, sys
sys.path.insert(0, sys.argv[1])
import matplotlib.pyplot as plt
import plot_run
outdir = os.path.join(sys.argv[2], "stopped")
plot_run.main([outdir, "--step", "2", "--out", os.path.join(sys.argv[2], "step2_check.png")])
title = plt.gcf().axes[0].get_title()
last = plot_run.read_summary(outdir)["last_converged_step"]
ok = "load step 2" in title and last != 2
print("--step 2: left panel '%s' (last converged step %d): %s" % (title, last, "ok" if ok else "BAD"))
sys.exit(0 if ok else 1)
PY
if out=$("$py" "$root/plotting/plot_run.py" "$work/stopped" --step 3 2>&1); then
  echo "plot_run.py --step 3 accepted a step with no mpData_3.vtk"; exit 1
fi
grep -q -- "--step 3: .* has no mpData_3.vtk; the load steps written there: 2, 4" <<< "$out" ||
  { echo "unclear --step error: $out"; exit 1; }

# two units, two y axes, each labelled with its unit
"$ample" footing lstps=4 --vtk 0 --quiet --out "$work/footing"
"$py" - "$root/plotting" "$work" <<'PY'
import os, sys
sys.path.insert(0, sys.argv[1])
import matplotlib.pyplot as plt
import plot_run
outdir = os.path.join(sys.argv[2], "footing")
plot_run.main([outdir, "--history", "settlement", "load_kN,imbalance", "--out", os.path.join(sys.argv[2], "footing.png")])
labels = sorted(ax.get_ylabel() for ax in plt.gcf().axes if ax.get_ylabel() in ("load_kN (kN/m)", "imbalance (N/m)"))
ok = labels == ["imbalance (N/m)", "load_kN (kN/m)"]
print("history axes: %s: %s" % (labels, "ok" if ok else "BAD"))
sys.exit(0 if ok else 1)
PY

if out=$("$py" "$root/plotting/plot_run.py" "$work" 2>&1); then
  echo "plot_run.py accepted $work, which is not a run's output folder"; exit 1
fi
grep -q "has no summary.json" <<< "$out" || { echo "unclear error: $out"; exit 1; }
echo "plot_run.py: 2 pictures not blank, 3 to scale with whole titles, --step drawn and checked, two units on two axes, bad folder refused"
