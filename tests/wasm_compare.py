#!/usr/bin/env python3
"""wasm_compare.py — the browser build of ample under node against the native program.

For each run given (a setup and its parameters), runs the native program and the browser build
(build/wasm/ample_wasm.js through tests/wasm_run.js under node; the same source compiled by
emscripten's clang for WebAssembly, with emscripten's libc++ and libc) with `--vtk 0 --quiet` and
compares their output:
  - the exit status, summary.json's sizes (nmp, nodes, nDoF, lstps), its parameters, converged,
    last_converged_step and total_NR_iterations, and the Newton-Raphson passes of every load
    step (steps.csv) and every pass's row (residuals.csv): equal;
  - summary.json's results: within TOL relative (|a - b| <= TOL max(|a|, |b|)), except a figure
    that is round-off in both runs (below 1e-6 of the largest figure of the run, e.g. the
    footing's imbalance_N, 0.1 N, the sum of forces that balance to tol = 1e-9 of a load of
    1e9 N, beside its load_kN = 1.2e6): said, not compared;
  - mp_final.csv: every value within TOL of the largest magnitude of its quantity (positions
    X0, Y0, x, y; volumes V0, V; the six stresses; the domain lpx, lpy): a stress that is
    round-off (compaction's sxy) is measured against the run's stresses, not against itself;
  - every pass's fErr (residuals.csv) of 1e-6 or more: within 1e-6 relative (below that, a
    residual is round-off and its digits are not the method's).
A control shows the comparison can fail: the native run with E (or the first parameter named in
--control) changed by 1e-8 relative must be caught.
usage: wasm_compare.py --native build/release/ample --wasm build/wasm/ample_wasm.js --work DIR
                       [--tol 1e-10] RUN ...      (RUN: "setup name=value ...", e.g. "collapse a=2")
Tests: CTest wasm.node (skipped, exit 77, without node or the browser build)
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time


def run(cmd):
    t = time.time()
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return r, time.time() - t


def columns(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head, body = rows[0], rows[1:]
    return {h: [float(r[k]) if r[k] != "" else math.nan for r in body] for k, h in enumerate(head)}


QUANTITIES = [("X0", "Y0", "x", "y"), ("V0", "V"), ("sxx", "syy", "szz", "sxy", "syz", "szx"), ("lpx", "lpy")]


def compare(native, wasm, tol):
    """(problems, measures) of two output folders"""
    bad, meas = [], {}
    sn, sw = (json.load(open(os.path.join(d, "summary.json"))) for d in (native, wasm))
    for key in ("setup", "parameters", "nmp", "nodes", "nDoF", "lstps", "converged",
                "last_converged_step", "total_NR_iterations"):
        if sn.get(key) != sw.get(key):
            bad.append("summary.json %s: native %r, wasm %r" % (key, sn.get(key), sw.get(key)))
    worst = 0.0
    largest = max([abs(v) for v in sn["results"].values() if v is not None] + [0.0])
    for name, a in sn["results"].items():
        b = sw["results"].get(name)
        if a is None or b is None:
            if a != b:
                bad.append("result %s: native %r, wasm %r" % (name, a, b))
            continue
        rel = abs(a - b) / max(abs(a), abs(b), 1e-300)
        if rel > tol and max(abs(a), abs(b)) < 1e-6 * largest:
            meas.setdefault("roundoff", []).append("%s %.3g / %.3g" % (name, a, b))
            continue
        worst = max(worst, rel)
        if rel > tol:
            bad.append("result %s: native %.17g, wasm %.17g (relative %.2e > %.0e)" % (name, a, b, rel, tol))
    meas["results"] = worst
    cn, cw = columns(os.path.join(native, "mp_final.csv")), columns(os.path.join(wasm, "mp_final.csv"))
    worst = 0.0
    for h, a in cn.items():
        b = cw.get(h, [])
        if len(a) != len(b):
            bad.append("mp_final.csv %s: %d points native, %d wasm" % (h, len(a), len(b)))
            continue
        group = next(g for g in QUANTITIES if h in g)
        scale = max([abs(v) for g in group for v in cn[g]] + [1e-300])
        d = max([abs(x - y) / scale for x, y in zip(a, b)] + [0.0])
        worst = max(worst, d)
        if not d <= tol:
            bad.append("mp_final.csv %s: differs by %.2e of the column's largest (> %.0e)" % (h, d, tol))
    meas["mp_final"] = worst
    rn, rw = columns(os.path.join(native, "residuals.csv")), columns(os.path.join(wasm, "residuals.csv"))
    if rn["lstp"] != rw["lstp"] or rn["NRit"] != rw["NRit"]:
        bad.append("residuals.csv: the passes differ (%d rows native, %d wasm)" % (len(rn["lstp"]), len(rw["lstp"])))
    else:
        worst = 0.0
        for a, b in zip(rn["fErr"], rw["fErr"]):
            if a >= 1e-6:
                worst = max(worst, abs(a - b) / a)
        meas["fErr"] = worst
        if worst > 1e-6:
            bad.append("residuals.csv: an fErr >= 1e-6 differs by %.2e relative" % worst)
    if columns(os.path.join(native, "steps.csv"))["NRit"] != columns(os.path.join(wasm, "steps.csv"))["NRit"]:
        bad.append("steps.csv: the passes per load step differ")
    return bad, meas


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--native", required=True)
    ap.add_argument("--wasm", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--tol", type=float, default=1e-10)
    ap.add_argument("--control", default="E")
    ap.add_argument("runs", nargs="+")
    opt = ap.parse_args()
    node = shutil.which("node")
    if not node or not os.path.exists(opt.wasm):
        print("SKIPPED: needs node and the browser build %s (cmake --workflow --preset wasm)" % opt.wasm)
        return 77
    runner = os.path.join(os.path.dirname(os.path.abspath(__file__)), "wasm_run.js")
    shutil.rmtree(opt.work, ignore_errors=True)
    problems = []
    for k, spec in enumerate(opt.runs):
        words = spec.split()
        tag = "%d_%s" % (k, words[0])
        nat, was = os.path.join(opt.work, tag + "_native"), os.path.join(opt.work, tag + "_wasm")
        flags = ["--vtk", "0", "--quiet"]
        rn, tn = run([opt.native] + words + flags + ["--out", nat])
        rw, tw = run([node, runner, opt.wasm] + words + flags + ["--out", was])
        if rn.returncode != rw.returncode or rn.stderr != rw.stderr:
            problems.append("%s: exit %d native, %d wasm; stderr native %r, wasm %r"
                            % (spec, rn.returncode, rw.returncode, rn.stderr[-300:], rw.stderr[-300:]))
            continue
        bad, meas = compare(nat, was, opt.tol)
        problems += ["%s: %s" % (spec, b) for b in bad]
        print("%-28s exit %d, native %.2f s, wasm (node) %.2f s; largest relative differences: results %.1e, "
              "mp_final %.1e (of each quantity's largest), fErr >= 1e-6 %.1e"
              % (spec, rn.returncode, tn, tw, meas["results"], meas["mp_final"], meas.get("fErr", math.nan)))
        if meas.get("roundoff"):
            print("  round-off figures (native / wasm), not compared: " + ", ".join(meas["roundoff"]))
        if k == 0:                             # the control: a native run 1e-8 off must be caught
            ctl = os.path.join(opt.work, tag + "_control")
            summary = json.load(open(os.path.join(nat, "summary.json")))
            value = summary["parameters"][opt.control] * (1 + 1e-8)
            run([opt.native] + words + ["%s=%.17g" % (opt.control, value)] + flags + ["--out", ctl])
            caught, _ = compare(ctl, was, opt.tol)
            print("control: %s with %s changed by 1e-8: %s" % (spec, opt.control, "caught (%d differences)"
                  % len(caught) if caught else "NOT CAUGHT"))
            if not caught:
                problems.append("control: a native run with %s changed by 1e-8 was not told apart" % opt.control)
    for p in problems:
        print("FAIL " + p)
    if problems:
        print("(a browser build older than this tree? rebuild it: cmake --workflow --preset wasm)")
    print("wasm.node: %d runs, %s" % (len(opt.runs), "all within %.0e" % opt.tol if not problems
                                      else "%d problems" % len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
