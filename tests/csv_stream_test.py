#!/usr/bin/env python3
"""csv_stream_test.py — steps.csv, residuals.csv and history.csv grow with the run (CTest output.stream)

ample appends each completed load step's rows to the three files at the step's end and flushes
them (setups/program/writeOutput.h, appendStepFiles), so a run that is killed keeps every completed
step. Checked here on runs with a history.csv, one thread each:
  1. killed: a simple shear (32 x 32 cells, 20 steps, about 0.1 s a step) is started, SIGKILLed as soon as steps.csv holds KILL_AFTER converged steps
     (k of the run's LSTPS); then every line of the three files is whole (ends with a newline,
     as many fields as the header), steps.csv holds exactly the steps 1..k, and residuals.csv and
     history.csv the same steps' rows, equal to the uninterrupted run's rows (steps.csv: all but
     the seconds column). The three files are appended one after the other, so a kill between
     two appends may leave the next step's whole rows in residuals.csv and history.csv (written
     first) before its steps.csv row: allowed for step k + 1 only, and only whole.
  2. stopped (exit 1): a footing in 200 steps, which stops after step 31 (its footing boundary
     leaves the cells of the points); its files hold every converged step (summary.json's
     last_converged_step: the converged steps.csv rows, history.csv rows and residuals.csv steps
     are exactly 1..last_converged_step, and no later step's rows, as this stop is before any
     pass of the next step).
usage: csv_stream_test.py AMPLE WORKDIR
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time

LSTPS, KILL_AFTER = 20, 3
RUN = ["shear", "nels=32", "dl=2", "lstps=%d" % LSTPS, "--vtk", "0", "--quiet"]


def lines_of(path):
    """the file's lines; every one must end with a newline and have the header's field count"""
    with open(path) as f:
        text = f.read()
    assert text.endswith("\n"), "%s: the last line is not whole: %r" % (path, text[-40:])
    rows = list(csv.reader(text.splitlines()))
    for r in rows:
        assert len(r) == len(rows[0]), "%s: a row of %d fields under a header of %d: %s" % (
            path, len(r), len(rows[0]), r)
    return rows


def by_step(rows, col=0):
    """{lstp: [rows]} of the data rows, the step in column col"""
    out = {}
    for r in rows[1:]:
        out.setdefault(int(r[col]), []).append(r)
    return out


def run_full(ample, work, env):
    out = os.path.join(work, "full")
    subprocess.run([ample] + RUN + ["--out", out], check=True, env=env, stdout=subprocess.DEVNULL)
    return out


def run_killed(ample, work, env):
    out = os.path.join(work, "killed")
    proc = subprocess.Popen([ample] + RUN + ["--out", out], env=env, stdout=subprocess.DEVNULL)
    steps = os.path.join(out, "steps.csv")
    deadline = time.time() + 120
    while time.time() < deadline and proc.poll() is None:
        try:
            with open(steps) as f:
                if sum(1 for line in f.read().splitlines()[1:] if line.split(",")[4] == "1") >= KILL_AFTER:
                    break
        except (FileNotFoundError, IndexError):
            pass
        time.sleep(0.005)
    if proc.poll() is not None:
        sys.exit("the run ended (exit %s) before it could be killed: make it longer" % proc.returncode)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    return out


def check_killed(full, killed):
    s_full, s_kill = lines_of(os.path.join(full, "steps.csv")), lines_of(os.path.join(killed, "steps.csv"))
    assert s_kill[0] == s_full[0], "steps.csv headers differ: %s / %s" % (s_kill[0], s_full[0])
    k = max(int(r[0]) for r in s_kill[1:]) if len(s_kill) > 1 else 0
    assert 0 < k < LSTPS, "killed at step %d of %d: not mid-way" % (k, LSTPS)
    assert [r[:-1] for r in s_kill[1:]] == [r[:-1] for r in s_full[1:] if int(r[0]) <= k], \
        "steps.csv rows differ from the uninterrupted run's (seconds aside)"
    assert all(r[4] == "1" for r in s_kill[1:]), "a step that did not converge"
    for name, col in (("residuals.csv", 0), ("history.csv", 0)):
        a, b = lines_of(os.path.join(killed, name)), lines_of(os.path.join(full, name))
        assert a[0] == b[0], "%s headers differ" % name
        got, want = by_step(a, col), by_step(b, col)
        for step in range(1, k + 1):
            assert got.get(step) == want[step], "%s: the rows of step %d differ or are missing" % (name, step)
        extra = sorted(set(got) - set(range(1, k + 1)))
        assert extra in ([], [k + 1]), "%s holds steps %s past steps.csv's %d" % (name, extra, k)
        if extra:
            assert got[k + 1] == want[k + 1], "%s: step %d only in part" % (name, k + 1)
        print("%s: steps 1-%d, %d rows, equal to the uninterrupted run's%s" % (
            name, k, len(a) - 1, " (and step %d, written before its steps.csv row)" % (k + 1) if extra else ""))
    print("steps.csv: steps 1-%d of %d, whole lines, equal to the uninterrupted run's (seconds aside)" % (k, LSTPS))


def check_stopped(ample, work, env):
    out = os.path.join(work, "stopped")
    rc = subprocess.run([ample, "footing", "lstps=200", "--vtk", "0", "--quiet", "--out", out], env=env,
                        stdout=subprocess.DEVNULL,
                        stderr=subprocess.DEVNULL).returncode
    summary = json.load(open(os.path.join(out, "summary.json")))
    assert rc == 1 and not summary["converged"], "this footing was expected to stop (exit %d)" % rc
    last = summary["last_converged_step"]
    steps = lines_of(os.path.join(out, "steps.csv"))
    converged = [int(r[0]) for r in steps[1:] if r[4] == "1"]
    assert converged == list(range(1, last + 1)), "steps.csv converged steps %s, last_converged_step %d" % (
        converged, last)
    assert last > 0 and len(steps) - 1 == last, "steps.csv: %d rows for %d steps" % (len(steps) - 1, last)
    res = by_step(lines_of(os.path.join(out, "residuals.csv")))
    assert sorted(res) == list(range(1, last + 1)), "residuals.csv steps %s" % sorted(res)
    hist = lines_of(os.path.join(out, "history.csv"))
    assert [int(r[0]) for r in hist[1:]] == list(range(1, last + 1)), "history.csv steps differ"
    print("stopped (exit 1) after %d converged steps: steps.csv, residuals.csv, history.csv hold exactly "
          "steps 1-%d" % (last, last))


def main(ample, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    full = run_full(ample, work, env)
    check_killed(full, run_killed(ample, work, env))
    check_stopped(ample, work, env)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    try:
        main(sys.argv[1], sys.argv[2])
    except AssertionError as e:
        sys.exit("FAILED: %s" % e)
