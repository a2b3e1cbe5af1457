#!/usr/bin/env python3
"""animate_run.py — the viewer (plotting/viewer/) with one run's output folder inside it: run.html.

The page is the viewer of the browser tab (docs/browser.md) with its scripts and style inlined and
the run's files (summary.json, the CSV files, mesh.vtk, mesh_<lstp>.vtk, mpData_<lstp>.vtk: `--vtk N`
writes every N steps; ASCII or BINARY) inside it, base64-encoded: one self-contained file (no
network, no server, no program) that plays every written load step over the grid, to scale,
coloured by a field (the colour list of the page; FIELD the one shown first), with a slider,
Play, zoom and pan, each step's load factor and residual, the residuals of every pass, the run's
figures, and a stopped run's whole message in its title and heading. A fragment picks the frame
shown first: run.html#frame=last, run.html#frame=3 (0 = the first frame written). Keys:
left/right arrows step, space plays or pauses. The same page opens any output folder ("Open an
output folder…") when served with the program (build/wasm/viewer).

usage: animate_run.py OUTDIR [--field NAME] [--out HTML]      (or plot_run.py --animate OUTDIR)
  --field   one of: vonMises sxx syy szz sxy p ux uy u J  (default vonMises; J needs
            mp_final.csv's V0, i.e. the number of points did not change)
  --out     the page to write (default OUTDIR/run.html)
e.g.   build/release/ample collapse --vtk 2 --out output/collapse &&
       plotting/plot_run.py --animate output/collapse
Only the Python standard library. Tests: tests/animate_test.sh (CTest browser.animate)
"""
import argparse
import base64
import glob
import html
import json
import os
import re
import sys
from run_output import FIELDS, read_summary

VIEWER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "viewer")
# the files of an output folder the viewer reads (readRun.js)
RUN_FILES = re.compile(r"^(summary\.json|steps\.csv|residuals\.csv|mp_final\.csv|history\.csv|"
                       r"mesh(_\d+)?\.vtk|mpData_\d+\.vtk)$")


def heading_of(summary):
    name = summary["setup"]
    if summary["converged"]:
        state = "converged, %d load steps" % summary["lstps"]
    else:
        state = "stopped after load step %d of %d: %s" % (summary["last_converged_step"],
                                                         summary["lstps"], summary["message"])
    return "%s — %s" % (name, state)


def inline(page, name):
    """the viewer's <script src> or <link> of name replaced by the file's text"""
    with open(os.path.join(VIEWER, name), encoding="utf-8") as f:
        text = f.read()
    if name.endswith(".css"):
        return page.replace('<link rel="stylesheet" href="%s">' % name, "<style>\n%s</style>" % text)
    return page.replace('<script src="%s"></script>' % name, "<script>\n%s</script>" % text.replace("</", "<\\/"))


def page_of(outdir, field, summary):
    files = {}
    for name in sorted(os.listdir(outdir)):
        if RUN_FILES.match(name):
            with open(os.path.join(outdir, name), "rb") as f:
                files[name] = base64.b64encode(f.read()).decode("ascii")
    with open(os.path.join(VIEWER, "index.html"), encoding="utf-8") as f:
        page = f.read()
    for name in ("viewer.css", "readRun.js", "viewer.js", "page.js"):
        page = inline(page, name)
    heading = html.escape(heading_of(summary))
    data = ("<script>\nwindow.AMPLE_RUN_FIELD = %s;\nwindow.AMPLE_RUN_FILES = %s;\n</script>\n"
            % (json.dumps(field), json.dumps(files, separators=(",", ":"))))
    page = re.sub(r"<title>.*?</title>", "<title>%s</title>" % heading, page, count=1)
    page = re.sub(r'<h1 id="title">.*?</h1>', '<h1 id="title" class="%s">%s</h1>'
                  % ("converged" if summary["converged"] else "stopped", heading), page, count=1)
    return page.replace('<pre id="status">not drawn</pre>', '<pre id="status">not drawn</pre>\n' + data, 1)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--field", default="vonMises", choices=sorted(FIELDS))
    ap.add_argument("--out")
    opt = ap.parse_args(argv)
    if not os.path.exists(os.path.join(opt.outdir, "summary.json")):
        sys.exit("animate_run.py: %s has no summary.json: not the output folder of a run" % opt.outdir)
    vtks = sorted(glob.glob(os.path.join(opt.outdir, "mpData_*.vtk")),
                  key=lambda p: int(re.findall(r"_(\d+)\.vtk$", p)[0]))
    if not vtks:
        sys.exit("animate_run.py: %s has no mpData_<lstp>.vtk: run with --vtk N (N > 0) "
                 "to write the points every N load steps" % opt.outdir)
    summary = read_summary(opt.outdir)
    page = page_of(opt.outdir, opt.field, summary)
    out = opt.out or os.path.join(opt.outdir, "run.html")
    with open(out, "w", encoding="utf-8") as f:
        f.write(page)
    first, last = (int(re.findall(r"_(\d+)\.vtk$", p)[0]) for p in (vtks[0], vtks[-1]))
    print("%s: %d frames (load steps %d-%d), %.0f kB" % (out, len(vtks), first, last,
                                                        len(page.encode("utf-8")) / 1024))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
