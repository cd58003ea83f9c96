#!/usr/bin/env bash
# Regenerates every golden image in tests/golden/ from the current code.
#
#   scripts/bless-goldens.sh            (build directory: $VPLAB_BUILD, default build/)
#
# The golden tests (tests/app/ui/golden_test.cpp) normally compare each image with its golden. With
# VPLAB_BLESS=1 they write the image they rendered as the new golden instead (and remove the goldens
# of scenes that are no longer in assets/scenes/). This script builds test_ui, runs the golden tests
# that way, runs them again normally to confirm that they now pass, and lists what changed.
#
# A golden is only as right as the eyes that checked it: LOOK at every changed PNG (git status
# tests/golden, then an image viewer) before committing, and bless only when the change in the
# pictures is the change you meant to make.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VPLAB_BUILD:-$root/build}"

cmake -S "$root" -B "$build" >/dev/null
cmake --build "$build" -j "$(nproc)" --target test_ui test_render vplab

# The golden tests are GoldenDefault (parameterized: Views/GoldenDefault.*), GoldenUi and
# GoldenScenes; GoldenTolerance skips itself while blessing. ctest runs them as every image test is
# run: on Mesa's llvmpipe, never on a GPU this machine may have (tests/CMakeLists.txt sets that
# environment on each test, and a test inherits VPLAB_BLESS from ours). SoftwareRenderer.* checks
# that environment first and stops the script before anything is written. One test at a time, as
# blessing also removes goldens; a pattern that selects no test is an error, not a quiet pass.
run_tests() { ctest --test-dir "$build" --parallel 1 --no-tests=error --output-on-failure -R "$1"; }
run_tests '^SoftwareRenderer\.'
VPLAB_BLESS=1 run_tests 'Golden'
run_tests 'Golden'

echo
echo "Changed goldens (LOOK at each before committing):"
git -C "$root" status --short -- tests/golden || ls -l "$root/tests/golden"
