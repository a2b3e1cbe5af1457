#!/usr/bin/env bash
#--------------------------------------------------------------------------
# make_student_version.sh — the student copy of the tree (the classroom kit)
#--------------------------------------------------------------------------
# Each region of the source between the lines
#     // BEGIN EXERCISE name
#     // END EXERCISE
# is an exercise (docs/exercises.md). The student copy has every region
# replaced by the one line
#     throw ExerciseNotDone("name: see docs/exercises.md#name");
# (constitutive/exercise.h), keeps the two marker lines, and has a file STUDENT.md at
# its top (the list of exercises; its presence also quietens the unused-
# parameter warnings of the stubs, CMakeLists.txt). The student writes the
# answer between the markers.
#
#   tools/make_student_version.sh DIR            # write the student copy to DIR
#   tools/make_student_version.sh --restore DIR  # paste this tree's solutions back into DIR
#   tools/make_student_version.sh --check DIR    # DIR with the solutions pasted back == this tree?
#   tools/make_student_version.sh --list         # exercises, files, lines
#   tools/make_student_version.sh --fill FILE NAME BODIES   # region(s) NAME of FILE := BODIES
#                                                # (a file of region bodies, separated by a
#                                                # line "// NEXT REGION"; tools/grading.sh)
# DIR must be outside the source folders (build/ is fine: it is not copied) and
# either not exist or hold an earlier student copy (it is then rewritten).
# The files copied are git's (tracked and untracked, not ignored) when the tree
# is a git checkout, else every file but build/ and .git.
# The instructor's material is left out of the copy (INSTRUCTOR_ONLY below: the
# wrong answers, each a solution with one change, the mutation check, whose
# substitutions quote solutions, and the scripts that need them); --check
# ignores it. tools/check_leak.sh DIR checks that no solution is left in DIR.
# Exit status: 0 done (--check: identical), 1 --check found a difference, 2 usage error
# Checked by .ci/run (both directions, and check_leak.sh); documented in docs/exercises.md.
#--------------------------------------------------------------------------
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
MARK='^[[:space:]]*// BEGIN EXERCISE [A-Za-z0-9_]+[[:space:]]*$'
usage() { sed -n '2,32p' "$0"; exit 2; }

# the instructor's files and folders: not in the student copy (docs/exercises.md)
INSTRUCTOR_ONLY=(tools/wrong_answers tools/grading.sh tools/mutants.sh tools/sync_tree.sh tools/check_leak.sh
                 tools/leak_known.txt)

# the files of a tree that hold regions
region_files() { (cd "$1" && grep -rlE "$MARK" ample constitutive setups plotting 2>/dev/null | sort) || true; }

# fill FILE NAME MODE [BODIES]: regions NAME ("*" = all) of FILE get the stub
# (MODE stub) or the bodies in the file BODIES, in order (MODE file)
fill() {
  local file=$1 name=$2 mode=$3 bodies=${4:-/dev/null} tmp
  tmp=$(mktemp)
  awk -v name="$name" -v mode="$mode" -v bodies="$bodies" -v file="$file" '
    BEGIN {
      nb = 0; k = 0; cur = ""
      if (mode == "file") {
        while ((getline line < bodies) > 0)
          if (line ~ /^[ \t]*\/\/ NEXT REGION[ \t]*$/) { B[nb++] = cur; cur = "" }
          else cur = cur line "\n"
        B[nb++] = cur
      }
    }
    inside && /^[ \t]*\/\/ END EXERCISE[ \t]*$/ { inside = 0; print; next }
    inside { next }
    /^[ \t]*\/\/ BEGIN EXERCISE / {
      print
      if (name != "*" && $4 != name) next
      inside = 1; n++
      ind = $0; sub(/\/\/.*/, "", ind)
      if (mode == "stub") print ind "throw ExerciseNotDone(\"" $4 ": see docs/exercises.md#" $4 "\");"
      else if (k < nb) printf "%s", B[k++]
      else { print file ": more regions " name " than bodies given" > "/dev/stderr"; bad = 1 }
      next
    }
    { print }
    END {
      if (inside) { print file ": a BEGIN EXERCISE without END EXERCISE" > "/dev/stderr"; exit 1 }
      if (mode == "file" && k != nb) { print file ": " nb " bodies given for " k " regions " name > "/dev/stderr"; exit 1 }
      if (bad) exit 1
    }' "$file" > "$tmp"
  cat "$tmp" > "$file"   # keeps the file mode
  rm -f "$tmp"
}

# bodies FILE NAME: the bodies of the regions NAME ("*" = all) of FILE, separated by "// NEXT REGION"
bodies() {
  awk -v name="$2" '
    inside && /^[ \t]*\/\/ END EXERCISE[ \t]*$/ { inside = 0; next }
    inside { print; next }
    /^[ \t]*\/\/ BEGIN EXERCISE / && (name == "*" || $4 == name) { if (n++) print "// NEXT REGION"; inside = 1 }' "$1"
}

# copy_tree FROM TO: the tree's files (no build/, no .git), less the instructor's
copy_tree() {
  local from=$1 to=$2 p
  mkdir -p "$to"
  if git -C "$from" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    (cd "$from" && git ls-files -co --exclude-standard -z | while IFS= read -r -d '' f; do
       [ -f "$f" ] && printf '%s\0' "$f"; done | tar --null -T - -cf -) | tar -C "$to" -xf -
  else
    (cd "$from" && tar --exclude=./build --exclude=./.git -cf - .) | tar -C "$to" -xf -
  fi
  for p in "${INSTRUCTOR_ONLY[@]}"; do rm -rf "${to:?}/$p"; done
}

exercises() {  # name file lines, one region a line, of the tree (or of the copy $1)
  (cd "${1:-$SRC}" && for f in $(region_files .); do
     awk -v f="$f" '/^[ \t]*\/\/ BEGIN EXERCISE /{n=$4; s=NR} /^[ \t]*\/\/ END EXERCISE/{printf "%-14s %-26s %d-%d\n", n, f, s, NR}' "$f"
   done)
}

restore() {  # paste the tree's solutions into the copy $1
  local dir=$1 f b
  b=$(mktemp)
  for f in $(region_files "$SRC"); do
    [ -f "$dir/$f" ] || { echo "$dir/$f: missing" >&2; exit 1; }
    bodies "$SRC/$f" "*" > "$b"
    fill "$dir/$f" "*" file "$b"
  done
  rm -f "$b"
}

student_md() {
  cat <<EOF
# Student copy of ample-cpp

Written by \`tools/make_student_version.sh\`. Each region between \`// BEGIN EXERCISE name\`
and \`// END EXERCISE\` throws \`ExerciseNotDone\` until you write it: docs/exercises.md
says what to implement, the equations and the command that grades it
(\`build/release/tests/ample_tests -ts=name\`, or \`ctest -L '^name\$'\` in build/release).
Until an exercise is done, its suite fails with one line naming it, and every other
test or run that needs it is skipped with "needs exercise name".

In course order (the table of docs/exercises.md: an exercise's suite can be graded once
the exercises above it that it calls are done):

| week | exercise | what | file | lines |
|---|---|---|---|---|
$(course_order "$dir" | awk -F'\t' '{printf "| %s | [%s](docs/exercises.md#%s) | %s | %s | %s |\n", $2, $1, $1, $3, $4, $5}')
EOF
}

# course_order: name, week, what, file, lines (tab-separated), one region a line, in the order of
# the table of docs/exercises.md ("| week | [name](#name) | what | ..."); exercises not in it last
course_order() {
  exercises "${1:-$SRC}" | awk -v doc="$SRC/docs/exercises.md" '
    BEGIN {
      while ((getline l < doc) > 0)
        if (l ~ /^\| *[0-9]+ *\| *\[[A-Za-z0-9_]+\]/) {
          split(l, c, "|"); n = c[3]; sub(/^ *\[/, "", n); sub(/\].*/, "", n)
          w = c[2]; gsub(/ /, "", w); what = c[4]; sub(/^ +/, "", what); sub(/ +$/, "", what)
          if (!(n in rank)) { rank[n] = ++k; week[n] = w; desc[n] = what }
        }
    }
    { r = ($1 in rank) ? rank[$1] : 1000; printf "%04d\t%04d\t%s\t%s\t%s\t%s\t%s\n", r, NR, $1, week[$1], desc[$1], $2, $3 }' |
    sort | cut -f3-
}

case "${1:-}" in
  ""|-h|--help) usage ;;
  --list) exercises ;;
  --fill) [ $# -eq 4 ] || usage; if [ "$4" = stub ]; then fill "$2" "$3" stub; else fill "$2" "$3" file "$4"; fi ;;
  --restore) [ $# -eq 2 ] && [ -f "$2/STUDENT.md" ] || usage; restore "$2" ;;
  --check)
    [ $# -eq 2 ] && [ -f "$2/STUDENT.md" ] || usage
    tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
    (cd "$2" && tar --exclude=./build --exclude=./STUDENT.md -cf - .) | (mkdir -p "$tmp/s" && tar -C "$tmp/s" -xf -)
    restore "$tmp/s"
    copy_tree "$SRC" "$tmp/t"
    if diff -r "$tmp/t" "$tmp/s" > "$tmp/diff"; then
      echo "student copy $2 with the $(exercises | wc -l) regions pasted back: identical to $SRC (less ${INSTRUCTOR_ONLY[*]})"
    else
      echo "student copy $2 with the regions pasted back differs from $SRC:"; head -40 "$tmp/diff"; exit 1
    fi ;;
  -*) usage ;;
  *)
    [ $# -eq 1 ] || usage
    dir=$(realpath -m "$1")
    for d in ample constitutive setups plotting tests tools docs; do
      case "$dir/" in "$SRC/$d/"*) echo "$1 is inside the source folder $d/" >&2; exit 2 ;; esac
    done
    [ "$dir" = "$SRC" ] && { echo "$1 is the tree itself" >&2; exit 2; }
    if [ -e "$dir" ] && [ -n "$(ls -A "$dir")" ]; then
      [ -f "$dir/STUDENT.md" ] || { echo "$1 exists and is no student copy (no STUDENT.md): not touched" >&2; exit 2; }
      find "$dir" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} +   # keep its build folder
    fi
    copy_tree "$SRC" "$dir"
    for f in $(region_files "$dir"); do fill "$dir/$f" "*" stub; done
    student_md > "$dir/STUDENT.md"
    echo "student copy in $1: $(exercises | awk '{print $1}' | sort -u | wc -l) exercises in $(exercises | wc -l) regions (STUDENT.md)" ;;
esac
