#!/usr/bin/env bash
# Installs what vplab needs from Debian 12 packages (only what is missing, with sudo when not root),
# then configures and builds into build/. Sourced by run.sh and test.sh; safe to run again.
set -euo pipefail

VPLAB_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VPLAB_BUILD="${VPLAB_BUILD:-$VPLAB_ROOT/build}"
source "$VPLAB_ROOT/scripts/lib.sh"

packages=(
  cmake g++ make pkg-config python3-glad
  libglfw3-dev libglm-dev libimgui-dev libstb-dev
  libegl-dev libgl-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libgif-dev
  libtbb-dev  # every core: the pipeline's stages over objects and faces (oneTBB)
  zlib1g-dev  # the course kit's feedback zip: zlib's crc32
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth x11-utils xdotool fonts-dejavu-core strace desktop-file-utils
  dpkg-dev file lintian  # the .deb: cpack's dpkg-shlibdeps (dpkg-dev) and file; lintian checks it
  clang libfuzzer-14-dev libclang-rt-14-dev time  # sanitizer and fuzz stages of test.sh; time -v
)
# vplab exercise: the .tex sheets are compiled by the tests (pdflatex; German with babel ngerman, T1 with
# Latin Modern) and turned into pictures (pdftoppm)
packages+=(texlive-latex-base texlive-latex-recommended texlive-lang-german lmodern poppler-utils)
# the SVG backend's tests rasterise its documents with rsvg-convert
packages+=(librsvg2-bin)

vplab_install_missing "${packages[@]}"

# VPLAB_BUILD_TESTING=OFF leaves out the test suites and the benchmarks (package.sh, under Debian's nocheck).
cmake -S "$VPLAB_ROOT" -B "$VPLAB_BUILD" -DCMAKE_BUILD_TYPE="${VPLAB_BUILD_TYPE:-Release}" \
  -DBUILD_TESTING="${VPLAB_BUILD_TESTING:-ON}" >/dev/null
cmake --build "$VPLAB_BUILD" -j "$(nproc)"
