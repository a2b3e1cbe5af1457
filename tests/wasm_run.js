#!/usr/bin/env node
//--------------------------------------------------------------------------
// wasm_run.js — the browser build of ample run under node, as the command line
//--------------------------------------------------------------------------
// Loads build/wasm/ample_wasm.js (the preset wasm) the way the page's worker
// does, runs the words after it as `ample` would (ampleRun: the same program,
// setups/program/wasm/ampleWasm.cpp) and copies what the run wrote into the
// module's memory file system to the folder of --out on disk. Prints the run's
// stdout and stderr, exits with its status; also counts what the run streamed
// (frames, passes) and checks it against the files: the last frame's points
// equal mp_final.csv's x, y to the last bit and every pass of residuals.csv was
// streamed (a mismatch: exit 4).
// usage: node tests/wasm_run.js build/wasm/ample_wasm.js SETUP [name=value ...]
//             [--out DIR] [--vtk N] [...]          (the options of `ample --help`)
// Tests:   tests/wasm_compare.py (CTest wasm.node)
//--------------------------------------------------------------------------
"use strict";
const fs = require("fs");
const path = require("path");

async function main() {
  const [glue, ...args] = process.argv.slice(2);
  if (!glue || !args.length) {
    console.error("usage: wasm_run.js build/wasm/ample_wasm.js SETUP [name=value ...] [--out DIR] [options]");
    return 2;
  }
  const outAt = args.indexOf("--out");
  const outDir = outAt >= 0 ? args[outAt + 1] : "output/" + args[0];
  const words = args.slice();
  if (outAt >= 0 && outAt + 1 < words.length) words[outAt + 1] = "/out";
  else if (outAt < 0 && !args.includes("--help") && !args.includes("-h")) words.push("--out", "/out");

  const frames = [], passes = [];
  const createAmple = require(path.resolve(glue));
  const Module = await createAmple({
    wasmBinary: fs.readFileSync(path.resolve(glue).replace(/\.js$/, ".wasm")),
    print: (line) => process.stdout.write(line + "\n"),
    printErr: (line) => process.stderr.write(line + "\n"),
  });
  Module.onFrame = (lstp, lf, NRit, fErr, nmp, v) => frames.push({lstp, nmp, v});
  Module.onPass = (lstp, NRit, fErr) => passes.push([lstp, NRit, fErr]);
  const status = Module.ccall("ampleRun", "number", ["string"], [words.join("\n")]);

  if (Module.FS.analyzePath("/out").exists) {
    fs.mkdirSync(outDir, {recursive: true});
    for (const name of Module.FS.readdir("/out")) {
      if (name === "." || name === "..") continue;
      fs.writeFileSync(path.join(outDir, name), Module.FS.readFile("/out/" + name));
    }
    const bad = checkStream(outDir, frames, passes);
    if (bad) {
      console.error("wasm_run.js: the stream differs from the files: " + bad);
      return 4;
    }
  }
  return status;
}

// the last frame against mp_final.csv (the same doubles) and the passes against residuals.csv
function checkStream(outDir, frames, passes) {
  const file = (name) => path.join(outDir, name);
  if (!fs.existsSync(file("mp_final.csv")) || !frames.length) return "";
  const rows = fs.readFileSync(file("mp_final.csv"), "utf8").trim().split("\n").slice(1);
  const last = frames[frames.length - 1];
  if (rows.length !== last.nmp) return "mp_final.csv has " + rows.length + " points, the last frame " + last.nmp;
  for (let p = 0; p < rows.length; ++p) {
    const c = rows[p].split(",").map(Number);          // X0, Y0, x, y, ...: 17 digits, exact
    if (c[2] !== last.v[p] || c[3] !== last.v[last.nmp + p])
      return "point " + p + ": mp_final.csv (" + c[2] + ", " + c[3] + "), frame (" + last.v[p] + ", " +
             last.v[last.nmp + p] + ")";
  }
  const res = fs.readFileSync(file("residuals.csv"), "utf8").trim().split("\n").slice(1);
  if (res.length !== passes.length) return "residuals.csv has " + res.length + " passes, the stream " + passes.length;
  return "";
}

main().then((status) => { process.exitCode = status; },
            (e) => { console.error("wasm_run.js: " + (e && e.stack || e)); process.exitCode = 5; });
