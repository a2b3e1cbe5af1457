#!/usr/bin/env bash
#--------------------------------------------------------------------------
# grading.sh — the test of the tests: does each exercise's suite reject the
# trivial wrong answers? (the classroom kit, docs/exercises.md)
#--------------------------------------------------------------------------
# For each exercise X (the `// BEGIN EXERCISE X` regions) the folder
# tools/wrong_answers/X/ holds wrong answers, one file each: the text that
# replaces the region(s) of X (several regions separated by a line
# "// NEXT REGION"; tools/make_student_version.sh --fill). The script copies
# the tree to a work folder outside the worktree, builds it and checks that
# every suite X passes there; then for each wrong answer (and for the stub of
# the student copy) it pastes it in, rebuilds ample_tests (only the changed
# file recompiles) and runs `ample_tests -ts=X`: "rejected" when the suite
# fails, "ACCEPTED" when it passes. The file is restored after each one.
#
#   tools/grading.sh                 # every exercise
#   tools/grading.sh VMconst SvpGIMP # some of them
#   tools/grading.sh --list          # the wrong answers, with their first comment line
# Environment: AMPLE_GRADING_DIR  work folder (default /tmp/ample-grading-$USER)
# Progress: the first build of the work folder (the whole tree, a few minutes on 2 cores) shows
# make's [ NN%] lines; then one line per wrong answer as it is built and run (a few seconds each).
# Instructor's tree only: the student copy has neither this script nor tools/wrong_answers.
# Exit status: 0 every wrong answer rejected, 1 some accepted (or did not build), 2 setup error
# Not part of the default ctest: configure with -DAMPLE_GRADING=ON to get the
# CTest test "grading" (label grading). Documented in docs/exercises.md.
#--------------------------------------------------------------------------
set -u
SRC=$(cd "$(dirname "$0")/.." && pwd)
WORK=${AMPLE_GRADING_DIR:-/tmp/ample-grading-${USER:-$(id -u)}}
ANSWERS=$SRC/tools/wrong_answers
EXERCISES=$("$SRC/tools/make_student_version.sh" --list | awk '{print $1}' | sort -u)

if [ "${1:-}" = --list ]; then
  for x in $EXERCISES; do
    for w in "$ANSWERS/$x"/*.inc; do
      printf '%-14s %-22s %s\n' "$x" "$(basename "$w" .inc)" "$(sed -n 's|^ *// wrong answer: ||p' "$w" | head -1)"
    done
  done
  exit 0
fi
[ "${1:-}" = -h ] || [ "${1:-}" = --help ] && { sed -n '2,27p' "$0"; exit 0; }
SELECT=${*:-$EXERCISES}

mkdir -p "$WORK/src" "$WORK/build" || exit 2
"$SRC/tools/sync_tree.sh" "$SRC" "$WORK/src"
build() { cmake --build "$WORK/build" -j2 --target ample_tests >"$WORK/build.log" 2>&1; }
build_shown() {  # the same, with make's [ NN%] lines shown
  cmake --build "$WORK/build" -j2 --target ample_tests 2>&1 | tee "$WORK/build.log" |
    grep --line-buffered -E '^\[ *[0-9]+%\] (Building|Linking)' | sed -u 's/^/  /'
  return "${PIPESTATUS[0]}"
}
suite() {  # the suite of exercise $1; $WORK/cases.tsv: status, suite, exercise, case (main_tests.cpp)
  rm -f "$WORK/cases.tsv"
  (cd "$WORK/build/tests" &&
     AMPLE_EXERCISE_LOG=$WORK/cases.tsv timeout 900 ./ample_tests -ts="$1" >"$WORK/tests.log" 2>&1)
}
if [ ! -f "$WORK/build/CMakeCache.txt" ]; then
  cmake -S "$WORK/src" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release -DAMPLE_DISCOVER_TESTS=OFF >"$WORK/configure.log" 2>&1 ||
    { echo "configure failed: $WORK/configure.log"; exit 2; }
fi
echo "grading check: tree $SRC, work folder $WORK"
echo "building ample_tests in $WORK/build (Release, -j2; only what changed since its last run)"
start=$(date +%s)
build_shown || { echo "the tree does not build: $WORK/build.log"; exit 2; }
echo "built in $(( $(date +%s) - start )) s; the suites on the solution:"
for x in $SELECT; do
  suite "$x" || { echo "the suite $x fails on the solution: $WORK/tests.log"; exit 2; }
done
echo "solution: the suites of $(echo $SELECT | wc -w) exercises pass; each wrong answer: paste, rebuild ample_tests, run its suite"

status=0 total=0 rejected=0 clr=""
[ -t 1 ] && clr=$'\033[K'   # on a terminal: "building..." shown while each one builds, then erased
for x in $SELECT; do
  file=$(cd "$WORK/src" && grep -rlE "^[[:space:]]*// BEGIN EXERCISE $x[[:space:]]*\$" ample constitutive | head -1)
  [ -n "$file" ] || { echo "$x: no region in the tree"; status=1; continue; }
  target=$WORK/src/$file
  for w in stub "$ANSWERS/$x"/*.inc; do
    [ "$w" = stub ] || [ -f "$w" ] || continue
    name=$([ "$w" = stub ] && echo "(student stub)" || basename "$w" .inc)
    cp "$target" "$WORK/original"
    "$SRC/tools/make_student_version.sh" --fill "$target" "$x" "$w" || { status=1; continue; }
    [ -t 1 ] && printf '%-14s %-22s building...\r' "$x" "$name"
    start=$(date +%s) detail=""
    total=$((total + 1))
    if ! build; then
      verdict=BUILD-ERROR status=1
      detail=$(grep -m1 'error:' "$WORK/build.log")
    elif suite "$x"; then
      verdict=ACCEPTED status=1
    else
      verdict=rejected rejected=$((rejected + 1))
      detail="$(awk -F'\t' '$1 != "pass"' "$WORK/cases.tsv" | wc -l) of $(wc -l < "$WORK/cases.tsv") cases fail: "
      detail+=$(awk -F'\t' '$1 != "pass" {print $4}' "$WORK/cases.tsv" | head -2 | paste -sd ';' -)
    fi
    cp "$WORK/original" "$target"   # restored with a new time: it recompiles next time
    printf '%-14s %-22s %-11s %4ss  %s%s\n' "$x" "$name" "$verdict" "$(( $(date +%s) - start ))" "$detail" "$clr"
  done
done
build >/dev/null 2>&1   # leave the build folder matching the tree
echo "grading: $rejected of $total wrong answers (stubs included) rejected"
exit $status
