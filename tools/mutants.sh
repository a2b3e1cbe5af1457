#!/usr/bin/env bash
#--------------------------------------------------------------------------
# mutants.sh — mutation check: does the test suite see a class of errors?
#--------------------------------------------------------------------------
# Each mutant is one plausible mistake, written as a sed substitution on one
# file. The script copies the source tree (no build/, no .git) to a work folder
# outside the worktree, applies ONE mutation at a time, rebuilds ample and
# ample_tests there with -j1 in a build folder that is kept between mutants and
# between runs (so only the mutated file recompiles and relinks), runs the tests
# and reports "caught" (a test fails) or "SURVIVED" (every test passes). The
# file is restored after each mutant. The unmutated tree is built and tested
# first: if its tests fail, nothing is reported.
#
#   tools/mutants.sh                    # every mutant, tests of the working tree
#   tools/mutants.sh compaction-vp vtk-vm-no-2     # some of them
#   tools/mutants.sh --list             # names, files and substitutions
#   tools/mutants.sh --tests-rev REV    # the tests/ folder of git revision REV
#                                       # (e.g. the suite before a change: "before")
# Environment: AMPLE_MUTANTS_DIR  work folder (default /tmp/ample-mutants-$USER);
#              AMPLE_MUTANTS_TESTS  doctest filter arguments for every mutant
#              (default: every test except the suite "stress": -tse=stress)
# Exit status: 0 every mutant caught, 1 some survived (or were not applied), 2 setup error
# The first run builds the whole tree (long on a shared machine); later runs
# rebuild only what changed. Not part of the default ctest: configure with
# -DAMPLE_MUTANTS=ON to get the CTest test "mutants" (label mutants).
# Documented in docs/structure.md, "Mutation check".
#--------------------------------------------------------------------------
set -u

# name | file | sed expression (extended regex, | is not used inside)
MUTANTS=(
  # the seven that once survived review
  "compaction-vp|setups/compaction.cpp|s/\* mp\.vp0;/* mp.vp;/"
  "vtk-vm-no-2|plotting/makeVtkMP.cpp|s/\+ 2 \* mp\.sig\.tail<3>\(\)/+ mp.sig.tail<3>()/"
  "vtk-szz-sxy-swap|plotting/makeVtkMP.cpp|s/\"sigma_zz\", \"sigma_xy\"/\"sigma_xy\", \"sigma_zz\"/"
  "restore-kirchhoff|ample/remedies/loadSteps.cpp|s/\.Ksig \/ mp\.Fn\.determinant\(\)/.Ksig/"
  "shear-nu-default|setups/shear.cpp|s/^    nu = 0\.3;/    nu = 0.25;/"
  "stretch-E-default|setups/stretch.cpp|s/^    E = 1000;/    E = 1100;/"
  "cli-unknown-unnamed|setups/program/cli.cpp|s/\"unknown parameter '\" \+ name \+ \"' for setup '\"/std::string(\"unknown parameter for setup '\")/"
  # a handful of others
  "body-force-sign|ample/detExtForce.cpp|s/Vector2d\(0\.0, -g\)/Vector2d(0.0, g)/"
  "vmconst-rho-no-2|constitutive/VMconst.cpp|s/\+ 2\.0 \* s\.tail<3>\(\)/+ s.tail<3>()/"
  "cauchy-no-J|ample/detMPs.cpp|s/cm\.Ksig \/ mp\.F\.determinant\(\)/cm.Ksig/"
  "uii-as-fii|ample/updateMPs.cpp|s/Vector2d\(U\(0, 0\), U\(1, 1\)\)/Vector2d(F(0, 0), F(1, 1))/"
  "eq35-denominator|ample/ample.cpp|s/\(\(fext \+ r\)\.array\(\)/((fext).array()/"
  "hooke-shear-G|constitutive/Hooke3d.cpp|s/E \/ \(2\.0 \* \(1\.0 \+ nu\)\)/E \/ (1.0 + nu)/"
  # implicit boundaries (tests/test_boundary.cpp)
  "eq16-slope-no-2|ample/boundaries/dirichletBand.cpp|s/return 2\.0 \/ delta \* \(1\.0 - phi \/ delta\);/return 1.0 \/ delta * (1.0 - phi \/ delta);/"
  "ib-centroid-not-moved|setups/setupHelpers.cpp|s/blockPoint\(x \+ in\.centroid, /blockPoint(x, /"
  "cutcells-wrong-side|ample/boundaries/cutCells.cpp|s/\(n\(k\) > 0 \? 0 : 1\)/(n(k) > 0 ? 1 : 0)/"
  # K2 with the free part only (int d d' dropped) and K2 without its transpose (tests/test_ibStiffness.cpp)
  "ib-k2-no-d-dp|ample/boundaries/ibStiffness.cpp|s/\(bi\.dp \* a \+ dDp \* m\)/(bi.dp * a)/"
  "ib-k2-no-transpose|ample/boundaries/ibStiffness.cpp|s/K \+= gw\[q\] \* len \* \(K2 \+ K2\.transpose\(\) \+ K3\);/K += gw[q] * len * (K2 + K3);/"
  # the consistent coupling as the printed 1/2; curve normals ignored; the boundary force's sign;
  # a prescribed boundary with no point to push, silently (tests/test_ibStiffness.cpp, test_ibMoving.cpp)
  "ib-consistent-as-paper|ample/boundaries/ibStiffness.cpp|s/\? bi\.d_dp : bi\.dp;/? bi.d_dp : bi.d_dp;/"
  "ib-curve-normal-ignored|ample/boundaries/boundary.h|s/if \(b\.curveNormal\.empty\(\)\) return inwardNormal\(b, s\);/return inwardNormal(b, s);/"
  "ib-force-sign|ample/boundaries/ibStiffness.cpp|s/r = t\.f - t\.k \* ue;/r = t.k * ue - t.f;/"
  "ib-empty-prescribed-silent|ample/boundaries/ibStiffness.cpp|s/      throw RunError\(\"implicit boundary \"/      if (false) throw RunError(\"implicit boundary \"/"
  # formulation=SS ([Boundaries]): grad du as (I + grad du) - I; the volume of the moved configuration
  "ss-grad-via-dF|ample/formulations/detMPsForm.cpp|s/: smallStrain\(H, mp\);/: smallStrain(dF.topLeftCorner<2, 2>() - Eigen::Matrix2d::Identity(), mp);/"
  "ss-volume-dF|ample/formulations/detMPsForm.cpp|s/mp\.vp\}; +\/\/ V_p = V_p0/(Eigen::Matrix2d::Identity() + H).determinant() * mp.vp};/"
  # the fast loop's copy of eq 6 (tests/test_pointLoops.cpp against the plain loops)
  "fast-cauchy-no-J|ample/fast/addPoint.cpp|s/cm\.Ksig \/ mp\.F\.determinant\(\)/cm.Ksig/"
)

SRC=$(cd "$(dirname "$0")/.." && pwd)
WORK=${AMPLE_MUTANTS_DIR:-/tmp/ample-mutants-${USER:-$(id -u)}}
FILTER=${AMPLE_MUTANTS_TESTS:--tse=stress}
TESTS_REV=""
SELECT=()
while [ $# -gt 0 ]; do
  case "$1" in
    --list) for m in "${MUTANTS[@]}"; do IFS='|' read -r n f e <<<"$m"; printf '%-22s %-28s %s\n' "$n" "$f" "$e"; done; exit 0 ;;
    --tests-rev) TESTS_REV=$2; shift 2 ;;
    -h|--help) sed -n '2,28p' "$0"; exit 0 ;;
    *) SELECT+=("$1"); shift ;;
  esac
done

mkdir -p "$WORK/src" "$WORK/build" || exit 2
"$SRC/tools/sync_tree.sh" "$SRC" "$WORK/src"   # changed files only: only they recompile
if [ -n "$TESTS_REV" ]; then        # the test folder of another revision
  tmp=$(mktemp -d)
  git -C "$SRC" archive "$TESTS_REV" tests | tar -x -C "$tmp" || exit 2
  for f in "$WORK"/src/tests/test_*.cpp; do   # test files the revision does not have
    [ -e "$tmp/tests/$(basename "$f")" ] || rm -f "$f"
  done
  (cd "$tmp" && find tests -type f) | while read -r f; do
    cmp -s "$tmp/$f" "$WORK/src/$f" || cp "$tmp/$f" "$WORK/src/$f"
  done
  rm -rf "$tmp"
fi

build() {
  cmake --build "$WORK/build" -j1 --target ample ample_tests >"$WORK/build.log" 2>&1
}
runtests() {
  (cd "$WORK/build/tests" && timeout 1800 ./ample_tests $FILTER >"$WORK/tests.log" 2>&1)
}

if [ ! -f "$WORK/build/CMakeCache.txt" ]; then
  cmake -S "$WORK/src" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release >"$WORK/configure.log" 2>&1 ||
    { echo "configure failed: $WORK/configure.log"; exit 2; }
fi
echo "mutation check: tree $SRC${TESTS_REV:+ (tests of $TESTS_REV)}, work folder $WORK, tests: $FILTER"
build || { echo "the unmutated tree does not build: $WORK/build.log"; exit 2; }
runtests || { echo "the unmutated tree fails its tests: $WORK/tests.log"; exit 2; }
echo "unmutated tree: tests pass"

status=0
for m in "${MUTANTS[@]}"; do
  IFS='|' read -r name file expr <<<"$m"
  if [ ${#SELECT[@]} -gt 0 ] && [[ ! " ${SELECT[*]} " == *" $name "* ]]; then continue; fi
  target="$WORK/src/$file"
  cp "$target" "$WORK/original"
  sed -E -i "$expr" "$target"
  if cmp -s "$target" "$WORK/original"; then
    printf '%-22s NOT APPLIED (pattern not found in %s)\n' "$name" "$file"
    status=1
    continue
  fi
  start=$(date +%s)
  detail=""
  if ! build; then
    verdict="BUILD-ERROR"
    status=1
  elif runtests; then
    verdict="SURVIVED"
    status=1
  else
    verdict="caught"
    detail=$(grep -o 'TEST CASE:  .*' "$WORK/tests.log" | sed 's/TEST CASE:  //' | sort -u | head -3 | paste -sd ';' -)
  fi
  cp "$WORK/original" "$target"   # restored with a new time: it recompiles next time
  printf '%-22s %-11s %5ss  %s\n' "$name" "$verdict" "$(( $(date +%s) - start ))" "$detail"
done
build >/dev/null 2>&1   # leave the build folder matching the unmutated tree
exit $status
