#!/usr/bin/env bash
#--------------------------------------------------------------------------
# check_leak.sh — does a student copy hold an exercise's solution anywhere?
#--------------------------------------------------------------------------
# For every exercise region of this tree (`// BEGIN EXERCISE name` ...
# `// END EXERCISE`, tools/make_student_version.sh) the lines of its solution
# are normalised: comments (// and /* */) and all white space removed, and the
# lines with nothing significant left dropped (lone braces and parentheses, a
# bare `else`, `break;`, `continue;`, `return;`, `default:`, `try`, `do`).
# Every text file of the student copy (any folder but build/ and .git;
# binary files skipped) is normalised the same way. Any two or more
# consecutive significant lines of a solution that appear as consecutive
# significant lines of a file of the copy are reported, with the region and
# the place in the copy; the exit status is then 1. tools/leak_known.txt lists
# the overlaps accepted (a sibling function, loop headers in a test), each
# for one exercise and one file, up to a number of lines; they are printed
# as "known" on every run.
#
#   tools/check_leak.sh STUDENT_DIR    # e.g. build/student-src (.ci/run)
# Exit status: 0 no solution found, 1 some found, 2 usage error
# Documented in docs/exercises.md ("The student copy holds no solution").
#--------------------------------------------------------------------------
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
[ $# -eq 1 ] && [ -f "$1/STUDENT.md" ] || { sed -n '2,22p' "$0"; exit 2; }
DIR=$(cd "$1" && pwd)
[ "$DIR" != "$SRC" ] || { echo "$1 is this tree, not a student copy" >&2; exit 2; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# the text files of the copy (paths relative to it), and the region files of the tree
(cd "$DIR" && find . \( -path ./build -o -name .git \) -prune -o -type f -print0 |
   xargs -0 grep -IlZ '' -- 2>/dev/null | tr '\0' '\n' | sed 's|^\./||' | sort) > "$tmp/copy"
"$SRC/tools/make_student_version.sh" --list | awk '{print $2}' | sort -u > "$tmp/regions"

nfiles=$(wc -l < "$tmp/copy")
(cd "$DIR" && awk -v copy="$tmp/copy" -v regions="$tmp/regions" -v tree="$SRC" -v knownfile="$SRC/tools/leak_known.txt" '
  # norm(line): the line without comments (state "inc": inside a /* */) and white space
  function norm(s,    out, i, c2) {
    out = ""
    while (s != "") {
      if (inc) {
        i = index(s, "*/"); if (!i) return out
        s = substr(s, i + 2); inc = 0; continue
      }
      i = index(s, "/*"); c2 = index(s, "//")
      if (c2 && (!i || c2 < i)) { out = out substr(s, 1, c2 - 1); break }
      if (i) { out = out substr(s, 1, i - 1); s = substr(s, i + 2); inc = 1; continue }
      out = out s; break
    }
    gsub(/[ \t\r\f\v]/, "", out)
    return out
  }
  function significant(s,    t) {
    t = s; gsub(/[{}();,]/, "", t)
    return t != "" && t !~ /^(else|break|continue|return|default:|try|do)$/
  }
  BEGIN {
    # the pairs of consecutive significant lines of every file of the copy, and where each first is
    while ((getline f < copy) > 0) {
      inc = 0; have = 0; ln = 0
      while ((getline line < f) > 0) {
        ln++
        n = norm(line)
        if (!significant(n)) continue
        if (have) {
          key = prev SUBSEP n
          if (lastf[key] != f) { where[key] = where[key] f ":" prevline "\n"; lastf[key] = f }
        }
        prev = n; prevline = ln; have = 1
      }
      close(f)
    }
    # the overlaps known and accepted: exercise, file of the copy, most lines, reason (tab-separated)
    while ((getline l < knownfile) > 0)
      if (l !~ /^#/ && split(l, c, "\t") >= 4) { known[c[1] SUBSEP c[2]] = c[3] + 0; why[c[1] SUBSEP c[2]] = c[4] }
    # the regions of the tree, each checked against them
    found = 0; checked = 0; nknown = 0
    while ((getline rf < regions) > 0) {
      path = tree "/" rf; inc = 0; inside = 0; ln = 0
      while ((getline line < path) > 0) {
        ln++
        if (line ~ /^[ \t]*\/\/ BEGIN EXERCISE /) { split(line, w, " "); name = w[4]; inside = 1; m = 0; inc = 0; continue }
        if (inside && line ~ /^[ \t]*\/\/ END EXERCISE[ \t]*$/) { report(); inside = 0; continue }
        if (!inside) continue
        s = norm(line)
        if (significant(s)) { m++; L[m] = s; N[m] = ln; T[m] = line }
      }
      close(path)
    }
    printf "%d regions checked, %d known\n", checked, nknown > "/dev/stderr"
    exit found ? 1 : 0
  }
  # the runs of consecutive significant lines of the region just read that a file of the copy
  # holds: a leak, or "known" when tools/leak_known.txt names the exercise and the file with at
  # least as many lines
  function report(    k, q, nl, loc, file, ln, has, files, i, j, t, kind, len) {
    checked++
    split("", has); split("", files)
    for (k = 1; k < m; k++) {
      if (!((L[k] SUBSEP L[k + 1]) in where)) continue
      nl = split(where[L[k] SUBSEP L[k + 1]], loc, "\n")
      for (q = 1; q <= nl; q++) if (loc[q] != "") {
        file = loc[q]; ln = loc[q]; sub(/:[0-9]+$/, "", file); sub(/.*:/, "", ln)
        has[file SUBSEP k] = ln; files[file] = 1
      }
    }
    for (file in files)
      for (i = 1; i < m; i++) {
        if (!((file SUBSEP i) in has)) continue
        for (j = i; (file SUBSEP j) in has; j++) ;   # pairs i..j-1: lines i..j
        len = j - i + 1
        kind = ((name SUBSEP file) in known && len <= known[name SUBSEP file]) ? "known" : "LEAK"
        if (kind == "LEAK") found++; else nknown++
        printf "%s: exercise %s, %s lines %d-%d (%d significant), in the copy at %s:%s%s\n", kind, name, \
          rf, N[i], N[j], len, file, has[file SUBSEP i], kind == "known" ? " (" why[name SUBSEP file] ")" : ""
        if (kind == "LEAK") {
          for (k = i; k <= j && k < i + 4; k++) { t = T[k]; sub(/^[ \t]+/, "", t); printf "    %s\n", t }
          if (len > 4) printf "    ...\n"
        }
        i = j
      }
  }') > "$tmp/out" 2> "$tmp/err" && status=0 || status=$?
cat "$tmp/out"
checked=$(sed -n 's/ regions checked, .*//p' "$tmp/err") known=$(sed -n 's/.* regions checked, \([0-9]*\) known$/\1/p' "$tmp/err")
grep -v ' regions checked, ' "$tmp/err" >&2 || true
if [ "$status" -eq 0 ]; then
  echo "no leak: no two consecutive significant lines of the $checked exercise regions of $SRC in the $nfiles text files of $1, but for the $known known overlaps above (tools/leak_known.txt)"
elif [ "$status" -eq 1 ]; then
  echo "LEAKS: $(grep -c '^LEAK:' "$tmp/out") runs of solution lines found in $1 (above)"
else
  echo "check_leak.sh: awk failed (status $status)" >&2; exit 2
fi
exit "$status"
