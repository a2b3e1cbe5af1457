#!/usr/bin/env bash
#--------------------------------------------------------------------------
# debug_recipe.sh — the README's debugger recipes, run as written (CTest debug.readme)
#--------------------------------------------------------------------------
# Reads the section "Stepping through in a debugger" of README.md: each command
# line that starts gdb (`tools/debug.sh ...` or `gdb ...`) and the `(gdb) ...`
# lines of the block after it. Runs each in gdb's batch mode (debug.sh: the
# first one builds the Debug program, the others --no-build; gdb: -batch -nx
# added), and checks the output:
#   - the breakpoint is hit and the program has not ended before the commands;
#   - no gdb error (no symbol, no frame, undefined command, Python exception);
#   - every print gives a value, in the form our printers promise:
#       p ....F       [3x3] {{n, n, n}, {n, n, n}, {n, n, n}}
#       p uvw         [N] {n, n, ...
#       p mp, p mpData[k], point   a point whose F, sig, epsE are such matrices and
#                     whose basis is there (ample/mpData.h: arrays of MAXN = 16):
#                     nn = N, nIN = {N node numbers, ...}, Svp = {N numbers, ...},
#                     dSvp = [2x16] {{N numbers, ...}, {N numbers, ...}}
#       p ....nIN     {n, n, ...} node numbers
#       p ....sig, p epsEtr        [6] {six numbers}
#       pmat X        "X = [RxC]" then R rows of C numbers
#       finish        "Value returned is"
#   - and the stated values of the first stop of the first recipe (compaction,
#     first pass: nothing has moved): mp.F = I, uvw all zero;
#   - from that stop, `step` reaches Hooke3d in at most the steps the README states
#     ("Hooke3d: N steps"), with the recipe's own skips (tools/gdb/skips.py).
# Skips (exit 77) when gdb is not installed, and in the student copy (docs/exercises.md).
# Usage: tests/debug_recipe.sh   (from anywhere; works in the source tree)
#--------------------------------------------------------------------------
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
command -v gdb > /dev/null || { echo "SKIPPED: gdb is not installed (apt-get install gdb)"; exit 77; }
[ -f STUDENT.md ] && { echo "SKIPPED: the student copy (STUDENT.md): the recipes step through the solved program (docs/exercises.md)"; exit 77; }

num='-?(nan|inf|[0-9.]+(e[-+]?[0-9]+)?)'
mat3="\[3x3\] \{\{$num, $num, $num\}, \{$num, $num, $num\}, \{$num, $num, $num\}\}"
vec6="\[6\] \{$num, $num, $num, $num, $num, $num\}"
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# the basis of every point printed whole (p mp, p mpData[k], point): after each `nn = N`,
# nIN starting with N node numbers, Svp with N numbers and dSvp [2x16] of two rows starting
# with N numbers (the rest of the arrays: zeros, as gdb shows them, e.g. 0 <repeats 12 times>).
# Prints the number of points so shown, or "bad: ..." for the first that is not. A point
# printed on one line (plain gdb, no `set print pretty`) is cut into lines at these members.
basis_shown() {
  sed -E 's/, (nn|ne|nIN|Svp|dSvp|Fn) = /,\n\1 = /g' | awk -v num="$num" '
    function count(list, whole,   a, k, n) {              # leading number entries of "{a, b, c, ...}"
      gsub(/^[{]|[}]$/, "", list); n = split(list, a, ", ")
      for (k = 1; k <= n; k++) if (a[k] !~ (whole ? "^[0-9]+$" : "^(" num ")$")) return k - 1
      return n
    }
    function bad(what) { print "bad: " what " for nn = " nn; failed = 1; exit }
    /^ *nn = [0-9]+,$/ { nn = $3 + 0; want = 3; next }
    want && /^ *nIN = / { sub(/^ *nIN = /, ""); sub(/,$/, ""); if (count($0, 1) < nn) bad("nIN " $0); want--; next }
    want && /^ *Svp = / { sub(/^ *Svp = /, ""); sub(/,$/, ""); if (count($0, 0) < nn) bad("Svp " $0); want--; next }
    want && /^ *dSvp = / { sub(/^ *dSvp = /, ""); sub(/,$/, "")
                           if ($0 !~ ("^\\[2x16\\] [{][{].*[}], [{].*[}][}]$")) bad("dSvp " $0)
                           sub(/^[^{]*[{]/, ""); sub(/[}]$/, ""); split($0, r, "[}], [{]")
                           if (count(r[1], 0) < nn || count(r[2], 0) < nn) bad("dSvp rows " $0)
                           if (!--want) shown++
                           next }
    END { if (failed) exit; if (want) print "bad: the basis of a point with nn = " nn " is not all there"
          else print shown + 0 }'
}

# the section, then recipes as "COMMAND<TAB>gdb line<TAB>gdb line ..."
section=$(awk '/^## Stepping through in a debugger/ {on = 1; next} /^## / {on = 0} on' README.md)
recipes=$(awk -F'\n' '
  /^(tools\/debug\.sh|gdb) / { if (cmd != "") print cmd; cmd = $0; sub(/[ ]+#.*$/, "", cmd); next }
  /^\(gdb\) / { line = substr($0, 7); sub(/[ ]+#.*$/, "", line); cmd = cmd "\t" line }
  END { if (cmd != "") print cmd }' <<< "$section")
[ -n "$recipes" ] || { echo "FAIL: no recipe found in README.md"; exit 1; }

n=0 built=0
while IFS=$'\t' read -r -u 3 -a parts; do
  n=$((n + 1))
  cmd="${parts[0]}"
  cmds=("${parts[@]:1}")
  [ ${#cmds[@]} -gt 0 ] || { fail "recipe $n ($cmd) has no (gdb) lines"; continue; }
  read -r -a words <<< "$cmd"
  ex=()
  if [ "${words[0]}" = tools/debug.sh ]; then
    for c in "${cmds[@]}"; do ex+=(--ex "$c"); done
    [ "$built" = 1 ] && ex+=(--no-build)                 # the first one builds
    out=$("${words[@]}" "${ex[@]}" < /dev/null 2>&1)
    built=1
  else
    for c in "${cmds[@]}"; do ex+=(-ex "$c"); done
    opts=() prog=()                                      # gdb runs -x and -ex in their order:
    for w in "${words[@]:1}"; do                         # the README's options first
      if [ ${#prog[@]} -gt 0 ] || [ "$w" = --args ]; then prog+=("$w"); else opts+=("$w"); fi
    done
    out=$(gdb -batch -nx "${opts[@]}" "${ex[@]}" "${prog[@]}" < /dev/null 2>&1)
  fi
  echo "== recipe $n: $cmd"
  echo "$out" | sed 's/^/   /' | head -200

  grep -q "^Breakpoint 1, " <<< "$out" || fail "recipe $n: the breakpoint was not hit"
  grep -Eq "exited normally|exited with code" <<< "$out" && fail "recipe $n: the program ended"
  grep -Eq "No symbol|No frame|Undefined command|There is no member|Python Exception|Cannot access|not defined in" \
    <<< "$out" && fail "recipe $n: gdb reported an error (above)"
  prints=0
  for c in "${cmds[@]}"; do
    case "$c" in
      p\ *|print\ *) prints=$((prints + 1)); e="${c#* }"
        case "$e" in
          *.F) grep -Eq "^\\\$[0-9]+ = $mat3\$" <<< "$out" || fail "recipe $n: '$c' is not a 3x3 matrix" ;;
          uvw) grep -Eq "^\\\$[0-9]+ = \[[0-9]+\] \{$num, $num" <<< "$out" || fail "recipe $n: '$c' shows no entries" ;;
          *.sig|epsEtr) grep -Eq "^\\\$[0-9]+ = $vec6\$" <<< "$out" || fail "recipe $n: '$c' is not a 6-vector" ;;
          *.nIN) grep -Eq "^\\\$[0-9]+ = \{[0-9]+( <repeats [0-9]+ times>)?(, [0-9]+( <repeats [0-9]+ times>)?)*\}\$" <<< "$out" || fail "recipe $n: '$c' shows no node numbers" ;;
          mp|mpData\[*\]) for m in "F = $mat3" "sig = $vec6" "epsE = $vec6"; do
                            grep -Eq "(^ *|[{ ])$m(,|\$|\})" <<< "$out" || fail "recipe $n: '$c' has no '${m%% *}' as a matrix"
                          done
                          basis=$(basis_shown <<< "$out")
                          [[ "$basis" =~ ^[1-9] ]] || fail "recipe $n: '$c' shows no whole basis (nn, nIN, Svp, dSvp): $basis" ;;
        esac ;;
      point) prints=$((prints + 1))
             grep -Eq "^point [0-9]+ of [0-9]+ in mpData" <<< "$out" || fail "recipe $n: 'point' names no point"
             grep -Eq "^ *F = $mat3,?\$" <<< "$out" || fail "recipe $n: 'point' shows no F"
             basis=$(basis_shown <<< "$out")
             [[ "$basis" =~ ^[1-9] ]] || fail "recipe $n: 'point' shows no whole basis (nn, nIN, Svp, dSvp): $basis" ;;
      pmat\ *) e="${c#pmat }"
               rows=$(grep -F -A8 "$e = [" <<< "$out" | grep -cE "^  +$num( +$num)*\$")
               [ "$rows" -ge 2 ] || fail "recipe $n: '$c' printed no rows" ;;
      finish) grep -q "Value returned is" <<< "$out" || fail "recipe $n: 'finish' returned no value" ;;
    esac
  done
  got=$(grep -cE '^\$[0-9]+ = ' <<< "$out")
  [ "$got" -ge "$prints" ] || fail "recipe $n: $prints prints, $got values"
  [ "$n" = 1 ] && first=("${words[@]}")
  if [ "$n" = 1 ]; then                                  # the stated values of the first stop
    grep -Eq '^\$[0-9]+ = \[3x3\] \{\{1, 0, 0\}, \{0, 1, 0\}, \{0, 0, 1\}\}$' <<< "$out" ||
      fail "recipe 1: mp.F at the first stop is not [3x3] {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}"
    grep -Eq '^\$[0-9]+ = \[[0-9]+\] \{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, \.\.\. \([0-9]+ more\)\}$' <<< "$out" ||
      fail "recipe 1: uvw at the first stop is not all zero"
  fi
done 3<<< "$recipes"

# the README's count of `step`s from the first recipe's stop to Hooke3d ("Hooke3d: N steps"),
# with the recipe as written: tools/debug.sh loads the skips (tools/gdb/skips.py); without
# them `step` enters the standard library and Eigen and takes thousands
stated=$(tr '\n' ' ' < README.md | grep -oE 'Hooke3d: [0-9]+ +steps' | head -1 | sed -E 's/^Hooke3d: ([0-9]+).*/\1/')
if [ -z "$stated" ]; then fail "README.md states no 'Hooke3d: N steps'"
elif [ "${first[0]:-}" != tools/debug.sh ]; then fail "the first recipe is not tools/debug.sh"
else
  walk="python n = next((k for k in range(1, 5001) if (gdb.execute('step', to_string=True) or True) and gdb.selected_frame().name().endswith('Hooke3d')), None); print('steps to Hooke3d:', n)"
  steps=$("${first[@]}" --no-build --ex "$walk" < /dev/null 2>&1 | grep -oE '^steps to Hooke3d: [0-9]+' | grep -oE '[0-9]+$')
  echo "== the first recipe, then step to Hooke3d: ${steps:-never} steps (README: $stated)"
  [ -n "$steps" ] && [ "$steps" -le "$stated" ] || fail "step from the first recipe's stop reaches Hooke3d in ${steps:-over 5000} steps, the README says $stated"
fi

[ "$fails" = 0 ] || { echo "$fails check(s) failed"; exit 1; }
echo "debug recipes: $n run, every check passed"
