#!/usr/bin/env bash
#--------------------------------------------------------------------------
# plot_run_test.sh — plotting/plot_run.py draws a small run's output (CTest plot.run)
#--------------------------------------------------------------------------
# Runs two small setups (compaction: points and grid; stretch: also history.csv),
# draws each with plotting/plot_run.py (default field, and --original
# --deformed-grid --field uy --history), reads every PNG back with matplotlib and checks
# that it is not blank: at least 64 distinct colours, coloured pixels (the
# viridis points) on at least 2 % of the left panel and the coloured
# convergence lines on at least 0.2 % of the right one. A folder that is not a
# run's output must give a clear error and a non-zero exit.
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

if out=$("$py" "$root/plotting/plot_run.py" "$work" 2>&1); then
  echo "plot_run.py accepted $work, which is not a run's output folder"; exit 1
fi
grep -q "has no summary.json" <<< "$out" || { echo "unclear error: $out"; exit 1; }
echo "plot_run.py: 2 pictures not blank, bad folder refused"
