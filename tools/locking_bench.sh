#!/usr/bin/env bash
#--------------------------------------------------------------------------
# locking_bench.sh — the volumetric-locking benchmark: run time against error, with and without
#                    the anti-locking option (locking=none, locking=Fbar)
#--------------------------------------------------------------------------
# Runs the three locking setups over their grids (docs/setups.md: prandtl, lame, layer), each
# with every value of LOCKING, and writes one CSV row per run: the commit, the setup, its
# parameters, the locking choice, the exit code, the wall time (s) and the run's three error
# figures from summary.json (name and value). A figure that is undefined is an empty field.
#   prandtl: q_over_cu, error = (q/c_u) / (2 + pi) - 1, plateau_change
#            nB = 2 4 8 (16 with FULL=1), rough 0 1, MPM and GIMP, nu = 0.3 and 0.49, substeps=4
#            (a load step that fails is retried in halves; a run that converges is unchanged)
#   lame:    error_inner, error_max, stress_rms; nels = 4 8 16 32, nu = 0.3 and 0.4999, MPM and CPDI2
#   layer:   checker_rms, dev_all_rms, dev_cell_rms; sides=free, nels = 4 8 16 32, nu = 0.49, 0.499
#            (and nu = 0.3), MPM; sides=roller at nels = 8
# Usage:  tools/locking_bench.sh [OUT.csv]        (default docs/results/locking_<commit>.csv)
#   env:  AMPLE=build/release/ample  LOCKING="none Fbar"  FULL=0|1  SETUPS="prandtl lame layer"
# Needs python3 (reads summary.json). Run from the repository root on an idle machine.
#--------------------------------------------------------------------------
set -euo pipefail
AMPLE=${AMPLE:-build/release/ample}
LOCKING=${LOCKING:-"none Fbar"}
FULL=${FULL:-0}
SETUPS=${SETUPS:-"prandtl lame layer"}
commit=$(git rev-parse --short HEAD)
[ -z "$(git status --porcelain --untracked-files=no)" ] || commit="$commit+dirty"
out=${1:-docs/results/locking_${commit}.csv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$AMPLE" ] || { echo "locking_bench.sh: no program at $AMPLE (build it, or set AMPLE)" >&2; exit 2; }
mkdir -p "$(dirname "$out")"
echo "commit,setup,params,locking,exit,wall_s,name1,value1,name2,value2,name3,value3" > "$out"

# one run: setup, the three result names, then its parameters
run() {
  local setup=$1 n1=$2 n2=$3 n3=$4
  shift 4
  for lock in $LOCKING; do
    local t0 t1 rc=0
    t0=$(date +%s.%N)
    "$AMPLE" "$setup" "$@" locking="$lock" --vtk 0 --quiet --out "$tmp/run" >/dev/null 2>"$tmp/err" || rc=$?
    t1=$(date +%s.%N)
    python3 - "$tmp/run/summary.json" "$commit" "$setup" "$*" "$lock" "$rc" "$t0" "$t1" "$n1" "$n2" "$n3" >> "$out" <<'PY'
import json, sys
path, commit, setup, params, lock, rc, t0, t1, *names = sys.argv[1:]
try:
    res = json.load(open(path))["results"]
except (OSError, ValueError, KeyError):
    res = {}
cells = [commit, setup, params, lock, rc, "%.3f" % (float(t1) - float(t0))]
for n in names:
    v = res.get(n)
    cells += [n, "" if v is None else "%.6g" % v]
print(",".join(cells))
PY
    tail -1 "$out"
  done
}

grids_p="2 4 8"
[ "$FULL" = 1 ] && grids_p="2 4 8 16"
for s in $SETUPS; do
  case $s in
    prandtl)
      for nu in 0.3 0.49; do for type in MPM GIMP; do for rough in 1 0; do for n in $grids_p; do
        run prandtl q_over_cu error plateau_change nB=$n rough=$rough mpType=$type nu=$nu substeps=4
      done; done; done; done ;;
    lame)
      for nu in 0.3 0.4999; do for type in MPM CPDI2; do for n in 4 8 16 32; do
        run lame error_inner error_max stress_rms nels=$n nu=$nu mpType=$type
      done; done; done ;;
    layer)
      for nu in 0.49 0.499 0.3; do for n in 4 8 16 32; do
        run layer checker_rms dev_all_rms dev_cell_rms sides=free nels=$n nu=$nu mpType=MPM
      done; done
      run layer checker_rms dev_all_rms dev_cell_rms sides=roller nels=8 nu=0.49 mpType=MPM ;;
    *) echo "locking_bench.sh: unknown setup '$s' (prandtl, lame, layer)" >&2; exit 2 ;;
  esac
done
echo "locking_bench.sh: $out"
