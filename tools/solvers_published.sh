#!/usr/bin/env bash
#--------------------------------------------------------------------------
# solvers_published.sh — the published cases with solver=LDLT and other solvers
#--------------------------------------------------------------------------
# Runs every published case (shared/reference: the compaction of [AMPLE] sec 5.1,
# the beams of [AMPLE] sec 5.2 and [Lagrangian] tables 3-4, the collapses of
# [AMPLE] table 5 and [Lagrangian] tables 6-7, PC against UL, the simple shear,
# the stretch of [CPDI] sec 3.1, the block, deep beam and shear of [Boundaries]
# sec 5) with solver=LDLT, the reference, and with each SOLVER given, one
# thread, no VTK, and writes one CSV row a case: each run's exit code and passes
# (rows of residuals.csv), whether the other solver's step log (load step and
# pass of every row) is LDLT's, and its points' largest difference from LDLT's
# over the largest value of that quantity (the stresses as one quantity), with
# the column where it lies.
# Usage:   tools/solvers_published.sh BUILD_DIR OUT.csv SOLVER [SOLVER ...]
#   e.g.   tools/solvers_published.sh build/fast docs/results/solvers_published.csv MUMPS LU
# With MUMPS and LU it took 17 minutes on one core (2026-12-05; the deep beam
# with 40 x 40 points per cell and the collapse at h = 0.25 m the longest).
#--------------------------------------------------------------------------
set -uo pipefail
[ $# -ge 3 ] || { echo "usage: tools/solvers_published.sh BUILD_DIR OUT.csv SOLVER [SOLVER ...]" >&2; exit 2; }
bin="$1/ample"; out="$2"; shift 2
solvers=("$@")
[ -x "$bin" ] || { echo "solvers_published.sh: no program $bin (build it first)" >&2; exit 2; }
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT

cases=()
for t in 1 2; do for e in $(seq 2 13); do cases+=("compaction mpType=$t nelsy=$((1 << e))"); done; done
for mp in 2 3 4 6; do cases+=("beam a=2 mp=$mp"); done
for t in 1 2 4; do for a in 1 2 4; do cases+=("beam mpType=$t a=$a mp=6"); done; done
cases+=("beam formulation=2")
for a in 2 4 8; do for mp in 3 6; do cases+=("collapse mpType=2 a=$a mp=$mp"); done; done
for a in 1 2 4 8; do for mp in 3 6 9; do cases+=("collapse mpType=1 a=$a mp=$mp"); done; done
for u in none detF Fii Uii corner FiiVol FiiVolInc; do cases+=("collapse mp=6 domainUpdate=$u"); done
cases+=("collapse mp=6 mpType=CPDI1" "collapse mp=6 mpType=CPDI2" "collapse mp=6 formulation=2")
cases+=("shear" "shear formulation=2")
for t in 1 3 4; do cases+=("stretch mpType=$t"); done
for th in 0 30 45 90; do cases+=("ibblock theta=$th"); done
for mp in 3 5 10 15 20 25 40; do cases+=("deepbeam mp=$mp"); done
for h in 0.005 0.002 0.001; do cases+=("deepbeam mp=4 h=$h"); done
for x in 0 0.025 0.05 0.075 0.1; do cases+=("ibshear xA=$x"); done

header="case,LDLT_exit,LDLT_passes"
for s in "${solvers[@]}"; do header+=",${s}_exit,${s}_passes,${s}_same_passes,${s}_vs_LDLT,${s}_vs_LDLT_column"; done
echo "$header" > "$out"

run() {  # run SOLVER CASE...: the exit code, the step log in $work/SOLVER.steps
  local s="$1"; shift
  rm -rf "$work/$s"
  OMP_NUM_THREADS=1 "$bin" "$@" solver="$s" --vtk 0 --quiet --out "$work/$s" > /dev/null 2>&1
  local rc=$?
  tail -n +2 "$work/$s/residuals.csv" 2> /dev/null | cut -d, -f1,2 > "$work/$s.steps"
  echo "$rc"
}

for c in "${cases[@]}"; do
  # shellcheck disable=SC2086
  row="\"$c\",$(run LDLT $c),$(wc -l < "$work/LDLT.steps")"
  for s in "${solvers[@]}"; do
    # shellcheck disable=SC2086
    rc=$(run "$s" $c)
    same=0; cmp -s "$work/LDLT.steps" "$work/$s.steps" && same=1
    diff=$(python3 - "$work/LDLT/mp_final.csv" "$work/$s/mp_final.csv" << 'EOF'
import csv, sys
def load(f):
    with open(f) as h:
        r = csv.reader(h); head = next(r)
        return head, [list(map(float, x)) for x in r]
try:
    ha, a = load(sys.argv[1]); hb, b = load(sys.argv[2])
except (OSError, ValueError, StopIteration):
    print(","); sys.exit()
if ha != hb or len(a) != len(b):
    print("points differ,"); sys.exit()
group = lambda n: "s" if n.startswith("s") else n     # the stresses: one quantity
scale = {}
for j, n in enumerate(ha):
    scale[group(n)] = max(scale.get(group(n), 0.0), max((abs(r[j]) for r in a), default=0.0))
worst, where = 0.0, ""
for j, n in enumerate(ha):
    if scale[group(n)] > 0:
        d = max((abs(x[j] - y[j]) for x, y in zip(a, b)), default=0.0) / scale[group(n)]
        if d > worst: worst, where = d, n
print("%.2e,%s" % (worst, where))
EOF
)
    row+=",$rc,$(wc -l < "$work/$s.steps"),$same,$diff"
  done
  echo "$row" >> "$out"
done
