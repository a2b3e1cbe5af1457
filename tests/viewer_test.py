#!/usr/bin/env python3
"""viewer_test.py — the page (plotting/viewer/) running the program built to WebAssembly, in
headless Chromium, against the native program.

Serves build/wasm/viewer from 127.0.0.1, drives the page through its form (tests/cdp.py) and checks:
  - the first picture (the set-up points of the default setup) is drawn within 2 s of opening;
  - bad inputs: each of BAD typed into the form gives the command line's message exactly (the
    native program's stderr line, exit 2) and leaves Run off; two inputs the form lets through
    (solver=MUMPS, not in the browser build; collapse width=9, whose toe leaves the grid) are
    refused by the program in the page with the native program's message, the stopped run
    keeping its steps up to the last converged one, as the native run does;
  - compaction, collapse and footing run through the form: summary.json and mp_final.csv within
    1e-10 of the native run's (wasm_compare.py's measures), every step streamed and drawn, the
    VTK file of the last step (downloaded from the page) within 1e-10 of the native one;
  - the controls on the footing: the slider replays frame 0, the wheel zooms, a drag pans by as
    many pixels, a double-click fits again, another field draws;
  - every other setup of the program's table runs through the form with its defaults (--vtk 0):
    the native program's exit status, one frame per converged step; its differences from the
    native run are printed (the round-off of emscripten's libc and libm against glibc's, which a
    badly conditioned problem amplifies: docs/browser.md);
  - speed: collapse a=4 (--vtk 0), Run pressed to the run's end, at most 3 times the native
    program on one thread (OMP_NUM_THREADS=1, the browser's one thread), best of two;
  - Cancel stops collapse a=16 within 1 s (no pass streamed after it), and the page answered
    its timers within 0.5 s all through the run (a frame of its 36,864 points drawn at a time);
  - the output folder of a native run (collapse --vtk 2) opens in the same viewer: one frame per
    mpData_<lstp>.vtk, each with its points drawn;
  - no script error on the page, no uncaught exception.
Screenshots (the page opened, the collapse and the footing during and after the run) go to WORK,
and to --shots if given. Skips (exit 77) without chromium or the browser build.
usage: viewer_test.py --native build/release/ample --viewer build/wasm/viewer --work DIR [--shots DIR]
Tests: CTest wasm.page
"""
import argparse
import functools
import glob
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cdp  # noqa: E402
import wasm_compare  # noqa: E402

# bad inputs of the form: (setup, {parameter: text}, {option: text}); each refused by the command line
BAD = [
    ("compaction", {"E": "abc"}, {}),          # not a number
    ("compaction", {"E": "0x10"}, {}),         # hex
    ("compaction", {"E": "inf"}, {}),          # not finite
    ("compaction", {"E": " 3"}, {}),           # a space
    ("compaction", {"E": "-1"}, {}),           # out of (0, inf)
    ("compaction", {"nu": "0.5"}, {}),         # out of (-1, 0.5)
    ("compaction", {"tol": "1"}, {}),          # out of (0, 1)
    ("compaction", {"rho": "1e400"}, {}),      # overflows a double
    ("collapse", {"a": "1.5"}, {}),            # not whole
    ("collapse", {"a": "0"}, {}),              # below [1, 64]
    ("collapse", {"a": "65"}, {}),             # above
    ("collapse", {"lstps": "2e3"}, {}),        # whole, but written with an exponent
    ("collapse", {"NRitMax": "1"}, {}),        # below [2, 1000]
    ("collapse", {"mp": ""}, {}),              # empty
    ("collapse", {"width": "8"}, {}),          # (8, 1000]: the open end
    ("collapse", {}, {"--vtk": "-1"}),         # an option's value
    ("collapse", {}, {"--vtk": "x"}),
]

FORM_JS = r"""
window.T = {
  form: async function (setup, params, opts) {
    var s = document.getElementById("setup");
    document.querySelectorAll("[data-option]").forEach(function (i) {
      if (i.tagName === "SELECT") i.selectedIndex = 0; else i.value = i.defaultValue;
    });
    document.querySelectorAll("[data-flag]").forEach(function (i) { i.checked = false; });
    s.value = setup;
    s.dispatchEvent(new Event("change", {bubbles: true}));
    for (var k in params) {
      var i = document.getElementById("param-" + k);
      i.value = params[k];
      i.dispatchEvent(new Event("input", {bubbles: true}));
    }
    for (var o in opts) {
      var j = document.querySelector('[data-option="' + o + '"]');
      j.value = opts[o];
      j.dispatchEvent(new Event("input", {bubbles: true}));
    }
    await amplePage.check();
    return {check: document.getElementById("check").textContent, command: document.getElementById("commandLine").textContent,
            runOff: document.getElementById("run").disabled};
  },
  run: function () { var n = ampleRuns.length; window.T.clicked = performance.now(); document.getElementById("run").click(); return n; },
  summary: function (n) {
    var r = ampleRuns[n];
    return {status: r.status, frames: r.frames.map(function (f) { return f.lstp; }), passes: r.passes.length,
            texts: r.texts, stderr: r.stderr, seconds: r.seconds, wall: (r.done - window.T.clicked) / 1000,
            title: document.getElementById("title").textContent, message: document.getElementById("message").textContent,
            drawn: Viewer.state().drawn, nmp: r.frames.length ? r.frames[r.frames.length - 1].n : 0};
  }
};
true
"""


def serve(folder):
    handler = functools.partial(Quiet, directory=folder)
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def native(opt, words, out, threads=None):
    env = dict(os.environ)
    if threads:
        env["OMP_NUM_THREADS"] = str(threads)
    t = time.time()
    r = subprocess.run([opt.native] + words + ["--quiet", "--out", out], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True, env=env)
    return r.returncode, r.stderr, time.time() - t


def args_of(setup, params, opts):
    return [setup] + ["%s=%s" % kv for kv in params.items()] + [w for kv in opts.items() for w in kv]


def run_page(b, setup, params, opts, timeout=180):
    form = b.eval("T.form(%s, %s, %s)" % (json.dumps(setup), json.dumps(params), json.dumps(opts)))
    if form["check"]:
        raise RuntimeError("the form refused %s: %s" % (form["command"], form["check"]))
    n = b.eval("T.run()")
    b.wait("ampleRuns.length > %d && ampleRuns[%d].status !== undefined" % (n, n), timeout)
    return n, b.eval("T.summary(%d)" % n)


def write_texts(texts, folder):
    os.makedirs(folder, exist_ok=True)
    for name, text in texts.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)


def vtk_numbers(text):
    """the numbers of a legacy ASCII VTK file, per section (keyword line: numbers)"""
    out, key = {}, None
    for line in text.splitlines():
        if re.match(r"^[A-Z_]+ ", line) or line.startswith("LOOKUP_TABLE"):
            key = line if not line.startswith("LOOKUP_TABLE") else key
            out.setdefault(key, [])
        elif key and line.strip():
            out[key] += [float(w) for w in line.split()]
    return out


def check_bad_inputs(b, opt, problems):
    same = 0
    for setup, params, opts in BAD:
        words = args_of(setup, params, opts)
        rc, err, _ = native(opt, words, os.path.join(opt.work, "bad"))
        form = b.eval("T.form(%s, %s, %s)" % (json.dumps(setup), json.dumps(params), json.dumps(opts)))
        want = err.strip()
        if rc != 2 or form["check"] != want or not form["runOff"]:
            problems.append("bad input %s: native exit %d %r; the form %r (Run %s)"
                            % (" ".join(words), rc, want, form["check"], "off" if form["runOff"] else "ON"))
        else:
            same += 1
    print("bad inputs: %d of %d refused by the form with the command line's message, Run off" % (same, len(BAD)))


def check_refused_by_program(b, opt, problems):
    # solver=MUMPS passes the form (a choice of the table) and is refused by the browser build
    # with the message of a native build without MUMPS (a native build with it runs it: exit 0)
    rc, err, _ = native(opt, ["compaction", "solver=MUMPS", "--vtk", "0"], os.path.join(opt.work, "mumps"))
    n, s = run_page(b, "compaction", {"solver": "MUMPS"}, {"--vtk": "0"})
    refusal = "ample: solver=MUMPS is not in this build: it has solver=LU, LDLT;"
    same = s["message"].strip() == err.strip() if rc == 2 else rc == 0
    if not (s["status"] == 2 and s["message"].startswith(refusal) and same):
        problems.append("solver=MUMPS: native exit %d %r, page %s %r" % (rc, err.strip(), s["status"], s["message"]))
    # a run that stops: the message, and the steps up to the last converged one
    out = os.path.join(opt.work, "stop_native")
    rc, err, _ = native(opt, ["collapse", "width=9", "--vtk", "0"], out)
    n, s = run_page(b, "collapse", {"width": "9"}, {"--vtk": "0"})
    summary = json.load(open(os.path.join(out, "summary.json")))
    first_native, first_page = err.splitlines()[0], (s["message"].splitlines() or [""])[0]
    write_texts(s["texts"], os.path.join(opt.work, "stop_page"))
    bad, meas = wasm_compare.compare(out, os.path.join(opt.work, "stop_page"), 1e-10)
    frames_ok = s["frames"] and s["frames"][-1] == summary["last_converged_step"]
    if rc != 1 or s["status"] != 1 or first_native != first_page or not frames_ok or bad:
        problems.append("collapse width=9: native exit %d %r, page %s %r, frames to step %s (native: %d); %s"
                        % (rc, first_native, s["status"], first_page, s["frames"][-1:] or None,
                           summary["last_converged_step"], bad))
    if "stopped" not in s["title"] or summary["message"] not in s["title"]:
        problems.append("collapse width=9: the heading lacks the stop or its message: %r" % s["title"])
    print("refused by the program in the page as natively: solver=MUMPS (exit 2), collapse width=9 (exit 1, "
          "stopped after load step %d, %d frames kept, within %.1e)" % (summary["last_converged_step"],
                                                                       len(s["frames"]), meas["mp_final"]))


def check_runs(b, opt, problems, shots):
    for setup, field in (("compaction", "syy"), ("collapse", "vonMises"), ("footing", "vonMises")):
        out = os.path.join(opt.work, setup + "_native")
        rc, err, _ = native(opt, [setup], out)
        b.eval("T.form(%s, {}, {})" % json.dumps(setup))
        b.eval("document.getElementById('field').value = %s; true" % json.dumps(field))
        n = b.eval("T.run()")
        if setup != "compaction":                      # a picture during the run: at 3/4 of the steps
            lstps = json.load(open(os.path.join(out, "summary.json")))["lstps"]
            b.wait("ampleRuns.length > %d && (ampleRuns[%d].frames.length > %d || ampleRuns[%d].status !== undefined)"
                   % (n, n, 3 * lstps // 4, n), 120)
            shots.append(b.screenshot(os.path.join(opt.work, setup + "_running.png")))
        b.wait("ampleRuns.length > %d && ampleRuns[%d].status !== undefined" % (n, n), 180)
        s = b.eval("T.summary(%d)" % n)
        page = os.path.join(opt.work, setup + "_page")
        write_texts(s["texts"], page)
        bad, meas = wasm_compare.compare(out, page, 1e-10)
        problems += ["%s through the form: %s" % (setup, x) for x in bad]
        summary = json.load(open(os.path.join(out, "summary.json")))
        steps = list(range(0, summary["lstps"] + 1))
        if rc != 0 or s["status"] != 0 or s["frames"] != steps:
            problems.append("%s: native exit %d, page %s, frames %s" % (setup, rc, s["status"], s["frames"]))
        if s["drawn"][-1:] != [summary["nmp"]]:
            problems.append("%s: the last frame drew %s points of %d" % (setup, s["drawn"][-1:], summary["nmp"]))
        last = "mpData_%d.vtk" % summary["lstps"]
        text = b.eval("Viewer.run.fetchFile(%s).then(function (b) { return new TextDecoder().decode(b); })"
                      % json.dumps(last))
        mine, theirs = vtk_numbers(text), vtk_numbers(open(os.path.join(out, last)).read())
        worst = 0.0
        stress = [v for key, want in theirs.items() if re.search(r" (sigma_|rho_)", key) for v in want]
        for key, want in theirs.items():
            got = mine.get(key, [])
            scale = max([abs(v) for v in (stress if re.search(r" (sigma_|rho_)", key) else want)] + [1e-300])
            if len(got) != len(want):
                worst = float("inf")
                continue
            worst = max([worst] + [abs(x - y) / scale for x, y in zip(got, want)])
        if not worst <= 1e-10 or set(mine) != set(theirs):
            problems.append("%s: the page's %s differs from the native one (%.2e)" % (setup, last, worst))
        if setup != "compaction":
            shots.append(b.screenshot(os.path.join(opt.work, setup + "_done.png")))
        print("%-10s through the form: exit 0, %d frames streamed and drawn, %d passes; within the native run: "
              "results %.1e, mp_final %.1e, %s %.1e; in the page %.2f s (native %.2f s with its VTK files)"
              % (setup, len(s["frames"]), s["passes"], meas["results"], meas["mp_final"], last, worst,
                 s["wall"], summary["wall_seconds"]))


def check_controls(b, problems):
    """on the last run shown (the footing): the replay, zoom, pan and Fit, a field"""
    r = b.eval(r"""(function () {
      var c = document.getElementById("canvas"), s = document.getElementById("slider"), out = {};
      var box = function () { var p = Viewer.state().plot; return [p.left, p.right, p.top, p.bottom]; };
      out.fitted = box();
      s.value = "0"; s.dispatchEvent(new Event("input", {bubbles: true}));
      out.first = [Viewer.state().shown, Viewer.state().lstp];
      var r = c.getBoundingClientRect();
      c.dispatchEvent(new WheelEvent("wheel", {deltaY: -400, clientX: r.left + r.width / 2, clientY: r.top + r.height / 2,
                                               bubbles: true, cancelable: true}));
      out.zoomed = box();
      c.dispatchEvent(new PointerEvent("pointerdown", {clientX: 100, clientY: 100, pointerId: 1, bubbles: true}));
      c.dispatchEvent(new PointerEvent("pointermove", {clientX: 160, clientY: 130, pointerId: 1, bubbles: true}));
      c.dispatchEvent(new PointerEvent("pointerup", {clientX: 160, clientY: 130, pointerId: 1, bubbles: true}));
      out.panned = box();
      c.dispatchEvent(new MouseEvent("dblclick", {bubbles: true}));
      out.refitted = box();
      var f = document.getElementById("field");
      f.value = "uy"; f.dispatchEvent(new Event("change", {bubbles: true}));
      out.drawnUy = Viewer.state().drawn[0];
      return out; })()""")
    w = lambda b_: b_[1] - b_[0]
    ok = (r["first"] == [0, 0] and w(r["zoomed"]) > 1.5 * w(r["fitted"]) and
          r["panned"][0] - r["zoomed"][0] == 60 and r["panned"][2] - r["zoomed"][2] == 30 and
          r["refitted"] == r["fitted"] and r["drawnUy"] > 0)
    print("controls: slider to frame %s (load step %s), wheel zoom %.2f x, drag pans (%d, %d) px, "
          "double-click fits again: %s" % (r["first"][0], r["first"][1], w(r["zoomed"]) / w(r["fitted"]),
                                          r["panned"][0] - r["zoomed"][0], r["panned"][2] - r["zoomed"][2],
                                          r["refitted"] == r["fitted"]))
    if not ok:
        problems.append("controls: %s" % r)


def check_every_setup(b, opt, problems):
    names = b.eval("Array.prototype.map.call(document.getElementById('setup').options, function (o) { return o.value; })")
    lines, t = [], time.time()
    for setup in names:
        if setup in ("compaction", "collapse", "footing"):
            continue
        out = os.path.join(opt.work, "every_" + setup)
        rc, err, tn = native(opt, [setup, "--vtk", "0"], out, threads=1)
        n, s = run_page(b, setup, {}, {"--vtk": "0"})
        page = os.path.join(opt.work, "every_%s_page" % setup)
        write_texts(s["texts"], page)
        summary = json.load(open(os.path.join(out, "summary.json")))
        if s["status"] != rc or s["frames"] != list(range(0, summary["last_converged_step"] + 1)):
            problems.append("%s in the page: exit %s (native %d), frames %s" % (setup, s["status"], rc, s["frames"]))
            continue
        bad, meas = wasm_compare.compare(out, page, 1e-10)
        lines.append("  %-13s exit %d, %4d points, %3d passes, page %.2f s (native %.2f s)%s"
                     % (setup, rc, summary["nmp"], summary["total_NR_iterations"], s["wall"], tn,
                        "" if not bad else "; differs: results %.1e, mp_final %.1e%s" % (
                            meas["results"], meas["mp_final"],
                            ", passes %d native, %d page" % (summary["total_NR_iterations"],
                                                            json.loads(s["texts"]["summary.json"])["total_NR_iterations"])
                            if any("passes" in x or "NR_iterations" in x for x in bad) else "")))
    print("every other setup through the form with its defaults (%.0f s):" % (time.time() - t))
    print("\n".join(lines))


def check_speed(b, opt, problems):
    words = ["collapse", "a=4", "--vtk", "0"]
    natives = [native(opt, words, os.path.join(opt.work, "speed_native"), threads=1)[2] for _ in range(2)]
    pages = []
    for _ in range(2):
        n, s = run_page(b, "collapse", {"a": "4"}, {"--vtk": "0"})
        if s["status"] != 0:
            problems.append("collapse a=4 in the page: exit %s" % s["status"])
        pages.append((s["wall"], s["seconds"]))
    nat, page = min(natives), min(p[0] for p in pages)
    print("speed: collapse a=4 --vtk 0: native (1 thread) %.2f s, in the page %.2f s from Run to its end "
          "(ampleRun itself %.2f s): %.2f x native" % (nat, page, min(p[1] for p in pages), page / nat))
    if page > 3 * nat:
        problems.append("collapse a=4 in the page %.2f s > 3 x native %.2f s" % (page, nat))


def check_cancel(b, opt, problems):
    b.eval("T.form('collapse', {a: '16'}, {'--vtk': '0'})")
    n = b.eval("T.run()")
    b.eval("""(function () { var last = performance.now(); window.gap = 0;
      window.gapTimer = setInterval(function () { var t = performance.now(); gap = Math.max(gap, t - last); last = t; }, 20);
      return true; })()""")
    b.wait("ampleRuns[%d].frames.some(function (f) { return f.lstp >= 1; })" % n, 300)
    passes = b.eval("ampleRuns[%d].passes.length" % n)
    t = b.eval("(function () { var t = performance.now(); document.getElementById('cancel').click(); "
               "return performance.now() - t; })()")
    after = b.eval("ampleRuns[%d].passes.length" % n)
    time.sleep(1.5)
    later = b.eval("ampleRuns[%d].passes.length" % n)
    gap = b.eval("clearInterval(gapTimer), gap")
    title = b.eval("document.getElementById('title').textContent")
    nmp = b.eval("ampleRuns[%d].frames[0].n" % n)
    print("cancel: collapse a=16 (%d points) cancelled in load step 2 after %d passes: Cancel took %.1f ms, "
          "passes streamed after it: %d; the page's longest timer gap during the run %.0f ms"
          % (nmp, passes, t, later - after, gap))
    if later != after or "cancelled" not in title or t > 1000:
        problems.append("cancel: %d passes after Cancel, title %r, %.0f ms" % (later - after, title, t))
    if gap > 500:
        problems.append("the page did not answer its timers for %.0f ms during the run" % gap)


def check_folder(b, opt, problems):
    out = os.path.join(opt.work, "folder_native")
    native(opt, ["collapse", "--vtk", "2", "--vtk-format", "binary"], out)
    node = b.call("DOM.querySelector", nodeId=b.call("DOM.getDocument")["root"]["nodeId"], selector="#folder")
    n = b.eval("ampleRuns.length")
    b.call("DOM.setFileInputFiles", nodeId=node["nodeId"], files=[os.path.abspath(out)])   # the folder
    b.wait("ampleRuns.length > %d" % n, 60)
    st = b.eval("Viewer.state()")
    vtks = sorted(glob.glob(os.path.join(out, "mpData_*.vtk")))
    summary = json.load(open(os.path.join(out, "summary.json")))
    print("native output folder (collapse --vtk 2, binary VTK): %d frames, points drawn in the last %s"
          % (st["frames"], st["drawn"][-1:]))
    if st["frames"] != len(vtks) or st["drawn"][-1] != summary["nmp"]:
        problems.append("the folder: %d frames for %d VTK files, %s points drawn" % (st["frames"], len(vtks), st["drawn"]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--native", required=True)
    ap.add_argument("--viewer", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--shots")
    ap.add_argument("--chromium", default=shutil.which("chromium") or shutil.which("chromium-browser"))
    opt = ap.parse_args()
    if not opt.chromium or not os.path.exists(os.path.join(opt.viewer, "ample_wasm.wasm")):
        print("SKIPPED: needs chromium and the browser build %s (cmake --workflow --preset wasm)" % opt.viewer)
        return 77
    shutil.rmtree(opt.work, ignore_errors=True)
    os.makedirs(opt.work)
    httpd = serve(opt.viewer)
    b = cdp.Browser(opt.chromium, opt.work)
    problems, shots = [], []
    try:
        b.call("Page.navigate", url="http://127.0.0.1:%d/index.html" % httpd.server_address[1])
        b.wait("window.pageReady", 30)
        first = b.eval("window.firstPictureSeconds")
        drawn = b.eval("Viewer.state().drawn")
        b.screenshot(os.path.join(opt.work, "opened.png"))
        print("first picture (collapse as set up, %s points) %.2f s after opening" % (drawn, first))
        if not first or first > 2 or not drawn or not drawn[0]:
            problems.append("first picture: %s s, points drawn %s" % (first, drawn))
        b.eval(FORM_JS)
        check_bad_inputs(b, opt, problems)
        check_refused_by_program(b, opt, problems)
        check_runs(b, opt, problems, shots)
        check_controls(b, problems)
        check_every_setup(b, opt, problems)
        check_speed(b, opt, problems)
        check_cancel(b, opt, problems)
        check_folder(b, opt, problems)
        errors = b.eval("window.pageErrors") + b.console
        if errors:
            problems.append("script errors: %s" % errors[:3])
    finally:
        b.close()
        httpd.shutdown()
    if opt.shots:
        os.makedirs(opt.shots, exist_ok=True)
        for s in shots:
            shutil.copy(s, os.path.join(opt.shots, "viewer_%s_%s.png" % (os.path.basename(s)[:-4],
                                                                        time.strftime("%Y-%m-%d"))))
    for p in problems:
        print("FAIL " + p)
    print("wasm.page: %s" % ("all checks passed" if not problems else "%d problems" % len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
