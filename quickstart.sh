#!/usr/bin/env bash
# quickstart.sh — build ample-cpp (Release) and run the default setup (compaction).
# Installs the Debian packages it needs (cmake, g++, libeigen3-dev, doctest-dev) if missing.
set -euo pipefail
cd "$(dirname "$0")"
pkgs="cmake g++ libeigen3-dev doctest-dev"
if ! dpkg -s $pkgs >/dev/null 2>&1; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update && $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y $pkgs
fi
cmake --preset release
cmake --build --preset release
build/release/ample compaction "$@"
