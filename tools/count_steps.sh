#!/usr/bin/env bash
#--------------------------------------------------------------------------
# count_steps.sh — how many gdb `step`s from the point loop to a function
#--------------------------------------------------------------------------
# Builds the Debug program (build/debug/ample: cmake --preset debug, target
# ample, as tools/debug.sh does), runs SETUP under gdb in batch mode, stops
# where tools/debug.sh stops by default (the line after
# `MaterialPoint& mp = mpData[p];` in ample/detMPs.cpp: the first point of the
# first Newton-Raphson pass), or at --from WHERE (gdb's `break WHERE`:
# ample::detMPs, the function's entry), then repeats `step` until the frame is in FUNC, or at
# FILE:LINE (--to detMPs.cpp:51: e.g. the point's assembly),
# at most 5000 steps (tools/gdb/count_steps.py, command count-steps), and
# prints each stop as gdb shows it to whoever steps by hand, then the number
# of steps, the functions stopped in on the way, in the order first met, with
# the times each was entered and the steps spent in it, and the backtrace.
# Skipped when stepping (set by tools/gdb/count_steps.py): every file under
# /usr/include (the standard library and Eigen) and the functions whose names
# begin with std::, Eigen:: or __ (the C library's exp and log, which have
# lines when libc6-dbg is installed); functions without line information are
# passed over as gdb always does.
#
# Usage:   tools/count_steps.sh SETUP [name=value ...] --to FUNC|FILE:LINE [--from WHERE]
#                                 [--limit N] [--no-build]
#   e.g.   tools/count_steps.sh compaction --to Hooke3d
#          tools/count_steps.sh collapse a=1 --to VMconst --from ample::detMPs
# The run writes to build/debug/output/SETUP (no VTK, --quiet).
#--------------------------------------------------------------------------
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
usage="usage: tools/count_steps.sh SETUP [name=value ...] --to FUNC|FILE:LINE [--from WHERE] [--limit N] [--no-build]"

[ $# -ge 1 ] && [ "${1#-}" = "$1" ] || { echo "$usage" >&2; exit 2; }
setup="$1"; shift
to="" from="" limit=5000 build=1 args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --to)       [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }; to="$2"; shift 2 ;;
    --limit)    [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }; limit="$2"; shift 2 ;;
    --from)     [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }; from="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    *)          args+=("$1"); shift ;;
  esac
done
[ -n "$to" ] || { echo "$usage" >&2; exit 2; }
command -v gdb > /dev/null || { echo "gdb is not installed: apt-get install gdb" >&2; exit 2; }

if [ "$build" = 1 ]; then
  mkdir -p "$root/build"
  log="$root/build/debug_build.log"
  echo "count_steps.sh: building the Debug program (log: build/debug_build.log)" >&2
  if ! (cd "$root" && { [ -f build/debug/CMakeCache.txt ] || cmake --preset debug; } &&
        cmake --build --preset debug --target ample) > "$log" 2>&1; then
    tail -30 "$log" >&2; echo "count_steps.sh: the Debug build failed" >&2; exit 2
  fi
fi
exe="$root/build/debug/ample"
[ -x "$exe" ] || { echo "count_steps.sh: no $exe (run without --no-build)" >&2; exit 2; }

# the stop of tools/debug.sh: the first line inside the point loop of detMPs
line=$(grep -n 'MaterialPoint& mp = mpData\[p\];' "$root/ample/detMPs.cpp" | tail -1 | cut -d: -f1)
where="${from:-detMPs.cpp:$((line + 1))}"

mkdir -p "$root/build/debug/output"
gdb -q -nx -batch -x "$root/tools/gdb/ample.gdb" -x "$root/tools/gdb/count_steps.py" \
  -ex "break $where" -ex run -ex "count-steps $to $limit" \
  --args "$exe" "$setup" --out "$root/build/debug/output/$setup" --vtk 0 --quiet "${args[@]}" 2>&1 |
  grep -v -e '^\[Thread debugging' -e '^Using host libthread_db' -e '^\[Inferior .* exited' || true
