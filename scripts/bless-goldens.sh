#!/usr/bin/env bash
# Regenerates every golden image in tests/golden/ from the current code.
#
#   scripts/bless-goldens.sh            (build directory: $VPLAB_BUILD, default build/)
#
# The golden tests (tests/app/golden_test.cpp) normally compare each image with its golden. With
# VPLAB_BLESS=1 they write the image they rendered as the new golden instead (and remove the goldens
# of scenes that are no longer in assets/scenes/). This script builds test_app, runs the golden tests
# that way, runs them again normally to confirm that they now pass, and lists what changed.
#
# A golden is only as right as the eyes that checked it: LOOK at every changed PNG (git status
# tests/golden, then an image viewer) before committing, and bless only when the change in the
# pictures is the change you meant to make.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VPLAB_BUILD:-$root/build}"

cmake -S "$root" -B "$build" >/dev/null
cmake --build "$build" -j "$(nproc)" --target test_app vplab

# The golden tests are GoldenDefault (parameterized: Views/GoldenDefault.*), GoldenUi and
# GoldenScenes; GoldenTolerance skips itself while blessing.
# On Mesa's llvmpipe, as ctest runs the image tests (tests/CMakeLists.txt, VPLAB_SOFTWARE_GL_ENVIRONMENT),
# never on a GPU this machine may have: SoftwareRenderer.* stops the script before anything is written.
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe __GLX_VENDOR_LIBRARY_NAME=mesa
if [ -f /usr/share/glvnd/egl_vendor.d/50_mesa.json ]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/glvnd/egl_vendor.d/50_mesa.json
fi
"$build/tests/test_app" --gtest_filter='SoftwareRenderer.*' --gtest_brief=1
VPLAB_BLESS=1 "$build/tests/test_app" --gtest_filter='*Golden*' --gtest_brief=1
"$build/tests/test_app" --gtest_filter='*Golden*' --gtest_brief=1

echo
echo "Changed goldens (LOOK at each before committing):"
git -C "$root" status --short -- tests/golden || ls -l "$root/tests/golden"
