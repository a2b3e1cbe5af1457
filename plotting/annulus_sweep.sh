#!/bin/bash
# annulus_sweep.sh — fig 19 of [Lagrangian]: the annulus error against h for mpTri = 1, 4, 8, 9, 16
# (both readings of the paper's "12, 22, 23, 24"); each run capped at CAP seconds.
# Writes docs/results/annulus.csv (h, mpTri, error, max point error, points, seconds, rc).
# Run from the repository root after building: plotting/annulus_sweep.sh [CAP]
CAP=${1:-120}
OUT=docs/results/annulus.csv
echo "h,mpTri,error,max_point_error,points,seconds,rc" > $OUT
for h in 0.43633 0.21817 0.10908 0.05454 0.02727; do
  for m in 1 4 8 9 16; do
    d=/tmp/annulus_sweep_${h}_$m
    timeout $CAP build/release/ample annulus h=$h mpTri=$m --vtk 0 --quiet --out $d > /dev/null 2>&1
    rc=$?
    /usr/bin/python3 - "$d/summary.json" $h $m $rc >> $OUT <<'PY'
import json, sys
f, h, m, rc = sys.argv[1:]
try:
    s = json.load(open(f)); r = s['results']
    t = s['wall_seconds']
    print(f"{h},{m},{r['error']:.6e},{r['max_point_error']:.6e},{int(r['points'])},{t},{rc}")
except Exception:
    print(f"{h},{m},,,,,{rc}")
PY
  done
done
