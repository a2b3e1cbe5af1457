//--------------------------------------------------------------------------
// page.js — the form, the runs in a Web Worker, the output folder opened
//--------------------------------------------------------------------------
// The setup list and each setup's parameter form come from the program's own
// table (ampleSetups: names, defaults, ranges, whole numbers, choice names,
// help). Every change is checked by the program's own command-line parser
// (ampleCheck, in a worker kept for the form): its message is shown as is,
// Run stays off until it passes, and the set-up state is drawn (the first
// picture). Run starts a fresh worker (worker.js) with the words of the command
// line the form shows; the run streams each pass and each converged step, drawn
// as it goes (viewer.js); Cancel ends the worker at once. What the program
// refuses (a setup that cannot be set up, a load step that does not converge)
// shows its own message and the steps up to the last converged one, as the
// command line does. "Open an output folder" draws a native run's files
// (readRun.js); run.html of plot_run.py --animate carries its files inside
// (window.AMPLE_RUN_FILES) and opens as that run alone.
// For the tests (tests/viewer_test.py): window.ampleRuns (every run of the page
// with its timings) and window.pageReady (the form built, the first picture drawn).
//--------------------------------------------------------------------------
(function () {
  "use strict";
  var el = {}, table = null, checker = null, compiled = null, pending = {}, nextId = 1;
  var running = null;                         // {worker, run} of the run going on
  var kept = null;                            // the worker of the last run ended, kept for its files
  var checkedArgs = null, previewTimer = null, lastPreview = "";
  window.ampleRuns = [];
  window.pageReady = false;

  function $(id) { return document.getElementById(id); }

  function setTitle(text, stopped) {
    el.title.textContent = text;
    el.title.className = stopped ? "stopped" : "";
    document.title = text;
  }

  // the heading of a finished run, as the page of the native program's folder says it
  function headingOf(summary) {
    if (summary.converged) return summary.setup + " — converged, " + summary.lstps + " load steps";
    return summary.setup + " — stopped after load step " + summary.last_converged_step + " of " + summary.lstps +
           ": " + summary.message;
  }

  function resultsTable(summary) {
    el.results.textContent = "";
    if (!summary) return;
    var t = document.createElement("table");
    function row(k, v) {
      var tr = t.insertRow();
      tr.insertCell().textContent = k;
      tr.insertCell().textContent = v;
    }
    Object.keys(summary.results || {}).forEach(function (k) {
      var v = summary.results[k];
      if (v === null) row(k, "undefined");
      else row(k, Number.isInteger(Number(v)) ? String(v) : Number(v).toPrecision(10));   // a count as such
    });
    row("load steps", summary.last_converged_step + " of " + summary.lstps);
    row("Newton-Raphson passes", summary.total_NR_iterations);
    if (!("points" in (summary.results || {}))) row("points", summary.nmp);   // once
    row("wall time (s)", Number(summary.wall_seconds).toFixed(3));
    el.results.appendChild(t);
  }

  //------------------------------------------------------------------ the form
  function selectedSetup() {
    return table.setups.filter(function (s) { return s.name === el.setup.value; })[0];
  }

  function numberText(v) { return v === null ? "" : String(v); }

  // the inputs of a setup's parameters: a choice is a list of its names, any other a text box
  function buildParams() {
    var st = selectedSetup();
    el.params.textContent = "";
    el.setupText.textContent = st.description;
    st.params.forEach(function (p) {
      var row = document.createElement("div"), label = document.createElement("label"), input;
      row.className = "row";
      label.textContent = p.name;
      label.title = p.help + "; " + p.range;
      if (p.names.length) {
        input = document.createElement("select");
        p.names.forEach(function (n, k) {
          var o = document.createElement("option");
          o.value = n; o.textContent = (p.lo + k) + " " + n; input.appendChild(o);
        });
        input.value = p.names[p.value - p.lo];
        input.dataset.dflt = input.value;
      } else {
        input = document.createElement("input");
        input.value = numberText(p.value);
        input.dataset.dflt = input.value;
        input.size = 10;
      }
      input.id = "param-" + p.name;
      input.dataset.param = p.name;
      input.title = p.help + "; allowed " + p.range;
      label.htmlFor = input.id;
      var range = document.createElement("span");
      range.className = "range";
      range.textContent = p.names.length ? "" : p.range;
      range.title = p.range;
      row.appendChild(label); row.appendChild(input); row.appendChild(range);
      el.params.appendChild(row);
    });
  }

  // the command line's words of the form: the setup, each parameter changed from its default
  // (name=value as typed), the options changed from theirs
  function formArgs() {
    var args = [el.setup.value];
    el.params.querySelectorAll("[data-param]").forEach(function (i) {
      if (i.value !== i.dataset.dflt) args.push(i.dataset.param + "=" + i.value);
    });
    document.querySelectorAll("[data-option]").forEach(function (i) {
      if (i.value !== i.defaultValue && !(i.tagName === "SELECT" && i.selectedIndex === 0)) args.push(i.dataset.option, i.value);
    });
    document.querySelectorAll("[data-flag]").forEach(function (i) { if (i.checked) args.push(i.dataset.flag); });
    return args;
  }

  function ask(msg) {
    var id = nextId++;
    msg.id = id;
    return new Promise(function (resolve) { pending[id] = resolve; checker.postMessage(msg); });
  }

  // the form's words checked by the program's parser; Run on when they pass
  function check() {
    var args = formArgs();
    el.command.textContent = "ample " + args.join(" ");
    return ask({cmd: "check", args: args}).then(function (r) {
      if (formArgs().join("\n") !== args.join("\n")) return;  // changed again meanwhile
      checkedArgs = r.message ? null : args;
      el.check.textContent = r.message ? "ample: " + r.message : "";
      var bad = /^parameter '([^']+)'/.exec(r.message) || /^option '([^']+)'/.exec(r.message);
      document.querySelectorAll("#runForm input, #runForm select").forEach(function (i) {
        var name = i.dataset.param || i.dataset.option;
        i.classList.toggle("bad", !!bad && name === bad[1]);
      });
      el.run.disabled = !checkedArgs || !!running;
      if (checkedArgs && !running) schedulePreview(args);
      return r.message;
    });
  }

  // the first picture of a setup: its points and grid as set up (no step run)
  function schedulePreview(args) {
    var key = args.filter(function (a) { return !/^--/.test(a); }).join("\n");
    if (key === lastPreview) return;
    clearTimeout(previewTimer);
    previewTimer = setTimeout(function () {
      lastPreview = key;
      var run = newRun(args, "preview");
      checker.onStream = function (m) { stream(run, m); };
      ask({cmd: "setup", args: args}).then(function (r) {
        checker.onStream = null;
        if (running || !run.frames.length) return;
        if (r.status === 0) {
          setTitle(args[0] + " — as set up (press Run)", false);
          Viewer.show(run);
        }
        if (!window.pageReady) {
          window.pageReady = true;
          window.firstPictureSeconds = performance.now() / 1000;       // since the page was asked for
        }
      });
    }, window.pageReady ? 150 : 0);
  }

  function paramValue(name) {
    var i = $("param-" + name);
    return i ? Number(i.value) : NaN;
  }

  function newRun(args, kind) {
    return {setup: args[0], args: args, kind: kind, lstps: paramValue("lstps") || 1, tol: paramValue("tol"),
            frames: [], grids: [], passes: [], stderr: [], source: "page", started: performance.now()};
  }

  // a message of the program's stream into the run
  function stream(run, m) {
    if (m.type === "grid") {
      run.grids.push({nodes: m.nodes, edges: ReadRun.edges({flat: m.cells, nen: m.nen}, m.nodes.length / 2)});
    } else if (m.type === "pass") {
      run.passes.push({lstp: m.lstp, NRit: m.NRit, fErr: m.fErr});
    } else if (m.type === "frame") {
      var cols = {};
      table.columns.forEach(function (c, k) {             // single precision: drawn, not computed
        cols[c] = Float32Array.from(m.data.subarray(k * m.n, (k + 1) * m.n));
      });
      run.frames.push({lstp: m.lstp, lf: m.lf, NRit: m.NRit, fErr: m.fErr, n: m.n, cols: cols,
                       grid: run.grids.length - 1});
      if (m.lstp === 1) run.firstStep = performance.now();
    } else if (m.type === "err") {
      run.stderr.push(m.line);
    }
  }

  //------------------------------------------------------------------ runs
  function progress(run, lstp, text) {
    el.bar.style.width = (100 * Math.min(1, lstp / run.lstps)).toFixed(1) + "%";
    el.state.textContent = text;
  }

  function startRun(args) {
    if (running) return;
    Viewer.stop();
    clearTimeout(previewTimer);
    if (kept) kept.terminate();                 // the last run's files go with its worker
    var run = newRun(args, "run"), worker = new Worker("worker.js");
    window.ampleRuns.push(run);
    running = {worker: worker, run: run};
    el.run.disabled = true; el.cancel.disabled = false;
    el.message.textContent = ""; el.results.textContent = ""; el.downloads.textContent = "";
    setTitle(args[0] + " — running", false);
    progress(run, 0, "starting " + args.join(" "));
    var shown = false;
    worker.onmessage = function (e) {
      var m = e.data;
      stream(run, m);
      if (m.type === "pass") progress(run, m.lstp - 1, "load step " + m.lstp + " of " + run.lstps + "  ·  pass " +
                                      (m.NRit + 1) + "  ·  fErr = " + (isFinite(m.fErr) ? m.fErr.toExponential(2) : m.fErr));
      if (m.type === "frame") progress(run, m.lstp, "load step " + m.lstp + " of " + run.lstps + " converged");
      if (m.type === "err") el.message.textContent += (el.message.textContent ? "\n" : "") + m.line;
      if (m.type === "frame" && !shown) { shown = true; Viewer.show(run); }
      else if (m.type === "frame" || m.type === "grid") Viewer.update();
      else if (m.type === "pass") Viewer.update(true);
      if (m.type === "done") finish(run, worker, m);
    };
    worker.onerror = function (e) {
      el.message.textContent += "worker: " + e.message;
      finish(run, worker, {status: -1, files: [], texts: {}, seconds: 0});
    };
    worker.postMessage({cmd: "load", module: compiled});
    worker.postMessage({cmd: "run", args: args});
  }

  function finish(run, worker, m) {
    run.status = m.status;
    run.seconds = m.seconds;
    run.done = performance.now();
    running = null;
    el.cancel.disabled = true;
    el.run.disabled = !checkedArgs;
    run.fileNames = m.files;
    run.texts = m.texts;
    var files = {}, ids = 0;
    run.fetchFile = function (name) {              // from the worker kept for this run's files
      if (m.texts[name] !== undefined) return Promise.resolve(new TextEncoder().encode(m.texts[name]));
      return new Promise(function (resolve) {
        var id = ++ids;
        files[id] = resolve;
        worker.postMessage({cmd: "file", id: id, name: name});
      });
    };
    worker.onmessage = function (e) { if (e.data.type === "file") files[e.data.id](e.data.bytes); };
    kept = worker;
    if (m.texts["summary.json"]) {
      run.summary = JSON.parse(m.texts["summary.json"]);
      resultsTable(run.summary);
      setTitle(headingOf(run.summary), !run.summary.converged);
    } else {
      setTitle(run.setup + " — " + (m.status === 2 ? "refused (bad input)" : "ended with exit status " + m.status), true);
    }
    progress(run, run.summary ? run.summary.last_converged_step : 0,
             ["converged", "stopped: a load step did not converge or the run could not go on", "bad input",
              "needs an exercise"][m.status] || "ended with exit status " + m.status);
    if (Viewer.run === run) Viewer.refresh(); else Viewer.show(run);
  }

  function cancel() {
    if (!running) return;
    var run = running.run;
    running.worker.terminate();
    running = null;
    run.cancelled = performance.now();
    run.status = "cancelled";
    el.cancel.disabled = true;
    el.run.disabled = !checkedArgs;
    var last = run.frames.length ? run.frames[run.frames.length - 1].lstp : 0;
    setTitle(run.setup + " — cancelled after load step " + last + " of " + run.lstps, true);
    progress(run, last, "cancelled: the steps up to load step " + last + " are drawn; the run's files went with it");
    if (run.frames.length && Viewer.run !== run) Viewer.show(run);
  }

  //------------------------------------------------------------------ a folder of the native program
  function openFolder(list) {
    var wanted = Array.prototype.filter.call(list, function (f) {
      return /^(summary\.json|steps\.csv|residuals\.csv|mp_final\.csv|history\.csv|mesh(_\d+)?\.vtk|mpData_\d+\.vtk)$/.test(f.name);
    });
    return Promise.all(wanted.map(function (f) {
      return f.arrayBuffer().then(function (b) { return [f.name, new Uint8Array(b)]; });
    })).then(function (pairs) {
      var files = {};
      pairs.forEach(function (p) { files[p[0]] = p[1]; });
      showFiles(files, {});
    }).catch(function (err) {
      el.message.textContent = "cannot read the folder: " + err.message;
    });
  }

  function showFiles(files, opts) {
    var run = ReadRun.fromFiles(files);
    run.fileNames = Object.keys(files);
    run.fetchFile = function (name) { return Promise.resolve(files[name]); };
    Viewer.stop();
    setTitle(headingOf(run.summary), !run.summary.converged);
    resultsTable(run.summary);
    el.message.textContent = run.summary.converged ? "" : run.summary.message;
    el.state.textContent = "output folder of a run: " + run.frames.length + " load steps written";
    Viewer.show(run, opts);
    window.ampleRuns.push(run);
    return run;
  }

  // run.html of plot_run.py --animate: the run's files are in the page (base64)
  function embedded() {
    var files = {};
    Object.keys(window.AMPLE_RUN_FILES).forEach(function (name) {
      var bin = atob(window.AMPLE_RUN_FILES[name]), bytes = new Uint8Array(bin.length);
      for (var k = 0; k < bin.length; ++k) bytes[k] = bin.charCodeAt(k);
      files[name] = bytes;
    });
    document.body.classList.add("embedded");
    showFiles(files, {frame: "hash", drawEvery: true, field: window.AMPLE_RUN_FIELD});
    window.pageReady = true;
  }

  //------------------------------------------------------------------ start
  function noProgram(why) {
    el.check.textContent = "The program is not here (" + why + "): build it with `cmake --workflow --preset wasm` " +
      "and serve build/wasm/viewer (README, \"In a browser tab\"). An output folder still opens.";
    el.run.disabled = true;
    window.pageReady = true;
  }

  function start() {
    ["title", "setup", "setupText", "params", "check", "run", "cancel", "reset", "command", "bar", "state",
     "message", "results", "downloads", "folder"].forEach(function (id) { el[id] = $(id); });
    el.command = $("commandLine");
    Viewer.init();
    el.folder.addEventListener("change", function () { openFolder(el.folder.files); });
    if (window.AMPLE_RUN_FILES) return embedded();
    if (location.protocol === "file:") return noProgram("a page opened as a file cannot start workers");
    fetch("ample_wasm.wasm").then(function (r) {
      if (!r.ok) throw new Error("ample_wasm.wasm: " + r.status);
      return r.arrayBuffer();
    }).then(function (b) { return WebAssembly.compile(b); }).then(function (mod) {
      compiled = mod;
      checker = new Worker("worker.js");
      checker.onmessage = function (e) {
        var m = e.data;
        if (m.type === "setups") return built(JSON.parse(m.json));
        if (checker.onStream && /^(grid|frame|pass)$/.test(m.type)) checker.onStream(m);
        if (m.type === "err" && !running) el.check.textContent = m.line;
        if (pending[m.id]) { pending[m.id](m); delete pending[m.id]; }
      };
      checker.postMessage({cmd: "load", module: compiled});
      checker.postMessage({cmd: "setups"});
    }).catch(function (err) { noProgram(err.message); });
  }

  function built(t) {
    table = t;
    t.setups.forEach(function (s) {
      var o = document.createElement("option");
      o.value = s.name; o.textContent = s.name; o.title = s.description; el.setup.appendChild(o);
    });
    el.setup.value = /[?&]setup=([a-z0-9_]+)/.test(location.search) ? /[?&]setup=([a-z0-9_]+)/.exec(location.search)[1] : "collapse";
    if (!selectedSetup()) el.setup.value = t.setups[0].name;
    buildParams();
    el.setup.addEventListener("change", function () { buildParams(); check(); });
    $("runForm").addEventListener("input", function () { check(); });
    $("runForm").addEventListener("change", function () { check(); });
    $("runForm").addEventListener("submit", function (e) {
      e.preventDefault();
      check().then(function (message) { if (!message && checkedArgs) startRun(checkedArgs); });
    });
    el.cancel.addEventListener("click", cancel);
    el.reset.addEventListener("click", function () { buildParams(); check(); });
    check();
  }

  window.amplePage = {check: check, formArgs: formArgs, cancel: cancel, get running() { return running; }};
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
