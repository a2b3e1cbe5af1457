#!/usr/bin/env bash
#--------------------------------------------------------------------------
# animate_test.sh — the HTML page of plot_run.py --animate in headless Chromium (CTest browser.animate)
#--------------------------------------------------------------------------
# Runs small collapse (ASCII VTK every 2 steps), beam (BINARY VTK every 10 steps), footing
# (every 3 of 10 steps: the last step is not written) and a collapse that stops (a grid too
# narrow), writes each run's page and checks it in headless Chromium with
# tests/animate_check.py: no script error, every frame drawn with the points of its VTK
# file, #frame=last shows the last step, the first and last frames' screenshots differ
# where the body moved, a stopped run's whole message in the title and heading; two
# controls show the checks can fail.
# Skips (exit 77) without chromium or python3 (apt-get install chromium python3).
# Usage: tests/animate_test.sh AMPLE_BINARY WORKDIR
#--------------------------------------------------------------------------
set -euo pipefail
ample="$1" work="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
py=""
for p in /usr/bin/python3 python3; do
  if command -v "$p" > /dev/null; then py="$p"; break; fi
done
[ -n "$py" ] || { echo "SKIPPED: no python3"; exit 77; }
browser=""
for b in chromium chromium-browser; do
  if command -v "$b" > /dev/null; then browser="$(command -v "$b")"; break; fi
done
[ -n "$browser" ] || { echo "SKIPPED: no chromium (apt-get install chromium)"; exit 77; }

rm -rf "$work" && mkdir -p "$work"
"$ample" collapse a=1 mp=2 lstps=10 --vtk 2 --quiet --out "$work/collapse"
"$ample" beam a=1 mp=3 --vtk 10 --vtk-format binary --quiet --out "$work/beam"
"$ample" footing lstps=10 --vtk 3 --quiet --out "$work/footing"
"$ample" collapse a=1 mp=2 lstps=10 width=9 --vtk 2 --quiet --out "$work/stopped" 2> /dev/null &&
  { echo "collapse width=9 was expected to stop (a point leaves the grid)"; exit 1; }
"$py" "$root/tests/animate_check.py" --chromium "$browser" --plot-run "$root/plotting/plot_run.py" \
  --work "$work" "$work/collapse" "$work/beam:uy" "$work/footing:syy" "$work/stopped:J"
