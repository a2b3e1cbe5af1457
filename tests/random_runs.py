#!/usr/bin/env python3
"""random_runs.py - randomised runs of every setup, checked for crashes and bad output (CTest random.runs)

Reads `ample --list` and each setup's `--help`, draws parameter sets inside the printed ranges
with a fixed seed, runs each one (--quiet, a fresh output folder, a timeout) on J workers and
checks what every run leaves behind:
  - no signal: a return code < 0 or >= 128 is a crash; a run past --timeout is a timeout;
  - the exit code is 0, 1 or 2 (3 is the student copy's, not expected here);
  - summary.json agrees with the exit code: "converged" is true iff the exit is 0; exits 0 and 1
    write it; exit 2 (bad input) may have none, but then leaves no output file of a run
    (steps.csv, residuals.csv, mp_final.csv, history.csv, mesh*.vtk, mpData_*.vtk);
  - summary.json parses with json.loads, strictly (NaN / Infinity literals refused, and no
    number that overflows to inf);
  - no non-finite number (nan, -nan, inf, NaN, Infinity) in any CSV, JSON or ASCII VTK file; a
    binary VTK file's header is checked and its big-endian float arrays decoded and checked;
  - a non-zero exit says why on stderr (a non-empty line);
  - the run stays within --mem-limit (std::bad_alloc on stderr: "out of memory"; the missing
    summary.json of such a run is not counted again as a mismatch).
It prints the count of each outcome and failure class, the stop messages (first stderr line)
grouped by their first words, and every failure's command line to reproduce it; the exit status
is 1 if any check failed, 0 otherwise (2: bad arguments).

How the parameters are drawn (per run: the setup round-robin over `ample --list`, or the one of
--setup; then 1-4 of its parameters changed, the rest left at their defaults):
  - a choice ("or by name: ..."): any of them, half the time by name, half by number;
  - an integer range with at most 5 values (flags such as supports, fem, reference): any;
  - lstps: 1 .. min(hi, max(4, 2 x default, capped at 64)), log-uniform: the load steps are
    capped so a run stays short;
  - NRitMax: 2 .. 50 log-uniform (the range goes to 1000); substeps: 0 .. 8 mostly, 10 % up to 30;
  - any other integer is taken as a size (cells, points per cell or triangle, margin): 90 % of
    draws are default/2 .. 2 x default (log-uniform), 10 % lo .. 3 x default, clipped to the range
    (the ranges allow grids far too big for a quick test, e.g. a = 64, nelsy = 4e6);
  - the float sizes h (grid spacing) and width (collapse: grid width) likewise stay within a
    factor 2 of the default;
  - (0, inf) and [0, inf): log-uniform over 3 decades either side of the default (1e-3 .. 1e3 for
    a zero default), and exactly 0 one time in ten where 0 is allowed;
  - a bounded float range: log-uniform when lo > 0 and hi / lo >= 1e3 (e.g. delta in
    [1e-12, 0.5]), uniform otherwise; one time in ten a value at a closed bound, or within
    1e-6 .. 1e-2 of the width from an open one.
Options too, each independently: --accept-floor (20 %); --vtk 0 (50 %), 1 (15 %), 2..10 (20 %) or
not given (15 %: the default, 1); --vtk-format binary (30 % of the runs that write VTK).
With these, seed 1 and 300 runs (CTest random.runs) on the 2-core machine with 2 jobs: run time
median 0.03 s, 90 % under 0.5 s, longest 4.9 s, 53 s in all (load average 1.1-1.8, other work
light); 143 s while other builds shared the machine (load 1.2-3.7; median 0.05 s, longest 10 s;
with a slower token-by-token file check since replaced by one regular expression). Seed 2 with
1000 runs: 289 s (load about 2.5). A run that does not end in --timeout seconds is reported.
Each run's address space is limited (--mem-limit, 2048 MB: some draws make grids of millions of
nodes; the program should then stop with a message, exit 1, not take the machine down). Every
worker runs the program with OMP_NUM_THREADS=1 unless --omp-threads says otherwise (2 workers
on 2 cores), and the draw does not depend on --jobs: seed and count give the same runs.

Pairs (--pairs F): a share F of the draws runs twice, with OMP_NUM_THREADS=1 and 2 and
AMPLE_POINTS_PER_THREAD=8 (so that even a small run's point loop takes the threaded path,
pointShares.h); each pair must end with the same exit code and, where both complete, the same
Newton-Raphson passes and the same mp_final.csv byte for byte (a run's outcome does not depend
on the number of threads). CTest random.runs pairs a third of its draws.

Usage: tests/random_runs.py --ample PATH [--seed S] [--count N] [--jobs J] [--timeout T]
                            [--out DIR] [--keep] [--setup NAME] [--json FILE] [--omp-threads N]
                            [--pairs F]
Python 3 standard library only.
"""
import argparse
import collections
import concurrent.futures
import json
import math
import os
import random
import re
import resource
import shlex
import shutil
import struct
import subprocess
import sys
import tempfile
import time

# ---------------------------------------------------------------------------------------------
# the setups and their ranges, as printed by the program


class Param:
    """One line of `ample SETUP --help`: "  name = default<TAB>help; RANGE"."""

    def __init__(self, name, default, rng):
        self.name = name
        self.default = default
        self.integer = rng.startswith("integer in ")
        body = rng[len("integer in "):] if self.integer else rng
        choices = ""
        if " or by name: " in body:
            body, choices = body.split(" or by name: ", 1)
        m = re.fullmatch(r"([\[(])\s*([^,]+),\s*([^\])]+)([\])])", body.strip())
        if not m:
            raise ValueError("range not understood: %r" % rng)
        self.lo_open, self.hi_open = m.group(1) == "(", m.group(4) == ")"
        self.lo, self.hi = float(m.group(2)), float(m.group(3))
        self.choices = []  # (number, name)
        for item in filter(None, (c.strip() for c in choices.split(","))):
            number, cname = item.split(None, 1)
            self.choices.append((int(float(number)), cname))

    def inside(self, v):
        if math.isnan(v):
            return False
        if v < self.lo or (self.lo_open and v == self.lo):
            return False
        if v > self.hi or (self.hi_open and v == self.hi):
            return False
        return not self.integer or v == int(v)


def parse_help(text):
    params = []
    for line in text.splitlines():
        m = re.match(r"^  (\w+) = (\S+)\t.*; ([^;]+)$", line)
        if m:
            params.append(Param(m.group(1), float(m.group(2)), m.group(3).strip()))
    return params


def read_setups(ample, only):
    out = subprocess.run([ample, "--list"], capture_output=True, text=True, check=True).stdout
    names = [line.split("\t")[0].strip() for line in out.splitlines() if "\t" in line]
    if only:
        unknown = [n for n in only if n not in names]
        if unknown:
            sys.exit("random_runs.py: no setup %s in `ample --list`" % ", ".join(unknown))
        names = [n for n in names if n in only]
    setups = collections.OrderedDict()
    for n in names:
        text = subprocess.run([ample, n, "--help"], capture_output=True, text=True, check=True).stdout
        setups[n] = parse_help(text)
        if not setups[n]:
            sys.exit("random_runs.py: no parameters read from `ample %s --help`" % n)
    return setups


# ---------------------------------------------------------------------------------------------
# the draw

SIZE_FLOATS = {"h", "width"}  # floats that set the number of cells: kept near the default


def fmt(p, v):
    """The value as text, inside the range after rounding (else None)."""
    if p.integer:
        text = str(int(v))
    else:
        text = "%.6g" % v
        if not p.inside(float(text)):
            text = repr(float(v))
    return text if p.inside(float(text)) else None


def log_uniform(rnd, a, b):
    return math.exp(rnd.uniform(math.log(a), math.log(b)))


def near_edge(rnd, p):
    """A value at a closed bound or just inside an open one (finite bounds only)."""
    width = p.hi - p.lo
    if rnd.random() < 0.5:
        return p.lo if not p.lo_open else p.lo + width * log_uniform(rnd, 1e-6, 1e-2)
    return p.hi if not p.hi_open else p.hi - width * log_uniform(rnd, 1e-6, 1e-2)


def clip_int(p, v):
    lo = int(math.ceil(p.lo + (1 if p.lo_open and p.lo == int(p.lo) else 0)))
    hi = int(math.floor(p.hi - (1 if p.hi_open and p.hi == int(p.hi) else 0)))
    return max(lo, min(hi, int(round(v))))


def draw_value(rnd, p):
    if p.choices:
        number, name = rnd.choice(p.choices)
        return name if rnd.random() < 0.5 else str(number)
    d = p.default
    if p.integer:
        if p.hi - p.lo <= 4:
            v = rnd.randint(int(p.lo), int(p.hi))
        elif p.name == "lstps":
            v = log_uniform(rnd, 1, max(4, min(64, 2 * max(d, 1))) + 0.999)
            v = math.floor(v)
        elif p.name == "NRitMax":
            v = math.floor(log_uniform(rnd, 2, 50.999))
        elif p.name == "substeps":
            v = rnd.randint(0, 8) if rnd.random() < 0.9 else rnd.randint(0, 30)
        elif rnd.random() < 0.9:  # a size
            v = log_uniform(rnd, max(d, 1) / 2, max(d, 1) * 2)
        else:
            v = rnd.uniform(p.lo, max(p.lo, 3 * max(d, 1)))
        return fmt(p, clip_int(p, v))
    if p.name in SIZE_FLOATS and d > 0:
        v = log_uniform(rnd, d / 2, d * 2)
        v = min(max(v, p.lo), p.hi)
    elif math.isinf(p.hi):
        if p.lo == 0 and not p.lo_open and rnd.random() < 0.1:
            v = 0.0
        else:
            centre = d if d > 0 else 1.0
            v = log_uniform(rnd, centre * 1e-3, centre * 1e3)
    elif rnd.random() < 0.1:
        v = near_edge(rnd, p)
    elif p.lo > 0 and p.hi / p.lo >= 1e3:
        v = log_uniform(rnd, p.lo, p.hi)
    else:
        v = rnd.uniform(p.lo, p.hi)
    return fmt(p, v)


def draw_run(rnd, setup, params):
    changes = collections.OrderedDict()
    k = rnd.randint(1, min(4, len(params)))
    for p in rnd.sample(params, k):
        for _ in range(20):
            text = draw_value(rnd, p)
            if text is not None:
                changes[p.name] = text
                break
    options = []
    if rnd.random() < 0.2:
        options.append("--accept-floor")
    r = rnd.random()
    vtk = 0 if r < 0.5 else 1 if r < 0.65 else rnd.randint(2, 10) if r < 0.85 else None
    if vtk is not None:
        options += ["--vtk", str(vtk)]
    if vtk != 0 and rnd.random() < 0.3:
        options += ["--vtk-format", "binary"]
    return [setup] + ["%s=%s" % kv for kv in changes.items()] + options


# ---------------------------------------------------------------------------------------------
# the checks of one run's output

RUN_FILES = re.compile(r"^(steps\.csv|residuals\.csv|mp_final\.csv|history\.csv|mesh(_\d+)?\.vtk|mpData_\d+\.vtk)$")


class StrictJsonError(ValueError):
    pass


def refuse_constant(name):
    raise StrictJsonError("non-standard JSON literal " + name)


def non_finite_in_json(obj):
    if isinstance(obj, float):
        return not math.isfinite(obj)
    if isinstance(obj, dict):
        return any(non_finite_in_json(v) for v in obj.values())
    if isinstance(obj, list):
        return any(non_finite_in_json(v) for v in obj)
    return False


NON_FINITE = re.compile(r"(?<![A-Za-z0-9_.#])[-+]?(?:nan|inf(?:inity)?)(?![A-Za-z0-9_])|1\.#(?:inf|ind|qnan)",
                        re.IGNORECASE)  # nan, -nan, nan(ind), inf, -Infinity, NaN, 1.#INF; not info, nanoseconds


def first_non_finite_token(text):
    """(line number, token) of the first non-finite number in a CSV or ASCII VTK text, or None."""
    m = NON_FINITE.search(text)
    if not m:
        return None
    return text.count("\n", 0, m.start()) + 1, m.group(0)


def check_binary_vtk(data):
    """Problems of a legacy VTK BINARY file: its header, then each section's big-endian arrays."""
    pos = 0

    def line():
        nonlocal pos
        end = data.find(b"\n", pos)
        if end < 0:
            raise ValueError("truncated at byte %d" % pos)
        text = data[pos:end].decode("ascii")
        pos = end + 1
        return text

    def array(n, kind):
        nonlocal pos
        raw = data[pos:pos + 4 * n]
        if len(raw) != 4 * n:
            raise ValueError("array of %d values truncated" % n)
        pos += 4 * n
        if data[pos:pos + 1] == b"\n":
            pos += 1
        if kind == "float":
            values = struct.unpack(">%df" % n, raw)
            bad = next((i for i, v in enumerate(values) if not math.isfinite(v)), None)
            if bad is not None:
                return "non-finite float %r at value %d" % (values[bad], bad)
        return None

    try:
        head = [line() for _ in range(4)]
        if not head[0].startswith("# vtk DataFile Version") or head[2] != "BINARY" \
                or not head[3].startswith("DATASET "):
            return "bad header %r" % head, False
        npoints = 0
        while pos < len(data):
            words = line().split()
            if not words:
                continue
            key, problem = words[0], None
            if key == "POINTS":
                problem = array(3 * int(words[1]), words[2])
            elif key == "CELLS":
                problem = array(int(words[2]), "int")
            elif key == "CELL_TYPES":
                problem = array(int(words[1]), "int")
            elif key in ("POINT_DATA", "CELL_DATA"):
                npoints = int(words[1])
            elif key == "VECTORS":
                problem = array(3 * npoints, words[2])
            elif key == "SCALARS":
                width = int(words[3]) if len(words) > 3 else 1
                if not line().startswith("LOOKUP_TABLE"):
                    return "SCALARS %s without LOOKUP_TABLE" % words[1], False
                problem = array(width * npoints, words[2])
            elif key == "TENSORS":
                problem = array(9 * npoints, words[2])
            else:
                return "unknown section %r at byte %d" % (key, pos), False
            if problem:
                return "%s: %s" % (" ".join(words[:2]), problem), True
    except (ValueError, UnicodeDecodeError, struct.error, IndexError) as e:
        return "unreadable: %s" % e, False
    return None, False


def check_files(outdir, failures, notes):
    for name in sorted(os.listdir(outdir)):
        path = os.path.join(outdir, name)
        if not os.path.isfile(path):
            continue
        with open(path, "rb") as f:
            data = f.read()
        if name.endswith(".vtk") and data[:200].split(b"\n")[2:3] == [b"BINARY"]:
            problem, non_finite = check_binary_vtk(data)
            if problem:
                failures.add("non-finite in file" if non_finite else "unreadable file")
                notes.append("%s: %s" % (name, problem))
            continue
        if not (name.endswith(".csv") or name.endswith(".vtk") or name.endswith(".json")):
            continue
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            failures.add("unreadable file")
            notes.append("%s: not UTF-8 text" % name)
            continue
        if name.endswith(".json"):
            try:
                obj = json.loads(text, parse_constant=refuse_constant)
            except (StrictJsonError, ValueError) as e:
                failures.add("invalid json")
                notes.append("%s: %s" % (name, e))
                continue
            if non_finite_in_json(obj):
                failures.add("non-finite in file")
                notes.append("%s: a number overflows to inf" % name)
            continue
        hit = first_non_finite_token(text)
        if hit:
            failures.add("non-finite in file")
            notes.append("%s line %d: %s" % (name, hit[0], hit[1]))


def check_summary(outdir, rc, failures, notes):
    path = os.path.join(outdir, "summary.json")
    if not os.path.isfile(path):
        if rc in (0, 1):
            failures.add("exit/summary mismatch")
            notes.append("exit %d without summary.json" % rc)
        elif rc == 2 and os.path.isdir(outdir):
            left = [n for n in os.listdir(outdir) if RUN_FILES.match(n)]
            if left:
                failures.add("exit/summary mismatch")
                notes.append("exit 2 without summary.json left %s" % ", ".join(sorted(left)[:4]))
        return
    try:
        with open(path, encoding="utf-8") as f:
            summary = json.loads(f.read(), parse_constant=refuse_constant)
    except (StrictJsonError, ValueError, UnicodeDecodeError):
        return  # counted by check_files as invalid json
    converged = summary.get("converged") if isinstance(summary, dict) else None
    if converged is not (rc == 0) and rc in (0, 1, 2):
        failures.add("exit/summary mismatch")
        notes.append("exit %d with \"converged\": %s" % (rc, json.dumps(converged)))


# ---------------------------------------------------------------------------------------------
# one run

def run_one(index, argv, ample, root, timeout, omp_threads, keep, pair=False):
    outdir = os.path.join(root, "run%05d_%s%s" % (index, argv[0], "_t%d" % omp_threads if pair else ""))
    if os.path.exists(outdir):
        shutil.rmtree(outdir)
    cmd = [ample] + argv + ["--out", outdir, "--quiet"]
    env = dict(os.environ)
    if omp_threads:
        env["OMP_NUM_THREADS"] = str(omp_threads)
    if pair:  # both runs of a pair: even a small run's point loop on the threads
        env["AMPLE_POINTS_PER_THREAD"] = str(PAIR_POINTS_PER_THREAD)
    failures, notes = set(), []
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, capture_output=True, env=env, timeout=timeout)
        rc, stderr = proc.returncode, proc.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as e:
        rc, stderr = None, (e.stderr or b"").decode("utf-8", "replace")
    seconds = time.monotonic() - start
    if rc is None:
        outcome = "timeout"
        failures.add("timeout")
    elif rc < 0 or rc >= 128:
        outcome = "crash"
        failures.add("crash")
        notes.append("signal %d" % (-rc if rc < 0 else rc - 128))
    elif rc in (0, 1, 2):
        outcome = "exit %d" % rc
    else:
        outcome = "exit %d" % rc
        failures.add("bad exit code")
    if rc is not None and rc != 0 and not stderr.strip():
        failures.add("no message")
    out_of_memory = rc is not None and "bad_alloc" in stderr
    if out_of_memory:
        failures.add("out of memory")
        notes.append("over the address-space limit (--mem-limit)")
    if rc is not None and os.path.isdir(outdir):
        check_files(outdir, failures, notes)
    if rc in (0, 1, 2) and not out_of_memory:  # std::bad_alloc ends the run before summary.json
        check_summary(outdir, rc, failures, notes)
    first = next((l.strip() for l in stderr.splitlines() if l.strip()), "")
    passes, final = pair_figures(outdir) if pair and rc is not None else (None, None)
    if not failures and not keep and not pair and os.path.isdir(outdir):
        shutil.rmtree(outdir, ignore_errors=True)
    prefix = "OMP_NUM_THREADS=%s " % omp_threads if omp_threads else ""
    if pair:
        prefix += "AMPLE_POINTS_PER_THREAD=%d " % PAIR_POINTS_PER_THREAD
    return {"index": index, "setup": argv[0], "command": prefix + shlex.join(cmd), "exit_code": rc,
            "outcome": outcome, "classes": sorted(failures), "notes": notes, "stderr": first,
            "seconds": round(seconds, 3), "outdir": outdir, "passes": passes, "mp_final": final}


# ---------------------------------------------------------------------------------------------
# pairs: the same draw on 1 and on 2 threads (a run's outcome must not depend on the threads)

PAIR_POINTS_PER_THREAD = 8  # pointShares.h: 2,048 by default; 8 puts nearly every run on 2 threads


def pair_figures(outdir):
    """Newton-Raphson passes (summary.json) and the bytes of mp_final.csv, None where absent."""
    passes = final = None
    try:
        with open(os.path.join(outdir, "summary.json"), encoding="utf-8") as f:
            passes = json.loads(f.read(), parse_constant=refuse_constant).get("total_NR_iterations")
    except (OSError, ValueError, StrictJsonError, AttributeError):
        pass
    try:
        with open(os.path.join(outdir, "mp_final.csv"), "rb") as f:
            final = f.read()
    except OSError:
        pass
    return passes, final


def compare_pair(one, two, keep):
    """The same exit code; where both completed, the same passes and the same mp_final.csv."""
    why = ["on 2 threads: " + ", ".join(two["classes"])] if two["classes"] else []
    if one["exit_code"] != two["exit_code"]:
        why.append("exit %s on 1 thread, %s on 2" % (one["exit_code"], two["exit_code"]))
    elif one["exit_code"] == 0:
        if one["passes"] != two["passes"]:
            why.append("%s Newton-Raphson passes on 1 thread, %s on 2" % (one["passes"], two["passes"]))
        if one["mp_final"] != two["mp_final"]:
            why.append("mp_final.csv differs")
    if not why and not keep:
        for r in (one, two):
            shutil.rmtree(r["outdir"], ignore_errors=True)
    for r in (one, two):
        del r["mp_final"]
    return why


def message_group(line, setups):
    """The first words of a stop message, without "ample: SETUP:" and with numbers as #."""
    text = re.sub(r"^ample:\s*", "", line)
    for s in setups:
        if text.startswith(s + ": "):
            text = text[len(s) + 2:]
            break
    text = re.sub(r"[-+]?\d[\d.eE+-]*", "#", text)
    words = text.split()
    return " ".join(words[:5]) + (" ..." if len(words) > 5 else "")


# ---------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description="Randomised runs of the ample setups, checked for "
                                 "crashes, timeouts and bad output.")
    ap.add_argument("--ample", required=True, help="the program (build/release/ample)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=300, help="number of runs (default 300)")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    ap.add_argument("--timeout", type=float, default=60, help="seconds a run may take (default 60)")
    ap.add_argument("--out", help="folder of the runs' output folders (default: a temporary one)")
    ap.add_argument("--keep", action="store_true", help="keep every run's folder (failed ones are always kept)")
    ap.add_argument("--setup", action="append", help="only this setup (may be given more than once)")
    ap.add_argument("--json", help="write one record per run to this file")
    ap.add_argument("--omp-threads", type=int, default=1,
                    help="OMP_NUM_THREADS of each run (default 1; 0: leave the environment's)")
    ap.add_argument("--mem-limit", type=int, default=2048,
                    help="address space of each run in MB (ulimit -v; default 2048, 0: none)")
    ap.add_argument("--pairs", type=float, default=0.0,
                    help="share of the draws (0 .. 1, default 0) run as pairs on 1 and 2 threads "
                         "(AMPLE_POINTS_PER_THREAD=%d) and compared: exit code, passes, mp_final.csv"
                         % PAIR_POINTS_PER_THREAD)
    ap.add_argument("--list-only", action="store_true", help="print the drawn command lines, run nothing")
    args = ap.parse_args()
    if args.count < 1 or args.jobs < 1 or args.timeout <= 0:
        ap.error("--count and --jobs must be at least 1, --timeout above 0")
    if not 0 <= args.pairs <= 1:
        ap.error("--pairs must be in [0, 1]")
    ample = os.path.abspath(args.ample)
    if not os.access(ample, os.X_OK):
        ap.error("not a program: %s" % ample)

    setups = read_setups(ample, args.setup)
    names = list(setups)
    rnd = random.Random(args.seed)
    runs = [draw_run(rnd, names[i % len(names)], setups[names[i % len(names)]]) for i in range(args.count)]
    if args.list_only:
        for argv in runs:
            print(shlex.join([ample] + argv))
        return 0

    if args.mem_limit > 0:  # inherited by every run: a grid that explodes meets bad_alloc, not the machine
        limit = args.mem_limit * 1024 * 1024
        hard = resource.getrlimit(resource.RLIMIT_AS)[1]
        resource.setrlimit(resource.RLIMIT_AS, (limit if hard == resource.RLIM_INFINITY else min(limit, hard), hard))
    root = os.path.abspath(args.out) if args.out else tempfile.mkdtemp(prefix="ample_random_")
    if os.path.isdir(root):
        for n in os.listdir(root):
            if re.match(r"^run\d{5}_", n):
                shutil.rmtree(os.path.join(root, n), ignore_errors=True)
    os.makedirs(root, exist_ok=True)
    print("random_runs.py: %d runs of %s, seed %d, %d jobs, timeout %g s, memory %s, output in %s"
          % (args.count, ", ".join(names), args.seed, args.jobs, args.timeout,
             "%d MB a run (ulimit -v %d)" % (args.mem_limit, args.mem_limit * 1024) if args.mem_limit > 0
             else "not limited", root), flush=True)

    # every draw whose index falls on the share's grid is a pair (independent of the draw itself)
    paired = [int(i * args.pairs) != int((i + 1) * args.pairs) for i in range(args.count)]
    start = time.monotonic()
    records, pairs = [], {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {}
        for i, argv in enumerate(runs):
            if paired[i]:
                for nt in (1, 2):
                    futures[pool.submit(run_one, i + 1, argv, ample, root, args.timeout, nt, args.keep, True)] = nt
            else:
                futures[pool.submit(run_one, i + 1, argv, ample, root, args.timeout, args.omp_threads,
                                    args.keep)] = 0
        for n, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            r = fut.result()
            if futures[fut]:
                pairs.setdefault(r["index"], {})[futures[fut]] = r
            if futures[fut] != 2:
                records.append(r)
            if n % 50 == 0 or n == len(futures):
                print("  %d / %d runs, %.0f s" % (n, len(futures), time.monotonic() - start), flush=True)
    wall = time.monotonic() - start
    records.sort(key=lambda r: r["index"])
    pair_failed = []
    for index in sorted(pairs):
        why = compare_pair(pairs[index][1], pairs[index][2], args.keep)
        if why:
            pair_failed.append((index, why, pairs[index]))

    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"seed": args.seed, "count": args.count, "jobs": args.jobs, "timeout": args.timeout,
                       "wall_seconds": round(wall, 1), "runs": records}, f, indent=1)

    times = sorted(r["seconds"] for r in records)
    print("\n== %d runs in %.1f s wall (run time median %.2f s, 90 %% %.2f s, max %.2f s)"
          % (len(records), wall, times[len(times) // 2], times[int(0.9 * (len(times) - 1))], times[-1]))
    outcomes = collections.Counter(r["outcome"] for r in records)
    print("outcomes:")
    for key in ["exit 0", "exit 1", "exit 2", "crash", "timeout"] + sorted(set(outcomes) - {
            "exit 0", "exit 1", "exit 2", "crash", "timeout"}):
        print("  %-24s %d" % ({"exit 0": "ok (exit 0)"}.get(key, key), outcomes.get(key, 0)))
    classes = collections.Counter(c for r in records for c in r["classes"])
    print("failed checks (a run may fail several):")
    for key in ["crash", "timeout", "out of memory", "bad exit code", "invalid json", "non-finite in file",
                "unreadable file", "no message", "exit/summary mismatch"]:
        print("  %-24s %d" % (key, classes.get(key, 0)))

    groups = collections.defaultdict(list)
    for r in records:
        if r["exit_code"] != 0 and r["stderr"]:
            groups[(r["outcome"], message_group(r["stderr"], names))].append(r)
    if groups:
        print("stop messages (first line of stderr, by first words; # = a number):")
        for (outcome, words), rs in sorted(groups.items(), key=lambda kv: (kv[0][0], -len(kv[1]))):
            print("  %4d  %-8s %s   [%s]" % (len(rs), outcome, words,
                                            ", ".join(sorted(set(r["setup"] for r in rs)))))

    if pairs:
        print("pairs on 1 and 2 threads: %d, %d agree (exit code; passes and mp_final.csv where both completed)"
              % (len(pairs), len(pairs) - len(pair_failed)))
    stub = next((r for r in records if r["exit_code"] == 3 and "needs exercise" in r["stderr"]), None)
    if stub:  # the student copy: a run reached an exercise not done yet, so nothing here is graded
        print("\nrandom_runs.py: skipped: %s" % stub["stderr"].strip().splitlines()[-1])
        return 77
    failed = [r for r in records if r["classes"]]
    for index, why, pair in pair_failed:
        print("\npair #%d differs on 1 and 2 threads: %s" % (index, "; ".join(why)))
        for nt in (1, 2):
            print("    " + pair[nt]["command"])
    if pair_failed:
        print("\nrandom_runs.py: FAILED: %d of %d pairs differ on 1 and 2 threads (seed %d)"
              % (len(pair_failed), len(pairs), args.seed))
    if failed:
        print("\nfailures (%d runs), each with its command line:" % len(failed))
        for r in failed:
            print("  #%d %s [%s] %s%s" % (r["index"], r["outcome"], ", ".join(r["classes"]),
                                         "; ".join(r["notes"][:3]), (" | " + r["stderr"]) if r["stderr"] else ""))
            print("    " + r["command"])
        print("\nrandom_runs.py: FAILED: %d of %d runs failed a check (seed %d)" % (len(failed), len(records), args.seed))
        return 1
    if pair_failed:
        return 1
    print("\nrandom_runs.py: all %d runs passed every check (seed %d)" % (len(records), args.seed))
    return 0


if __name__ == "__main__":
    sys.exit(main())
