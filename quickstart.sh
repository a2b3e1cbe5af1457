#!/usr/bin/env bash
# quickstart.sh — build ample-cpp (Release) and run the default setup (compaction).
# Installs the Debian packages it needs (cmake, g++, libeigen3-dev, doctest-dev) and the one the
# README's next line needs (python3-matplotlib: plotting/plot_run.py draws the picture of a run
# with it, under /usr/bin/python3 when the python3 on PATH has no matplotlib) if missing.
# Builds the program only (build/release/ample, the build preset "release", -j2): about 1-2 min
# on 2 idle cores, make's [ NN%] lines show the progress; the tests are built by
# `cmake --workflow --preset quick` (README, "Test").
# ./quickstart.sh --fast [args]: also MUMPS and a fast serial BLAS (libmumps-seq-dev,
# libopenblas0-serial), built with the preset "fast" (build/fast/ample, solver=MUMPS).
# ./quickstart.sh --wasm: the program for a browser tab instead (emscripten; the preset "wasm",
# about 2 min: build/wasm/viewer, the page with ample_wasm.js and .wasm), and the line that
# serves it (docs/browser.md).
set -euo pipefail
cd "$(dirname "$0")"
pkgs="cmake g++ libeigen3-dev doctest-dev python3-matplotlib"
preset=release
if [ "${1:-}" = "--fast" ]; then
  shift
  pkgs="$pkgs libmumps-seq-dev libopenblas0-serial"
  preset=fast
elif [ "${1:-}" = "--wasm" ]; then
  pkgs="cmake libeigen3-dev emscripten"
  preset=wasm
fi
if ! dpkg -s $pkgs >/dev/null 2>&1; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "quickstart: installing $pkgs"
  $sudo apt-get update && $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y $pkgs
fi
if [ $preset = wasm ]; then
  echo "quickstart: building build/wasm/viewer (emscripten, -j2)"
  cmake --workflow --preset wasm
  echo "quickstart: built; serve the page and open http://127.0.0.1:8000/ :"
  echo "  python3 -m http.server -d build/wasm/viewer -b 127.0.0.1 8000"
  exit 0
fi
echo "quickstart: configuring build/$preset (Release)"
cmake --preset $preset > /dev/null
echo "quickstart: building build/$preset/ample (-j2; one line per source file)"
start=$(date +%s)
cmake --build --preset $preset --target ample
echo "quickstart: built in $(( $(date +%s) - start )) s; running: build/$preset/ample compaction $*"
build/$preset/ample compaction "$@"
