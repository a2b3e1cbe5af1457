#!/usr/bin/env bash
#--------------------------------------------------------------------------
# core_coverage.sh — how much of the code one plain run executes (gcov)
#--------------------------------------------------------------------------
# Builds the program with gcc's --coverage in its own folder, build/coverage
# (Debug: -O0 -g3, AMPLE_OPENMP off as in every Debug build, AMPLE_TESTS=OFF;
# only the target ample), zeroes the counters (removes the .gcda files), runs
#   build/coverage/ample SETUP [name=value ...] --vtk 0 --quiet --out build/coverage/output
# (the folder removed first, so that the run writes into a new one) and reads the counts with the gcov that matches g++ (gcov-N for g++ N;
# --json-format). Prints a short table:
#   - per file of ample/ (setups/program/ aside, the command line) and
#     constitutive/, headers too: the source lines executed (a line counts once
#     when its execution count is > 0, however many blocks or template copies
#     it has) and the lines that hold code, then the total of both folders and
#     the number of files with at least one executed line ("files entered");
#   - the same totals for plotting/ and setups/ (outside the count);
#   - per core function (solve, loadStep, elemMPinfo, detExtForce, detFDoFs, linSolve,
#     detMPs, updateMPs, Hooke3d, VMconst): the executed lines between the first
#     and last line of its body as gcov's function record gives them (lambdas
#     inside the body included), the lines with code there, and its calls.
# The .gcov text of every file is left in build/coverage/gcov/ (e.g.
# build/coverage/gcov/ample#detExtForce.cpp.gcov) to check a file by hand:
# "-:" no code, "#####:" code not run, "N:" run N times.
#
# Usage:   tools/core_coverage.sh [SETUP [name=value ...]]      (default: compaction)
#   e.g.   tools/core_coverage.sh
#          tools/core_coverage.sh collapse a=1
# Exit status: 0 done (also when the run stopped, exit 1: the lines up to the
# stop are counted, and it is said), 2 build failure, bad input or no gcov.
# A first build takes several minutes on 2 cores; log: build/coverage_build.log.
#--------------------------------------------------------------------------
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -ge 1 ] && [ "${1#-}" != "$1" ] && { sed -n '2,30p' "$0"; exit 2; }
setup="${1:-compaction}"; [ $# -ge 1 ] && shift
bdir="$root/build/coverage"

# the gcov of the compiler: gcov-12 for g++ 12 (plain gcov when it is the same version)
cxx="${CXX:-g++}"
major=$("$cxx" -dumpfullversion -dumpversion 2>/dev/null | cut -d. -f1)
gcov=""
for g in "gcov-$major" gcov; do
  if command -v "$g" > /dev/null &&
     [ "$("$g" --version | head -1 | grep -o '[0-9][0-9]*\.[0-9.]*' | tail -1 | cut -d. -f1)" = "$major" ]; then
    gcov="$g"; break
  fi
done
[ -n "$gcov" ] || { echo "core_coverage.sh: no gcov for $cxx $major (apt-get install gcc-$major)" >&2; exit 2; }

mkdir -p "$root/build"
log="$root/build/coverage_build.log"
echo "core_coverage.sh: building build/coverage/ample (Debug, --coverage; log: build/coverage_build.log)" >&2
if ! { cmake -S "$root" -B "$bdir" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER="$cxx" \
         -DAMPLE_TESTS=OFF -DAMPLE_OPENMP=OFF \
         -DCMAKE_CXX_FLAGS=--coverage -DCMAKE_EXE_LINKER_FLAGS=--coverage &&
       cmake --build "$bdir" --target ample -j2; } > "$log" 2>&1; then
  tail -30 "$log" >&2; echo "core_coverage.sh: the coverage build failed" >&2; exit 2
fi

find "$bdir" -name '*.gcda' -delete                      # zero the counters
rm -rf "$bdir/output"                                    # a first run: no old files to remove
echo "core_coverage.sh: running ample $setup $* --vtk 0 --quiet" >&2
set +e
"$bdir/ample" "$setup" "$@" --vtk 0 --quiet --out "$bdir/output"
rc=$?
set -e
case $rc in
  0) note="every load step converged" ;;
  1) note="the run stopped (exit 1): lines up to the stop" ;;
  *) echo "core_coverage.sh: the run failed (exit $rc)" >&2; exit 2 ;;
esac

rm -rf "$bdir/gcov"; mkdir -p "$bdir/gcov"
ROOT="$root" BDIR="$bdir" GCOV="$gcov" RUN="ample $setup $*" NOTE="$note" python3 - <<'PY'
import json, os, re, subprocess, sys
root, bdir, gcov = os.environ["ROOT"], os.environ["BDIR"], os.environ["GCOV"]
gdir = os.path.join(bdir, "gcov")

objs = []                                               # every object of our sources
for d, _, files in os.walk(os.path.join(bdir, "CMakeFiles")):
    objs += [os.path.join(d, f) for f in files if f.endswith(".gcno")]
lines = {}                                              # file -> {line: count}
funcs = {}                                              # (file, name, start) -> [end, calls]
for gcno in sorted(objs):
    obj = gcno[:-len(".gcno")] + ".o"
    out = subprocess.run([gcov, "--json-format", "--stdout", obj], capture_output=True,
                         text=True, cwd=gdir).stdout
    text = subprocess.run([gcov, "--preserve-paths", "-o", obj, obj], capture_output=True,
                          cwd=gdir)                     # the .gcov text, to read by hand
    dec, at = json.JSONDecoder(), 0
    while True:
        while at < len(out) and out[at].isspace():
            at += 1
        if at >= len(out):
            break
        doc, at = dec.raw_decode(out, at)
        for f in doc["files"]:
            path = os.path.normpath(os.path.join(doc.get("current_working_directory", ""), f["file"]))
            if not path.startswith(root + "/"):
                continue                                # the standard library, Eigen
            rel = path[len(root) + 1:]
            got = lines.setdefault(rel, {})
            for l in f["lines"]:
                n = l["line_number"]
                got[n] = max(got.get(n, 0), l["count"])
            for fn in f["functions"]:
                key = (rel, fn["demangled_name"], fn["start_line"])
                e = funcs.setdefault(key, [fn["end_line"], 0])
                e[1] += fn["execution_count"]

# keep only the .gcov texts of our own files, named by their path in the tree
# (gcov -p writes '#' for '/'; a header's text is that of the last object read)
for f in os.listdir(gdir):
    full = f.replace("#", "/")[:-len(".gcov")]
    if not full.startswith(root + "/"):
        os.remove(os.path.join(gdir, f))
    else:
        os.rename(os.path.join(gdir, f),
                  os.path.join(gdir, full[len(root) + 1:].replace("/", "#") + ".gcov"))

def counted(rel):
    return (rel.startswith("ample/") and not rel.startswith("setups/program/")) or \
        rel.startswith("constitutive/")

def tally(files):
    run = sum(sum(1 for c in lines[f].values() if c > 0) for f in files)
    code = sum(len(lines[f]) for f in files)
    entered = sum(1 for f in files if any(c > 0 for c in lines[f].values()))
    return run, code, entered

def pct(a, b):
    return "%5.1f%%" % (100.0 * a / b) if b else "     -"

print("run: %s (%s)" % (os.environ["RUN"], os.environ["NOTE"]))
print("lines executed (count > 0) / lines with code, per file of ample/ (less setups/program/) and constitutive/")
core = sorted(f for f in lines if counted(f) and lines[f])   # files with code (not ample.h)
w = max(len(f) for f in core)
print("  %-*s %8s %6s %7s" % (w, "file", "executed", "code", ""))
for f in core:
    run, code, _ = tally([f])
    print("  %-*s %8d %6d %7s" % (w, f, run, code, pct(run, code)))
run, code, entered = tally(core)
print("  %-*s %8d %6d %7s" % (w, "total", run, code, pct(run, code)))
print("files entered: %d of %d (ample/ less setups/program/, constitutive/)" % (entered, len(core)))
print("outside the count:")
for name in ("plotting/", "setups/", "setups/program/"):
    fs = [f for f in lines if f.startswith(name) and lines[f]]
    run, code, entered = tally(fs)
    print("  %-14s %6d of %6d lines %7s, %d of %d files entered" %
          (name, run, code, pct(run, code), entered, len(fs)))

print("core functions: executed lines / lines with code between the function's first and last line"
      " (name/N: the overload of N parameters)")
core_funcs = [("ample/ample.cpp", "solve"), ("ample/ample.cpp", "loadStep"), ("ample/elemMPinfo.cpp", "elemMPinfo"),
              ("ample/detExtForce.cpp", "detExtForce"), ("ample/detFDoFs.cpp", "detFDoFs"),
              ("ample/linSolve.cpp", "linSolve"), ("ample/detMPs.cpp", "detMPs"),
              ("ample/updateMPs.cpp", "updateMPs"), ("constitutive/Hooke3d.cpp", "Hooke3d"),
              ("constitutive/VMconst.cpp", "VMconst")]
print("  %-12s %-26s %7s %8s %6s %7s %7s" % ("function", "file", "lines", "executed", "code", "", "calls"))
for file, name in core_funcs:
    recs = sorted((k[2], v[0], v[1], k[1]) for k, v in funcs.items()   # not its lambdas
                  if k[0] == file and "{lambda" not in k[1] and
                  re.sub(r"\(.*", "", k[1]).split("::")[-1] == name)
    if not recs:
        print("  %-12s %-26s (no function record: not compiled?)" % (name, file))
    for start, end, calls, full in recs:
        got = {n: c for n, c in lines.get(file, {}).items() if start <= n <= end}
        run = sum(1 for c in got.values() if c > 0)
        args = full.split("(", 1)[1]
        while re.search(r"<[^<>]*>", args):
            args = re.sub(r"<[^<>]*>", "", args)          # template arguments hold commas
        shown = name if len(recs) == 1 else "%s/%d" % (name, args.count(",") + 1)   # overloads
        print("  %-12s %-26s %7s %8d %6d %7s %7d" % (shown, file, "%d-%d" % (start, end), run, len(got),
                                                 pct(run, len(got)), calls))
print("the .gcov text of each file: build/coverage/gcov/ (e.g. ample#detExtForce.cpp.gcov)")
PY
