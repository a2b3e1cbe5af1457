#!/usr/bin/env bash
# run_benchmarks.sh — regenerate every CSV, PNG and table in docs/results (Release build).
# Takes about 15-20 minutes on the 2-core development machine; --quick for a short check.
# Needs Debian's python3-matplotlib for the plots (installed here if missing).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update && $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y python3-matplotlib
fi
cmake --preset release
cmake --build --preset release --target ample_bench
build/release/ample_bench --out docs/results "$@"
/usr/bin/python3 plotting/plot_results.py docs/results
/usr/bin/python3 plotting/plot_ib.py docs/results > /dev/null   # deepbeam.png, ibshear.png
