//--------------------------------------------------------------------------
// viewer.js — a run drawn on the canvas: the points step by step, the grid,
// a colour scale, zoom and pan, the replay, the residuals, the downloads
//--------------------------------------------------------------------------
// One viewer for a run in the page (streamed from the worker as it goes,
// page.js) and for a run of the native program (its output folder, readRun.js;
// or run.html of plot_run.py --animate, whose files are inside the page).
//   Viewer.show(run)    draw a new run (readRun.js describes it); frames, grids
//                       and passes may grow afterwards: Viewer.update()
//   Viewer.state()      what is drawn, for the tests (also in #status)
// The points: each its domain, GIMP 2 lpx x 2 lpy, otherwise a square of area
// V (as plot_run.py draws them), coloured by a field over all steps (or this
// step); a point whose field is not a number is grey. Equal axes. Zoom with the
// wheel, pan by dragging, Fit (or double-click) shows the whole run again.
// The residual plot: fErr (eq 35) against the Newton-Raphson pass, one line per
// load step, the shown step's in red, the tolerance dashed. Keys: left/right
// arrows step, space plays or pauses; run.html#frame=last opens at the last step.
//--------------------------------------------------------------------------
var Viewer = (function () {
  "use strict";

  // the fields a point can be coloured by: label and value of point p of a frame's columns
  var FIELDS = {
    vonMises: ["von Mises stress ρ = √(2 J2) (Pa)", function (c, p) { return c.vonMises[p]; }],
    sxx: ["σxx (Pa)", function (c, p) { return c.sxx[p]; }],
    syy: ["σyy (Pa)", function (c, p) { return c.syy[p]; }],
    sxy: ["σxy (Pa)", function (c, p) { return c.sxy[p]; }],
    szz: ["σzz (Pa)", function (c, p) { return c.szz[p]; }],
    p: ["mean stress p (Pa)", function (c, p) { return (c.sxx[p] + c.syy[p] + c.szz[p]) / 3; }],
    u: ["displacement |u| (m)", function (c, p) { return Math.hypot(c.ux[p], c.uy[p]); }],
    ux: ["displacement ux (m)", function (c, p) { return c.ux[p]; }],
    uy: ["displacement uy (m)", function (c, p) { return c.uy[p]; }],
    epsP: ["plastic strain ε̄p = √(2/3 e:e), e = ½ ln(F Fᵀ) − εe", function (c, p) { return c.epsP[p]; }],
    J: ["volume ratio V / V0", function (c, p, v0) { return v0 ? c.V[p] / v0[p] : NaN; }]
  };
  var M = {left: 62, right: 96, top: 10, bottom: 38};       // room for the axes and the colour bar
  // matplotlib's viridis, 17 samples, interpolated into 256 colours
  var LUT = (function () {
    var hex = ["#440154", "#48186a", "#472d7b", "#424086", "#3b528b", "#33638d", "#2c728e", "#26828e",
               "#21918c", "#1fa088", "#28ae80", "#3fbc73", "#5ec962", "#84d44b", "#addc30", "#d8e219", "#fde725"];
    var rgb = hex.map(function (h) { return [1, 3, 5].map(function (i) { return parseInt(h.substr(i, 2), 16); }); });
    var out = [];
    for (var k = 0; k < 256; ++k) {
      var t = k / 255 * (rgb.length - 1), i = Math.min(rgb.length - 2, Math.floor(t)), f = t - i;
      out.push("rgb(" + [0, 1, 2].map(function (j) { return Math.round(rgb[i][j] + f * (rgb[i + 1][j] - rgb[i][j])); }).join(",") + ")");
    }
    return out;
  })();
  var GREY = "rgb(170,170,170)";

  var el = {}, run = null, current = 0, follow = true, timer = null, view = null, drawnCount = [];
  var pending = false, drawMs = 0;

  function $(id) { return document.getElementById(id); }

  function fmt(v) {
    if (v === null || v === undefined || !isFinite(v)) return "–";
    if (v === 0) return "0";
    var a = Math.abs(v);
    return a >= 1e5 || a < 1e-3 ? v.toExponential(2) : String(Number(v.toPrecision(4)));
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

  // a canvas sized to its box in CSS pixels, drawn at the device's resolution
  function sized(canvas) {
    var w = canvas.clientWidth || 600, h = canvas.clientHeight || 300, dpr = window.devicePixelRatio || 1;
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
    }
    var ctx = canvas.getContext("2d");
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    return {ctx: ctx, w: w, h: h};
  }

  // half sizes of point p's drawn domain, into h (no allocation per point)
  var h = [0, 0];
  function half(c, p) {
    var lx = c.lpx[p], ly = c.lpy[p];
    if (lx > 0 && ly > 0) { h[0] = lx; h[1] = ly; return h; }
    h[0] = h[1] = 0.5 * Math.sqrt(Math.max(c.V[p], 0));
    return h;
  }

  // the bounds of everything the run has drawn so far
  function bounds() {
    var b = {x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity};
    function grow(x, y) {
      if (!isFinite(x) || !isFinite(y)) return;
      b.x0 = Math.min(b.x0, x); b.x1 = Math.max(b.x1, x); b.y0 = Math.min(b.y0, y); b.y1 = Math.max(b.y1, y);
    }
    run.grids.forEach(function (g) { for (var k = 0; k < g.nodes.length; k += 2) grow(g.nodes[k], g.nodes[k + 1]); });
    run.frames.forEach(function (f) {
      if (!f.box) {
        var fb = {x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity};
        for (var p = 0; p < f.n; ++p) {
          var hp = half(f.cols, p), x = f.cols.x[p], y = f.cols.y[p];
          if (!isFinite(x) || !isFinite(y)) continue;
          fb.x0 = Math.min(fb.x0, x - hp[0]); fb.x1 = Math.max(fb.x1, x + hp[0]);
          fb.y0 = Math.min(fb.y0, y - hp[1]); fb.y1 = Math.max(fb.y1, y + hp[1]);
        }
        f.box = fb;
      }
      grow(f.box.x0, f.box.y0); grow(f.box.x1, f.box.y1);
    });
    if (!(b.x1 > b.x0)) { b.x0 = (isFinite(b.x0) ? b.x0 : 0) - 0.5; b.x1 = b.x0 + 1; }
    if (!(b.y1 > b.y0)) { b.y0 = (isFinite(b.y0) ? b.y0 : 0) - 0.5; b.y1 = b.y0 + 1; }
    return b;
  }

  // the view that shows the whole run: scale (pixels per m) and the screen position of x = y = 0
  function fitView(w, h) {
    var b = bounds(), pad = 0.02 * Math.max(b.x1 - b.x0, b.y1 - b.y0);
    var pw = w - M.left - M.right, ph = h - M.top - M.bottom;
    var s = Math.min(pw / (b.x1 - b.x0 + 2 * pad), ph / (b.y1 - b.y0 + 2 * pad));
    return {s: s, ox: M.left + 0.5 * pw - s * 0.5 * (b.x0 + b.x1), oy: M.top + 0.5 * ph + s * 0.5 * (b.y0 + b.y1),
            fitted: true, box: b};
  }

  function fieldValues(f, name) {
    f.values = f.values || {};
    if (f.values[name]) return f.values[name];
    var v = new Float64Array(f.n), get = FIELDS[name][1], v0 = null, lo = Infinity, hi = -Infinity;
    if (name === "J" && run.frames.length && run.frames[0].n === f.n && run.frames[0].lstp === 0) v0 = run.frames[0].cols.V;
    if (name === "J" && !v0 && run.v0 && run.v0.length === f.n) v0 = run.v0;
    for (var p = 0; p < f.n; ++p) {
      v[p] = get(f.cols, p, v0);
      if (isFinite(v[p])) { lo = Math.min(lo, v[p]); hi = Math.max(hi, v[p]); }
    }
    v.lo = lo; v.hi = hi;
    f.values[name] = v;
    return v;
  }

  // the colour scale's ends: over every frame, or the shown one
  function range(name) {
    var lo = Infinity, hi = -Infinity;
    var frames = el.scaleOf.value === "step" ? [run.frames[current]] : run.frames;
    frames.forEach(function (f) { var v = fieldValues(f, name); lo = Math.min(lo, v.lo); hi = Math.max(hi, v.hi); });
    if (!isFinite(lo)) { lo = 0; hi = 1; }
    if (hi - lo <= 1e-9 * Math.max(Math.abs(lo), Math.abs(hi), 1e-300)) {  // uniform: a visible range
      lo -= 0.01 * Math.abs(lo) + 1e-12; hi += 0.01 * Math.abs(hi) + 1e-12;
    }
    return [lo, hi];
  }

  function drawGrid(ctx, g) {
    ctx.strokeStyle = "#c4c4c4"; ctx.lineWidth = 0.6; ctx.beginPath();
    var n = g.nodes, e = g.edges;
    for (var k = 0; k < e.length; k += 2) {
      var a = 2 * e[k], b = 2 * e[k + 1];
      ctx.moveTo(view.ox + view.s * n[a], view.oy - view.s * n[a + 1]);
      ctx.lineTo(view.ox + view.s * n[b], view.oy - view.s * n[b + 1]);
    }
    ctx.stroke();
  }

  // the points of frame f coloured by field name over [lo, hi]; how many it drew. The points are
  // sorted by colour (a counting sort into 256 colours and grey) and each colour filled as one path
  function drawPoints(ctx, f, name, lo, hi) {
    var v = fieldValues(f, name), c = f.cols, k = 255 / (hi - lo), n = f.n, drawn = 0;
    var colourOf = new Uint16Array(n), count = new Int32Array(258), order = new Int32Array(n), p;
    for (p = 0; p < n; ++p) {
      colourOf[p] = isFinite(v[p]) ? Math.max(0, Math.min(255, Math.round((v[p] - lo) * k))) : 256;
      ++count[colourOf[p] + 1];
    }
    for (var i = 1; i < 258; ++i) count[i] += count[i - 1];     // count[i]: where colour i starts
    for (p = 0; p < n; ++p) order[count[colourOf[p]]++] = p;
    for (var at = 0, col = 0; col <= 256; ++col) {
      var end = count[col];
      if (end === at) continue;
      ctx.fillStyle = col < 256 ? LUT[col] : GREY;
      ctx.beginPath();
      for (; at < end; ++at) {
        p = order[at];
        var x = c.x[p], y = c.y[p];
        if (!isFinite(x) || !isFinite(y)) continue;
        var hp = half(c, p), w = Math.max(1, 2 * hp[0] * view.s), hh = Math.max(1, 2 * hp[1] * view.s);
        ctx.rect(view.ox + view.s * x - 0.5 * w, view.oy - view.s * y - 0.5 * hh, w, hh);
        ++drawn;
      }
      ctx.fill();
    }
    return drawn;
  }

  function drawAxes(ctx, w, h) {
    var x0 = M.left, x1 = w - M.right, y0 = h - M.bottom, y1 = M.top;
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, w, y1); ctx.fillRect(0, y0, w, h - y0); ctx.fillRect(0, 0, x0, h); ctx.fillRect(x1, 0, w - x1, h);
    ctx.strokeStyle = "#444"; ctx.lineWidth = 1; ctx.strokeRect(x0, y1, x1 - x0, y0 - y1);
    ctx.fillStyle = "#222"; ctx.font = "12px sans-serif"; ctx.textAlign = "center"; ctx.textBaseline = "top";
    var wx0 = (x0 - view.ox) / view.s, wx1 = (x1 - view.ox) / view.s;
    var wy0 = (view.oy - y0) / view.s, wy1 = (view.oy - y1) / view.s;
    niceTicks(wx0, wx1, Math.max(2, Math.round((x1 - x0) / 90))).forEach(function (v) {
      var px = view.ox + view.s * v;
      ctx.beginPath(); ctx.moveTo(px, y0); ctx.lineTo(px, y0 + 4); ctx.stroke();
      ctx.fillText(fmt(v), px, y0 + 6);
    });
    ctx.fillText("x (m)", 0.5 * (x0 + x1), y0 + 21);
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    niceTicks(wy0, wy1, Math.max(2, Math.round((y0 - y1) / 60))).forEach(function (v) {
      var py = view.oy - view.s * v;
      ctx.beginPath(); ctx.moveTo(x0, py); ctx.lineTo(x0 - 4, py); ctx.stroke();
      ctx.fillText(fmt(v), x0 - 6, py);
    });
    ctx.save(); ctx.translate(14, 0.5 * (y0 + y1)); ctx.rotate(-Math.PI / 2);
    ctx.textAlign = "center"; ctx.fillText("y (m)", 0, 0); ctx.restore();
  }

  function drawColourBar(ctx, w, h, name, lo, hi) {
    var bx = w - M.right + 12, bw = 16, by = M.top + 8, bh = h - M.top - M.bottom - 16;
    for (var k = 0; k < bh; ++k) {
      ctx.fillStyle = LUT[Math.round(255 * (1 - k / (bh - 1)))];
      ctx.fillRect(bx, by + k, bw, 1.5);
    }
    ctx.strokeStyle = "#444"; ctx.strokeRect(bx, by, bw, bh);
    ctx.fillStyle = "#222"; ctx.font = "11px sans-serif"; ctx.textAlign = "left"; ctx.textBaseline = "middle";
    niceTicks(lo, hi, 6).forEach(function (v) {
      var y = by + bh * (hi - v) / (hi - lo);
      ctx.beginPath(); ctx.moveTo(bx + bw, y); ctx.lineTo(bx + bw + 4, y); ctx.stroke();
      ctx.fillText(fmt(v), bx + bw + 6, y);
    });
    ctx.save(); ctx.translate(w - 6, by + 0.5 * bh); ctx.rotate(-Math.PI / 2);
    ctx.textAlign = "center"; ctx.textBaseline = "bottom"; ctx.fillText(FIELDS[name][0], 0, 0); ctx.restore();
  }

  // frame i on the canvas: the grid, the points, the axes and the colour bar; the points drawn
  function drawFrame(i) {
    var S = sized(el.canvas), ctx = S.ctx;
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, S.w, S.h);
    if (!run || !run.frames.length) { view = null; return 0; }
    if (!view || view.fitted) view = fitView(S.w, S.h);
    var f = run.frames[i], name = el.field.value, r = range(name);
    if (el.showGrid.checked && f.grid >= 0 && run.grids[f.grid]) drawGrid(ctx, run.grids[f.grid]);
    var drawn = drawPoints(ctx, f, name, r[0], r[1]);
    drawAxes(ctx, S.w, S.h);
    drawColourBar(ctx, S.w, S.h, name, r[0], r[1]);
    return drawn;
  }

  // the residual plot: log10 fErr against the pass, one line per load step
  function drawResiduals() {
    var S = sized(el.residuals), ctx = S.ctx, m = {left: 62, right: 96, top: 8, bottom: 30};
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, S.w, S.h);
    if (!run || !run.passes.length) return;
    var bySteps = {}, maxPass = 1, lo = Infinity, hi = -Infinity;
    run.passes.forEach(function (q) {
      (bySteps[q.lstp] = bySteps[q.lstp] || []).push(q);
      maxPass = Math.max(maxPass, q.NRit + 1);
      if (q.fErr > 0 && isFinite(q.fErr)) { lo = Math.min(lo, q.fErr); hi = Math.max(hi, q.fErr); }
    });
    var tol = run.tol;
    if (tol > 0) { lo = Math.min(lo, tol); hi = Math.max(hi, tol); }
    if (!isFinite(lo)) return;
    var l0 = Math.floor(Math.log10(lo)), l1 = Math.max(l0 + 1, Math.ceil(Math.log10(hi)));
    var x0 = m.left, x1 = S.w - m.right, y0 = S.h - m.bottom, y1 = m.top;
    function X(pass) { return x0 + (x1 - x0) * (pass - 1) / Math.max(1, maxPass - 1); }
    function Y(v) { return y0 - (y0 - y1) * (Math.log10(v) - l0) / (l1 - l0); }
    ctx.strokeStyle = "#444"; ctx.lineWidth = 1; ctx.strokeRect(x0, y1, x1 - x0, y0 - y1);
    ctx.fillStyle = "#222"; ctx.font = "11px sans-serif"; ctx.textAlign = "right"; ctx.textBaseline = "middle";
    var every = Math.max(1, Math.ceil((l1 - l0) / 6));
    for (var e = l0; e <= l1; e += every) {
      ctx.beginPath(); ctx.moveTo(x0 - 4, Y(Math.pow(10, e))); ctx.lineTo(x0, Y(Math.pow(10, e))); ctx.stroke();
      ctx.fillText("1e" + e, x0 - 6, Y(Math.pow(10, e)));
    }
    ctx.textAlign = "center"; ctx.textBaseline = "top";
    for (var k = 1; k <= maxPass; k += Math.max(1, Math.ceil(maxPass / 12))) ctx.fillText(String(k), X(k), y0 + 4);
    ctx.fillText("Newton-Raphson pass", 0.5 * (x0 + x1), y0 + 16);
    ctx.save(); ctx.translate(12, 0.5 * (y0 + y1)); ctx.rotate(-Math.PI / 2); ctx.fillText("fErr", 0, 0); ctx.restore();
    if (tol > 0) {
      ctx.setLineDash([5, 4]); ctx.strokeStyle = "#777"; ctx.beginPath();
      ctx.moveTo(x0, Y(tol)); ctx.lineTo(x1, Y(tol)); ctx.stroke(); ctx.setLineDash([]);
      ctx.textAlign = "left"; ctx.textBaseline = "middle"; ctx.fillText("tol " + fmt(tol), x1 + 6, Y(tol));
    }
    var shown = run.frames.length ? run.frames[current].lstp : -1;
    function line(qs, colour, width) {
      ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = width; ctx.beginPath();
      var started = false;
      qs.forEach(function (q) {
        if (!(q.fErr > 0) || !isFinite(q.fErr)) return;
        var px = X(q.NRit + 1), py = Y(q.fErr);
        if (started) ctx.lineTo(px, py); else ctx.moveTo(px, py);
        started = true;
      });
      ctx.stroke();
      qs.forEach(function (q) { if (q.fErr > 0 && isFinite(q.fErr)) ctx.fillRect(X(q.NRit + 1) - 2, Y(q.fErr) - 2, 4, 4); });
    }
    // the passes of one attempt at a step restart at NRit 0: each attempt its own line
    function attempts(qs) {
      var out = [], cur = [];
      qs.forEach(function (q) { if (q.NRit === 0 && cur.length) { out.push(cur); cur = []; } cur.push(q); });
      if (cur.length) out.push(cur);
      return out;
    }
    Object.keys(bySteps).forEach(function (s) {
      if (Number(s) !== shown) attempts(bySteps[s]).forEach(function (qs) { line(qs, "rgba(59,82,139,0.25)", 1); });
    });
    var last = run.passes[run.passes.length - 1].lstp;
    var live = run.source === "page" && run.status === undefined;
    var red = live && follow ? last : shown;             // following a run: the step going on
    if (bySteps[red]) attempts(bySteps[red]).forEach(function (qs) { line(qs, "#c0392b", 2); });
    ctx.fillStyle = "#222"; ctx.textAlign = "left"; ctx.textBaseline = "top";
    if (bySteps[red]) ctx.fillText("load step " + red, x1 + 6, y1);
  }

  function infoText(f) {
    var s = "load step " + f.lstp + " of " + run.lstps + "  ·  load factor " + fmt(f.lf);
    if (f.lstp > 0)
      s += "  ·  final residual fErr = " + (isFinite(f.fErr) ? f.fErr.toExponential(2) : "–") +
           (isFinite(f.NRit) ? " (Newton-Raphson pass " + f.NRit + ")" : "");
    return s + "  ·  " + f.n + " points";
  }

  function report() {
    var r = el.canvas.getBoundingClientRect(), b = view && view.box ? view.box : null;
    var st = {frames: run ? run.frames.length : 0, drawn: drawnCount, shown: current,
              lstp: run && run.frames.length ? run.frames[current].lstp : null, errors: window.pageErrors,
              drawMs: drawMs};
    if (b && view)
      st.plot = {left: Math.floor(r.left + view.ox + view.s * b.x0), right: Math.ceil(r.left + view.ox + view.s * b.x1),
                 top: Math.floor(r.top + view.oy - view.s * b.y1), bottom: Math.ceil(r.top + view.oy - view.s * b.y0)};
    el.status.textContent = JSON.stringify(st);
    return st;
  }

  function showFrame(i) {
    if (!run || !run.frames.length) return;
    current = Math.max(0, Math.min(run.frames.length - 1, i));
    follow = current === run.frames.length - 1;
    var f = run.frames[current], t0 = performance.now();
    drawnCount[current] = drawFrame(current);
    drawResiduals();
    drawMs = performance.now() - t0;
    el.slider.max = String(run.frames.length - 1);
    el.slider.value = String(current);
    el.frameNo.textContent = "frame " + (current + 1) + " of " + run.frames.length;
    el.info.textContent = infoText(f);
    report();
  }

  // frames, grids or passes were added (the run goes on): the newest frame if it was followed, at
  // most once a display frame; passes alone redraw the residual plot only (the main thread stays
  // free: the run's worker and the page share the machine's cores)
  var pendingFrame = false;
  function update(passesOnly) {
    pendingFrame = pendingFrame || !passesOnly;
    if (pending) return;
    pending = true;
    requestAnimationFrame(function () {
      pending = false;
      if (!run) return;
      if (!run.frames.length || !pendingFrame) { drawResiduals(); return; }
      pendingFrame = false;
      showFrame(follow ? run.frames.length - 1 : current);
    });
  }

  function stop() { if (timer) clearInterval(timer); timer = null; el.play.textContent = "Play"; }
  function play() {
    if (!run || run.frames.length < 2) return;
    if (current >= run.frames.length - 1) showFrame(0);
    el.play.textContent = "Pause";
    timer = setInterval(function () {
      if (current >= run.frames.length - 1) { stop(); return; }
      showFrame(current + 1);
    }, Number(el.speed.value));
  }

  function fromHash() {
    var m = /frame=(last|\d+)/.exec(location.hash);
    return m ? (m[1] === "last" ? run.frames.length - 1 : Number(m[1])) : 0;
  }

  function show(r, opts) {
    opts = opts || {};
    stop();
    run = r; view = null; drawnCount = []; follow = opts.follow !== false;
    el.field.disabled = false;
    if (opts.field && FIELDS[opts.field]) el.field.value = opts.field;
    if (opts.drawEvery)                                  // each frame once (the tests count the points)
      for (var i = 0; i < run.frames.length; ++i) drawnCount[i] = drawFrame(i);
    showFrame(opts.frame === "hash" ? fromHash() : run.frames.length - 1);
    downloads();
  }

  // the run's files to download: summary.json, the CSVs, the VTK files of a chosen step
  function downloads() {
    var box = el.downloads;
    box.textContent = "";
    if (!run || !run.fileNames || !run.fetchFile) return;
    var names = run.fileNames.slice();
    function link(name, label) {
      var b = document.createElement("button");
      b.type = "button"; b.textContent = label || name; b.dataset.file = name;
      b.addEventListener("click", function () { save(name); });
      box.appendChild(b);
    }
    var title = document.createElement("div");
    title.textContent = "download:"; box.appendChild(title);
    ["summary.json", "steps.csv", "residuals.csv", "mp_final.csv", "history.csv"].forEach(function (n) {
      if (names.indexOf(n) >= 0) link(n);
    });
    var vtks = names.filter(function (n) { return /^mpData_\d+\.vtk$/.test(n); })
                    .sort(function (a, b) { return /(\d+)/.exec(a)[1] - /(\d+)/.exec(b)[1]; });
    if (vtks.length) {
      var row = document.createElement("div"), sel = document.createElement("select");
      sel.id = "vtkStep";
      vtks.forEach(function (n) {
        var o = document.createElement("option"); o.value = n; o.textContent = "step " + /(\d+)/.exec(n)[1]; sel.appendChild(o);
      });
      sel.value = vtks[vtks.length - 1];
      var b = document.createElement("button");
      b.type = "button"; b.textContent = "VTK files of"; b.id = "vtkSave";
      b.addEventListener("click", function () {
        var lstp = /(\d+)/.exec(sel.value)[1], grid = "mesh_" + lstp + ".vtk";
        save(sel.value);
        save(names.indexOf(grid) >= 0 ? grid : "mesh.vtk");
      });
      row.appendChild(b); row.appendChild(sel); box.appendChild(row);
    }
  }

  function save(name) {
    return run.fetchFile(name).then(function (bytes) {
      var a = document.createElement("a");
      a.href = URL.createObjectURL(new Blob([bytes]));
      a.download = name;
      document.body.appendChild(a); a.click(); a.remove();
      setTimeout(function () { URL.revokeObjectURL(a.href); }, 10000);
      return bytes.length;
    });
  }

  // zoom and pan: the wheel zooms about the cursor, a drag pans, a double-click fits
  function bindView() {
    var c = el.canvas, drag = null;
    c.addEventListener("wheel", function (e) {
      if (!view) return;
      e.preventDefault();
      var r = c.getBoundingClientRect(), mx = e.clientX - r.left, my = e.clientY - r.top;
      var k = Math.exp(-e.deltaY * 0.0015);
      view = {s: view.s * k, ox: mx - k * (mx - view.ox), oy: my - k * (my - view.oy), fitted: false, box: view.box};
      showFrame(current);
    }, {passive: false});
    c.addEventListener("pointerdown", function (e) {
      if (!view) return;
      drag = {x: e.clientX, y: e.clientY, ox: view.ox, oy: view.oy};
      c.setPointerCapture(e.pointerId); c.classList.add("panning");
    });
    c.addEventListener("pointermove", function (e) {
      if (!drag) return;
      view = {s: view.s, ox: drag.ox + e.clientX - drag.x, oy: drag.oy + e.clientY - drag.y, fitted: false, box: view.box};
      showFrame(current);
    });
    c.addEventListener("pointerup", function () { drag = null; c.classList.remove("panning"); });
    c.addEventListener("dblclick", function () { view = null; showFrame(current); });
  }

  function init() {
    ["canvas", "residuals", "slider", "play", "speed", "field", "scaleOf", "showGrid", "fit", "info", "frameNo",
     "downloads", "status"].forEach(function (id) { el[id] = $(id); });
    Object.keys(FIELDS).forEach(function (k) {
      var o = document.createElement("option"); o.value = k; o.textContent = FIELDS[k][0]; el.field.appendChild(o);
    });
    el.play.addEventListener("click", function () { timer ? stop() : play(); });
    el.speed.addEventListener("change", function () { if (timer) { stop(); play(); } });
    el.slider.addEventListener("input", function () { stop(); showFrame(Number(el.slider.value)); });
    ["field", "scaleOf", "showGrid"].forEach(function (id) { el[id].addEventListener("change", function () { showFrame(current); }); });
    el.fit.addEventListener("click", function () { view = null; showFrame(current); });
    document.addEventListener("keydown", function (e) {
      if (!run || /INPUT|SELECT|TEXTAREA/.test((e.target && e.target.tagName) || "")) return;
      if (e.key === "ArrowRight") { stop(); showFrame(current + 1); }
      else if (e.key === "ArrowLeft") { stop(); showFrame(current - 1); }
      else if (e.key === " ") { e.preventDefault(); timer ? stop() : play(); }
    });
    window.addEventListener("hashchange", function () { if (run) { stop(); showFrame(fromHash()); } });
    window.addEventListener("resize", function () { if (run) showFrame(current); });
    bindView();
  }

  // the run ended: its downloads, and the last frame if it was followed
  function refresh() { downloads(); update(); }

  return {init: init, show: show, update: update, refresh: refresh, state: report, stop: stop,
          showFrame: showFrame, save: save, fields: FIELDS,
          get run() { return run; }, get current() { return current; }};
})();
