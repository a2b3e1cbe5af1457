#!/usr/bin/env bash
#--------------------------------------------------------------------------
# check_student.sh — the student copy's tests fail only where they should
#--------------------------------------------------------------------------
# Builds ample and ample_tests in the build folder of a student copy
# (tools/make_student_version.sh; -j2, make's [ NN%] lines shown, the whole
# output in BUILD/build_student.log), runs every CTest test there (ctest -j2)
# and checks what docs/exercises.md promises:
#   - the only failing tests are test cases of an exercise's own suite that
#     reached a blanked exercise, each with exactly one "FAILED: exercise" line;
#   - every other test passes or is skipped with "needs exercise X" (the
#     setup runs included);
#   - every exercise has at least one failing test naming it.
# Prints the count per exercise and the times.
#   tools/check_student.sh STUDENT_BUILD_DIR    # configured: cmake -S COPY -B STUDENT_BUILD_DIR
# Exit status: 0 as promised, 1 not (or the build failed), 2 usage error. Run by .ci/run.
#--------------------------------------------------------------------------
set -uo pipefail
[ $# -eq 1 ] && [ -f "$1/CTestTestfile.cmake" ] || { sed -n '2,17p' "$0"; exit 2; }
BUILD=$(cd "$1" && pwd)
SRC=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$BUILD/CMakeCache.txt")
[ -f "$SRC/STUDENT.md" ] || { echo "$SRC is no student copy (no STUDENT.md)"; exit 2; }
LOG=$BUILD/exercise_log.tsv OUT=$BUILD/ctest_student.log
rm -f "$LOG"
start=$(date +%s)
echo "check_student: building ample and ample_tests of $SRC in $BUILD (-j2; from clean a few minutes)"
cmake --build "$BUILD" -j2 --target ample ample_tests 2>&1 | tee "$BUILD/build_student.log" |
  grep --line-buffered -E '^\[ *[0-9]+%\] (Building|Linking)'
[ "${PIPESTATUS[0]}" -eq 0 ] ||
  { echo "check_student: the build failed ($BUILD/build_student.log):"; grep -m5 -E 'error' "$BUILD/build_student.log"; exit 1; }
echo "check_student: built in $(( $(date +%s) - start )) s; running ctest -j2 in $BUILD (every test of the copy)"
start=$(date +%s)
(cd "$BUILD" && AMPLE_EXERCISE_LOG=$LOG ctest -j2 --output-on-failure > "$OUT" 2>&1)
secs=$(( $(date +%s) - start ))
bad=0
summary=$(grep -E '^[0-9]+% tests passed' "$OUT")
failed=$(echo "$summary" | sed -E 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\1/')
total=$(echo "$summary" | sed -E 's/.* out of ([0-9]+).*/\1/')
skipped=$(grep -cE '\*\*\*Skipped|Not Run' "$OUT")
graded=$(awk -F'\t' '$1 == "graded"' "$LOG" | wc -l)
lines=$(grep -c ': FAILED: exercise ' "$OUT")
echo "student copy: $total tests, $failed failed, $skipped skipped, in ${secs}s (ctest -j2)"
if awk -F'\t' '$1 == "fail"' "$LOG" | grep -q .; then
  echo "tests failing for another reason than an exercise not done:"; awk -F'\t' '$1 == "fail" {print "  " $2 ": " $4}' "$LOG"; bad=1
fi
[ "$failed" = "$graded" ] || { echo "ctest counts $failed failures, the test cases $graded graded ones: a setup or other test failed"; grep -A3 'tests FAILED' "$OUT" | head; bad=1; }
[ "$lines" = "$graded" ] || { echo "$lines 'FAILED: exercise' lines for $graded failing test cases (one each expected)"; bad=1; }
for x in $("$SRC/tools/make_student_version.sh" --list | awk '{print $1}' | sort -u); do
  own=$(awk -F'\t' -v x="$x" '$1 == "graded" && $2 == x && $3 == x' "$LOG" | wc -l)
  dep=$(awk -F'\t' -v x="$x" '$1 == "graded" && $2 == x && $3 != x' "$LOG" | wc -l)
  needs=$(awk -F'\t' -v x="$x" '$1 == "needs" && $3 == x' "$LOG" | wc -l)
  printf '  %-14s %3d failing (own stub)  %3d failing (an earlier exercise)  %3d skipped elsewhere\n' "$x" "$own" "$dep" "$needs"
  [ $((own + dep)) -gt 0 ] || { echo "  $x: no failing test names it"; bad=1; }
done
[ $bad -eq 0 ] && echo "student copy as promised: only the exercises' own suites fail, one line each ($OUT)"
exit $bad
