#!/usr/bin/env bash
# check_layers.sh — the includes of the project run one way (docs/structure.md)
#
# Layers, bottom to top; a file may include files of its own layer or below:
#   0 data          ample/mpData.h ample/errors.h ample/analysis.h
#   0 constitutive  constitutive/*  (Eigen and the standard library only; exercise.h, the
#                   student copy's error, lives here so that nothing of ample/ is needed)
#   1 pieces        ample/stiffness/*
#   2 parts         ample/basis/*
#   3 core          ample/*.h ample/*.cpp (the loop, its hooks and the functions it calls:
#                   elemMPinfo, detExtForce, detFDoFs, linSolve, detMPs, updateMPs)
#   4 extensions    the rooms ample/solver/ remedies/ boundaries/ fast/ domains/ locking/
#                   initial/ cpdi/ meshes/ formulations/ (each with a README.md; they may include the
#                   core and each other, never the core them: a core file, layers 0-3, that
#                   includes a room is named; ample/fast/, a core function replaced as a
#                   whole for large runs, is included by setups/program/* only, which
#                   chooses it)
#   5 output        plotting/*  (postPro and the VTK writers; the scripts that draw a run)
#   6 setups        setups/*
#   7 program       setups/program/* (the command line, the run and its hooks, its output files)
# so that between the top-level folders every include runs one way: constitutive/ <- ample/
# <- plotting/ <- setups/ (whose program/ joins them)
# and no two modules (a .h/.cpp pair) include each other, directly or round a
# cycle (checked with tsort over the module graph). Prints every offending
# include; exit 0 when there is none, 1 otherwise.
#   tools/check_layers.sh            (from the top of the tree)
set -uo pipefail
cd "$(dirname "$0")/.."

layer() {  # layer of a project file, -1 for one outside the layered tree
  case "$1" in
    ample/mpData.h|ample/errors.h|ample/analysis.h|constitutive/*) echo 0 ;;
    ample/stiffness/*) echo 1 ;;
    ample/basis/*) echo 2 ;;
    ample/solver/*|ample/remedies/*|ample/boundaries/*|ample/fast/*|ample/domains/*|ample/locking/*|\
    ample/initial/*|ample/cpdi/*|ample/meshes/*|ample/formulations/*) echo 4 ;;
    setups/program/*) echo 7 ;;
    ample/*/*) echo -1 ;;   # a folder of ample/ without a layer
    ample/*) echo 3 ;;
    setups/*) echo 6 ;;
    plotting/*) echo 5 ;;
    *) echo -1 ;;
  esac
}

bad=0
edges=$(mktemp)
trap 'rm -f "$edges"' EXIT
for f in ample/* ample/*/* constitutive/* setups/* setups/*/* plotting/*; do
  case "$f" in *.h|*.cpp) ;; *) continue ;; esac
  lf=$(layer "$f")
  while IFS= read -r inc; do
    [ -z "$inc" ] && continue
    # resolve "x.h" next to the file, else from the top of the tree
    if [ -e "$(dirname "$f")/$inc" ]; then t="$(dirname "$f")/$inc"; else t="$inc"; fi
    t=$(realpath --relative-to=. "$t")
    lt=$(layer "$t")
    if [ "$lt" -lt 0 ]; then echo "$f includes $inc, which is not in the tree"; bad=1; continue; fi
    if [ "$lf" -le 3 ] && [ "$lt" -eq 4 ]; then
      echo "$f (the core, layer $lf) includes $t: the core includes no extension (layer 4)"; bad=1
    elif [ "$lt" -gt "$lf" ]; then
      echo "$f (layer $lf) includes $t (layer $lt): an include up a layer"; bad=1
    fi
    case "$t" in ample/fast/*)   # an extension: only the program (and its own room) chooses it
      case "$f" in ample/fast/*|setups/program/*) ;; *) echo "$f includes $t: the core includes no extension (ample/fast/ is chosen by setups/program/)"; bad=1 ;; esac
    esac
    case "$f" in constitutive/*)
      case "$t" in constitutive/*) ;; *) echo "$f includes $t: constitutive/ must stand alone"; bad=1 ;; esac
    esac
    mf=${f%.*}; mt=${t%.*}
    [ "$mf" != "$mt" ] && echo "$mt $mf" >> "$edges"
  done < <(sed -n 's/^#include "\(.*\)".*/\1/p' "$f")
done
if ! tsort "$edges" > /dev/null 2> "$edges.err"; then
  echo "include cycle between modules:"; grep -v 'input contains a loop' "$edges.err" | sed 's/^tsort: /  /'
  bad=1
fi
rm -f "$edges.err"
[ $bad -eq 0 ] && echo "layers: every include runs down a layer or within one; no include cycle"
exit $bad
