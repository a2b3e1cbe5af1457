//--------------------------------------------------------------------------
// readRun.js — a run's output folder read into the viewer's run
//--------------------------------------------------------------------------
// The files the program writes (README, "Output"): summary.json, steps.csv,
// residuals.csv, mp_final.csv, history.csv, mesh.vtk, mesh_<lstp>.vtk and
// mpData_<lstp>.vtk (legacy VTK, ASCII or BINARY: big-endian float32 / int32,
// plotting/makeVtkWriter.h), read without a server: from the files of an
// opened folder, or from the ones plot_run.py --animate put inside run.html.
//   ReadRun.fromFiles(files)  files: {name: Uint8Array} -> the run (below)
//   ReadRun.csv(text)         {head: [names], cols: {name: Float64Array}}
//   ReadRun.vtk(bytes)        {points: Float64Array [x y z ...], cells: [[node, ...]],
//                              data: {name: Float64Array (n or 3 n values)}}
//   ReadRun.edges(cells, nn)  each edge of the cells once: Int32Array [a b a b ...];
//                             cells: [[node, ...]], or {flat: Int32Array, nen} (nen nodes a cell)
// The run: {setup, lstps, tol, summary, frames, grids, passes, message,
// converged, files}. A frame: {lstp, lf, NRit, fErr, n, grid, cols}, cols the
// points' fields by name (viewer.js, COLUMNS: the same as the page's stream,
// setups/program/wasm/ampleWasm.cpp); the VTK files have no plastic strain:
// epsP is NaN there. No mpData_<lstp>.vtk (a run with --vtk 0): one frame,
// the last converged step, from mp_final.csv.
//--------------------------------------------------------------------------
var ReadRun = (function () {
  "use strict";

  function text(bytes) { return new TextDecoder("utf-8").decode(bytes); }

  function csv(body) {
    var lines = body.split(/\r?\n/).filter(function (l) { return l.length > 0; });
    var head = lines.length ? lines[0].split(",") : [], cols = {};
    head.forEach(function (h, k) {
      var v = new Float64Array(lines.length - 1);
      for (var r = 1; r < lines.length; ++r) {
        var f = lines[r].split(",")[k];
        v[r - 1] = f === undefined || f === "" ? NaN : Number(f);
      }
      cols[h] = v;
    });
    return {head: head, cols: cols, rows: lines.length - 1};
  }

  // the sections of a legacy VTK file as ample writes them: keyword lines in text, numbers in
  // text (ASCII) or as big-endian 4-byte values (BINARY) with one "\n" after each block
  function vtk(bytes) {
    var pos = 0, view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    function line() {                                    // the next non-empty text line, or null
      while (pos < bytes.length) {
        var end = bytes.indexOf(10, pos);
        if (end < 0) end = bytes.length;
        var t = text(bytes.subarray(pos, end)).trim();
        pos = end + 1;
        if (t) return t;
      }
      return null;
    }
    if (!/^# vtk DataFile/.test(line() || "")) throw new Error("not a legacy VTK file");
    line();                                              // the title
    var binary = (line() || "").toUpperCase() === "BINARY";
    function values(count, type) {
      var out = new Float64Array(count), k;
      if (binary) {
        var isInt = type === "int" || type === "vtkIdType", size = type === "double" ? 8 : 4;
        for (k = 0; k < count; ++k, pos += size)
          out[k] = size === 8 ? view.getFloat64(pos) : isInt ? view.getInt32(pos) : view.getFloat32(pos);
        if (bytes[pos] === 10) ++pos;
        return out;
      }
      k = 0;
      while (k < count) {
        var words = line().split(/\s+/);
        for (var w = 0; w < words.length && k < count; ++w) out[k++] = Number(words[w]);
      }
      return out;
    }
    var out = {points: new Float64Array(0), cells: [], data: {}}, n = 0, head;
    while ((head = line()) !== null) {
      var w = head.split(/\s+/);
      if (w[0] === "POINTS") {
        n = Number(w[1]);
        out.points = values(3 * n, w[2]);
      } else if (w[0] === "CELLS") {
        var v = values(Number(w[2]), "int");
        for (var c = 0, k = 0; c < Number(w[1]); ++c) {
          out.cells.push(Array.prototype.slice.call(v, k + 1, k + 1 + v[k]));
          k += 1 + v[k];
        }
      } else if (w[0] === "CELL_TYPES") {
        values(Number(w[1]), "int");
      } else if (w[0] === "VECTORS") {
        out.data[w[1]] = values(3 * n, w[2]);
      } else if (w[0] === "SCALARS") {
        var components = w.length > 3 ? Number(w[3]) : 1, at = pos;
        if (!/^LOOKUP_TABLE/.test(line() || "")) pos = at;
        out.data[w[1]] = values(components * n, w[2]);
      }                                                  // DATASET, POINT_DATA: the keyword only
    }
    return out;
  }

  function edges(cells, nn) {
    var seen = new Set(), out = [];
    function cell(c, at, len) {
      for (var k = 0; k < len; ++k) {
        var a = c[at + k], b = c[at + (k + 1) % len], lo = Math.min(a, b), hi = Math.max(a, b), key = lo * nn + hi;
        if (!seen.has(key)) { seen.add(key); out.push(lo, hi); }
      }
    }
    if (cells.flat instanceof Int32Array)
      for (var at = 0; at < cells.flat.length; at += cells.nen) cell(cells.flat, at, cells.nen);
    else cells.forEach(function (c) { cell(c, 0, c.length); });
    return new Int32Array(out);
  }

  function gridOf(v) {
    var nn = v.points.length / 3, nodes = new Float64Array(2 * nn);
    for (var p = 0; p < nn; ++p) { nodes[2 * p] = v.points[3 * p]; nodes[2 * p + 1] = v.points[3 * p + 1]; }
    return {nodes: nodes, edges: edges(v.cells, nn)};
  }

  // the columns of a frame from mpData_<lstp>.vtk's point data
  function colsOfVtk(v) {
    var n = v.points.length / 3, d = v.data, cols = {}, names = {
      sxx: "sigma_xx", syy: "sigma_yy", szz: "sigma_zz", sxy: "sigma_xy", vonMises: "rho_vonMises",
      V: "volume", lpx: "lpx", lpy: "lpy", ux: "ux", uy: "uy"};
    cols.x = new Float64Array(n); cols.y = new Float64Array(n);
    for (var p = 0; p < n; ++p) { cols.x[p] = v.points[3 * p]; cols.y[p] = v.points[3 * p + 1]; }
    Object.keys(names).forEach(function (c) { cols[c] = d[names[c]] || new Float64Array(n).fill(NaN); });
    cols.epsP = new Float64Array(n).fill(NaN);
    return {n: n, cols: cols};
  }

  // the columns of a frame from mp_final.csv (the last converged step)
  function colsOfFinal(t) {
    var c = t.cols, n = t.rows, cols = {x: c.x, y: c.y, sxx: c.sxx, syy: c.syy, szz: c.szz, sxy: c.sxy,
                                        V: c.V, lpx: c.lpx, lpy: c.lpy};
    cols.ux = new Float64Array(n); cols.uy = new Float64Array(n); cols.vonMises = new Float64Array(n);
    for (var p = 0; p < n; ++p) {
      cols.ux[p] = c.x[p] - c.X0[p]; cols.uy[p] = c.y[p] - c.Y0[p];
      var s = [c.sxx[p], c.syy[p], c.szz[p]], m = (s[0] + s[1] + s[2]) / 3;
      cols.vonMises[p] = Math.sqrt(Math.pow(s[0] - m, 2) + Math.pow(s[1] - m, 2) + Math.pow(s[2] - m, 2) +
                                   2 * (c.sxy[p] * c.sxy[p] + c.syz[p] * c.syz[p] + c.szx[p] * c.szx[p]));
    }
    cols.epsP = new Float64Array(n).fill(NaN);
    return {n: n, cols: cols};
  }

  function lstpOf(name) { return Number(/_(\d+)\.vtk$/.exec(name)[1]); }

  function fromFiles(files) {
    if (!files["summary.json"]) throw new Error("no summary.json: not the output folder of a run of ample");
    var summary = JSON.parse(text(files["summary.json"]));
    var run = {setup: summary.setup, lstps: summary.lstps, tol: summary.parameters ? summary.parameters.tol : NaN,
               summary: summary, frames: [], grids: [], passes: [], converged: summary.converged,
               message: summary.message || "", files: files, source: "folder"};
    if (files["residuals.csv"]) {
      var r = csv(text(files["residuals.csv"])).cols;
      for (var k = 0; k < r.lstp.length; ++k) run.passes.push({lstp: r.lstp[k], NRit: r.NRit[k], fErr: r.fErr[k]});
    }
    var steps = {};                                      // lstp: the converged row of steps.csv
    if (files["steps.csv"]) {
      var s = csv(text(files["steps.csv"])).cols;
      for (k = 0; k < s.lstp.length; ++k)
        if (s.converged[k] === 1) steps[s.lstp[k]] = {lf: s.load_factor[k], NRit: s.NRit[k], fErr: s.fErr[k]};
    }
    var gridKeys = [];
    function gridIndex(name) {
      if (!files[name]) return -1;
      var at = gridKeys.indexOf(name);
      if (at < 0) { run.grids.push(gridOf(vtk(files[name]))); gridKeys.push(name); at = gridKeys.length - 1; }
      return at;
    }
    var names = Object.keys(files).filter(function (n) { return /^mpData_\d+\.vtk$/.test(n); })
                      .sort(function (a, b) { return lstpOf(a) - lstpOf(b); });
    function addFrame(lstp, pc) {
      var row = steps[lstp] || {lf: NaN, NRit: NaN, fErr: NaN};
      var g = gridIndex("mesh_" + lstp + ".vtk");
      run.frames.push({lstp: lstp, lf: row.lf, NRit: row.NRit, fErr: row.fErr, n: pc.n, cols: pc.cols,
                       grid: g >= 0 ? g : gridIndex("mesh.vtk")});
    }
    names.forEach(function (name) { addFrame(lstpOf(name), colsOfVtk(vtk(files[name]))); });
    var final = files["mp_final.csv"] ? csv(text(files["mp_final.csv"])) : null;
    if (final) run.v0 = final.cols.V0;                   // the volume ratio J = V / V0
    if (!names.length && final) addFrame(summary.last_converged_step, colsOfFinal(final));
    if (!run.frames.length) throw new Error("no mpData_<lstp>.vtk and no mp_final.csv: nothing to draw");
    return run;
  }

  return {fromFiles: fromFiles, csv: csv, vtk: vtk, edges: edges, text: text};
})();
