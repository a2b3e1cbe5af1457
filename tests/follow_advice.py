#!/usr/bin/env python3
"""follow_advice.py - does a stop message's advice, followed, complete the run?

Reads the --json record of tests/random_runs.py, takes the runs that stopped (exit 1), and for
each one whose first stderr line advises a setting ("try substeps=4 ... or lstps=80", "e.g.
NRitMax=20", "try ghost=0.01", "try a wider grid, width=18", "tol=1e-9") reruns its command
with the first advised setting put in (replacing the parameter if it was given), and, if that
run stops too, with the second one instead. It counts:
  - stops with advice and stops without (the message names no setting to try);
  - of those with advice: completed with the first setting, with the second, or neither
    (the rerun then stopped again, with its own message, or exceeded --timeout).
--sample N takes N of the stops, evenly over the record (all when N is 0).

Usage: tests/follow_advice.py RECORD.json [RECORD.json ...] [--sample N] [--jobs J]
                              [--timeout T] [--out DIR]
Python 3 standard library only.
"""
import argparse
import collections
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import tempfile

ADVICE = re.compile(r"\b([A-Za-z]+)=([-+0-9.eE]+)")
NOT_A_SETTING = {"fErr", "tol_now", "x", "y"}  # key=value pairs of a message that report state


def advised(message):
    """the settings a stop message advises, in order: the ones after 'try' or 'e.g.'"""
    lines = [l for l in message.splitlines() if l.startswith("ample: ") and ": warning: " not in l]
    first = lines[0] if lines else ""
    cut = max(first.find("try "), first.find("e.g. "), first.find("would pass"))
    if cut < 0:
        return []
    out = []
    for key, value in ADVICE.findall(first[cut:]):
        if key not in NOT_A_SETTING and (key, value) not in out:
            out.append((key, value))
    return out


def with_setting(command, key, value, out_dir):
    """the command with key=value put in (replaced when given) and a fresh --out"""
    words = shlex.split(command)
    words = [w for w in words if not w.startswith(key + "=")]
    i = words.index("--out")
    words[i + 1] = out_dir
    words.insert(i, key + "=" + value)
    return words


def rerun(job):
    run, tries, timeout, out = job
    env_words = []
    results = []
    for k, (key, value) in enumerate(tries):
        words = with_setting(run["command"], key, value, os.path.join(out, "run%05d_%d" % (run["index"], k)))
        while words and "=" in words[0] and not words[0].startswith("/"):
            env_words.append(words.pop(0))
        env = dict(os.environ, **dict(w.split("=", 1) for w in env_words))
        try:
            code = subprocess.run(words, env=env, capture_output=True, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            code = "timeout"
        results.append((key + "=" + value, code))
        if code == 0:
            break
    return run, results


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("records", nargs="+")
    ap.add_argument("--sample", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    stops = []
    for path in a.records:
        with open(path) as f:
            stops += [r for r in json.load(f)["runs"] if r["exit_code"] == 1]
    if a.sample and a.sample < len(stops):
        stops = [stops[int(i * len(stops) / a.sample)] for i in range(a.sample)]
    out = a.out or tempfile.mkdtemp(prefix="follow_advice_")
    jobs, silent = [], []
    for r in stops:
        tries = advised(r["stderr"])[:2]
        (jobs if tries else silent).append((r, tries, a.timeout, out) if tries else r)
    count = collections.Counter()
    by_key = collections.defaultdict(collections.Counter)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for run, results in pool.map(rerun, jobs):
            done = [k for k, (_, code) in enumerate(results) if code == 0]
            outcome = "first" if done == [0] else "second" if done else "neither"
            count[outcome] += 1
            by_key[results[0][0].split("=")[0]][outcome] += 1
            if outcome == "neither":
                print("  not completed: %s  [%s]" % (run["command"].split("/ample ", 1)[-1].split(" --")[0],
                                                   ", ".join("%s -> %s" % rc for rc in results)))
    n = len(jobs)
    print("stops: %d (%d with advice, %d without)" % (len(stops), n, len(silent)))
    for s in silent:
        lines = [l for l in s["stderr"].splitlines() if l.startswith("ample: ") and ": warning: " not in l]
        print("  no advice: %s" % (lines or s["stderr"].splitlines() or [""])[0][:160])
    if n:
        print("advice followed completes the run: %d of %d (%.0f %%): first setting %d, second %d; neither %d"
              % (count["first"] + count["second"], n, 100.0 * (count["first"] + count["second"]) / n,
                 count["first"], count["second"], count["neither"]))
        for key, c in sorted(by_key.items()):
            print("  %-10s %3d advised first: completed %d (first %d, second %d), not %d"
                  % (key, sum(c.values()), c["first"] + c["second"], c["first"], c["second"], c["neither"]))
    print("reruns in %s" % out)


if __name__ == "__main__":
    main()
