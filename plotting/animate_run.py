#!/usr/bin/env python3
"""animate_run.py — one HTML page to watch a run of ample load step by load step.

The page holds, for every load step the run wrote (mpData_<lstp>.vtk: `--vtk N` writes every
N steps; ASCII or BINARY), the material points, each its domain (GIMP: 2 lp x 2 lp; otherwise
a square of area V, as plot_run.py draws them), coloured by FIELD over the background grid
(mesh_<lstp>.vtk, else mesh.vtk), with a slider, a play/pause button and, per frame, the load
step, the load factor and the final residual fErr of that step (steps.csv, residuals.csv).
Axes are equal (a square cell looks square); the colour bar spans the field's range over all
frames. A run that stopped says so, with its whole message, in the page's title and heading.

The page is one self-contained file (data as JSON, drawn on a canvas by inline JavaScript:
no network, no server). Open it in a browser; a fragment picks the frame shown first:
run.html#frame=last, run.html#frame=3 (0 = the first frame written). Keys: left/right arrows
step, space plays or pauses.

usage: animate_run.py OUTDIR [--field NAME] [--out HTML]      (or plot_run.py --animate OUTDIR)
  --field   one of: vonMises sxx syy szz sxy p ux uy u J  (default vonMises; J needs
            mp_final.csv's V0, i.e. the number of points did not change)
  --out     the page to write (default OUTDIR/run.html)
e.g.   build/release/ample collapse --vtk 2 --out output/collapse &&
       plotting/plot_run.py --animate output/collapse
Only the Python standard library. Tests: tests/animate_test.sh (CTest browser.animate)
"""
import argparse
import glob
import html
import json
import math
import os
import re
import sys
from run_output import FIELDS, read_csv, read_legacy_vtk, read_mesh, read_summary


def _mean_stress(d, p):
    return (d["sigma_xx"][p] + d["sigma_yy"][p] + d["sigma_zz"][p]) / 3


# a field of plot_run.py from the point data of an mpData VTK file (d) and mp_final.csv's V0
VTK_FIELDS = {
    "vonMises": lambda d, p, v0: d["rho_vonMises"][p],
    "sxx": lambda d, p, v0: d["sigma_xx"][p],
    "syy": lambda d, p, v0: d["sigma_yy"][p],
    "szz": lambda d, p, v0: d["sigma_zz"][p],
    "sxy": lambda d, p, v0: d["sigma_xy"][p],
    "p": lambda d, p, v0: _mean_stress(d, p),
    "ux": lambda d, p, v0: d["ux"][p],
    "uy": lambda d, p, v0: d["uy"][p],
    "u": lambda d, p, v0: math.hypot(d["ux"][p], d["uy"][p]),
    "J": lambda d, p, v0: d["volume"][p] / v0[p],
}


def lstp_of(path):
    return int(re.findall(r"_(\d+)\.vtk$", path)[0])


def short(x):
    """a number to 6 significant digits for the page (None if not finite: JSON null)"""
    return float("%.6g" % x) if math.isfinite(x) else None


def grid_of(path):
    """the grid's nodes and its edges, each once"""
    nodes, cells, _ = read_mesh(path)
    edges = sorted({tuple(sorted((c[k], c[(k + 1) % len(c)]))) for c in cells for k in range(len(c))})
    return {"nodes": [v for n in nodes for v in (short(n[0]), short(n[1]))],
            "edges": [i for e in edges for i in e]}


def step_rows(outdir):
    """lstp: (load factor, final fErr, Newton-Raphson passes) of each step written"""
    out = {}
    if os.path.exists(os.path.join(outdir, "residuals.csv")):
        for r in read_csv(os.path.join(outdir, "residuals.csv")):
            out[int(r["lstp"])] = (None, r["fErr"], int(r["NRit"]))
    if os.path.exists(os.path.join(outdir, "steps.csv")):
        for r in read_csv(os.path.join(outdir, "steps.csv")):
            out[int(r["lstp"])] = (r["load_factor"], r["fErr"], int(r["NRit"]))
    return out


def frames_of(outdir, field):
    paths = sorted(glob.glob(os.path.join(outdir, "mpData_*.vtk")), key=lstp_of)
    if not paths:
        sys.exit("animate_run.py: %s has no mpData_<lstp>.vtk: run with --vtk N (N > 0) "
                 "to write the points every N load steps" % outdir)
    v0 = None
    if field == "J" and os.path.exists(os.path.join(outdir, "mp_final.csv")):
        v0 = [r["V0"] for r in read_csv(os.path.join(outdir, "mp_final.csv"))]
    steps = step_rows(outdir)
    grids, frames = [], []
    first_grid = os.path.join(outdir, "mesh.vtk")
    for path in paths:
        lstp = lstp_of(path)
        d = read_legacy_vtk(path)
        data, n = d["data"], len(d["points"])
        if field == "J" and (v0 is None or len(v0) != n):
            sys.exit("animate_run.py: J = V / V0 needs mp_final.csv with the %d points of %s" % (n, path))
        try:
            values = [VTK_FIELDS[field](data, p, v0) for p in range(n)]
        except KeyError as e:
            sys.exit("animate_run.py: %s has no %s for the field %s" % (path, e, field))
        half = []
        for p in range(n):
            lx, ly = data["lpx"][p], data["lpy"][p]
            if not (lx > 0 and ly > 0):
                lx = ly = 0.5 * math.sqrt(max(data["volume"][p], 0.0))
            half.append((lx, ly))
        mesh = os.path.join(outdir, "mesh_%d.vtk" % lstp)
        mesh = mesh if os.path.exists(mesh) else first_grid
        g = -1
        if os.path.exists(mesh):
            grid = grid_of(mesh)
            if grid not in grids:
                grids.append(grid)
            g = grids.index(grid)
        lf, ferr, nrit = steps.get(lstp, (None, None, None))
        frames.append({
            "lstp": lstp, "load_factor": lf if lf is None else short(lf),
            "fErr": ferr if ferr is None else short(ferr), "NRit": nrit, "grid": g, "n": n,
            "x": [short(xy[0]) for xy in d["points"]], "y": [short(xy[1]) for xy in d["points"]],
            "hx": [short(h[0]) for h in half], "hy": [short(h[1]) for h in half],
            "v": [short(v) for v in values]})
    return frames, grids


def heading_of(summary):
    name = summary["setup"]
    if summary["converged"]:
        state = "converged, %d load steps" % summary["lstps"]
    else:
        state = "stopped after load step %d of %d: %s" % (summary["last_converged_step"],
                                                         summary["lstps"], summary["message"])
    return "%s — %s" % (name, state)


PAGE = r"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>__TITLE__</title>
<style>
 body { font-family: sans-serif; margin: 12px 16px; color: #222; background: #fff; }
 h1 { font-size: 17px; font-weight: normal; margin: 0 0 6px 0; max-width: 1100px;
      overflow-wrap: anywhere; }
 h1.stopped { color: #a01010; }
 #info { font-size: 14px; margin: 4px 0 8px 0; min-height: 1.3em; }
 #controls { margin: 6px 0; font-size: 14px; }
 #controls input[type=range] { width: 520px; vertical-align: middle; }
 #play { width: 70px; }
 canvas { display: block; border: 1px solid #ddd; }
 #status { display: none; }   /* what the page drew, for tests/animate_check.py */
 #errors { color: #c00; font-size: 13px; white-space: pre-wrap; }
</style>
<script>
// errors of any later script (even one that does not parse) end up in the page
window.pageErrors = [];
window.addEventListener("error", function (e) {
  window.pageErrors.push(String(e.message) + " (line " + e.lineno + ")");
  var el = document.getElementById("errors");
  if (el) el.textContent = "script error: " + window.pageErrors.join("; ");
});
</script>
</head>
<body>
<h1 id="title" class="__STATE__">__HEADING__</h1>
<div id="info"></div>
<canvas id="view"></canvas>
<div id="controls">
 <button id="play" type="button">Play</button>
 <input id="slider" type="range" min="0" max="0" step="1" value="0">
 <span id="frameNo"></span>
 <label> frame time <select id="speed">
  <option value="1000">1 s</option><option value="400" selected>0.4 s</option>
  <option value="150">0.15 s</option><option value="50">0.05 s</option></select></label>
</div>
<div id="errors"></div>
<pre id="status">not drawn</pre>
<script id="run-data" type="application/json">__DATA__</script>
<script>
"use strict";
var RUN = JSON.parse(document.getElementById("run-data").textContent);
var frames = RUN.frames, grids = RUN.grids;
var W = 980;                                 // canvas width in CSS pixels; the height follows the body
var BAR = 120;                               // room for the colour bar, right
var M = {left: 70, right: 16 + BAR, top: 16, bottom: 46};
// matplotlib's viridis, 17 samples, interpolated linearly
var VIRIDIS = ["#440154", "#48186a", "#472d7b", "#424086", "#3b528b", "#33638d", "#2c728e",
  "#26828e", "#21918c", "#1fa088", "#28ae80", "#3fbc73", "#5ec962", "#84d44b", "#addc30",
  "#d8e219", "#fde725"].map(function (h) {
    return [parseInt(h.substr(1, 2), 16), parseInt(h.substr(3, 2), 16), parseInt(h.substr(5, 2), 16)];
  });
function colour(t) {
  if (!isFinite(t)) return "rgb(160,160,160)";
  t = Math.min(1, Math.max(0, t)) * (VIRIDIS.length - 1);
  var i = Math.min(VIRIDIS.length - 2, Math.floor(t)), f = t - i, a = VIRIDIS[i], b = VIRIDIS[i + 1];
  return "rgb(" + Math.round(a[0] + f * (b[0] - a[0])) + "," + Math.round(a[1] + f * (b[1] - a[1])) +
         "," + Math.round(a[2] + f * (b[2] - a[2])) + ")";
}
function niceTicks(lo, hi, want) {
  var span = hi - lo;
  if (!(span > 0)) return [lo];
  var step = Math.pow(10, Math.floor(Math.log10(span / want))), r = span / want / step;
  step *= r > 5 ? 10 : r > 2 ? 5 : r > 1 ? 2 : 1;
  var out = [];
  for (var v = Math.ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * span; v += step)
    out.push(Math.abs(v) < 1e-12 * span ? 0 : v);
  return out;
}
function fmt(v) {
  if (v === null || v === undefined) return "–";
  if (v === 0) return "0";
  var a = Math.abs(v);
  return a >= 1e5 || a < 1e-3 ? v.toExponential(2) : String(Number(v.toPrecision(4)));
}

// bounds of everything drawn in any frame, and one scale for x and y (equal axes)
var xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
function grow(x, y) {
  if (!isFinite(x) || !isFinite(y)) return;
  xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymin = Math.min(ymin, y); ymax = Math.max(ymax, y);
}
grids.forEach(function (g) { for (var k = 0; k < g.nodes.length; k += 2) grow(g.nodes[k], g.nodes[k + 1]); });
frames.forEach(function (f) {
  for (var p = 0; p < f.n; ++p) { grow(f.x[p] - f.hx[p], f.y[p] - f.hy[p]); grow(f.x[p] + f.hx[p], f.y[p] + f.hy[p]); }
});
if (!(xmax > xmin)) { xmin -= 0.5; xmax += 0.5; }
if (!(ymax > ymin)) { ymin -= 0.5; ymax += 0.5; }
var pad = 0.02 * Math.max(xmax - xmin, ymax - ymin);
xmin -= pad; xmax += pad; ymin -= pad; ymax += pad;
var plotW = W - M.left - M.right;
var plotH = Math.max(260, Math.min(620, plotW * (ymax - ymin) / (xmax - xmin)));
var H = plotH + M.top + M.bottom;
var scale = Math.min(plotW / (xmax - xmin), plotH / (ymax - ymin));
// centre the drawing in the plot area: the unused room is shared on both sides
var ox = M.left + 0.5 * (plotW - scale * (xmax - xmin)), oy = M.top + 0.5 * (plotH - scale * (ymax - ymin));
function px(x) { return ox + (x - xmin) * scale; }
function py(y) { return oy + (ymax - y) * scale; }
var lo = RUN.range[0], hi = RUN.range[1];

var canvas = document.getElementById("view");
var dpr = window.devicePixelRatio || 1;
canvas.style.width = W + "px"; canvas.style.height = H + "px";
canvas.width = Math.round(W * dpr); canvas.height = Math.round(H * dpr);
var ctx = canvas.getContext("2d");
ctx.setTransform(dpr, 0, 0, dpr, 0, 0);

function drawAxes() {
  var x0 = px(xmin), x1 = px(xmax), y0 = py(ymin), y1 = py(ymax);
  ctx.strokeStyle = "#444"; ctx.lineWidth = 1;
  ctx.strokeRect(x0, y1, x1 - x0, y0 - y1);
  ctx.fillStyle = "#222"; ctx.font = "12px sans-serif";
  ctx.textAlign = "center"; ctx.textBaseline = "top";
  niceTicks(xmin, xmax, 8).forEach(function (v) {
    ctx.beginPath(); ctx.moveTo(px(v), y0); ctx.lineTo(px(v), y0 + 4); ctx.stroke();
    ctx.fillText(fmt(v), px(v), y0 + 6);
  });
  ctx.fillText("x (m)", 0.5 * (x0 + x1), y0 + 24);
  ctx.textAlign = "right"; ctx.textBaseline = "middle";
  niceTicks(ymin, ymax, 6).forEach(function (v) {
    ctx.beginPath(); ctx.moveTo(x0, py(v)); ctx.lineTo(x0 - 4, py(v)); ctx.stroke();
    ctx.fillText(fmt(v), x0 - 6, py(v));
  });
  ctx.save(); ctx.translate(x0 - 52, 0.5 * (y0 + y1)); ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center"; ctx.fillText("y (m)", 0, 0); ctx.restore();
}
function drawColourBar() {
  var bx = W - BAR + 10, bw = 18, by = M.top + 10, bh = plotH - 20;
  for (var k = 0; k < bh; ++k) {
    ctx.fillStyle = colour(1 - k / (bh - 1));
    ctx.fillRect(bx, by + k, bw, 1.5);
  }
  ctx.strokeStyle = "#444"; ctx.strokeRect(bx, by, bw, bh);
  ctx.fillStyle = "#222"; ctx.font = "11px sans-serif"; ctx.textAlign = "left"; ctx.textBaseline = "middle";
  var ticks = niceTicks(lo, hi, 6);
  ticks.forEach(function (v) {
    var y = by + bh * (hi - v) / (hi - lo);
    ctx.beginPath(); ctx.moveTo(bx + bw, y); ctx.lineTo(bx + bw + 4, y); ctx.stroke();
    ctx.fillText(fmt(v), bx + bw + 6, y);
  });
  ctx.save(); ctx.translate(W - 8, by + 0.5 * bh); ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center"; ctx.textBaseline = "bottom"; ctx.fillText(RUN.label, 0, 0); ctx.restore();
}
// one frame: the grid, then the points; returns how many points it drew
function drawFrame(i) {
  var f = frames[i];
  ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, W, H);
  if (f.grid >= 0) {
    var g = grids[f.grid];
    ctx.strokeStyle = "#c4c4c4"; ctx.lineWidth = 0.6; ctx.beginPath();
    for (var e = 0; e < g.edges.length; e += 2) {
      var a = g.edges[e], b = g.edges[e + 1];
      ctx.moveTo(px(g.nodes[2 * a]), py(g.nodes[2 * a + 1]));
      ctx.lineTo(px(g.nodes[2 * b]), py(g.nodes[2 * b + 1]));
    }
    ctx.stroke();
  }
  var drawn = 0;
  for (var p = 0; p < f.n; ++p) {
    var x = f.x[p], y = f.y[p];
    if (x === null || y === null) continue;
    var v = f.v[p];
    ctx.fillStyle = colour(v === null ? NaN : (v - lo) / (hi - lo));
    var w = Math.max(1, 2 * f.hx[p] * scale), h = Math.max(1, 2 * f.hy[p] * scale);
    ctx.fillRect(px(x) - 0.5 * w, py(y) - 0.5 * h, w, h);
    ++drawn;
  }
  drawAxes();
  drawColourBar();
  return drawn;
}

var slider = document.getElementById("slider"), playButton = document.getElementById("play");
var info = document.getElementById("info"), frameNo = document.getElementById("frameNo");
slider.max = String(frames.length - 1);
var current = 0, timer = null, drawnCount = [];
function show(i) {
  current = Math.max(0, Math.min(frames.length - 1, i));
  var f = frames[current];
  drawFrame(current);
  slider.value = String(current);
  frameNo.textContent = "frame " + (current + 1) + " of " + frames.length;
  info.textContent = "load step " + f.lstp + " of " + RUN.lstps + "  ·  load factor " + fmt(f.load_factor) +
    "  ·  final residual fErr = " + (f.fErr === null ? "–" : f.fErr.toExponential(2)) +
    (f.NRit === null ? "" : " (Newton-Raphson pass " + f.NRit + ")") + "  ·  " + f.n + " points";
  report();
}
function report() {
  document.getElementById("status").textContent = JSON.stringify({
    frames: frames.length, drawn: drawnCount, shown: current, lstp: frames[current].lstp,
    errors: window.pageErrors,
    plot: {left: Math.floor(canvas.getBoundingClientRect().left + px(xmin)),
           top: Math.floor(canvas.getBoundingClientRect().top + py(ymax)),
           right: Math.ceil(canvas.getBoundingClientRect().left + px(xmax)),
           bottom: Math.ceil(canvas.getBoundingClientRect().top + py(ymin))}});
}
function stop() { if (timer) clearInterval(timer); timer = null; playButton.textContent = "Play"; }
function play() {
  if (current >= frames.length - 1) show(0);
  playButton.textContent = "Pause";
  timer = setInterval(function () {
    if (current >= frames.length - 1) { stop(); return; }
    show(current + 1);
  }, Number(document.getElementById("speed").value));
}
playButton.addEventListener("click", function () { timer ? stop() : play(); });
document.getElementById("speed").addEventListener("change", function () { if (timer) { stop(); play(); } });
slider.addEventListener("input", function () { stop(); show(Number(slider.value)); });
document.addEventListener("keydown", function (e) {
  if (e.key === "ArrowRight") { stop(); show(current + 1); }
  else if (e.key === "ArrowLeft") { stop(); show(current - 1); }
  else if (e.key === " ") { e.preventDefault(); timer ? stop() : play(); }
});
function fromHash() {
  var m = /frame=(last|\d+)/.exec(location.hash);
  return m ? (m[1] === "last" ? frames.length - 1 : Number(m[1])) : 0;
}
window.addEventListener("hashchange", function () { stop(); show(fromHash()); });
// every frame drawn once at load (the count of points each drew is in #status), then the one asked for
for (var i = 0; i < frames.length; ++i) drawnCount.push(drawFrame(i));
show(fromHash());
</script>
</body>
</html>
"""


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--field", default="vonMises", choices=sorted(FIELDS))
    ap.add_argument("--out")
    opt = ap.parse_args(argv)
    if not os.path.exists(os.path.join(opt.outdir, "summary.json")):
        sys.exit("animate_run.py: %s has no summary.json: not the output folder of a run" % opt.outdir)
    summary = read_summary(opt.outdir)
    frames, grids = frames_of(opt.outdir, opt.field)
    values = [v for f in frames for v in f["v"] if v is not None]
    lo, hi = (min(values), max(values)) if values else (0.0, 1.0)
    if hi - lo <= 1e-9 * max(abs(lo), abs(hi), 1e-300):  # a uniform field: a visible range around it
        lo, hi = lo - 0.01 * abs(lo) - 1e-12, hi + 0.01 * abs(hi) + 1e-12
    heading = heading_of(summary)
    data = {"setup": summary["setup"], "lstps": summary["lstps"], "field": opt.field,
            "label": FIELDS[opt.field][1], "range": [lo, hi], "converged": summary["converged"],
            "frames": frames, "grids": grids}
    text = json.dumps(data, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    page = (PAGE.replace("__TITLE__", html.escape(heading))
                .replace("__HEADING__", html.escape(heading))
                .replace("__STATE__", "converged" if summary["converged"] else "stopped")
                .replace("__DATA__", text))
    out = opt.out or os.path.join(opt.outdir, "run.html")
    with open(out, "w", encoding="utf-8") as f:
        f.write(page)
    print("%s: %d frames (load steps %d-%d), %d points in the last, %.0f kB"
          % (out, len(frames), frames[0]["lstp"], frames[-1]["lstp"], frames[-1]["n"],
             len(page.encode("utf-8")) / 1024))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
