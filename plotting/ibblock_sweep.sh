#!/bin/sh
# ibblock_sweep.sh — [Boundaries] figs 10-13: the contained block's ru and r_sxx (eqs 29-30)
# against the grid spacing h and the band width delta/h, at 30, 45 and 90 degrees, with
# the paper's K2 coupling (ibK2=0) and the consistent one (ibK2=1).
# usage: plotting/ibblock_sweep.sh [build/release/ample] > docs/results/ibblock_sweep.csv
# tol = 1e-6: SS is linear, one solve gives the answer, and the round-off floor of fErr
# grows as (h / delta) sqrt(nDoF) (1.6e-8 at h = 1 mm, delta = 1e-6 h).
# (about 240 runs, 2-3 minutes on 2 cores; then plotting/plot_ibblock.py)
AMPLE=${1:-build/release/ample}
OUT=$(mktemp -d)
echo "theta,h_m,delta_over_h,ibK2,ru,r_sxx,seconds"
for k in 0 1; do
  for th in 30 45 90; do
    for h in 0.02 0.01 0.005 0.002 0.001; do
      for d in 1e-1 1e-2 1e-3 1e-4 1e-5 1e-6 1e-7 1e-8; do
        "$AMPLE" ibblock theta=$th h=$h delta=$d ibK2=$k tol=1e-6 NRitMax=4 --vtk 0 --quiet --out "$OUT" >/dev/null 2>&1
        ru=$(grep -o '"ru": [^,}]*' "$OUT/summary.json" | cut -d' ' -f2)
        rs=$(grep -o '"r_sxx": [^,}]*' "$OUT/summary.json" | cut -d' ' -f2)
        t=$(grep -o '"wall_seconds": [^,}]*' "$OUT/summary.json" | cut -d' ' -f2)
        echo "$th,$h,$d,$k,$ru,$rs,$t"
      done
    done
  done
done
rm -rf "$OUT"
