#!/usr/bin/env bash
#--------------------------------------------------------------------------
# debug.sh — one command from a setup to gdb stopped in the point loop
#--------------------------------------------------------------------------
# Builds the Debug program only (cmake --preset debug, target ample: -O0 -g3,
# Eigen values NaN until set), loads our Eigen printers (tools/gdb/eigen.py),
# the skips that keep `step` in our code (tools/gdb/skips.py: the standard
# library, Eigen, the C library's maths) and the `point` command
# (tools/gdb/ample.gdb), and runs the setup under gdb
# up to the first stop at WHERE:
#   detMPs (default)  the first line inside the point loop, `mp` in scope
#   any other name    gdb's `break NAME` (e.g. VMconst); `point` then shows
#                     the point being worked on and selects detMPs' frame
# Usage:   tools/debug.sh SETUP [name=value ...] [--break WHERE] [--no-build]
#                         [--ex 'GDB COMMAND' ...]
#   e.g.   tools/debug.sh compaction nelsy=4 lstps=4
#          tools/debug.sh collapse a=1 --break VMconst
#   --ex:  run these gdb commands at the stop and exit (batch mode, as the test does)
# The run writes to build/debug/output/SETUP (no VTK) unless --out / --vtk are given.
# Tests:   tests/debug_recipe.sh (CTest debug.script, debug.readme)
#--------------------------------------------------------------------------
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
usage="usage: tools/debug.sh SETUP [name=value ...] [--break WHERE] [--no-build] [--ex 'GDB COMMAND' ...]"

[ $# -ge 1 ] && [ "${1#-}" = "$1" ] || { echo "$usage" >&2; exit 2; }
setup="$1"; shift
where=detMPs build=1 args=() cmds=()
while [ $# -gt 0 ]; do
  case "$1" in
    --break) [ $# -ge 2 ] || { echo "option '--break' needs a function name, e.g. VMconst" >&2; exit 2; }
             where="$2"; shift 2 ;;
    --ex)    [ $# -ge 2 ] || { echo "option '--ex' needs a gdb command, e.g. 'p mp.F'" >&2; exit 2; }
             cmds+=(-ex "$2"); shift 2 ;;
    --no-build) build=0; shift ;;
    *)       args+=("$1"); shift ;;
  esac
done
command -v gdb > /dev/null || { echo "gdb is not installed: apt-get install gdb" >&2; exit 2; }

if [ "$build" = 1 ]; then
  mkdir -p "$root/build"
  log="$root/build/debug_build.log"
  [ -x "$root/build/debug/ample" ] && when="up to date in seconds unless sources changed" ||
    when="a first build takes 2-4 minutes on 2 cores"
  echo "debug.sh: building the Debug program ($when; log: build/debug_build.log)" >&2
  # the build's [ NN%] progress on one line of stderr, everything else to the log
  if ! (cd "$root" && { [ -f build/debug/CMakeCache.txt ] || cmake --preset debug; } &&
        cmake --build --preset debug --target ample) 2>&1 | tee "$log" |
       { grep --line-buffered -o '^\[ *[0-9]*%\]' || true; } |
       while read -r p; do printf '\r  %s' "$p" >&2; done; then
    echo >&2; cat "$log" >&2; echo "debug.sh: the Debug build failed" >&2; exit 2
  fi
  echo >&2
fi
exe="$root/build/debug/ample"
[ -x "$exe" ] || { echo "debug.sh: no $exe (run without --no-build)" >&2; exit 2; }

# detMPs: stop where the loop has its point, not at the entry (no `mp` there yet)
if [ "$where" = detMPs ]; then
  line=$(grep -n 'MaterialPoint& mp = mpData\[p\];' "$root/ample/detMPs.cpp" | tail -1 | cut -d: -f1)
  where="detMPs.cpp:$((line + 1))"
fi

batch=() defaults=()
[ ${#cmds[@]} -gt 0 ] && batch=(-batch)
own=" ${args[*]:-} "                           # the program refuses an option given twice
[[ "$own" == *" --out "* ]] || defaults+=(--out "$root/build/debug/output/$setup")
[[ "$own" == *" --vtk "* ]] || defaults+=(--vtk 0)
exec gdb -q -nx "${batch[@]}" -x "$root/tools/gdb/eigen.py" -x "$root/tools/gdb/skips.py" -x "$root/tools/gdb/ample.gdb" \
  -ex "set breakpoint pending on" -ex "break $where" -ex run "${cmds[@]}" \
  --args "$exe" "$setup" "${defaults[@]}" "${args[@]}"
