//--------------------------------------------------------------------------
// worker.js — the program (ample_wasm.js/.wasm) in a Web Worker of the page
//--------------------------------------------------------------------------
// page.js starts one worker to answer the form (the table of setups, the
// command line's checks, the set-up state of the first picture) and a fresh
// one for every run, ended by Cancel (terminate) or by the next run: no state
// is carried from one run to the next. The functions called are those of
// setups/program/wasm/ampleWasm.cpp; the command line's words are joined by "\n".
// Messages in (postMessage):
//   {cmd: "load", module}             instantiate the program (module: a compiled
//                                     WebAssembly.Module, or none: fetch ample_wasm.wasm)
//   {cmd: "setups"}                   -> {type: "setups", json}
//   {cmd: "check", id, args}          -> {type: "check", id, message} ("" passes)
//   {cmd: "setup", id, args}          -> grid, frame, then {type: "setupDone", id, status}
//   {cmd: "run", args}                -> grid, pass, frame ... then {type: "done", status,
//                                        files: [names], texts: {summary.json, *.csv}, seconds}
//   {cmd: "file", id, name}           -> {type: "file", id, name, bytes} (the run's files)
// Out, as the run goes: {type: "grid", nodes, cells, nen}, {type: "pass", lstp, NRit, fErr},
// {type: "frame", lstp, lf, NRit, fErr, n, data} (Float64Array, transferred),
// {type: "err" | "out", line} (the program's stderr and stdout lines).
//--------------------------------------------------------------------------
"use strict";
importScripts("ample_wasm.js");

var Module = null, OUT = "/out";

function post(msg, transfer) { self.postMessage(msg, transfer || []); }

function load(compiled) {
  var opts = {
    print: function (line) { post({type: "out", line: line}); },
    printErr: function (line) { post({type: "err", line: line}); }
  };
  if (compiled)
    opts.instantiateWasm = function (imports, receive) {
      WebAssembly.instantiate(compiled, imports).then(function (instance) { receive(instance, compiled); });
      return {};
    };
  return createAmple(opts).then(function (m) {
    Module = m;
    m.onGrid = function (nodes, cells, nen) { post({type: "grid", nodes: nodes, cells: cells, nen: nen}, [nodes.buffer, cells.buffer]); };
    m.onPass = function (lstp, NRit, fErr) { post({type: "pass", lstp: lstp, NRit: NRit, fErr: fErr}); };
    m.onFrame = function (lstp, lf, NRit, fErr, n, data) {
      post({type: "frame", lstp: lstp, lf: lf, NRit: NRit, fErr: fErr, n: n, data: data}, [data.buffer]);
    };
  });
}

function call(name, args, returns) {
  return Module.ccall(name, returns || "number", ["string"], [args.join("\n")]);
}

// the run's files in the memory file system: their names, and the text of the small ones
function outFiles() {
  var names = [], texts = {};
  if (!Module.FS.analyzePath(OUT).exists) return {names: names, texts: texts};
  Module.FS.readdir(OUT).forEach(function (n) {
    if (n === "." || n === "..") return;
    names.push(n);
    if (/\.(csv|json)$/.test(n)) texts[n] = Module.FS.readFile(OUT + "/" + n, {encoding: "utf8"});
  });
  return {names: names, texts: texts};
}

var ready = null;
self.onmessage = function (e) {
  var m = e.data;
  if (m.cmd === "load") { ready = load(m.module); return; }
  ready.then(function () {
    if (m.cmd === "setups") post({type: "setups", json: Module.ccall("ampleSetups", "string", [], [])});
    else if (m.cmd === "check") post({type: "check", id: m.id, message: call("ampleCheck", m.args, "string")});
    else if (m.cmd === "setup") post({type: "setupDone", id: m.id, status: call("ampleSetup", m.args)});
    else if (m.cmd === "run") {
      var t = performance.now(), status = call("ampleRun", m.args.concat(["--out", OUT]));
      var files = outFiles();
      post({type: "done", status: status, files: files.names, texts: files.texts, seconds: (performance.now() - t) / 1000});
    } else if (m.cmd === "file") {
      var bytes = Module.FS.readFile(OUT + "/" + m.name);
      post({type: "file", id: m.id, name: m.name, bytes: bytes}, [bytes.buffer]);
    }
  }).catch(function (err) {
    post({type: "err", line: "worker: " + (err && err.message || err)});
    post({type: "done", status: -1, files: [], texts: {}, seconds: 0});
  });
};
